//! A local orthonormal frame at a surface point: where a BSDF works, with the normal as
//! `z` so that `cos θ = w.z`.

use crate::float::{Float, lit};
use crate::sampling::orthonormal_basis;
use crate::vec3::Vec3;

/// A right-handed orthonormal frame `(s, t, n)`: `n` the normal (local `z`), `s` the
/// tangent (local `x`, the direction of `∂p/∂u` where the surface has one) and
/// `t = n × s` (local `y`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frame<F> {
    /// The tangent, local `x`.
    pub s: Vec3<F>,
    /// The bitangent `n × s`, local `y`.
    pub t: Vec3<F>,
    /// The normal, local `z`.
    pub n: Vec3<F>,
}

impl<F: Float> Frame<F> {
    /// The frame about the unit normal `n` whose tangent is `dpdu` made perpendicular to
    /// it (Gram–Schmidt, `s ∝ dpdu − n(n·dpdu)`); where that leaves too little of
    /// `dpdu` to normalise (zero, or along `n`), the tangent of [`orthonormal_basis`].
    #[inline]
    pub fn new(n: Vec3<F>, dpdu: Vec3<F>) -> Self {
        let across = dpdu - n * n.dot(dpdu);
        // Below this the subtraction has cancelled to noise: |across| ≤ ~ε|dpdu|.
        let enough = across.length_squared() > dpdu.length_squared() * F::eps() * F::eps() * lit(1e4);
        let s = match across.try_normalize() {
            Some(s) if enough => s,
            _ => orthonormal_basis(n).0,
        };
        Self { s, t: n.cross(s), n }
    }

    /// The frame of [`orthonormal_basis`] about the unit `n`.
    #[inline]
    pub fn from_normal(n: Vec3<F>) -> Self {
        let (s, t) = orthonormal_basis(n);
        Self { s, t, n }
    }

    /// `w` in local coordinates: `(w·s, w·t, w·n)`.
    #[inline]
    pub fn to_local(&self, w: Vec3<F>) -> Vec3<F> {
        Vec3::new(w.dot(self.s), w.dot(self.t), w.dot(self.n))
    }

    /// The local vector `v` in world coordinates: `vₓs + v_y t + v_z n`.
    #[inline]
    pub fn to_world(&self, v: Vec3<F>) -> Vec3<F> {
        self.s * v.x + self.t * v.y + self.n * v.z
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_trips_and_keeps_the_tangent() {
        let n = Vec3::new(0.3f64, -0.5, 0.8).normalize();
        let dpdu = Vec3::new(1.0f64, 2.0, 0.5);
        let f = Frame::new(n, dpdu);
        assert!((f.s.dot(f.n)).abs() < 1e-15 && (f.t.dot(f.n)).abs() < 1e-15);
        assert!((f.s.length() - 1.0).abs() < 1e-15 && (f.t.length() - 1.0).abs() < 1e-15);
        // s points along the part of dpdu in the plane.
        assert!(f.s.dot(dpdu) > 0.0);
        let w = Vec3::new(-0.2f64, 0.9, 0.1);
        let back = f.to_world(f.to_local(w));
        assert!((back - w).length() < 1e-15);
        assert!((f.to_local(n).z - 1.0).abs() < 1e-15);
    }

    #[test]
    fn a_tangent_along_the_normal_or_zero_falls_back() {
        let n = Vec3::new(0.0f64, 0.0, 1.0);
        for dpdu in [Vec3::zero(), n * 3.0, Vec3::new(1e-30, 0.0, 1.0)] {
            let f = Frame::new(n, dpdu);
            assert_eq!(f, Frame::from_normal(n), "{dpdu:?}");
        }
    }
}
