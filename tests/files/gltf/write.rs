//! A small glTF 2.0 writer for the tests, written from the specification: meshes, images,
//! materials, nodes, cameras and lights as JSON over one binary buffer, saved as a
//! `.gltf` with its buffer beside it (`.bin`) or embedded (a base64 `data:` URI), or as a
//! `.glb`. The tests make every asset they read with it.

use serde_json::{Value, json};
use std::path::{Path, PathBuf};

/// A glTF asset being written.
pub struct Gltf {
    /// The binary buffer (buffer 0).
    pub bin: Vec<u8>,
    /// The JSON, without its `buffers` (added when saved).
    pub json: Value,
}

/// The component types of the specification.
pub const FLOAT: u32 = 5126;
pub const UNSIGNED_INT: u32 = 5125;
pub const UNSIGNED_SHORT: u32 = 5123;

impl Gltf {
    /// An asset with nothing in it.
    pub fn new() -> Self {
        Self {
            bin: Vec::new(),
            json: json!({ "asset": { "version": "2.0", "generator": "raytrace tests" } }),
        }
    }

    /// Appends `v` to the top-level array `array`; its index.
    pub fn push(&mut self, array: &str, v: Value) -> usize {
        let list = self
            .json
            .as_object_mut()
            .unwrap()
            .entry(array)
            .or_insert(json!([]));
        let list = list.as_array_mut().unwrap();
        list.push(v);
        list.len() - 1
    }

    /// Names `extension` in `extensionsUsed` (once).
    pub fn uses(&mut self, extension: &str) {
        let list = self
            .json
            .as_object_mut()
            .unwrap()
            .entry("extensionsUsed")
            .or_insert(json!([]));
        let list = list.as_array_mut().unwrap();
        if !list.iter().any(|e| e == extension) {
            list.push(json!(extension));
        }
    }

    /// A buffer view over `bytes`, appended to the buffer at a multiple of 4.
    pub fn view(&mut self, bytes: &[u8]) -> usize {
        while !self.bin.len().is_multiple_of(4) {
            self.bin.push(0);
        }
        let offset = self.bin.len();
        self.bin.extend_from_slice(bytes);
        self.push(
            "bufferViews",
            json!({ "buffer": 0, "byteOffset": offset, "byteLength": bytes.len() }),
        )
    }

    /// An accessor of `N`-component float vectors (with `min` and `max`, as POSITION needs).
    pub fn floats<const N: usize>(&mut self, data: &[[f32; N]]) -> usize {
        let bytes: Vec<u8> = data.iter().flatten().flat_map(|x| x.to_le_bytes()).collect();
        let view = self.view(&bytes);
        let min: Vec<f32> = (0..N)
            .map(|k| data.iter().map(|v| v[k]).fold(f32::INFINITY, f32::min))
            .collect();
        let max: Vec<f32> = (0..N)
            .map(|k| data.iter().map(|v| v[k]).fold(f32::NEG_INFINITY, f32::max))
            .collect();
        let kind = ["SCALAR", "VEC2", "VEC3", "VEC4"][N - 1];
        self.push(
            "accessors",
            json!({ "bufferView": view, "componentType": FLOAT, "count": data.len(), "type": kind,
                    "min": min, "max": max }),
        )
    }

    /// An accessor of 32-bit indices.
    pub fn indices(&mut self, data: &[u32]) -> usize {
        let bytes: Vec<u8> = data.iter().flat_map(|x| x.to_le_bytes()).collect();
        let view = self.view(&bytes);
        self.push(
            "accessors",
            json!({ "bufferView": view, "componentType": UNSIGNED_INT, "count": data.len(), "type": "SCALAR" }),
        )
    }

    /// A mesh of one triangle primitive.
    pub fn mesh(
        &mut self,
        positions: &[[f32; 3]],
        normals: Option<&[[f32; 3]]>,
        uvs: Option<&[[f32; 2]]>,
        indices: &[u32],
        material: Option<usize>,
    ) -> usize {
        let mut attributes = json!({ "POSITION": self.floats(positions) });
        if let Some(n) = normals {
            attributes["NORMAL"] = json!(self.floats(n));
        }
        if let Some(t) = uvs {
            attributes["TEXCOORD_0"] = json!(self.floats(t));
        }
        let mut primitive = json!({ "attributes": attributes, "indices": self.indices(indices) });
        if let Some(m) = material {
            primitive["material"] = json!(m);
        }
        self.push("meshes", json!({ "primitives": [primitive] }))
    }

    /// An RGB PNG of `width × height` pixels (row by row from the top), embedded in the
    /// buffer; the image's index.
    pub fn png(&mut self, width: u32, height: u32, pixels: &[[u8; 3]]) -> usize {
        let mut bytes = Vec::new();
        {
            let mut encoder = png::Encoder::new(&mut bytes, width, height);
            encoder.set_color(png::ColorType::Rgb);
            encoder.set_depth(png::BitDepth::Eight);
            let mut writer = encoder.write_header().unwrap();
            let data: Vec<u8> = pixels.iter().flatten().copied().collect();
            writer.write_image_data(&data).unwrap();
        }
        let view = self.view(&bytes);
        self.push("images", json!({ "bufferView": view, "mimeType": "image/png" }))
    }

    /// A texture of image `image` (with the default sampler).
    pub fn texture(&mut self, image: usize) -> usize {
        self.push("textures", json!({ "source": image }))
    }

    /// A node; its index.
    pub fn node(&mut self, node: Value) -> usize {
        self.push("nodes", node)
    }

    /// The scene of `roots`, made the file's scene.
    pub fn scene(&mut self, roots: &[usize]) {
        let s = self.push("scenes", json!({ "nodes": roots }));
        self.json["scene"] = json!(s);
    }

    /// A `KHR_lights_punctual` light; its index.
    pub fn light(&mut self, light: Value) -> usize {
        self.uses("KHR_lights_punctual");
        let ext = self
            .json
            .as_object_mut()
            .unwrap()
            .entry("extensions")
            .or_insert(json!({}));
        let lights = ext
            .as_object_mut()
            .unwrap()
            .entry("KHR_lights_punctual")
            .or_insert(json!({ "lights": [] }));
        let list = lights["lights"].as_array_mut().unwrap();
        list.push(light);
        list.len() - 1
    }

    /// The JSON with `buffers[0]` at `uri` (none: a `.glb`'s binary chunk).
    pub fn json_text(&self, uri: Option<&str>) -> String {
        let mut json = self.json.clone();
        if !self.bin.is_empty() {
            let mut buffer = json!({ "byteLength": self.bin.len() });
            if let Some(uri) = uri {
                buffer["uri"] = json!(uri);
            }
            json["buffers"] = json!([buffer]);
        }
        serde_json::to_string_pretty(&json).unwrap()
    }

    /// Saves `name.gltf` in `dir` with its buffer beside it as `name.bin`; the path.
    pub fn save_gltf(&self, dir: &Path, name: &str) -> PathBuf {
        std::fs::create_dir_all(dir).unwrap();
        let bin = format!("{name}.bin");
        std::fs::write(dir.join(&bin), &self.bin).unwrap();
        let path = dir.join(format!("{name}.gltf"));
        std::fs::write(&path, self.json_text(Some(&bin))).unwrap();
        path
    }

    /// Saves `name.gltf` in `dir` with its buffer embedded as a base64 `data:` URI.
    pub fn save_embedded(&self, dir: &Path, name: &str) -> PathBuf {
        std::fs::create_dir_all(dir).unwrap();
        let uri = format!("data:application/octet-stream;base64,{}", base64(&self.bin));
        let path = dir.join(format!("{name}.gltf"));
        std::fs::write(&path, self.json_text(Some(&uri))).unwrap();
        path
    }

    /// The asset as a `.glb` file's bytes: the 12-byte header, the JSON chunk padded with
    /// spaces, the binary chunk padded with zeros.
    pub fn glb(&self) -> Vec<u8> {
        let mut json = self.json_text(None).into_bytes();
        while !json.len().is_multiple_of(4) {
            json.push(b' ');
        }
        let mut bin = self.bin.clone();
        while !bin.len().is_multiple_of(4) {
            bin.push(0);
        }
        let total = 12 + 8 + json.len() + if bin.is_empty() { 0 } else { 8 + bin.len() };
        let mut out = Vec::with_capacity(total);
        out.extend_from_slice(b"glTF");
        out.extend_from_slice(&2u32.to_le_bytes());
        out.extend_from_slice(&(total as u32).to_le_bytes());
        out.extend_from_slice(&(json.len() as u32).to_le_bytes());
        out.extend_from_slice(b"JSON");
        out.extend_from_slice(&json);
        if !bin.is_empty() {
            out.extend_from_slice(&(bin.len() as u32).to_le_bytes());
            out.extend_from_slice(b"BIN\0");
            out.extend_from_slice(&bin);
        }
        out
    }

    /// Saves `name.glb` in `dir`.
    pub fn save_glb(&self, dir: &Path, name: &str) -> PathBuf {
        std::fs::create_dir_all(dir).unwrap();
        let path = dir.join(format!("{name}.glb"));
        std::fs::write(&path, self.glb()).unwrap();
        path
    }
}

/// RFC 4648 base64 with padding.
pub fn base64(bytes: &[u8]) -> String {
    const DIGITS: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut out = String::new();
    for chunk in bytes.chunks(3) {
        let b = [chunk[0], *chunk.get(1).unwrap_or(&0), *chunk.get(2).unwrap_or(&0)];
        let word = (u32::from(b[0]) << 16) | (u32::from(b[1]) << 8) | u32::from(b[2]);
        for k in 0..4 {
            if k <= chunk.len() {
                out.push(DIGITS[(word >> (18 - 6 * k) & 63) as usize] as char);
            } else {
                out.push('=');
            }
        }
    }
    out
}

/// A folder of its own for test `name` under the system's temporary folder, empty.
pub fn folder(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("rt-gltf-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}
