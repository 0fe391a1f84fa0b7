//! Cameras: where each pixel's rays come from.

mod look_at;
mod screen;

pub use look_at::LookAtCamera;
pub use screen::ScreenCamera;

use crate::float::Float;
use crate::ray::Ray;

/// Maps continuous pixel coordinates to primary rays.
///
/// Pixel `(i, j)` (column `i` from the left, row `j` from the top) has its centre at
/// coordinates `(i, j)`; a jittered sample is at `(i + δx, j + δy)`, `δ ∈ [−½, ½)`.
///
/// A camera with a lens of some size ([`Camera::has_lens`]) also takes a point of the
/// lens for each ray ([`Camera::ray_through_lens`]); the renderer draws the two numbers it
/// is made from only for such a camera, so a pinhole's random stream is unchanged.
pub trait Camera<F: Float> {
    /// The image width in pixels.
    fn width(&self) -> usize;
    /// The image height in pixels.
    fn height(&self) -> usize;
    /// The primary ray through the point `(x, y)` in pixel coordinates (through the centre
    /// of the lens, for a camera that has one).
    fn ray(&self, x: F, y: F) -> Ray<F>;
    /// Whether rays start from a lens of non-zero size, so that each needs a point of it
    /// ([`Camera::ray_through_lens`]). `false` for a pinhole.
    fn has_lens(&self) -> bool {
        false
    }
    /// The primary ray through `(x, y)` from the point of the lens that `lens ∈ [0, 1)²`
    /// (two uniform numbers) picks. A pinhole ignores `lens`: [`Camera::ray`].
    fn ray_through_lens(&self, x: F, y: F, lens: [f64; 2]) -> Ray<F> {
        let _ = lens;
        self.ray(x, y)
    }
}

/// A camera that can be rebuilt for another scalar, so one camera serves renders in every
/// precision ([`crate::advice::advise`] renders a scene in several).
pub trait CastCamera {
    /// The camera in scalar `G`.
    type In<G: Float>: Camera<G> + Sync;
    /// Rebuilds the camera in scalar `G`.
    fn cast<G: Float>(&self) -> Self::In<G>;
}

impl CastCamera for ScreenCamera {
    type In<G: Float> = ScreenCamera;
    fn cast<G: Float>(&self) -> ScreenCamera {
        *self
    }
}

impl<F: Float> CastCamera for LookAtCamera<F> {
    type In<G: Float> = LookAtCamera<G>;
    fn cast<G: Float>(&self) -> LookAtCamera<G> {
        LookAtCamera::cast(self)
    }
}

impl<F: Float, C: Camera<F> + ?Sized> Camera<F> for &C {
    fn width(&self) -> usize {
        (**self).width()
    }
    fn height(&self) -> usize {
        (**self).height()
    }
    fn ray(&self, x: F, y: F) -> Ray<F> {
        (**self).ray(x, y)
    }
    fn has_lens(&self) -> bool {
        (**self).has_lens()
    }
    fn ray_through_lens(&self, x: F, y: F, lens: [f64; 2]) -> Ray<F> {
        (**self).ray_through_lens(x, y, lens)
    }
}
