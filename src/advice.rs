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
#[derive(Clone, Debug, PartialEq)]
pub struct Advice {
    /// The `f32` render; `None` when the scene cannot be built in `f32` at all.
    pub f32: Option<Trial>,
    /// The `f64` render.
    pub f64: Trial,
    /// The cheapest scalar within one 8-bit step of the reference on 99 % of the pixels
    /// (`f64` if neither is, or if `f32` cannot hold the scene).
    pub recommended: Precision,
    /// Why: what the `f32` render showed, or why there is none.
    pub reason: Reason,
}

/// Why [`Advice::recommended`] is what it is.
#[derive(Clone, Debug, PartialEq)]
pub enum Reason {
    /// `f32`'s image is within one 8-bit step of the reference on 99 % of the pixels.
    F32Close,
    /// `f32`'s image is not.
    F32Off,
    /// The scene cannot be built in `f32`: a value does not survive rounding to it (the
    /// error's message says which).
    F32CannotHold(String),
}

impl fmt::Display for Reason {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::F32Close => f.write_str("f32 is within one 8-bit step on 99 % of the pixels"),
            Self::F32Off => f.write_str("f32 is more than one 8-bit step off on over 1 % of the pixels"),
            Self::F32CannotHold(why) => write!(f, "the scene cannot be built in f32: {why}"),
        }
    }
}

/// Renders `scene` with `camera` and `settings` in `f32`, `f64` and double-double, and
/// advises the cheapest scalar whose image is within one 8-bit step (on sRGB-encoded
/// values) of the double-double one on 99 % of the pixels. A scene that cannot be built
/// in `f32` (a radius that underflows, a triangle that degenerates) is advised `f64`,
/// with the reason. Use a small image: the reference render is roughly ten times slower
/// than `f64`.
///
/// # Errors
/// If the settings are invalid, or the scene cannot be built in double-double.
pub fn advise<C: CastCamera>(
    scene: &EnumScene<f64>,
    camera: &C,
    settings: &RenderSettings,
) -> Result<Advice> {
    let (reference, _) = render_in::<DoubleDouble, C>(&scene.cast()?, camera, settings)?;
    let trial = |(image, time): (Image, Duration)| -> Result<Trial> {
        Ok(Trial {
            error: ImageError::between(&image, &reference, Encoding::Srgb)?,
            time,
        })
    };
    let f64 = trial(render_in::<f64, C>(scene, camera, settings)?)?;
    let (f32, recommended, reason) = match scene.cast::<f32>() {
        Err(e) => (None, Precision::F64, Reason::F32CannotHold(e.to_string())),
        Ok(single) => {
            let f32 = trial(render_in::<f32, C>(&single, camera, settings)?)?;
            let (recommended, reason) = if f32.error.within_one_step() {
                (Precision::F32, Reason::F32Close)
            } else {
                (Precision::F64, Reason::F32Off)
            };
            (Some(f32), recommended, reason)
        }
    };
    Ok(Advice {
        f32,
        f64,
        recommended,
        reason,
    })
}

/// Renders `scene` (in scalar `G`) with `camera`.
fn render_in<G: Float, C: CastCamera>(
    scene: &EnumScene<G>,
    camera: &C,
    settings: &RenderSettings,
) -> Result<(Image, Duration)> {
    let r = render(scene, &camera.cast::<G>(), settings)?;
    Ok((r.image, r.stats.elapsed))
}
