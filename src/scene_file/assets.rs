//! Meshes and images an importer read out of a container file (a glTF file's buffers and
//! embedded images), held in memory under the names the scene file's `file` keys give
//! them, and the files they were read from.
//!
//! A `file` key is looked up here first: a name found here is never read from disk, so a
//! mesh from a glTF buffer goes through the same checks, placement and BVH build as an
//! OBJ or PLY file's. The files they came from are the scene's inputs instead (hashed
//! into a tile's header, never overwritten by an output).

use crate::mesh::MeshData;
use crate::texture::Bitmap;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// Meshes and decoded images by name, and the files they were read from.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Assets {
    meshes: BTreeMap<String, Arc<MeshData>>,
    images: BTreeMap<String, Arc<Bitmap>>,
    sources: Vec<PathBuf>,
}

impl Assets {
    /// Holds `mesh` under `name`, which a mesh's or a `[meshes]` entry's `file` then names.
    pub fn insert_mesh(&mut self, name: String, mesh: MeshData) {
        self.meshes.insert(name, Arc::new(mesh));
    }

    /// Holds `bitmap` under `name`, which an image texture's `file` then names. Its pixels
    /// are used as they are, whatever the texture's `raw` says: they are decoded already.
    pub fn insert_image(&mut self, name: String, bitmap: Arc<Bitmap>) {
        self.images.insert(name, bitmap);
    }

    /// Records that what is held was read (in part) from the file at `path`.
    pub fn add_source(&mut self, path: &Path) {
        if !self.sources.iter().any(|p| p == path) {
            self.sources.push(path.to_path_buf());
        }
    }

    /// The mesh held under `name`.
    pub fn mesh(&self, name: &str) -> Option<&Arc<MeshData>> {
        self.meshes.get(name)
    }

    /// The image held under `name`.
    pub fn image(&self, name: &str) -> Option<&Arc<Bitmap>> {
        self.images.get(name)
    }

    /// Whether a mesh or an image is held under `name`.
    pub fn holds(&self, name: &str) -> bool {
        self.meshes.contains_key(name) || self.images.contains_key(name)
    }

    /// The files what is held was read from, in the order first recorded.
    pub fn sources(&self) -> &[PathBuf] {
        &self.sources
    }
}
