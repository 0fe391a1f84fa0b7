//! The options every example accepts, parsed by clap over the example's own defaults.
//!
//! ```text
//! --width W            image width in pixels (the height follows the scene's aspect)
//! --spp N              samples (rays) per pixel, ≥ 1
//! --max-depth D        most bounces per path
//! --seed S             random seed
//! --precision P        f32 or f64
//! --threads T          worker threads, 1 to 256 (default: all cores)
//! --encoding E         srgb or linear (how colour is stored in the files)
//! --out DIR            output folder
//! --help               this text
//! ```

use clap::builder::{PossibleValuesParser, TypedValueParser};
use clap::{Arg, CommandFactory, FromArgMatches, Parser};
use raytrace::advice::Precision;
use raytrace::cli::parse_threads;
use raytrace::image::Encoding;
use std::ffi::OsString;
use std::num::ParseIntError;
use std::path::PathBuf;
use std::str::FromStr;

/// An example's name, one-line description and default options.
pub struct Example {
    /// The example's name, also the output files' stem.
    pub name: &'static str,
    /// What it renders.
    pub about: &'static str,
    /// Its default options.
    pub defaults: Options,
}

/// Parsed example options. The defaults are the example's ([`Example::command`] sets
/// them on each argument, so `--help` shows them).
#[derive(Clone, Debug, PartialEq, Eq, Parser)]
pub struct Options {
    /// Image width in pixels; the height follows the scene's aspect
    #[arg(long, value_name = "W", value_parser = at_least_one::<usize>)]
    pub width: usize,
    /// Samples (rays) per pixel, at least 1
    #[arg(long, value_name = "N", value_parser = at_least_one::<u32>)]
    pub spp: u32,
    /// Most bounces per path
    #[arg(long, value_name = "D")]
    pub max_depth: u32,
    /// Random seed
    #[arg(long, value_name = "S")]
    pub seed: u64,
    /// The scalar the render runs in
    #[arg(long, value_name = "P", value_parser = PossibleValuesParser::new(["f32", "f64"])
        .map(|s| if s == "f32" { Precision::F32 } else { Precision::F64 }))]
    pub precision: Precision,
    /// Worker threads, 1 to 256 [default: all cores]
    #[arg(long, value_name = "T", value_parser = parse_threads)]
    pub threads: Option<usize>,
    /// How colour is stored in the files
    #[arg(long, value_name = "E", value_parser = PossibleValuesParser::new(["srgb", "linear"])
        .map(|s| if s == "srgb" { Encoding::Srgb } else { Encoding::Linear }))]
    pub encoding: Encoding,
    /// Output folder
    #[arg(long, value_name = "DIR")]
    pub out: PathBuf,
}

impl Options {
    /// An example's defaults: its width, samples and depth; seed 0, f64, all cores,
    /// sRGB, output folder `output/`.
    pub fn defaults(width: usize, spp: u32, max_depth: u32) -> Self {
        Self {
            width,
            spp,
            max_depth,
            seed: 0,
            precision: Precision::F64,
            threads: None,
            encoding: Encoding::Srgb,
            out: PathBuf::from("output"),
        }
    }
}

impl Example {
    /// The example's command line: its name, its description as the about text, and its
    /// defaults on every option that has one.
    pub fn command(&self) -> clap::Command {
        let d = &self.defaults;
        let encoding = match d.encoding {
            Encoding::Srgb => "srgb",
            Encoding::Linear => "linear",
        };
        // The derive makes every option without a default required; these get theirs here.
        let default = |value: String| move |arg: Arg| arg.default_value(value).required(false);
        Options::command()
            .name(self.name)
            .bin_name(format!("cargo run --release --example {} --", self.name))
            .about(self.about)
            .long_about(None)
            .mut_arg("width", default(d.width.to_string()))
            .mut_arg("spp", default(d.spp.to_string()))
            .mut_arg("max_depth", default(d.max_depth.to_string()))
            .mut_arg("seed", default(d.seed.to_string()))
            .mut_arg("precision", default(d.precision.to_string()))
            .mut_arg("encoding", default(encoding.to_string()))
            .mut_arg("out", default(d.out.display().to_string()))
    }

    /// Parses `args` (the program name first, as in [`std::env::args_os`]) over the
    /// example's defaults.
    ///
    /// # Errors
    /// A usage mistake (unknown option, missing or malformed value, a number out of
    /// range), or `--help`; [`clap::Error::exit`] prints either and exits accordingly.
    pub fn try_parse_from<I, T>(&self, args: I) -> Result<Options, clap::Error>
    where
        I: IntoIterator<Item = T>,
        T: Into<OsString> + Clone,
    {
        let mut command = self.command();
        let matches = command.try_get_matches_from_mut(args)?;
        Options::from_arg_matches(&matches).map_err(|e| e.format(&mut command))
    }
}

/// Parses a whole number of at least 1: a zero width or sample count renders nothing.
fn at_least_one<T>(s: &str) -> Result<T, String>
where
    T: FromStr<Err = ParseIntError> + PartialOrd + From<u8>,
{
    match s.parse::<T>() {
        Ok(n) if n >= T::from(1) => Ok(n),
        Ok(_) => Err("must be at least 1".into()),
        Err(e) => Err(format!("expected a whole number ≥ 1 ({e})")),
    }
}
