//! `Vec3<F>`: points, directions and linear RGB colours.

use crate::float::{Float, lit, to};
use std::ops::{Add, Div, Index, Mul, Neg, Sub};

/// A 3-vector of scalars `F`: a point, a direction, or a linear RGB colour.
///
/// `a * b` between two vectors is the element-wise (Hadamard) product, used for
/// absorption `C⁺ = A ∘ C⁻`; [`Vec3::dot`] and [`Vec3::cross`] are the other products.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Vec3<F> {
    /// First component (x, or red).
    pub x: F,
    /// Second component (y, or green).
    pub y: F,
    /// Third component (z, or blue).
    pub z: F,
}

/// A linear RGB colour; each channel is a non-negative radiance, `[0, 1]` for albedos.
pub type Color<F> = Vec3<F>;

impl<F: Float> Vec3<F> {
    /// A vector from its three components.
    #[inline]
    pub const fn new(x: F, y: F, z: F) -> Self {
        Self { x, y, z }
    }

    /// A vector from `f64` components, rounded to `F`.
    #[inline]
    pub fn from_f64(x: f64, y: f64, z: f64) -> Self {
        Self::new(lit(x), lit(y), lit(z))
    }

    /// The components as `f64` (rounded for wider scalars).
    #[inline]
    pub fn to_f64(self) -> [f64; 3] {
        [self.x.to_f64(), self.y.to_f64(), self.z.to_f64()]
    }

    /// `(0, 0, 0)`.
    #[inline]
    pub fn zero() -> Self {
        Self::splat(F::zero())
    }

    /// `(v, v, v)`.
    #[inline]
    pub fn splat(v: F) -> Self {
        Self::new(v, v, v)
    }

    /// `a·b = aₓbₓ + a_yb_y + a_zb_z`.
    #[inline]
    pub fn dot(self, o: Self) -> F {
        self.x * o.x + self.y * o.y + self.z * o.z
    }

    /// `a×b`, right-handed.
    #[must_use]
    #[inline]
    pub fn cross(self, o: Self) -> Self {
        Self::new(
            self.y * o.z - self.z * o.y,
            self.z * o.x - self.x * o.z,
            self.x * o.y - self.y * o.x,
        )
    }

    /// `|v|²`.
    #[inline]
    pub fn length_squared(self) -> F {
        self.dot(self)
    }

    /// `|v|`.
    #[inline]
    pub fn length(self) -> F {
        self.length_squared().sqrt()
    }

    /// `v / |v|`.
    ///
    /// # Panics
    /// In debug builds, if `v` is zero or not finite; use [`Vec3::try_normalize`]
    /// where that can happen.
    #[must_use]
    #[inline]
    pub fn normalize(self) -> Self {
        let len = self.length();
        debug_assert!(len > F::zero() && len.is_finite(), "normalize of {self:?}");
        self / len
    }

    /// `v / |v|`, or `None` when `v` is zero or not finite.
    ///
    /// Vectors whose `|v|²` overflows or underflows are first divided by their largest
    /// component, so every finite non-zero vector normalises.
    #[must_use]
    #[inline]
    pub fn try_normalize(self) -> Option<Self> {
        let len2 = self.length_squared();
        if len2 >= F::min_positive_value() && len2.is_finite() {
            return Some(self / len2.sqrt());
        }
        let m = self.abs().max_element();
        if !(m > F::zero() && m.is_finite() && self.is_finite()) {
            return None;
        }
        let scaled = self / m;
        Some(scaled / scaled.length())
    }

    /// Component-wise absolute value.
    #[must_use]
    #[inline]
    pub fn abs(self) -> Self {
        Self::new(self.x.abs(), self.y.abs(), self.z.abs())
    }

    /// Component-wise minimum.
    #[must_use]
    #[inline]
    pub fn min(self, o: Self) -> Self {
        Self::new(self.x.min(o.x), self.y.min(o.y), self.z.min(o.z))
    }

    /// Component-wise maximum.
    #[must_use]
    #[inline]
    pub fn max(self, o: Self) -> Self {
        Self::new(self.x.max(o.x), self.y.max(o.y), self.z.max(o.z))
    }

    /// The largest component.
    #[inline]
    pub fn max_element(self) -> F {
        self.x.max(self.y).max(self.z)
    }

    /// The smallest component.
    #[inline]
    pub fn min_element(self) -> F {
        self.x.min(self.y).min(self.z)
    }

    /// Whether every component is finite (not NaN, not ±∞).
    #[inline]
    pub fn is_finite(self) -> bool {
        self.x.is_finite() && self.y.is_finite() && self.z.is_finite()
    }

    /// Applies `f` to each component.
    #[must_use]
    #[inline]
    pub fn map(self, f: impl Fn(F) -> F) -> Self {
        Self::new(f(self.x), f(self.y), f(self.z))
    }

    /// Converts each component to another scalar through `f64`.
    #[must_use]
    #[inline]
    pub fn cast<G: Float>(self) -> Vec3<G> {
        Vec3::new(to(self.x), to(self.y), to(self.z))
    }
}

impl<F: Float> Add for Vec3<F> {
    type Output = Self;
    #[inline]
    fn add(self, o: Self) -> Self {
        Self::new(self.x + o.x, self.y + o.y, self.z + o.z)
    }
}

impl<F: Float> Sub for Vec3<F> {
    type Output = Self;
    #[inline]
    fn sub(self, o: Self) -> Self {
        Self::new(self.x - o.x, self.y - o.y, self.z - o.z)
    }
}

impl<F: Float> Neg for Vec3<F> {
    type Output = Self;
    #[inline]
    fn neg(self) -> Self {
        Self::new(-self.x, -self.y, -self.z)
    }
}

/// Scalar product `v·s`.
impl<F: Float> Mul<F> for Vec3<F> {
    type Output = Self;
    #[inline]
    fn mul(self, s: F) -> Self {
        Self::new(self.x * s, self.y * s, self.z * s)
    }
}

/// Element-wise product `a ∘ b` (absorption of colour by albedo).
impl<F: Float> Mul for Vec3<F> {
    type Output = Self;
    #[inline]
    fn mul(self, o: Self) -> Self {
        Self::new(self.x * o.x, self.y * o.y, self.z * o.z)
    }
}

/// Scalar quotient `v/s`.
impl<F: Float> Div<F> for Vec3<F> {
    type Output = Self;
    #[inline]
    fn div(self, s: F) -> Self {
        Self::new(self.x / s, self.y / s, self.z / s)
    }
}

impl<F> Index<usize> for Vec3<F> {
    type Output = F;
    /// # Panics
    /// If `i > 2`.
    #[inline]
    fn index(&self, i: usize) -> &F {
        match i {
            0 => &self.x,
            1 => &self.y,
            2 => &self.z,
            _ => panic!("Vec3 index {i} out of range 0..3"),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    type V = Vec3<f64>;

    #[test]
    fn arithmetic() {
        let a = V::new(1.0, 2.0, 3.0);
        let b = V::new(-4.0, 0.5, 2.0);
        assert_eq!(a + b, V::new(-3.0, 2.5, 5.0));
        assert_eq!(a - b, V::new(5.0, 1.5, 1.0));
        assert_eq!(-a, V::new(-1.0, -2.0, -3.0));
        assert_eq!(a * 2.0, V::new(2.0, 4.0, 6.0));
        assert_eq!(a / 2.0, V::new(0.5, 1.0, 1.5));
        assert_eq!(a * b, V::new(-4.0, 1.0, 6.0));
        assert_eq!(a.dot(b), 3.0);
        assert_eq!(a[0] + a[1] + a[2], 6.0);
    }

    #[test]
    fn cross_is_right_handed_and_orthogonal() {
        let x = V::new(1.0, 0.0, 0.0);
        let y = V::new(0.0, 1.0, 0.0);
        assert_eq!(x.cross(y), V::new(0.0, 0.0, 1.0));
        let a = V::new(1.0, 2.0, 3.0);
        let b = V::new(-4.0, 0.5, 2.0);
        assert_eq!(a.cross(b).dot(a), 0.0);
        assert_eq!(a.cross(b).dot(b), 0.0);
    }

    #[test]
    fn normalize_and_try_normalize() {
        let v = V::new(3.0, 0.0, 4.0);
        assert_eq!(v.length(), 5.0);
        assert_eq!(v.normalize(), V::new(0.6, 0.0, 0.8));
        assert_eq!(v.try_normalize(), Some(V::new(0.6, 0.0, 0.8)));
        assert_eq!(V::zero().try_normalize(), None);
        // |v|² underflows but v is not zero: still normalises.
        assert_eq!(
            V::new(0.0, 1e-200, 0.0).try_normalize(),
            Some(V::new(0.0, 1.0, 0.0))
        );
        assert_eq!(V::new(f64::NAN, 0.0, 1.0).try_normalize(), None);
        assert_eq!(V::new(f64::INFINITY, 0.0, 1.0).try_normalize(), None);
        // |v|² overflows but v is finite: still normalises.
        assert_eq!(
            V::new(3e300, 0.0, 4e300).try_normalize(),
            Some(V::new(0.6, 0.0, 0.8))
        );
        assert_eq!(
            Vec3::<f32>::new(1e20, 0.0, 0.0).try_normalize(),
            Some(Vec3::new(1.0, 0.0, 0.0))
        );
        assert_eq!(
            Vec3::<f32>::new(0.0, 0.0, -1e-40).try_normalize(),
            Some(Vec3::new(0.0, 0.0, -1.0))
        );
    }
}
