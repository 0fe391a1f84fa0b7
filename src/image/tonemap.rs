//! Exposure and a filmic tone curve: how a linear render with values far above 1 is made
//! into a picture for the display formats (PNG, PPM) before their encoding. The float
//! formats (EXR, PFM) store the linear values and never pass through here.

use crate::error::{Error, Field, Result};

/// The curve that maps exposed linear values to `[0, 1]` before encoding.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum ToneCurve {
    /// None: values above 1 clip, as the specification's PPM has them (the default).
    #[default]
    None,
    /// Krzysztof Narkowicz's fit of the ACES filmic curve (the RRT and the Rec. 709 ODT,
    /// with the 2.4 gamma taken out), "ACES Filmic Tone Mapping Curve", 2016:
    ///
    /// `f(x) = x(2.51x + 0.03) / (x(2.43x + 0.59) + 0.14)`, clamped to `[0, 1]`,
    ///
    /// per channel. It is pre-exposed so that 1 maps to about 0.8 (`f(1) = 2.54/3.16`);
    /// the original ACES curve is `f(0.6x)`. A toe below about 0.1, and a shoulder that
    /// reaches 1 only at `x = (0.56 + √0.3584)/0.16 ≈ 7.24` instead of a hard clip at 1.
    Aces,
}

impl ToneCurve {
    /// The curve at an exposed linear value `x`: in `[0, 1]` for `x ≥ 0` ([`ToneCurve::None`]
    /// leaves `x` as it is, for the encoding to clamp).
    #[inline]
    pub fn apply(self, x: f64) -> f64 {
        match self {
            Self::None => x,
            Self::Aces => aces_narkowicz(x),
        }
    }
}

/// Narkowicz's ACES fit (see [`ToneCurve::Aces`]): `x(2.51x + 0.03)/(x(2.43x + 0.59) + 0.14)`
/// clamped to `[0, 1]`. Negative values give 0; `+∞` gives 1 (the limit `2.51/2.43` clamped),
/// not the NaN of `∞/∞`; NaN stays NaN.
#[inline]
pub fn aces_narkowicz(x: f64) -> f64 {
    const A: f64 = 2.51;
    const B: f64 = 0.03;
    const C: f64 = 2.43;
    const D: f64 = 0.59;
    const E: f64 = 0.14;
    // The fit is a ratio of quadratics that turns up again below 0 (f(−3) ≈ 1.1) and
    // overflows to ∞/∞ for huge x, so both ends are set. f(x) ≥ 1 from the root of
    // 0.08x² − 0.56x − 0.14 (x ≈ 7.24) on, where the clamp gives 1 anyway. NaN stays NaN.
    if x.is_nan() {
        return x;
    }
    if x <= 0.0 {
        return 0.0;
    }
    if x >= 8.0 {
        return 1.0;
    }
    (x * (A * x + B) / (x * (C * x + D) + E)).clamp(0.0, 1.0)
}

/// Exposure in stops, then a [`ToneCurve`]: a linear value `c` becomes `curve(c·2^S)`,
/// which the file's [`Encoding`](super::Encoding) then encodes and quantizes.
///
/// [`Tonemap::NONE`] (0 stops, no curve) leaves every value exactly as it is, so the
/// specification's PPM is unchanged unless a tone map is asked for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tonemap {
    exposure: f64,
    /// `2^exposure`.
    scale: f64,
    curve: ToneCurve,
}

impl Default for Tonemap {
    fn default() -> Self {
        Self::NONE
    }
}

impl Tonemap {
    /// No exposure change and no curve: the identity.
    pub const NONE: Self = Self {
        exposure: 0.0,
        scale: 1.0,
        curve: ToneCurve::None,
    };

    /// The most stops an exposure may move by either way: `2^±64` spans 38 orders of
    /// magnitude, and keeps every finite pixel finite once exposed.
    pub const MAX_STOPS: f64 = 64.0;

    /// `exposure` stops (`+1` doubles every value, `−1` halves it), then `curve`.
    ///
    /// # Errors
    /// An exposure that is not a finite number in `[−64, 64]` ([`Tonemap::MAX_STOPS`]).
    pub fn new(exposure: f64, curve: ToneCurve) -> Result<Self> {
        if exposure.is_nan() || exposure.abs() > Self::MAX_STOPS {
            return Err(Error::invalid(
                Field::Exposure,
                format!(
                    "must be a number of stops in [-{0}, {0}] (got {exposure})",
                    Self::MAX_STOPS
                ),
            ));
        }
        Ok(Self {
            exposure,
            // Exact for whole stops: 2^k is a power of two.
            scale: exposure.exp2(),
            curve,
        })
    }

    /// The exposure, in stops.
    pub fn exposure(&self) -> f64 {
        self.exposure
    }

    /// The tone curve.
    pub fn curve(&self) -> ToneCurve {
        self.curve
    }

    /// Whether this changes nothing ([`Tonemap::NONE`]).
    pub fn is_identity(&self) -> bool {
        self.scale == 1.0 && self.curve == ToneCurve::None
    }

    /// `curve(c·2^S)`. With 0 stops the product is skipped, so the identity keeps even
    /// `−0` and NaN as they are.
    #[inline]
    pub fn apply(&self, c: f64) -> f64 {
        let exposed = if self.scale == 1.0 { c } else { c * self.scale };
        self.curve.apply(exposed)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn refuses_exposures_that_are_not_finite_or_too_far() {
        for bad in [f64::NAN, f64::INFINITY, -65.0, 64.5] {
            assert!(Tonemap::new(bad, ToneCurve::None).is_err(), "{bad}");
        }
        assert!(Tonemap::new(-64.0, ToneCurve::Aces).is_ok());
        assert!(Tonemap::NONE.is_identity());
        assert!(Tonemap::new(0.0, ToneCurve::None).unwrap().is_identity());
    }

    #[test]
    fn aces_ends() {
        assert_eq!(aces_narkowicz(0.0), 0.0);
        assert_eq!(aces_narkowicz(-3.0), 0.0);
        assert_eq!(aces_narkowicz(f64::INFINITY), 1.0);
        assert_eq!(aces_narkowicz(1e300), 1.0);
        // Either side of where the clamp takes over.
        assert!(aces_narkowicz(7.2) < 1.0);
        assert_eq!(aces_narkowicz(7.25), 1.0);
        assert!(aces_narkowicz(f64::NAN).is_nan());
    }
}
