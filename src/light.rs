//! Lights: the delta lights a shading point sees through one shadow ray each ([`Light`]:
//! point, spot and directional), and the scene's emitting surfaces as lights to sample
//! ([`Emitters`], chosen by power) with the weights that combine two ways of finding
//! their light ([`power_heuristic`]).

mod directional;
mod emitters;
mod mis;
mod point;
mod spot;

pub use directional::DirectionalLight;
pub use emitters::Emitters;
pub use mis::power_heuristic;
pub use point::PointLight;
pub(crate) use point::aim;
pub use spot::SpotLight;

use crate::error::Result;
use crate::float::Float;
use crate::vec3::{Color, Vec3};

/// A light that reaches a point along one direction only (a delta light): no ray can hit
/// it, so it lights a surface through a shadow ray alone; in Mitsuba 3's terms `point`,
/// `spot` and `directional`.
///
/// Every kind answers one question, [`Light::incident`]: what arrives at a shading point.
/// The renderer's light loop asks only that, never which kind of light it is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Light<F> {
    /// An isotropic point light ([`PointLight`]).
    Point(PointLight<F>),
    /// A point light shining into a cone ([`SpotLight`]).
    Spot(SpotLight<F>),
    /// A light at infinity shining one way, the sun ([`DirectionalLight`]).
    Directional(DirectionalLight<F>),
}

/// What a light sends to a point `x`: the light arriving there is `intensity/falloff`
/// along `direction`, if nothing lies within `distance` of `x` that way.
///
/// A light at a point gives `intensity = I` (times a spot's falloff) and `falloff = d²`,
/// the inverse-square law; a light at infinity gives its irradiance `E` with `falloff = 1`
/// and `distance = ∞`. The two are kept apart, not divided, so the light loop folds them
/// into the BSDF's scale as `(f ∘ I)·(scale/d²)`, the arithmetic the specification's point
/// lights have always had.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Incident<F> {
    /// The unit direction from `x` toward the light.
    pub direction: Vec3<F>,
    /// How far the shadow ray must go unblocked: the distance to the light, `∞` for a
    /// light at infinity.
    pub distance: F,
    /// `I` for a light at a point (a spot's falloff included), `E` for one at infinity.
    pub intensity: Color<F>,
    /// What `intensity` is divided by: `d²` at a point, 1 at infinity.
    pub falloff: F,
}

impl<F: Float> Light<F> {
    /// What the light sends to the point `x` (a shadow ray's origin), or `None` if it sends
    /// nothing there: `x` is the light's own position, or outside a spot's cone.
    // Always inlined: called, it returns the incident light through memory, once per
    // light at every shading point.
    #[inline(always)]
    pub fn incident(&self, x: Vec3<F>) -> Option<Incident<F>> {
        match self {
            Self::Point(l) => l.incident(x),
            Self::Spot(l) => l.incident(x),
            Self::Directional(l) => l.incident(x),
        }
    }

    /// This light in scalar `G`, rounded through `f64` and re-validated, as
    /// [`EnumScene::cast`](crate::EnumScene::cast) explains.
    pub fn cast<G: Float>(&self) -> Result<Light<G>> {
        Ok(match self {
            Self::Point(l) => l.cast()?.into(),
            Self::Spot(l) => l.cast()?.into(),
            Self::Directional(l) => l.cast()?.into(),
        })
    }
}

impl<F> From<PointLight<F>> for Light<F> {
    fn from(light: PointLight<F>) -> Self {
        Self::Point(light)
    }
}

impl<F> From<SpotLight<F>> for Light<F> {
    fn from(light: SpotLight<F>) -> Self {
        Self::Spot(light)
    }
}

impl<F> From<DirectionalLight<F>> for Light<F> {
    fn from(light: DirectionalLight<F>) -> Self {
        Self::Directional(light)
    }
}
