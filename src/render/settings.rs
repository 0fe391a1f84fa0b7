//! Render settings.

use crate::error::{Error, Field, Result};

/// How to render: samples per pixel, recursion limit, seed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RenderSettings {
    /// Rays per pixel, at least 1. One goes through the pixel centre; more are jittered.
    pub samples_per_pixel: u32,
    /// The most bounces a path may take: a ray that hits a surface after `max_depth`
    /// bounces returns black. `0` shows only what the camera rays see directly as black
    /// silhouettes against the background. At most [`RenderSettings::MAX_DEPTH`].
    pub max_depth: u32,
    /// The seed every pixel's random stream derives from.
    pub seed: u64,
    /// Show a progress bar on stderr when it is a terminal.
    pub progress: bool,
    /// How the light of emitting surfaces is found (next-event estimation with multiple
    /// importance sampling by default).
    pub light_sampling: LightSampling,
}

/// How the light of emitting surfaces ([`Emissive`](crate::material::Emissive)) is found.
/// Both give the same image in expectation; point lights are sampled either way.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum LightSampling {
    /// At every matte hit one emitter is sampled directly, with a shadow ray
    /// (next-event estimation), and that light and the light the scattered ray finds are
    /// weighted by the power heuristic (multiple importance sampling). The default.
    #[default]
    Mis,
    /// Only scattered rays find emitters: the plain path tracer, noisy for small lights.
    Bsdf,
}

impl RenderSettings {
    /// The deepest recursion accepted. The trace takes one stack frame per bounce (the
    /// spec's recursive trace), and a path trapped between mirrors uses every one: 5000
    /// bounces already fit in a 2 MiB thread stack (rayon's default) in `f64` and 7000
    /// overflowed it, so 1000 leaves room for every scalar and for pairs of rays. No image
    /// needs more: after 1000 bounces on albedo 0.99 a path carries 4·10⁻⁵ of its light.
    pub const MAX_DEPTH: u32 = 1000;

    /// Settings with the given samples per pixel, depth and seed (no progress bar).
    ///
    /// # Errors
    /// If `samples_per_pixel` is 0 or `max_depth` exceeds [`RenderSettings::MAX_DEPTH`].
    pub fn new(samples_per_pixel: u32, max_depth: u32, seed: u64) -> Result<Self> {
        let s = Self {
            samples_per_pixel,
            max_depth,
            seed,
            progress: false,
            light_sampling: LightSampling::Mis,
        };
        s.validate()?;
        Ok(s)
    }

    /// Checks the settings (the fields are public, so the renderer checks again).
    ///
    /// # Errors
    /// [`Error::InvalidValue`] at [`Field::SamplesPerPixel`] or [`Field::MaxDepth`].
    pub fn validate(&self) -> Result<()> {
        if self.samples_per_pixel == 0 {
            return Err(Error::invalid(
                Field::SamplesPerPixel,
                "must be at least 1 (got 0)",
            ));
        }
        if self.max_depth > Self::MAX_DEPTH {
            return Err(Error::invalid(
                Field::MaxDepth,
                format!(
                    "must be at most {} (got {}): the recursion takes a stack frame per bounce",
                    Self::MAX_DEPTH,
                    self.max_depth
                ),
            ));
        }
        Ok(())
    }
}

/// The spec's minimum: one ray per pixel centre, `max_depth = 10`, seed 0.
impl Default for RenderSettings {
    fn default() -> Self {
        Self {
            samples_per_pixel: 1,
            max_depth: 10,
            seed: 0,
            progress: false,
            light_sampling: LightSampling::Mis,
        }
    }
}
