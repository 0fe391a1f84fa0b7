//! Image files: each format read exactly where it is exact, sRGB decoded on known pixels,
//! and every bad file an `Error::Image` naming it, never a panic.

use crate::common::Scratch;
use rand::{RngExt, SeedableRng};
use raytrace::texture::{Bitmap, Decode};
use raytrace::{DefaultRng, Error, Image};
use std::path::Path;

/// The sRGB decoding curve, written out here as IEC 61966-2-1 gives it.
fn srgb(c: f64) -> f64 {
    if c <= 0.04045 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

/// The message of the `Error::Image` that loading `path` gives; its display names the file.
fn image_error(path: &Path) -> String {
    let e = Bitmap::load(path, Decode::Color).expect_err(&path.display().to_string());
    assert!(e.to_string().starts_with(&path.display().to_string()), "{e}");
    match e {
        Error::Image { path: named, message } => {
            assert_eq!(named, path);
            message
        }
        other => panic!("expected Error::Image, got {other:?}"),
    }
}

#[test]
fn an_8_bit_png_is_srgb_decoded_exactly_from_the_top_row_down() {
    let dir = Scratch::new("png8");
    let levels: [u8; 8] = [0, 1, 10, 11, 64, 128, 200, 255];
    // 4 × 2, each pixel three different levels; the top row first.
    let rgb: Vec<[u8; 3]> = (0..8)
        .map(|k| [levels[k], levels[(k + 3) % 8], levels[(k + 5) % 8]])
        .collect();
    let path = dir.png8("levels.png", 4, 2, &rgb);
    let colour = Bitmap::load(&path, Decode::Color).unwrap();
    let raw = Bitmap::load(&path, Decode::Raw).unwrap();
    assert_eq!((colour.width(), colour.height()), (4, 2));
    for (k, p) in rgb.iter().enumerate() {
        let want = p.map(|q| srgb(f64::from(q) / 255.0) as f32);
        assert_eq!(colour.pixels()[k], want, "pixel {k}");
        assert_eq!(
            raw.pixels()[k],
            p.map(|q| (f64::from(q) / 255.0) as f32),
            "pixel {k}"
        );
    }
    // A value known from the literature: 128 decodes to 0.2158605.
    assert!((f64::from(colour.pixels()[5][0]) - 0.215_860_5).abs() < 1e-7);
    assert_eq!(colour.pixels()[0][0], 0.0);
    assert_eq!(colour.pixels()[7][0], 1.0);
}

#[test]
fn a_16_bit_grey_png_fills_every_channel() {
    let dir = Scratch::new("png16");
    let levels: [u16; 4] = [0, 1000, 32768, 65535];
    let samples: Vec<u8> = levels.iter().flat_map(|q| q.to_be_bytes()).collect();
    let path = dir.png(
        "grey16.png",
        2,
        2,
        png::ColorType::Grayscale,
        png::BitDepth::Sixteen,
        &samples,
    );
    let colour = Bitmap::load(&path, Decode::Color).unwrap();
    let raw = Bitmap::load(&path, Decode::Raw).unwrap();
    assert!(colour.is_grey());
    for (k, q) in levels.iter().enumerate() {
        let c = f64::from(*q) / 65535.0;
        assert_eq!(colour.pixels()[k], [srgb(c) as f32; 3], "pixel {k}");
        assert_eq!(raw.pixels()[k], [c as f32; 3], "pixel {k}");
    }
}

#[test]
fn alpha_is_dropped_not_multiplied_in() {
    let dir = Scratch::new("rgba");
    let path = dir.png(
        "rgba.png",
        1,
        1,
        png::ColorType::Rgba,
        png::BitDepth::Eight,
        &[200, 100, 50, 0],
    );
    let b = Bitmap::load(&path, Decode::Raw).unwrap();
    assert_eq!(
        b.pixels()[0],
        [200.0 / 255.0, 100.0 / 255.0, 50.0 / 255.0].map(|c: f64| c as f32)
    );
}

#[test]
fn a_jpeg_is_srgb_decoded() {
    let dir = Scratch::new("jpeg");
    // A flat block of 128 is DC-only and zero after the level shift: exact in JPEG.
    let path = dir.jpeg("grey.jpg", 16, 16, &[128; 16 * 16 * 3]);
    let b = Bitmap::load(&path, Decode::Color).unwrap();
    let want = srgb(128.0 / 255.0) as f32;
    assert!(b.pixels().iter().all(|p| *p == [want; 3]), "{:?}", b.pixels()[0]);
    let raw = Bitmap::load(&path, Decode::Raw).unwrap();
    assert_eq!(raw.pixels()[0], [(128.0 / 255.0) as f32; 3]);
}

#[test]
fn float_images_are_linear_whatever_raw_says() {
    let dir = Scratch::new("float");
    // Radiance HDR: values its shared exponent holds exactly.
    let hdr_values = vec![
        [0.5, 1.0, 0.25],
        [2.0, 4.0, 1.0],
        [0.0, 0.0, 0.0],
        [8.0, 0.5, 2.0],
    ];
    let hdr = dir.hdr("values.hdr", 2, 2, &hdr_values);
    for decode in [Decode::Color, Decode::Raw] {
        assert_eq!(
            Bitmap::load(&hdr, decode).unwrap().pixels(),
            hdr_values.as_slice()
        );
    }
    // OpenEXR through the exr crate, as the renderer writes it: f32 as is.
    let exr_values = vec![[0.1, 3.5, 1e-3], [100.0, 0.0, 0.5], [0.7, 0.2, 12.25]];
    let exr = dir.path("values.exr");
    raytrace::image::write_exr(&exr, &Image::from_pixels(3, 1, exr_values.clone()).unwrap()).unwrap();
    for decode in [Decode::Color, Decode::Raw] {
        let b = Bitmap::load(&exr, decode).unwrap();
        assert_eq!((b.width(), b.height()), (3, 1));
        for (got, want) in b.pixels().iter().zip(&exr_values) {
            assert_eq!(*got, want.map(|c| c as f32));
        }
    }
    // A value no texture may hold.
    let nan = dir.path("nan.exr");
    let pixels = vec![[0.5; 3], [0.5; 3], [0.5, f64::NAN, 0.5]];
    raytrace::image::write_exr(&nan, &Image::from_pixels(1, 3, pixels).unwrap()).unwrap();
    let message = image_error(&nan);
    assert!(
        message.contains("pixel (0, 2)") && message.contains("finite"),
        "{message}"
    );
}

/// A PNG declaring `width × height` 8-bit RGB pixels and holding none: its signature, the
/// header chunk, an empty data chunk and the end chunk.
pub(super) fn png_header(width: u32, height: u32) -> Vec<u8> {
    let mut ihdr = Vec::new();
    ihdr.extend(width.to_be_bytes());
    ihdr.extend(height.to_be_bytes());
    ihdr.extend([8, 2, 0, 0, 0]);
    let mut png = b"\x89PNG\r\n\x1a\n".to_vec();
    for (name, data) in [(b"IHDR", ihdr), (b"IDAT", Vec::new()), (b"IEND", Vec::new())] {
        let mut chunk = name.to_vec();
        chunk.extend(&data);
        png.extend((data.len() as u32).to_be_bytes());
        png.extend(&chunk);
        png.extend(crc32(&chunk).to_be_bytes());
    }
    png
}

/// CRC-32 (ISO-HDLC), as PNG chunks carry it.
fn crc32(bytes: &[u8]) -> u32 {
    let mut crc = !0u32;
    for &b in bytes {
        crc ^= u32::from(b);
        for _ in 0..8 {
            crc = if crc & 1 == 1 {
                (crc >> 1) ^ 0xEDB8_8320
            } else {
                crc >> 1
            };
        }
    }
    !crc
}

#[test]
fn an_image_too_large_for_memory_is_refused_from_its_header() {
    let dir = Scratch::new("large");
    // 20000 × 20000 = 4·10⁸ pixels, past 2²⁸; no pixel data follows.
    let png = dir.file("huge.png", png_header(20_000, 20_000));
    let hdr = dir.file(
        "huge.hdr",
        "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 70000 +X 70000\n",
    );
    for path in [png, hdr] {
        let message = image_error(&path);
        assert!(
            message.contains("too large for memory") && message.contains("268435456"),
            "{message}"
        );
    }
    // Just inside the bound the header passes, and the missing data is the error.
    let message = image_error(&dir.file("tall.png", png_header(1, 1 << 20)));
    assert!(!message.contains("too large"), "{message}");
}

#[test]
fn bad_files_are_errors_naming_the_file() {
    let dir = Scratch::new("bad");
    let good = dir.png8("good.png", 2, 2, &[[1, 2, 3]; 4]);
    let bytes = std::fs::read(&good).unwrap();
    let cases = [
        (dir.path("missing.png"), "cannot open the image"),
        (dir.0.clone(), "a folder"),
        (dir.file("empty.png", b""), "not an image of a known format"),
        (
            dir.file("text.png", "hello, world"),
            "not an image of a known format",
        ),
        (dir.file("cut.png", &bytes[..bytes.len() / 2]), "cannot decode"),
        (
            dir.file("anim.gif", b"GIF89a\x01\x00\x01\x00\x00\x00\x00;"),
            "not an image of a known format",
        ),
        (
            dir.file("garbage.exr", [0x76, 0x2f, 0x31, 0x01, 9, 9, 9, 9]),
            "cannot read the OpenEXR header",
        ),
    ];
    for (path, words) in cases {
        let message = image_error(&path);
        assert!(message.contains(words), "{}: {message}", path.display());
    }
    #[cfg(unix)]
    assert!(image_error(Path::new("/dev/null")).contains("a device"));
}

#[test]
fn no_damaged_file_makes_the_reader_panic() {
    let dir = Scratch::new("damaged");
    let png = std::fs::read(dir.png8("a.png", 3, 2, &[[9, 200, 77]; 6])).unwrap();
    let gradient: Vec<u8> = (0..64)
        .flat_map(|k| [(k % 8) as u8 * 30, (k / 8) as u8 * 30, 7])
        .collect();
    let jpeg_path = dir.jpeg("a.jpg", 8, 8, &gradient);
    let hdr_path = dir.hdr("a.hdr", 2, 1, &[[0.5, 1.0, 2.0], [3.0, 0.125, 0.0]]);
    let exr_path = dir.path("a.exr");
    raytrace::image::write_exr(&exr_path, &Image::from_pixels(2, 2, vec![[0.25; 3]; 4]).unwrap()).unwrap();
    let originals = [
        png,
        std::fs::read(&jpeg_path).unwrap(),
        std::fs::read(&hdr_path).unwrap(),
        std::fs::read(&exr_path).unwrap(),
    ];
    let mut rng = DefaultRng::seed_from_u64(32);
    let (mut loaded, mut refused) = (0, 0);
    for round in 0..240 {
        let mut bytes = originals[round % originals.len()].clone();
        // Change up to four bytes past the magic number, or cut the file short.
        if rng.random_bool(0.25) {
            bytes.truncate(rng.random_range(4..bytes.len()));
        } else {
            for _ in 0..rng.random_range(1..=4) {
                let at = rng.random_range(4..bytes.len());
                bytes[at] = rng.random();
            }
        }
        let path = dir.file(&format!("damaged{round}"), &bytes);
        match Bitmap::load(&path, Decode::Color) {
            Ok(b) => {
                assert!(b.pixels().iter().flatten().all(|c| c.is_finite()));
                loaded += 1;
            }
            Err(Error::Image { .. }) => refused += 1,
            Err(other) => panic!("{other:?}"),
        }
    }
    // Both outcomes happen: the damage is neither always harmless nor always fatal.
    assert!(loaded > 0 && refused > 0, "{loaded} loaded, {refused} refused");
}
