//! [`Bitmap`]: an image's pixels as a texture stores them, linear RGB in `f32`, decoded
//! once and shared.

use crate::error::{Error, Result};
use std::path::Path;

/// The most pixels an image texture may have: 2²⁸ (a 16384 × 16384 image), 3 GiB as the
/// `f32` RGB a [`Bitmap`] stores, the same bound a render's image has
/// ([`image::MAX_PIXELS`](crate::image::MAX_PIXELS)). A file whose header declares more is
/// refused before any pixel is decoded.
pub const MAX_TEXTURE_PIXELS: usize = 1 << 28;

/// How an image file's stored values become a texture's, Mitsuba 3's `raw` flag.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Decode {
    /// Colour (`raw = false`, the default): an integer image (PNG, JPEG, 8 or 16 bits) is
    /// sRGB-encoded and decoded to linear RGB by [`srgb_to_linear`]; a float image
    /// (OpenEXR, Radiance HDR) is linear already and kept as it is.
    #[default]
    Color,
    /// Data (`raw = true`): the values as stored, an integer `q` of `n` bits as
    /// `q/(2ⁿ − 1)`, a float as it is. For what is not a colour: a normal map, a roughness.
    Raw,
}

/// The sRGB transfer function undone: the linear value of an encoded `c ∈ [0, 1]`,
///
/// `c/12.92` for `c ≤ 0.04045`, else `((c + 0.055)/1.055)^2.4`
///
/// (IEC 61966-2-1, the exact curve Mitsuba 3's bitmaps decode with).
pub fn srgb_to_linear(c: f64) -> f64 {
    if c <= 0.04045 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

/// An image's pixels: `width × height` linear RGB values in `f32`, row by row from the top
/// row of the image as its file stores it.
///
/// Made once per file ([`Bitmap::load`]) and shared behind an `Arc` by every texture that
/// uses it. Every value is finite.
#[derive(Clone, Debug, PartialEq)]
pub struct Bitmap {
    width: usize,
    height: usize,
    pixels: Vec<[f32; 3]>,
    grey: bool,
    range: [f32; 2],
}

impl Bitmap {
    /// The bitmap of `pixels` (row by row from the top, `width × height` of them), each
    /// channel finite; `grey` says its channels are equal, an image of one channel.
    ///
    /// # Errors
    /// [`Error::InvalidValue`] (`what = "image"`) for a size of zero or past
    /// [`MAX_TEXTURE_PIXELS`], a count of pixels other than `width × height`, or a value
    /// that is not finite.
    pub fn from_rgb(width: usize, height: usize, pixels: Vec<[f32; 3]>) -> Result<Self> {
        check_size(width, height).map_err(|why| Error::invalid("image", why))?;
        if pixels.len() != width * height {
            return Err(Error::invalid(
                "image",
                format!("{} pixels given for {width} × {height}", pixels.len()),
            ));
        }
        Self::checked(width, height, pixels).map_err(|why| Error::invalid("image", why))
    }

    /// The bitmap of `pixels` already of the right count, if every value is finite; the
    /// first that is not, by its position, otherwise.
    pub(super) fn checked(width: usize, height: usize, pixels: Vec<[f32; 3]>) -> Result<Self, String> {
        let mut range = [f32::INFINITY, f32::NEG_INFINITY];
        for (k, p) in pixels.iter().enumerate() {
            for &c in p {
                if !c.is_finite() {
                    let (x, y) = (k % width, k / width);
                    return Err(format!(
                        "pixel ({x}, {y}) (from the top left) is {c}: a texture's values must be finite"
                    ));
                }
                range = [range[0].min(c), range[1].max(c)];
            }
        }
        let grey = pixels.iter().all(|[r, g, b]| r == g && g == b);
        Ok(Self {
            width,
            height,
            pixels,
            grey,
            range,
        })
    }

    /// Reads the image file at `path`: PNG (the `png` crate), JPEG (`zune-jpeg`), Radiance
    /// HDR (read here) or OpenEXR (`exr`), told apart by their contents (not their names).
    /// Colour becomes linear RGB as `decode` says; a grey image's value goes into every
    /// channel; an alpha channel is dropped (not multiplied in), as Mitsuba 3's bitmap
    /// texture does. Of an OpenEXR file, the first layer with `R`, `G` and `B` channels is
    /// read, at its full resolution.
    ///
    /// # Errors
    /// [`Error::Image`], naming the file, for a file that is missing or not a regular file
    /// (a folder, a FIFO, a device), of another format, truncated or malformed, declaring
    /// more than [`MAX_TEXTURE_PIXELS`] pixels (refused before decoding), or holding a
    /// value that is not finite. No file makes it panic.
    pub fn load(path: &Path, decode: Decode) -> Result<Self> {
        super::load::load(path, decode).map_err(|message| Error::Image {
            path: path.to_path_buf(),
            message,
        })
    }

    /// Decodes an image held in memory (a glTF file's embedded PNG or JPEG) as
    /// [`Bitmap::load`] decodes a file; `name` says where it came from in messages.
    ///
    /// # Errors
    /// [`Error::Image`], naming `name`, for bytes of an unknown format, truncated or
    /// malformed, declaring more than [`MAX_TEXTURE_PIXELS`] pixels (refused before
    /// decoding), or holding a value that is not finite. No bytes make it panic.
    pub fn decode(bytes: &[u8], decode: Decode, name: &Path) -> Result<Self> {
        super::load::decode_bytes(bytes, decode).map_err(|message| Error::Image {
            path: name.to_path_buf(),
            message,
        })
    }

    /// The width in pixels.
    pub fn width(&self) -> usize {
        self.width
    }

    /// The height in pixels.
    pub fn height(&self) -> usize {
        self.height
    }

    /// The pixels, row by row from the top.
    pub fn pixels(&self) -> &[[f32; 3]] {
        &self.pixels
    }

    /// The pixels, row by row from the top, taken out of the bitmap.
    pub fn into_pixels(self) -> Vec<[f32; 3]> {
        self.pixels
    }

    /// Whether every pixel's three channels are equal (an image of one channel).
    pub fn is_grey(&self) -> bool {
        self.grey
    }

    /// The smallest and the largest channel value.
    pub fn range(&self) -> [f32; 2] {
        self.range
    }

    /// The pixel in column `x` and row `y` (from the top); both must be in range.
    #[inline]
    pub(super) fn texel(&self, x: usize, y: usize) -> [f32; 3] {
        self.pixels[y * self.width + x]
    }
}

/// Checks that a `width × height` image may be a texture: at least one pixel, at most
/// [`MAX_TEXTURE_PIXELS`].
pub(super) fn check_size(width: usize, height: usize) -> Result<(), String> {
    if width == 0 || height == 0 {
        return Err(format!("the image is {width} × {height} pixels: it has none"));
    }
    match width.checked_mul(height) {
        Some(n) if n <= MAX_TEXTURE_PIXELS => Ok(()),
        _ => Err(format!(
            "the image is {width} × {height} pixels, too large for memory: a texture may have \
             at most {MAX_TEXTURE_PIXELS} pixels (2^28, 16384 × 16384: 3 GiB as f32 RGB)"
        )),
    }
}
