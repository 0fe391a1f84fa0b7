//! A transparent, refracting material (glass, water): the spec's refraction extra.

use super::{BsdfSample, Emission, Eval, Lobes, Material, Scatter};
use crate::error::Result;
use crate::float::Float;
use crate::optics::{fresnel, reflect, refract, schlick_reflectance};
use crate::sampling::uniform;
use crate::shape::Hit;
use crate::validate;
use crate::vec3::{Color, Vec3};
use rand::Rng;

/// A dielectric (glass-like) surface with refractive index `n` relative to the medium
/// outside it: at each hit the ray is either reflected or refracted by Snell's law
/// `η₁ sin θ₁ = η₂ sin θ₂`, chosen at random with the probability of reflection equal to
/// the interface's reflectance `R`, so the expected energy split is exactly `R : 1 − R`.
///
/// With `η = η₁/η₂` (`1/n` entering through the front face, `n` leaving through the
/// back face) and `cos θ₁ = −D·N` (`N` the normal facing the ray):
///
/// - total internal reflection (`η sin θ₁ ≥ 1`): `D⁺ = D − 2(D·N)N`;
/// - otherwise reflect if `u < R`, `u` uniform in `[0, 1)`, else refract
///   `D⁺ = ηD + (η cos θ₁ − cos θ₂)N`, `cos θ₂ = √(1 − η²(1 − cos²θ₁))`.
///
/// `R` is Schlick's approximation `R₀ + (1 − R₀)(1 − cos θ)⁵`, `R₀ = ((1 − η)/(1 + η))²`
/// (the specification's choice, the default) or the exact unpolarised Fresnel reflectance
/// ([`Reflectance`]). The colour is absorbed by the albedo, `C⁺ = A ∘ C⁻` (white by
/// default: clear glass).
///
/// A hollow glass shell is two concentric spheres: the outer of index `n`, the inner of
/// index `1/n` (the inner surface is a glass → air interface seen from the glass).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Dielectric<F> {
    refractive_index: F,
    albedo: Color<F>,
    reflectance: Reflectance,
}

/// How a [`Dielectric`] computes the share `R` of light an interface reflects.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Reflectance {
    /// Schlick's approximation ([`schlick_reflectance`]), evaluated at the angle in the
    /// rarer medium; the specification's choice and the default.
    #[default]
    Schlick,
    /// The exact Fresnel equations for unpolarised light ([`fresnel`]).
    Fresnel,
}

impl<F: Float> Dielectric<F> {
    /// Clear glass-like material of refractive index `n` (relative to the outside
    /// medium); `n` must be finite and `> 0` (`n < 1` models a bubble of a rarer medium,
    /// e.g. the air inside a hollow glass sphere).
    pub fn new(refractive_index: F) -> Result<Self> {
        Ok(Self {
            refractive_index: validate::positive(crate::error::Field::RefractiveIndex, refractive_index)?,
            albedo: Color::splat(F::one()),
            reflectance: Reflectance::Schlick,
        })
    }

    /// The same material tinted by `albedo`; each channel must lie in `[0, 1]`.
    pub fn with_albedo(self, albedo: Color<F>) -> Result<Self> {
        Ok(Self {
            albedo: validate::albedo(crate::error::Field::DielectricAlbedo, albedo)?,
            ..self
        })
    }

    /// The same material computing its reflectance by `reflectance`.
    #[must_use]
    pub fn with_reflectance(self, reflectance: Reflectance) -> Self {
        Self { reflectance, ..self }
    }

    /// The refractive index `n`.
    pub fn refractive_index(&self) -> F {
        self.refractive_index
    }

    /// The albedo `A` (the tint).
    pub fn albedo(&self) -> Color<F> {
        self.albedo
    }

    /// How the reflectance is computed.
    pub fn reflectance(&self) -> Reflectance {
        self.reflectance
    }

    /// The relative index `η = η₁/η₂` for a hit: `1/n` entering through the front face,
    /// `n` leaving through the back face.
    #[inline]
    pub fn eta(&self, front_face: bool) -> F {
        if front_face {
            self.refractive_index.recip()
        } else {
            self.refractive_index
        }
    }

    /// The reflectance `R ∈ [0, 1]` at incidence `cos θ₁` with `η = η₁/η₂`; 1 under
    /// total internal reflection.
    #[inline]
    pub fn reflectance_at(&self, cos_i: F, eta: F) -> F {
        match self.reflectance {
            Reflectance::Schlick => schlick_reflectance(cos_i, eta),
            Reflectance::Fresnel => fresnel(cos_i, eta),
        }
    }
}

impl<F: Float> Material<F> for Dielectric<F> {
    /// No: it has no texture.
    #[inline]
    fn reads_coordinates(&self) -> bool {
        false
    }

    #[inline]
    fn lobes(&self) -> Lobes {
        Lobes::REFLECTION | Lobes::TRANSMISSION | Lobes::DELTA
    }

    /// None: both lobes are deltas.
    #[inline]
    fn eval(&self, _: &Hit<F>, _: Vec3<F>, _: Vec3<F>) -> Option<Eval<F>> {
        None
    }

    #[inline]
    fn pdf(&self, _: &Hit<F>, _: Vec3<F>, _: Vec3<F>) -> F {
        F::zero()
    }

    #[inline]
    fn emits(&self) -> Option<Emission<F>> {
        None
    }
}

impl<F: Float, R: Rng + ?Sized> Scatter<F, R> for Dielectric<F> {
    /// Always scatters (reflects or refracts), with weight `A`. Draws exactly one uniform
    /// number per call, even under total internal reflection, so the random stream does
    /// not depend on a decision that f32 and f64 can take differently near the critical
    /// angle.
    // Always inlined: called out of line, it takes the hit by reference, and the batched
    // renderer then writes every ray's hit to memory, glass or not (+3 % instructions).
    #[inline(always)]
    fn sample(&self, hit: &Hit<F>, wo: Vec3<F>, rng: &mut R) -> Option<BsdfSample<F>> {
        let (d, n) = (-wo, hit.shading_normal);
        let eta = self.eta(hit.front_face);
        // `n` faces the ray, so cos θ₁ = −D·N ≥ 0 (clamped by the optics functions).
        let cos_i = -d.dot(n);
        let reflectance = self.reflectance_at(cos_i, eta);
        let u = uniform(rng);
        // `refract` returns `None` under total internal reflection (the same clamped test
        // that makes `R = 1`): reflect. Otherwise reflect when `u < R`, probability `R`.
        let (direction, pdf, lobe) = match refract(d, n, eta) {
            Some(t) if u >= reflectance.to_f64() => (t, F::one() - reflectance, Lobes::TRANSMISSION),
            _ => (reflect(d, n), reflectance, Lobes::REFLECTION),
        };
        Some(BsdfSample {
            direction,
            weight: self.albedo,
            pdf,
            lobe: lobe | Lobes::DELTA,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ray::Ray;
    use crate::shape::Surface;
    use std::convert::Infallible;

    /// A generator that always returns the same word: `u64::MAX` draws `u → 1⁻`
    /// (always refract unless `R = 1`), `0` draws `u = 0` (always reflect unless `R = 0`).
    struct Constant(u64);

    impl rand::TryRng for Constant {
        type Error = Infallible;
        fn try_next_u32(&mut self) -> std::result::Result<u32, Infallible> {
            Ok((self.0 >> 32) as u32)
        }
        fn try_next_u64(&mut self) -> std::result::Result<u64, Infallible> {
            Ok(self.0)
        }
        fn try_fill_bytes(&mut self, dst: &mut [u8]) -> std::result::Result<(), Infallible> {
            dst.fill(self.0 as u8);
            Ok(())
        }
    }

    /// A hit at the origin on the plane `y = 0` (outward normal `+y`, or `−y` when
    /// `front` is false), the ray coming down at angle `theta` from the vertical.
    fn hit_at(theta: f64, front: bool) -> (Ray<f64>, Hit<f64>) {
        let d = Vec3::new(theta.sin(), -theta.cos(), 0.0);
        let outward = if front {
            Vec3::new(0.0, 1.0, 0.0)
        } else {
            Vec3::new(0.0, -1.0, 0.0)
        };
        let ray = Ray::new(Vec3::new(-theta.sin(), theta.cos(), 0.0), d);
        (ray, Hit::new(Surface::bare(1.0, Vec3::zero(), outward), d))
    }

    #[test]
    fn rejects_invalid_values() {
        for n in [0.0, -1.5, f64::NAN, f64::INFINITY] {
            assert!(Dielectric::new(n).is_err(), "index {n}");
        }
        let glass = Dielectric::new(1.5f32).unwrap();
        assert!(glass.with_albedo(Vec3::new(1.1, 0.5, 0.5)).is_err());
        assert!(glass.with_albedo(Vec3::new(0.5, f32::NAN, 0.5)).is_err());
        let msg = Dielectric::new(-2.0f64).unwrap_err().to_string();
        assert!(msg.contains("refractive index") && msg.contains("-2"), "{msg}");
        assert_eq!(glass.albedo(), Vec3::splat(1.0), "clear by default");
        assert_eq!(
            glass.reflectance(),
            Reflectance::Schlick,
            "the spec's choice by default"
        );
    }

    #[test]
    fn eta_follows_the_face() {
        let glass = Dielectric::new(1.5f64).unwrap();
        assert_eq!(glass.eta(true), 1.0 / 1.5);
        assert_eq!(glass.eta(false), 1.5);
    }

    #[test]
    fn refracts_or_reflects_by_the_draw() {
        let glass = Dielectric::new(1.5f64)
            .unwrap()
            .with_albedo(Vec3::new(0.9, 0.8, 0.7))
            .unwrap();
        let theta = 0.5f64;
        let (ray, hit) = hit_at(theta, true);
        let t = glass
            .sample(&hit, -ray.direction, &mut Constant(u64::MAX))
            .unwrap();
        assert_eq!(t.weight, Vec3::new(0.9, 0.8, 0.7));
        assert_eq!(t.lobe, Lobes::TRANSMISSION | Lobes::DELTA);
        assert!(t.direction.y < 0.0, "refracted into the glass");
        // Snell: sin θ₂ = sin θ₁ / 1.5.
        assert!((t.direction.x - theta.sin() / 1.5).abs() < 1e-15);
        let r = glass.sample(&hit, -ray.direction, &mut Constant(0)).unwrap();
        assert_eq!(r.direction, reflect(ray.direction, hit.normal));
    }

    #[test]
    fn total_internal_reflection_always_reflects() {
        let glass = Dielectric::new(1.5f64).unwrap();
        let critical = (1.0f64 / 1.5).asin();
        for theta in [critical + 1e-9, 1.0, 1.5] {
            let (ray, hit) = hit_at(theta, false);
            assert!(!hit.front_face);
            let s = glass
                .sample(&hit, -ray.direction, &mut Constant(u64::MAX))
                .unwrap();
            assert_eq!(s.direction, reflect(ray.direction, hit.normal), "θ = {theta}");
        }
        let (ray, hit) = hit_at(critical - 1e-6, false);
        let s = glass
            .sample(&hit, -ray.direction, &mut Constant(u64::MAX))
            .unwrap();
        assert!(
            s.direction.y < 0.0,
            "just below the critical angle it refracts out"
        );
    }

    #[test]
    fn reflectance_modes_agree_at_normal_incidence_and_differ_at_grazing() {
        let schlick = Dielectric::new(1.5f64).unwrap();
        let exact = schlick.with_reflectance(Reflectance::Fresnel);
        let r0 = 0.04;
        assert!((schlick.reflectance_at(1.0, 1.0 / 1.5) - r0).abs() < 1e-15);
        assert!((exact.reflectance_at(1.0, 1.0 / 1.5) - r0).abs() < 1e-15);
        let (s, f) = (
            schlick.reflectance_at(0.2, 1.0 / 1.5),
            exact.reflectance_at(0.2, 1.0 / 1.5),
        );
        assert!(
            (s - f).abs() > 1e-3 && (s - f).abs() < 0.05,
            "Schlick {s}, Fresnel {f}"
        );
    }
}
