//! `F4<F>`: four scalars side by side, for testing one ray against four objects at once.
//!
//! Every operation is written lane by lane on a plain array; each is one short
//! expression per lane, which the compiler reliably turns into a single SIMD instruction
//! (for `f32` one SSE register, for `f64` two) on any target, with no `unsafe` and no
//! dependency. Each lane rounds exactly as the same scalar expression does, so code on
//! `F4` gives bit for bit the scalar code's answers. (Writing a whole intersection as one
//! loop over the lanes instead left the vectorisation to chance: measured, it sometimes
//! came out scalar.)

use crate::float::Float;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// Lanes in an [`F4`].
pub const LANES: usize = 4;

/// Four scalars; arithmetic acts on each lane alone.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct F4<F>(pub [F; LANES]);

impl<F: Float> F4<F> {
    /// `f` applied to each lane.
    #[inline(always)]
    fn map(self, f: impl Fn(F) -> F) -> Self {
        let [a, b, c, d] = self.0;
        Self([f(a), f(b), f(c), f(d)])
    }

    /// `f` applied to each pair of lanes.
    #[inline(always)]
    fn zip(self, o: Self, f: impl Fn(F, F) -> F) -> Self {
        let ([a, b, c, d], [e, g, h, i]) = (self.0, o.0);
        Self([f(a, e), f(b, g), f(c, h), f(d, i)])
    }

    /// All four lanes `v`.
    #[inline(always)]
    pub fn splat(v: F) -> Self {
        Self([v; LANES])
    }

    /// `|x|` per lane.
    #[inline(always)]
    pub fn abs(self) -> Self {
        self.map(F::abs)
    }

    /// The larger of each pair of lanes by one comparison: `o` where `self < o`, else
    /// `self`, so a NaN in either gives `self`. (`Float::max`, which drops the NaN, compiles
    /// to a compare and two blends a lane pair: 1.65 % of the Cornell box's instructions.)
    #[inline(always)]
    pub fn max(self, o: Self) -> Self {
        Self::select_lt(self, o, o, self)
    }

    /// The smaller of each pair of lanes; where one is NaN, the other (as `f32::min`),
    /// by comparisons alone, so infinities count for every [`Float`].
    #[inline(always)]
    pub fn least(self, o: Self) -> Self {
        self.zip(o, |a, b| if b < a || a.is_nan() { b } else { a })
    }

    /// The larger of each pair of lanes; where one is NaN, the other, as [`F4::least`].
    #[inline(always)]
    pub fn greatest(self, o: Self) -> Self {
        self.zip(o, |a, b| if b > a || a.is_nan() { b } else { a })
    }

    /// Per lane: `x` where bit `k` of `mask` is set, else `y`.
    #[inline(always)]
    pub fn select(mask: u32, x: Self, y: Self) -> Self {
        let sel = |k: usize| if mask & (1 << k) != 0 { x.0[k] } else { y.0[k] };
        Self([sel(0), sel(1), sel(2), sel(3)])
    }

    /// `√x` per lane (NaN for a negative lane).
    #[inline(always)]
    pub fn sqrt(self) -> Self {
        self.map(F::sqrt)
    }

    /// Per lane: `if a < b { x } else { y }` (false for NaN, like the scalar `<`).
    #[inline(always)]
    pub fn select_lt(a: Self, b: Self, x: Self, y: Self) -> Self {
        let sel = |k: usize| if a.0[k] < b.0[k] { x.0[k] } else { y.0[k] };
        Self([sel(0), sel(1), sel(2), sel(3)])
    }

    /// Per lane: `if a == b { x } else { y }`.
    #[inline(always)]
    pub fn select_eq(a: Self, b: Self, x: Self, y: Self) -> Self {
        let sel = |k: usize| if a.0[k] == b.0[k] { x.0[k] } else { y.0[k] };
        Self([sel(0), sel(1), sel(2), sel(3)])
    }

    /// The smallest lane (for lanes that are not NaN).
    #[inline(always)]
    pub fn min_lane(self) -> F {
        let [a, b, c, d] = self.0;
        let ab = if b < a { b } else { a };
        let cd = if d < c { d } else { c };
        if cd < ab { cd } else { ab }
    }

    /// Whether `test(k)` holds in all four lanes. Written as one `&` of the four lane
    /// tests, which the compiler turns into one vector comparison and one test of its
    /// mask on any target. (A bit mask compared with `0b1111` does too with SSE, but with
    /// AVX-512 LLVM pulls the mask's bits out one by one.)
    #[inline(always)]
    pub fn all(test: impl Fn(usize) -> bool) -> bool {
        test(0) & test(1) & test(2) & test(3)
    }

    /// Whether some lane is `< bound` (see [`F4::all`] for the form).
    #[inline(always)]
    pub fn any_lt(self, bound: F) -> bool {
        let [a, b, c, d] = self.0;
        (a < bound) | (b < bound) | (c < bound) | (d < bound)
    }

    /// Bit `k` set where lane `k` is `== v`.
    #[inline(always)]
    pub fn mask_eq(self, v: F) -> u32 {
        let [a, b, c, d] = self.0.map(|x| u32::from(x == v));
        a | (b << 1) | (c << 2) | (d << 3)
    }

    /// Bit `k` set where lane `k` of `a` is `<` lane `k` of `b` (never for NaN).
    #[inline(always)]
    pub fn mask_lt(a: Self, b: Self) -> u32 {
        let m = |k: usize| u32::from(a.0[k] < b.0[k]) << k;
        m(0) | m(1) | m(2) | m(3)
    }

    /// Bit `k` set where lane `k` of `a` is `<= ` lane `k` of `b`.
    #[inline(always)]
    pub fn mask_le(a: Self, b: Self) -> u32 {
        let m = |k: usize| u32::from(a.0[k] <= b.0[k]) << k;
        m(0) | m(1) | m(2) | m(3)
    }
}

impl<F: Float> Add for F4<F> {
    type Output = Self;
    #[inline(always)]
    fn add(self, o: Self) -> Self {
        self.zip(o, |a, b| a + b)
    }
}

impl<F: Float> Sub for F4<F> {
    type Output = Self;
    #[inline(always)]
    fn sub(self, o: Self) -> Self {
        self.zip(o, |a, b| a - b)
    }
}

impl<F: Float> Mul for F4<F> {
    type Output = Self;
    #[inline(always)]
    fn mul(self, o: Self) -> Self {
        self.zip(o, |a, b| a * b)
    }
}

impl<F: Float> Div for F4<F> {
    type Output = Self;
    #[inline(always)]
    fn div(self, o: Self) -> Self {
        self.zip(o, |a, b| a / b)
    }
}

impl<F: Float> Neg for F4<F> {
    type Output = Self;
    #[inline(always)]
    fn neg(self) -> Self {
        self.map(|a| -a)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lanes_act_alone() {
        let a = F4([1.0f32, -2.0, 4.0, f32::NAN]);
        let b = F4::splat(2.0f32);
        assert_eq!((a + b).0[..3], [3.0, 0.0, 6.0]);
        assert_eq!((a * b).0[..3], [2.0, -4.0, 8.0]);
        assert_eq!((a / b).0[..3], [0.5, -1.0, 2.0]);
        assert_eq!((-a).0[..3], [-1.0, 2.0, -4.0]);
        let s = F4::select_lt(a, b, F4::splat(1.0), F4::splat(0.0));
        assert_eq!(s.0, [1.0, 1.0, 0.0, 0.0], "NaN < 2 is false");
        assert!(a.any_lt(-1.0) && !a.any_lt(-2.0), "NaN < x is false");
        assert!(F4::<f32>::all(|k| a.0[k] < 5.0 || a.0[k].is_nan()));
        assert!(!F4::<f32>::all(|k| a.0[k] < 4.0));
        assert_eq!(F4([1.0f32, 3.0, 2.0, 3.0]).mask_eq(3.0), 0b1010);
        assert_eq!(F4::mask_le(a, b), 0b0011, "NaN <= x is false");
        assert_eq!(F4::mask_lt(a, b), 0b0011, "NaN < x is false");
        assert_eq!(F4::select(0b0101, a, b).0[..3], [1.0, 2.0, 4.0]);
        assert_eq!(a.min_lane(), -2.0);
        assert_eq!(F4([5.0f64, 3.0, 4.0, 3.0]).min_lane(), 3.0);
        assert!(F4([-1.0f64, 4.0, 0.0, 9.0]).sqrt().0[0].is_nan());
        let (inf, nan) = (f64::INFINITY, f64::NAN);
        let p = F4([nan, 1.0, -inf, nan]);
        let q = F4([2.0, nan, 3.0, nan]);
        assert_eq!(p.least(q).0[..3], [2.0, 1.0, -inf], "a NaN gives the other");
        assert_eq!(q.least(p).0[..3], [2.0, 1.0, -inf]);
        assert_eq!(p.greatest(q).0[..3], [2.0, 1.0, 3.0]);
        assert_eq!(F4([inf; 4]).greatest(q).0[..3], [inf; 3]);
        assert!(p.least(q).0[3].is_nan() && p.greatest(q).0[3].is_nan());
    }
}
