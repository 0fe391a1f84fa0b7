//! Rectangles of pixels: the part of an image a render or a tile covers.

use crate::error::{Error, Result};

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
