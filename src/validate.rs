//! Checks shared by the constructors: every scene value is validated once, where it enters.

use crate::error::{Error, Result};
use crate::float::Float;
use crate::vec3::Vec3;

/// `v` if every component is finite.
pub(crate) fn finite_vec<F: Float>(what: &'static str, v: Vec3<F>) -> Result<Vec3<F>> {
    if v.is_finite() {
        Ok(v)
    } else {
        Err(Error::invalid(what, format!("must be finite, got {v:?}")))
    }
}

/// `x` if it is finite and strictly positive.
pub(crate) fn positive<F: Float>(what: &'static str, x: F) -> Result<F> {
    if x.is_finite() && x > F::zero() {
        Ok(x)
    } else {
        Err(Error::invalid(what, format!("must be finite and > 0, got {x}")))
    }
}

/// `c` if every channel lies in `[0, 1]` (an albedo: a surface cannot reflect more than it receives).
pub(crate) fn albedo<F: Float>(what: &'static str, c: Vec3<F>) -> Result<Vec3<F>> {
    let ok = |x: F| x >= F::zero() && x <= F::one();
    if ok(c.x) && ok(c.y) && ok(c.z) {
        Ok(c)
    } else {
        Err(Error::invalid(
            what,
            format!("each channel must be in [0, 1], got {c:?}"),
        ))
    }
}

/// `c` if every channel is finite and non-negative (a radiance or an intensity).
pub(crate) fn non_negative<F: Float>(what: &'static str, c: Vec3<F>) -> Result<Vec3<F>> {
    let ok = |x: F| x.is_finite() && x >= F::zero();
    if ok(c.x) && ok(c.y) && ok(c.z) {
        Ok(c)
    } else {
        Err(Error::invalid(
            what,
            format!("each channel must be finite and ≥ 0, got {c:?}"),
        ))
    }
}

/// A unit vector along `v`, if `v` is finite and not (nearly) zero.
pub(crate) fn direction<F: Float>(what: &'static str, v: Vec3<F>) -> Result<Vec3<F>> {
    finite_vec(what, v)?
        .try_normalize()
        .ok_or_else(|| Error::invalid(what, format!("must be a non-zero vector, got {v:?}")))
}
