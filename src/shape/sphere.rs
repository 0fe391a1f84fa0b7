//! The sphere `|X − C|² = r²`.

use super::{
    Coordinates, Hit, Hittable, Intersection, Surface, SurfaceSample, area_to_solid_angle, hit_solid_angle,
};
use crate::aabb::Aabb;
use crate::error::Result;
use crate::float::{Float, lit, to};
use crate::ray::Ray;
use crate::sampling::{orthonormal_basis, uniform_sphere};
use crate::validate;
use crate::vec3::Vec3;
use std::f64::consts::{PI, TAU};

/// A sphere with centre `C` and radius `r > 0`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sphere<F> {
    center: Vec3<F>,
    radius: F,
}

impl<F: Float> Sphere<F> {
    /// A sphere; rejects a non-finite centre and a radius that is not finite and `> 0`.
    pub fn new(center: Vec3<F>, radius: F) -> Result<Self> {
        Ok(Self {
            center: validate::finite_vec(crate::error::Field::SphereCenter, center)?,
            radius: validate::positive(crate::error::Field::SphereRadius, radius)?,
        })
    }

    /// The centre `C`.
    pub fn center(&self) -> Vec3<F> {
        self.center
    }

    /// The radius `r`.
    pub fn radius(&self) -> F {
        self.radius
    }

    /// This sphere in scalar `G`, rounded through `f64` and re-validated, as [`EnumScene::cast`](crate::EnumScene::cast) explains.
    pub fn cast<G: Float>(&self) -> Result<Sphere<G>> {
        Sphere::new(self.center.cast(), to(self.radius))
    }

    /// Both roots of `|O + tD − C|² = r²` (unit `D`), nearer first, or `None` if the ray
    /// misses the sphere's carrier.
    ///
    /// With `f = O − C` and `b = f·D` the roots are `t = −b ± √(r² − |f − bD|²)`.
    /// Two numerical choices make this stable where the textbook form fails (Haines et
    /// al., *Ray Tracing Gems* ch. 7):
    /// - the discriminant is `r² − |f − bD|²` (the squared distance from the centre to
    ///   the ray's line) instead of `b² − (|f|² − r²)`, which cancels catastrophically
    ///   when `|f| ≫ r` (a small sphere far away);
    /// - the root of larger magnitude is `q = −b − sign(b)√Δ` (no cancellation) and the
    ///   other is `c/q` with `c = |f|² − r²` (Vieta), instead of `−b ± √Δ`.
    #[inline]
    pub fn roots(&self, ray: &Ray<F>) -> Option<(F, F)> {
        let f = ray.origin - self.center;
        let b = f.dot(ray.direction);
        let c = f.length_squared() - self.radius * self.radius;
        let l = f - ray.direction * b;
        let disc = self.radius * self.radius - l.length_squared();
        if disc < F::zero() {
            return None;
        }
        let sqrt_d = disc.sqrt();
        let q = if b > F::zero() { -b - sqrt_d } else { -b + sqrt_d };
        let other = if q == F::zero() { F::zero() } else { c / q };
        Some(if q < other { (q, other) } else { (other, q) })
    }

    /// The hit at parameter `t` (a root from [`Sphere::roots`]), with the point moved back
    /// onto the surface and its rounding-error bound: what [`Hittable::finish`] reports.
    ///
    /// # Precision
    /// pbrt-v4 §6.8.5: after reprojection `p ← C + (p − C)·r/|p − C|` each component of
    /// the local point `p − C` is within `γ(5)|p − C|` of the true surface point; adding `C`
    /// back (exact, it is the stored centre) costs one more rounding, at most `γ(1)|p|`. So
    /// the bound per component is `γ(5)|p − C| + γ(1)|p|`; we use `γ(6)|p − C| + γ(2)|p|`,
    /// since the tests see the tighter bound reached to 96 % in the worst of 10⁵ rays.
    #[inline]
    fn hit_at(&self, ray: &Ray<F>, t: F) -> Hit<F> {
        let l = ray.at(t) - self.center;
        let len = l.length();
        let local = l * (self.radius / len);
        let point = self.center + local;
        let error = local.abs() * F::gamma(6) + point.abs() * F::gamma(2);
        // The normal `l/|l|` rather than `local/r`: the two divisions run side by side
        // instead of one after the other on the path's critical chain.
        let outward = l * (F::one() / len);
        let surface = Surface {
            t,
            point,
            error,
            outward,
            shading_normal: None,
        };
        Hit::new(surface, ray.direction)
    }

    /// The surface area `4πr²`.
    #[inline]
    fn surface(&self) -> F {
        lit::<F>(4.0 * PI) * self.radius * self.radius
    }

    /// Whether `p` lies inside the sphere or on it, where it sees no cone but the whole
    /// sphere around it.
    #[inline]
    fn encloses(&self, p: Vec3<F>) -> bool {
        (p - self.center).length_squared() <= self.radius * self.radius
    }

    /// `1 − cos θ_max` of the cone of directions from a point at squared distance `d2`
    /// from the centre that meet the sphere, `sin²θ_max = r²/d²`: computed as
    /// `sin²θ_max/(1 + cos θ_max)`, which equals it without the cancellation of
    /// `1 − cos θ_max` for a small or far sphere (where pbrt-v4 switches to a Taylor
    /// expansion below `sin²θ_max = sin²1.5°`).
    #[inline]
    fn cone(&self, d2: F) -> (F, F) {
        let sin2_max = self.radius * self.radius / d2;
        let cos_max = (F::one() - sin2_max).max(F::zero()).sqrt();
        (sin2_max, sin2_max / (F::one() + cos_max))
    }

    /// A direction of the cone from `from`, uniform in solid angle (pbrt-v4's
    /// `Sphere::Sample`), as the visible point it reaches: with `x = 1 − cos θ = u₀(1 − cos θ_max)`,
    /// `sin²θ = x(2 − x)`, `φ = 2πu₁`, the point is at the angle `α` from the centre's
    /// direction to `from`, `cos α = sin²θ/sin θ_max + cos θ·√(1 − sin²θ/sin²θ_max)`
    /// (the nearer intersection of that direction with the sphere). Density
    /// `1/(2π(1 − cos θ_max))`.
    fn sample_cone(&self, from: Vec3<F>, u: [f64; 2]) -> SurfaceSample<F> {
        let axis = self.center - from;
        let d2 = axis.length_squared();
        let (sin2_max, one_minus_cos_max) = self.cone(d2);
        let x = lit::<F>(u[0]) * one_minus_cos_max;
        let (cos_t, sin2_t) = (F::one() - x, x * (lit::<F>(2.0) - x));
        let sin_max = sin2_max.sqrt();
        let cos_a = sin2_t / sin_max + cos_t * (F::one() - sin2_t / sin2_max).max(F::zero()).sqrt();
        let sin_a = (F::one() - cos_a * cos_a).max(F::zero()).sqrt();
        let (sin_p, cos_p) = (TAU * u[1]).sin_cos();
        let w = axis / d2.sqrt();
        let (t, b) = orthonormal_basis(w);
        let normal = -(t * (sin_a * lit(cos_p)) + b * (sin_a * lit(sin_p)) + w * cos_a);
        SurfaceSample {
            point: self.center + normal * self.radius,
            normal,
            part: 0,
            pdf: F::one() / (lit::<F>(TAU) * one_minus_cos_max),
        }
    }
}

impl<F: Float> Hittable<F> for Sphere<F> {
    /// The nearer root in `(0, t_max)`; [`Sphere4`](super::Sphere4) gives the same `t` four
    /// spheres at a time.
    #[inline]
    fn intersect(&self, ray: &Ray<F>, t_max: F) -> Option<Intersection<F>> {
        let f = ray.origin - self.center;
        let (b, c) = (
            f.dot(ray.direction),
            f.length_squared() - self.radius * self.radius,
        );
        // Outside (`c > 0`) and heading away (`b > 0`): both roots are negative, so skip the
        // square root and the division (one branch for both tests, `&` not `&&`).
        if (c > F::zero()) & (b > F::zero()) {
            return None;
        }
        let (t0, t1) = self.roots(ray)?;
        let t = if t0 > F::zero() { t0 } else { t1 };
        (t > F::zero() && t < t_max).then(|| Intersection::at(t))
    }

    #[inline]
    fn finish(&self, ray: &Ray<F>, hit: &Intersection<F>) -> Hit<F> {
        self.hit_at(ray, hit.t)
    }

    /// Mitsuba 3's: with `n = (p − C)/r` the outward normal, `φ = atan2(n_y, n_x)` in
    /// `[0, 2π)` and `θ = acos n_z`, `uv = (φ/2π, θ/π)` and `∂p/∂u = 2πr·(−n_y, n_x, 0)`.
    fn coordinates(&self, _: &Ray<F>, _: &Intersection<F>, record: &Hit<F>) -> Coordinates<F> {
        let n = if record.front_face {
            record.normal
        } else {
            -record.normal
        };
        let two_pi = lit::<F>(TAU);
        let phi = n.y.atan2(n.x);
        let phi = if phi < F::zero() { phi + two_pi } else { phi };
        let theta = n.z.max(-F::one()).min(F::one()).acos();
        Coordinates {
            uv: [phi / two_pi, theta / lit(PI)],
            dpdu: Vec3::new(-n.y, n.x, F::zero()) * (two_pi * self.radius),
        }
    }

    /// `C ± r`, widened by the rounding of the two sums (`γ(1)(|C| + r)`).
    #[inline]
    fn bounds(&self) -> Option<Aabb<F>> {
        let pad = (self.center.abs() + Vec3::splat(self.radius)) * F::gamma(1) + Vec3::splat(self.radius);
        Some(Aabb::new(self.center - pad, self.center + pad))
    }

    #[inline]
    fn parts(&self) -> u32 {
        1
    }

    #[inline]
    fn part_bounds(&self, _: u32) -> Option<Aabb<F>> {
        self.bounds()
    }

    #[inline]
    fn intersect_part(&self, _: u32, ray: &Ray<F>, t_max: F) -> Option<Intersection<F>> {
        self.intersect(ray, t_max)
    }

    /// `4πr²`.
    #[inline]
    fn area(&self) -> Option<F> {
        Some(self.surface())
    }

    /// From outside, a direction uniform in the cone of directions that meet the sphere,
    /// `1 − cos θ = u₀(1 − cos θ_max)`, `φ = 2πu₁`, as the visible point it reaches
    /// (pbrt-v4's cone sampling; density `1/(2π(1 − cos θ_max))`); from inside, a point
    /// uniform on the whole sphere, its density `1/4πr²` per area converted to solid angle.
    /// `u₂` is not used.
    fn sample(&self, from: Vec3<F>, u: [f64; 3]) -> Option<SurfaceSample<F>> {
        if !self.encloses(from) {
            return Some(self.sample_cone(from, [u[0], u[1]]));
        }
        let [x, y, z] = uniform_sphere([u[0], u[1]]);
        let normal = Vec3::from_f64(x, y, z);
        let point = self.center + normal * self.radius;
        let pdf = area_to_solid_angle(F::one() / self.surface(), from, point, normal);
        Some(SurfaceSample {
            point,
            normal,
            part: 0,
            pdf,
        })
    }

    fn pdf(&self, ray: &Ray<F>, hit: &Hit<F>) -> F {
        if self.encloses(ray.origin) {
            return hit_solid_angle(F::one() / self.surface(), ray, hit);
        }
        let d2 = (self.center - ray.origin).length_squared();
        F::one() / (lit::<F>(TAU) * self.cone(d2).1)
    }
}

/// The textbook ray–sphere intersection (*Ray Tracing in One Weekend*), kept as the naive
/// method the tests, the benches and the accuracy study compare against: `a = D·D`,
/// `b = 2f·D`, `c = f·f − r²`, `t = (−b ∓ √(b² − 4ac))/2a`, the first root in
/// `(t_min, t_max)`.
///
/// # Precision
/// `b² − 4ac` subtracts two numbers of size `~|f|²` to get one of size `~r²`: for a
/// sphere at distance `|f|` the discriminant keeps only `log₂(r²/(ε|f|²))` bits and in
/// f32 is lost completely from `|f|/r ≈ 3·10³` (garbled from a few hundred). The point
/// `O + tD` is not reprojected and carries no error bound, which is why the textbook
/// needs a fixed `t_min`.
pub fn textbook_sphere_hit<F: Float>(s: &Sphere<F>, ray: &Ray<F>, t_min: F, t_max: F) -> Option<Hit<F>> {
    let t = textbook_sphere_t(s, ray, t_min, t_max)?;
    Some(textbook_sphere_record(s, ray, t))
}

/// The `t` of [`textbook_sphere_hit`]: its first phase.
pub fn textbook_sphere_t<F: Float>(s: &Sphere<F>, ray: &Ray<F>, t_min: F, t_max: F) -> Option<F> {
    let two = F::one() + F::one();
    let f = ray.origin - s.center;
    let a = ray.direction.dot(ray.direction);
    let b = two * f.dot(ray.direction);
    let c = f.dot(f) - s.radius * s.radius;
    let disc = b * b - two * two * a * c;
    if disc < F::zero() {
        return None;
    }
    let sqrt_d = disc.sqrt();
    [(-b - sqrt_d) / (two * a), (-b + sqrt_d) / (two * a)]
        .into_iter()
        .find(|&t| t > t_min && t < t_max)
}

/// The record of [`textbook_sphere_hit`] at `t`: the point `O + tD` as computed, no error
/// bound, the normal `(P − C)/r`.
pub fn textbook_sphere_record<F: Float>(s: &Sphere<F>, ray: &Ray<F>, t: F) -> Hit<F> {
    let point = ray.at(t);
    let outward = (point - s.center) / s.radius;
    Hit::new(Surface::bare(t, point, outward), ray.direction)
}

/// The textbook's fixed lower bound on `t`, *Ray Tracing in One Weekend*'s `0.001`.
pub const TEXTBOOK_T_MIN: f64 = 1e-3;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::float::lit;
    use crate::shape::Alone;

    fn unit_sphere_at<F: Float>(z: f64) -> Sphere<F> {
        Sphere::new(Vec3::from_f64(0.0, 0.0, z), lit(1.0)).unwrap()
    }

    #[test]
    fn hits_front_then_back() {
        let s = unit_sphere_at::<f64>(-5.0);
        let ray = Ray::new(Vec3::zero(), Vec3::new(0.0, 0.0, -1.0));
        let h = s.hit(&ray, f64::INFINITY).unwrap();
        assert_eq!(h.t, 4.0);
        assert_eq!(h.point, Vec3::new(0.0, 0.0, -4.0));
        assert_eq!(h.normal, Vec3::new(0.0, 0.0, 1.0));
        assert!(h.front_face);
        assert!(s.hit(&ray, 4.0).is_none(), "t_max is exclusive");
        let inside = Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::new(0.0, 0.0, -1.0));
        let h = s.hit(&inside, f64::INFINITY).unwrap();
        assert_eq!(
            (h.t, h.front_face, h.normal),
            (1.0, false, Vec3::new(0.0, 0.0, 1.0))
        );
    }

    #[test]
    fn misses_and_behind() {
        let s = unit_sphere_at::<f32>(-5.0);
        let up = Ray::new(Vec3::zero(), Vec3::new(0.0, 1.0, 0.0));
        assert!(s.hit(&up, f32::INFINITY).is_none());
        let away = Ray::new(Vec3::zero(), Vec3::new(0.0, 0.0, 1.0));
        assert!(s.hit(&away, f32::INFINITY).is_none());
    }

    #[test]
    fn rejects_invalid_values() {
        assert!(Sphere::new(Vec3::zero(), 0.0f64).is_err());
        assert!(Sphere::new(Vec3::zero(), -1.0f64).is_err());
        assert!(Sphere::new(Vec3::zero(), f64::NAN).is_err());
        assert!(Sphere::new(Vec3::zero(), f64::INFINITY).is_err());
        assert!(Sphere::new(Vec3::new(f64::NAN, 0.0, 0.0), 1.0).is_err());
        let msg = Sphere::new(Vec3::zero(), -2.0f32).unwrap_err().to_string();
        assert!(msg.contains("sphere radius") && msg.contains("-2"), "{msg}");
    }

    #[test]
    fn textbook_agrees_on_an_easy_case() {
        let s = unit_sphere_at::<f64>(-5.0);
        let ray = Ray::new(Vec3::zero(), Vec3::new(0.0, 0.0, -1.0));
        assert_eq!(textbook_sphere_hit(&s, &ray, 1e-3, f64::INFINITY).unwrap().t, 4.0);
    }
}
