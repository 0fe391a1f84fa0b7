//! The isotropic point light: the specification's extra.

use super::Incident;
use crate::error::{Field, Result};
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
            position: validate::finite_vec(Field::LightPosition, position)?,
            intensity: validate::non_negative(Field::LightIntensity, intensity)?,
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

    /// `I` from `d = |X − x|` away along `(X − x)/d`, falling off as `1/d²`; `None` at
    /// the light itself.
    #[inline]
    pub fn incident(&self, x: Vec3<F>) -> Option<Incident<F>> {
        let (direction, dist2) = aim(x, self.position)?;
        Some(Incident {
            direction,
            distance: dist2.sqrt(),
            intensity: self.intensity,
            falloff: dist2,
        })
    }

    /// This light in scalar `G`, rounded through `f64` and re-validated, as [`EnumScene::cast`](crate::EnumScene::cast) explains.
    pub fn cast<G: Float>(&self) -> Result<PointLight<G>> {
        PointLight::new(self.position.cast(), self.intensity.cast())
    }
}

/// The unit direction from `x` to `target` and their squared distance, `None` if they
/// coincide: the one computation every light at a point (and every sampled point of an
/// emitter) is aimed with, so all of them round the same way.
#[inline(always)]
pub(crate) fn aim<F: Float>(x: Vec3<F>, target: Vec3<F>) -> Option<(Vec3<F>, F)> {
    let to = target - x;
    let dist2 = to.length_squared();
    Some((to.try_normalize()?, dist2))
}
