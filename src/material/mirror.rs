//! A perfect mirror.

use super::{BsdfSample, Emission, Eval, Lobes, Material, Scatter};
use crate::error::Result;
use crate::float::Float;
use crate::optics::reflect;
use crate::shape::Hit;
use crate::validate;
use crate::vec3::{Color, Vec3};
use rand::Rng;

/// A mirror: `D⁺ = D⁻ − 2(D⁻·N)N` (`N` the shading normal), colour absorbed by the
/// albedo, `C⁺ = A ∘ C⁻`. One delta lobe: lights reach it only through the ray it
/// reflects.
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

impl<F: Float> Material<F> for Mirror<F> {
    /// No: it has no texture.
    #[inline]
    fn reads_coordinates(&self) -> bool {
        false
    }

    #[inline]
    fn lobes(&self) -> Lobes {
        Lobes::REFLECTION | Lobes::DELTA
    }

    /// None: a delta lobe has no value for a direction light sampling picks.
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

impl<F: Float, R: Rng + ?Sized> Scatter<F, R> for Mirror<F> {
    /// The reflection of the arriving direction `D = −wo`, with weight `A`; draws nothing.
    #[inline]
    fn sample(&self, hit: &Hit<F>, wo: Vec3<F>, _: &mut R) -> Option<BsdfSample<F>> {
        Some(BsdfSample {
            direction: reflect(-wo, hit.shading_normal),
            weight: self.albedo,
            pdf: F::one(),
            lobe: Lobes::REFLECTION | Lobes::DELTA,
        })
    }
}
