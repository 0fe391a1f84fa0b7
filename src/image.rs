//! Images: the linear RGB buffer a render produces, its 16-bit encoding, the files it is
//! written to (PPM and PNG for viewing, exposed and tone mapped if asked, PFM and OpenEXR
//! keeping linear values above 1),
//! and the tile files a render split across processes is merged from. Every file is
//! written atomically ([`write_atomic`]'s rules for links, devices and FIFOs); each format
//! also has a `write_*_to` form that encodes into any writer (a pipe, standard output).

pub(crate) mod atomic;
mod encoding;
mod exr;
mod pfm;
mod png;
mod ppm;
mod rect;
mod tile;
mod tonemap;

pub use self::exr::{
    ExrChannel, ExrValues, write_exr, write_exr_to, write_layered_exr, write_layered_exr_to,
};
pub use atomic::write_atomic;
pub use encoding::Encoding;
pub use pfm::{parse_pfm, read_pfm, write_pfm, write_pfm_to};
pub use png::{write_png, write_png_to};
pub use ppm::{parse_ppm, read_ppm, write_ppm, write_ppm_to};
pub use rect::Rect;
pub use tile::{TileHeader, check_tile, merge_tiles, parse_tile, read_tile, write_tile, write_tile_to};
pub use tonemap::{ToneCurve, Tonemap, aces_narkowicz};

use crate::error::{Error, Result};

/// `c` rounded to the nearest `f32`, clamped to `±f32::MAX` where it lies beyond: a very
/// bright but finite value stays finite in a float file (EXR, PFM), as the brightest value
/// the file can hold. NaN stays NaN.
///
/// # Precision
/// As `c as f32` inside `f32`'s range (round to nearest, ties to even).
pub fn to_finite_f32(c: f64) -> f32 {
    c.clamp(-f64::from(f32::MAX), f64::from(f32::MAX)) as f32
}

/// The largest image accepted, in pixels (2²⁸: a 16384×16384 render, 6 GiB as `f64`).
pub const MAX_PIXELS: usize = 1 << 28;

/// Checks that `width × height` is a possible image: both at least 1, at most
/// [`MAX_PIXELS`] pixels in all.
pub fn check_size(width: usize, height: usize) -> Result<()> {
    match width.checked_mul(height) {
        Some(n) if width > 0 && height > 0 && n <= MAX_PIXELS => Ok(()),
        _ => Err(Error::InvalidSettings(format!(
            "image size {width}×{height} must be at least 1×1 and at most {MAX_PIXELS} pixels"
        ))),
    }
}

/// A linear RGB image: what the renderer computes, one `[r, g, b]` per pixel, row by row
/// from the top-left.
#[derive(Clone, Debug, PartialEq)]
pub struct Image {
    width: usize,
    height: usize,
    pixels: Vec<[f64; 3]>,
}

impl Image {
    /// A black image.
    pub fn new(width: usize, height: usize) -> Result<Self> {
        check_size(width, height)?;
        Ok(Self {
            width,
            height,
            pixels: vec![[0.0; 3]; width * height],
        })
    }

    /// An image from its pixels, row by row; `None` if the count is not `width × height`.
    pub fn from_pixels(width: usize, height: usize, pixels: Vec<[f64; 3]>) -> Option<Self> {
        (check_size(width, height).is_ok() && pixels.len() == width * height).then_some(Self {
            width,
            height,
            pixels,
        })
    }

    /// Width in pixels.
    pub fn width(&self) -> usize {
        self.width
    }

    /// Height in pixels.
    pub fn height(&self) -> usize {
        self.height
    }

    /// The pixels, row by row from the top-left.
    pub fn pixels(&self) -> &[[f64; 3]] {
        &self.pixels
    }

    /// The pixels, mutably.
    pub fn pixels_mut(&mut self) -> &mut [[f64; 3]] {
        &mut self.pixels
    }

    /// Pixel `(x, y)`, `x` from the left, `y` from the top.
    ///
    /// # Panics
    /// If the pixel lies outside the image.
    pub fn pixel(&self, x: usize, y: usize) -> [f64; 3] {
        assert!(
            x < self.width && y < self.height,
            "pixel ({x}, {y}) outside {}×{}",
            self.width,
            self.height
        );
        self.pixels[y * self.width + x]
    }

    /// The 16-bit samples of this image under `encoding` (see [`Encoding::quantize`]).
    #[must_use]
    pub fn to_u16(&self, encoding: Encoding) -> Image16 {
        self.to_u16_tonemapped(Tonemap::NONE, encoding)
    }

    /// The 16-bit samples of this image exposed and tone mapped by `tonemap`, then encoded:
    /// `quantize(encoding, tonemap(c))` per channel. With [`Tonemap::NONE`] the samples of
    /// [`Image::to_u16`].
    #[must_use]
    pub fn to_u16_tonemapped(&self, tonemap: Tonemap, encoding: Encoding) -> Image16 {
        Image16 {
            width: self.width,
            height: self.height,
            max_value: u16::MAX,
            samples: self
                .pixels
                .iter()
                .flat_map(|p| p.map(|c| encoding.quantize(tonemap.apply(c))))
                .collect(),
        }
    }
}

/// Integer RGB samples as stored in a PPM or PNG file.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Image16 {
    /// Width in pixels.
    pub width: usize,
    /// Height in pixels.
    pub height: usize,
    /// The largest sample value (`65535` for the spec's files).
    pub max_value: u16,
    /// `3 × width × height` samples, `R G B` per pixel, row by row from the top-left.
    pub samples: Vec<u16>,
}
