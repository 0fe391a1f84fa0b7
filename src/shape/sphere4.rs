//! Four spheres side by side, intersected with one ray at once.

use super::Sphere;
use crate::float::Float;
use crate::lanes::F4;
use crate::lanes::LANES;
use crate::ray::Ray;

/// Up to four spheres in structure-of-arrays layout (`cx[lane]`, `cy[lane]`, …), so one ray
/// is tested against all four with the same instructions per lane: SIMD, four `f32` lanes
/// in one SSE register, `f64` in two.
///
/// A scene packs the parts its shapes' [`Layout`](crate::scene::Layout) calls spheres into
/// these; the answer is bit for bit the one [`Sphere::intersect`](super::Hittable::intersect) gives for
/// each sphere alone.
#[derive(Clone, Copy, Debug)]
pub struct Sphere4<F> {
    cx: F4<F>,
    cy: F4<F>,
    cz: F4<F>,
    /// `r²`, or `−1` for an empty lane (its discriminant is always negative: never hit).
    r2: F4<F>,
}

impl<F: Float> Sphere4<F> {
    /// The first (up to) four of `spheres`; unused lanes are empty and never hit.
    pub fn new(spheres: impl IntoIterator<Item = Sphere<F>>) -> Self {
        let mut p = Self {
            cx: F4::splat(F::zero()),
            cy: F4::splat(F::zero()),
            cz: F4::splat(F::zero()),
            r2: F4::splat(-F::one()),
        };
        for (lane, s) in spheres.into_iter().take(LANES).enumerate() {
            let c = s.center();
            (p.cx.0[lane], p.cy.0[lane], p.cz.0[lane]) = (c.x, c.y, c.z);
            p.r2.0[lane] = s.radius() * s.radius();
        }
        p
    }

    /// For each lane, the `t` that [`Sphere::intersect`](super::Hittable::intersect) reports for that
    /// sphere with no bound (`t_max = +∞`), or `+∞` where it reports none. (With a bound `t_max`, `Sphere::hit`
    /// reports the same `t` if it is below `t_max`, else nothing.)
    ///
    /// The arithmetic is [`Sphere::roots`]' stable form, operation for operation
    /// (`f = O − C`, `b = f·D`, `c = |f|² − r²`, `Δ = r² − |f − bD|²`,
    /// `q = −b − sign(b)√Δ`, roots `q` and `c/q`, the nearer positive one), so every lane
    /// rounds exactly as the scalar code does. Packets that miss in every lane stop early;
    /// otherwise all lanes are computed and the misses masked at the end (a negative `Δ`
    /// gives a NaN root).
    #[inline(always)]
    pub(crate) fn hits(&self, ray: &Ray<F>) -> F4<F> {
        let (o, d) = (ray.origin, ray.direction);
        let (dx, dy, dz) = (F4::splat(d.x), F4::splat(d.y), F4::splat(d.z));
        let fx = F4::splat(o.x) - self.cx;
        let fy = F4::splat(o.y) - self.cy;
        let fz = F4::splat(o.z) - self.cz;
        let b = fx * dx + fy * dy + fz * dz;
        let (lx, ly, lz) = (fx - dx * b, fy - dy * b, fz - dz * b);
        let disc = self.r2 - (lx * lx + ly * ly + lz * lz);
        let c = (fx * fx + fy * fy + fz * fz) - self.r2;
        let (zero, inf) = (F4::splat(F::zero()), F4::splat(F::infinity()));
        // Most packets miss in every lane: the line misses (`Δ < 0`), or the ray starts
        // outside (`c > 0`) and heads away (`b > 0`), so both roots are negative (in
        // floating point too: `q = −b − √Δ < 0` and `c/q < 0`). Then skip the square roots
        // and divisions. (Secondary rays leave a sphere whose line they always cross.)
        let miss = |k: usize| {
            let o = F::zero();
            (disc.0[k] < o) | ((c.0[k] > o) & (b.0[k] > o))
        };
        if F4::<F>::all(miss) {
            return inf;
        }
        let sqrt_d = disc.sqrt();
        let q = F4::select_lt(zero, b, -b - sqrt_d, -b + sqrt_d);
        let other = F4::select_eq(q, zero, zero, c / q);
        let t0 = F4::select_lt(q, other, q, other);
        let t1 = F4::select_lt(q, other, other, q);
        let t = F4::select_lt(zero, t0, t0, t1);
        // A miss (`Δ < 0`), a root that is not positive, or a NaN: +∞.
        let t = F4::select_lt(disc, zero, inf, t);
        F4::select_lt(zero, t, t, inf)
    }

    /// Whether any lane's sphere is hit at some `t` in `(0, t_max)`.
    #[inline(always)]
    pub fn any(&self, ray: &Ray<F>, t_max: F) -> bool {
        self.hits(ray).any_lt(t_max)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shape::Alone;
    use crate::vec3::Vec3;
    use rand::{RngExt, SeedableRng};

    /// Every lane agrees bit for bit with the scalar sphere's hit, for rays from outside, inside and on spheres of very
    /// different sizes and distances.
    fn lanes_match_the_scalar_sphere<F: Float>() {
        let mut rng = rand::rngs::Xoshiro256PlusPlus::seed_from_u64(9);
        for _ in 0..2_000 {
            let scale = 10f64.powi(rng.random_range(-3..6));
            let spheres: Vec<Sphere<F>> = (0..rng.random_range(1..=LANES))
                .map(|_| {
                    let c = Vec3::from_f64(
                        rng.random_range(-2.0..2.0) * scale,
                        rng.random_range(-2.0..2.0) * scale,
                        rng.random_range(-2.0..2.0) * scale,
                    );
                    Sphere::new(c, crate::float::lit(rng.random_range(0.01..1.5) * scale)).unwrap()
                })
                .collect();
            let packet = Sphere4::new(spheres.iter().copied());
            let o = Vec3::from_f64(
                rng.random_range(-3.0..3.0) * scale,
                rng.random_range(-3.0..3.0) * scale,
                rng.random_range(-3.0..3.0) * scale,
            );
            let target = spheres[rng.random_range(0..spheres.len())].center();
            let aim = Vec3::<F>::from_f64(0.5, -0.3, 0.2) * crate::float::lit::<F>(scale);
            let Some(ray) = Ray::towards(o, target + aim) else {
                continue;
            };
            let got = packet.hits(&ray).0;
            for (lane, s) in spheres.iter().enumerate() {
                let want = s.hit(&ray, F::infinity()).map_or(F::infinity(), |h| h.t);
                assert_eq!(got[lane].to_f64().to_bits(), want.to_f64().to_bits(), "{ray:?}");
            }
            for &t in &got[spheres.len()..] {
                assert_eq!(t, F::infinity(), "empty lanes are never hit");
            }
            for t_max in [F::infinity(), crate::float::lit(2.0 * scale)] {
                let want = spheres.iter().any(|s| s.hit(&ray, t_max).is_some());
                assert_eq!(packet.any(&ray, t_max), want, "{ray:?}");
            }
        }
    }

    mod scalars {
        crate::float::for_each_scalar!(lanes_match_the_scalar_sphere);
    }
}
