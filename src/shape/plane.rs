//! The infinite plane `(X − P₀)·n = 0`.

use super::{Coordinates, Hit, Hittable, Intersection, Surface, SurfaceSample, flat_hit_error};
use crate::aabb::Aabb;
use crate::error::Result;
use crate::float::Float;
use crate::ray::Ray;
use crate::sampling::orthonormal_basis;
use crate::validate;
use crate::vec3::Vec3;

/// An infinite plane through the point `P₀` with unit normal `n`.
///
/// The front face is the side `n` points to: a ray coming from there gets a
/// [`Hit`] with `front_face == true`. The plane is the set `(X − P₀)·n = 0` for the
/// *stored* (rounded) `P₀` and `n`; the error bounds below are relative to that set.
///
/// Its surface coordinates are lengths along the plane from `P₀`: `u = (X − P₀)·s`,
/// `v = (X − P₀)·t`, `(s, t, n)` the orthonormal frame of
/// [`orthonormal_basis`]`(n)` (Mitsuba has no infinite plane to follow), so a texture
/// of period 1 repeats every unit of length.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Plane<F> {
    point: Vec3<F>,
    normal: Vec3<F>,
}

impl<F: Float> Plane<F> {
    /// The plane through `point` perpendicular to `normal` (any non-zero length; it is
    /// normalized). Rejects non-finite values and a (nearly) zero normal with
    /// [`Error::InvalidValue`](crate::Error::InvalidValue).
    pub fn new(point: Vec3<F>, normal: Vec3<F>) -> Result<Self> {
        Ok(Self {
            point: validate::finite_vec(crate::error::Field::PlanePoint, point)?,
            normal: validate::direction(crate::error::Field::PlaneNormal, normal)?,
        })
    }

    /// The point `P₀` the plane was built through.
    pub fn point(&self) -> Vec3<F> {
        self.point
    }

    /// The unit outward normal `n` (pointing to the front face).
    pub fn normal(&self) -> Vec3<F> {
        self.normal
    }

    /// This plane in scalar `G`, rounded through `f64` and re-validated, as [`EnumScene::cast`](crate::EnumScene::cast) explains.
    pub fn cast<G: Float>(&self) -> Result<Plane<G>> {
        Plane::new(self.point.cast(), self.normal.cast())
    }

    /// The ray parameter of the hit, `t = ((P₀ − O)·n) / (D·n)`, if it lies in
    /// `(0, t_max)` and `t > 0` is certain despite rounding.
    ///
    /// No hit when the ray is parallel to the plane (`D·n = 0`), nor when `D·n` or
    /// `(P₀ − O)·n` is smaller than its own rounding-error bound: then the side the ray
    /// travels towards (for a ray within about `γ(5)` radians of parallel), or the side
    /// its origin lies on (an origin within rounding of the plane), is rounding noise.
    /// This is the plane's version of pbrt-v4's conservative `t > 0` test (interval
    /// arithmetic for quadrics, `δt` for triangles): a reported hit has `t > 0` in exact
    /// arithmetic, because both signs are then exact. Together with the error bound of the
    /// hit point it makes [`Hit::spawn`] safe: a spawned origin lies strictly on the side
    /// its direction leaves towards, so the exact `t` is negative, and the test either
    /// computes both signs exactly (and sees `t < 0`) or reports no hit.
    ///
    /// # Precision
    /// `D·n` (three products, two sums) is within `γ(3)·Σ|Dᵢnᵢ|` of the exact value;
    /// `(P₀ − O)·n` adds one rounding for the difference, so it is within
    /// `γ(4)·Σ|P₀ᵢ − Oᵢ||nᵢ| ≤ γ(5)·Σ|fl(P₀ᵢ − Oᵢ)||nᵢ|`. A computed sign that differs from
    /// the exact one has a magnitude below these bounds. The tests use `γ(5)` and `γ(7)`:
    /// two more roundings cover the evaluation of the bounds themselves, which may round
    /// down.
    #[inline]
    pub fn crossing(&self, ray: &Ray<F>, t_max: F) -> Option<F> {
        let n = self.normal;
        let denom = ray.direction.dot(n);
        let denom_err = ray.direction.abs().dot(n.abs()) * F::gamma(5);
        let to_plane = self.point - ray.origin;
        let num = to_plane.dot(n);
        let num_err = to_plane.abs().dot(n.abs()) * F::gamma(7);
        // Written positively, so a NaN anywhere means "no hit".
        if !(denom.abs() > denom_err && num.abs() > num_err) {
            return None;
        }
        let t = num / denom;
        (t > F::zero() && t < t_max).then_some(t)
    }

    /// The hit at parameter `t`: the point `O + tD` with its rounding-error bound.
    ///
    /// # Precision
    /// The bound is [`flat_hit_error`]'s for the plane through `P₀` (the derivation is
    /// there): `t` comes from [`Plane::crossing`], `((P₀ − O)·n)/(D·n)`. The point is not
    /// projected onto the plane: that would not shrink a bound of this form, and costs a
    /// dot product and a multiply-add per hit.
    #[inline]
    fn hit_at(&self, ray: &Ray<F>, t: F) -> Hit<F> {
        let point = ray.origin + ray.direction * t;
        let error = flat_hit_error(ray, t, self.point);
        let surface = Surface {
            t,
            point,
            error,
            outward: self.normal,
            shading_normal: None,
        };
        Hit::new(surface, ray.direction)
    }
}

impl<F: Float> Hittable<F> for Plane<F> {
    #[inline]
    fn intersect(&self, ray: &Ray<F>, t_max: F) -> Option<Intersection<F>> {
        self.crossing(ray, t_max).map(Intersection::at)
    }

    #[inline]
    fn finish(&self, ray: &Ray<F>, hit: &Intersection<F>) -> Hit<F> {
        self.hit_at(ray, hit.t)
    }

    /// Lengths along the plane from `P₀` (see [`Plane`]).
    fn coordinates(&self, _: &Ray<F>, _: &Intersection<F>, record: &Hit<F>) -> Coordinates<F> {
        let (s, t) = orthonormal_basis(self.normal);
        let from_anchor = record.point - self.point;
        Coordinates {
            uv: [from_anchor.dot(s), from_anchor.dot(t)],
            dpdu: s,
        }
    }

    /// None: the plane is unbounded.
    #[inline]
    fn bounds(&self) -> Option<Aabb<F>> {
        None
    }

    #[inline]
    fn parts(&self) -> u32 {
        1
    }

    #[inline]
    fn part_bounds(&self, _: u32) -> Option<Aabb<F>> {
        None
    }

    #[inline]
    fn intersect_part(&self, _: u32, ray: &Ray<F>, t_max: F) -> Option<Intersection<F>> {
        self.intersect(ray, t_max)
    }

    /// None: an infinite area is not sampled as a light.
    fn area(&self) -> Option<F> {
        None
    }

    fn sample(&self, _: Vec3<F>, _: [f64; 3]) -> Option<SurfaceSample<F>> {
        None
    }

    fn pdf(&self, _: &Ray<F>, _: &Hit<F>) -> F {
        F::zero()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::float::lit;
    use crate::shape::Alone;

    /// The plane `z = −4` facing `+z`.
    fn floor<F: Float>() -> Plane<F> {
        Plane::new(Vec3::from_f64(1.0, -2.0, -4.0), Vec3::from_f64(0.0, 0.0, 2.0)).unwrap()
    }

    fn ray<F: Float>(o: &[f64; 3], d: &[f64; 3]) -> Ray<F> {
        Ray::new(Vec3::from_f64(o[0], o[1], o[2]), Vec3::from_f64(d[0], d[1], d[2]))
    }

    fn hits_from_the_front<F: Float>() {
        let p = floor::<F>();
        assert_eq!(p.normal(), Vec3::from_f64(0.0, 0.0, 1.0), "{}", F::NAME);
        let h = p
            .hit(&ray(&[0.0, 0.0, 0.0], &[0.0, 0.0, -1.0]), F::infinity())
            .unwrap();
        assert_eq!(h.t, lit(4.0), "{}", F::NAME);
        assert_eq!(h.point, Vec3::from_f64(0.0, 0.0, -4.0), "{}", F::NAME);
        assert_eq!(h.normal, Vec3::from_f64(0.0, 0.0, 1.0), "{}", F::NAME);
        assert!(h.front_face, "{}", F::NAME);
        assert!(
            h.error.min_element() > F::zero(),
            "{}: error bound {:?}",
            F::NAME,
            h.error
        );
    }

    fn hits_from_the_back<F: Float>() {
        let p = floor::<F>();
        let h = p
            .hit(&ray(&[3.0, 1.0, -10.0], &[0.0, 0.6, 0.8]), F::infinity())
            .unwrap();
        assert!(
            (h.t - lit(7.5)).abs() <= lit::<F>(7.5) * F::eps(),
            "{}: t = {}",
            F::NAME,
            h.t
        );
        assert!(!h.front_face, "{}", F::NAME);
        assert_eq!(h.normal, Vec3::from_f64(0.0, 0.0, -1.0), "{}", F::NAME);
    }

    fn misses_parallel_behind_and_beyond<F: Float>() {
        let p = floor::<F>();
        let inf = F::infinity();
        // Parallel above and in the plane.
        assert!(p.hit(&ray(&[0.0, 0.0, 0.0], &[1.0, 0.0, 0.0]), inf).is_none());
        assert!(p.hit(&ray(&[0.0, 0.0, -4.0], &[0.0, 1.0, 0.0]), inf).is_none());
        // Pointing away, from either side.
        assert!(p.hit(&ray(&[0.0, 0.0, 0.0], &[0.0, 0.6, 0.8]), inf).is_none());
        assert!(p.hit(&ray(&[0.0, 0.0, -5.0], &[0.0, 0.0, -1.0]), inf).is_none());
        // Origin on the plane: t = 0 is outside (0, t_max).
        assert!(p.hit(&ray(&[0.5, 0.0, -4.0], &[0.0, 0.0, -1.0]), inf).is_none());
        // t_max is exclusive.
        let down = ray(&[0.0, 0.0, 0.0], &[0.0, 0.0, -1.0]);
        assert!(p.hit(&down, lit(4.0)).is_none(), "{}", F::NAME);
        assert!(p.hit(&down, lit::<F>(4.0).next_up()).is_some(), "{}", F::NAME);
        assert!(!p.occluded(&down, lit(4.0)));
        assert!(p.occluded(&down, lit(4.5)));
        // NaN in the ray: no hit.
        let nan = Ray {
            origin: Vec3::new(F::nan(), F::zero(), F::zero()),
            direction: down.direction,
        };
        assert!(p.hit(&nan, inf).is_none());
    }

    fn rejects_invalid_values<F: Float>() {
        let o = Vec3::<F>::zero();
        let up = Vec3::from_f64(0.0, 1.0, 0.0);
        assert!(Plane::new(o, Vec3::zero()).is_err());
        assert!(Plane::new(o, Vec3::new(F::nan(), F::one(), F::zero())).is_err());
        assert!(Plane::new(o, Vec3::new(F::infinity(), F::one(), F::zero())).is_err());
        assert!(Plane::new(Vec3::new(F::zero(), F::nan(), F::zero()), up).is_err());
        let msg = Plane::new(o, Vec3::zero()).unwrap_err().to_string();
        assert!(msg.contains("plane normal"), "{msg}");
    }

    mod scalars {
        use crate::float::for_each_scalar;

        for_each_scalar!(
            hits_from_the_front,
            hits_from_the_back,
            misses_parallel_behind_and_beyond,
            rejects_invalid_values
        );
    }
}
