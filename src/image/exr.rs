//! OpenEXR output: linear colour as 32-bit floats, values above 1 kept, for tools
//! that expect HDR images in the film industry's format; and the same with more layers
//! (an adaptive render's maps, a denoiser's features) in the one file.

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

/// One more channel of an EXR file beside the colour's `R`, `G` and `B`: named by
/// OpenEXR's layer convention, `layer.channel` (`albedo.R`, `normal.X`, `depth.Z`).
#[derive(Clone, Debug, PartialEq)]
pub struct ExrChannel {
    /// The channel's full name.
    pub name: String,
    /// One value per pixel, row by row from the top-left.
    pub values: ExrValues,
}

/// The values of an [`ExrChannel`].
#[derive(Clone, Debug, PartialEq)]
pub enum ExrValues {
    /// 32-bit floats (finite values beyond `f32`'s range clamped, as [`to_finite_f32`]).
    F32(Vec<f32>),
    /// 32-bit unsigned integers (counts, stored exactly).
    U32(Vec<u32>),
}

impl ExrChannel {
    /// A float channel from `f64` values, rounded as [`to_finite_f32`] rounds.
    pub fn floats(name: impl Into<String>, values: impl IntoIterator<Item = f64>) -> Self {
        Self {
            name: name.into(),
            values: ExrValues::F32(values.into_iter().map(to_finite_f32).collect()),
        }
    }

    /// A channel of counts.
    pub fn counts(name: impl Into<String>, values: Vec<u32>) -> Self {
        Self {
            name: name.into(),
            values: ExrValues::U32(values),
        }
    }

    fn len(&self) -> usize {
        match &self.values {
            ExrValues::F32(v) => v.len(),
            ExrValues::U32(v) => v.len(),
        }
    }
}

/// Writes `image` and `layers` as one EXR file, atomically (see [`write_atomic`]); as
/// [`write_layered_exr_to`].
pub fn write_layered_exr(path: &Path, image: &Image, layers: &[ExrChannel]) -> Result<()> {
    write_atomic(path, |out| {
        if out.get_ref().metadata()?.is_file() {
            write_layered_exr_to(out, image, layers)
        } else {
            let mut bytes = io::Cursor::new(Vec::new());
            write_layered_exr_to(&mut bytes, image, layers)?;
            out.write_all(bytes.get_ref())
        }
    })
}

/// Writes `image` as the `R`, `G` and `B` channels of a single-part OpenEXR file, with the
/// `layers` as further channels of the same part, losslessly compressed, into `out`.
/// A reader that knows nothing of layers shows the colour; one that groups channels by
/// the prefix before the last dot (OpenImageIO, Nuke, Blender, `exrheader`) shows each
/// layer.
///
/// # Errors
/// [`io::ErrorKind::InvalidInput`] if a channel does not hold one value per pixel or is
/// named `R`, `G`, `B` or twice; a failure to write or to seek.
pub fn write_layered_exr_to(out: impl Write + Seek, image: &Image, layers: &[ExrChannel]) -> io::Result<()> {
    let pixels = image.width() * image.height();
    let invalid = |m: String| io::Error::new(io::ErrorKind::InvalidInput, m);
    let mut names: Vec<&str> = vec!["R", "G", "B"];
    for layer in layers {
        if layer.len() != pixels {
            return Err(invalid(format!(
                "EXR channel {} has {} values for {pixels} pixels",
                layer.name,
                layer.len()
            )));
        }
        if names.contains(&layer.name.as_str()) {
            return Err(invalid(format!("EXR channel {} is given twice", layer.name)));
        }
        names.push(&layer.name);
    }
    let colour = |k: usize| {
        exr::AnyChannel::new(
            ["R", "G", "B"][k],
            exr::FlatSamples::F32(image.pixels().iter().map(|p| to_finite_f32(p[k])).collect()),
        )
    };
    let mut channels: exr::SmallVec<[exr::AnyChannel<exr::FlatSamples>; 4]> = (0..3).map(colour).collect();
    channels.extend(layers.iter().map(|layer| {
        let samples = match &layer.values {
            ExrValues::F32(v) => exr::FlatSamples::F32(v.clone()),
            ExrValues::U32(v) => exr::FlatSamples::U32(v.clone()),
        };
        exr::AnyChannel::new(layer.name.as_str(), samples)
    }));
    let layer = exr::Layer::new(
        (image.width(), image.height()),
        exr::LayerAttributes::default(),
        exr::Encoding::FAST_LOSSLESS,
        exr::AnyChannels::sort(channels),
    );
    exr::Image::from_layer(layer)
        .write()
        .to_buffered(out)
        .map_err(|e| match e {
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
    fn layers_are_channels_of_the_one_part() {
        let image = Image::from_pixels(2, 1, vec![[1.0, 2.0, 3.0], [4.0, 5.0, 6.0]]).unwrap();
        let layers = [
            ExrChannel::counts("samples.Y", vec![32, 4096]),
            ExrChannel::floats("albedo.R", [0.25, 1e300]),
        ];
        let mut bytes = io::Cursor::new(Vec::new());
        write_layered_exr_to(&mut bytes, &image, &layers).unwrap();
        bytes.set_position(0);
        use ::exr::prelude::{ReadChannels, ReadLayers};
        let read = exr::read()
            .no_deep_data()
            .largest_resolution_level()
            .all_channels()
            .all_layers()
            .all_attributes()
            .from_buffered(bytes)
            .unwrap();
        assert_eq!(read.layer_data.len(), 1);
        let channels = &read.layer_data[0].channel_data.list;
        let names: Vec<String> = channels.iter().map(|c| c.name.to_string()).collect();
        assert_eq!(names, ["B", "G", "R", "albedo.R", "samples.Y"]);
        assert_eq!(channels[2].sample_data, exr::FlatSamples::F32(vec![1.0, 4.0]));
        assert_eq!(
            channels[3].sample_data,
            exr::FlatSamples::F32(vec![0.25, f32::MAX])
        );
        assert_eq!(channels[4].sample_data, exr::FlatSamples::U32(vec![32, 4096]));

        let short = [ExrChannel::floats("depth.Z", [1.0])];
        let err = write_layered_exr_to(io::Cursor::new(Vec::new()), &image, &short).unwrap_err();
        assert!(err.to_string().contains("1 values for 2 pixels"), "{err}");
        let twice = [ExrChannel::floats("G", [1.0, 2.0])];
        let err = write_layered_exr_to(io::Cursor::new(Vec::new()), &image, &twice).unwrap_err();
        assert!(err.to_string().contains("given twice"), "{err}");
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
