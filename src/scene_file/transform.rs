//! Placing a mesh: its vertices scaled, then rotated, then translated.

use crate::transform::Affine;
use crate::vec3::Vec3;

/// A mesh's placement in the scene: `p ↦ T + Rz·Ry·Rx·(S ∘ p)`, that is scale by `S` per
/// axis, rotate about x, then y, then z (degrees, counter-clockwise looking down each axis
/// towards the origin: the right-hand rule), then translate by `T`.
///
/// Or, from a Mitsuba scene's `to_world`, any invertible affine map ([`Placement::map`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Placement {
    scale: [f64; 3],
    // (sin, cos) of each rotation, computed once for all vertices.
    turns: [(f64, f64); 3],
    translate: [f64; 3],
    /// A whole map instead, with the inverse transpose of its linear part for normals.
    map: Option<(Affine, [[f64; 3]; 3])>,
}

impl Placement {
    /// The placement with scale factors, rotations in degrees and a translation.
    pub fn new(scale: [f64; 3], rotate_degrees: [f64; 3], translate: [f64; 3]) -> Self {
        Self {
            scale,
            turns: rotate_degrees.map(|d| d.to_radians().sin_cos()),
            translate,
            map: None,
        }
    }

    /// The placement by the invertible map `map`.
    ///
    /// # Errors
    /// [`Error::InvalidValue`](crate::Error::InvalidValue) ([`Field::Transform`](crate::error::Field::Transform))
    /// if the map cannot be inverted.
    pub fn map(map: Affine) -> crate::Result<Self> {
        let inverse = map.inverse().ok_or_else(|| {
            crate::Error::invalid(
                crate::error::Field::Transform,
                "the map flattens space: it has no inverse",
            )
        })?;
        let r = inverse.rows();
        let normals = [0, 1, 2].map(|i| [r[0][i], r[1][i], r[2][i]]);
        Ok(Self {
            map: Some((map, normals)),
            ..Self::new([1.0; 3], [0.0; 3], [0.0; 3])
        })
    }

    /// Where the vertex `p` of the mesh file lands in the scene.
    pub fn apply(&self, p: Vec3<f64>) -> Vec3<f64> {
        if let Some((map, _)) = &self.map {
            let [x, y, z] = map.point([p.x, p.y, p.z]);
            return Vec3::new(x, y, z);
        }
        let [sx, sy, sz] = self.scale;
        let [tx, ty, tz] = self.translate;
        let r = self.rotate(Vec3::new(p.x * sx, p.y * sy, p.z * sz));
        Vec3::new(r.x + tx, r.y + ty, r.z + tz)
    }

    /// The direction a normal `n` of the mesh file takes in the scene (not of unit length):
    /// the inverse transpose of the linear part `R·S`, which is `R·S⁻¹` (`R` a rotation,
    /// `S` diagonal), so that it stays perpendicular to the placed surface under a
    /// non-uniform scale. A zero normal stays zero.
    pub fn apply_normal(&self, n: Vec3<f64>) -> Vec3<f64> {
        if let Some((_, m)) = &self.map {
            let [x, y, z] = m.map(|r| r[0] * n.x + r[1] * n.y + r[2] * n.z);
            return Vec3::new(x, y, z);
        }
        let [sx, sy, sz] = self.scale;
        self.rotate(Vec3::new(n.x / sx, n.y / sy, n.z / sz))
    }

    /// `Rz·Ry·Rx·v`.
    fn rotate(&self, v: Vec3<f64>) -> Vec3<f64> {
        let (x, y, z) = (v.x, v.y, v.z);
        let [(s, c), _, _] = self.turns;
        let (y, z) = (y * c - z * s, y * s + z * c);
        let [_, (s, c), _] = self.turns;
        let (z, x) = (z * c - x * s, z * s + x * c);
        let [_, _, (s, c)] = self.turns;
        let (x, y) = (x * c - y * s, x * s + y * c);
        Vec3::new(x, y, z)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: Vec3<f64>, b: Vec3<f64>) -> bool {
        (a - b).length() < 1e-12
    }

    #[test]
    fn each_axis_turns_by_the_right_hand_rule() {
        let (x, y, z) = (
            Vec3::new(1.0, 0.0, 0.0),
            Vec3::new(0.0, 1.0, 0.0),
            Vec3::new(0.0, 0.0, 1.0),
        );
        let turn = |r| Placement::new([1.0; 3], r, [0.0; 3]);
        assert!(close(turn([90.0, 0.0, 0.0]).apply(y), z));
        assert!(close(turn([0.0, 90.0, 0.0]).apply(z), x));
        assert!(close(turn([0.0, 0.0, 90.0]).apply(x), y));
        assert!(close(turn([0.0, 0.0, 90.0]).apply(y), -x));
    }

    #[test]
    fn scale_then_x_then_y_then_z_then_translate() {
        // Scaling x by 2 before turning: (1, 0, 0) → (2, 0, 0); 90° about x leaves it;
        // 90° about y takes x to −z; 90° about z leaves −z; then the translation.
        let p = Placement::new([2.0, 3.0, 4.0], [90.0, 90.0, 90.0], [10.0, 20.0, 30.0]);
        assert!(close(
            p.apply(Vec3::new(1.0, 0.0, 0.0)),
            Vec3::new(10.0, 20.0, 28.0)
        ));
        // (0, 1, 0) → (0, 3, 0) → about x: (0, 0, 3) → about y: (3, 0, 0) → about z: (0, 3, 0).
        assert!(close(
            p.apply(Vec3::new(0.0, 1.0, 0.0)),
            Vec3::new(10.0, 23.0, 30.0)
        ));
        // The other order would differ: x first then z puts (0, 1, 0) elsewhere.
        let z_only = Placement::new([1.0; 3], [0.0, 0.0, 90.0], [0.0; 3]);
        let x_only = Placement::new([1.0; 3], [90.0, 0.0, 0.0], [0.0; 3]);
        let zx = x_only.apply(z_only.apply(Vec3::new(0.0, 1.0, 0.0)));
        let xz = z_only.apply(x_only.apply(Vec3::new(0.0, 1.0, 0.0)));
        assert!(!close(zx, xz));
        let both = Placement::new([1.0; 3], [90.0, 0.0, 90.0], [0.0; 3]);
        assert!(close(both.apply(Vec3::new(0.0, 1.0, 0.0)), xz));
    }

    #[test]
    fn normals_stay_perpendicular_under_a_non_uniform_scale() {
        // The plane x + y = 1 (normal (1, 1, 0)), stretched along x by 3 and turned.
        let p = Placement::new([3.0, 1.0, 0.5], [10.0, 20.0, 30.0], [1.0, 2.0, 3.0]);
        let (a, b) = (Vec3::new(1.0, 0.0, 0.0), Vec3::new(0.0, 1.0, 0.0));
        let c = Vec3::new(0.3, 0.7, 2.0);
        let n = p.apply_normal(Vec3::new(1.0, 1.0, 0.0));
        for edge in [p.apply(b) - p.apply(a), p.apply(c) - p.apply(a)] {
            assert!(n.dot(edge).abs() < 1e-12, "{}", n.dot(edge));
        }
        // The plain linear map would not be: (3, 1, 0) is not perpendicular to the stretched edge.
        let wrong = p.apply(Vec3::new(1.0, 1.0, 0.0)) - p.apply(Vec3::zero());
        assert!(wrong.dot(p.apply(b) - p.apply(a)).abs() > 1.0);
        assert_eq!(p.apply_normal(Vec3::zero()), Vec3::zero());
    }

    #[test]
    fn identity_keeps_every_bit() {
        let p = Placement::new([1.0; 3], [0.0; 3], [0.0; 3]);
        let v = Vec3::new(0.1, -2.5e-7, 3.3e12);
        assert_eq!(p.apply(v), v);
    }
}
