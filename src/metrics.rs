//! How far one image is from another: the error measures of the accuracy study.

use crate::error::{Error, Result};
use crate::image::{Encoding, Image};
use std::fmt;

/// The difference between an image and a reference, measured on the stored values: each
/// channel encoded (sRGB by default), clamped to `[0, 1]`, so one 8-bit step is `1/255`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ImageError {
    /// Root-mean-square difference over every channel of every pixel.
    pub rmse: f64,
    /// Largest difference of any channel.
    pub max: f64,
    /// Peak signal-to-noise ratio in dB, `20·log₁₀(1/RMSE)` (∞ for identical images).
    pub psnr: f64,
    /// Share of pixels with some channel off by more than one 8-bit step (`> 1/255`).
    pub over_one_step: f64,
}

impl ImageError {
    /// Whether at least 99 % of the pixels are within one 8-bit step of the reference:
    /// the criterion the precision advice uses.
    ///
    /// Not the RMSE or the maximum: a handful of pixels (silhouette edges, rays trapped
    /// between convex mirrors, where each bounce multiplies a deviation) can flip to a
    /// different surface under any rounding change and dominate both, while the share of
    /// pixels off measures how much of the picture a scalar changes.
    pub fn within_one_step(&self) -> bool {
        self.over_one_step <= 0.01
    }

    /// Compares `image` with `reference` under `encoding`.
    ///
    /// # Errors
    /// If the sizes differ.
    pub fn between(image: &Image, reference: &Image, encoding: Encoding) -> Result<Self> {
        if (image.width(), image.height()) != (reference.width(), reference.height()) {
            return Err(Error::InvalidSettings(format!(
                "cannot compare a {}×{} image with a {}×{} reference",
                image.width(),
                image.height(),
                reference.width(),
                reference.height()
            )));
        }
        let (mut sum2, mut max, mut over) = (0.0f64, 0.0f64, 0usize);
        for (p, q) in image.pixels().iter().zip(reference.pixels()) {
            let mut worst = 0.0f64;
            for k in 0..3 {
                let d = (encoding.encode(p[k]) - encoding.encode(q[k])).abs();
                // NaN must not hide: count it as the largest possible error.
                let d = if d.is_nan() { 1.0 } else { d };
                sum2 += d * d;
                worst = worst.max(d);
            }
            max = max.max(worst);
            over += usize::from(worst > 1.0 / 255.0);
        }
        let n = image.pixels().len() as f64;
        let rmse = (sum2 / (3.0 * n)).sqrt();
        Ok(Self {
            rmse,
            max,
            psnr: if rmse > 0.0 {
                -20.0 * rmse.log10()
            } else {
                f64::INFINITY
            },
            over_one_step: over as f64 / n,
        })
    }
}

impl fmt::Display for ImageError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "RMSE {:.2e}, max {:.2e}, PSNR {:.1} dB, {:.3} % of pixels off by > 1/255",
            self.rmse,
            self.max,
            self.psnr,
            100.0 * self.over_one_step
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn measures() {
        let a = Image::from_pixels(2, 1, vec![[0.5; 3], [0.0; 3]]).unwrap();
        let b = Image::from_pixels(2, 1, vec![[0.5; 3], [0.1, 0.0, 0.0]]).unwrap();
        let same = ImageError::between(&a, &a, Encoding::Linear).unwrap();
        assert_eq!((same.rmse, same.max, same.over_one_step), (0.0, 0.0, 0.0));
        assert!(same.psnr.is_infinite() && same.within_one_step());
        let e = ImageError::between(&b, &a, Encoding::Linear).unwrap();
        assert!((e.rmse - (0.01f64 / 6.0).sqrt()).abs() < 1e-15);
        assert!((e.max - 0.1).abs() < 1e-15);
        assert_eq!(e.over_one_step, 0.5);
        assert!(!e.within_one_step());
        let c = Image::from_pixels(1, 2, vec![[0.0; 3]; 2]).unwrap();
        assert!(ImageError::between(&a, &c, Encoding::Linear).is_err());
        let nan = Image::from_pixels(2, 1, vec![[f64::NAN; 3], [0.0; 3]]).unwrap();
        assert_eq!(ImageError::between(&nan, &a, Encoding::Linear).unwrap().max, 1.0);
    }
}
