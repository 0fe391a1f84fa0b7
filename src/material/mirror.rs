//! A perfect mirror.

use super::{Material, Scatter};
use crate::error::Result;
use crate::float::Float;
use crate::optics::reflect;
use crate::ray::Ray;
use crate::shape::Hit;
use crate::validate;
use crate::vec3::Color;
use rand::Rng;

/// A mirror: `D⁺ = D⁻ − 2(D⁻·N)N`, colour absorbed by the albedo, `C⁺ = A ∘ C⁻`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Mirror<F> {
    albedo: Color<F>,
}

impl<F: Float> Mirror<F> {
    /// A mirror with albedo `A`; each channel must lie in `[0, 1]`.
    pub fn new(albedo: Color<F>) -> Result<Self> {
        Ok(Self {
            albedo: validate::albedo(crate::error::Field::MirrorAlbedo, albedo)?,
        })
    }

    /// The albedo `A`.
    pub fn albedo(&self) -> Color<F> {
        self.albedo
    }
}

impl<F: Float, R: Rng + ?Sized> Material<F, R> for Mirror<F> {
    #[inline]
    fn scatter(&self, ray: &Ray<F>, hit: &Hit<F>, _rng: &mut R) -> Option<Scatter<F>> {
        Some(Scatter {
            attenuation: self.albedo,
            direction: reflect(ray.direction, hit.normal),
        })
    }
}
