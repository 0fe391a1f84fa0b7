//! A glTF file opened: its bytes read within a bound, a `.glb` container split into its
//! JSON and binary chunks, the JSON parsed (an error at its line and column) and
//! validated, and every buffer's bytes read: the binary chunk, a `data:` URI or a file
//! beside the glTF file, each checked to hold at least the length it declares.

use super::uri::{self, Uri};
use crate::error::{Error, Result};
use crate::mesh::MAX_MESH_BYTES;
use ::gltf::json;
use std::path::{Path, PathBuf};

/// A glTF file read: its document, its buffers' bytes, and the files they came from.
pub(super) struct Opened {
    /// The file.
    pub path: PathBuf,
    /// The validated document.
    pub doc: ::gltf::Document,
    /// Each buffer's bytes, in order: at least its declared `byteLength`.
    pub buffers: Vec<Vec<u8>>,
    /// The files read: the glTF file, then every buffer's and image's file.
    pub sources: Vec<PathBuf>,
}

/// The first four bytes of a binary glTF (`.glb`) file.
const GLB_MAGIC: &[u8; 4] = b"glTF";

/// An error about the glTF file `path` at `location` (a JSON path such as
/// `meshes[0].primitives[1]`, or `the whole file`).
pub(super) fn error(path: &Path, location: impl Into<String>, message: impl Into<String>) -> Error {
    Error::SceneFile {
        path: path.to_path_buf(),
        location: location.into(),
        message: message.into(),
        field: None,
        line: None,
    }
}

/// Reads the regular file at `path`, of at most [`MAX_MESH_BYTES`] (the bound on any mesh
/// file), never past the size it had when opened; the reason if not.
pub(super) fn read_bounded(path: &Path) -> std::result::Result<Vec<u8>, String> {
    use std::io::Read;
    // Asked before opening: opening a FIFO would wait for a writer.
    let meta = std::fs::metadata(path).map_err(|e| format!("cannot open: {e}"))?;
    if !meta.is_file() {
        return Err("cannot read it: not a regular file".into());
    }
    if meta.len() > MAX_MESH_BYTES {
        return Err(format!(
            "the file has {} bytes; at most {MAX_MESH_BYTES} ({} GiB) are read",
            meta.len(),
            MAX_MESH_BYTES >> 30
        ));
    }
    let mut bytes = Vec::new();
    std::fs::File::open(path)
        .and_then(|f| f.take(meta.len()).read_to_end(&mut bytes))
        .map_err(|e| format!("cannot read: {e}"))?;
    Ok(bytes)
}

/// Opens the glTF (`.gltf`, JSON) or binary glTF (`.glb`) file at `path`, told apart by
/// its first four bytes.
pub(super) fn open(path: &Path) -> Result<Opened> {
    let whole = |m: String| error(path, "the whole file", m);
    let (json_bytes, bin, glb) = {
        let bytes = read_bounded(path).map_err(whole)?;
        if bytes.starts_with(GLB_MAGIC) {
            let (json, bin) = split_glb(&bytes).map_err(whole)?;
            (bytes[json].to_vec(), bin.map(|r| bytes[r].to_vec()), true)
        } else {
            (bytes, None, false)
        }
    };
    let root = json::Root::from_slice(&json_bytes).map_err(|e| {
        let chunk = if glb { "the JSON chunk, " } else { "" };
        let at = format!("{chunk}line {}, column {}", e.line(), e.column());
        error(path, at, format!("not glTF JSON: {e}"))
    })?;
    drop(json_bytes);
    validate(path, &root)?;
    let doc = ::gltf::Document::from_json_without_validation(root);
    let mut sources = vec![path.to_path_buf()];
    let buffers = read_buffers(path, &doc, bin, &mut sources)?;
    Ok(Opened {
        path: path.to_path_buf(),
        doc,
        buffers,
        sources,
    })
}

/// The byte ranges of a `.glb` file's JSON chunk and binary chunk: a 12-byte header
/// (`glTF`, version 2, total length), then chunks of a length, a type and the data.
fn split_glb(
    bytes: &[u8],
) -> std::result::Result<(std::ops::Range<usize>, Option<std::ops::Range<usize>>), String> {
    let word = |at: usize| -> Option<u32> {
        let b = bytes.get(at..at.checked_add(4)?)?;
        Some(u32::from_le_bytes([b[0], b[1], b[2], b[3]]))
    };
    let (Some(version), Some(length)) = (word(4), word(8)) else {
        return Err(format!(
            "a binary glTF (.glb) file of {} bytes: shorter than its 12-byte header",
            bytes.len()
        ));
    };
    if version != 2 {
        return Err(format!("binary glTF version {version}: only version 2 is read"));
    }
    let length = length as usize;
    if length > bytes.len() || length < 12 {
        return Err(format!(
            "the binary glTF header declares {length} bytes, the file has {}",
            bytes.len()
        ));
    }
    // Chunks, each padded to 4 bytes: the JSON first, then at most one binary chunk.
    let chunk = |at: usize, name: &str| -> std::result::Result<(u32, std::ops::Range<usize>), String> {
        let (Some(len), Some(kind)) = (word(at), word(at + 4)) else {
            return Err(format!("the {name} chunk's header runs past the file's end"));
        };
        let start = at + 8;
        let end = start
            .checked_add(len as usize)
            .filter(|&e| e <= length)
            .ok_or_else(|| format!("the {name} chunk declares {len} bytes, past the file's {length}"))?;
        Ok((kind, start..end))
    };
    let (kind, json) = chunk(12, "JSON")?;
    if kind != u32::from_le_bytes(*b"JSON") {
        return Err("the first chunk of a binary glTF file is not its JSON chunk".into());
    }
    let next = json.end.next_multiple_of(4);
    if next + 8 > length {
        return Ok((json, None));
    }
    let (kind, bin) = chunk(next, "binary")?;
    if kind != u32::from_le_bytes(*b"BIN\0") {
        return Err("the second chunk of a binary glTF file is not a BIN chunk".into());
    }
    Ok((json, Some(bin)))
}

/// The glTF crate's validation (indices in range, required fields, enumerations), every
/// failure reported at its JSON path; the extensions a file requires are checked by the
/// importer itself, which reads some the crate does not.
fn validate(path: &Path, root: &json::Root) -> Result<()> {
    use json::validation::Validate;
    // The crate's check of a primitive's POSITION reads the accessor before its index is
    // checked (and panics past the end): checked here first.
    for (m, mesh) in root.meshes.iter().enumerate() {
        for (p, primitive) in mesh.primitives.iter().enumerate() {
            let position = json::validation::Checked::Valid(json::mesh::Semantic::Positions);
            if let Some(a) = primitive.attributes.get(&position)
                && a.value() >= root.accessors.len()
            {
                return Err(error(
                    path,
                    format!("meshes[{m}].primitives[{p}].attributes.POSITION"),
                    format!(
                        "invalid glTF: accessor {} does not exist (the file has {})",
                        a.value(),
                        root.accessors.len()
                    ),
                ));
            }
        }
    }
    let mut errors = Vec::new();
    root.validate(root, json::Path::new, &mut |at, e| {
        let at = at().to_string();
        if !at.starts_with("extensionsRequired") {
            errors.push((at, e));
        }
    });
    match errors.first() {
        None => Ok(()),
        Some((at, e)) => {
            let more = match errors.len() {
                1 => String::new(),
                n => format!(" ({} more problems in the file)", n - 1),
            };
            Err(error(path, at.clone(), format!("invalid glTF: {e}{more}")))
        }
    }
}

/// Every buffer's bytes: the binary chunk for one without a URI, a `data:` URI's decoded
/// bytes, or a file relative to the glTF file's folder. Each must hold at least its
/// `byteLength` (a longer one is padded; only the declared bytes are kept).
fn read_buffers(
    path: &Path,
    doc: &::gltf::Document,
    mut bin: Option<Vec<u8>>,
    sources: &mut Vec<PathBuf>,
) -> Result<Vec<Vec<u8>>> {
    let folder = path.parent().unwrap_or(Path::new(""));
    let mut buffers = Vec::new();
    for buffer in doc.buffers() {
        let at = format!("buffers[{}]", buffer.index());
        let mut bytes = match buffer.source() {
            ::gltf::buffer::Source::Bin => bin.take().ok_or_else(|| {
                error(
                    path,
                    &at,
                    "a buffer without a `uri` is a .glb file's binary chunk, and this file has none \
                     (or an earlier buffer took it)",
                )
            })?,
            ::gltf::buffer::Source::Uri(text) => match uri::parse(text) {
                Ok(Uri::Data { bytes, .. }) => bytes,
                Ok(Uri::File(relative)) => {
                    let file = folder.join(&relative);
                    let bytes = read_bounded(&file).map_err(|m| {
                        error(path, format!("{at}.uri"), format!("`{}`: {m}", file.display()))
                    })?;
                    sources.push(file);
                    bytes
                }
                Err(m) => return Err(error(path, format!("{at}.uri"), m)),
            },
        };
        let declared = buffer.length();
        if bytes.len() < declared {
            return Err(error(
                path,
                &at,
                format!(
                    "the buffer holds {} bytes but declares byteLength {declared}",
                    bytes.len()
                ),
            ));
        }
        bytes.truncate(declared);
        buffers.push(bytes);
    }
    Ok(buffers)
}
