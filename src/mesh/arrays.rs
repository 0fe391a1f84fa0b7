//! A mesh from arrays another reader decoded (a glTF primitive's accessors), put through
//! the checks a mesh file gets: finite vertices and attributes, indices in range,
//! triangles with area.

use super::MeshData;
use super::check::{Triangulator, check_attributes, check_positions};
use crate::vec3::Vec3;

/// The mesh of `positions`, with a normal and texture coordinates per vertex if given, and
/// the triangles `triangles` (indices into `positions`, as read: possibly out of range).
/// Triangles without area are skipped and counted, as a mesh file's are.
///
/// # Errors
/// A message naming the problem: an attribute array of another length than the positions,
/// a coordinate or attribute that is NaN or infinite (`vertex 3: coordinate y is NaN`,
/// `vertex 2: normal x is infinite`), an index past the vertices (`face 7: vertex index 9
/// out of range`), or no triangle with area. Vertices and faces count from 0.
pub fn from_arrays(
    positions: Vec<Vec3<f64>>,
    normals: Option<Vec<Vec3<f64>>>,
    uvs: Option<Vec<[f64; 2]>>,
    triangles: impl Iterator<Item = [u32; 3]>,
) -> Result<MeshData, String> {
    let count = positions.len();
    for (name, len) in [
        ("normals", normals.as_ref().map(Vec::len)),
        ("texture coordinates", uvs.as_ref().map(Vec::len)),
    ] {
        if let Some(len) = len.filter(|&l| l != count) {
            return Err(format!("{len} {name} for {count} vertices: one per vertex"));
        }
    }
    check_positions(&positions).map_err(|p| p.to_string())?;
    let names = (["normal x", "normal y", "normal z"], ["u", "v"]);
    check_attributes(normals.as_deref(), uvs.as_deref(), names).map_err(|p| p.to_string())?;
    let mut t = Triangulator::new(positions);
    for (face, triangle) in triangles.enumerate() {
        t.add_face(face, triangle.into_iter().map(i64::from))
            .map_err(|p| p.to_string())?;
    }
    let mut mesh = t.finish().map_err(|p| p.to_string())?;
    mesh.normals = normals;
    mesh.uvs = uvs;
    Ok(mesh)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn quad() -> Vec<Vec3<f64>> {
        vec![
            Vec3::new(0.0, 0.0, 0.0),
            Vec3::new(1.0, 0.0, 0.0),
            Vec3::new(1.0, 1.0, 0.0),
            Vec3::new(0.0, 1.0, 0.0),
        ]
    }

    #[test]
    fn arrays_become_a_mesh_with_its_attributes() {
        let uvs = vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        let mesh = from_arrays(
            quad(),
            None,
            Some(uvs.clone()),
            [[0, 1, 2], [0, 2, 2]].into_iter(),
        )
        .unwrap();
        assert_eq!(mesh.triangles, vec![[0, 1, 2]]);
        assert_eq!(mesh.skipped_degenerate, 1);
        assert_eq!(mesh.uvs, Some(uvs));
    }

    #[test]
    fn bad_arrays_are_named() {
        let e = from_arrays(
            quad(),
            Some(vec![Vec3::new(0.0, 0.0, 1.0)]),
            None,
            [[0, 1, 2]].into_iter(),
        );
        assert_eq!(e.unwrap_err(), "1 normals for 4 vertices: one per vertex");
        let e = from_arrays(quad(), None, None, [[0, 1, 4]].into_iter());
        assert!(e.unwrap_err().contains("face 0: vertex index 4 out of range"));
        let mut n = vec![Vec3::new(0.0, 0.0, 1.0); 4];
        n[2].x = f64::INFINITY;
        let e = from_arrays(quad(), Some(n), None, [[0, 1, 2]].into_iter());
        assert_eq!(e.unwrap_err(), "vertex 2: normal x is infinite");
    }
}
