//! A rough plastic, Mitsuba 3's `roughplastic`.

use super::coating::{self, RESOLUTION};
use super::microfacet::{Distribution, Microfacet};
use super::{BsdfSample, Coated, Emission, Eval, Interface, Lobes, Material, Scatter};
use crate::error::{Field, Result};
use crate::float::{Float, lit};
use crate::optics::fresnel;
use crate::sampling::{cosine_hemisphere, uniform};
use crate::shape::Hit;
use crate::validate;
use crate::vec3::{Color, Vec3};
use rand::Rng;
use std::f64::consts::FRAC_1_PI;

/// A rough plastic, Mitsuba 3's `roughplastic`: a [`Coated`] base under a rough coat
/// whose microfacets follow an isotropic distribution of roughness `α`. In the shading
/// frame, with `h = (wo + wi)/|wo + wi|`, `F` the coat's exact dielectric [`fresnel`],
/// `t(μ)` the rough coat's transmittance at `cos θ = μ` and `R_int` its internal
/// diffuse reflectance (both integrated when the material is made, as Mitsuba does:
/// see `coating.rs`),
///
/// `f·cos θᵢ = F(wo·h)·D(h)·G(wo, wi, h)/(4 cos θₒ)·specular_reflectance
///           + ρ'·(cos θᵢ/π)·t(cos θₒ)·t(cos θᵢ)/η²`,
///
/// `ρ'` the base's albedo with its bounces ([`Coated`], with `R_int`). Sampling picks
/// the specular lobe with probability
/// `p_s = (1 − t(cos θₒ))w_s / ((1 − t(cos θₒ))w_s + t(cos θₒ)(1 − w_s))`, draws a
/// visible normal and reflects about it, or else a cosine-distributed direction; the
/// density is the mixture
///
/// `pdf = p_s·D(h)G₁(wo, h)/(4 cos θₒ) + (1 − p_s)·cos θᵢ/π`, weight `f·cos θᵢ/pdf`.
///
/// `α` is one number, not a texture, and the distribution isotropic, as in Mitsuba: the
/// tables hold for one `α`. One-sided: black from its back face.
#[derive(Clone, Debug, PartialEq)]
pub struct RoughPlastic<F> {
    coated: Coated<F>,
    microfacet: Microfacet<F>,
    alpha: F,
    transmittance: [f64; RESOLUTION],
    internal: F,
    weight: f64,
}

impl<F: Float> RoughPlastic<F> {
    /// A rough plastic of `coated`, its coat's normals following `distribution` with
    /// roughness `alpha` (finite, `> 0`); the coat's two indices must differ.
    pub fn new(coated: Coated<F>, distribution: Distribution, alpha: F) -> Result<Self> {
        let alpha = validate::positive(Field::Alpha, alpha)?;
        let i = coated.interface();
        Interface::<F>::new(i.interior().to_f64(), i.exterior().to_f64(), true)?;
        let eta = i.eta().to_f64();
        let md = Microfacet::new(distribution, alpha.to_f64(), alpha.to_f64());
        let weight = coated.specular_sampling_weight();
        Ok(Self {
            transmittance: coating::transmittance(&md, eta),
            internal: F::from_f64(coating::internal_reflectance(&md, eta)),
            microfacet: Microfacet::new(distribution, alpha, alpha),
            coated,
            alpha,
            weight,
        })
    }

    /// What it is made of.
    pub fn coated(&self) -> &Coated<F> {
        &self.coated
    }

    /// The coat's distribution.
    pub fn distribution(&self) -> Distribution {
        self.microfacet.distribution()
    }

    /// The coat's roughness `α`.
    pub fn alpha(&self) -> F {
        self.alpha
    }

    /// This material in scalar `G`, rounded through `f64` and re-checked.
    pub fn cast<G: Float>(&self) -> Result<RoughPlastic<G>> {
        RoughPlastic::new(
            self.coated.cast()?,
            self.distribution(),
            G::from_f64(self.alpha.to_f64()),
        )
    }

    /// `t(cos θ)`.
    fn t(&self, cos: F) -> F {
        F::from_f64(coating::lookup(&self.transmittance, cos.to_f64()))
    }

    /// The probability of the specular lobe, seen from `cos θₒ`.
    fn specular_probability(&self, cos_o: F) -> F {
        let ws = lit::<F>(self.weight);
        let ti = self.t(cos_o);
        let s = (F::one() - ti) * ws;
        let d = ti * (F::one() - ws);
        s / (s + d)
    }

    /// `wo`, `wi` in the shading frame, when both are above the front face.
    fn local(hit: &Hit<F>, wo: Vec3<F>, wi: Vec3<F>) -> Option<(Vec3<F>, Vec3<F>)> {
        let frame = hit.shading_frame();
        let (o, i) = (frame.to_local(wo), frame.to_local(wi));
        (hit.front_face && o.z > F::zero() && i.z > F::zero()).then_some((o, i))
    }

    /// `f·cos θᵢ` for local `o`, `i` above the surface.
    fn value(&self, hit: &Hit<F>, o: Vec3<F>, i: Vec3<F>) -> Color<F> {
        let md = &self.microfacet;
        let eta = self.coated.interface().eta();
        let specular = match (o + i).try_normalize() {
            Some(h) => {
                let f = fresnel(o.dot(h), eta.recip());
                let s = f * md.d(h) * md.g(o, i, h) / (lit::<F>(4.0) * o.z);
                self.coated.specular_at(hit) * s
            }
            None => Color::zero(),
        };
        let diffuse = i.z * lit::<F>(FRAC_1_PI) * self.t(o.z) * self.t(i.z) / (eta * eta);
        specular + self.coated.base(hit, self.internal) * diffuse
    }

    /// The mixture density for local `o`, `i` above the surface.
    fn density(&self, o: Vec3<F>, i: Vec3<F>) -> F {
        let ps = self.specular_probability(o.z);
        let md = &self.microfacet;
        let specular = (o + i)
            .try_normalize()
            .map_or(F::zero(), |h| md.d(h) * md.g1(o, h) / (lit::<F>(4.0) * o.z));
        ps * specular + (F::one() - ps) * i.z * lit::<F>(FRAC_1_PI)
    }
}

impl<F: Float> Material<F> for RoughPlastic<F> {
    fn lobes(&self) -> Lobes {
        Lobes::REFLECTION | Lobes::GLOSSY | Lobes::DIFFUSE
    }

    fn reads_coordinates(&self) -> bool {
        self.coated.reads_coordinates()
    }

    fn eval(&self, hit: &Hit<F>, wo: Vec3<F>, wi: Vec3<F>) -> Option<Eval<F>> {
        let (o, i) = Self::local(hit, wo, wi)?;
        Some(Eval {
            colour: self.value(hit, o, i),
            scale: F::one(),
        })
    }

    fn pdf(&self, hit: &Hit<F>, wo: Vec3<F>, wi: Vec3<F>) -> F {
        Self::local(hit, wo, wi).map_or(F::zero(), |(o, i)| self.density(o, i))
    }

    fn emits(&self) -> Option<Emission<F>> {
        None
    }
}

impl<F: Float, R: Rng + ?Sized> Scatter<F, R> for RoughPlastic<F> {
    /// Three uniform numbers (always): one chooses the lobe, two draw its direction.
    /// `None` on the back face or when a reflection points below the surface.
    fn sample(&self, hit: &Hit<F>, wo: Vec3<F>, rng: &mut R) -> Option<BsdfSample<F>> {
        let (choice, u) = (uniform(rng), [uniform(rng), uniform(rng)]);
        let frame = hit.shading_frame();
        let o = frame.to_local(wo);
        if !hit.front_face || o.z <= F::zero() {
            return None;
        }
        let specular = choice < self.specular_probability(o.z).to_f64();
        let i = if specular {
            let m = self.microfacet.sample_visible(o, u);
            m * (lit::<F>(2.0) * o.dot(m)) - o
        } else {
            let [x, y, z] = cosine_hemisphere(u);
            Vec3::from_f64(x, y, z)
        };
        if i.z <= F::zero() {
            return None;
        }
        let pdf = self.density(o, i);
        if !(pdf > F::zero() && pdf.is_finite()) {
            return None;
        }
        let lobe = if specular { Lobes::GLOSSY } else { Lobes::DIFFUSE };
        Some(BsdfSample {
            direction: frame.to_world(i),
            weight: self.value(hit, o, i) * pdf.recip(),
            pdf,
            lobe: Lobes::REFLECTION | lobe,
        })
    }
}
