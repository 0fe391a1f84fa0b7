//! Reading an environment map's image: OpenEXR, its first RGB(A) layer, linear.

use super::EnvironmentMap;
use crate::error::{Error, Field, Result};
use ::exr::prelude as exr;
use std::path::Path;

/// The texels being read: the image's width and height, and storage for them (empty for
/// an image too large to hold, which is refused once the header is read).
struct Texels {
    width: usize,
    height: usize,
    pixels: Vec<[f32; 3]>,
}

impl EnvironmentMap {
    /// The map in the OpenEXR file `path` (its first layer's R, G and B, linear), scaled
    /// by `scale`.
    ///
    /// # Errors
    /// [`Error::InvalidValue`] ([`Field::EnvironmentMap`]) naming the file for one that
    /// cannot be read or is not an OpenEXR image, is larger than
    /// [`EnvironmentMap::MAX_TEXELS`] (refused without allocating its pixels), or that
    /// [`EnvironmentMap::new`] refuses.
    pub fn load(path: &Path, scale: f64) -> Result<Self> {
        let fail =
            |reason: String| Error::invalid(Field::EnvironmentMap, format!("{}: {reason}", path.display()));
        let read = exr::read_first_rgba_layer_from_file(
            path,
            |size, _| {
                let (width, height) = (size.width(), size.height());
                let pixels = match width.checked_mul(height) {
                    Some(n) if n <= Self::MAX_TEXELS => vec![[0.0f32; 3]; n],
                    _ => Vec::new(),
                };
                Texels {
                    width,
                    height,
                    pixels,
                }
            },
            |texels: &mut Texels, exr::Vec2(x, y), (r, g, b, _): (f32, f32, f32, f32)| {
                let width = texels.width;
                if let Some(p) = texels.pixels.get_mut(y * width + x) {
                    *p = [r, g, b];
                }
            },
        )
        .map_err(|e| fail(format!("cannot read it as an OpenEXR image ({e})")))?;
        let Texels {
            width,
            height,
            pixels,
        } = read.layer_data.channel_data.pixels;
        if pixels.len() != width.saturating_mul(height) {
            return Err(fail(format!(
                "{width}×{height} texels is more than the {} an environment map may have",
                Self::MAX_TEXELS
            )));
        }
        Self::new(width, height, pixels, scale).map_err(|e| match e {
            Error::InvalidValue { field, reason } => {
                Error::invalid(field, format!("{}: {reason}", path.display()))
            }
            other => other,
        })
    }
}
