//! A thin dielectric sheet (a window pane, a soap bubble), Mitsuba 3's `thindielectric`.

use super::ior::Ior;
use super::{BsdfSample, Emission, Eval, Interface, Lobes, Material, Scatter, param};
use crate::error::{Field, Result};
use crate::float::{Float, lit};
use crate::optics::{fresnel, reflect};
use crate::sampling::uniform;
use crate::shape::Hit;
use crate::texture::Texture;
use crate::vec3::{Color, Vec3};
use rand::Rng;

/// A thin sheet of dielectric, Mitsuba 3's `thindielectric`: two parallel smooth
/// boundaries so close that the light passing through is not displaced. Light bounces
/// between them; summing every path (`R + T²R + T²R³ + …` reflected, `T = 1 − R`), the
/// sheet reflects
///
/// `R' = 2R/(1 + R)`, `R = F(|cos θ|)` the exact dielectric [`fresnel`] into the sheet,
///
/// and lets `1 − R'` straight through (`wi = −wo`, unrefracted). Sampling picks one with
/// those probabilities, so the weight is 1 (times `specular_reflectance` or
/// `specular_transmittance`, 1 by default). Both lobes are deltas; both faces alike.
#[derive(Clone, Debug, PartialEq)]
pub struct ThinDielectric<F> {
    interface: Interface<F>,
    reflectance: Option<Texture<F>>,
    transmittance: Option<Texture<F>>,
}

impl<F: Float> ThinDielectric<F> {
    /// A sheet of index `interior` in a medium of index `exterior` (numbers or named
    /// media, [`Ior`]; Mitsuba's defaults are `"bk7"` and `"air"`), each finite and `> 0`.
    pub fn new(interior: impl Into<Ior>, exterior: impl Into<Ior>) -> Result<Self> {
        Ok(Self {
            interface: Interface::new(interior, exterior, false)?,
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

    /// The indices.
    pub fn interface(&self) -> Interface<F> {
        self.interface
    }

    /// The share `R' = 2R/(1 + R)` the sheet reflects at `cos θ`.
    #[inline]
    pub fn reflectance_at(&self, cos_theta: F) -> F {
        let r = fresnel(cos_theta.abs(), self.interface.eta().recip());
        r * lit::<F>(2.0) / (F::one() + r)
    }

    /// This material in scalar `G`, rounded through `f64` and re-checked.
    pub fn cast<G: Float>(&self) -> Result<ThinDielectric<G>> {
        let i = self.interface.cast::<G>(false)?;
        let mut m = ThinDielectric::new(i.interior().to_f64(), i.exterior().to_f64())?;
        if let Some(t) = &self.reflectance {
            m = m.with_specular_reflectance(param::cast(t)?)?;
        }
        if let Some(t) = &self.transmittance {
            m = m.with_specular_transmittance(param::cast(t)?)?;
        }
        Ok(m)
    }
}

impl<F: Float> Material<F> for ThinDielectric<F> {
    fn lobes(&self) -> Lobes {
        Lobes::REFLECTION | Lobes::TRANSMISSION | Lobes::DELTA
    }

    fn reads_coordinates(&self) -> bool {
        self.reflectance.as_ref().is_some_and(Texture::reads_coordinates)
            || self
                .transmittance
                .as_ref()
                .is_some_and(Texture::reads_coordinates)
    }

    /// None: both lobes are deltas.
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

impl<F: Float, R: Rng + ?Sized> Scatter<F, R> for ThinDielectric<F> {
    /// Reflects with probability `R'`, else goes straight through; one uniform number.
    fn sample(&self, hit: &Hit<F>, wo: Vec3<F>, rng: &mut R) -> Option<BsdfSample<F>> {
        let u = uniform(rng);
        let n = hit.shading_normal;
        let r = self.reflectance_at(n.dot(wo));
        let factor = |t: &Option<Texture<F>>| t.as_ref().map_or(Color::splat(F::one()), |t| t.eval(hit));
        Some(if u < r.to_f64() {
            BsdfSample {
                direction: reflect(-wo, n),
                weight: factor(&self.reflectance),
                pdf: r,
                lobe: Lobes::REFLECTION | Lobes::DELTA,
            }
        } else {
            BsdfSample {
                direction: -wo,
                weight: factor(&self.transmittance),
                pdf: F::one() - r,
                lobe: Lobes::TRANSMISSION | Lobes::DELTA,
            }
        })
    }
}
