//! The validity predicates (see the crate docs) and `expect`, which judges a constructor by them.

use proptest::prelude::*;
use raytrace::image::MAX_PIXELS;
use raytrace::{Float, Vec3};
use std::fmt::Debug;
use twofloat::TwoFloat;

/// What the predicate says about one input.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Verdict {
    Valid,
    Invalid,
    /// Within rounding of a threshold: either answer is right.
    Either,
}

use Verdict::*;

impl Verdict {
    pub(crate) fn from_bool(ok: bool) -> Self {
        if ok { Valid } else { Invalid }
    }

    /// The stricter of two verdicts on the same input.
    pub(crate) fn and(self, other: Self) -> Self {
        match (self, other) {
            (Invalid, _) | (_, Invalid) => Invalid,
            (Either, _) | (_, Either) => Either,
            _ => Valid,
        }
    }
}

/// Checks a constructor's result against the verdicts of its inputs, each with the name
/// its error message must use: `Ok` only if no input is invalid; `Err` only if some input
/// is not valid, and then the message names one of those inputs.
pub(crate) fn expect<T: Debug>(
    call: &str,
    result: raytrace::Result<T>,
    inputs: &[(&str, Verdict)],
) -> Result<(), TestCaseError> {
    let named = |which: &[Verdict]| -> Vec<&str> {
        inputs
            .iter()
            .filter(|(_, v)| which.contains(v))
            .map(|(n, _)| *n)
            .collect()
    };
    let invalid = named(&[Invalid]);
    let suspect = named(&[Invalid, Either]);
    match result {
        Ok(v) => prop_assert!(invalid.is_empty(), "{call} accepted invalid {invalid:?}: {v:?}"),
        Err(e) => {
            let msg = e.to_string();
            prop_assert!(!suspect.is_empty(), "{call} rejected valid input: {msg}");
            prop_assert!(
                suspect.iter().any(|name| msg.contains(name)),
                "{call}: the error {msg:?} names none of {suspect:?}"
            );
        }
    }
    Ok(())
}

/// Within a relative `10⁻⁵` (in `log₂`, `1.4·10⁻⁵`) of a threshold.
pub(crate) const BAND: f64 = 2e-5;

pub(crate) fn finite3<F: Float>(v: Vec3<F>) -> bool {
    v.x.is_finite() && v.y.is_finite() && v.z.is_finite()
}

pub(crate) fn positive<F: Float>(x: F) -> Verdict {
    Verdict::from_bool(x.is_finite() && x > F::zero())
}

pub(crate) fn albedo<F: Float>(c: Vec3<F>) -> Verdict {
    let ok = |x: F| x >= F::zero() && x <= F::one();
    Verdict::from_bool(ok(c.x) && ok(c.y) && ok(c.z))
}

pub(crate) fn non_negative<F: Float>(c: Vec3<F>) -> Verdict {
    Verdict::from_bool(finite3(c) && c.x >= F::zero() && c.y >= F::zero() && c.z >= F::zero())
}

/// `v·2^e`, exactly, in two steps so that exponents beyond ±1022 neither overflow nor
/// underflow on the way.
pub(crate) fn times_pow2(v: Vec3<TwoFloat>, e: i32) -> Vec3<TwoFloat> {
    let h = e / 2;
    v * TwoFloat::from(2f64.powi(h)) * TwoFloat::from(2f64.powi(e - h))
}

/// An exact vector `2^k·v̂` (double-double), `v̂`'s largest component in `[1, 2)`, so that
/// lengths, products and cross products of `v̂` cannot overflow or underflow.
pub(crate) type Scaled = (i32, Vec3<TwoFloat>);

/// `v` as [`Scaled`]; `None` for the zero vector.
pub(crate) fn scaled(v: Vec3<TwoFloat>) -> Option<Scaled> {
    let m = v.abs().max_element().hi();
    (m > 0.0).then(|| {
        let k = m.log2().floor() as i32;
        (k, times_pow2(v, -k))
    })
}

pub(crate) fn exact<F: Float>(v: Vec3<F>) -> Vec3<TwoFloat> {
    v.cast()
}

/// `a − b`, computed as `2·(a/2 − b/2)` in double-double (halving first, it cannot
/// overflow; it is exact but for the last bit of subnormal inputs, far below any threshold
/// used here), with the verdict on whether `a − b` rounds to a finite `F` (`Either` within
/// `10⁻⁵` of the largest finite value). `None` when `a = b`.
pub(crate) fn difference<F: Float>(a: Vec3<F>, b: Vec3<F>) -> (Verdict, Option<Scaled>) {
    let half = TwoFloat::from(0.5);
    let d = exact(a) * half - exact(b) * half;
    let half_max = F::max_value().to_f64() / 2.0;
    let m = d.abs().max_element().hi();
    let fits = if m.is_nan() || m > half_max * (1.0 + BAND) {
        Invalid
    } else if m > half_max * (1.0 - BAND) {
        Either
    } else {
        Valid
    };
    (fits, scaled(d).map(|(k, w)| (k + 1, w)))
}

/// The verdict on a finite exact vector used as a direction: valid unless it is zero
/// (tiny and huge vectors normalise after scaling by their largest component).
pub(crate) fn direction(v: Option<&Scaled>) -> Verdict {
    match v {
        None => Invalid,
        Some(_) => Valid,
    }
}

/// `sin θ` between two non-zero exact vectors.
pub(crate) fn sine((_, a): &Scaled, (_, b): &Scaled) -> f64 {
    (a.cross(*b).length() / (a.length() * b.length())).hi()
}

/// The verdict on a triangle (see the module docs).
pub(crate) fn triangle<F: Float>(a: Vec3<F>, b: Vec3<F>, c: Vec3<F>) -> Verdict {
    if !(finite3(a) && finite3(b) && finite3(c)) {
        return Invalid;
    }
    let ((fits_u, u), (fits_v, v)) = (difference(b, a), difference(c, a));
    let edges = fits_u.and(fits_v);
    if edges == Invalid {
        return Invalid;
    }
    let (Some((ku, uh)), Some((kv, vh))) = (u, v) else {
        return Invalid; // two vertices coincide
    };
    let cross = uh.cross(vh).length().hi();
    if cross == 0.0 {
        return Invalid; // exactly collinear
    }
    let eps = F::epsilon().to_f64();
    let sin = cross / (uh.length() * vh.length()).hi();
    let angle = if sin <= 0.25 * eps {
        Invalid
    } else if sin <= 8.0 * eps {
        Either
    } else {
        Valid
    };
    // The library judges the angle on the edges scaled by their largest components, so
    // neither |u×v|² overflowing nor underflowing is a reason to reject.
    let _ = (ku, kv);
    edges.and(angle)
}

pub(crate) fn size_ok(w: usize, h: usize) -> bool {
    w >= 1 && h >= 1 && (w as u128) * (h as u128) <= MAX_PIXELS as u128
}
