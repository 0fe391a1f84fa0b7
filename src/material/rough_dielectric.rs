//! A rough dielectric (frosted glass, rough water), Mitsuba 3's `roughdielectric`.

use super::ior::Ior;
use super::microfacet::Microfacet;
use super::{BsdfSample, Emission, Eval, Interface, Lobes, Material, Roughness, Scatter, param};
use crate::error::{Field, Result};
use crate::float::{Float, lit};
use crate::optics::{fresnel, refract};
use crate::sampling::uniform;
use crate::shape::Hit;
use crate::texture::Texture;
use crate::vec3::{Color, Vec3};
use rand::Rng;

/// A rough boundary between two dielectrics, Mitsuba 3's `roughdielectric` (Walter et
/// al. 2007, "Microfacet Models for Refraction through Rough Surfaces"): microfacets of
/// smooth glass whose normals follow a distribution ([`Roughness`]), each reflecting the
/// Fresnel share `F` and refracting the rest.
///
/// In the shading frame (`wo` above, `cos θₒ > 0`), with `η` the index beyond the
/// surface over the index on `wo`'s side ([`Interface::eta_toward`]) and `F = F(wo·m)`
/// the exact dielectric [`fresnel`]:
///
/// - reflection (`cos θᵢ > 0`), `h = (wo + wi)/|wo + wi|`:
///   `f·|cos θᵢ| = F·D(h)·G(wo, wi, h) / (4 cos θₒ)`;
/// - transmission (`cos θᵢ < 0`), `h ∝ wo + η wi` turned up:
///   `f·|cos θᵢ| = (1/η²)·(1 − F)·D(h)·G(wo, wi, h)·η²|wi·h|(wo·h) / (cos θₒ (wo·h + η wi·h)²)`;
///
/// the `1/η²` is radiance's change across the boundary (Mitsuba's `TransportMode::Radiance`;
/// it cancels the `η²` of Walter's formula), so a ray entering glass carries `1/η²` of what
/// it would in air and one leaving gains `η²`, and a closed object leaves radiance as it
/// was. Both need the facet seen from both sides it must be (`(w·h)·cos θ_w > 0`).
///
/// Sampling draws a normal visible from `wo` ([`Microfacet::sample_visible`]), then
/// reflects with probability `F` and refracts otherwise (`F = 1` under total internal
/// reflection). The density of `wi` is the visible normal's times the lobe's
/// probability times the Jacobian of the map from `h` to `wi`:
///
/// `pdf = D_wo(h)·F/(4|wi·h|)` (reflection), `pdf = D_wo(h)·(1 − F)·η²|wi·h|/(wo·h + η wi·h)²`
/// (transmission), and the weight is `G₁(wi, m)`, times `1/η²` when refracted.
///
/// `specular_reflectance` and `specular_transmittance` multiply the two lobes (1 by
/// default; "for physical realism never touched", as Mitsuba says). Both faces are
/// alike: from inside, `η` is inverted.
#[derive(Clone, Debug, PartialEq)]
pub struct RoughDielectric<F> {
    roughness: Roughness<F>,
    interface: Interface<F>,
    reflectance: Option<Texture<F>>,
    transmittance: Option<Texture<F>>,
}

impl<F: Float> RoughDielectric<F> {
    /// A rough boundary of `roughness` between `interior` and `exterior` (numbers or
    /// named media, [`Ior`]; Mitsuba's defaults are `"bk7"` and `"air"`), each finite,
    /// `> 0`, and the two different.
    pub fn new(roughness: Roughness<F>, interior: impl Into<Ior>, exterior: impl Into<Ior>) -> Result<Self> {
        Ok(Self {
            roughness,
            interface: Interface::new(interior, exterior, true)?,
            reflectance: None,
            transmittance: None,
        })
    }

    /// The same with its reflection multiplied by `factor` (each channel in `[0, 1]`).
    pub fn with_specular_reflectance(self, factor: Texture<F>) -> Result<Self> {
        Ok(Self {
            reflectance: Some(param::unit_colour(Field::SpecularReflectance, factor)?),
            ..self
        })
    }

    /// The same with its transmission multiplied by `factor` (each channel in `[0, 1]`).
    pub fn with_specular_transmittance(self, factor: Texture<F>) -> Result<Self> {
        Ok(Self {
            transmittance: Some(param::unit_colour(Field::SpecularTransmittance, factor)?),
            ..self
        })
    }

    /// How rough it is.
    pub fn roughness(&self) -> &Roughness<F> {
        &self.roughness
    }

    /// The indices either side.
    pub fn interface(&self) -> Interface<F> {
        self.interface
    }

    /// This material in scalar `G`, rounded through `f64` and re-checked.
    pub fn cast<G: Float>(&self) -> Result<RoughDielectric<G>> {
        let i = self.interface.cast::<G>(true)?;
        let mut m = RoughDielectric::new(
            self.roughness.cast()?,
            i.interior().to_f64(),
            i.exterior().to_f64(),
        )?;
        if let Some(t) = &self.reflectance {
            m = m.with_specular_reflectance(param::cast(t)?)?;
        }
        if let Some(t) = &self.transmittance {
            m = m.with_specular_transmittance(param::cast(t)?)?;
        }
        Ok(m)
    }

    fn factor(factor: &Option<Texture<F>>, hit: &Hit<F>) -> Color<F> {
        factor.as_ref().map_or(Color::splat(F::one()), |t| t.eval(hit))
    }

    /// The pieces `eval` and `pdf` share: `wo`, `wi` in the shading frame, `η`, the
    /// generalised half vector `h` and whether `wi` is reflected, when the pair is one
    /// the BSDF connects.
    fn geometry(&self, hit: &Hit<F>, wo: Vec3<F>, wi: Vec3<F>) -> Option<Pair<F>> {
        let frame = hit.shading_frame();
        let (o, i) = (frame.to_local(wo), frame.to_local(wi));
        if o.z <= F::zero() || i.z == F::zero() {
            return None;
        }
        let reflected = i.z > F::zero();
        let eta = self.interface.eta_toward(hit.front_face);
        let h = if reflected { o + i } else { o + i * eta }.try_normalize()?;
        let h = if h.z < F::zero() { -h } else { h };
        let (oh, ih) = (o.dot(h), i.dot(h));
        // The facet must face both directions from the side each is on.
        (oh > F::zero() && ih * i.z > F::zero()).then_some(Pair {
            o,
            i,
            h,
            eta,
            reflected,
            md: self.roughness.at(hit),
        })
    }
}

/// A pair of directions in the shading frame and what connects them.
struct Pair<F> {
    o: Vec3<F>,
    i: Vec3<F>,
    h: Vec3<F>,
    eta: F,
    reflected: bool,
    md: Microfacet<F>,
}

impl<F: Float> Pair<F> {
    /// `F(wo·h)`, with `η₁/η₂ = 1/η` as [`fresnel`] takes it.
    fn fresnel(&self) -> F {
        fresnel(self.o.dot(self.h), self.eta.recip())
    }

    /// `|dh/dwi|`: `1/(4|wi·h|)` reflected, `η²|wi·h|/(wo·h + η wi·h)²` refracted.
    fn jacobian(&self) -> F {
        let (oh, ih) = (self.o.dot(self.h), self.i.dot(self.h));
        if self.reflected {
            (lit::<F>(4.0) * ih.abs()).recip()
        } else {
            let den = oh + self.eta * ih;
            self.eta * self.eta * ih.abs() / (den * den)
        }
    }
}

impl<F: Float> Material<F> for RoughDielectric<F> {
    fn lobes(&self) -> Lobes {
        Lobes::REFLECTION | Lobes::TRANSMISSION | Lobes::GLOSSY
    }

    fn reads_coordinates(&self) -> bool {
        self.roughness.reads_coordinates()
            || self.reflectance.as_ref().is_some_and(Texture::reads_coordinates)
            || self
                .transmittance
                .as_ref()
                .is_some_and(Texture::reads_coordinates)
    }

    fn eval(&self, hit: &Hit<F>, wo: Vec3<F>, wi: Vec3<F>) -> Option<Eval<F>> {
        let p = self.geometry(hit, wo, wi)?;
        let dg = p.md.d(p.h) * p.md.g(p.o, p.i, p.h);
        if dg <= F::zero() {
            return None;
        }
        let f = p.fresnel();
        let colour = if p.reflected {
            Self::factor(&self.reflectance, hit) * (f * dg / (lit::<F>(4.0) * p.o.z))
        } else {
            // (1/η²)·η²|wi·h|/(wo·h + η wi·h)² = jacobian/η².
            let t = (F::one() - f) * dg * p.o.dot(p.h) * p.jacobian() / (p.eta * p.eta * p.o.z);
            Self::factor(&self.transmittance, hit) * t
        };
        Some(Eval {
            colour,
            scale: F::one(),
        })
    }

    fn pdf(&self, hit: &Hit<F>, wo: Vec3<F>, wi: Vec3<F>) -> F {
        let Some(p) = self.geometry(hit, wo, wi) else {
            return F::zero();
        };
        let f = p.fresnel();
        let choice = if p.reflected { f } else { F::one() - f };
        p.md.visible_pdf(p.o, p.h) * choice * p.jacobian()
    }

    fn emits(&self) -> Option<Emission<F>> {
        None
    }
}

impl<F: Float, R: Rng + ?Sized> Scatter<F, R> for RoughDielectric<F> {
    /// Draws three uniform numbers (always): one to choose the lobe, two for the
    /// visible normal. `None` when the drawn direction lands on the wrong side (its
    /// weight `G₁` would be 0).
    fn sample(&self, hit: &Hit<F>, wo: Vec3<F>, rng: &mut R) -> Option<BsdfSample<F>> {
        let (choice, u) = (uniform(rng), [uniform(rng), uniform(rng)]);
        let frame = hit.shading_frame();
        let o = frame.to_local(wo);
        if o.z <= F::zero() {
            return None;
        }
        let md = self.roughness.at(hit);
        let m = md.sample_visible(o, u);
        let visible = md.visible_pdf(o, m);
        let eta = self.interface.eta_toward(hit.front_face);
        let om = o.dot(m);
        let f = fresnel(om, eta.recip());
        let (i, pdf, weight, lobe) = if choice < f.to_f64() {
            let i = m * (lit::<F>(2.0) * om) - o;
            let pdf = visible * f / (lit::<F>(4.0) * i.dot(m).abs());
            (i, pdf, Self::factor(&self.reflectance, hit), Lobes::REFLECTION)
        } else {
            let i = refract(-o, m, eta.recip())?;
            let den = om + eta * i.dot(m);
            let pdf = visible * (F::one() - f) * eta * eta * i.dot(m).abs() / (den * den);
            let weight = Self::factor(&self.transmittance, hit) * (eta * eta).recip();
            (i, pdf, weight, Lobes::TRANSMISSION)
        };
        let g1 = md.g1(i, m);
        if !(pdf > F::zero() && pdf.is_finite()) || g1 <= F::zero() {
            return None;
        }
        Some(BsdfSample {
            direction: frame.to_world(i),
            weight: weight * g1,
            pdf,
            lobe: lobe | Lobes::GLOSSY,
        })
    }
}
