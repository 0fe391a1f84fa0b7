//! The camera a scene file describes, in either of the library's kinds.

use crate::camera::{Camera, CastCamera, LookAtCamera, ScreenCamera};
use crate::float::Float;
use crate::ray::Ray;

/// A scene file's camera: the specification's or a look-at camera.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FileCamera<F> {
    /// The specification's camera ([`ScreenCamera`]).
    Screen(ScreenCamera),
    /// A camera anywhere, a pinhole or a thin lens ([`LookAtCamera`]).
    LookAt(LookAtCamera<F>),
}

impl<F: Float> Camera<F> for FileCamera<F> {
    fn width(&self) -> usize {
        match self {
            Self::Screen(c) => Camera::<F>::width(c),
            Self::LookAt(c) => c.width(),
        }
    }
    fn height(&self) -> usize {
        match self {
            Self::Screen(c) => Camera::<F>::height(c),
            Self::LookAt(c) => c.height(),
        }
    }
    #[inline]
    fn ray(&self, x: F, y: F) -> Ray<F> {
        match self {
            Self::Screen(c) => c.ray(x, y),
            Self::LookAt(c) => c.ray(x, y),
        }
    }
    fn has_lens(&self) -> bool {
        match self {
            Self::Screen(c) => Camera::<F>::has_lens(c),
            Self::LookAt(c) => c.has_lens(),
        }
    }
    #[inline]
    fn ray_through_lens(&self, x: F, y: F, lens: [f64; 2]) -> Ray<F> {
        match self {
            Self::Screen(c) => c.ray_through_lens(x, y, lens),
            Self::LookAt(c) => c.ray_through_lens(x, y, lens),
        }
    }
}

impl<F: Float> CastCamera for FileCamera<F> {
    type In<G: Float> = FileCamera<G>;
    fn cast<G: Float>(&self) -> FileCamera<G> {
        match self {
            Self::Screen(c) => FileCamera::Screen(*c),
            Self::LookAt(c) => FileCamera::LookAt(c.cast()),
        }
    }
}
