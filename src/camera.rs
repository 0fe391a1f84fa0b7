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
pub trait Camera<F: Float> {
    /// The image width in pixels.
    fn width(&self) -> usize;
    /// The image height in pixels.
    fn height(&self) -> usize;
    /// The primary ray through the point `(x, y)` in pixel coordinates.
    fn ray(&self, x: F, y: F) -> Ray<F>;
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
}
