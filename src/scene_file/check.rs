//! Value checks with messages in the file's terms: `must be > 0 (got -1)`.
//!
//! They run in `f64` on the values as written, before the library's constructors run in
//! the render's scalar; a value that only fails after rounding is caught by
//! [`blame`], which keeps the constructor's message.

use super::location::Field;
use super::model::Triple;
use crate::error::{Error, Result};
use crate::float::Float;
use crate::vec3::Vec3;

/// `[x, y, z]` as the file writes it.
pub fn show(t: Triple) -> String {
    format!("[{}, {}, {}]", t[0], t[1], t[2])
}

/// `t` in scalar `F`, each component rounded to nearest.
pub fn vec<F: Float>(t: Triple) -> Vec3<F> {
    Vec3::from_f64(t[0], t[1], t[2])
}

/// `x` if it is finite and `> 0`.
pub fn positive(at: &Field, x: f64) -> Result<f64> {
    if !x.is_finite() {
        Err(at.error(format!("must be a finite number > 0 (got {x})")))
    } else if x > 0.0 {
        Ok(x)
    } else {
        Err(at.error(format!("must be > 0 (got {x})")))
    }
}

/// `t` if every component is finite.
pub fn finite(at: &Field, t: Triple) -> Result<Triple> {
    if t.iter().all(|c| c.is_finite()) {
        Ok(t)
    } else {
        Err(at.error(format!("every component must be finite (got {})", show(t))))
    }
}

/// `t` if it is finite and not zero (a direction).
pub fn direction(at: &Field, t: Triple) -> Result<Triple> {
    if finite(at, t)?.iter().any(|&c| c != 0.0) {
        Ok(t)
    } else {
        Err(at.error(format!("must be a non-zero vector (got {})", show(t))))
    }
}

/// `t` if every channel is in `[0, 1]`: an albedo (a surface reflects at most what it
/// receives).
pub fn albedo(at: &Field, t: Triple) -> Result<Triple> {
    if t.iter().all(|c| (0.0..=1.0).contains(c)) {
        Ok(t)
    } else {
        Err(at.error(format!("each channel must be in [0, 1] (got {})", show(t))))
    }
}

/// `t` if every channel is finite and `≥ 0`: a colour or an intensity.
pub fn non_negative(at: &Field, t: Triple) -> Result<Triple> {
    if t.iter().all(|c| c.is_finite() && *c >= 0.0) {
        Ok(t)
    } else {
        Err(at.error(format!("each channel must be finite and ≥ 0 (got {})", show(t))))
    }
}

/// A library constructor's error in scalar `F` as an error at the field it concerns:
/// `fields` maps the constructor's `what` to a key below `at`; anything else is put on
/// `at` itself. The values passed the checks above, so this is a value that did not
/// survive rounding to `F` (or a whole-object condition, such as a degenerate triangle).
pub fn blame<F: Float>(at: &Field, e: Error, fields: &[(&str, &str)]) -> Error {
    let target = match &e {
        Error::InvalidValue { what, .. } => {
            fields.iter().find(|(w, _)| w == what).map(|(_, key)| at.key(key))
        }
        _ => None,
    };
    target
        .unwrap_or_else(|| at.clone())
        .error(format!("{e} (in {})", F::NAME))
}
