//! The options every example accepts, parsed by one small helper.
//!
//! ```text
//! --width W            image width in pixels (the height follows the scene's aspect)
//! --spp N              samples (rays) per pixel, ≥ 1
//! --max-depth D        most bounces per path
//! --seed S             random seed
//! --precision P        f32 or f64
//! --threads T          worker threads (default: all cores)
//! --encoding E         srgb or linear (how colour is stored in the files)
//! --out DIR            output folder
//! --help               this text
//! ```

pub use crate::advice::Precision;
use crate::image::Encoding;
use std::fmt;
use std::path::PathBuf;

/// Parsed example options.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Options {
    /// Image width in pixels.
    pub width: usize,
    /// Samples per pixel.
    pub spp: u32,
    /// Maximum bounces per path.
    pub max_depth: u32,
    /// Random seed.
    pub seed: u64,
    /// Scalar type.
    pub precision: Precision,
    /// Worker threads; `None` for all cores.
    pub threads: Option<usize>,
    /// How colour is stored.
    pub encoding: Encoding,
    /// Output folder.
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

/// What the command line asks for.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Command {
    /// Render with these options.
    Run(Options),
    /// Print this usage text and exit successfully.
    Help(String),
}

/// A command-line mistake; its message says what was wrong and how to get help.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CliError(pub String);

impl fmt::Display for CliError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for CliError {}

/// The usage text for example `name` with its `defaults`.
pub fn usage(name: &str, about: &str, d: &Options) -> String {
    format!(
        "{about}\n\nUsage: cargo run --release --example {name} -- [options]\n\n\
         Options:\n  \
         --width W        image width in pixels; the height follows the scene's aspect [{}]\n  \
         --spp N          samples (rays) per pixel, at least 1 [{}]\n  \
         --max-depth D    most bounces per path [{}]\n  \
         --seed S         random seed [{}]\n  \
         --precision P    f32 or f64 [{}]\n  \
         --threads T      worker threads [all cores]\n  \
         --encoding E     srgb or linear: how colour is stored [srgb]\n  \
         --out DIR        output folder [{}]\n  \
         --help           print this text",
        d.width,
        d.spp,
        d.max_depth,
        d.seed,
        d.precision,
        d.out.display()
    )
}

/// Parses `args` (without the program name) over an example's `defaults`.
///
/// Accepts `--opt value` and `--opt=value`. Unknown options, missing or malformed
/// values, and zero where at least 1 is needed are errors.
pub fn parse(
    name: &str,
    about: &str,
    defaults: Options,
    args: impl IntoIterator<Item = String>,
) -> Result<Command, CliError> {
    let mut o = defaults.clone();
    let mut args = args.into_iter();
    let hint = format!("(try: cargo run --example {name} -- --help)");
    while let Some(arg) = args.next() {
        let (key, inline) = match arg.split_once('=') {
            Some((k, v)) if k.starts_with("--") => (k.to_string(), Some(v.to_string())),
            _ => (arg.clone(), None),
        };
        if key == "--help" || key == "-h" {
            return Ok(Command::Help(usage(name, about, &defaults)));
        }
        let known = [
            "--width",
            "--spp",
            "--max-depth",
            "--seed",
            "--precision",
            "--threads",
            "--encoding",
            "--out",
        ];
        if !known.contains(&key.as_str()) {
            return Err(CliError(format!("unknown option {arg:?} {hint}")));
        }
        let value = match inline.or_else(|| args.next()) {
            Some(v) => v,
            None => return Err(CliError(format!("{key} needs a value {hint}"))),
        };
        let bad = |what: &str| CliError(format!("{key} {value:?}: expected {what} {hint}"));
        let positive = |v: &str| v.parse::<u64>().ok().filter(|&n| n > 0);
        match key.as_str() {
            "--width" => {
                o.width = positive(&value)
                    .and_then(|n| usize::try_from(n).ok())
                    .ok_or_else(|| bad("a whole number ≥ 1"))?
            }
            "--spp" => {
                o.spp = positive(&value)
                    .and_then(|n| u32::try_from(n).ok())
                    .ok_or_else(|| bad("a whole number ≥ 1"))?
            }
            "--max-depth" => o.max_depth = value.parse().map_err(|_| bad("a whole number ≥ 0"))?,
            "--seed" => o.seed = value.parse().map_err(|_| bad("a whole number ≥ 0"))?,
            "--threads" => {
                o.threads = Some(
                    positive(&value)
                        .and_then(|n| usize::try_from(n).ok())
                        .ok_or_else(|| bad("a whole number ≥ 1"))?,
                )
            }
            "--precision" => {
                o.precision = match value.as_str() {
                    "f32" => Precision::F32,
                    "f64" => Precision::F64,
                    _ => return Err(bad("f32 or f64")),
                }
            }
            "--encoding" => {
                o.encoding = match value.as_str() {
                    "srgb" => Encoding::Srgb,
                    "linear" => Encoding::Linear,
                    _ => return Err(bad("srgb or linear")),
                }
            }
            _ => o.out = PathBuf::from(value),
        }
    }
    Ok(Command::Run(o))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn run(args: &[&str]) -> Result<Command, CliError> {
        parse(
            "demo",
            "A demo.",
            Options::defaults(800, 1, 10),
            args.iter().map(|s| s.to_string()),
        )
    }

    #[test]
    fn defaults_and_every_option() {
        assert_eq!(run(&[]).unwrap(), Command::Run(Options::defaults(800, 1, 10)));
        let Command::Run(o) = run(&[
            "--width",
            "400",
            "--spp=16",
            "--max-depth",
            "0",
            "--seed",
            "7",
            "--precision",
            "f32",
            "--threads",
            "2",
            "--encoding",
            "linear",
            "--out",
            "/tmp/x",
        ])
        .unwrap() else {
            panic!("expected Run")
        };
        assert_eq!((o.width, o.spp, o.max_depth, o.seed), (400, 16, 0, 7));
        assert_eq!(
            (o.precision, o.threads, o.encoding),
            (Precision::F32, Some(2), Encoding::Linear)
        );
        assert_eq!(o.out, PathBuf::from("/tmp/x"));
    }

    #[test]
    fn help_lists_the_options() {
        let Command::Help(text) = run(&["--help"]).unwrap() else {
            panic!()
        };
        for opt in [
            "--width",
            "--spp",
            "--max-depth",
            "--seed",
            "--precision",
            "--threads",
            "--out",
            "[800]",
        ] {
            assert!(text.contains(opt), "{opt} missing from help");
        }
    }

    #[test]
    fn mistakes_are_named() {
        for (args, want) in [
            (&["--bogus"][..], "unknown option \"--bogus\""),
            (&["--width"], "--width needs a value"),
            (&["--width", "0"], "--width \"0\""),
            (&["--spp", "-3"], "--spp \"-3\""),
            (&["--spp", "5000000000"], "--spp"),
            (&["--precision", "f16"], "f32 or f64"),
            (&["--threads", "x"], "--threads"),
            (&["--encoding", "gamma"], "srgb or linear"),
            (&["800"], "unknown option \"800\""),
        ] {
            let err = run(args).unwrap_err().to_string();
            assert!(err.contains(want), "{args:?}: {err}");
            assert!(err.contains("--help"), "{args:?}: {err}");
        }
    }
}
