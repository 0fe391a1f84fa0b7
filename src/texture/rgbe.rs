//! Radiance HDR (`.hdr`, RGBE) files, as Greg Ward's Radiance writes them: a text header,
//! a resolution line, then scanlines of four bytes a pixel, flat or run-length encoded.
//!
//! A pixel is three 8-bit mantissas sharing one exponent byte `e`: each channel is
//! `c · 2^(e − 136)`, and `e = 0` is black. Every such value is exact in `f32` (`c < 2⁸` and
//! `e − 136 ≥ −135`, above `f32`'s smallest subnormal exponent, −149).

use super::bitmap::check_size;
use std::io::{BufRead, Read};

/// The longest header line read: a line of the header is a few words.
const MAX_LINE: u64 = 4096;

/// The pixels of the Radiance HDR file in `reader`, with its width and height, or why not.
/// The size is checked from the resolution line, before any pixel is read.
pub(super) fn read(mut reader: impl BufRead) -> Result<(usize, usize, Vec<[f32; 3]>), String> {
    let (width, height) = header(&mut reader)?;
    check_size(width, height)?;
    let mut pixels = Vec::with_capacity(width * height);
    let mut scanline = vec![[0u8; 4]; width];
    for _ in 0..height {
        read_scanline(&mut reader, &mut scanline)?;
        pixels.extend(scanline.iter().map(|&p| radiance(p)));
    }
    Ok((width, height, pixels))
}

/// The value of an RGBE pixel: `c · 2^(e − 136)` a channel, exact in `f32`.
fn radiance([r, g, b, e]: [u8; 4]) -> [f32; 3] {
    if e == 0 {
        return [0.0; 3];
    }
    // 2^(e − 136) built from its bits, as an f64 (whose exponent covers −135..=119);
    // the product with an 8-bit mantissa is exact there, and so is its rounding to f32.
    let scale = f64::from_bits(((i64::from(e) - 136 + 1023) as u64) << 52);
    [r, g, b].map(|c| (f64::from(c) * scale) as f32)
}

/// The header up to and including the resolution line: the width and the height.
fn header(reader: &mut impl BufRead) -> Result<(usize, usize), String> {
    let first = line(reader)?;
    if !first.starts_with("#?") {
        return Err("not a Radiance HDR file: it does not start with `#?`".into());
    }
    loop {
        let line = line(reader)?;
        if line.is_empty() {
            break;
        }
        if let Some(format) = line.strip_prefix("FORMAT=")
            && format.trim() != "32-bit_rle_rgbe"
        {
            return Err(format!(
                "the Radiance HDR format `{}` is not read: only `32-bit_rle_rgbe`",
                format.trim()
            ));
        }
    }
    let resolution = line(reader)?;
    match resolution.split_whitespace().collect::<Vec<_>>()[..] {
        ["-Y", h, "+X", w] => match (h.parse(), w.parse()) {
            (Ok(h), Ok(w)) => Ok((w, h)),
            _ => Err(format!(
                "the Radiance HDR resolution line `{resolution}` is not two sizes"
            )),
        },
        _ => Err(format!(
            "the Radiance HDR resolution line `{resolution}` is not `-Y height +X width` \
             (the only orientation read)"
        )),
    }
}

/// One header line, without its line feed; at most [`MAX_LINE`] bytes.
fn line(reader: &mut impl BufRead) -> Result<String, String> {
    let mut bytes = Vec::new();
    reader
        .take(MAX_LINE)
        .read_until(b'\n', &mut bytes)
        .map_err(|e| format!("cannot read the Radiance HDR header: {e}"))?;
    if bytes.pop() != Some(b'\n') {
        return Err("the Radiance HDR header ends early or has a line too long".into());
    }
    String::from_utf8(bytes).map_err(|_| "the Radiance HDR header is not text".into())
}

/// One scanline into `out`: run-length encoded by channel (the form Radiance writes for
/// widths 8 to 32767), or flat pixels with the older runs of repeated pixels.
fn read_scanline(reader: &mut impl Read, out: &mut [[u8; 4]]) -> Result<(), String> {
    let width = out.len();
    let first = pixel(reader)?;
    let encoded = usize::from(first[2]) << 8 | usize::from(first[3]);
    if first[..2] == [2, 2] && first[2] & 0x80 == 0 && (8..0x8000).contains(&width) {
        if encoded != width {
            return Err(format!(
                "a Radiance HDR scanline is {encoded} pixels wide, not {width}"
            ));
        }
        for channel in 0..4 {
            read_channel(reader, out, channel)?;
        }
        return Ok(());
    }
    // Flat pixels; (1, 1, 1, n) repeats the pixel before it n times, and each marker that
    // follows another one shifts its count up by eight more bits.
    let (mut x, mut shift) = (0, 0u32);
    let mut next = Some(first);
    while x < width {
        let p = match next.take() {
            Some(p) => p,
            None => pixel(reader)?,
        };
        if p[..3] == [1, 1, 1] {
            let previous = match x {
                0 => return Err("a Radiance HDR scanline starts with a run".into()),
                _ => out[x - 1],
            };
            let run = usize::from(p[3]).checked_shl(shift).filter(|&n| n <= width - x);
            let run = run.ok_or("a Radiance HDR run goes past the end of its scanline")?;
            out[x..x + run].fill(previous);
            x += run;
            shift += 8;
        } else {
            out[x] = p;
            x += 1;
            shift = 0;
        }
    }
    Ok(())
}

/// One channel of a run-length encoded scanline: a count byte above 128 is a run of one
/// value repeated (count − 128) times, any other a count of literal values that follow.
fn read_channel(reader: &mut impl Read, out: &mut [[u8; 4]], channel: usize) -> Result<(), String> {
    let mut x = 0;
    while x < out.len() {
        let count = byte(reader)?;
        let (n, run) = match count {
            0 => return Err("a Radiance HDR scanline has an empty run".into()),
            129.. => (usize::from(count - 128), true),
            _ => (usize::from(count), false),
        };
        if n > out.len() - x {
            return Err("a Radiance HDR run goes past the end of its scanline".into());
        }
        let value = if run { byte(reader)? } else { 0 };
        for p in &mut out[x..x + n] {
            p[channel] = if run { value } else { byte(reader)? };
        }
        x += n;
    }
    Ok(())
}

/// The next four bytes.
fn pixel(reader: &mut impl Read) -> Result<[u8; 4], String> {
    let mut p = [0; 4];
    reader.read_exact(&mut p).map_err(truncated)?;
    Ok(p)
}

/// The next byte.
fn byte(reader: &mut impl Read) -> Result<u8, String> {
    let mut b = [0; 1];
    reader.read_exact(&mut b).map_err(truncated)?;
    Ok(b[0])
}

/// The message for a file that ends inside its pixels.
fn truncated(e: std::io::Error) -> String {
    format!("cannot decode the Radiance HDR pixels: {e}")
}

#[cfg(test)]
mod tests;
