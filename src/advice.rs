//! Which scalar a scene needs: measured, not guessed.
//!
//! [`advise`] renders a (small) version of the scene in `f32` and `f64` and compares both
//! with a double-double reference along the same random stream; the advice is the
//! cheapest scalar whose image stays within one 8-bit step of the reference on 99 % of
//! the pixels ([`ImageError::within_one_step`]).

use crate::camera::CastCamera;
use crate::double_double::DoubleDouble;
use crate::error::Result;
use crate::float::Float;
use crate::image::{Encoding, Image};
use crate::metrics::ImageError;
use crate::render::{RenderSettings, render};
use crate::scene::EnumScene;
use std::fmt;
use std::time::Duration;

/// The scalar a render runs in: what [`advise`] recommends.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Precision {
    /// Single precision (`f32`).
    F32,
    /// Double precision (`f64`).
    F64,
}

impl fmt::Display for Precision {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Self::F32 => "f32",
            Self::F64 => "f64",
        })
    }
}

/// One scalar's render of the scene, measured against the reference.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Trial {
    /// Its error against the double-double reference.
    pub error: ImageError,
    /// Wall time of its render.
    pub time: Duration,
}

/// The measured precision advice for a scene.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Advice {
    /// The `f32` render.
    pub f32: Trial,
    /// The `f64` render.
    pub f64: Trial,
    /// The cheapest scalar within one 8-bit step of the reference on 99 % of the pixels
    /// (`f64` if neither is).
    pub recommended: Precision,
}

/// Renders `scene` with `camera` and `settings` in `f32`, `f64` and double-double, and
/// advises the cheapest scalar whose image is within one 8-bit step (on sRGB-encoded
/// values) of the double-double one on 99 % of the pixels. Use a small image: the reference
/// render is roughly ten times slower than `f64`.
///
/// # Errors
/// If the scene does not survive rounding to `f32` (a radius that underflows, a triangle
/// that degenerates), or the settings are invalid.
pub fn advise<C: CastCamera>(
    scene: &EnumScene<f64>,
    camera: &C,
    settings: &RenderSettings,
) -> Result<Advice> {
    let (reference, _) = render_in::<DoubleDouble, C>(scene, camera, settings)?;
    let trial = |(image, time): (Image, Duration)| -> Result<Trial> {
        Ok(Trial {
            error: ImageError::between(&image, &reference, Encoding::Srgb)?,
            time,
        })
    };
    let f32 = trial(render_in::<f32, C>(scene, camera, settings)?)?;
    let f64 = trial(render_in::<f64, C>(scene, camera, settings)?)?;
    let recommended = if f32.error.within_one_step() {
        Precision::F32
    } else {
        Precision::F64
    };
    Ok(Advice {
        f32,
        f64,
        recommended,
    })
}

/// Renders the scene in scalar `G`.
fn render_in<G: Float, C: CastCamera>(
    scene: &EnumScene<f64>,
    camera: &C,
    settings: &RenderSettings,
) -> Result<(Image, Duration)> {
    let r = render(&scene.cast::<G>()?, &camera.cast::<G>(), settings)?;
    Ok((r.image, r.stats.elapsed))
}
