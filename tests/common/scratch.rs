//! A scratch folder for a test's files (images, meshes, materials), removed on drop.

use std::path::PathBuf;

/// A scratch folder for one test, named by the process and the test; removed on drop.
pub struct Scratch(pub PathBuf);

impl Scratch {
    pub fn new(test: &str) -> Self {
        let dir = std::env::temp_dir().join(format!("raytrace-scratch-{}-{test}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        Self(dir)
    }

    /// The path of `name` in the folder.
    pub fn path(&self, name: &str) -> PathBuf {
        self.0.join(name)
    }

    /// Writes `bytes` to the file `name` in the folder and returns its path.
    pub fn file(&self, name: &str, bytes: impl AsRef<[u8]>) -> PathBuf {
        let path = self.path(name);
        std::fs::write(&path, bytes).unwrap();
        path
    }

    /// Writes an 8-bit RGB PNG of `w × h` pixels, row by row from the top.
    pub fn png8(&self, name: &str, w: u32, h: u32, rgb: &[[u8; 3]]) -> PathBuf {
        let data: Vec<u8> = rgb.iter().flatten().copied().collect();
        self.png(name, w, h, png::ColorType::Rgb, png::BitDepth::Eight, &data)
    }

    /// Writes a PNG of `w × h` pixels of `color` and `depth` from its samples, row by row
    /// from the top (16-bit samples big-endian, as PNG stores them).
    pub fn png(
        &self,
        name: &str,
        w: u32,
        h: u32,
        color: png::ColorType,
        depth: png::BitDepth,
        data: &[u8],
    ) -> PathBuf {
        let path = self.path(name);
        let mut encoder = png::Encoder::new(std::fs::File::create(&path).unwrap(), w, h);
        encoder.set_color(color);
        encoder.set_depth(depth);
        encoder.write_header().unwrap().write_image_data(data).unwrap();
        path
    }

    /// Writes a baseline JPEG of `w × h` RGB pixels at quality 90.
    pub fn jpeg(&self, name: &str, w: u16, h: u16, rgb: &[u8]) -> PathBuf {
        let path = self.path(name);
        let encoder = jpeg_encoder::Encoder::new_file(&path, 90).unwrap();
        encoder.encode(rgb, w, h, jpeg_encoder::ColorType::Rgb).unwrap();
        path
    }

    /// Writes a Radiance HDR file of `w × h` pixels as flat RGBE pixels. Each pixel must be
    /// exact in RGBE (8-bit mantissas under the largest channel's power of two): the test
    /// then knows every value the reader must give back.
    pub fn hdr(&self, name: &str, w: usize, h: usize, pixels: &[[f32; 3]]) -> PathBuf {
        assert_eq!(pixels.len(), w * h);
        let mut bytes = format!("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y {h} +X {w}\n").into_bytes();
        for p in pixels {
            bytes.extend(rgbe(p.map(f64::from)));
        }
        self.file(name, bytes)
    }
}

/// The RGBE bytes of `rgb`: with `m = f · 2^k` the largest channel (`f` in [½, 1)), the
/// exponent byte is `k + 128` and each mantissa `c · 2^(8 − k)`, which must be an integer.
fn rgbe(rgb: [f64; 3]) -> [u8; 4] {
    let m = rgb.iter().copied().fold(0.0, f64::max);
    if m == 0.0 {
        return [0; 4];
    }
    let k = m.log2().floor() as i32 + 1;
    let [r, g, b] = rgb.map(|c| {
        let q = c * 2f64.powi(8 - k);
        assert!(
            q.fract() == 0.0 && (0.0..256.0).contains(&q),
            "{rgb:?} is not exact in RGBE"
        );
        q as u8
    });
    [r, g, b, (k + 128) as u8]
}

impl Drop for Scratch {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}
