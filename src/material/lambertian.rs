//! An ideal matte (Lambertian) surface.

use super::{BsdfSample, BsdfVisitor, Emission, Eval, Lobes, Material, Scatter};
use crate::error::{Error, Field, Result};
use crate::float::{Float, lit};
use crate::sampling::{cosine_direction, cosine_pdf, lambertian_direction};
use crate::shape::Hit;
use crate::texture::Texture;
use crate::validate;
use crate::vec3::{Color, Vec3};
use rand::Rng;
use std::f64::consts::PI;

/// A matte surface: the BRDF `A/π`, one scattered ray with density `cos θ/π` drawn by
/// the specification's tangent-sphere method ([`lambertian_direction`]), colour absorbed
/// by the albedo, `C⁺ = A ∘ C⁻`. It reflects from both faces (the normal it shades with
/// faces the ray).
///
/// The albedo is a [`Texture`]: a constant ([`Lambertian::new`], the specification's
/// material) or one that varies over the surface ([`Lambertian::textured`]), looked up at
/// the hit's `uv`.
#[derive(Clone, Debug, PartialEq)]
pub struct Lambertian<F> {
    albedo: Texture<F>,
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
            albedo: Texture::Constant(validate::albedo(Field::MatteAlbedo, albedo)?),
            sampler: CosineSampler::TangentSphere,
        })
    }

    /// A matte surface whose albedo is `texture`, every value of which must lie in
    /// `[0, 1]` ([`Texture::range`]: an 8-bit image always does, a float image or a
    /// checkerboard may not).
    ///
    /// # Errors
    /// [`Error::InvalidValue`](crate::Error::InvalidValue) (`Field::MatteAlbedo`) for a
    /// texture with a value outside `[0, 1]`.
    pub fn textured(texture: impl Into<Texture<F>>) -> Result<Self> {
        let texture = texture.into();
        if let Some(c) = texture.as_constant() {
            return Self::new(c);
        }
        let [lo, hi] = texture.range();
        if !(lo >= 0.0 && hi <= 1.0) {
            return Err(Error::invalid(
                Field::MatteAlbedo,
                format!(
                    "each channel must be in [0, 1]: the texture's values reach from {} to {}",
                    shortest(lo),
                    shortest(hi)
                ),
            ));
        }
        Ok(Self {
            albedo: texture,
            sampler: CosineSampler::TangentSphere,
        })
    }

    /// The same surface drawing its directions with `sampler`.
    #[must_use]
    pub fn with_sampler(self, sampler: CosineSampler) -> Self {
        Self { sampler, ..self }
    }

    /// The albedo `A`.
    pub fn albedo(&self) -> &Texture<F> {
        &self.albedo
    }

    /// How directions are drawn.
    pub fn sampler(&self) -> CosineSampler {
        self.sampler
    }
}

/// `x` as briefly as it reads back: as an `f32` if it is one (an image's value), else in
/// full.
fn shortest(x: f64) -> String {
    if f64::from(x as f32) == x {
        validate::number(x as f32)
    } else {
        validate::number(x)
    }
}

impl<F: Float> Lambertian<F> {
    /// Its answers at `hit`: the albedo looked up there, once.
    #[inline(always)]
    fn at(&self, hit: &Hit<F>) -> Diffuse<F> {
        Diffuse {
            albedo: self.albedo.eval(hit),
            sampler: self.sampler,
        }
    }
}

impl<F: Float> Material<F> for Lambertian<F> {
    /// Only if its albedo is not a constant.
    #[inline]
    fn reads_coordinates(&self) -> bool {
        self.albedo.reads_coordinates()
    }

    #[inline]
    fn lobes(&self) -> Lobes {
        Lobes::REFLECTION | Lobes::DIFFUSE
    }

    /// `(A/π, cos θᵢ)`, `cos θᵢ = N·wi` with the shading normal; `None` below the surface.
    // Always inlined, as `sample`: called, they take the renderer's hit by reference,
    // which keeps every hit in memory.
    #[inline(always)]
    fn eval(&self, hit: &Hit<F>, wo: Vec3<F>, wi: Vec3<F>) -> Option<Eval<F>> {
        self.at(hit).eval(hit, wo, wi)
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
    #[inline(always)]
    fn sample(&self, hit: &Hit<F>, wo: Vec3<F>, rng: &mut R) -> Option<BsdfSample<F>> {
        self.at(hit).sample(hit, wo, rng)
    }

    /// The surface with its albedo looked up at `hit`: a texture is read once a hit, not
    /// once a question.
    #[inline(always)]
    fn resolve<V: BsdfVisitor<F, R>>(&self, hit: &Hit<F>, visitor: V) -> V::Output {
        visitor.visit(&self.at(hit))
    }
}

/// A matte surface at one hit, its albedo a colour: what a [`Lambertian`] (its texture
/// looked up) and a reflecting [`Emissive`](super::Emissive) answer with.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Diffuse<F> {
    albedo: Color<F>,
    sampler: CosineSampler,
}

impl<F: Float> Diffuse<F> {
    /// Albedo `A`, already checked, with the specification's sampler.
    #[inline]
    pub(super) fn new(albedo: Color<F>) -> Self {
        Self {
            albedo,
            sampler: CosineSampler::TangentSphere,
        }
    }
}

impl<F: Float> Material<F> for Diffuse<F> {
    /// No: its albedo is already looked up.
    #[inline]
    fn reads_coordinates(&self) -> bool {
        false
    }

    #[inline]
    fn lobes(&self) -> Lobes {
        Lobes::REFLECTION | Lobes::DIFFUSE
    }

    /// `(A/π, cos θᵢ)`, `cos θᵢ = N·wi` with the shading normal; `None` below the surface.
    #[inline(always)]
    fn eval(&self, hit: &Hit<F>, _: Vec3<F>, wi: Vec3<F>) -> Option<Eval<F>> {
        let cos = hit.shading_normal.dot(wi);
        if cos > F::zero() {
            Some(Eval {
                colour: self.albedo * (F::one() / lit::<F>(PI)),
                scale: cos,
            })
        } else {
            None
        }
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

impl<F: Float, R: Rng + ?Sized> Scatter<F, R> for Diffuse<F> {
    /// A cosine-distributed direction about the shading normal `n`, weight `A`
    /// (`(A/π)·cos θ/(cos θ/π)`), density [`cosine_pdf`].
    #[inline(always)]
    fn sample(&self, hit: &Hit<F>, _: Vec3<F>, rng: &mut R) -> Option<BsdfSample<F>> {
        let n = hit.shading_normal;
        let d = match self.sampler {
            CosineSampler::TangentSphere => lambertian_direction(n, rng),
            CosineSampler::ClosedForm => cosine_direction(n, rng),
        };
        Some(BsdfSample {
            direction: d,
            weight: self.albedo,
            pdf: cosine_pdf(n, d),
            lobe: Lobes::REFLECTION | Lobes::DIFFUSE,
        })
    }
}
