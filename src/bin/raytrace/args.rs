//! The command line: `raytrace render | check | advise | merge`.

use clap::{Args, Parser, Subcommand, ValueEnum};
use raytrace::RenderSettings;
use raytrace::cli::parse_threads;
use raytrace::image::ToneCurve;
use std::path::PathBuf;

/// Renders scene files (TOML; the format: docs/SCENE_FORMAT.md).
#[derive(Debug, Parser)]
#[command(name = "raytrace", version, about)]
pub struct Cli {
    /// What to do.
    #[command(subcommand)]
    pub command: Command,
}

/// The subcommands.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Render a scene file into an image (or, with --tile, into a tile file).
    Render(RenderArgs),
    /// Check a scene file: print its counts, bounds, acceleration and precision.
    Check {
        /// The scene file.
        scene: PathBuf,
    },
    /// Measure which precision the scene needs (f32 against f64 and a double-double reference).
    Advise {
        /// The scene file.
        scene: PathBuf,
    },
    /// Merge tile files rendered with --tile into the whole image.
    Merge(MergeArgs),
}

/// `raytrace render`.
#[derive(Debug, Args)]
pub struct RenderArgs {
    /// The scene file.
    pub scene: PathBuf,
    /// Image width in pixels; the height follows the camera [default: the scene's]
    #[arg(long, value_name = "W", value_parser = clap::value_parser!(u64).range(1..))]
    pub width: Option<u64>,
    /// Samples (rays) per pixel [default: the scene's]
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..))]
    pub spp: Option<u32>,
    /// Most bounces per path, 0 to 1000 [default: the scene's]
    #[arg(long, value_name = "D", value_parser = clap::value_parser!(u32).range(0..=i64::from(RenderSettings::MAX_DEPTH)))]
    pub max_depth: Option<u32>,
    /// Random seed [default: the scene's]
    #[arg(long, value_name = "S")]
    pub seed: Option<u64>,
    /// The scalar the render runs in; auto measures it first [default: the scene's]
    #[arg(long, value_name = "P")]
    pub precision: Option<PrecisionArg>,
    /// Worker threads, 1 to 256 [default: all cores]
    #[arg(long, value_name = "T", value_parser = parse_threads)]
    pub threads: Option<usize>,
    /// The output file, `-` for standard output; missing folders are made [default: the
    /// scene's name and the settings, in the current folder]
    #[arg(long, value_name = "FILE")]
    pub out: Option<PathBuf>,
    /// The output format [default: from --out's extension, else png]
    #[arg(long, value_name = "F")]
    pub format: Option<Format>,
    /// How colour is stored in PPM and PNG files (EXR and PFM are always linear)
    #[arg(long, value_name = "E", default_value = "srgb")]
    pub encoding: EncodingArg,
    /// Stops of exposure for PPM and PNG, -64 to 64: +1 doubles every value (EXR and PFM
    /// stay linear) [default: the scene's]
    #[arg(long, value_name = "S", allow_negative_numbers = true)]
    pub exposure: Option<f64>,
    /// The tone curve for PPM and PNG (EXR and PFM stay linear) [default: the scene's]
    #[arg(long, value_name = "C")]
    pub tonemap: Option<TonemapArg>,
    /// Render only tile K of N (horizontal bands, K from 1), into a tile file for `merge`
    #[arg(long, value_name = "K/N", value_parser = parse_tile)]
    pub tile: Option<(usize, usize)>,
    /// No progress bar
    #[arg(long)]
    pub quiet: bool,
}

/// `raytrace merge`.
#[derive(Debug, Args)]
pub struct MergeArgs {
    /// The tile files, in any order.
    #[arg(required = true)]
    pub tiles: Vec<PathBuf>,
    /// The image to write, `-` for standard output; missing folders are made.
    #[arg(long, value_name = "FILE")]
    pub out: PathBuf,
    /// The output format [default: from --out's extension]
    #[arg(long, value_name = "F")]
    pub format: Option<Format>,
    /// How colour is stored in PPM and PNG files
    #[arg(long, value_name = "E", default_value = "srgb")]
    pub encoding: EncodingArg,
    /// Stops of exposure for PPM and PNG, -64 to 64: +1 doubles every value
    #[arg(long, value_name = "S", default_value_t = 0.0, allow_negative_numbers = true)]
    pub exposure: f64,
    /// The tone curve for PPM and PNG
    #[arg(long, value_name = "C", default_value = "none")]
    pub tonemap: TonemapArg,
    /// Nothing on stderr while the image is written
    #[arg(long)]
    pub quiet: bool,
}

/// `--precision`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum PrecisionArg {
    /// Single precision.
    F32,
    /// Double precision.
    F64,
    /// Measured on a small render first (`raytrace advise`).
    Auto,
}

/// The image formats.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Format {
    /// The spec's 16-bit plain PPM.
    Ppm,
    /// 16-bit PNG.
    Png,
    /// OpenEXR, linear 32-bit float: keeps values above 1.
    Exr,
    /// Portable float map, linear 32-bit float.
    Pfm,
}

impl Format {
    /// The file extension.
    pub fn extension(self) -> &'static str {
        match self {
            Self::Ppm => "ppm",
            Self::Png => "png",
            Self::Exr => "exr",
            Self::Pfm => "pfm",
        }
    }

    /// The format a file name's extension names, if any.
    pub fn of(path: &std::path::Path) -> Option<Self> {
        let ext = path.extension()?.to_str()?.to_ascii_lowercase();
        [Self::Ppm, Self::Png, Self::Exr, Self::Pfm]
            .into_iter()
            .find(|f| f.extension() == ext)
    }
}

/// `--encoding`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum EncodingArg {
    /// sRGB-encoded values, for viewing.
    Srgb,
    /// Linear values.
    Linear,
}

/// `--tonemap`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum TonemapArg {
    /// No curve: values above 1 clip.
    None,
    /// Narkowicz's fit of the ACES filmic curve.
    Aces,
}

impl TonemapArg {
    /// The library's curve.
    pub fn curve(self) -> ToneCurve {
        match self {
            Self::None => ToneCurve::None,
            Self::Aces => ToneCurve::Aces,
        }
    }
}

/// `K/N` with `1 ≤ K ≤ N`.
fn parse_tile(s: &str) -> Result<(usize, usize), String> {
    let (k, n) = s
        .split_once('/')
        .ok_or_else(|| format!("`{s}` is not K/N (for example 2/4)"))?;
    let number = |t: &str| {
        t.trim()
            .parse::<usize>()
            .map_err(|e| format!("`{t}` in `{s}`: {e}"))
    };
    let (k, n) = (number(k)?, number(n)?);
    if n == 0 || k == 0 || k > n {
        return Err(format!("tile {k}/{n}: need 1 ≤ K ≤ N"));
    }
    Ok((k, n))
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::CommandFactory;

    #[test]
    fn the_command_line_is_consistent() {
        Cli::command().debug_assert();
    }

    #[test]
    fn tiles_parse_and_reject() {
        assert_eq!(parse_tile("2/4"), Ok((2, 4)));
        for bad in ["0/4", "5/4", "1/0", "2", "a/4", "2/-1", ""] {
            assert!(parse_tile(bad).is_err(), "{bad}");
        }
    }

    #[test]
    fn the_deepest_recursion_allowed_is_accepted() {
        let cli = Cli::try_parse_from(["raytrace", "render", "s.toml", "--max-depth", "1000"]).unwrap();
        let Command::Render(args) = cli.command else {
            panic!("{cli:?}")
        };
        assert_eq!(args.max_depth, Some(RenderSettings::MAX_DEPTH));
    }

    #[test]
    fn a_negative_exposure_is_a_value() {
        let cli = Cli::try_parse_from([
            "raytrace",
            "render",
            "s.toml",
            "--exposure",
            "-1.5",
            "--tonemap",
            "aces",
        ])
        .unwrap();
        let Command::Render(args) = cli.command else {
            panic!("{cli:?}")
        };
        assert_eq!(
            (args.exposure, args.tonemap),
            (Some(-1.5), Some(TonemapArg::Aces))
        );
    }

    #[test]
    fn bad_options_are_usage_errors() {
        for args in [
            &["raytrace", "render", "s.toml", "--threads", "0"][..],
            &["raytrace", "render", "s.toml", "--threads", "100000"],
            &["raytrace", "render", "s.toml", "--width", "0"],
            &["raytrace", "render", "s.toml", "--spp", "0"],
            &["raytrace", "render", "s.toml", "--max-depth", "1001"],
            &["raytrace", "render", "s.toml", "--precision", "f16"],
            &["raytrace", "render", "s.toml", "--format", "jpg"],
            &["raytrace", "render", "s.toml", "--tonemap", "filmic"],
            &["raytrace", "render", "s.toml", "--exposure", "bright"],
            &["raytrace", "merge", "--out", "x.png"],
            &["raytrace", "paint", "s.toml"],
        ] {
            let err = Cli::try_parse_from(args).unwrap_err();
            assert_eq!(err.exit_code(), 2, "{args:?}: {err}");
        }
    }
}
