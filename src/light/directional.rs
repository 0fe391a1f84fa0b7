//! The directional light: the sun, as Mitsuba 3's `directional`.

use super::Incident;
use crate::error::{Field, Result};
use crate::float::Float;
use crate::validate;
use crate::vec3::{Color, Vec3};

/// A light at infinity shining along one direction, as Mitsuba 3's `directional` emitter:
/// every point it reaches receives the irradiance `E` on a surface facing it, along the
/// same direction, with no falloff. At a matte surface of albedo `A` whose normal makes
/// the angle `θ` with the way to the light, it adds `A/π · E · cos θ`, if a shadow ray
/// toward the light escapes the scene.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DirectionalLight<F> {
    /// Unit: the way the light travels.
    direction: Vec3<F>,
    /// `−direction`: the way to the light.
    toward: Vec3<F>,
    irradiance: Color<F>,
}

impl<F: Float> DirectionalLight<F> {
    /// A light travelling along `direction` (finite, non-zero, any length) with irradiance
    /// `E` (finite, `≥ 0`) on a surface facing it.
    ///
    /// # Errors
    /// A value outside its domain, under its [`Field`].
    pub fn new(direction: Vec3<F>, irradiance: Color<F>) -> Result<Self> {
        let direction = validate::direction(Field::LightDirection, direction)?;
        Ok(Self {
            direction,
            toward: -direction,
            irradiance: validate::non_negative(Field::LightIrradiance, irradiance)?,
        })
    }

    /// The unit direction the light travels along.
    pub fn direction(&self) -> Vec3<F> {
        self.direction
    }

    /// The irradiance `E` on a surface facing the light.
    pub fn irradiance(&self) -> Color<F> {
        self.irradiance
    }

    /// `E` from infinitely far along `−direction`, the same at every point.
    #[inline]
    pub fn incident(&self, _x: Vec3<F>) -> Option<Incident<F>> {
        Some(Incident {
            direction: self.toward,
            distance: F::infinity(),
            intensity: self.irradiance,
            falloff: F::one(),
        })
    }

    /// This light in scalar `G`, rounded through `f64` and re-validated, as [`EnumScene::cast`](crate::EnumScene::cast) explains.
    pub fn cast<G: Float>(&self) -> Result<DirectionalLight<G>> {
        DirectionalLight::new(self.direction.cast(), self.irradiance.cast())
    }
}
