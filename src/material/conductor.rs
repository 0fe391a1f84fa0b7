//! A smooth conductor (a polished metal), Mitsuba 3's `conductor`, and [`Metal`], what a
//! conductor is made of, shared with the rough one.

use super::{BsdfSample, Emission, Eval, Lobes, Material, Scatter, ior, param};
use crate::error::{Field, Result};
use crate::float::Float;
use crate::optics::{fresnel_conductor, reflect};
use crate::shape::Hit;
use crate::texture::Texture;
use crate::vec3::{Color, Vec3};
use rand::Rng;

/// What a conductor is made of: its complex index of refraction `η + ik` per channel
/// (relative to the medium outside), and an optional factor on its reflection
/// (`specular_reflectance`, 1 by default; "for physical realism never touched", as
/// Mitsuba's docs say, but a way to tint). Each is a texture. It reflects the share
/// [`fresnel_conductor`]`(cos θ, η, k)` per channel of the light arriving at `cos θ` to the
/// (micro)surface.
#[derive(Clone, Debug, PartialEq)]
pub struct Metal<F> {
    eta: Texture<F>,
    k: Texture<F>,
    specular: Option<Texture<F>>,
}

impl<F: Float> Metal<F> {
    /// A conductor of index `η` and extinction `k`, each channel finite and `≥ 0`
    /// (`η = 0, k = 1`: Mitsuba's perfect mirror).
    pub fn new(eta: Texture<F>, k: Texture<F>) -> Result<Self> {
        Ok(Self {
            eta: param::non_negative(Field::ConductorEta, eta)?,
            k: param::non_negative(Field::ConductorK, k)?,
            specular: None,
        })
    }

    /// One of Mitsuba 3's named conductors ([`ior::conductor`]: `Au`, `Ag`, `Cu`, `Al`,
    /// `Cr`, `Ni_palik`, `W`, … and `none`, the perfect mirror); an unknown name is an
    /// error listing the known ones.
    pub fn named(name: &str) -> Result<Self> {
        let c = ior::conductor_named(Field::ConductorName, name)?;
        let colour = |v: [f64; 3]| Texture::constant(Color::from_f64(v[0], v[1], v[2]));
        Self::new(colour(c.eta), colour(c.k))
    }

    /// The same conductor with its reflection multiplied by `factor`, each channel in
    /// `[0, 1]`.
    pub fn with_specular_reflectance(self, factor: Texture<F>) -> Result<Self> {
        Ok(Self {
            specular: Some(param::unit_colour(Field::SpecularReflectance, factor)?),
            ..self
        })
    }

    /// `η`.
    pub fn eta(&self) -> &Texture<F> {
        &self.eta
    }

    /// `k`.
    pub fn k(&self) -> &Texture<F> {
        &self.k
    }

    /// The factor on the reflection, if one was given.
    pub fn specular_reflectance(&self) -> Option<&Texture<F>> {
        self.specular.as_ref()
    }

    /// The share of light reflected at `hit` by a (micro)surface seen at `cos θ`:
    /// `fresnel_conductor(cos θ, η, k)` per channel, times the factor.
    #[inline]
    pub fn reflectance(&self, hit: &Hit<F>, cos_theta: F) -> Color<F> {
        let (eta, k) = (self.eta.eval(hit), self.k.eval(hit));
        let f = Color::new(
            fresnel_conductor(cos_theta, eta.x, k.x),
            fresnel_conductor(cos_theta, eta.y, k.y),
            fresnel_conductor(cos_theta, eta.z, k.z),
        );
        match &self.specular {
            Some(s) => f * s.eval(hit),
            None => f,
        }
    }

    /// Whether a texture reads the hit's coordinates.
    pub fn reads_coordinates(&self) -> bool {
        self.eta.reads_coordinates()
            || self.k.reads_coordinates()
            || self.specular.as_ref().is_some_and(Texture::reads_coordinates)
    }

    /// This conductor in scalar `G`, rounded through `f64` and re-checked.
    pub fn cast<G: Float>(&self) -> Result<Metal<G>> {
        let metal = Metal::new(param::cast(&self.eta)?, param::cast(&self.k)?)?;
        match &self.specular {
            Some(s) => metal.with_specular_reflectance(param::cast(s)?),
            None => Ok(metal),
        }
    }
}

/// A smooth conductor, Mitsuba 3's `conductor`: a perfect mirror that reflects the
/// share `F = fresnel_conductor(cos θ, η, k)` per channel ([`Metal`]), `D⁺ = D − 2(D·N)N`,
/// with weight `F·specular_reflectance` (one delta lobe, probability 1).
///
/// One-sided, as in Mitsuba: seen from its back face it is black (wrap it in
/// [`TwoSided`](super::TwoSided) to shade both faces alike).
#[derive(Clone, Debug, PartialEq)]
pub struct Conductor<F> {
    metal: Metal<F>,
}

impl<F: Float> Conductor<F> {
    /// A smooth surface of `metal`.
    pub fn new(metal: Metal<F>) -> Self {
        Self { metal }
    }

    /// What it is made of.
    pub fn metal(&self) -> &Metal<F> {
        &self.metal
    }

    /// This material in scalar `G`, rounded through `f64` and re-checked.
    pub fn cast<G: Float>(&self) -> Result<Conductor<G>> {
        Ok(Conductor::new(self.metal.cast()?))
    }
}

impl<F: Float> Material<F> for Conductor<F> {
    fn lobes(&self) -> Lobes {
        Lobes::REFLECTION | Lobes::DELTA
    }

    fn reads_coordinates(&self) -> bool {
        self.metal.reads_coordinates()
    }

    /// None: a delta lobe has no value for a direction light sampling picks.
    fn eval(&self, _: &Hit<F>, _: Vec3<F>, _: Vec3<F>) -> Option<Eval<F>> {
        None
    }

    fn pdf(&self, _: &Hit<F>, _: Vec3<F>, _: Vec3<F>) -> F {
        F::zero()
    }

    fn emits(&self) -> Option<Emission<F>> {
        None
    }
}

impl<F: Float, R: Rng + ?Sized> Scatter<F, R> for Conductor<F> {
    /// The mirror direction about the shading normal, weight `F(cos θ)`; draws nothing.
    /// `None` (absorbed) on the back face.
    fn sample(&self, hit: &Hit<F>, wo: Vec3<F>, _: &mut R) -> Option<BsdfSample<F>> {
        let n = hit.shading_normal;
        let cos = n.dot(wo);
        if !hit.front_face || cos <= F::zero() {
            return None;
        }
        Some(BsdfSample {
            direction: reflect(-wo, n),
            weight: self.metal.reflectance(hit, cos),
            pdf: F::one(),
            lobe: Lobes::REFLECTION | Lobes::DELTA,
        })
    }
}
