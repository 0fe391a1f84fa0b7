//! Shadow rays that wait: a light's contribution at a bounce, and how the contributions
//! that arrive add up.

use crate::float::Float;
use crate::ray::Ray;
use crate::vec3::Color;

/// A light's contribution at a bounce, waiting on its shadow ray: it arrives unless
/// something blocks `ray` in `(0, reach)`. Where the batch walks a tree, shading does not
/// wait for the answer, so that the shadow rays of many paths are traced together
/// (`Scene::occluded_all`), as their rays are.
#[derive(Clone, Copy, Debug)]
pub(super) struct Shadow<F> {
    /// The shadow ray.
    pub(super) ray: Ray<F>,
    /// Where the light is along it; with `aimed`, a bound past it.
    pub(super) reach: F,
    /// The emitter's part `(object, part)` the ray is aimed at, where the walk is left to
    /// find the light's own distance ([`Scene::occluded_all`](crate::Scene)): `None`
    /// where `reach` is the light's exact distance.
    pub(super) aimed: Option<(u32, u32)>,
    /// The light that arrives if nothing blocks it.
    pub(super) light: Color<F>,
    /// Whether it is the light sample's (of an emitter or the background), not a delta
    /// light's (point, spot, directional).
    pub(super) sampled: bool,
}

/// `direct` with the light of a bounce's `shadows` whose rays arrive (`blocked(i)` false
/// for `shadows[i]`), added as [`Tracer::shade`](super::Tracer) adds them when it traces each at once: the
/// delta lights' sum, then the light sample's.
pub(super) fn arrive<F: Float>(
    direct: Color<F>,
    shadows: &[Shadow<F>],
    blocked: impl Fn(usize) -> bool,
) -> Color<F> {
    let (mut sum, mut sample) = (None, None);
    for (i, s) in shadows.iter().enumerate() {
        match (blocked(i), s.sampled) {
            (true, _) => {}
            (false, true) => sample = Some(s.light),
            (false, false) => sum = Some(sum.map_or(s.light, |sum| sum + s.light)),
        }
    }
    let direct = sum.map_or(direct, |sum| sum + direct);
    sample.map_or(direct, |light| direct + light)
}
