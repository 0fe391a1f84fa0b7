//! Tile files (`.rtile`): one part of a render split across processes, stored exactly,
//! so that [`merge_tiles`] gives the bits of the whole render.
//!
//! The format is documented on [`TileHeader`], where the public docs show it.

use super::{Image, Rect, check_size, write_atomic};
use crate::error::{Error, Result};
use std::io::Write;
use std::path::Path;

/// The first line of every tile file.
const MAGIC: &str = "raytrace-tile 1";

/// What a tile file says about its tile: which render it belongs to and where it goes.
///
/// A tile file is a text header, an empty line, then the data:
///
/// ```text
/// raytrace-tile 1
/// scene = 9f3c0a4e5d7b2e11
/// settings = spp=16 max_depth=10 seed=0 precision=f32
/// image = 640 480
/// rect = 0 120 640 120
///
/// <the tile's linear pixels: R G B as f64 little-endian, row by row from its top-left>
/// ```
///
/// - The first line is the magic `raytrace-tile` and the format's version, `1`.
/// - Then one `key = value` line for each of the four keys, in any order, each once:
///   the value is everything after the first ` = ` on its line.
///   - `scene`: a hash of what was rendered, chosen by the caller (for example FNV-1a 64
///     of the scene file's bytes and the settings), as hexadecimal digits;
///   - `settings`: free text chosen by the caller, without control characters, that must
///     match between tiles (for example `spp=16 max_depth=10 seed=0 precision=f32`);
///   - `image`: the whole image's width and height;
///   - `rect`: the tile's `x y width height` in that image (rows from the top).
/// - An empty line ends the header (every line ends in `\n`).
/// - Exactly `24 × width × height` bytes of the rect follow, nothing after them.
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
/// [`Error::Tiles`] if the header is invalid ([`TileHeader::validate`]) or the image's
/// size is not the rect's; [`Error::Io`] if the file cannot be written.
pub fn write_tile(path: &Path, header: &TileHeader, image: &Image) -> Result<()> {
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
    write_atomic(path, |out| {
        write!(
            out,
            "{MAGIC}\nscene = {}\nsettings = {}\nimage = {} {}\nrect = {}\n\n",
            header.scene,
            header.settings,
            header.image_width,
            header.image_height,
            show(r)
        )?;
        for &c in image.pixels().iter().flatten() {
            out.write_all(&c.to_le_bytes())?;
        }
        Ok(())
    })
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
    let [mut scene, mut settings, mut image, mut rect] = [None::<&str>; 4];
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
            _ => return bad(format!("unknown header key {:?}", clip(key))),
        };
        if slot.replace(value).is_some() {
            return bad(format!("header key {key:?} is given twice"));
        }
    }
    let missing = |key| Error::Tiles(format!("header key {key:?} is missing"));
    let image = numbers::<2>(image.ok_or_else(|| missing("image"))?, "image", "width height")?;
    let rect = numbers::<4>(rect.ok_or_else(|| missing("rect"))?, "rect", "x y width height")?;
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

/// Assembles the whole image from its tiles, after checking that they belong together:
/// the same scene, settings and image size in every header, each image the size of its
/// rect, and the rects covering every pixel exactly once. Tiles are named in errors by
/// their position in `tiles`, counting from 1.
///
/// # Errors
/// [`Error::Tiles`] naming the disagreeing tiles, the overlapping tiles and the rows and
/// columns they share, or the rows with pixels in no tile.
pub fn merge_tiles(tiles: &[(TileHeader, Image)]) -> Result<Image> {
    let bad = |m: String| Err(Error::Tiles(m));
    let Some((first, _)) = tiles.first() else {
        return bad("no tiles to merge".into());
    };
    let (width, height) = (first.image_width, first.image_height);
    for (i, (h, image)) in tiles.iter().enumerate() {
        let n = i + 1;
        h.validate().map_err(|e| Error::Tiles(format!("tile {n}: {e}")))?;
        if h.scene != first.scene {
            return bad(format!(
                "tile {n} is of scene {} but tile 1 of scene {}",
                h.scene, first.scene
            ));
        }
        if h.settings != first.settings {
            return bad(format!(
                "tile {n} has settings {:?} but tile 1 has {:?}",
                h.settings, first.settings
            ));
        }
        if (h.image_width, h.image_height) != (width, height) {
            return bad(format!(
                "tile {n} is part of a {}×{} image but tile 1 of a {width}×{height} image",
                h.image_width, h.image_height
            ));
        }
        if (image.width(), image.height()) != (h.rect.width, h.rect.height) {
            return bad(format!(
                "tile {n}'s image is {}×{} but its rect {} is {}×{}",
                image.width(),
                image.height(),
                show(&h.rect),
                h.rect.width,
                h.rect.height
            ));
        }
    }
    check_overlaps(tiles)?;
    check_coverage(tiles, width, height)?;
    let mut whole = Image::new(width, height)?;
    for (h, image) in tiles {
        let r = &h.rect;
        for (row, src) in image.pixels().chunks_exact(r.width).enumerate() {
            let start = (r.y + row) * width + r.x;
            whole.pixels_mut()[start..start + r.width].copy_from_slice(src);
        }
    }
    Ok(whole)
}

/// Fails on the first two tiles whose rects share a pixel.
fn check_overlaps(tiles: &[(TileHeader, Image)]) -> Result<()> {
    let span = |a: usize, len: usize| a..a + len;
    for (i, (a, _)) in tiles.iter().enumerate() {
        for (j, (b, _)) in tiles.iter().enumerate().skip(i + 1) {
            let (a, b) = (&a.rect, &b.rect);
            let (ax, ay) = (span(a.x, a.width), span(a.y, a.height));
            let (bx, by) = (span(b.x, b.width), span(b.y, b.height));
            let cols = ax.start.max(bx.start)..ax.end.min(bx.end);
            let rows = ay.start.max(by.start)..ay.end.min(by.end);
            if !cols.is_empty() && !rows.is_empty() {
                return Err(Error::Tiles(format!(
                    "tiles {} and {} overlap: both cover rows {rows:?}, columns {cols:?} ({} pixels)",
                    i + 1,
                    j + 1,
                    rows.len() * cols.len()
                )));
            }
        }
    }
    Ok(())
}

/// Fails if some pixel is in no tile, naming the rows that have such pixels. The rects
/// lie inside the image and do not overlap, so a row is covered when its tiles' widths
/// add up to the image's width.
fn check_coverage(tiles: &[(TileHeader, Image)], width: usize, height: usize) -> Result<()> {
    let mut missing = 0;
    let mut rows: Vec<std::ops::Range<usize>> = Vec::new();
    for y in 0..height {
        let covered: usize = tiles
            .iter()
            .map(|(h, _)| &h.rect)
            .filter(|r| (r.y..r.y + r.height).contains(&y))
            .map(|r| r.width)
            .sum();
        if covered < width {
            missing += width - covered;
            match rows.last_mut() {
                Some(last) if last.end == y => last.end = y + 1,
                _ => rows.push(y..y + 1),
            }
        }
    }
    if missing == 0 {
        return Ok(());
    }
    let mut list: Vec<String> = rows.iter().take(4).map(|r| format!("{r:?}")).collect();
    if rows.len() > 4 {
        list.push(format!("and {} more ranges", rows.len() - 4));
    }
    Err(Error::Tiles(format!(
        "{missing} pixels are in no tile, in rows {}",
        list.join(", ")
    )))
}

#[cfg(test)]
mod tests;
