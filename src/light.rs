//! Lights: point lights, and the scene's emitting surfaces as lights to sample
//! ([`Emitters`], chosen by power) with the weights that combine two ways of finding
//! their light ([`power_heuristic`]).

mod emitters;
mod mis;

pub use emitters::Emitters;
pub use mis::power_heuristic;

use crate::error::Result;
use crate::float::Float;
use crate::validate;
use crate::vec3::{Color, Vec3};

/// An isotropic point light: radiant intensity `I` (per colour channel) at a position.
///
/// At a matte surface point `P` with normal `N` and albedo `A`, a visible light adds
/// `A/π · I · max(0, N·L)/|X − P|²`, `L` the unit vector towards the light at `X`
/// (the BRDF `A/π`, the cosine factor, and the inverse-square falloff).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointLight<F> {
    position: Vec3<F>,
    intensity: Color<F>,
}

impl<F: Float> PointLight<F> {
    /// A light; the position must be finite, the intensity finite and `≥ 0`.
    pub fn new(position: Vec3<F>, intensity: Color<F>) -> Result<Self> {
        Ok(Self {
            position: validate::finite_vec(crate::error::Field::LightPosition, position)?,
            intensity: validate::non_negative(crate::error::Field::LightIntensity, intensity)?,
        })
    }

    /// The light's position.
    pub fn position(&self) -> Vec3<F> {
        self.position
    }

    /// The radiant intensity `I`.
    pub fn intensity(&self) -> Color<F> {
        self.intensity
    }

    /// This light in scalar `G`, rounded through `f64` and re-validated, as [`EnumScene::cast`](crate::EnumScene::cast) explains.
    pub fn cast<G: Float>(&self) -> Result<PointLight<G>> {
        PointLight::new(self.position.cast(), self.intensity.cast())
    }
}
