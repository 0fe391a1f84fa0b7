//! An ideal matte (Lambertian) surface.

use super::{BsdfSample, Emission, Eval, Lobes, Material, Scatter};
use crate::error::Result;
use crate::float::{Float, lit};
use crate::sampling::{cosine_direction, cosine_pdf, lambertian_direction};
use crate::shape::Hit;
use crate::validate;
use crate::vec3::{Color, Vec3};
use rand::Rng;
use std::f64::consts::PI;

/// A matte surface: the BRDF `A/π`, one scattered ray with density `cos θ/π` drawn by
/// the specification's tangent-sphere method ([`lambertian_direction`]), colour absorbed
/// by the albedo, `C⁺ = A ∘ C⁻`. It reflects from both faces (the normal it shades with
/// faces the ray).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Lambertian<F> {
    albedo: Color<F>,
    sampler: CosineSampler,
}

/// How a matte surface draws its cosine-distributed direction. Both draw the same
/// distribution (one χ² harness tests both); they differ in speed and in the random
/// numbers they consume.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum CosineSampler {
    /// The specification's method, [`lambertian_direction`]: a cube-rejection point on
    /// the unit sphere tangent at the hit point. The default.
    #[default]
    TangentSphere,
    /// The closed form [`cosine_direction`]: two uniform numbers and a local frame.
    ClosedForm,
}

impl<F: Float> Lambertian<F> {
    /// A matte surface with albedo `A`; each channel must lie in `[0, 1]`.
    pub fn new(albedo: Color<F>) -> Result<Self> {
        Ok(Self {
            albedo: validate::albedo(crate::error::Field::MatteAlbedo, albedo)?,
            sampler: CosineSampler::TangentSphere,
        })
    }

    /// A matte surface of an albedo already checked, with the specification's sampler.
    pub(super) fn from_valid(albedo: Color<F>) -> Self {
        Self {
            albedo,
            sampler: CosineSampler::TangentSphere,
        }
    }

    /// The same surface drawing its directions with `sampler`.
    #[must_use]
    pub fn with_sampler(self, sampler: CosineSampler) -> Self {
        Self { sampler, ..self }
    }

    /// The albedo `A`.
    pub fn albedo(&self) -> Color<F> {
        self.albedo
    }

    /// How directions are drawn.
    pub fn sampler(&self) -> CosineSampler {
        self.sampler
    }
}

impl<F: Float> Lambertian<F> {
    /// The BSDF sample of direction `d` drawn about the unit normal `n`: weight `A`
    /// (`(A/π)·cos θ/(cos θ/π)`), density [`cosine_pdf`](crate::sampling::cosine_pdf).
    #[inline]
    pub(super) fn sample_toward(&self, n: Vec3<F>, d: Vec3<F>) -> BsdfSample<F> {
        BsdfSample {
            direction: d,
            weight: self.albedo,
            pdf: cosine_pdf(n, d),
            lobe: Lobes::REFLECTION | Lobes::DIFFUSE,
        }
    }
}

impl<F: Float> Material<F> for Lambertian<F> {
    /// No: it has no texture.
    #[inline]
    fn reads_coordinates(&self) -> bool {
        false
    }

    #[inline]
    fn lobes(&self) -> Lobes {
        Lobes::REFLECTION | Lobes::DIFFUSE
    }

    /// `(A/π, cos θᵢ)`, `cos θᵢ = N·wi` with the shading normal; `None` below the surface.
    #[inline]
    fn eval(&self, hit: &Hit<F>, _: Vec3<F>, wi: Vec3<F>) -> Option<Eval<F>> {
        let cos = hit.shading_normal.dot(wi);
        (cos > F::zero()).then(|| Eval {
            colour: self.albedo * (F::one() / lit::<F>(PI)),
            scale: cos,
        })
    }

    #[inline]
    fn pdf(&self, hit: &Hit<F>, _: Vec3<F>, wi: Vec3<F>) -> F {
        cosine_pdf(hit.shading_normal, wi)
    }

    #[inline]
    fn emits(&self) -> Option<Emission<F>> {
        None
    }
}

impl<F: Float, R: Rng + ?Sized> Scatter<F, R> for Lambertian<F> {
    /// A cosine-distributed direction about the shading normal, by the sampler chosen
    /// (the specification's rejection method draws a variable count of numbers).
    #[inline]
    fn sample(&self, hit: &Hit<F>, _: Vec3<F>, rng: &mut R) -> Option<BsdfSample<F>> {
        let n = hit.shading_normal;
        let d = match self.sampler {
            CosineSampler::TangentSphere => lambertian_direction(n, rng),
            CosineSampler::ClosedForm => cosine_direction(n, rng),
        };
        Some(self.sample_toward(n, d))
    }
}
