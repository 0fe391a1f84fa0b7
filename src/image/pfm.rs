//! Portable FloatMap (PFM): linear colour as 32-bit floats, values above 1 kept.
//!
//! ```text
//! PF           ← colour ("Pf" is greyscale, read but never written)
//! width height
//! -1.0         ← scale: negative means little-endian samples
//! R G B …      ← f32 per channel, rows from the BOTTOM up, left to right
//! ```
//!
//! Each header line ends in one whitespace byte (a newline here); the samples follow it.

use super::{Image, check_size, to_finite_f32, write_atomic};
use crate::error::{Error, Result};
use std::io::{self, Write};
use std::path::Path;

/// Writes `image` as a colour PFM, atomically (see [`write_atomic`]); as [`write_pfm_to`].
pub fn write_pfm(path: &Path, image: &Image) -> Result<()> {
    write_atomic(path, |out| write_pfm_to(out, image))
}

/// Writes `image` as a colour PFM into `out`: little-endian (scale `-1.0`), rows bottom
/// to top as the format requires.
///
/// # Precision
/// Each channel is rounded to the nearest `f32`; a finite value beyond `f32`'s range is
/// clamped to the largest finite `f32` ([`to_finite_f32`]), never written as infinity.
///
/// # Errors
/// A failure to write.
pub fn write_pfm_to(out: &mut impl Write, image: &Image) -> io::Result<()> {
    write!(out, "PF\n{} {}\n-1.0\n", image.width(), image.height())?;
    let mut row = Vec::with_capacity(12 * image.width());
    for line in image.pixels().chunks_exact(image.width()).rev() {
        row.clear();
        for &c in line.iter().flatten() {
            row.extend_from_slice(&to_finite_f32(c).to_le_bytes());
        }
        out.write_all(&row)?;
    }
    Ok(())
}

/// Reads a PFM file (see [`parse_pfm`]).
pub fn read_pfm(path: &Path) -> Result<Image> {
    let bytes = std::fs::read(path).map_err(|source| Error::Io {
        path: path.to_path_buf(),
        source,
    })?;
    parse_pfm(&bytes)
}

/// Parses a PFM: `PF` (colour) or `Pf` (greyscale, each value copied to R, G and B),
/// width, height, a finite non-zero scale whose sign gives the byte order, then exactly
/// `channels × width × height` floats, rows bottom to top. The scale's magnitude is not
/// applied: it carries no agreed meaning for linear renders.
///
/// Never panics, and checks the data's length against the header before allocating.
pub fn parse_pfm(bytes: &[u8]) -> Result<Image> {
    let mut pos = 0;
    let channels = match token(bytes, &mut pos, "magic number")? {
        b"PF" => 3,
        b"Pf" => 1,
        m => {
            return Err(Error::Pfm(format!(
                "expected magic number PF or Pf, found {:?}",
                String::from_utf8_lossy(&m[..m.len().min(16)])
            )));
        }
    };
    let width = number(token(bytes, &mut pos, "width")?, "width")?;
    let height = number(token(bytes, &mut pos, "height")?, "height")?;
    let scale = token(bytes, &mut pos, "scale")?;
    let scale: f32 = std::str::from_utf8(scale)
        .ok()
        .and_then(|s| s.parse().ok())
        .filter(|s: &f32| s.is_finite() && *s != 0.0)
        .ok_or_else(|| {
            Error::Pfm(format!(
                "scale must be a finite non-zero number, found {:?}",
                String::from_utf8_lossy(&scale[..scale.len().min(24)])
            ))
        })?;
    // Exactly one whitespace byte separates the header from the samples.
    match bytes.get(pos) {
        Some(b) if b.is_ascii_whitespace() => pos += 1,
        _ => return Err(Error::Pfm("no whitespace after the scale".into())),
    }
    if check_size(width, height).is_err() {
        return Err(Error::Pfm(format!("impossible image size {width}×{height}")));
    }
    let data = &bytes[pos..];
    let expected = 4 * channels * width * height;
    if data.len() != expected {
        let how = if data.len() < expected {
            "truncated"
        } else {
            "trailing bytes"
        };
        return Err(Error::Pfm(format!(
            "{how}: a {width}×{height} image with {channels} channel(s) needs {expected} \
             bytes of samples, found {}",
            data.len()
        )));
    }
    let sample = |b: &[u8]| {
        let b = [b[0], b[1], b[2], b[3]];
        f64::from(if scale < 0.0 {
            f32::from_le_bytes(b)
        } else {
            f32::from_be_bytes(b)
        })
    };
    let mut pixels = Vec::with_capacity(width * height);
    for row in data.chunks_exact(4 * channels * width).rev() {
        pixels.extend(row.chunks_exact(4 * channels).map(|p| match channels {
            1 => [sample(p); 3],
            _ => [sample(&p[0..4]), sample(&p[4..8]), sample(&p[8..12])],
        }));
    }
    Image::from_pixels(width, height, pixels)
        .ok_or_else(|| Error::Pfm("pixel count does not match the size".into()))
}

/// The next whitespace-delimited header token, after skipping whitespace.
fn token<'a>(bytes: &'a [u8], pos: &mut usize, what: &str) -> Result<&'a [u8]> {
    while bytes.get(*pos).is_some_and(u8::is_ascii_whitespace) {
        *pos += 1;
    }
    let start = *pos;
    // A header token is short; stop early so binary garbage is not scanned to the end.
    while bytes.get(*pos).is_some_and(|b| !b.is_ascii_whitespace()) && *pos - start < 64 {
        *pos += 1;
    }
    if start == *pos {
        return Err(Error::Pfm(format!("file ends where the {what} was expected")));
    }
    Ok(&bytes[start..*pos])
}

/// A header token as a decimal size.
fn number(t: &[u8], what: &str) -> Result<usize> {
    std::str::from_utf8(t)
        .ok()
        .filter(|s| s.bytes().all(|b| b.is_ascii_digit()))
        .and_then(|s| s.parse().ok())
        .ok_or_else(|| {
            Error::Pfm(format!(
                "{what} is not a size: {:?}",
                String::from_utf8_lossy(&t[..t.len().min(24)])
            ))
        })
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;
    use proptest::test_runner::{FileFailurePersistence, RngSeed};

    fn temp_path(name: &str) -> std::path::PathBuf {
        std::env::temp_dir().join(format!("raytrace-pfm-{}-{name}", std::process::id()))
    }

    #[test]
    fn writes_the_exact_format_bottom_row_first() {
        let image = Image::from_pixels(1, 2, vec![[1.0, 2.0, 3.0], [4.0, 5.5, 100.0]]).unwrap();
        let path = temp_path("exact.pfm");
        write_pfm(&path, &image).unwrap();
        let bytes = std::fs::read(&path).unwrap();
        let mut want = b"PF\n1 2\n-1.0\n".to_vec();
        for v in [4.0f32, 5.5, 100.0, 1.0, 2.0, 3.0] {
            want.extend_from_slice(&v.to_le_bytes());
        }
        assert_eq!(bytes, want);
        assert_eq!(read_pfm(&path).unwrap(), image);
        std::fs::remove_file(path).unwrap();
    }

    #[test]
    fn very_bright_values_are_clamped_never_infinite() {
        let big = f64::from(f32::MAX);
        let image =
            Image::from_pixels(2, 1, vec![[1e300, 1e41, big * 1.000_000_1], [big, 1.0, 0.0]]).unwrap();
        let mut bytes = Vec::new();
        write_pfm_to(&mut bytes, &image).unwrap();
        let read = parse_pfm(&bytes).unwrap();
        assert_eq!(read.pixels(), &[[big; 3], [big, 1.0, 0.0]]);
    }

    #[test]
    fn reads_big_endian_and_greyscale() {
        let mut bytes = b"Pf\n2 1\n1.0\n".to_vec();
        for v in [0.25f32, 7.0] {
            bytes.extend_from_slice(&v.to_be_bytes());
        }
        let image = parse_pfm(&bytes).unwrap();
        assert_eq!(image.pixels(), &[[0.25; 3], [7.0; 3]]);
    }

    #[test]
    fn rejects_malformed_input_with_a_reason() {
        let cases: [(&[u8], &str); 8] = [
            (b"", "magic number was expected"),
            (b"P6\n1 1\n-1.0\n", "PF or Pf"),
            (b"PF\n1 x\n-1.0\n", "height is not a size"),
            (b"PF\n1 1\n0\n", "non-zero"),
            (b"PF\n1 1\nnan\n", "finite"),
            (b"PF\n0 1\n-1.0\n", "impossible image size"),
            (b"PF\n1 1\n-1.0\n\0\0\0\0", "truncated"),
            (b"PF\n1 1\n-1.0\n0123456789abc", "trailing bytes"),
        ];
        for (bytes, want) in cases {
            let msg = parse_pfm(bytes).unwrap_err().to_string();
            assert!(msg.contains(want), "{:?}: {msg}", String::from_utf8_lossy(bytes));
        }
    }

    proptest! {
        // Seeded, so every run tries the same inputs; failures are kept for re-running.
        #![proptest_config(ProptestConfig {
            cases: 1000,
            rng_seed: RngSeed::Fixed(0x9f3),
            failure_persistence: Some(Box::new(FileFailurePersistence::Direct("proptest-regressions/image_pfm.txt"))),
            ..ProptestConfig::default()
        })]
        #[test]
        fn never_panics(bytes in proptest::collection::vec(any::<u8>(), 0..256)) {
            let _ = parse_pfm(&bytes);
        }

        #[test]
        fn never_panics_after_a_valid_header(
            w in 0usize..5, h in 0usize..5, data in proptest::collection::vec(any::<u8>(), 0..200)
        ) {
            let mut bytes = format!("PF\n{w} {h}\n-1.0\n").into_bytes();
            bytes.extend(data);
            let _ = parse_pfm(&bytes);
        }
    }
}
