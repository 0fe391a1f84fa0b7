//! Where a shape is shaded otherwise than in Mitsuba 3, a warning. Mitsuba shades an
//! instance with its file's normals, this renderer with its faces' normals. Mitsuba's
//! `rectangle` and `cube` have uv over each face; here each triangle has its own. (A mesh
//! whose file has no normals is shaded smooth in both: `smooth.rs`.)

use super::convert::Importer;
use super::xml::Plugin;
use crate::error::Result;
use crate::scene_file::{MaterialSpec, TextureRef};
use std::io::{BufRead, BufReader};
use std::path::Path;

/// The most header lines of a PLY file looked through for its normals.
const PLY_HEADER_LINES: usize = 1000;

impl Importer {
    /// A warning for the mesh shape `s` of a shapegroup unless it says `face_normals =
    /// true`: an instance is shaded with its faces' normals here.
    pub(super) fn instance_normals(&mut self, s: &Plugin) -> Result<()> {
        if self.boolean(s, "face_normals")? != Some(true) {
            self.warn(
                s,
                "an instance is shaded with its faces' normals here, in Mitsuba with its file's (or \
                 smooth ones); face_normals = true renders it alike in both"
                    .into(),
            );
        }
        Ok(())
    }
}

impl Importer {
    /// A warning if the `rectangle` or `cube` `s` has a material that reads its surface
    /// coordinates (a texture, an anisotropic roughness).
    pub(super) fn unit_shape_uv(&mut self, s: &Plugin, material: &str) {
        let Some(m) = self.file.materials.get(material) else {
            return;
        };
        let textured = m.textures().iter().any(|t| !matches!(t, TextureRef::Color(_)));
        let anisotropic = match m {
            MaterialSpec::RoughConductor(c) => c.alpha_u.is_some(),
            MaterialSpec::RoughDielectric(d) => d.alpha_u.is_some(),
            _ => false,
        };
        if textured || anisotropic {
            self.warn(
                s,
                "its triangles have their own uv here, Mitsuba's run over each face: a texture or an \
                 anisotropic roughness on it differs (an obj with uv renders it alike)"
                    .into(),
            );
        }
    }
}

/// Whether the OBJ or PLY file at `path` holds vertex normals (`vn` lines; `nx` among a PLY
/// header's properties); `None` if it cannot be read (the scene's build says why) or is
/// of neither kind.
pub(super) fn declares_normals(path: &Path) -> Option<bool> {
    let extension = path.extension()?.to_str()?.to_ascii_lowercase();
    let mut lines = BufReader::new(std::fs::File::open(path).ok()?).split(b'\n');
    match extension.as_str() {
        "obj" => Some(lines.any(|l| l.is_ok_and(|l| l.starts_with(b"vn ") || l.starts_with(b"vn\t")))),
        "ply" => {
            for line in lines.take(PLY_HEADER_LINES) {
                let line = line.ok()?;
                let words: Vec<&[u8]> = line
                    .split(u8::is_ascii_whitespace)
                    .filter(|w| !w.is_empty())
                    .collect();
                match words[..] {
                    [b"end_header", ..] => return Some(false),
                    [b"property", _, b"nx"] => return Some(true),
                    _ => {}
                }
            }
            None
        }
        _ => None,
    }
}
