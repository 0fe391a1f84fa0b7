//! Render settings and image regions.

use crate::error::{Error, Result};

/// How to render: samples per pixel, recursion limit, seed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RenderSettings {
    /// Rays per pixel, at least 1. One goes through the pixel centre; more are jittered.
    pub samples_per_pixel: u32,
    /// The most bounces a path may take: a ray that hits a surface after `max_depth`
    /// bounces returns black. `0` shows only what the camera rays see directly as black
    /// silhouettes against the background.
    pub max_depth: u32,
    /// The seed every pixel's random stream derives from.
    pub seed: u64,
    /// Show a progress bar on stderr when it is a terminal.
    pub progress: bool,
}

impl RenderSettings {
    /// Settings with the given samples per pixel, depth and seed (no progress bar).
    ///
    /// # Errors
    /// If `samples_per_pixel` is 0.
    pub fn new(samples_per_pixel: u32, max_depth: u32, seed: u64) -> Result<Self> {
        let s = Self {
            samples_per_pixel,
            max_depth,
            seed,
            progress: false,
        };
        s.validate()?;
        Ok(s)
    }

    /// Checks the settings (the fields are public, so the renderer checks again).
    pub fn validate(&self) -> Result<()> {
        if self.samples_per_pixel == 0 {
            return Err(Error::InvalidSettings(
                "samples per pixel must be at least 1, got 0".into(),
            ));
        }
        Ok(())
    }
}

/// The spec's minimum: one ray per pixel centre, `max_depth = 10`, seed 0.
impl Default for RenderSettings {
    fn default() -> Self {
        Self {
            samples_per_pixel: 1,
            max_depth: 10,
            seed: 0,
            progress: false,
        }
    }
}

/// A rectangle of pixels: columns `x..x + width`, rows `y..y + height` (rows from the top).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Rect {
    /// First column.
    pub x: usize,
    /// First row.
    pub y: usize,
    /// Number of columns.
    pub width: usize,
    /// Number of rows.
    pub height: usize,
}

impl Rect {
    /// The whole `width × height` image.
    pub fn full(width: usize, height: usize) -> Self {
        Self {
            x: 0,
            y: 0,
            width,
            height,
        }
    }

    /// Checks the rectangle is non-empty and inside a `width × height` image.
    pub fn check_inside(&self, width: usize, height: usize) -> Result<()> {
        let fits =
            |a: usize, len: usize, max: usize| len > 0 && a.checked_add(len).is_some_and(|end| end <= max);
        if fits(self.x, self.width, width) && fits(self.y, self.height, height) {
            Ok(())
        } else {
            Err(Error::InvalidSettings(format!(
                "tile {self:?} is empty or outside the {width}×{height} image"
            )))
        }
    }
}
