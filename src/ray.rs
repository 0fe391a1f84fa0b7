//! `Ray<F>`: `R(t) = O + t·D` for `t > 0`.

use crate::float::Float;
use crate::vec3::Vec3;

/// A half-line `R(t) = O + t·D`, `t > 0`, with a unit direction `D`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ray<F> {
    /// The origin `O`.
    pub origin: Vec3<F>,
    /// The unit direction `D`.
    pub direction: Vec3<F>,
}

impl<F: Float> Ray<F> {
    /// A ray from `origin` along `direction`.
    ///
    /// `direction` must be unit length (checked in debug builds to within `1e-3`
    /// relative, loose enough for f32 rounding). Use [`Ray::towards`] to aim at a point.
    #[inline]
    pub fn new(origin: Vec3<F>, direction: Vec3<F>) -> Self {
        debug_assert!(
            (direction.length_squared() - F::one()).abs() < crate::float::lit(1e-3),
            "ray direction {direction:?} is not unit length"
        );
        Self { origin, direction }
    }

    /// The ray from `origin` through `target`, `D = (target − O)/|target − O|`;
    /// `None` when the two points coincide.
    #[inline]
    pub fn towards(origin: Vec3<F>, target: Vec3<F>) -> Option<Self> {
        (target - origin)
            .try_normalize()
            .map(|direction| Self { origin, direction })
    }

    /// The point `R(t) = O + t·D`.
    #[inline]
    pub fn at(&self, t: F) -> Vec3<F> {
        self.origin + self.direction * t
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn at_walks_along_the_direction() {
        let r = Ray::new(Vec3::new(1.0, 2.0, 3.0), Vec3::new(0.0, 0.0, -1.0));
        assert_eq!(r.at(0.0), r.origin);
        assert_eq!(r.at(2.5), Vec3::new(1.0, 2.0, 0.5));
    }

    #[test]
    fn towards_normalizes_and_rejects_coincident_points() {
        let o = Vec3::new(0.0f32, 0.0, 0.0);
        let r = Ray::towards(o, Vec3::new(0.0, 3.0, 4.0)).unwrap();
        assert_eq!(r.direction, Vec3::new(0.0, 0.6, 0.8));
        assert!(Ray::towards(o, o).is_none());
    }
}
