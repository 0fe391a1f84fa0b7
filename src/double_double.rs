//! [`DoubleDouble`]: a ~104-bit scalar for reference renders.
//!
//! A thin wrapper of [`twofloat::TwoFloat`] (a value `hi + lo` of two non-overlapping
//! `f64`s) that fixes its division. `twofloat` 0.8.4 divides by Joldes, Muller & Popescu's
//! algorithm 18 but computes the residual `1 − y_hi·t_hi` with a rounded product instead
//! of a fused multiply-add; the residual then rounds to 0 and the quotient, and everything
//! built on it (`recip`, normalisation, the sphere's roots), is only `f64`-accurate:
//! `TwoFloat(1)/TwoFloat(3)` has a zero low word. Here division is algorithm 17 of the
//! same paper (`DWDivDW2`, relative error below `15u²`), written with `twofloat`'s exact
//! products; every other operation is `twofloat`'s own.

use num_traits::{Num, One, ToPrimitive, Zero};
use std::cmp::Ordering;
use std::fmt;
use std::num::FpCategory;
use std::ops::{Add, Div, Mul, Neg, Rem, Sub};
use twofloat::TwoFloat;

/// A double-double scalar (about 104 significant bits) with correctly working division and
/// comparisons.
#[derive(Clone, Copy, Debug, Default)]
pub struct DoubleDouble(pub TwoFloat);

impl DoubleDouble {
    /// The value rounded to `f64`.
    pub fn hi(self) -> f64 {
        self.0.hi()
    }

    /// The low word: `self = hi + lo` exactly.
    pub fn lo(self) -> f64 {
        self.0.lo()
    }

    /// `x / y` by `DWDivDW2` (Joldes et al. 2017, algorithm 17):
    /// `t = x_hi/y_hi`, `r = y·t` (exact double-double product), `δ = x − r`,
    /// `x/y ≈ t + δ_hi/y_hi`.
    fn divide(x: TwoFloat, y: TwoFloat) -> TwoFloat {
        let th = x.hi() / y.hi();
        if !th.is_finite() || th == 0.0 {
            return TwoFloat::from(th);
        }
        let delta = x - y * th;
        TwoFloat::new_add(th, delta.hi() / y.hi())
    }
}

impl From<f64> for DoubleDouble {
    fn from(x: f64) -> Self {
        Self(TwoFloat::from(x))
    }
}

/// Ordered as the real numbers they stand for: the high words first, as `f64`s (so `−∞` is
/// below every finite value), then, between equal finite high words, the low words.
/// `twofloat` 0.8.4 orders every infinity after every finite value, `−∞` too, and calls
/// `+∞` and `−∞` equal; a box's empty side (`−∞`) then grew to no box at all.
impl PartialOrd for DoubleDouble {
    fn partial_cmp(&self, o: &Self) -> Option<Ordering> {
        if self.lo().is_nan() || o.lo().is_nan() {
            return None;
        }
        match self.hi().partial_cmp(&o.hi())? {
            Ordering::Equal if self.hi().is_finite() => self.lo().partial_cmp(&o.lo()),
            order => Some(order),
        }
    }
}

impl PartialEq for DoubleDouble {
    fn eq(&self, o: &Self) -> bool {
        self.partial_cmp(o) == Some(Ordering::Equal)
    }
}

impl fmt::Display for DoubleDouble {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(&self.0, f)
    }
}

macro_rules! binary_ops {
    ($($trait:ident $method:ident),*) => {$(
        impl $trait for DoubleDouble {
            type Output = Self;
            #[inline]
            fn $method(self, o: Self) -> Self {
                Self(self.0.$method(o.0))
            }
        }
    )*};
}
binary_ops!(Add add, Sub sub, Mul mul, Rem rem);

impl Div for DoubleDouble {
    type Output = Self;
    #[inline]
    fn div(self, o: Self) -> Self {
        Self(Self::divide(self.0, o.0))
    }
}

impl Neg for DoubleDouble {
    type Output = Self;
    #[inline]
    fn neg(self) -> Self {
        Self(-self.0)
    }
}

impl Zero for DoubleDouble {
    fn zero() -> Self {
        Self(TwoFloat::from(0.0))
    }
    fn is_zero(&self) -> bool {
        self.0 == TwoFloat::from(0.0)
    }
}

impl One for DoubleDouble {
    fn one() -> Self {
        Self(TwoFloat::from(1.0))
    }
}

impl Num for DoubleDouble {
    type FromStrRadixErr = <TwoFloat as Num>::FromStrRadixErr;
    fn from_str_radix(s: &str, radix: u32) -> Result<Self, Self::FromStrRadixErr> {
        TwoFloat::from_str_radix(s, radix).map(Self)
    }
}

impl ToPrimitive for DoubleDouble {
    fn to_i64(&self) -> Option<i64> {
        self.0.to_i64()
    }
    fn to_u64(&self) -> Option<u64> {
        self.0.to_u64()
    }
    fn to_f64(&self) -> Option<f64> {
        Some(self.0.hi() + self.0.lo())
    }
}

impl num_traits::NumCast for DoubleDouble {
    fn from<T: ToPrimitive>(n: T) -> Option<Self> {
        <TwoFloat as num_traits::NumCast>::from(n).map(Self)
    }
}

/// Forwards methods to `TwoFloat`'s `num_traits::Float` implementation.
macro_rules! forward {
    (unary: $($m:ident),*) => {$(
        #[inline]
        fn $m(self) -> Self { Self(num_traits::Float::$m(self.0)) }
    )*};
    (predicate: $($m:ident),*) => {$(
        #[inline]
        fn $m(self) -> bool { num_traits::Float::$m(self.0) }
    )*};
    (constant: $($m:ident),*) => {$(
        #[inline]
        fn $m() -> Self { Self(<TwoFloat as num_traits::Float>::$m()) }
    )*};
    (binary: $($m:ident),*) => {$(
        #[inline]
        fn $m(self, o: Self) -> Self { Self(num_traits::Float::$m(self.0, o.0)) }
    )*};
}

impl num_traits::Float for DoubleDouble {
    forward!(constant: nan, infinity, neg_infinity, neg_zero, min_value, min_positive_value, max_value);
    forward!(predicate: is_nan, is_infinite, is_finite, is_normal, is_sign_positive, is_sign_negative);
    forward!(unary: floor, ceil, round, trunc, fract, abs, signum, sqrt, exp, exp2, ln, log2, log10, cbrt,
        sin, cos, tan, asin, acos, atan, exp_m1, ln_1p, sinh, cosh, tanh, asinh, acosh, atanh);
    forward!(binary: powf, log, max, min, abs_sub, hypot, atan2);

    /// `2⁻¹⁰⁰`, not `twofloat`'s `EPSILON` (which is `f64::MIN_POSITIVE`).
    fn epsilon() -> Self {
        Self::from(2f64.powi(-100))
    }
    fn classify(self) -> FpCategory {
        num_traits::Float::classify(self.0)
    }
    fn mul_add(self, a: Self, b: Self) -> Self {
        self * a + b
    }
    fn recip(self) -> Self {
        Self::one() / self
    }
    fn powi(self, n: i32) -> Self {
        let mut acc = Self::one();
        for _ in 0..n.unsigned_abs() {
            acc = acc * self;
        }
        if n < 0 { acc.recip() } else { acc }
    }
    fn sin_cos(self) -> (Self, Self) {
        (num_traits::Float::sin(self), num_traits::Float::cos(self))
    }
    fn integer_decode(self) -> (u64, i16, i8) {
        num_traits::Float::integer_decode(self.0)
    }
    fn to_degrees(self) -> Self {
        self * (Self::from(180.0) / Self(twofloat::consts::PI))
    }
    fn to_radians(self) -> Self {
        self * (Self(twofloat::consts::PI) / Self::from(180.0))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{RngExt, SeedableRng};

    fn dd(x: f64) -> DoubleDouble {
        DoubleDouble::from(x)
    }

    #[test]
    fn division_keeps_the_low_word() {
        let third = dd(1.0) / dd(3.0);
        assert_ne!(third.lo(), 0.0, "1/3 needs a low word");
        let err = third * dd(3.0) - dd(1.0);
        assert!(num_traits::Float::abs(err).hi() < 1e-31, "{err:?}");
        // twofloat's own division loses it: the reason this type exists.
        assert_eq!((TwoFloat::from(1.0) / TwoFloat::from(3.0)).lo(), 0.0);
    }

    #[test]
    fn division_is_accurate_to_about_2_pow_minus_100() {
        let mut rng = rand::rngs::Xoshiro256PlusPlus::seed_from_u64(9);
        for _ in 0..10_000 {
            let x = dd(rng.random_range(-1e6..1e6)) + dd(rng.random_range(-1e-12..1e-12));
            let y = dd(rng.random_range(1e-3..1e3)) + dd(rng.random_range(-1e-20..1e-20));
            let q = x / y;
            let residual = (q * y - x) / x;
            assert!(
                num_traits::Float::abs(residual).hi() < 2f64.powi(-98),
                "{x} / {y}: {residual:?}"
            );
        }
    }

    /// Infinities order as they do in `f64`: `−∞ < x < +∞` for every finite `x`, and
    /// `+∞ ≠ −∞` (which `twofloat` gets wrong).
    #[test]
    fn comparisons_with_infinities() {
        use num_traits::Float;
        let (inf, ninf, x) = (DoubleDouble::infinity(), DoubleDouble::neg_infinity(), dd(3.0));
        assert!(ninf < x && x < inf && ninf < inf);
        assert!(x >= ninf && inf >= x);
        assert_ne!(inf, ninf);
        assert_eq!(inf, inf);
        assert!(dd(1.0) + dd(1e-20) > dd(1.0), "the low words break ties");
        assert_eq!(DoubleDouble::nan().partial_cmp(&x), None);
        // `twofloat`'s own order, which this type replaces.
        assert!(TwoFloat::NEG_INFINITY > TwoFloat::from(3.0));
    }

    #[test]
    fn special_values() {
        use num_traits::Float;
        assert!((dd(1.0) / dd(0.0)).is_infinite());
        assert!((dd(0.0) / dd(0.0)).is_nan());
        assert_eq!(dd(0.0) / dd(5.0), dd(0.0));
        assert_eq!(dd(2.0).powi(-2), dd(0.25));
        let pi = DoubleDouble(twofloat::consts::PI);
        assert!((dd(180.0).to_radians() - pi).abs().hi() < 1e-30);
    }
}
