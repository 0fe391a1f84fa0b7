//! How linear colour becomes a stored 16-bit sample.

/// The transfer function from linear colour to stored samples.
///
/// The default is [`Encoding::Srgb`]: the Netpbm format defines PPM samples as
/// gamma-encoded (nominally with the Rec. 709 transfer function, which nearly every
/// viewer treats as sRGB) and PNG viewers assume sRGB, so the same samples look right
/// in both files. [`Encoding::Linear`] stores the radiance itself, for tools that want
/// numbers rather than a picture.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Encoding {
    /// The sRGB transfer function (IEC 61966-2-1):
    /// `12.92·c` for `c ≤ 0.0031308`, else `1.055·c^(1/2.4) − 0.055`.
    #[default]
    Srgb,
    /// No transfer function: the stored sample is proportional to the linear colour.
    Linear,
}

impl Encoding {
    /// Encodes one linear channel, clamped to `[0, 1]`.
    #[inline]
    pub fn encode(self, c: f64) -> f64 {
        let c = c.clamp(0.0, 1.0);
        match self {
            Self::Linear => c,
            Self::Srgb if c <= 0.003_130_8 => 12.92 * c,
            Self::Srgb => 1.055 * c.powf(1.0 / 2.4) - 0.055,
        }
    }

    /// The 16-bit sample of one linear channel: `round(65535 · encode(clamp(c, 0, 1)))`.
    ///
    /// Colour above 1 saturates to 65535. NaN cannot come out of the renderer (the
    /// tests check every pixel of random scenes); if it ever did it would be stored
    /// as 0, never as a garbage value.
    #[inline]
    pub fn quantize(self, c: f64) -> u16 {
        if c.is_nan() {
            return 0;
        }
        // encode(..) ∈ [0, 1], so the product is in [0, 65535] and the cast is exact.
        (self.encode(c) * 65535.0).round() as u16
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ends_and_middle() {
        for e in [Encoding::Srgb, Encoding::Linear] {
            assert_eq!(e.quantize(0.0), 0);
            assert_eq!(e.quantize(1.0), 65535);
            assert_eq!(e.quantize(7.0), 65535);
            assert_eq!(e.quantize(-1.0), 0);
            assert_eq!(e.quantize(f64::NAN), 0);
        }
        assert_eq!(Encoding::Linear.quantize(0.5), 32768);
        // sRGB(0.5) = 0.7353569...
        assert_eq!(
            Encoding::Srgb.quantize(0.5),
            (0.735_356_983_052_449 * 65535.0f64).round() as u16
        );
    }

    #[test]
    fn srgb_is_continuous_and_monotone() {
        let lo = Encoding::Srgb.encode(0.003_130_8);
        let hi = Encoding::Srgb.encode(0.003_130_8 + 1e-12);
        assert!((hi - lo).abs() < 1e-6);
        let mut prev = 0;
        for i in 0..=1000 {
            let q = Encoding::Srgb.quantize(f64::from(i) / 1000.0);
            assert!(q >= prev);
            prev = q;
        }
    }
}
