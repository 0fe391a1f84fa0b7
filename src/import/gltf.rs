//! glTF 2.0 (`.gltf` and `.glb`) read into a [`SceneFile`](crate::scene_file::SceneFile):
//! the scene's node hierarchy with its transforms, its meshes' triangles (positions,
//! normals, `TEXCOORD_0`, indices) held in memory and placed as mesh objects or
//! instances, metallic-roughness materials mapped onto the renderer's BSDFs with their
//! base-colour, metallic-roughness, normal and emissive images, the camera,
//! `KHR_lights_punctual` and `KHR_materials_emissive_strength`.
//!
//! The JSON is parsed and validated by the `gltf` crate; everything with a length (the
//! `.glb` container, buffers, buffer views, accessors, images) is read here, each range
//! checked against the bytes present before anything is allocated for it. Bad input is an
//! error naming the file and the JSON path (`meshes[0].primitives[1]`) or the line and
//! column of malformed JSON, never a panic.

mod accessor;
mod container;
mod convert;
mod geometry;
mod images;
mod material;
mod nodes;
mod transmission;
mod uri;
mod view;

pub use convert::MAX_COPIED_TRIANGLES;
pub use view::{DEFAULT_ASPECT, DEFAULT_VFOV, LUMENS_PER_WATT};

use super::Imported;
use crate::error::Result;
use std::path::Path;

/// The extensions read: every other one a file uses is a warning naming it, and one it
/// requires an error.
pub const SUPPORTED_EXTENSIONS: [&str; 7] = [
    "KHR_lights_punctual",
    "KHR_materials_emissive_strength",
    "KHR_materials_ior",
    "KHR_materials_transmission",
    "KHR_materials_volume",
    "KHR_mesh_quantization",
    "KHR_texture_transform",
];

/// Reads the glTF file at `path`.
pub(super) fn import(path: &Path) -> Result<Imported> {
    let g = container::open(path)?;
    let root = g.doc.as_json();
    if let Some((i, name)) = root
        .extensions_required
        .iter()
        .enumerate()
        .find(|(_, e)| !SUPPORTED_EXTENSIONS.contains(&e.as_str()))
    {
        return Err(container::error(
            path,
            format!("extensionsRequired[{i}]"),
            format!(
                "the file requires the extension {name}, which this importer does not read (it reads {})",
                SUPPORTED_EXTENSIONS.join(", ")
            ),
        ));
    }
    let unread: Vec<&str> = root
        .extensions_used
        .iter()
        .map(String::as_str)
        .filter(|e| !SUPPORTED_EXTENSIONS.contains(e))
        .collect();
    let mut importer = convert::Importer::new(&g);
    for name in unread {
        importer.warnings.push(format!(
            "extensionsUsed: {name} is not read: the file is rendered without it"
        ));
    }
    importer.run()
}
