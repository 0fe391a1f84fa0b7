//! 16-bit PNG output, for viewing.

use super::{Encoding, Image16, write_atomic};
use crate::error::Result;
use std::io::{self, Write};
use std::path::Path;

/// The compression every PNG is written with: `Fast` (the `fdeflate` crate's DEFLATE,
/// tuned for PNG) rather than the `png` crate's default `Balanced` (zlib level 6), whose
/// encoding of a large render took longer than the render. The tests bound what the
/// files gain in size.
const PNG_COMPRESSION: ::png::Compression = ::png::Compression::Fast;

/// Writes 16-bit RGB samples as a PNG, atomically (see [`write_atomic`]); as
/// [`write_png_to`].
pub fn write_png(path: &Path, image: &Image16, encoding: Encoding) -> Result<()> {
    write_atomic(path, |out| write_png_to(out, image, encoding))
}

/// Writes 16-bit RGB samples as a PNG into `out`, compressed for speed (the `png` crate's
/// `Compression::Fast`).
/// The file is tagged with the transfer function the samples were made with (an sRGB
/// chunk, or gAMA = 1 for linear).
///
/// # Errors
/// An image wider or taller than PNG allows, or a failure to write.
pub fn write_png_to(out: impl Write, image: &Image16, encoding: Encoding) -> io::Result<()> {
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
    let mut enc = ::png::Encoder::new(out, width?, height?);
    enc.set_color(::png::ColorType::Rgb);
    enc.set_depth(::png::BitDepth::Sixteen);
    enc.set_compression(PNG_COMPRESSION);
    match encoding {
        Encoding::Srgb => enc.set_source_srgb(::png::SrgbRenderingIntent::Perceptual),
        Encoding::Linear => enc.set_source_gamma(::png::ScaledFloat::new(1.0)),
    }
    let mut writer = enc.write_header().map_err(to_io)?;
    writer.write_image_data(&bytes).map_err(to_io)?;
    writer.finish().map_err(to_io)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::image::Image;

    /// A render-like picture: smooth gradients with a little deterministic noise.
    fn picture(width: usize, height: usize) -> Image16 {
        let mut state = 0x9e37_79b9_u32;
        let pixels = (0..width * height)
            .map(|i| {
                state ^= state << 13;
                state ^= state >> 17;
                state ^= state << 5;
                let noise = f64::from(state % 256) / 25_600.0;
                let (x, y) = (
                    (i % width) as f64 / width as f64,
                    (i / width) as f64 / height as f64,
                );
                [0.2 + 0.6 * x + noise, 0.3 + 0.5 * y, 0.9 - 0.4 * x * y + noise]
            })
            .collect();
        Image::from_pixels(width, height, pixels)
            .unwrap()
            .to_u16(Encoding::Srgb)
    }

    /// `image` encoded with `compression`, tagged sRGB as [`write_png_to`] does.
    fn encode(image: &Image16, compression: ::png::Compression) -> Vec<u8> {
        let mut bytes = Vec::new();
        let mut enc = ::png::Encoder::new(&mut bytes, image.width as u32, image.height as u32);
        enc.set_color(::png::ColorType::Rgb);
        enc.set_depth(::png::BitDepth::Sixteen);
        enc.set_compression(compression);
        enc.set_source_srgb(::png::SrgbRenderingIntent::Perceptual);
        let samples: Vec<u8> = image.samples.iter().flat_map(|s| s.to_be_bytes()).collect();
        let mut writer = enc.write_header().unwrap();
        writer.write_image_data(&samples).unwrap();
        writer.finish().unwrap();
        bytes
    }

    #[test]
    fn pngs_are_compressed_for_speed_at_a_small_cost_in_size() {
        let image = picture(256, 128);
        let mut written = Vec::new();
        write_png_to(&mut written, &image, Encoding::Srgb).unwrap();
        assert_eq!(
            written,
            encode(&image, ::png::Compression::Fast),
            "not the fast compression"
        );
        let balanced = encode(&image, ::png::Compression::Balanced);
        assert_ne!(written, balanced);
        // What speed costs in size: 1.16 times the default's bytes on this picture.
        let ratio = written.len() as f64 / balanced.len() as f64;
        assert!(
            ratio < 1.25,
            "{} bytes against {} at the default",
            written.len(),
            balanced.len()
        );
        // And it reads back to the same samples.
        let mut reader = ::png::Decoder::new(std::io::Cursor::new(&written))
            .read_info()
            .unwrap();
        let mut buf = vec![0; reader.output_buffer_size().unwrap()];
        let info = reader.next_frame(&mut buf).unwrap();
        let read: Vec<u16> = buf[..info.buffer_size()]
            .chunks_exact(2)
            .map(|b| u16::from_be_bytes([b[0], b[1]]))
            .collect();
        assert_eq!(read, image.samples);
    }
}
