//! OpenEXR output: linear colour as 32-bit floats, values above 1 kept, for tools
//! that expect HDR images in the film industry's format.

use super::{Image, to_finite_f32, write_atomic};
use crate::error::Result;
use ::exr::prelude::{self as exr, WritableImage};
use std::io::{self, Seek, Write};
use std::path::Path;

/// Writes `image` as EXR, atomically (see [`write_atomic`]); as [`write_exr_to`]. Into a
/// stream (a FIFO, a device), which cannot seek, the file is made in memory first.
pub fn write_exr(path: &Path, image: &Image) -> Result<()> {
    write_atomic(path, |out| {
        if out.get_ref().metadata()?.is_file() {
            write_exr_to(out, image)
        } else {
            let mut bytes = io::Cursor::new(Vec::new());
            write_exr_to(&mut bytes, image)?;
            out.write_all(bytes.get_ref())
        }
    })
}

/// Writes `image` as a single-layer OpenEXR file with `R`, `G` and `B` channels of linear
/// `f32`, losslessly compressed, into `out` (which must seek: the format ends with a
/// table of offsets; to stream one, write into an `io::Cursor` first).
///
/// # Precision
/// Each channel is rounded to the nearest `f32`; a finite value beyond `f32`'s range is
/// clamped to the largest finite `f32` ([`to_finite_f32`]), never written as infinity, as
/// in [`write_pfm`](super::write_pfm).
///
/// # Errors
/// A failure to write or to seek.
pub fn write_exr_to(out: impl Write + Seek, image: &Image) -> io::Result<()> {
    let width = image.width();
    let channels = exr::SpecificChannels::rgb(|exr::Vec2(x, y): exr::Vec2<usize>| {
        let [r, g, b] = image.pixels()[y * width + x].map(to_finite_f32);
        (r, g, b)
    });
    let exr_image = exr::Image::from_channels((width, image.height()), channels);
    exr_image.write().to_buffered(out).map_err(|e| match e {
        exr::Error::Io(e) => e,
        other => io::Error::other(other),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn very_bright_values_are_clamped_never_infinite() {
        use ::exr::prelude::{ReadChannels, ReadLayers};
        let image = Image::from_pixels(2, 1, vec![[1e300, 1e41, 3.5e38], [1.0, 0.5, 0.0]]).unwrap();
        let mut bytes = io::Cursor::new(Vec::new());
        write_exr_to(&mut bytes, &image).unwrap();
        bytes.set_position(0);
        let read = exr::read()
            .no_deep_data()
            .largest_resolution_level()
            .rgba_channels(
                |size, _| vec![[0.0f32; 3]; size.width() * size.height()],
                |pixels: &mut Vec<[f32; 3]>, exr::Vec2(x, _), (r, g, b, _): (f32, f32, f32, f32)| {
                    pixels[x] = [r, g, b];
                },
            )
            .first_valid_layer()
            .all_attributes()
            .from_buffered(bytes)
            .unwrap();
        assert_eq!(
            read.layer_data.channel_data.pixels,
            [[f32::MAX; 3], [1.0, 0.5, 0.0]]
        );
    }

    #[test]
    fn reads_back_with_the_exr_crate() {
        let (w, h) = (5, 3);
        let pixels = (0..w * h)
            .map(|i| {
                let v = i as f64;
                // Above 1, a fraction no f32 holds, and a tiny value.
                [v * 10.5, 0.1 + v, 1e-30 * v]
            })
            .collect();
        let image = Image::from_pixels(w, h, pixels).unwrap();
        let path = std::env::temp_dir().join(format!("raytrace-exr-{}.exr", std::process::id()));
        write_exr(&path, &image).unwrap();
        let read = exr::read_first_rgba_layer_from_file(
            &path,
            |size, _| vec![[0.0f32; 3]; size.width() * size.height()],
            move |pixels: &mut Vec<[f32; 3]>, exr::Vec2(x, y), (r, g, b, _): (f32, f32, f32, f32)| {
                pixels[y * w + x] = [r, g, b];
            },
        )
        .unwrap();
        std::fs::remove_file(&path).unwrap();
        let size = read.layer_data.size;
        assert_eq!((size.width(), size.height()), (w, h));
        let got = &read.layer_data.channel_data.pixels;
        for (i, (g, want)) in got.iter().zip(image.pixels()).enumerate() {
            assert_eq!(*g, want.map(|c| c as f32), "pixel {i}");
        }
    }
}
