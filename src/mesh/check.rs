//! Validation shared by the formats: finite vertices, indices in range, fans of triangles
//! with area.
//!
//! The checks report a [`Problem`] numbered in the mesh handed to them; each format turns it
//! into a message in its own terms (a PLY element number, an OBJ line).

use super::MeshData;
use crate::vec3::Vec3;
use std::fmt;

/// Something that makes a mesh unusable, numbered from 0 in the order the reader gave.
#[derive(Clone, Debug, PartialEq)]
pub(super) enum Problem {
    /// A coordinate is NaN or infinite.
    NonFinite {
        /// The vertex.
        vertex: usize,
        /// `'x'`, `'y'` or `'z'`.
        axis: char,
        /// The coordinate itself.
        value: f64,
    },
    /// A face refers to a vertex that does not exist.
    IndexOutOfRange {
        /// The face.
        face: usize,
        /// The index as read (possibly negative for signed PLY types).
        index: i64,
        /// How many vertices the mesh has.
        vertices: usize,
    },
    /// A face with fewer than three vertices.
    TooFewVertices {
        /// The face.
        face: usize,
        /// How many it has.
        count: usize,
    },
    /// A vertex attribute (a normal's or a texture coordinate's component) is NaN or
    /// infinite.
    NonFiniteAttribute {
        /// The vertex.
        vertex: usize,
        /// The component, as the file names it: `nx`, `u`, …
        name: &'static str,
        /// The value itself.
        value: f64,
    },
    /// Every face was degenerate (or there were none).
    NoTriangles {
        /// How many faces were skipped for having no area.
        skipped: usize,
    },
}

/// The name of a non-finite value: `NaN`, `infinite` or `-infinite`.
fn describe(value: f64) -> &'static str {
    if value.is_nan() {
        "NaN"
    } else if value > 0.0 {
        "infinite"
    } else {
        "-infinite"
    }
}

impl fmt::Display for Problem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Self::NonFinite { vertex, axis, value } => {
                write!(f, "vertex {vertex}: coordinate {axis} is {}", describe(value))
            }
            Self::IndexOutOfRange {
                face,
                index,
                vertices,
            } => write!(
                f,
                "face {face}: vertex index {index} out of range (the mesh has {vertices} vertices)"
            ),
            Self::NonFiniteAttribute { vertex, name, value } => {
                write!(f, "vertex {vertex}: {name} is {}", describe(value))
            }
            Self::TooFewVertices { face, count } => {
                write!(f, "face {face}: {count} vertices (a face needs at least 3)")
            }
            Self::NoTriangles { skipped: 0 } => {
                f.write_str("no faces: the file holds no triangle or polygon of this format")
            }
            Self::NoTriangles { skipped } => {
                write!(f, "no triangles with area ({skipped} degenerate faces skipped)")
            }
        }
    }
}

/// Checks that every coordinate is finite; the first that is not is the problem.
pub(super) fn check_positions(positions: &[Vec3<f64>]) -> Result<(), Problem> {
    for (vertex, p) in positions.iter().enumerate() {
        for (axis, value) in [('x', p.x), ('y', p.y), ('z', p.z)] {
            if !value.is_finite() {
                return Err(Problem::NonFinite { vertex, axis, value });
            }
        }
    }
    Ok(())
}

/// Checks that every normal and texture coordinate is finite; the first that is not is the
/// problem, its component named as `names` (`["nx", "ny", "nz"]`, `["u", "v"]`) say.
pub(super) fn check_attributes(
    normals: Option<&[Vec3<f64>]>,
    uvs: Option<&[[f64; 2]]>,
    names: ([&'static str; 3], [&'static str; 2]),
) -> Result<(), Problem> {
    let bad = |vertex, name, value: f64| {
        (!value.is_finite()).then_some(Problem::NonFiniteAttribute { vertex, name, value })
    };
    for (vertex, n) in normals.unwrap_or_default().iter().enumerate() {
        for (name, value) in names.0.into_iter().zip([n.x, n.y, n.z]) {
            if let Some(p) = bad(vertex, name, value) {
                return Err(p);
            }
        }
    }
    for (vertex, uv) in uvs.unwrap_or_default().iter().enumerate() {
        for (name, value) in names.1.into_iter().zip(*uv) {
            if let Some(p) = bad(vertex, name, value) {
                return Err(p);
            }
        }
    }
    Ok(())
}

/// Builds the triangles of a mesh face by face, from checked positions.
pub(super) struct Triangulator {
    mesh: MeshData,
}

impl Triangulator {
    /// Starts a mesh on `positions`, which must have passed [`check_positions`].
    pub(super) fn new(positions: Vec<Vec3<f64>>) -> Self {
        Self {
            mesh: MeshData {
                positions,
                ..MeshData::default()
            },
        }
    }

    /// How many triangles are kept so far.
    pub(super) fn triangles(&self) -> u32 {
        // A mesh file of at most 4 GiB has fewer: each triangle takes a face index's bytes.
        u32::try_from(self.mesh.triangles.len()).unwrap_or(u32::MAX)
    }

    /// Adds face number `face` (its vertex indices in order) as a fan of triangles around its
    /// first vertex, skipping and counting those without area.
    ///
    /// A fan is exact for convex polygons, which is what mesh files hold in practice.
    pub(super) fn add_face(
        &mut self,
        face: usize,
        indices: impl ExactSizeIterator<Item = i64>,
    ) -> Result<(), Problem> {
        let count = indices.len();
        if count < 3 {
            return Err(Problem::TooFewVertices { face, count });
        }
        let vertices = self.mesh.positions.len();
        let mut checked = indices.map(|index| {
            usize::try_from(index)
                .ok()
                .filter(|&i| i < vertices)
                // The positions are indexed by u32, so a valid index always fits.
                .and_then(|i| u32::try_from(i).ok())
                .ok_or(Problem::IndexOutOfRange {
                    face,
                    index,
                    vertices,
                })
        });
        // `count >= 3`, so the first two exist.
        let (Some(first), Some(second)) = (checked.next(), checked.next()) else {
            return Err(Problem::TooFewVertices { face, count });
        };
        let (first, mut previous) = (first?, second?);
        for next in checked {
            let next = next?;
            self.push_triangle([first, previous, next]);
            previous = next;
        }
        Ok(())
    }

    /// Keeps `triangle` if it has area, else counts it as skipped.
    fn push_triangle(&mut self, triangle: [u32; 3]) {
        let [a, b, c] = triangle;
        let p = |i: u32| self.mesh.positions[i as usize];
        // A repeated index makes the cross product zero too; testing it first is cheaper.
        let degenerate =
            a == b || b == c || a == c || (p(b) - p(a)).cross(p(c) - p(a)) == Vec3::new(0.0, 0.0, 0.0);
        if degenerate {
            self.mesh.skipped_degenerate += 1;
        } else {
            self.mesh.triangles.push(triangle);
        }
    }

    /// The mesh, unless no triangle with area is left.
    pub(super) fn finish(self) -> Result<MeshData, Problem> {
        if self.mesh.triangles.is_empty() {
            return Err(Problem::NoTriangles {
                skipped: self.mesh.skipped_degenerate,
            });
        }
        Ok(self.mesh)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square() -> Vec<Vec3<f64>> {
        vec![
            Vec3::new(0.0, 0.0, 0.0),
            Vec3::new(1.0, 0.0, 0.0),
            Vec3::new(1.0, 1.0, 0.0),
            Vec3::new(0.0, 1.0, 0.0),
            Vec3::new(2.0, 0.0, 0.0),
        ]
    }

    #[test]
    fn a_quad_is_a_fan_of_two() {
        let mut t = Triangulator::new(square());
        t.add_face(0, [0, 1, 2, 3].into_iter()).unwrap();
        let mesh = t.finish().unwrap();
        assert_eq!(mesh.triangles, vec![[0, 1, 2], [0, 2, 3]]);
        assert_eq!(mesh.skipped_degenerate, 0);
    }

    #[test]
    fn repeated_and_collinear_triangles_are_skipped() {
        let mut t = Triangulator::new(square());
        t.add_face(0, [0, 0, 1].into_iter()).unwrap();
        t.add_face(1, [0, 1, 4].into_iter()).unwrap();
        t.add_face(2, [0, 1, 2].into_iter()).unwrap();
        let mesh = t.finish().unwrap();
        assert_eq!(mesh.triangles, vec![[0, 1, 2]]);
        assert_eq!(mesh.skipped_degenerate, 2);
    }

    #[test]
    fn bad_faces_are_named() {
        let mut t = Triangulator::new(square());
        let out = t.add_face(7, [0, 1, 9000].into_iter()).unwrap_err();
        assert_eq!(
            out.to_string(),
            "face 7: vertex index 9000 out of range (the mesh has 5 vertices)"
        );
        let negative = t.add_face(8, [-1, 1, 2].into_iter()).unwrap_err();
        assert!(matches!(negative, Problem::IndexOutOfRange { index: -1, .. }));
        let short = t.add_face(3, [0, 1].into_iter()).unwrap_err();
        assert_eq!(short, Problem::TooFewVertices { face: 3, count: 2 });
    }

    #[test]
    fn only_degenerate_faces_is_an_error() {
        let mut t = Triangulator::new(square());
        t.add_face(0, [0, 1, 4].into_iter()).unwrap();
        assert_eq!(t.finish(), Err(Problem::NoTriangles { skipped: 1 }));
    }

    #[test]
    fn non_finite_coordinates_are_named() {
        let mut positions = square();
        positions[3].y = f64::NAN;
        let problem = check_positions(&positions).unwrap_err();
        assert_eq!(problem.to_string(), "vertex 3: coordinate y is NaN");
        positions[3].y = 0.0;
        positions[1].z = f64::NEG_INFINITY;
        let problem = check_positions(&positions).unwrap_err();
        assert_eq!(problem.to_string(), "vertex 1: coordinate z is -infinite");
        positions[1].z = 0.0;
        assert_eq!(check_positions(&positions), Ok(()));
    }
}
