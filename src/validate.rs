//! The checks every scene value passes, once, where it enters.
//!
//! The constructors call them with their typed [`Field`]; a scene file calls the same
//! [`rule`]s for the keys only it has (a mesh's scale, a camera's aspect). A reason reads
//! after a field's name (`invalid sphere radius: must be > 0 (got -1)`) as well as after a
//! scene file's key (`objects[3].radius: must be > 0 (got -1)`), so there is one wording.

use crate::error::{Error, Field, Result};
use crate::float::Float;
use crate::vec3::Vec3;

/// `[x, y, z]`, each component as [`number`] writes it.
pub(crate) fn show<F: Float>(v: Vec3<F>) -> String {
    format!("[{}, {}, {}]", number(v.x), number(v.y), number(v.z))
}

/// `x` as `Display` writes it (the shortest form that reads back), but in scientific
/// notation for magnitudes from 10¹⁶ or below 10⁻⁶: `1e39`, not forty digits; `1e-60`, not
/// sixty zeros.
pub(crate) fn number(x: impl std::fmt::Display) -> String {
    let plain = x.to_string();
    let body = plain.strip_prefix('-').unwrap_or(&plain);
    if plain.len() <= 16 || !body.bytes().all(|b| b.is_ascii_digit() || b == b'.') {
        return plain;
    }
    let sign = if body.len() < plain.len() { "-" } else { "" };
    let (int, frac) = body.split_once('.').unwrap_or((body, ""));
    let digits = format!("{int}{frac}");
    let Some(first) = digits.find(|c| c != '0') else {
        return plain;
    };
    let exponent = int.len() as i64 - 1 - first as i64;
    if (-6..16).contains(&exponent) {
        return plain;
    }
    let significant = digits[first..].trim_end_matches('0');
    let (lead, rest) = significant.split_at(1);
    let dot = if rest.is_empty() { "" } else { "." };
    format!("{sign}{lead}{dot}{rest}e{exponent}")
}

/// The rules, each returning the value or why it is refused.
pub(crate) mod rule {
    use super::show;
    use crate::float::Float;
    use crate::vec3::Vec3;

    /// `v` if every component is finite.
    pub(crate) fn finite<F: Float>(v: Vec3<F>) -> Result<Vec3<F>, String> {
        if v.is_finite() {
            Ok(v)
        } else {
            Err(format!("every component must be finite (got {})", show(v)))
        }
    }

    /// `x` if it is finite and strictly positive.
    pub(crate) fn positive<F: Float>(x: F) -> Result<F, String> {
        if !x.is_finite() {
            Err(format!("must be a finite number > 0 (got {x})"))
        } else if x > F::zero() {
            Ok(x)
        } else {
            Err(format!("must be > 0 (got {})", super::number(x)))
        }
    }

    /// `c` if every channel lies in `[0, 1]` (an albedo: a surface cannot reflect more than
    /// it receives).
    pub(crate) fn albedo<F: Float>(c: Vec3<F>) -> Result<Vec3<F>, String> {
        let ok = |x: F| x >= F::zero() && x <= F::one();
        if ok(c.x) && ok(c.y) && ok(c.z) {
            Ok(c)
        } else {
            Err(format!("each channel must be in [0, 1] (got {})", show(c)))
        }
    }

    /// `c` if every channel is finite and non-negative (a radiance or an intensity).
    pub(crate) fn non_negative<F: Float>(c: Vec3<F>) -> Result<Vec3<F>, String> {
        let ok = |x: F| x.is_finite() && x >= F::zero();
        if ok(c.x) && ok(c.y) && ok(c.z) {
            Ok(c)
        } else {
            Err(format!("each channel must be finite and ≥ 0 (got {})", show(c)))
        }
    }

    /// A unit vector along `v`, if `v` is finite and not (nearly) zero.
    pub(crate) fn direction<F: Float>(v: Vec3<F>) -> Result<Vec3<F>, String> {
        finite(v)?
            .try_normalize()
            .ok_or_else(|| format!("must be a non-zero vector (got {})", show(v)))
    }
}

/// `v` if every component is finite.
pub(crate) fn finite_vec<F: Float>(field: Field, v: Vec3<F>) -> Result<Vec3<F>> {
    rule::finite(v).map_err(|why| Error::invalid(field, why))
}

/// `x` if it is finite and strictly positive.
pub(crate) fn positive<F: Float>(field: Field, x: F) -> Result<F> {
    rule::positive(x).map_err(|why| Error::invalid(field, why))
}

/// `c` if every channel lies in `[0, 1]`.
pub(crate) fn albedo<F: Float>(field: Field, c: Vec3<F>) -> Result<Vec3<F>> {
    rule::albedo(c).map_err(|why| Error::invalid(field, why))
}

/// `c` if every channel is finite and non-negative.
pub(crate) fn non_negative<F: Float>(field: Field, c: Vec3<F>) -> Result<Vec3<F>> {
    rule::non_negative(c).map_err(|why| Error::invalid(field, why))
}

/// A unit vector along `v`, if `v` is finite and not (nearly) zero.
pub(crate) fn direction<F: Float>(field: Field, v: Vec3<F>) -> Result<Vec3<F>> {
    rule::direction(v).map_err(|why| Error::invalid(field, why))
}

/// `Ok` if a camera can make a `width × height` image ([`check_size`](crate::image::check_size)).
pub(crate) fn image_size(width: usize, height: usize) -> Result<()> {
    crate::image::check_size(width, height).map_err(|_| {
        Error::invalid(
            Field::ImageSize,
            format!(
                "the image must have at least 1×1 and at most {} pixels (got {width}×{height})",
                crate::image::MAX_PIXELS
            ),
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn long_numbers_are_written_in_scientific_notation() {
        assert_eq!(number(1e39), "1e39");
        assert_eq!(number(-1e-60), "-1e-60");
        assert_eq!(number(1.2345678901234568e20), "1.2345678901234568e20");
        assert_eq!(number(1e30f32), "1e30");
        assert_eq!(number(0.5), "0.5");
        assert_eq!(number(16.0 / 9.0), "1.7777777777777777");
        assert_eq!(number(0.000_123_456_789_012_345_67), "0.00012345678901234567");
        assert_eq!(number(-3.0), "-3");
        assert_eq!(number(f64::NEG_INFINITY), "-inf");
        assert_eq!(number(f64::NAN), "NaN");
        assert_eq!(show(Vec3::new(1e39, 0.0, -3.0)), "[1e39, 0, -3]");
    }
}
