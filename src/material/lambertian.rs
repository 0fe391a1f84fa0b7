//! An ideal matte (Lambertian) surface.

use super::{Material, Scatter};
use crate::error::Result;
use crate::float::Float;
use crate::ray::Ray;
use crate::sampling::{cosine_direction, lambertian_direction};
use crate::shape::Hit;
use crate::validate;
use crate::vec3::Color;
use rand::Rng;

/// A matte surface: one scattered ray with density `cos θ/π`, drawn by the
/// specification's tangent-sphere method ([`lambertian_direction`]), colour absorbed by
/// the albedo, `C⁺ = A ∘ C⁻`.
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

impl<F: Float, R: Rng + ?Sized> Material<F, R> for Lambertian<F> {
    #[inline]
    fn scatter(&self, _ray: &Ray<F>, hit: &Hit<F>, rng: &mut R) -> Option<Scatter<F>> {
        Some(Scatter {
            attenuation: self.albedo,
            direction: match self.sampler {
                CosineSampler::TangentSphere => lambertian_direction(hit.normal, rng),
                CosineSampler::ClosedForm => cosine_direction(hit.normal, rng),
            },
        })
    }

    #[inline]
    fn diffuse_albedo(&self) -> Option<Color<F>> {
        Some(self.albedo)
    }
}
