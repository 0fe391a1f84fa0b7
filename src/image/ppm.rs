//! The specification's output format: plain (ASCII) PPM, `P3`, 16-bit.
//!
//! ```text
//! P3
//! nx ny
//! 65535
//! R G B        ← one pixel per line, from the top-left, row by row
//! ```

use super::{Image16, check_size, write_atomic};
use crate::error::{Error, Result};
use std::io::{self, Write};
use std::path::Path;

/// Writes `image` as the spec's plain PPM, atomically (see [`write_atomic`]).
pub fn write_ppm(path: &Path, image: &Image16) -> Result<()> {
    write_atomic(path, |out| write_ppm_to(out, image))
}

/// Writes `image` as plain PPM to any writer: the header `P3`, `nx ny`, the maximum
/// value, then one `R G B` line per pixel. Buffer the writer: there is one line per pixel.
pub fn write_ppm_to(out: &mut impl Write, image: &Image16) -> io::Result<()> {
    write!(out, "P3\n{} {}\n{}\n", image.width, image.height, image.max_value)?;
    let mut line = Vec::with_capacity(24);
    for rgb in image.samples.chunks_exact(3) {
        line.clear();
        for (k, &s) in rgb.iter().enumerate() {
            if k > 0 {
                line.push(b' ');
            }
            push_decimal(&mut line, s);
        }
        line.push(b'\n');
        out.write_all(&line)?;
    }
    Ok(())
}

/// Appends the decimal digits of `v` (the formatter machinery is the slow part of
/// writing 320 000 lines).
fn push_decimal(buf: &mut Vec<u8>, v: u16) {
    let mut digits = [0u8; 5];
    let mut n = v;
    let mut i = digits.len();
    loop {
        i -= 1;
        digits[i] = b'0' + (n % 10) as u8;
        n /= 10;
        if n == 0 {
            break;
        }
    }
    buf.extend_from_slice(&digits[i..]);
}

/// Reads a plain PPM (`P3`) file.
pub fn read_ppm(path: &Path) -> Result<Image16> {
    let bytes = std::fs::read(path).map_err(|source| Error::Io {
        path: path.to_path_buf(),
        source,
    })?;
    parse_ppm(&bytes)
}

/// Parses a plain PPM (`P3`): magic, width, height, maximum value (1‥65535), then
/// `3·width·height` samples, each at most the maximum; `#` comments and any whitespace
/// between tokens, as Netpbm allows. Errors name the line.
///
/// Never panics, and never allocates from the header alone: a header declaring more
/// samples than the remaining bytes could hold (each needs a digit and a separator)
/// is rejected before any buffer is made.
pub fn parse_ppm(bytes: &[u8]) -> Result<Image16> {
    let mut tok = Tokens {
        bytes,
        pos: 0,
        line: 1,
    };
    match tok.next() {
        Some((b"P3", _)) => {}
        Some((m, line)) => {
            return Err(Error::Ppm(format!(
                "line {line}: expected magic number P3, found {:?}",
                String::from_utf8_lossy(&m[..m.len().min(16)])
            )));
        }
        None => return Err(Error::Ppm("empty file".into())),
    }
    let width = tok.number("width", u64::MAX)?;
    let height = tok.number("height", u64::MAX)?;
    let max_value = tok.number("maximum value", 65535)?;
    if max_value == 0 {
        return Err(Error::Ppm(
            "maximum value must be between 1 and 65535, got 0".into(),
        ));
    }
    let (width, height) = match (usize::try_from(width), usize::try_from(height)) {
        (Ok(w), Ok(h)) if check_size(w, h).is_ok() => (w, h),
        _ => return Err(Error::Ppm(format!("impossible image size {width}×{height}"))),
    };
    let count = 3 * width * height;
    let remaining = bytes.len() - tok.pos;
    if count > remaining / 2 + 1 {
        return Err(Error::Ppm(format!(
            "header declares {width}×{height} pixels ({count} samples) but only {remaining} bytes follow"
        )));
    }
    let mut samples = Vec::with_capacity(count);
    for k in 0..count {
        let what = ["red", "green", "blue"][k % 3];
        let s = tok.number(what, max_value)?;
        samples.push(s as u16);
    }
    if let Some((extra, line)) = tok.next() {
        return Err(Error::Ppm(format!(
            "line {line}: unexpected data after {count} samples: {:?}",
            String::from_utf8_lossy(&extra[..extra.len().min(16)])
        )));
    }
    Ok(Image16 {
        width,
        height,
        max_value: max_value as u16,
        samples,
    })
}

/// Whitespace-separated tokens of a Netpbm file, skipping `#` comments.
struct Tokens<'a> {
    bytes: &'a [u8],
    pos: usize,
    line: usize,
}

impl<'a> Tokens<'a> {
    fn next(&mut self) -> Option<(&'a [u8], usize)> {
        loop {
            match self.bytes.get(self.pos)? {
                b'\n' => {
                    self.line += 1;
                    self.pos += 1;
                }
                b'#' => {
                    while self.bytes.get(self.pos).is_some_and(|&b| b != b'\n') {
                        self.pos += 1;
                    }
                }
                b if b.is_ascii_whitespace() => self.pos += 1,
                _ => break,
            }
        }
        let start = self.pos;
        while self
            .bytes
            .get(self.pos)
            .is_some_and(|&b| !b.is_ascii_whitespace() && b != b'#')
        {
            self.pos += 1;
        }
        Some((&self.bytes[start..self.pos], self.line))
    }

    /// The next token as a decimal integer in `0..=max`.
    fn number(&mut self, what: &str, max: u64) -> Result<u64> {
        let (t, line) = self
            .next()
            .ok_or_else(|| Error::Ppm(format!("file ends where the {what} was expected")))?;
        let text = String::from_utf8_lossy(&t[..t.len().min(24)]);
        if !t.iter().all(u8::is_ascii_digit) {
            return Err(Error::Ppm(format!(
                "line {line}: {what} is not a number: {text:?}"
            )));
        }
        let v = t.iter().try_fold(0u64, |acc, &d| {
            acc.checked_mul(10)?.checked_add(u64::from(d - b'0'))
        });
        match v {
            Some(v) if v <= max => Ok(v),
            _ => Err(Error::Ppm(format!("line {line}: {what} {text} exceeds {max}"))),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tiny() -> Image16 {
        Image16 {
            width: 2,
            height: 1,
            max_value: 65535,
            samples: vec![0, 1, 65535, 10, 200, 3000],
        }
    }

    #[test]
    fn writes_the_exact_format() {
        let mut out = Vec::new();
        write_ppm_to(&mut out, &tiny()).unwrap();
        assert_eq!(
            String::from_utf8(out).unwrap(),
            "P3\n2 1\n65535\n0 1 65535\n10 200 3000\n"
        );
    }

    #[test]
    fn round_trips() {
        let mut out = Vec::new();
        write_ppm_to(&mut out, &tiny()).unwrap();
        assert_eq!(parse_ppm(&out).unwrap(), tiny());
    }

    #[test]
    fn accepts_comments_and_free_whitespace() {
        let text = b"P3 # magic\n# size next\n2\t1 255\n0 1 2   3 4\r\n5\n";
        let img = parse_ppm(text).unwrap();
        assert_eq!((img.width, img.height, img.max_value), (2, 1, 255));
        assert_eq!(img.samples, vec![0, 1, 2, 3, 4, 5]);
    }

    #[test]
    fn rejects_malformed_input_with_a_reason() {
        let cases: [(&[u8], &str); 10] = [
            (b"", "empty"),
            (b"P6\n1 1\n255\n", "P3"),
            (b"P3\n1 1\n", "maximum value"),
            (b"P3\n1 1\n0\n0 0 0\n", "between 1 and 65535"),
            (b"P3\n1 1\n70000\n0 0 0\n", "exceeds 65535"),
            (b"P3\n1 1\n255\n0 256 0\n", "green 256 exceeds 255"),
            (b"P3\n1 1\n255\n0 x 0\n", "not a number"),
            (b"P3\n1 1\n255\n0 0 0 7\n", "unexpected data"),
            (b"P3\n0 1\n255\n", "impossible image size"),
            (b"P3\n100000 100000\n255\n0 0 0\n", "impossible image size"),
        ];
        for (bytes, want) in cases {
            let msg = parse_ppm(bytes).unwrap_err().to_string();
            assert!(msg.contains(want), "{:?}: {msg}", String::from_utf8_lossy(bytes));
        }
    }

    #[test]
    fn an_absurd_header_allocates_nothing() {
        let msg = parse_ppm(b"P3\n10000 10000\n65535\n1 2 3\n")
            .unwrap_err()
            .to_string();
        assert!(msg.contains("only"), "{msg}");
        let msg = parse_ppm(b"P3\n99999999999999999999 1\n255\n")
            .unwrap_err()
            .to_string();
        assert!(msg.contains("exceeds"), "{msg}");
    }
}
