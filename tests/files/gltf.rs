//! glTF 2.0 import: files the tests write themselves ([`write`]) read into scene files and
//! rendered. Each test checks a fact computed apart from the importer: where a node's
//! map puts a vertex, what an emitter or a camera shows, where a texture's texels land,
//! that a lit quad renders the bytes of its TOML twin; bad files are clear errors, and
//! no bytes make the importer panic.

mod bad_files;
mod cli;
mod fuzz;
mod materials;
mod placement;
mod rendering;
pub mod write;

use raytrace::import::{self, Imported};
use raytrace::scene_file::ObjectSpec;
use std::path::Path;

/// The file at `path` imported; panics with the error if it is refused.
pub fn import(path: &Path) -> Imported {
    match import::gltf(path) {
        Ok(i) => i,
        Err(e) => panic!("{e}"),
    }
}

/// The rows of object `o`'s map (the identity when it has none).
pub fn matrix_of(o: &ObjectSpec) -> [[f64; 4]; 3] {
    let identity = [[1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0]];
    match o {
        ObjectSpec::Mesh { matrix, .. } | ObjectSpec::Instance { matrix, .. } => matrix.unwrap_or(identity),
        _ => panic!("not a mesh: {o:?}"),
    }
}

/// `m` applied to the point `p`.
pub fn apply(m: &[[f64; 4]; 3], p: [f64; 3]) -> [f64; 3] {
    m.map(|r| r[0] * p[0] + r[1] * p[1] + r[2] * p[2] + r[3])
}
