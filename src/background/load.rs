//! Reading an environment map's image: OpenEXR or Radiance HDR (any format a texture
//! reads), linear, through [`Bitmap::load`].

use super::EnvironmentMap;
use crate::error::{Error, Field, Result};
use crate::texture::{Bitmap, Decode};
use std::path::Path;

impl EnvironmentMap {
    /// The map in the image file `path`, scaled by `scale`. An OpenEXR or Radiance HDR file
    /// is linear and read as stored; an 8- or 16-bit file (PNG, JPEG) is sRGB-decoded, as
    /// Mitsuba 3's `envmap` does.
    ///
    /// # Errors
    /// [`Error::InvalidValue`] ([`Field::EnvironmentMap`]) naming the file for one that
    /// [`Bitmap::load`] cannot read (missing, not a regular file, malformed, larger than
    /// [`EnvironmentMap::MAX_TEXELS`], refused before decoding) or that
    /// [`EnvironmentMap::new`] refuses.
    pub fn load(path: &Path, scale: f64) -> Result<Self> {
        let at_file = |reason: &dyn std::fmt::Display| {
            Error::invalid(Field::EnvironmentMap, format!("{}: {reason}", path.display()))
        };
        let bitmap = Bitmap::load(path, Decode::Color).map_err(|e| match e {
            Error::Image { message, .. } => at_file(&message),
            other => other,
        })?;
        let (width, height) = (bitmap.width(), bitmap.height());
        Self::new(width, height, bitmap.into_pixels(), scale).map_err(|e| match e {
            Error::InvalidValue { field, reason } => {
                Error::invalid(field, format!("{}: {reason}", path.display()))
            }
            other => other,
        })
    }
}
