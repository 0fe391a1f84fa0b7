//! Mitsuba 3 shades a mesh whose file holds no normals smooth: each vertex takes the unit
//! normals of the triangles around it, each weighted by the triangle's angle at that vertex
//! (Thürmer and Wüthrich's weighting), computed where the mesh is placed. The importer
//! gives such a mesh the same normals, held in memory ([`SceneFile::assets`]), so that it
//! renders as Mitsuba renders it (found by the cross-check: `validate/xml/outdoor.xml`'s
//! crates were 30 standard errors apart when shaded with their faces' normals).
//!
//! [`SceneFile::assets`]: crate::scene_file::SceneFile::assets

use super::convert::Importer;
use crate::mesh::MeshData;
use crate::transform::Affine;
use crate::vec3::Vec3;

impl Importer {
    /// The name under which the mesh file `file`, placed by `to_world`, is held in memory
    /// with Mitsuba's vertex normals, if its file has none; `None` if it has normals or
    /// cannot be read (the build then reads the file itself, and says why it cannot).
    pub(super) fn smooth_mesh(&mut self, file: &str, to_world: &Affine) -> Option<String> {
        let path = self.located(file);
        if super::shading::declares_normals(&path) != Some(false) {
            return None;
        }
        let mut mesh = crate::mesh::load(&path).ok()?;
        mesh.normals = Some(placed_normals(&mesh, to_world));
        self.smoothed += 1;
        let name = format!("{}#smooth{}", self.path_of(file), self.smoothed);
        self.assets.insert_mesh(name.clone(), mesh);
        self.assets.add_source(&path);
        Some(name)
    }
}

/// The vertex normals of `mesh` as Mitsuba computes them for the mesh placed by `to_world`,
/// written in the file's coordinates: `Lᵀ·n` for the scene's normal `n` (`L` the map's
/// linear part), which the build's `L⁻ᵀ` turns back into `n`.
fn placed_normals(mesh: &MeshData, to_world: &Affine) -> Vec<Vec3<f64>> {
    let placed: Vec<Vec3<f64>> = mesh
        .positions
        .iter()
        .map(|p| {
            let [x, y, z] = to_world.point(p.to_f64());
            Vec3::new(x, y, z)
        })
        .collect();
    let r = to_world.rows();
    vertex_normals(&placed, &mesh.triangles)
        .into_iter()
        .map(|n| {
            let [x, y, z] = [0, 1, 2].map(|j| r[0][j] * n.x + r[1][j] * n.y + r[2][j] * n.z);
            Vec3::new(x, y, z)
        })
        .collect()
}

/// Unit vertex normals of the triangles `triangles` over `positions`: at each vertex the sum
/// of its triangles' unit normals, each times the triangle's angle there,
/// `n_v ∝ Σ α_v(t)·n̂(t)`, normalised. A vertex no triangle with area uses keeps a zero
/// normal (a triangle with one shades with its face's normal).
pub(super) fn vertex_normals(positions: &[Vec3<f64>], triangles: &[[u32; 3]]) -> Vec<Vec3<f64>> {
    let mut sum = vec![Vec3::zero(); positions.len()];
    for t in triangles {
        let p = t.map(|i| positions[i as usize]);
        let Some(n) = (p[1] - p[0]).cross(p[2] - p[0]).try_normalize() else {
            continue;
        };
        for k in 0..3 {
            let angle = unit_angle(p[(k + 1) % 3] - p[k], p[(k + 2) % 3] - p[k]);
            sum[t[k] as usize] = sum[t[k] as usize] + n * angle;
        }
    }
    sum.into_iter().map(|n| n.try_normalize().unwrap_or(n)).collect()
}

/// The angle between `a` and `b`, in radians (zero if either is zero). From the chord
/// between the unit vectors, `2·asin(|â − b̂|/2)`, or `π − 2·asin(|â + b̂|/2)` past a right
/// angle: accurate where `acos` of the dot product is not (near 0 and π).
fn unit_angle(a: Vec3<f64>, b: Vec3<f64>) -> f64 {
    let (Some(a), Some(b)) = (a.try_normalize(), b.try_normalize()) else {
        return 0.0;
    };
    if a.dot(b) >= 0.0 {
        2.0 * ((a - b).length() / 2.0).min(1.0).asin()
    } else {
        std::f64::consts::PI - 2.0 * ((a + b).length() / 2.0).min(1.0).asin()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The cube `[−1, 1]³` as twelve triangles sharing its eight corners.
    fn cube() -> (Vec<Vec3<f64>>, Vec<[u32; 3]>) {
        let corners = (0..8)
            .map(|i| Vec3::new([-1.0, 1.0][i & 1], [-1.0, 1.0][(i >> 1) & 1], [-1.0, 1.0][i >> 2]))
            .collect();
        // Each face's corners counter-clockwise seen from outside.
        let faces = [
            [0, 2, 3, 1],
            [4, 5, 7, 6],
            [0, 1, 5, 4],
            [2, 6, 7, 3],
            [0, 4, 6, 2],
            [1, 3, 7, 5],
        ];
        let triangles = faces
            .iter()
            .flat_map(|&[a, b, c, d]| [[a, b, c], [a, c, d]])
            .collect();
        (corners, triangles)
    }

    /// Each corner of a cube meets three faces at a right angle each, whichever way a face
    /// is split: its normal points along the diagonal (an unweighted sum would not: a corner
    /// on two triangles of one face and one of another leans towards the first).
    #[test]
    fn a_cubes_corners_point_along_its_diagonals() {
        let (corners, triangles) = cube();
        let normals = vertex_normals(&corners, &triangles);
        for (p, n) in corners.iter().zip(&normals) {
            let want = *p / 3f64.sqrt();
            assert!((*n - want).length() < 1e-12, "{p:?}: {n:?}");
        }
    }

    #[test]
    fn angles_are_exact_at_both_ends() {
        let x = Vec3::new(1.0, 0.0, 0.0);
        assert_eq!(unit_angle(x, x * 3.0), 0.0);
        assert!((unit_angle(x, -x) - std::f64::consts::PI).abs() < 1e-15);
        let tiny = Vec3::new(1.0, 1e-9, 0.0);
        assert!((unit_angle(x, tiny) - 1e-9).abs() < 1e-20);
        assert!((unit_angle(x, Vec3::new(0.0, 2.0, 0.0)) - std::f64::consts::FRAC_PI_2).abs() < 1e-15);
        assert_eq!(unit_angle(x, Vec3::new(0.0, 0.0, 0.0)), 0.0);
    }

    /// Under a non-uniform scale the normals are those of the placed (stretched) surface,
    /// carried back so that the build's inverse transpose returns them.
    #[test]
    fn normals_are_computed_where_the_mesh_is_placed() {
        let (corners, triangles) = cube();
        let mesh = MeshData {
            positions: corners.clone(),
            triangles,
            ..MeshData::default()
        };
        let to_world = Affine::scale([4.0, 1.0, 1.0]);
        let carried = placed_normals(&mesh, &to_world);
        let placed: Vec<Vec3<f64>> = corners.iter().map(|p| Vec3::new(4.0 * p.x, p.y, p.z)).collect();
        let want = vertex_normals(&placed, &mesh.triangles);
        for (c, w) in carried.iter().zip(&want) {
            // The build's map for normals: L⁻ᵀ = diag(1/4, 1, 1).
            let back = Vec3::new(c.x / 4.0, c.y, c.z).try_normalize().unwrap();
            assert!((back - *w).length() < 1e-12, "{back:?} {w:?}");
        }
        // Still a box's corner, each face at a right angle: the diagonal, here too.
        assert!((want[7] - Vec3::new(1.0, 1.0, 1.0) / 3f64.sqrt()).length() < 1e-12);
    }
}
