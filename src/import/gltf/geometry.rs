//! A glTF mesh primitive as a [`MeshData`]: `POSITION`, `NORMAL` and `TEXCOORD_0` read
//! from their accessors, the triangles from the indices (or the vertices in order) as the
//! primitive's mode lays them out, then the checks every mesh file gets
//! ([`crate::mesh::from_arrays`]).
//!
//! glTF's texture coordinates already follow the renderer's convention (`v = 0` is an
//! image's top row), so they are kept as they are.

use super::accessor;
use crate::mesh::MeshData;
use crate::vec3::Vec3;
use ::gltf::mesh::{Mode, Semantic};

/// What a primitive is, by its mode.
pub(super) enum Read {
    /// Triangles (of a `TRIANGLES`, `TRIANGLE_STRIP` or `TRIANGLE_FAN` primitive).
    Mesh(MeshData),
    /// Points or lines, which have no area: the mode's name.
    NoArea(&'static str),
}

/// The triangles of primitive `p`, each wound the other way if `mirrored` (a node whose
/// map turns space inside out keeps its front faces in front, as glTF says); why not, if
/// its accessors do not hold a mesh.
pub(super) fn read(p: &::gltf::Primitive, buffers: &[Vec<u8>], mirrored: bool) -> Result<Read, String> {
    let name = match p.mode() {
        Mode::Points => Some("POINTS"),
        Mode::Lines => Some("LINES"),
        Mode::LineLoop => Some("LINE_LOOP"),
        Mode::LineStrip => Some("LINE_STRIP"),
        Mode::Triangles | Mode::TriangleStrip | Mode::TriangleFan => None,
    };
    if let Some(name) = name {
        return Ok(Read::NoArea(name));
    }
    let position = p
        .get(&Semantic::Positions)
        .ok_or("no POSITION attribute: a primitive needs its vertices")?;
    let attribute = |what: &str, e: String| format!("attributes.{what}: {e}");
    let positions: Vec<Vec3<f64>> = accessor::vectors::<3>(&position, buffers)
        .map_err(|e| attribute("POSITION", e))?
        .into_iter()
        .map(|[x, y, z]| Vec3::new(x, y, z))
        .collect();
    let normals = match p.get(&Semantic::Normals) {
        Some(a) => Some(
            accessor::vectors::<3>(&a, buffers)
                .map_err(|e| attribute("NORMAL", e))?
                .into_iter()
                .map(|[x, y, z]| Vec3::new(x, y, z))
                .collect::<Vec<_>>(),
        ),
        None => None,
    };
    let uvs = match p.get(&Semantic::TexCoords(0)) {
        Some(a) => Some(accessor::vectors::<2>(&a, buffers).map_err(|e| attribute("TEXCOORD_0", e))?),
        None => None,
    };
    let order = match p.indices() {
        Some(a) => accessor::indices(&a, buffers).map_err(|e| format!("indices: {e}"))?,
        None => {
            let n = u32::try_from(positions.len()).map_err(|_| "more than 2^32 vertices")?;
            (0..n).collect()
        }
    };
    let triangles = triangles(p.mode(), &order)?;
    let wound = triangles
        .into_iter()
        .map(|[a, b, c]| if mirrored { [a, c, b] } else { [a, b, c] });
    crate::mesh::from_arrays(positions, normals, uvs, wound).map(Read::Mesh)
}

/// The triangles `mode` makes of the vertices in `order`, as the glTF specification
/// (3.7.2.1) lays them out: `TRIANGLES` takes them three by three; `TRIANGLE_STRIP`'s
/// triangle `i` is `(vᵢ, vᵢ₊₁₊ᵢ﹪₂, vᵢ₊₂₋ᵢ﹪₂)`; `TRIANGLE_FAN`'s is `(vᵢ₊₁, vᵢ₊₂, v₀)`.
fn triangles(mode: Mode, order: &[u32]) -> Result<Vec<[u32; 3]>, String> {
    let n = order.len();
    Ok(match mode {
        Mode::TriangleStrip => (0..n.saturating_sub(2))
            .map(|i| [order[i], order[i + 1 + i % 2], order[i + 2 - i % 2]])
            .collect(),
        Mode::TriangleFan => (0..n.saturating_sub(2))
            .map(|i| [order[i + 1], order[i + 2], order[0]])
            .collect(),
        _ => {
            if !n.is_multiple_of(3) {
                return Err(format!(
                    "{n} vertices in the index order of a TRIANGLES primitive: a multiple of 3 is needed"
                ));
            }
            order.chunks_exact(3).map(|t| [t[0], t[1], t[2]]).collect()
        }
    })
}

/// Whether every triangle's vertex normals all point along its face's normal (to `10⁻⁶`),
/// as a flat-shaded export's do: then the mesh shades alike with its faces' normals, and
/// may be instanced without its normals. True for a mesh without normals.
pub(super) fn normals_are_flat(mesh: &MeshData) -> bool {
    let Some(normals) = &mesh.normals else {
        return true;
    };
    mesh.triangles.iter().all(|t| {
        let p = t.map(|i| mesh.positions[i as usize]);
        let Some(face) = (p[1] - p[0]).cross(p[2] - p[0]).try_normalize() else {
            return true;
        };
        t.iter().all(|&i| {
            normals[i as usize]
                .try_normalize()
                .is_some_and(|n| n.dot(face) > 1.0 - 1e-6)
        })
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn strips_and_fans_are_laid_out_as_the_specification_says() {
        let order = [10, 11, 12, 13, 14];
        assert_eq!(
            triangles(Mode::TriangleStrip, &order).unwrap(),
            vec![[10, 11, 12], [11, 13, 12], [12, 13, 14]]
        );
        assert_eq!(
            triangles(Mode::TriangleFan, &order).unwrap(),
            vec![[11, 12, 10], [12, 13, 10], [13, 14, 10]]
        );
        assert_eq!(
            triangles(Mode::Triangles, &order[..3]).unwrap(),
            vec![[10, 11, 12]]
        );
        assert!(
            triangles(Mode::Triangles, &order)
                .unwrap_err()
                .contains("multiple of 3")
        );
        assert!(triangles(Mode::TriangleFan, &order[..2]).unwrap().is_empty());
    }
}
