//! Reading OBJ files.

use super::MeshData;
use crate::error::{Error, Result};
use std::path::Path;

/// Loads an OBJ mesh.
pub(super) fn load(path: &Path) -> Result<MeshData> {
    Err(Error::Mesh {
        path: path.to_path_buf(),
        message: "OBJ meshes cannot be read yet".into(),
    })
}
