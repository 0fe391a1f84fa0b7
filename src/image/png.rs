//! 16-bit PNG output, for viewing.

use super::{Encoding, Image16, write_atomic};
use crate::error::Result;
use std::io;
use std::path::Path;

/// Writes 16-bit RGB samples as a PNG, atomically. The file is tagged with the
/// transfer function the samples were made with (an sRGB chunk, or gAMA = 1 for linear).
pub fn write_png(path: &Path, image: &Image16, encoding: Encoding) -> Result<()> {
    let to_io = |e: ::png::EncodingError| io::Error::other(e.to_string());
    let too_big = || io::Error::new(io::ErrorKind::InvalidInput, "image too large for PNG");
    let width = u32::try_from(image.width).map_err(|_| too_big());
    let height = u32::try_from(image.height).map_err(|_| too_big());
    let scale = f64::from(u16::MAX) / f64::from(image.max_value.max(1));
    let bytes: Vec<u8> = image
        .samples
        .iter()
        .flat_map(|&s| ((f64::from(s) * scale).round() as u16).to_be_bytes())
        .collect();
    write_atomic(path, |out| {
        let mut enc = ::png::Encoder::new(out, width?, height?);
        enc.set_color(::png::ColorType::Rgb);
        enc.set_depth(::png::BitDepth::Sixteen);
        match encoding {
            Encoding::Srgb => enc.set_source_srgb(::png::SrgbRenderingIntent::Perceptual),
            Encoding::Linear => enc.set_source_gamma(::png::ScaledFloat::new(1.0)),
        }
        let mut writer = enc.write_header().map_err(to_io)?;
        writer.write_image_data(&bytes).map_err(to_io)?;
        writer.finish().map_err(to_io)
    })
}
