//! The scalar every geometric type and the renderer are generic over.
//!
//! [`Float`] is [`num_traits::Float`] plus the few things a ray tracer needs that
//! `num-traits` lacks: a way to write constants once ([`lit`]), the neighbouring
//! representable values ([`Float::next_up`], [`Float::next_down`]) for error-bounded
//! ray offsets, and pbrt's `γ(n)` rounding-error bound. It is implemented for
//! `f32`, `f64` and [`twofloat::TwoFloat`] (double-double, about 106 bits), so the
//! same renderer produces fast previews and reference images.

use std::fmt::{Debug, Display};
use std::ops::{Index, IndexMut};

/// A floating-point scalar the renderer can run on.
///
/// Implemented for `f32`, `f64` and [`twofloat::TwoFloat`].
pub trait Float: num_traits::Float + Debug + Display + Default + Send + Sync + 'static {
    /// A short name for reports: `"f32"`, `"f64"`, `"dd"`.
    const NAME: &'static str;

    /// The lanes of a wide BVH node, one per child: `[T; 8]` for `f32` (eight boxes' faces
    /// fill a 256-bit register), `[T; 4]` for the wider scalars. Measured against four
    /// lanes, eight traced 10⁵ spheres 1.1× as fast in both precisions, but took 1.05–1.09×
    /// the time on the spec's `random_spheres` in `f64` (`docs/PERFORMANCE.md`).
    type Node<T: Copy + Debug + Send + Sync>: Lanes<T>;

    /// Converts an `f64` literal or random draw to this scalar, rounding to nearest.
    ///
    /// Every constant in the crate is written through this one function (or [`lit`]),
    /// so no `F::from(..).unwrap()` is scattered through the code.
    fn from_f64(x: f64) -> Self;

    /// This value rounded to the nearest `f64` (exact for `f32` and `f64`).
    fn to_f64(self) -> f64;

    /// The machine epsilon: the gap between 1 and the next representable value, `2u` for
    /// the unit roundoff `u` of the arithmetic. Use this, not `num_traits::Float::epsilon`,
    /// which `twofloat` defines as the smallest positive `f64` (so every error bound
    /// derived from it would be zero).
    fn eps() -> Self;

    /// The smallest representable value greater than `self` (identity for NaN and +∞).
    fn next_up(self) -> Self;

    /// The largest representable value less than `self` (identity for NaN and −∞).
    fn next_down(self) -> Self;

    /// For finite `self`, the neighbouring representable value in the direction of `s`'s
    /// sign: [`next_up`](Float::next_up) for `s > 0`, [`next_down`](Float::next_down) for
    /// `s < 0`, `self` for `s = 0` or NaN. A non-finite `self` is returned as it is.
    // The step helpers are trait methods, hidden, so f32 and f64 can replace them with
    // their branch-free lanes; only `Hit::offset_origin` needs them.
    #[doc(hidden)]
    #[inline]
    fn step_toward(self, s: Self) -> Self {
        if !self.is_finite() {
            self
        } else if s > Self::zero() {
            self.next_up()
        } else if s < Self::zero() {
            self.next_down()
        } else {
            self
        }
    }

    /// [`step_toward`](Float::step_toward) on each of three components: `p[k]` stepped
    /// toward `s[k]`'s sign.
    #[doc(hidden)]
    #[inline]
    fn step_toward_each(p: [Self; 3], s: [Self; 3]) -> [Self; 3] {
        [
            p[0].step_toward(s[0]),
            p[1].step_toward(s[1]),
            p[2].step_toward(s[2]),
        ]
    }

    /// pbrt's bound on the relative error of `n` successive roundings:
    /// `γ(n) = n·u / (1 − n·u)` with the unit roundoff `u = ε/2`.
    ///
    /// # Precision
    /// For `n·u < 1` the product of `n` factors `(1 ± u)` lies within `1 ± γ(n)`
    /// (Higham, *Accuracy and Stability of Numerical Algorithms*, lemma 3.1).
    #[inline]
    fn gamma(n: u32) -> Self {
        let nu = Self::from_f64(f64::from(n)) * Self::eps() * Self::from_f64(0.5);
        nu / (Self::one() - nu)
    }
}

/// Writes a constant in any [`Float`]: `lit::<F>(0.5)`.
#[inline]
pub fn lit<F: Float>(x: f64) -> F {
    F::from_f64(x)
}

/// `x` in scalar `G`, rounded through `f64`: how every `cast` changes a value's scalar.
#[inline]
pub(crate) fn to<F: Float, G: Float>(x: F) -> G {
    G::from_f64(x.to_f64())
}

/// [`Float::step_toward_each`] for `$float`, on its bits as signed integers of its width
/// `$int` (`i32` for `f32`, `i64` for `f64`), in four lanes (the fourth idle), with
/// bitwise selects and no branch.
///
/// In sign-magnitude bits, a step towards `s` grows the magnitude (adds 1 to the bits)
/// when the value and `s` have the same sign and shrinks it (subtracts 1) when not; from
/// ±0 it goes to the smallest value of `s`'s sign. The step is taken where the value is
/// finite (magnitude bits below those of ∞) and `s` is neither zero nor NaN (magnitude
/// bits nonzero and at most those of ∞); elsewhere the value stays.
///
/// Each operation is one expression over the four lanes, as in [`crate::lanes`], so the
/// compiler makes each one SIMD instruction: written as one expression per lane, it
/// compiled to three scalar copies with a branch each. (No multiplication: a 32- or
/// 64-bit integer product has no SSE2 instruction.)
macro_rules! step_lanes {
    ($float:ty, $int:ty, $p:expr, $s:expr) => {{
        #[inline(always)]
        fn lanes(f: impl Fn(usize) -> $int) -> [$int; 4] {
            [f(0), f(1), f(2), f(3)]
        }
        let (p, s): ([$float; 3], [$float; 3]) = ($p, $s);
        let b = lanes(|k| if k < 3 { p[k].to_bits() as $int } else { 0 });
        let sb = lanes(|k| if k < 3 { s[k].to_bits() as $int } else { 0 });
        let inf = <$float>::INFINITY.to_bits() as $int;
        let mask = |c: bool| -<$int>::from(c);
        let mag = lanes(|k| b[k] & <$int>::MAX);
        let smag = lanes(|k| sb[k] & <$int>::MAX);
        let stepped = lanes(|k| b[k].wrapping_add(((b[k] ^ sb[k]) >> (<$int>::BITS - 1)) | 1));
        let from_zero = lanes(|k| (sb[k] & <$int>::MIN) | 1);
        let at_zero = lanes(|k| mask(mag[k] == 0));
        let moved = lanes(|k| (from_zero[k] & at_zero[k]) | (stepped[k] & !at_zero[k]));
        let go = lanes(|k| mask((mag[k] < inf) & (smag[k] != 0) & (smag[k] <= inf)));
        let r = lanes(|k| (moved[k] & go[k]) | (b[k] & !go[k]));
        [r[0], r[1], r[2]].map(|r| <$float>::from_bits(r as _))
    }};
}

impl Float for f32 {
    const NAME: &'static str = "f32";
    type Node<T: Copy + Debug + Send + Sync> = [T; 8];
    #[inline]
    fn from_f64(x: f64) -> Self {
        x as f32
    }
    #[inline]
    fn to_f64(self) -> f64 {
        f64::from(self)
    }
    #[inline]
    fn eps() -> Self {
        f32::EPSILON
    }
    #[inline]
    fn next_up(self) -> Self {
        f32::next_up(self)
    }
    #[inline]
    fn next_down(self) -> Self {
        f32::next_down(self)
    }
    /// Branch-free: the signs of hit points and offsets are random, so branches would
    /// mispredict (see `step_lanes!`).
    #[inline]
    fn step_toward(self, s: Self) -> Self {
        Self::step_toward_each([self; 3], [s; 3])[0]
    }
    /// The three steps as lanes of one vector, one sequence of SIMD integer operations
    /// (`step_lanes!`; this runs once per spawned ray).
    #[inline]
    fn step_toward_each(p: [Self; 3], s: [Self; 3]) -> [Self; 3] {
        step_lanes!(f32, i32, p, s)
    }
}

impl Float for f64 {
    const NAME: &'static str = "f64";
    type Node<T: Copy + Debug + Send + Sync> = [T; 4];
    #[inline]
    fn from_f64(x: f64) -> Self {
        x
    }
    #[inline]
    fn to_f64(self) -> f64 {
        self
    }
    #[inline]
    fn eps() -> Self {
        f64::EPSILON
    }
    #[inline]
    fn next_up(self) -> Self {
        f64::next_up(self)
    }
    #[inline]
    fn next_down(self) -> Self {
        f64::next_down(self)
    }
    /// Branch-free, as for `f32`.
    #[inline]
    fn step_toward(self, s: Self) -> Self {
        Self::step_toward_each([self; 3], [s; 3])[0]
    }
    /// As for `f32`, in 64-bit lanes.
    #[inline]
    fn step_toward_each(p: [Self; 3], s: [Self; 3]) -> [Self; 3] {
        step_lanes!(f64, i64, p, s)
    }
}

/// `twofloat`'s type compiles and renders, but its division is only `f64`-accurate (see
/// [`DoubleDouble`](crate::double_double::DoubleDouble), which fixes it): use
/// `DoubleDouble` for reference renders.
impl Float for twofloat::TwoFloat {
    const NAME: &'static str = "twofloat";
    type Node<T: Copy + Debug + Send + Sync> = [T; 4];
    #[inline]
    fn from_f64(x: f64) -> Self {
        twofloat::TwoFloat::from(x)
    }
    #[inline]
    fn to_f64(self) -> f64 {
        self.hi() + self.lo()
    }
    /// `2⁻¹⁰⁰`: double-double addition and multiplication are accurate to about `2⁻¹⁰⁴`
    /// relative, division and square root to a few bits less (Joldes, Muller, Popescu
    /// 2017), so `2⁻¹⁰⁰` keeps the error bounds built on it conservative.
    #[inline]
    fn eps() -> Self {
        Self::from_f64(2f64.powi(-100))
    }
    /// Steps by one unit in the last place of the double-double (`|x|·ε`, at
    /// least the smallest positive `f64`); enough for ray offsets, which only
    /// need a value strictly on the far side.
    fn next_up(self) -> Self {
        let step = (self.abs() * Self::eps()).max(Self::from_f64(f64::from_bits(1)));
        self + step
    }
    fn next_down(self) -> Self {
        let step = (self.abs() * Self::eps()).max(Self::from_f64(f64::from_bits(1)));
        self - step
    }
}

impl Float for crate::double_double::DoubleDouble {
    const NAME: &'static str = "dd";
    type Node<T: Copy + Debug + Send + Sync> = [T; 4];
    #[inline]
    fn from_f64(x: f64) -> Self {
        Self::from(x)
    }
    #[inline]
    fn to_f64(self) -> f64 {
        self.hi() + self.lo()
    }
    /// `2⁻¹⁰⁰`: double-double addition and multiplication are accurate to about `2⁻¹⁰⁴`
    /// relative, division to `15u²` (Joldes, Muller, Popescu 2017), square root a little
    /// worse, so `2⁻¹⁰⁰` keeps the error bounds built on it conservative.
    #[inline]
    fn eps() -> Self {
        Self::from(2f64.powi(-100))
    }
    fn next_up(self) -> Self {
        let step = num_traits::Float::max(
            num_traits::Float::abs(self) * Self::eps(),
            Self::from(f64::from_bits(1)),
        );
        self + step
    }
    fn next_down(self) -> Self {
        let step = num_traits::Float::max(
            num_traits::Float::abs(self) * Self::eps(),
            Self::from(f64::from_bits(1)),
        );
        self - step
    }
}

/// Test helper: each named generic test function `fn name<F: Float>()` becomes a
/// `#[test]` running it for `f32` and for `f64`.
#[cfg(test)]
macro_rules! for_each_scalar {
    ($($name:ident),* $(,)?) => {$(
        #[test]
        fn $name() {
            super::$name::<f32>();
            super::$name::<f64>();
        }
    )*};
}
#[cfg(test)]
pub(crate) use for_each_scalar;

/// Values side by side in a plain array, `[T; N]`: one per child of a wide BVH node, as
/// many as the scalar picks ([`Float::Node`]).
pub trait Lanes<T>:
    Copy + Debug + Send + Sync + Index<usize, Output = T> + IndexMut<usize> + AsRef<[T]> + AsMut<[T]>
{
    /// How many.
    const N: usize;
    /// Lane `k` set to `f(k)`.
    fn from_fn(f: impl FnMut(usize) -> T) -> Self;
}

impl<T: Copy + Debug + Send + Sync, const N: usize> Lanes<T> for [T; N] {
    const N: usize = N;
    #[inline(always)]
    fn from_fn(f: impl FnMut(usize) -> T) -> Self {
        std::array::from_fn(f)
    }
}

#[cfg(test)]
mod tests;
