//! Triangle meshes from files: Wavefront OBJ and Stanford PLY (and, through
//! [`from_arrays`], from the arrays an importer decoded).
//!
//! A mesh is loaded as shared vertex positions and triangles indexing them. Polygons are
//! split into triangles as fans; faces without area are skipped and counted, so a caller
//! can report them. An OBJ file may also be read split by the materials of its `.mtl`
//! libraries ([`load_parts`]).

mod arrays;
mod check;
mod mtl;
mod obj;
mod obj_parts;
mod ply;
mod source;

pub use arrays::from_arrays;
pub use mtl::{At, MtlLibrary, MtlMap, MtlMaterial, read as read_mtl};
pub use obj_parts::{ObjPart, ObjParts, load_parts, material_files, usemtl_names};
pub use source::{MAX_LINE_BYTES, MAX_MESH_BYTES};

use crate::error::{Error, Result};
use crate::vec3::Vec3;
use std::path::Path;

/// A triangle mesh as read from a file, in the file's own coordinates.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct MeshData {
    /// The vertex positions, every coordinate finite: a PLY file's in its order; an OBJ
    /// file's those its faces use, in the order first used, object after object (a
    /// position its faces use with two texture coordinates or two normals is two
    /// vertices).
    pub positions: Vec<Vec3<f64>>,
    /// A normal per vertex, every coordinate finite, as the file gives it (any length;
    /// zero where an OBJ object has none and another has): OBJ `vn`, PLY `nx ny nz`.
    /// `None` if the file has none.
    pub normals: Option<Vec<Vec3<f64>>>,
    /// Texture coordinates `(u, v)` per vertex, finite, as the file writes them (zero where
    /// an OBJ object has none and another has; see [`flips_tex_coords`] for the
    /// convention of `v`): OBJ `vt`, PLY `u v`, `s t` or `texture_u texture_v`. `None` if
    /// the file has none.
    pub uvs: Option<Vec<[f64; 2]>>,
    /// The triangles, as indices into `positions`, each with a non-zero area.
    pub triangles: Vec<[u32; 3]>,
    /// Faces of the file skipped for having no area (repeated or collinear vertices).
    pub skipped_degenerate: usize,
}

/// Whether texture coordinates read from the file at `path` are flipped (`v ↦ 1 − v`) to
/// reach the renderer's convention, in which `v = 0` is an image's top row: Mitsuba 3's
/// default `flip_tex_coords`, `true` for OBJ (whose `vt` counts `v` up from the image's
/// bottom) and `false` for PLY.
pub fn flips_tex_coords(path: &Path) -> bool {
    path.extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| e.eq_ignore_ascii_case("obj"))
}

/// Loads the mesh at `path`, choosing the format by its extension (`.obj` or `.ply`, in any
/// case).
///
/// Only a regular file of at most [`MAX_MESH_BYTES`] is read, never past the size it had
/// when opened, and a text file's lines (OBJ, ASCII PLY, any PLY header) may have at most
/// [`MAX_LINE_BYTES`]: a link to `/dev/zero` or a FIFO is refused before it is read, and a
/// file of one endless line stops at the bound instead of filling memory.
///
/// # Errors
/// [`Error::Mesh`], naming the file and the element, for a file that is missing, not a
/// regular file, too large, of another format, truncated or garbled, with a line past the
/// bound, an index out of range, or with a coordinate that is NaN or infinite, a face of
/// fewer than three vertices, or no triangle with area. Vertices and faces are numbered as
/// the format counts them: from 0 in PLY, from 1 (with the line) in OBJ. The message never
/// quotes the file.
pub fn load(path: &Path) -> Result<MeshData> {
    let extension = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    match extension.as_deref() {
        Some("obj") => obj::load(path),
        Some("ply") => ply::load(path),
        _ => Err(Error::Mesh {
            path: path.to_path_buf(),
            message: "unknown mesh format: the name must end in .obj or .ply".into(),
        }),
    }
}
