//! OpenEXR output: linear colour as 32-bit floats, values above 1 kept, for tools
//! that expect HDR images in the film industry's format.

use super::{Image, write_atomic};
use crate::error::Result;
use ::exr::prelude::{self as exr, WritableImage};
use std::io;
use std::path::Path;

/// Writes `image` as a single-layer OpenEXR file with `R`, `G` and `B` channels of
/// linear `f32`, losslessly compressed, atomically (see [`write_atomic`]).
///
/// # Precision
/// Each channel is rounded to the nearest `f32`, as in [`write_pfm`](super::write_pfm).
pub fn write_exr(path: &Path, image: &Image) -> Result<()> {
    let width = image.width();
    let channels = exr::SpecificChannels::rgb(|exr::Vec2(x, y): exr::Vec2<usize>| {
        let [r, g, b] = image.pixels()[y * width + x];
        (r as f32, g as f32, b as f32)
    });
    let exr_image = exr::Image::from_channels((width, image.height()), channels);
    write_atomic(path, |out| {
        exr_image.write().to_buffered(out).map_err(|e| match e {
            exr::Error::Io(e) => e,
            other => io::Error::other(other),
        })
    })
}

#[cfg(test)]
mod tests {
    use super::*;

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
