//! Render settings and image regions.

use crate::error::{Error, Result};

/// How to render: samples per pixel, recursion limit, seed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RenderSettings {
    /// Rays per pixel, at least 1. One goes through the pixel centre; more are jittered.
    pub samples_per_pixel: u32,
    /// The most bounces a path may take: a ray that hits a surface after `max_depth`
    /// bounces returns black. `0` shows only what the camera rays see directly as black
    /// silhouettes against the background. At most [`RenderSettings::MAX_DEPTH`].
    pub max_depth: u32,
    /// The seed every pixel's random stream derives from.
    pub seed: u64,
    /// Show a progress bar on stderr when it is a terminal.
    pub progress: bool,
}

impl RenderSettings {
    /// The deepest recursion accepted. The trace takes one stack frame per bounce (the
    /// spec's recursive trace), and a path trapped between mirrors uses every one: 5000
    /// bounces already fit in a 2 MiB thread stack (rayon's default) in `f64` and 7000
    /// overflowed it, so 1000 leaves room for every scalar and for pairs of rays. No image
    /// needs more: after 1000 bounces on albedo 0.99 a path carries 4·10⁻⁵ of its light.
    pub const MAX_DEPTH: u32 = 1000;

    /// Settings with the given samples per pixel, depth and seed (no progress bar).
    ///
    /// # Errors
    /// If `samples_per_pixel` is 0 or `max_depth` exceeds [`RenderSettings::MAX_DEPTH`].
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
        if self.max_depth > Self::MAX_DEPTH {
            return Err(Error::InvalidSettings(format!(
                "max depth must be at most {}, got {} (the recursion takes a stack frame per bounce)",
                Self::MAX_DEPTH,
                self.max_depth
            )));
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

    /// Tile `k` of `n` (`k` counts from 0, so `k in 0..n`) of a `width × height` image:
    /// a band of whole rows, rows `⌊k·height/n⌋..⌊(k+1)·height/n⌋`. The `n` bands cover
    /// the image in order, and their heights differ by at most one row.
    ///
    /// # Errors
    /// [`Error::Tiles`] if `n` is 0, `k ≥ n`, `n` exceeds `height` (a band would be
    /// empty), or the image is empty.
    pub fn tile(k: usize, n: usize, width: usize, height: usize) -> Result<Self> {
        let problem = if n == 0 {
            Some("the image must be split into at least 1 tile".to_string())
        } else if k >= n {
            Some(format!(
                "tile index {k} is not below the tile count {n} (it counts from 0)"
            ))
        } else if width == 0 || height == 0 {
            Some(format!("a {width}×{height} image has no rows to split"))
        } else if n > height {
            Some(format!(
                "{n} tiles of whole rows need at least {n} rows, the image has {height}"
            ))
        } else {
            None
        };
        if let Some(problem) = problem {
            return Err(Error::Tiles(problem));
        }
        // In u128 so that k·height cannot overflow.
        let row = |k: usize| (k as u128 * height as u128 / n as u128) as usize;
        Ok(Self {
            x: 0,
            y: row(k),
            width,
            height: row(k + 1) - row(k),
        })
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tiles_are_even_bands_covering_every_row_once() {
        for height in [1, 2, 7, 10, 99, 240] {
            for n in 1..=height.min(13) {
                let mut next = 0;
                for k in 0..n {
                    let t = Rect::tile(k, n, 5, height).unwrap();
                    assert_eq!(
                        (t.x, t.width, t.y),
                        (0, 5, next),
                        "tile {k} of {n}, height {height}"
                    );
                    let even = height / n;
                    assert!(t.height == even || t.height == even + 1, "{t:?}");
                    next += t.height;
                }
                assert_eq!(next, height, "{n} tiles of {height} rows");
            }
        }
        assert_eq!(Rect::tile(0, 1, 4, 3).unwrap(), Rect::full(4, 3));
    }

    #[test]
    fn impossible_tilings_are_refused_with_a_reason() {
        let cases = [
            ((0, 0, 4, 4), "at least 1 tile"),
            ((4, 4, 4, 4), "not below the tile count 4"),
            ((0, 5, 4, 4), "need at least 5 rows"),
            ((0, 1, 0, 4), "no rows"),
        ];
        for ((k, n, w, h), want) in cases {
            let msg = Rect::tile(k, n, w, h).unwrap_err().to_string();
            assert!(msg.contains(want), "{k} {n} {w} {h}: {msg}");
        }
    }
}
