//! Reading image files into a [`Bitmap`]: PNG, JPEG and Radiance HDR through the `image`
//! crate, OpenEXR through the `exr` crate. The size is checked from the header, before any
//! pixel is decoded; every failure is a message about the file, never a panic.

use super::bitmap::{Bitmap, Decode, MAX_TEXTURE_PIXELS, check_size, srgb_to_linear};
use ::image::{DynamicImage, ImageDecoder, ImageReader, Limits};
use std::fs::File;
use std::io::{BufRead, BufReader, Cursor, Read, Seek};
use std::path::Path;

/// The first four bytes of every OpenEXR file.
const EXR_MAGIC: [u8; 4] = [0x76, 0x2f, 0x31, 0x01];

/// The bitmap of the image file at `path`, or why not (the caller names the file).
pub(super) fn load(path: &Path, decode: Decode) -> Result<Bitmap, String> {
    // Asked before opening: opening a FIFO would wait for a writer.
    let meta = std::fs::metadata(path).map_err(|e| format!("cannot open the image: {e}"))?;
    if !meta.is_file() {
        let kind = if meta.is_dir() {
            "a folder"
        } else {
            "a device, a FIFO or a socket"
        };
        return Err(format!("cannot read {kind}: an image must be a regular file"));
    }
    let mut magic = [0u8; 4];
    let mut file = File::open(path).map_err(|e| format!("cannot open the image: {e}"))?;
    let n = file
        .read(&mut magic)
        .map_err(|e| format!("cannot read the image: {e}"))?;
    if n == 4 && magic == EXR_MAGIC {
        load_exr(path)
    } else {
        load_other(path, decode)
    }
}

/// A PNG, JPEG or Radiance HDR file, its format guessed from its first bytes.
fn load_other(path: &Path, decode: Decode) -> Result<Bitmap, String> {
    let file = File::open(path).map_err(|e| format!("cannot open the image: {e}"))?;
    decode_reader(BufReader::new(file), decode)
}

/// The bitmap of an encoded image held in memory (a glTF file's embedded PNG or JPEG),
/// or why not: PNG, JPEG or Radiance HDR, its format guessed from its first bytes.
pub(super) fn decode_bytes(bytes: &[u8], decode: Decode) -> Result<Bitmap, String> {
    decode_reader(Cursor::new(bytes), decode)
}

/// An image read from `reader`, its format guessed from its first bytes, its size checked
/// from its header before a pixel is decoded.
fn decode_reader(reader: impl BufRead + Seek, decode: Decode) -> Result<Bitmap, String> {
    let mut reader = ImageReader::new(reader)
        .with_guessed_format()
        .map_err(|e| format!("cannot read the image: {e}"))?;
    if reader.format().is_none() {
        return Err(
            "not an image of a known format: a texture is a PNG, JPEG, Radiance HDR (.hdr) \
                    or OpenEXR file"
                .into(),
        );
    }
    // The decoder's own allocation bound, a second guard behind the size check below: the
    // largest decoded buffer, 16-bit RGBA or f32 RGB, at the largest size.
    let mut limits = Limits::default();
    limits.max_alloc = Some(MAX_TEXTURE_PIXELS as u64 * 16);
    reader.limits(limits);
    let decoder = reader
        .into_decoder()
        .map_err(|e| format!("cannot decode the image: {e}"))?;
    let (w, h) = decoder.dimensions();
    check_size(w as usize, h as usize)?;
    let image = DynamicImage::from_decoder(decoder).map_err(|e| format!("cannot decode the image: {e}"))?;
    convert(image, decode)
}

/// The decoded image as linear `f32` RGB.
fn convert(image: DynamicImage, decode: Decode) -> Result<Bitmap, String> {
    let (w, h) = (image.width() as usize, image.height() as usize);
    let table8 = || table(8, decode);
    let table16 = || table(16, decode);
    let grey = |t: &[f32], v: usize| [t[v]; 3];
    let rgb = |t: &[f32], p: &[u16]| [t[p[0] as usize], t[p[1] as usize], t[p[2] as usize]];
    let pixels: Vec<[f32; 3]> = match &image {
        DynamicImage::ImageLuma8(i) => {
            let t = table8();
            i.pixels().map(|p| grey(&t, p.0[0] as usize)).collect()
        }
        DynamicImage::ImageLumaA8(i) => {
            let t = table8();
            i.pixels().map(|p| grey(&t, p.0[0] as usize)).collect()
        }
        DynamicImage::ImageRgb8(i) => {
            let t = table8();
            i.pixels().map(|p| rgb(&t, &p.0.map(u16::from))).collect()
        }
        DynamicImage::ImageRgba8(i) => {
            let t = table8();
            i.pixels().map(|p| rgb(&t, &p.0.map(u16::from))).collect()
        }
        DynamicImage::ImageLuma16(i) => {
            let t = table16();
            i.pixels().map(|p| grey(&t, p.0[0] as usize)).collect()
        }
        DynamicImage::ImageLumaA16(i) => {
            let t = table16();
            i.pixels().map(|p| grey(&t, p.0[0] as usize)).collect()
        }
        DynamicImage::ImageRgb16(i) => {
            let t = table16();
            i.pixels().map(|p| rgb(&t, &p.0)).collect()
        }
        DynamicImage::ImageRgba16(i) => {
            let t = table16();
            i.pixels().map(|p| rgb(&t, &p.0)).collect()
        }
        // Float images are linear already (Mitsuba 3 reads HDR and EXR so).
        DynamicImage::ImageRgb32F(i) => i.pixels().map(|p| p.0).collect(),
        DynamicImage::ImageRgba32F(i) => i.pixels().map(|p| [p.0[0], p.0[1], p.0[2]]).collect(),
        other => return Err(format!("unsupported pixel format {:?}", other.color())),
    };
    drop(image);
    Bitmap::checked(w, h, pixels)
}

/// The linear value of each stored integer of `bits` bits: `q/(2ⁿ − 1)`, sRGB-decoded
/// for [`Decode::Color`]. Each entry is the exact value in `f64` rounded once to `f32`.
fn table(bits: u32, decode: Decode) -> Vec<f32> {
    let top = f64::from((1u32 << bits) - 1);
    (0..=(1u32 << bits) - 1)
        .map(|q| {
            let c = f64::from(q) / top;
            (match decode {
                Decode::Color => srgb_to_linear(c),
                Decode::Raw => c,
            }) as f32
        })
        .collect()
}

/// An OpenEXR file: its size checked from the header first, then the first layer with
/// RGB channels at full resolution (linear, whatever `raw` says).
fn load_exr(path: &Path) -> Result<Bitmap, String> {
    use ::exr::prelude::{ReadChannels, ReadLayers};
    let meta = ::exr::meta::MetaData::read_from_file(path, false)
        .map_err(|e| format!("cannot read the OpenEXR header: {e}"))?;
    for header in &meta.headers {
        let size = header.layer_size;
        check_size(size.width(), size.height())?;
    }
    // The pixels with the row length, so the setter can place each one.
    type Rows = (usize, Vec<[f32; 3]>);
    let image = ::exr::prelude::read()
        .no_deep_data()
        .largest_resolution_level()
        .rgba_channels(
            |size, _| -> Rows { (size.width(), vec![[0.0f32; 3]; size.width() * size.height()]) },
            |(width, pixels): &mut Rows, ::exr::math::Vec2(x, y), (r, g, b, _): (f32, f32, f32, f32)| {
                pixels[y * *width + x] = [r, g, b];
            },
        )
        .first_valid_layer()
        .all_attributes()
        .from_file(path)
        .map_err(|e| format!("cannot read the OpenEXR image: {e}"))?;
    let size = image.layer_data.size;
    let (_, pixels) = image.layer_data.channel_data.pixels;
    Bitmap::checked(size.width(), size.height(), pixels)
}
