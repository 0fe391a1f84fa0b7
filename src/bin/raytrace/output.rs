//! Where the results go: file names, formats, writing, merging tiles, the thread pool.

use crate::args::{Command, EncodingArg, Format, MAX_THREADS, MergeArgs, RenderArgs};
use raytrace::advice::Precision;
use raytrace::image::{
    Encoding, TileHeader, check_writable, merge_tiles, read_tile, write_exr, write_pfm, write_png, write_ppm,
    write_tile,
};
use raytrace::scene_file::{RenderOptions, SceneFile};
use raytrace::{Error, Image, Result};
use std::path::{Path, PathBuf};

/// A file to write and how.
pub struct Target {
    /// The file.
    pub path: PathBuf,
    /// Its image format; `None` for a tile file.
    format: Option<Format>,
    encoding: Encoding,
}

impl Target {
    /// The output of `raytrace render`: `--out`, or [`default_name`].
    pub fn for_render(args: &RenderArgs, file: &SceneFile, precision: Precision) -> Result<Self> {
        let encoding = encoding(args.encoding);
        let format = match args.tile {
            Some(_) => None,
            None => Some(choose_format(args.format, args.out.as_deref(), Format::Png)?),
        };
        let path = args
            .out
            .clone()
            .unwrap_or_else(|| default_name(args, file, precision, format));
        Ok(Self {
            path,
            format,
            encoding,
        })
    }

    /// Fails now, before any render, if the file's folder cannot be written.
    pub fn check_writable(&self) -> Result<()> {
        check_writable(folder(&self.path))
    }

    /// Writes `image` in the target's format.
    pub fn write_image(&self, image: &Image) -> Result<()> {
        match self.format {
            Some(Format::Ppm) => write_ppm(&self.path, &image.to_u16(self.encoding)),
            Some(Format::Png) => write_png(&self.path, &image.to_u16(self.encoding), self.encoding),
            Some(Format::Exr) => write_exr(&self.path, image),
            Some(Format::Pfm) => write_pfm(&self.path, image),
            None => Err(usage("a tile target holds a tile, not an image")),
        }
    }

    /// Writes a tile file.
    pub fn write_tile(&self, header: &TileHeader, image: &Image) -> Result<()> {
        write_tile(&self.path, header, image)
    }
}

/// `raytrace merge`: reads the tiles, checks they make one image, writes it.
pub fn merge(args: &MergeArgs) -> Result<()> {
    let format = choose_format(args.format, Some(&args.out), Format::Png)?;
    let target = Target {
        path: args.out.clone(),
        format: Some(format),
        encoding: encoding(args.encoding),
    };
    target.check_writable()?;
    let tiles = args
        .tiles
        .iter()
        .map(|p| read_tile(p))
        .collect::<Result<Vec<_>>>()?;
    let image = merge_tiles(&tiles)?;
    target.write_image(&image)?;
    println!(
        "wrote {}: {}×{} pixels from {} tiles",
        target.path.display(),
        image.width(),
        image.height(),
        tiles.len()
    );
    Ok(())
}

/// The worker threads asked for (all cores if none).
pub fn pool(threads: Option<u16>) -> Result<rayon::ThreadPool> {
    let mut pool = rayon::ThreadPoolBuilder::new();
    if let Some(t) = threads {
        debug_assert!(usize::from(t) <= MAX_THREADS, "clap checks the range");
        pool = pool.num_threads(usize::from(t));
    }
    pool.build()
        .map_err(|e| Error::InvalidSettings(format!("cannot start the worker threads: {e}")))
}

/// The settings that make an image what it is, in words: the tile files carry them, and
/// the merge checks that they agree.
pub fn describe(r: &RenderOptions, precision: Precision) -> String {
    format!(
        "width {}, {} spp, max depth {}, seed {}, {precision}",
        r.width, r.spp, r.max_depth, r.seed
    )
}

/// FNV-1a (64-bit) of the scene as rendered, after the overrides: tiles of different
/// scenes are told apart. (A mesh is named by its path; its contents are not hashed.)
pub fn scene_hash(file: &SceneFile) -> String {
    let hash = file.to_toml().bytes().fold(0xcbf2_9ce4_8422_2325_u64, |h, b| {
        (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3)
    });
    format!("{hash:016x}")
}

/// The name of a render without `--out`: the scene's, then every setting that changes the
/// file's bytes (`-linear` only where the format stores sRGB otherwise), so renders with
/// other settings do not overwrite each other: `matte_spheres-w800-16spp-d10-seed0-f32.png`,
/// `…-f64-linear.ppm`, `…-f64-tile2of4.rtile`. `format` is `None` for a tile.
fn default_name(
    args: &RenderArgs,
    file: &SceneFile,
    precision: Precision,
    format: Option<Format>,
) -> PathBuf {
    let name = args
        .scene
        .file_stem()
        .map_or_else(|| "render".into(), |s| s.to_string_lossy().into_owned());
    let r = file.render();
    let mut name = format!(
        "{name}-w{}-{}spp-d{}-seed{}-{precision}",
        r.width, r.spp, r.max_depth, r.seed
    );
    match (format, args.tile) {
        (Some(f), _) => {
            if args.encoding == EncodingArg::Linear && matches!(f, Format::Ppm | Format::Png) {
                name.push_str("-linear");
            }
            name.push('.');
            name.push_str(f.extension());
        }
        (None, Some((k, n))) => name.push_str(&format!("-tile{k}of{n}.{TILE_EXTENSION}")),
        (None, None) => unreachable!("a render without a format writes a tile"),
    }
    PathBuf::from(name)
}

/// The extension of tile files.
const TILE_EXTENSION: &str = "rtile";

/// The usage mistakes clap cannot see: an output format that contradicts the output's name.
pub fn check_usage(command: &Command) -> Result<(), String> {
    match command {
        Command::Render(args) if args.tile.is_some() => {
            if args.format.is_some() {
                return Err("--format does not apply to --tile: a tile file holds linear f64 values".into());
            }
            match &args.out {
                Some(out) if !has_extension(out, TILE_EXTENSION) => Err(format!(
                    "--tile writes a tile file, not an image: name it .{TILE_EXTENSION} (got --out {}); \
                     `raytrace merge` makes the image from the tiles",
                    out.display()
                )),
                _ => Ok(()),
            }
        }
        Command::Render(args) => format_for(args.format, args.out.as_deref(), Format::Png).map(drop),
        Command::Merge(args) => format_for(args.format, Some(&args.out), Format::Png).map(drop),
        _ => Ok(()),
    }
}

/// `--format`, else the extension of `--out`, else `default`; a conflict is an error.
fn format_for(asked: Option<Format>, out: Option<&Path>, default: Format) -> Result<Format, String> {
    let named = out.and_then(Format::of);
    match (asked, named) {
        (Some(a), Some(n)) if a != n => Err(format!(
            "--format {} but the output is named .{}",
            a.extension(),
            n.extension()
        )),
        (Some(a), _) => Ok(a),
        (None, Some(n)) => Ok(n),
        (None, None) => match out {
            Some(p) if p.extension().is_some() => Err(format!(
                "{}: unknown image format (ppm, png, exr or pfm; or say --format)",
                p.display()
            )),
            _ => Ok(default),
        },
    }
}

/// Whether `path` ends in `.ext` (in any case).
fn has_extension(path: &Path, ext: &str) -> bool {
    path.extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| e.eq_ignore_ascii_case(ext))
}

/// [`format_for`], after [`check_usage`] has reported its errors.
fn choose_format(asked: Option<Format>, out: Option<&Path>, default: Format) -> Result<Format> {
    format_for(asked, out, default).map_err(|e| usage(&e))
}

fn encoding(e: EncodingArg) -> Encoding {
    match e {
        EncodingArg::Srgb => Encoding::Srgb,
        EncodingArg::Linear => Encoding::Linear,
    }
}

/// The folder a file goes into (`.` for a bare name).
fn folder(path: &Path) -> &Path {
    match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    }
}

fn usage(message: &str) -> Error {
    Error::InvalidSettings(message.into())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn formats_follow_the_name_unless_told() {
        let p = |s: &str| Some(PathBuf::from(s));
        assert_eq!(
            choose_format(None, p("a.exr").as_deref(), Format::Png).unwrap(),
            Format::Exr
        );
        assert_eq!(choose_format(None, None, Format::Png).unwrap(), Format::Png);
        assert_eq!(
            choose_format(Some(Format::Pfm), p("a").as_deref(), Format::Png).unwrap(),
            Format::Pfm
        );
        assert!(choose_format(Some(Format::Pfm), p("a.png").as_deref(), Format::Png).is_err());
        assert!(choose_format(None, p("a.jpg").as_deref(), Format::Png).is_err());
        assert_eq!(folder(Path::new("x.png")), Path::new("."));
        assert_eq!(folder(Path::new("out/x.png")), Path::new("out"));
    }
}
