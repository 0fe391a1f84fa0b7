//! A smooth plastic, Mitsuba 3's `plastic`, and [`Coated`], the diffuse base under a
//! dielectric coat that the rough plastic shares.

use super::ior::Ior;
use super::{BsdfSample, Emission, Eval, Interface, Lobes, Material, Scatter, param};
use crate::error::{Field, Result};
use crate::float::{Float, lit};
use crate::optics::{fresnel, fresnel_diffuse_reflectance};
use crate::sampling::{cosine_hemisphere, uniform};
use crate::shape::Hit;
use crate::texture::Texture;
use crate::vec3::{Color, Vec3};
use rand::Rng;
use std::f64::consts::FRAC_1_PI;

/// A diffuse base (`diffuse_reflectance`, a texture in `[0, 1]`, Mitsuba's default 0.5)
/// under a dielectric coat of relative index `η = η_int/η_ext` (Mitsuba's defaults:
/// `"polypropylene"` in `"air"`), with an optional factor on the coat's specular
/// reflection (`specular_reflectance`, 1 by default). What [`Plastic`] and
/// [`RoughPlastic`](super::RoughPlastic) are made of.
///
/// Light that enters the coat scatters in the base and, reflected back by the coat's
/// underside (the internal diffuse reflectance `R_int`), bounces again; summing the
/// bounces the base acts as the albedo
///
/// `ρ' = ρ/(1 − R_int)` (Mitsuba's default) or `ρ' = ρ/(1 − ρ·R_int)` (`nonlinear`: the
/// base absorbs at each bounce, which darkens and saturates colours).
///
/// Sampling chooses between the coat's specular lobe and the base with Mitsuba's
/// specular sampling weight `w_s = s̄/(ρ̄ + s̄)`, `ρ̄` and `s̄` the means of the diffuse
/// and specular textures (`s̄ = 1` without one), times each lobe's Fresnel share.
#[derive(Clone, Debug, PartialEq)]
pub struct Coated<F> {
    diffuse: Texture<F>,
    specular: Option<Texture<F>>,
    interface: Interface<F>,
    nonlinear: bool,
}

impl<F: Float> Coated<F> {
    /// A base of `diffuse` reflectance (each channel in `[0, 1]`) under a coat of index
    /// `interior` in a medium of index `exterior` (numbers or named media, [`Ior`]),
    /// each finite and `> 0`.
    pub fn new(diffuse: Texture<F>, interior: impl Into<Ior>, exterior: impl Into<Ior>) -> Result<Self> {
        Ok(Self {
            diffuse: param::unit_colour(Field::DiffuseReflectance, diffuse)?,
            specular: None,
            interface: Interface::new(interior, exterior, false)?,
            nonlinear: false,
        })
    }

    /// The same with the coat's reflection multiplied by `factor` (in `[0, 1]`).
    pub fn with_specular_reflectance(self, factor: Texture<F>) -> Result<Self> {
        Ok(Self {
            specular: Some(param::unit_colour(Field::SpecularReflectance, factor)?),
            ..self
        })
    }

    /// The same with the base's bounces summed nonlinearly (`true`) or not.
    #[must_use]
    pub fn nonlinear(self, nonlinear: bool) -> Self {
        Self { nonlinear, ..self }
    }

    /// The base's reflectance.
    pub fn diffuse(&self) -> &Texture<F> {
        &self.diffuse
    }

    /// The factor on the coat's reflection, if one was given.
    pub fn specular_reflectance(&self) -> Option<&Texture<F>> {
        self.specular.as_ref()
    }

    /// The indices either side of the coat.
    pub fn interface(&self) -> Interface<F> {
        self.interface
    }

    /// Whether the bounces are summed nonlinearly.
    pub fn is_nonlinear(&self) -> bool {
        self.nonlinear
    }

    /// `w_s = s̄/(ρ̄ + s̄)` (½ when both are black).
    pub fn specular_sampling_weight(&self) -> f64 {
        let s = self.specular.as_ref().map_or(1.0, param::mean);
        let d = param::mean(&self.diffuse);
        if s + d > 0.0 { s / (s + d) } else { 0.5 }
    }

    /// The base's albedo with its bounces under a coat that reflects `internal` of the
    /// diffuse light back: `ρ/(1 − R_int)` or, nonlinear, `ρ/(1 − ρ R_int)`.
    pub(super) fn base(&self, hit: &Hit<F>, internal: F) -> Color<F> {
        let rho = self.diffuse.eval(hit);
        if self.nonlinear {
            rho.map(|r| r / (F::one() - r * internal))
        } else {
            rho * (F::one() - internal).recip()
        }
    }

    /// The coat's reflection factor at `hit` (1 without one).
    pub(super) fn specular_at(&self, hit: &Hit<F>) -> Color<F> {
        self.specular
            .as_ref()
            .map_or(Color::splat(F::one()), |t| t.eval(hit))
    }

    /// Whether a texture reads the hit's coordinates.
    pub fn reads_coordinates(&self) -> bool {
        self.diffuse.reads_coordinates() || self.specular.as_ref().is_some_and(Texture::reads_coordinates)
    }

    /// This base and coat in scalar `G`, rounded through `f64` and re-checked.
    pub fn cast<G: Float>(&self) -> Result<Coated<G>> {
        let i = self.interface.cast::<G>(false)?;
        let mut c = Coated::new(
            param::cast(&self.diffuse)?,
            i.interior().to_f64(),
            i.exterior().to_f64(),
        )?;
        if let Some(t) = &self.specular {
            c = c.with_specular_reflectance(param::cast(t)?)?;
        }
        Ok(c.nonlinear(self.nonlinear))
    }
}

/// A smooth plastic, Mitsuba 3's `plastic`: a [`Coated`] base under a smooth coat. In
/// the shading frame, with `Fᵢ = F(cos θₒ)`, `Fₒ = F(cos θᵢ)` the exact dielectric
/// [`fresnel`] of the coat and `R_int` the fit [`fresnel_diffuse_reflectance`]`(1/η)`:
///
/// - a delta lobe, the mirror direction, of weight `Fᵢ·specular_reflectance`;
/// - a diffuse lobe, `f·cos θᵢ = ρ'·(cos θᵢ/π)·(1 − Fᵢ)(1 − Fₒ)/η²`.
///
/// The specular lobe is chosen with probability `p_s = Fᵢw_s/(Fᵢw_s + (1 − Fᵢ)(1 − w_s))`,
/// the diffuse one otherwise, then cosine-distributed: `pdf = (1 − p_s)·cos θᵢ/π`.
/// One-sided, as in Mitsuba: black from its back face.
#[derive(Clone, Debug, PartialEq)]
pub struct Plastic<F> {
    coated: Coated<F>,
    internal: F,
    weight: f64,
}

impl<F: Float> Plastic<F> {
    /// A smooth plastic of `coated`.
    pub fn new(coated: Coated<F>) -> Self {
        let internal = F::from_f64(fresnel_diffuse_reflectance(
            coated.interface.eta().recip().to_f64(),
        ));
        let weight = coated.specular_sampling_weight();
        Self {
            coated,
            internal,
            weight,
        }
    }

    /// What it is made of.
    pub fn coated(&self) -> &Coated<F> {
        &self.coated
    }

    /// This material in scalar `G`, rounded through `f64` and re-checked.
    pub fn cast<G: Float>(&self) -> Result<Plastic<G>> {
        Ok(Plastic::new(self.coated.cast()?))
    }

    /// `F(cos θ)` of the coat from outside.
    fn fresnel(&self, cos: F) -> F {
        fresnel(cos, self.coated.interface.eta().recip())
    }

    /// The probability of the specular lobe for `Fᵢ`.
    fn specular_probability(&self, fi: F) -> F {
        let ws = lit::<F>(self.weight);
        let s = fi * ws;
        let d = (F::one() - fi) * (F::one() - ws);
        s / (s + d)
    }

    /// `wo`, `wi` in the shading frame, when both are above the front face.
    fn local(hit: &Hit<F>, wo: Vec3<F>, wi: Vec3<F>) -> Option<(Vec3<F>, Vec3<F>)> {
        let frame = hit.shading_frame();
        let (o, i) = (frame.to_local(wo), frame.to_local(wi));
        (hit.front_face && o.z > F::zero() && i.z > F::zero()).then_some((o, i))
    }

    /// The diffuse lobe's `f·cos θᵢ` for `Fᵢ` and `cos θᵢ`.
    fn diffuse(&self, hit: &Hit<F>, fi: F, cos_i: F) -> Color<F> {
        let eta = self.coated.interface.eta();
        let fo = self.fresnel(cos_i);
        let scale = cos_i * lit::<F>(FRAC_1_PI) * (F::one() - fi) * (F::one() - fo) / (eta * eta);
        self.coated.base(hit, self.internal) * scale
    }
}

impl<F: Float> Material<F> for Plastic<F> {
    fn lobes(&self) -> Lobes {
        Lobes::REFLECTION | Lobes::DELTA | Lobes::DIFFUSE
    }

    fn reads_coordinates(&self) -> bool {
        self.coated.reads_coordinates()
    }

    /// The diffuse lobe's (the delta lobe has no value for a direction picked elsewhere).
    fn eval(&self, hit: &Hit<F>, wo: Vec3<F>, wi: Vec3<F>) -> Option<Eval<F>> {
        let (o, i) = Self::local(hit, wo, wi)?;
        Some(Eval {
            colour: self.diffuse(hit, self.fresnel(o.z), i.z),
            scale: F::one(),
        })
    }

    fn pdf(&self, hit: &Hit<F>, wo: Vec3<F>, wi: Vec3<F>) -> F {
        let Some((o, i)) = Self::local(hit, wo, wi) else {
            return F::zero();
        };
        (F::one() - self.specular_probability(self.fresnel(o.z))) * i.z * lit::<F>(FRAC_1_PI)
    }

    fn emits(&self) -> Option<Emission<F>> {
        None
    }
}

impl<F: Float, R: Rng + ?Sized> Scatter<F, R> for Plastic<F> {
    /// Three uniform numbers (always): one chooses the lobe, two draw the diffuse
    /// direction. `None` on the back face.
    fn sample(&self, hit: &Hit<F>, wo: Vec3<F>, rng: &mut R) -> Option<BsdfSample<F>> {
        let (choice, u) = (uniform(rng), [uniform(rng), uniform(rng)]);
        let frame = hit.shading_frame();
        let o = frame.to_local(wo);
        if !hit.front_face || o.z <= F::zero() {
            return None;
        }
        let fi = self.fresnel(o.z);
        let ps = self.specular_probability(fi);
        if choice < ps.to_f64() {
            return Some(BsdfSample {
                direction: frame.to_world(Vec3::new(-o.x, -o.y, o.z)),
                weight: self.coated.specular_at(hit) * (fi / ps),
                pdf: ps,
                lobe: Lobes::REFLECTION | Lobes::DELTA,
            });
        }
        let [x, y, z] = cosine_hemisphere(u);
        let i = Vec3::from_f64(x, y, z);
        let pdf = (F::one() - ps) * i.z * lit::<F>(FRAC_1_PI);
        if pdf <= F::zero() || pdf.is_nan() {
            return None;
        }
        Some(BsdfSample {
            direction: frame.to_world(i),
            weight: self.diffuse(hit, fi, i.z) * pdf.recip(),
            pdf,
            lobe: Lobes::REFLECTION | Lobes::DIFFUSE,
        })
    }
}
