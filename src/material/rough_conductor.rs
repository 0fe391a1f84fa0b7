//! A rough conductor (a brushed or frosted metal), Mitsuba 3's `roughconductor`.

use super::microfacet::Microfacet;
use super::{BsdfSample, Emission, Eval, Lobes, Material, Metal, Roughness, Scatter};
use crate::error::Result;
use crate::float::{Float, lit};
use crate::sampling::uniform;
use crate::shape::Hit;
use crate::vec3::Vec3;
use rand::Rng;

/// A rough conductor, Mitsuba 3's `roughconductor` (Walter et al. 2007, "Microfacet
/// Models for Refraction through Rough Surfaces", its reflection part): a surface of
/// mirror microfacets of a [`Metal`] whose normals follow a microfacet distribution
/// ([`Roughness`]). In the shading frame, with `h = (wo + wi)/|wo + wi|`,
///
/// `f(wo, wi)·cos θᵢ = F(wo·h)·D(h)·G(wo, wi, h) / (4 cos θₒ)`,
///
/// `F` the metal's [`reflectance`](Metal::reflectance), `D` and `G` the distribution's
/// ([`Microfacet`]), both `cos θ > 0`. It samples the normals visible from `wo`
/// ([`Microfacet::sample_visible`]) and reflects `wo` about them, so
///
/// `pdf(wi) = D_wo(h)/(4 wi·h) = D(h)·G₁(wo, h)/(4 cos θₒ)` (`1/(4 wi·h)` the Jacobian of
/// the reflection), weight `F(wo·m)·G₁(wi, m)`.
///
/// One-sided, as in Mitsuba: black seen from its back face ([`TwoSided`](super::TwoSided)
/// shades both).
#[derive(Clone, Debug, PartialEq)]
pub struct RoughConductor<F> {
    metal: Metal<F>,
    roughness: Roughness<F>,
}

impl<F: Float> RoughConductor<F> {
    /// A surface of `metal` with `roughness`.
    pub fn new(metal: Metal<F>, roughness: Roughness<F>) -> Self {
        Self { metal, roughness }
    }

    /// What it is made of.
    pub fn metal(&self) -> &Metal<F> {
        &self.metal
    }

    /// How rough it is.
    pub fn roughness(&self) -> &Roughness<F> {
        &self.roughness
    }

    /// This material in scalar `G`, rounded through `f64` and re-checked.
    pub fn cast<G: Float>(&self) -> Result<RoughConductor<G>> {
        Ok(RoughConductor::new(self.metal.cast()?, self.roughness.cast()?))
    }

    /// `wo` and `wi` in the shading frame, with the distribution at `hit`, when light can
    /// go between them: the front face, both above the surface.
    fn local(&self, hit: &Hit<F>, wo: Vec3<F>, wi: Vec3<F>) -> Option<(Vec3<F>, Vec3<F>, Microfacet<F>)> {
        let frame = hit.shading_frame();
        let (o, i) = (frame.to_local(wo), frame.to_local(wi));
        (hit.front_face && o.z > F::zero() && i.z > F::zero()).then(|| (o, i, self.roughness.at(hit)))
    }
}

impl<F: Float> Material<F> for RoughConductor<F> {
    fn lobes(&self) -> Lobes {
        Lobes::REFLECTION | Lobes::GLOSSY
    }

    fn reads_coordinates(&self) -> bool {
        self.metal.reads_coordinates() || self.roughness.reads_coordinates()
    }

    fn eval(&self, hit: &Hit<F>, wo: Vec3<F>, wi: Vec3<F>) -> Option<Eval<F>> {
        let (o, i, md) = self.local(hit, wo, wi)?;
        let h = (o + i).try_normalize()?;
        let dg = md.d(h) * md.g(o, i, h);
        if dg <= F::zero() {
            return None;
        }
        Some(Eval {
            colour: self.metal.reflectance(hit, o.dot(h)) * (dg / (lit::<F>(4.0) * o.z)),
            scale: F::one(),
        })
    }

    fn pdf(&self, hit: &Hit<F>, wo: Vec3<F>, wi: Vec3<F>) -> F {
        let Some((o, i, md)) = self.local(hit, wo, wi) else {
            return F::zero();
        };
        match (o + i).try_normalize() {
            // Both must see the facet's front, as G₁ demands of the samples.
            Some(h) if o.dot(h) > F::zero() && i.dot(h) > F::zero() => {
                md.d(h) * md.g1(o, h) / (lit::<F>(4.0) * o.z)
            }
            _ => F::zero(),
        }
    }

    fn emits(&self) -> Option<Emission<F>> {
        None
    }
}

impl<F: Float, R: Rng + ?Sized> Scatter<F, R> for RoughConductor<F> {
    /// Reflects `wo` about a visible normal drawn from two uniform numbers (always two,
    /// whatever happens); `None` on the back face or when the reflection points below
    /// the surface.
    fn sample(&self, hit: &Hit<F>, wo: Vec3<F>, rng: &mut R) -> Option<BsdfSample<F>> {
        let u = [uniform(rng), uniform(rng)];
        let frame = hit.shading_frame();
        let o = frame.to_local(wo);
        if !hit.front_face || o.z <= F::zero() {
            return None;
        }
        let md = self.roughness.at(hit);
        let m = md.sample_visible(o, u);
        let cos = o.dot(m);
        let i = m * (lit::<F>(2.0) * cos) - o;
        if i.z <= F::zero() {
            return None;
        }
        let pdf = md.visible_pdf(o, m) / (lit::<F>(4.0) * i.dot(m));
        if !(pdf > F::zero() && pdf.is_finite()) {
            return None;
        }
        Some(BsdfSample {
            direction: frame.to_world(i),
            weight: self.metal.reflectance(hit, cos) * md.g1(i, m),
            pdf,
            lobe: Lobes::REFLECTION | Lobes::GLOSSY,
        })
    }
}
