//! Tile files (`.rtile`): one part of a render split across processes, stored exactly,
//! so that [`merge_tiles`] gives the bits of the whole render.
//!
//! The format is documented on [`TileHeader`], where the public docs show it.

mod merge;

pub use merge::merge_tiles;

use super::{Image, Rect, check_size, write_atomic};
use crate::error::{Error, Result};
use std::io::{self, Write};
use std::path::Path;

/// The first line of every tile file.
const MAGIC: &str = "raytrace-tile 2";

/// What a tile file says about its tile: which render it belongs to and where it goes.
///
/// A tile file is a text header, an empty line, then the data:
///
/// ```text
/// raytrace-tile 2
/// scene = 9f3c0a4e5d7b2e11
/// settings = spp=16 max_depth=10 seed=0 precision=f32
/// image = 640 480
/// rect = 0 120 640 120
/// pixels = 5d3ab2c0e1f49a07
///
/// <the tile's linear pixels: R G B as f64 little-endian, row by row from its top-left>
/// ```
///
/// - The first line is the magic `raytrace-tile` and the format's version, `2` (version
///   1 had no `pixels` key; it is refused).
/// - Then one `key = value` line for each of the five keys, in any order, each once:
///   the value is everything after the first ` = ` on its line.
///   - `scene`: a hash of what was rendered, chosen by the caller (for example FNV-1a 64
///     of the scene file's bytes and the settings), as hexadecimal digits;
///   - `settings`: free text chosen by the caller, without control characters, that must
///     match between tiles (for example `spp=16 max_depth=10 seed=0 precision=f32`);
///   - `image`: the whole image's width and height;
///   - `rect`: the tile's `x y width height` in that image (rows from the top);
///   - `pixels`: the checksum of the pixel bytes, FNV-1a 64 as 16 hexadecimal digits,
///     written by [`write_tile`] (it is not a field of this struct). Any one changed byte
///     changes it: each step of FNV-1a is a bijection of its state.
/// - An empty line ends the header (every line ends in `\n`).
/// - Exactly `24 × width × height` bytes of the rect follow, nothing after them. Every
///   value is a number that is not negative (`+∞` included): a render makes no other.
///
/// What a tile proves on reading ([`read_tile`]): its pixels are the bytes its writer
/// wrote, and none is NaN or negative. What the merge adds ([`merge_tiles`]): the tiles
/// agree on the scene hash, the settings and the image, and cover it exactly once.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TileHeader {
    /// A hash identifying the scene (and whatever else the caller hashes), as hex digits.
    pub scene: String,
    /// The render settings as text, one line without control characters.
    pub settings: String,
    /// The whole image's width in pixels.
    pub image_width: usize,
    /// The whole image's height in pixels.
    pub image_height: usize,
    /// Where this tile lies in the whole image.
    pub rect: Rect,
}

impl TileHeader {
    /// Checks the fields can be written and read back: a non-empty hex `scene`, a
    /// `settings` line without control characters, a possible image size, and a `rect`
    /// inside it.
    pub fn validate(&self) -> Result<()> {
        if self.scene.is_empty() || !self.scene.bytes().all(|b| b.is_ascii_hexdigit()) {
            return Err(Error::Tiles(format!(
                "scene hash must be hexadecimal digits, got {:?}",
                self.scene
            )));
        }
        if self.settings.chars().any(char::is_control) {
            return Err(Error::Tiles(format!(
                "settings must be one line without control characters, got {:?}",
                self.settings
            )));
        }
        let (w, h) = (self.image_width, self.image_height);
        check_size(w, h).map_err(|e| Error::Tiles(e.to_string()))?;
        self.rect.check_inside(w, h).map_err(|_| {
            Error::Tiles(format!(
                "rect {} lies outside the {w}×{h} image",
                show(&self.rect)
            ))
        })
    }
}

/// `x y width height`, as in the file.
fn show(r: &Rect) -> String {
    format!("{} {} {} {}", r.x, r.y, r.width, r.height)
}

/// Writes `image`, the pixels of `header.rect`, as a tile file, atomically (see
/// [`write_atomic`]).
///
/// # Errors
/// As [`check_tile`]; [`Error::Io`] if the file cannot be written.
pub fn write_tile(path: &Path, header: &TileHeader, image: &Image) -> Result<()> {
    check_tile(header, image)?;
    write_atomic(path, |out| write_tile_to(out, header, image))
}

/// Writes the tile file of [`write_tile`] into `out`, after [`check_tile`].
///
/// # Errors
/// [`io::ErrorKind::InvalidInput`] with [`check_tile`]'s message, or a failure to write.
pub fn write_tile_to(out: &mut impl Write, header: &TileHeader, image: &Image) -> io::Result<()> {
    check_tile(header, image).map_err(|e| io::Error::new(io::ErrorKind::InvalidInput, e.to_string()))?;
    write!(
        out,
        "{MAGIC}\nscene = {}\nsettings = {}\nimage = {} {}\nrect = {}\npixels = {:016x}\n\n",
        header.scene,
        header.settings,
        header.image_width,
        header.image_height,
        show(&header.rect),
        checksum(image)
    )?;
    let mut row = Vec::with_capacity(24 * image.width());
    for line in image.pixels().chunks_exact(image.width()) {
        row.clear();
        row.extend(line.iter().flatten().flat_map(|c| c.to_le_bytes()));
        out.write_all(&row)?;
    }
    Ok(())
}

/// Checks that `image` can be written as the tile `header` describes: a valid header
/// ([`TileHeader::validate`]), an image the size of the rect, and no pixel value that
/// is NaN or negative.
///
/// # Errors
/// [`Error::Tiles`] saying which.
pub fn check_tile(header: &TileHeader, image: &Image) -> Result<()> {
    header.validate()?;
    let r = &header.rect;
    if (image.width(), image.height()) != (r.width, r.height) {
        return Err(Error::Tiles(format!(
            "the image is {}×{} but the rect {} is {}×{}",
            image.width(),
            image.height(),
            show(r),
            r.width,
            r.height
        )));
    }
    check_values(image)
}

/// FNV-1a (64-bit) of the pixels' bytes as the file stores them.
fn checksum(image: &Image) -> u64 {
    image
        .pixels()
        .iter()
        .flatten()
        .flat_map(|c| c.to_le_bytes())
        .fold(0xcbf2_9ce4_8422_2325, |h, b| {
            (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3)
        })
}

/// Fails on the first NaN or negative value, naming its pixel in the tile.
fn check_values(image: &Image) -> Result<()> {
    let bad = image
        .pixels()
        .iter()
        .position(|p| p.iter().any(|c| c.is_nan() || *c < 0.0));
    match bad {
        None => Ok(()),
        Some(i) => Err(Error::Tiles(format!(
            "pixel ({}, {}) of the tile is {:?}: a render never makes NaN or a negative value",
            i % image.width(),
            i / image.width(),
            image.pixels()[i]
        ))),
    }
}

/// Reads a tile file (see [`parse_tile`]); errors name the file.
pub fn read_tile(path: &Path) -> Result<(TileHeader, Image)> {
    let bytes = std::fs::read(path).map_err(|source| Error::Io {
        path: path.to_path_buf(),
        source,
    })?;
    parse_tile(&bytes).map_err(|e| match e {
        Error::Tiles(m) => Error::Tiles(format!("{}: {m}", path.display())),
        other => other,
    })
}

/// Parses a tile file: the header described at [`TileHeader`], validated as
/// [`TileHeader::validate`] does, then exactly the rect's pixels.
///
/// Never panics, and checks the data's length against the header before allocating.
///
/// # Errors
/// [`Error::Tiles`] saying what is wrong: a bad magic line, a malformed, unknown,
/// repeated or missing key, truncated data or trailing bytes.
pub fn parse_tile(bytes: &[u8]) -> Result<(TileHeader, Image)> {
    let bad = |m: String| Err(Error::Tiles(m));
    let mut lines = Lines { bytes, pos: 0 };
    match lines.next()? {
        MAGIC => {}
        l if l.starts_with("raytrace-tile ") => {
            return bad(format!("unsupported tile format version {:?}", clip(&l[14..])));
        }
        l => {
            return bad(format!(
                "not a raytrace tile file: the first line is {:?}",
                clip(l)
            ));
        }
    }
    let [mut scene, mut settings, mut image, mut rect, mut sum] = [None::<&str>; 5];
    loop {
        let line = lines.next()?;
        if line.is_empty() {
            break;
        }
        let Some((key, value)) = line.split_once(" = ") else {
            return bad(format!("header line {:?} is not `key = value`", clip(line)));
        };
        let slot = match key {
            "scene" => &mut scene,
            "settings" => &mut settings,
            "image" => &mut image,
            "rect" => &mut rect,
            "pixels" => &mut sum,
            _ => return bad(format!("unknown header key {:?}", clip(key))),
        };
        if slot.replace(value).is_some() {
            return bad(format!("header key {key:?} is given twice"));
        }
    }
    let missing = |key| Error::Tiles(format!("header key {key:?} is missing"));
    let image = numbers::<2>(image.ok_or_else(|| missing("image"))?, "image", "width height")?;
    let rect = numbers::<4>(rect.ok_or_else(|| missing("rect"))?, "rect", "x y width height")?;
    let sum = sum.ok_or_else(|| missing("pixels"))?;
    let sum = u64::from_str_radix(sum, 16)
        .ok()
        .filter(|_| sum.len() == 16)
        .ok_or_else(|| {
            Error::Tiles(format!(
                "header key \"pixels\" must be 16 hexadecimal digits, got {:?}",
                clip(sum)
            ))
        })?;
    let header = TileHeader {
        scene: scene.ok_or_else(|| missing("scene"))?.to_string(),
        settings: settings.ok_or_else(|| missing("settings"))?.to_string(),
        image_width: image[0],
        image_height: image[1],
        rect: Rect {
            x: rect[0],
            y: rect[1],
            width: rect[2],
            height: rect[3],
        },
    };
    header.validate()?;
    // validate() bounds the rect by the image and the image by MAX_PIXELS: no overflow.
    let (w, h) = (header.rect.width, header.rect.height);
    let data = &bytes[lines.pos..];
    let expected = 24 * w * h;
    if data.len() != expected {
        let how = if data.len() < expected {
            "truncated"
        } else {
            "trailing bytes"
        };
        return bad(format!(
            "{how}: a {w}×{h} tile needs {expected} bytes of pixels, found {}",
            data.len()
        ));
    }
    let f = |b: &[u8]| f64::from_le_bytes(b.try_into().unwrap_or([0; 8]));
    let pixels = data
        .chunks_exact(24)
        .map(|p| [f(&p[0..8]), f(&p[8..16]), f(&p[16..24])])
        .collect();
    let image = Image::from_pixels(w, h, pixels)
        .ok_or_else(|| Error::Tiles("pixel count does not match the rect".into()))?;
    if checksum(&image) != sum {
        return bad(format!(
            "the pixels' checksum is {:016x} but the header says {sum:016x}: the file was \
             changed or damaged after it was written",
            checksum(&image)
        ));
    }
    check_values(&image)?;
    Ok((header, image))
}

/// The header's lines, each ended by `\n`.
struct Lines<'a> {
    bytes: &'a [u8],
    pos: usize,
}

impl<'a> Lines<'a> {
    fn next(&mut self) -> Result<&'a str> {
        let rest = &self.bytes[self.pos..];
        // A header line is short; a longer one means this is not a tile file.
        let window = &rest[..rest.len().min(4096)];
        let Some(end) = window.iter().position(|&b| b == b'\n') else {
            return Err(Error::Tiles(if rest.len() > window.len() {
                "header line longer than 4096 bytes".into()
            } else {
                "file ends inside the header (no empty line before the pixels)".into()
            }));
        };
        self.pos += end + 1;
        std::str::from_utf8(&rest[..end]).map_err(|_| Error::Tiles("header line is not UTF-8 text".into()))
    }
}

/// At most 40 characters of `s`, for messages about garbage.
fn clip(s: &str) -> String {
    s.chars().take(40).collect()
}

/// Exactly `N` space-separated decimal numbers.
fn numbers<const N: usize>(value: &str, key: &str, form: &str) -> Result<[usize; N]> {
    let err = || {
        Error::Tiles(format!(
            "header key {key:?} must be `{form}`, got {:?}",
            clip(value)
        ))
    };
    let mut out = [0; N];
    let mut words = value.split(' ');
    for slot in &mut out {
        let word = words.next().ok_or_else(err)?;
        if !word.bytes().all(|b| b.is_ascii_digit()) {
            return Err(err());
        }
        *slot = word.parse().map_err(|_| err())?;
    }
    match words.next() {
        None => Ok(out),
        Some(_) => Err(err()),
    }
}

#[cfg(test)]
mod tests;
