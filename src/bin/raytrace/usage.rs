//! The output's format and the usage mistakes clap cannot see: a format that contradicts
//! the output's name, limits that contradict each other, layers where none can go.

use crate::args::{Command, EncodingArg, Format, MergeArgs};
use crate::names::{TILE_EXTENSION, adaptive_of};
use raytrace::image::{Encoding, Tonemap};
use raytrace::{Error, Result};
use std::path::Path;
#[cfg(test)]
use std::path::PathBuf;

/// The usage mistakes clap cannot see: an output format that contradicts the output's
/// name, adaptive limits that contradict each other, feature layers where none can go.
pub fn check_usage(command: &Command) -> Result<(), String> {
    if let Command::Render(args) = command {
        if adaptive_of(args).is_some() && args.max_spp < args.min_spp {
            return Err(format!(
                "--max-spp {} is below --min-spp {}: the most samples a pixel may take must be at \
                 least the number every pixel takes first",
                args.max_spp, args.min_spp
            ));
        }
        if args.aov && args.tile.is_some() {
            return Err("--aov does not apply to --tile: a tile file holds only the colour".into());
        }
        let to_stdout = args.out.as_deref() == Some(Path::new("-"));
        let exr = format_for(args.format, args.out.as_deref(), Format::Png) == Ok(Format::Exr);
        if args.aov && to_stdout && !exr {
            return Err(
                "--aov with --out - needs --format exr: the layers go into the EXR, and there is no \
                 file beside standard output"
                    .into(),
            );
        }
    }
    match command {
        Command::Render(args) if args.tile.is_some() => {
            if args.format.is_some() {
                return Err("--format does not apply to --tile: a tile file holds linear f64 values".into());
            }
            match &args.out {
                Some(out) if out != Path::new("-") && !has_extension(out, TILE_EXTENSION) => Err(format!(
                    "--tile writes a tile file, not an image: name it .{TILE_EXTENSION} (got --out {}); \
                     `raytrace merge` makes the image from the tiles",
                    out.display()
                )),
                _ => Ok(()),
            }
        }
        Command::Render(args) => format_for(args.format, args.out.as_deref(), Format::Png).map(drop),
        Command::Merge(args) => {
            merge_tonemap(args)?;
            format_for(args.format, Some(&args.out), Format::Png).map(drop)
        }
        _ => Ok(()),
    }
}

/// `raytrace merge`'s `--exposure` and `--tonemap`, or the usage error naming the option.
pub(crate) fn merge_tonemap(args: &MergeArgs) -> Result<Tonemap, String> {
    Tonemap::new(args.exposure, args.tonemap.curve()).map_err(|e| match e {
        Error::InvalidValue { reason, .. } => {
            format!("invalid value '{}' for '--exposure': {reason}", args.exposure)
        }
        other => other.to_string(),
    })
}

/// `--format`, else the extension of `--out`, else `default`; a conflict is an error.
pub(crate) fn format_for(
    asked: Option<Format>,
    out: Option<&Path>,
    default: Format,
) -> Result<Format, String> {
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
pub(crate) fn has_extension(path: &Path, ext: &str) -> bool {
    path.extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| e.eq_ignore_ascii_case(ext))
}

/// [`format_for`], after [`check_usage`] has reported its errors.
pub(crate) fn choose_format(asked: Option<Format>, out: Option<&Path>, default: Format) -> Result<Format> {
    format_for(asked, out, default).map_err(|e| usage(&e))
}

pub(crate) fn encoding(e: EncodingArg) -> Encoding {
    match e {
        EncodingArg::Srgb => Encoding::Srgb,
        EncodingArg::Linear => Encoding::Linear,
    }
}

pub(crate) fn usage(message: &str) -> Error {
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
    }
}
