//! The command line: `raytrace render | check | advise | merge`.

use clap::{ArgGroup, Args, Parser, Subcommand, ValueEnum};
use raytrace::RenderSettings;
use raytrace::cli::parse_threads;
use raytrace::image::ToneCurve;
use raytrace::render::Adaptive;
use std::path::PathBuf;
use std::time::Duration;

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
    /// Check a scene file: print its counts, bounds, acceleration and precision (for a
    /// Mitsuba XML scene, also what was read and where the render differs).
    Check {
        /// The scene file (TOML, or Mitsuba 3 XML by its `.xml` extension).
        scene: PathBuf,
        /// For a Mitsuba XML scene: NAME=VALUE for its `$NAME`, over its `<default>`s.
        #[arg(short = 'D', value_name = "NAME=VALUE", value_parser = parse_define)]
        define: Vec<(String, String)>,
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
#[command(group(ArgGroup::new("adaptive").args(["target_error", "time_budget"]).multiple(true)))]
pub struct RenderArgs {
    /// The scene file (TOML, or Mitsuba 3 XML by its `.xml` extension).
    pub scene: PathBuf,
    /// For a Mitsuba XML scene: NAME=VALUE for its `$NAME`, over its `<default>`s.
    #[arg(short = 'D', value_name = "NAME=VALUE", value_parser = parse_define)]
    pub define: Vec<(String, String)>,
    /// Image width in pixels; the height follows the camera [default: the scene's]
    #[arg(long, value_name = "W", value_parser = clap::value_parser!(u64).range(1..))]
    pub width: Option<u64>,
    /// Samples (rays) per pixel [default: the scene's]
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..), conflicts_with = "adaptive")]
    pub spp: Option<u32>,
    /// Sample each pixel until the relative standard error of its mean luminance is at
    /// most E (0.01 or 1%), measured against a floor for dark pixels (--error-floor)
    #[arg(long, value_name = "E", value_parser = parse_error, allow_negative_numbers = true)]
    pub target_error: Option<f64>,
    /// Sample adaptively for this long (90, 90s, 1.5m, 2h, 500ms), where the error is
    /// largest; the image then depends on the time
    #[arg(long, value_name = "T", value_parser = parse_duration, allow_hyphen_values = true)]
    pub time_budget: Option<Duration>,
    /// With --target-error or --time-budget: samples every pixel takes first
    #[arg(long, value_name = "N", requires = "adaptive", default_value_t = Adaptive::DEFAULT_MIN_SPP,
          value_parser = clap::value_parser!(u32).range(i64::from(Adaptive::MIN_SPP)..))]
    pub min_spp: u32,
    /// With --target-error or --time-budget: samples no pixel goes beyond
    #[arg(long, value_name = "N", requires = "adaptive", default_value_t = Adaptive::DEFAULT_MAX_SPP,
          value_parser = clap::value_parser!(u32).range(1..))]
    pub max_spp: u32,
    /// With --target-error or --time-budget: the luminance below which a pixel's error is
    /// measured in absolute terms
    #[arg(long, value_name = "Y", requires = "adaptive", default_value_t = Adaptive::DEFAULT_FLOOR,
          value_parser = parse_error, allow_negative_numbers = true)]
    pub error_floor: f64,
    /// Also write a denoiser's feature layers (albedo, shading normal, first-hit depth)
    /// into the EXR (or, for another format, into NAME.layers.exr beside the image)
    #[arg(long)]
    pub aov: bool,
    /// Most bounces per path, 0 to 1000 [default: the scene's]
    #[arg(long, value_name = "D", value_parser = clap::value_parser!(u32).range(0..=i64::from(RenderSettings::MAX_DEPTH)))]
    pub max_depth: Option<u32>,
    /// Random seed [default: the scene's]
    #[arg(long, value_name = "S")]
    pub seed: Option<u64>,
    /// The scalar the render runs in; auto measures it first [default: the scene's]
    #[arg(long, value_name = "P")]
    pub precision: Option<PrecisionArg>,
    /// The BVH build: high adds spatial splits (long triangles cut into pieces) [default:
    /// the scene's]
    #[arg(long, value_name = "Q")]
    pub bvh_quality: Option<QualityArg>,
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

/// `--bvh-quality`, Embree's names.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum QualityArg {
    /// The binned SAH build over whole primitives.
    Medium,
    /// The same after spatial splits.
    High,
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

/// `NAME=VALUE`, the name not empty.
fn parse_define(s: &str) -> Result<(String, String), String> {
    match s.split_once('=') {
        Some((name, value)) if !name.is_empty() => Ok((name.to_owned(), value.to_owned())),
        _ => Err(format!("`{s}` is not NAME=VALUE")),
    }
}

/// A number `> 0`, finite, written plainly (`0.01`) or as a percentage (`1%`).
fn parse_error(s: &str) -> Result<f64, String> {
    let (number, scale) = match s.trim().strip_suffix('%') {
        Some(n) => (n, 0.01),
        None => (s.trim(), 1.0),
    };
    let v: f64 = number
        .trim()
        .parse()
        .map_err(|_| format!("`{s}` is not a number (for example 0.01 or 1%)"))?;
    let v = v * scale;
    if !(v.is_finite() && v > 0.0) {
        return Err(format!("must be a finite number > 0 (got {s})"));
    }
    Ok(v)
}

/// A duration: seconds (`90`, `90s`, `1.5`), milliseconds (`500ms`), minutes (`1.5m`) or
/// hours (`2h`); longer than zero, at most a year.
fn parse_duration(s: &str) -> Result<Duration, String> {
    let t = s.trim();
    let (number, unit) = [("ms", 0.001), ("s", 1.0), ("m", 60.0), ("h", 3600.0)]
        .into_iter()
        .find_map(|(suffix, unit)| t.strip_suffix(suffix).map(|n| (n, unit)))
        .unwrap_or((t, 1.0));
    let v: f64 = number
        .trim()
        .parse()
        .map_err(|_| format!("`{s}` is not a duration (for example 90, 90s, 1.5m, 2h, 500ms)"))?;
    let seconds = v * unit;
    if !(seconds.is_finite() && seconds > 0.0 && seconds <= 365.0 * 86_400.0) {
        return Err(format!("must be longer than 0 s and at most a year (got {s})"));
    }
    Ok(Duration::from_secs_f64(seconds))
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
    fn errors_and_durations_parse_and_reject() {
        assert_eq!(parse_error("0.01"), Ok(0.01));
        assert_eq!(parse_error("2%"), Ok(0.02));
        assert_eq!(parse_error(" 0.5 % "), Ok(0.005));
        for bad in ["0", "-0.01", "nan", "inf", "%", "x", "1e400", "-1%"] {
            assert!(parse_error(bad).is_err(), "{bad}");
        }
        assert_eq!(parse_duration("90"), Ok(Duration::from_secs(90)));
        assert_eq!(parse_duration("90s"), Ok(Duration::from_secs(90)));
        assert_eq!(parse_duration("1.5m"), Ok(Duration::from_secs(90)));
        assert_eq!(parse_duration("2h"), Ok(Duration::from_secs(7200)));
        assert_eq!(parse_duration("500ms"), Ok(Duration::from_millis(500)));
        for bad in ["0", "-5s", "nan", "s", "5 minutes", "1e30", "inf"] {
            assert!(parse_duration(bad).is_err(), "{bad}");
        }
    }

    #[test]
    fn adaptive_options_go_together() {
        let parse = |args: &[&str]| Cli::try_parse_from([&["raytrace", "render", "s.toml"], args].concat());
        let cli = parse(&["--target-error", "1%", "--max-spp", "256"]).unwrap();
        let Command::Render(a) = cli.command else {
            panic!("{cli:?}")
        };
        assert_eq!((a.target_error, a.min_spp, a.max_spp), (Some(0.01), 32, 256));
        assert!(parse(&["--time-budget", "10s", "--target-error", "0.02"]).is_ok());
        for bad in [
            &["--spp", "16", "--target-error", "0.01"][..],
            &["--spp", "16", "--time-budget", "5"],
            &["--min-spp", "64"],
            &["--max-spp", "64"],
            &["--error-floor", "0.1"],
            &["--target-error", "0.01", "--min-spp", "8"],
            &["--target-error", "-0.01"],
            &["--time-budget", "0s"],
            &["--time-budget", "-5s"],
        ] {
            let err = parse(bad).unwrap_err();
            assert_eq!(err.exit_code(), 2, "{bad:?}: {err}");
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
