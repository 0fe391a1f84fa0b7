//! A camera placed anywhere, looking at a point: a pinhole, or a thin lens that gives depth
//! of field.

use super::Camera;
use crate::error::{Error, Field, Result};
use crate::float::{Float, lit};
use crate::ray::Ray;
use crate::sampling::uniform_disk_concentric;
use crate::validate;
use crate::vec3::Vec3;

/// A pinhole camera at `from`, looking at `at`, with `up` roughly up and a vertical field
/// of view `vfov` (degrees). Used for scenes the spec's fixed camera cannot frame, such as
/// *Ray Tracing in One Weekend*'s final scene.
///
/// With the orthonormal frame `w = (from − at)/|from − at|`, `u = up×w/|up×w|`, `v = w×u`
/// and the viewport `2·tan(vfov/2)` high at distance 1, pixel coordinates `(x, y)` (centre
/// of pixel `(i, j)` at `(i, j)`, rows from the top) map to the direction
///
/// `D ∝ −w + ((x + ½)/nx − ½)·h_w·u + (½ − (y + ½)/ny)·h_h·v`, `h_w = h_h·nx/ny`.
///
/// # Depth of field
/// [`LookAtCamera::with_lens`] replaces the pinhole by a thin lens of radius `A`, as
/// Mitsuba 3's `thinlens` sensor: the points at distance `f` (the focus distance, along
/// the view axis) are sharp, and a ray leaves from a uniform point `L = A·(ℓₓu + ℓᵧv)` of
/// the lens disk (`ℓ` the [concentric map](uniform_disk_concentric) of two uniform numbers)
/// toward the point `f·D̃` its pinhole ray `D̃ = −w + s·h_w·u + t·h_h·v` meets on the
/// plane of focus:
///
/// `O = from + L`, `D = (f·D̃ − L)/|f·D̃ − L|`.
///
/// A point at distance `z` along the axis is then spread over a circle of confusion of
/// radius `A·|z − f|/z` on the plane of focus. With `A = 0` the camera is the pinhole,
/// ray for ray.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LookAtCamera<F> {
    width: usize,
    height: usize,
    origin: Vec3<F>,
    forward: Vec3<F>,
    right: Vec3<F>,
    up: Vec3<F>,
    /// The unit `u` and `v`, which span the lens.
    unit_right: Vec3<F>,
    unit_up: Vec3<F>,
    /// `|from − at|`: the focus distance unless one is given.
    target_distance: F,
    lens: Option<Lens<F>>,
}

/// A thin lens of radius `A > 0`, focused at `f`.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Lens<F> {
    /// `A·u` and `A·v`.
    right: Vec3<F>,
    up: Vec3<F>,
    aperture: F,
    focus_distance: F,
}

impl<F: Float> LookAtCamera<F> {
    /// A camera for a `width × height` image.
    ///
    /// # Errors
    /// Non-finite points, `from == at`, `up` parallel to the view direction, `vfov`
    /// outside `(0°, 180°)`, or an impossible image size.
    pub fn new(
        from: Vec3<F>,
        at: Vec3<F>,
        up: Vec3<F>,
        vfov: F,
        width: usize,
        height: usize,
    ) -> Result<Self> {
        validate::image_size(width, height)?;
        let from = validate::finite_vec(Field::CameraFrom, from)?;
        let at = validate::finite_vec(Field::CameraAt, at)?;
        let w = validate::direction(Field::CameraView, from - at)?;
        let target_distance = (from - at).length();
        let up = validate::direction(Field::CameraUp, up)?;
        // Both unit: |up × w| is the sine of their angle, and below γ(6) the frame would be
        // built from rounding noise (the same relative test as a degenerate triangle).
        let side = up.cross(w);
        if side.length().partial_cmp(&F::gamma(6)) != Some(std::cmp::Ordering::Greater) {
            return Err(Error::invalid(
                Field::CameraUp,
                format!(
                    "must not be parallel to the view direction (got {})",
                    validate::show(up)
                ),
            ));
        }
        let u = side.normalize();
        let v = w.cross(u);
        if !(vfov > F::zero() && vfov < lit(180.0)) {
            return Err(Error::invalid(
                Field::CameraVfov,
                format!("must be in (0, 180) degrees (got {})", validate::number(vfov)),
            ));
        }
        let h = lit::<F>(2.0) * (vfov.to_radians() * lit(0.5)).tan();
        let aspect = lit::<F>(width as f64) / lit(height as f64);
        Ok(Self {
            width,
            height,
            origin: from,
            forward: -w,
            right: u * (h * aspect),
            up: v * h,
            unit_right: u,
            unit_up: v,
            target_distance,
            lens: None,
        })
    }

    /// The same camera with a thin lens of radius `aperture` (`≥ 0`; 0 keeps the pinhole)
    /// focused at `focus_distance` (`> 0`) along the view axis; `None` focuses on `at`.
    ///
    /// # Errors
    /// A negative or non-finite aperture, a focus distance that is not finite and `> 0`.
    pub fn with_lens(self, aperture: F, focus_distance: Option<F>) -> Result<Self> {
        if !(aperture >= F::zero() && aperture.is_finite()) {
            return Err(Error::invalid(
                Field::CameraAperture,
                format!("must be a finite number ≥ 0 (got {})", validate::number(aperture)),
            ));
        }
        let focus_distance = match focus_distance {
            Some(f) => validate::positive(Field::CameraFocusDistance, f)?,
            None => self.target_distance,
        };
        let lens = (aperture > F::zero()).then(|| Lens {
            right: self.unit_right * aperture,
            up: self.unit_up * aperture,
            aperture,
            focus_distance,
        });
        Ok(Self { lens, ..self })
    }

    /// The lens radius, 0 for a pinhole.
    pub fn aperture(&self) -> F {
        self.lens.map_or(F::zero(), |l| l.aperture)
    }

    /// The distance along the view axis that is in focus: `|from − at|` unless
    /// [`LookAtCamera::with_lens`] said otherwise (every distance, for a pinhole).
    pub fn focus_distance(&self) -> F {
        self.lens.map_or(self.target_distance, |l| l.focus_distance)
    }

    /// The pinhole direction `D̃` through `(x, y)`, not normalized: its component along
    /// the view axis is 1.
    #[inline]
    fn pinhole(&self, x: F, y: F) -> Vec3<F> {
        let half = lit::<F>(0.5);
        let s = (x + half) / lit(self.width as f64) - half;
        let t = half - (y + half) / lit(self.height as f64);
        self.forward + self.right * s + self.up * t
    }
}

impl<F: Float> LookAtCamera<F> {
    /// The same camera in scalar `G` (its frame rounded through `f64`).
    #[must_use]
    pub fn cast<G: Float>(&self) -> LookAtCamera<G> {
        let lit = |x: F| G::from_f64(x.to_f64());
        LookAtCamera {
            width: self.width,
            height: self.height,
            origin: self.origin.cast(),
            forward: self.forward.cast(),
            right: self.right.cast(),
            up: self.up.cast(),
            unit_right: self.unit_right.cast(),
            unit_up: self.unit_up.cast(),
            target_distance: lit(self.target_distance),
            lens: self.lens.map(|l| Lens {
                right: l.right.cast(),
                up: l.up.cast(),
                aperture: lit(l.aperture),
                focus_distance: lit(l.focus_distance),
            }),
        }
    }
}

impl<F: Float> Camera<F> for LookAtCamera<F> {
    fn width(&self) -> usize {
        self.width
    }
    fn height(&self) -> usize {
        self.height
    }
    #[inline]
    fn ray(&self, x: F, y: F) -> Ray<F> {
        Ray::new(self.origin, self.pinhole(x, y).normalize())
    }
    fn has_lens(&self) -> bool {
        self.lens.is_some()
    }
    /// `O = from + L`, `D ∝ f·D̃ − L` (see [`LookAtCamera`]'s "Depth of field"); the
    /// pinhole's own ray without a lens.
    #[inline]
    fn ray_through_lens(&self, x: F, y: F, lens: [f64; 2]) -> Ray<F> {
        let Some(l) = self.lens else {
            return self.ray(x, y);
        };
        let [lx, ly] = uniform_disk_concentric(lens);
        let offset = l.right * lit::<F>(lx) + l.up * lit::<F>(ly);
        // Relative to the eye: the point in focus minus the point of the lens.
        let d = self.pinhole(x, y) * l.focus_distance - offset;
        Ray::new(self.origin + offset, d.normalize())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn centre_looks_at_the_target_and_corners_span_the_fov() {
        let from = Vec3::new(13.0, 2.0, 3.0);
        let at = Vec3::zero();
        let cam = LookAtCamera::new(from, at, Vec3::new(0.0, 1.0, 0.0), 20.0f64, 400, 200).unwrap();
        let centre = cam.ray(199.5, 99.5);
        assert!((centre.direction - (at - from).normalize()).length() < 1e-12);
        // The top and bottom edges are vfov apart.
        let top = cam.ray(199.5, -0.5).direction;
        let bottom = cam.ray(199.5, 199.5).direction;
        assert!((top.dot(bottom).acos().to_degrees() - 20.0).abs() < 1e-9);
        assert!(top.y > bottom.y, "row 0 is the top");
    }

    #[test]
    fn rejects_degenerate_setups() {
        let o = Vec3::<f64>::zero();
        let y = Vec3::new(0.0, 1.0, 0.0);
        let z = Vec3::new(0.0, 0.0, -1.0);
        assert!(LookAtCamera::new(o, o, y, 40.0, 10, 10).is_err());
        assert!(LookAtCamera::new(o, y, y, 40.0, 10, 10).is_err());
        assert!(LookAtCamera::new(o, z, y, 0.0, 10, 10).is_err());
        assert!(LookAtCamera::new(o, z, y, 180.0, 10, 10).is_err());
        assert!(LookAtCamera::new(o, z, y, f64::NAN, 10, 10).is_err());
        assert!(LookAtCamera::new(o, z, y, 40.0, 0, 10).is_err());
        assert!(LookAtCamera::new(o, z, y, 40.0, 10, 10).is_ok());
    }
}
