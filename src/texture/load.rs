//! Reading image files into a [`Bitmap`]: PNG through the `png` crate, JPEG through
//! `zune-jpeg`, Radiance HDR by [`super::rgbe`], OpenEXR through the `exr` crate. The
//! format is told by the file's first bytes and the size is checked from the header, before
//! any pixel is decoded; every failure is a message about the file, never a panic.

use super::bitmap::{Bitmap, Decode, MAX_TEXTURE_PIXELS, check_size, srgb_to_linear};
use super::rgbe;
use std::fs::File;
use std::io::{BufRead, BufReader, Cursor, Seek};
use std::path::Path;
use zune_core::{colorspace::ColorSpace, options::DecoderOptions};

/// The first four bytes of every OpenEXR file.
const EXR_MAGIC: [u8; 4] = [0x76, 0x2f, 0x31, 0x01];

/// The formats read, by the bytes each file starts with.
enum Format {
    Png,
    Jpeg,
    Hdr,
}

impl Format {
    /// The format of a file that starts with `magic`, if it is one read here.
    fn of(magic: &[u8]) -> Option<Self> {
        match magic {
            [0x89, b'P', b'N', b'G', ..] => Some(Self::Png),
            [0xff, 0xd8, 0xff, ..] => Some(Self::Jpeg),
            [b'#', b'?', ..] => Some(Self::Hdr),
            _ => None,
        }
    }
}

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
    let file = File::open(path).map_err(|e| format!("cannot open the image: {e}"))?;
    let mut reader = BufReader::new(file);
    let magic = reader
        .fill_buf()
        .map_err(|e| format!("cannot read the image: {e}"))?;
    if magic.starts_with(&EXR_MAGIC) {
        load_exr(path)
    } else {
        decode_reader(reader, decode)
    }
}

/// The bitmap of an encoded image held in memory (a glTF file's embedded PNG or JPEG),
/// or why not: PNG, JPEG or Radiance HDR, its format told by its first bytes.
pub(super) fn decode_bytes(bytes: &[u8], decode: Decode) -> Result<Bitmap, String> {
    decode_reader(Cursor::new(bytes), decode)
}

/// A PNG, JPEG or Radiance HDR image read from `reader`, its format told by its first
/// bytes (a buffered reader holds at least four unless the file is shorter).
fn decode_reader(mut reader: impl BufRead + Seek, decode: Decode) -> Result<Bitmap, String> {
    let magic = reader
        .fill_buf()
        .map_err(|e| format!("cannot read the image: {e}"))?;
    let (width, height, pixels) = match Format::of(magic) {
        Some(Format::Png) => png(reader, decode)?,
        Some(Format::Jpeg) => jpeg(reader, decode)?,
        // Float images are linear already (Mitsuba 3 reads HDR and EXR so).
        Some(Format::Hdr) => rgbe::read(reader)?,
        None => {
            return Err(
                "not an image of a known format: a texture is a PNG, JPEG, Radiance HDR \
                        (.hdr) or OpenEXR file"
                    .into(),
            );
        }
    };
    Bitmap::checked(width, height, pixels)
}

/// The width, height and linear pixels of an image.
type Pixels = (usize, usize, Vec<[f32; 3]>);

/// A PNG file: palettes and bit depths below 8 expanded to 8-bit samples, 16-bit kept.
fn png(reader: impl BufRead + Seek, decode: Decode) -> Result<Pixels, String> {
    let failed = |e: png::DecodingError| format!("cannot decode the image: {e}");
    let mut decoder = png::Decoder::new(reader);
    decoder.set_transformations(png::Transformations::EXPAND);
    // The decoder's own allocation bound, behind the size check below: the largest decoded
    // buffer, 16-bit RGBA, at the largest size.
    decoder.set_limits(png::Limits {
        bytes: MAX_TEXTURE_PIXELS * 8,
    });
    let mut reader = decoder.read_info().map_err(failed)?;
    let (w, h) = reader.info().size();
    let (width, height) = (w as usize, h as usize);
    check_size(width, height)?;
    let size = reader
        .output_buffer_size()
        .ok_or("the image is too large for memory")?;
    let mut buf = vec![0; size];
    let frame = reader.next_frame(&mut buf).map_err(failed)?;
    buf.truncate(frame.buffer_size());
    let channels = frame.color_type.samples();
    let pixels = match frame.bit_depth {
        png::BitDepth::Sixteen => {
            let samples: Vec<u16> = buf
                .chunks_exact(2)
                .map(|b| u16::from_be_bytes([b[0], b[1]]))
                .collect();
            linear(&samples, channels, &table(16, decode))
        }
        _ => linear(&buf, channels, &table(8, decode)),
    };
    Ok((width, height, pixels))
}

/// A JPEG file, decoded to 8-bit RGB (a grey image's one channel copied to all three).
fn jpeg(reader: impl BufRead + Seek, decode: Decode) -> Result<Pixels, String> {
    let failed = |e: zune_jpeg::errors::DecodeErrors| format!("cannot decode the image: {e}");
    // The size is bounded by `check_size`, not by the decoder's own default limits.
    let options = DecoderOptions::default()
        .set_strict_mode(false)
        .set_max_width(usize::MAX)
        .set_max_height(usize::MAX)
        .jpeg_set_out_colorspace(ColorSpace::RGB);
    let mut decoder = zune_jpeg::JpegDecoder::new_with_options(reader, options);
    decoder.decode_headers().map_err(failed)?;
    let (width, height) = decoder
        .dimensions()
        .ok_or("cannot decode the image: no frame header")?;
    check_size(width, height)?;
    let samples = decoder.decode().map_err(failed)?;
    if samples.len() != width * height * 3 {
        return Err("cannot decode the image: the JPEG decoder gave too few samples".into());
    }
    Ok((width, height, linear(&samples, 3, &table(8, decode))))
}

/// Integer samples, `channels` a pixel (grey, grey and alpha, RGB or RGBA), as linear RGB
/// through `table`; alpha is dropped, not multiplied in.
fn linear<T: Copy + Into<usize>>(samples: &[T], channels: usize, table: &[f32]) -> Vec<[f32; 3]> {
    let t = |v: T| table[v.into()];
    samples
        .chunks_exact(channels)
        .map(|p| match p {
            [v] | [v, _] => [t(*v); 3],
            [r, g, b, ..] => [t(*r), t(*g), t(*b)],
            [] => unreachable!("chunks_exact gives no empty chunk"),
        })
        .collect()
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
