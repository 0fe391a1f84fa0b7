//! Merging tiles: checking that they make one image, then placing each.

use super::{TileHeader, show};
use crate::error::{Error, Result};
use crate::image::Image;

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
        // Settings first: a seed or a width given on the command line changes both.
        if h.settings != first.settings {
            return bad(format!(
                "tile {n} has settings {:?} but tile 1 has {:?}",
                h.settings, first.settings
            ));
        }
        if h.scene != first.scene {
            return bad(format!(
                "tile {n} is of scene {} but tile 1 of scene {}",
                h.scene, first.scene
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
