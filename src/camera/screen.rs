//! The specification's camera.

use super::Camera;
use crate::error::{Error, Field, Result};
use crate::float::{Float, lit};
use crate::ray::Ray;
use crate::vec3::Vec3;

/// The specification's camera: the eye at the origin `E = (0, 0, 0)`, looking down the
/// **−z** axis (x to the right, y up, a right-handed frame), and the screen in the plane
/// `z = −1` (focal distance `d = 1`, perpendicular to the z axis).
///
/// The screen is `h_x = 4` wide and `h_y = 2` high **between the centres of the outermost
/// pixels**, so pixel `(i, j)` of an `nx × ny` image (column `i` from the left, row `j`
/// from the top) has its centre at
///
/// `P_ij = (−2 + 4i/(nx − 1), 1 − 2j/(ny − 1), −1)`
///
/// and its ray is `D = (P_ij − E)/|P_ij − E|`. The four corner pixels are centred at
/// `(±2, ±1, −1)`. The image keeps the 2:1 aspect: `nx = 2·ny`. (The pixel pitch is then
/// `4/(nx − 1)` across and `2/(ny − 1)` down, which differ by `1/(2ny − 1)` relative,
/// 0.13 % at 800×400 — the price of measuring between centres, as the spec does.)
///
/// [`ScreenCamera::translated`] moves the eye (and the screen with it) away from the
/// origin, for studying precision far from the origin; the default is the spec's origin.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ScreenCamera {
    width: usize,
    height: usize,
    eye: [f64; 3],
}

impl ScreenCamera {
    /// The spec's camera for an `width × height` image.
    ///
    /// # Errors
    /// [`Error::InvalidValue`] ([`Field::ImageSize`]) unless `width = 2·height` and `height ≥ 2` (one row
    /// has no "outermost centres" to span 2 units between), or if the image would
    /// have more than [`MAX_PIXELS`](crate::image::MAX_PIXELS) pixels.
    pub fn new(width: usize, height: usize) -> Result<Self> {
        if height < 2 || height.checked_mul(2) != Some(width) {
            return Err(Error::invalid(
                Field::ImageSize,
                format!(
                    "the spec's camera needs a 2:1 image at least 4×2 (width = 2·height), got {width}×{height}"
                ),
            ));
        }
        crate::validate::image_size(width, height)?;
        Ok(Self {
            width,
            height,
            eye: [0.0; 3],
        })
    }

    /// The same camera with the eye at `eye` instead of the origin (the screen moves with
    /// it: `P_ij + eye`). Rays start at `eye` rounded to the scalar; directions are unchanged.
    ///
    /// # Errors
    /// If a coordinate is not finite.
    pub fn translated(self, eye: [f64; 3]) -> Result<Self> {
        if eye.iter().all(|c| c.is_finite()) {
            Ok(Self { eye, ..self })
        } else {
            Err(Error::invalid(
                Field::CameraEye,
                format!(
                    "every component must be finite (got {})",
                    crate::validate::show(Vec3::new(eye[0], eye[1], eye[2]))
                ),
            ))
        }
    }

    /// The spec's camera for an image `width` pixels wide (`height = width/2`).
    ///
    /// # Errors
    /// [`Field::ImageWidth`] for an odd width or one below 4; [`Field::ImageSize`] past
    /// [`MAX_PIXELS`](crate::image::MAX_PIXELS).
    pub fn with_width(width: usize) -> Result<Self> {
        if width < 4 || !width.is_multiple_of(2) {
            return Err(Error::invalid(
                Field::ImageWidth,
                format!("the spec's camera needs an even width of at least 4, for a 2:1 image (got {width})"),
            ));
        }
        Self::new(width, width / 2)
    }

    /// The point on the screen at pixel coordinates `(x, y)`: `(−2 + 4x/(nx−1), 1 − 2y/(ny−1), −1)`.
    #[inline]
    pub fn screen_point<F: Float>(&self, x: F, y: F) -> Vec3<F> {
        let sx = lit::<F>(4.0) / lit((self.width - 1) as f64);
        let sy = lit::<F>(2.0) / lit((self.height - 1) as f64);
        Vec3::new(lit::<F>(-2.0) + x * sx, F::one() - y * sy, -F::one())
    }
}

impl<F: Float> Camera<F> for ScreenCamera {
    fn width(&self) -> usize {
        self.width
    }
    fn height(&self) -> usize {
        self.height
    }
    #[inline]
    fn ray(&self, x: F, y: F) -> Ray<F> {
        // |P − E| ≥ 1 since P_z = −1, so the normalisation never fails.
        let [ex, ey, ez] = self.eye;
        Ray::new(Vec3::from_f64(ex, ey, ez), self.screen_point(x, y).normalize())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn corners_and_middle_land_where_the_spec_says() {
        let cam = ScreenCamera::new(800, 400).unwrap();
        let p = |i: f64, j: f64| cam.screen_point(i, j);
        assert_eq!(p(0.0, 0.0), Vec3::new(-2.0, 1.0, -1.0));
        assert_eq!(p(799.0, 0.0), Vec3::new(2.0, 1.0, -1.0));
        assert_eq!(p(0.0, 399.0), Vec3::new(-2.0, -1.0, -1.0));
        assert_eq!(p(799.0, 399.0), Vec3::new(2.0, -1.0, -1.0));
        assert_eq!(p(399.5, 199.5), Vec3::new(0.0, 0.0, -1.0));
        let r: Ray<f64> = cam.ray(799.0, 0.0);
        assert_eq!(r.origin, Vec3::zero());
        let expect = Vec3::new(2.0, 1.0, -1.0) / 6.0f64.sqrt();
        assert!((r.direction - expect).length() < 1e-15);
    }

    #[test]
    fn rejects_sizes_that_are_not_two_to_one() {
        for (w, h) in [(800, 401), (801, 400), (799, 400), (400, 400), (2, 1), (0, 0)] {
            let err = ScreenCamera::new(w, h).unwrap_err().to_string();
            assert!(err.contains("2:1"), "{w}×{h}: {err}");
        }
        assert!(ScreenCamera::new(4, 2).is_ok());
    }
}
