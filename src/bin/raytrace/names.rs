//! What a render is called: its settings in words (which tile files carry and the merge
//! compares) and the file name it gets without `--out`.

use crate::args::{EncodingArg, Format, RenderArgs};
use raytrace::advice::Precision;
use raytrace::image::{ToneCurve, Tonemap};
use raytrace::render::adaptive::{Adaptive, ErrorEstimate};
use raytrace::scene_file::{RenderOptions, SceneFile};
use std::path::PathBuf;

/// The settings that make an image what it is, in words: the tile files carry them, and
/// the merge checks that they agree.
pub fn describe(r: &RenderOptions, adaptive: Option<&Adaptive>, precision: Precision) -> String {
    let sampling = match adaptive {
        None => format!("{} spp", r.spp),
        Some(a) => {
            let mut goal = Vec::new();
            if let Some(e) = a.target_error {
                goal.push(format!("target error {e}"));
            }
            if let Some(t) = a.time_budget {
                goal.push(format!("time budget {} s", t.as_secs_f64()));
            }
            format!(
                "{} ({} to {} spp, error floor {})",
                goal.join(", "),
                a.min_spp,
                a.max_spp,
                a.error_floor
            )
        }
    };
    format!(
        "width {}, {sampling}, max depth {}, seed {}, {precision}",
        r.width, r.max_depth, r.seed
    )
}

/// The adaptive settings the command line asks for, if any.
pub fn adaptive_of(args: &RenderArgs) -> Option<Adaptive> {
    (args.target_error.is_some() || args.time_budget.is_some()).then_some(Adaptive {
        target_error: args.target_error,
        time_budget: args.time_budget,
        min_spp: args.min_spp,
        max_spp: args.max_spp,
        error_floor: args.error_floor,
        estimate: ErrorEstimate::Guarded,
    })
}

/// The name of a render without `--out`: the scene's, then every setting that changes the
/// file's bytes (`-linear`, the exposure and the tone curve only where the format stores a
/// picture), so renders with other settings do not overwrite each other:
/// `matte_spheres-w800-16spp-d10-seed0-f32.png`, `…-f64-linear.ppm`,
/// `…-f64-ev1.5-aces.png`, `…-f64-tile2of4.rtile`. `format` is `None` for a tile.
pub fn default_name(
    args: &RenderArgs,
    file: &SceneFile,
    precision: Precision,
    format: Option<Format>,
    tonemap: Tonemap,
) -> PathBuf {
    let name = args
        .scene
        .file_stem()
        .map_or_else(|| "render".into(), |s| s.to_string_lossy().into_owned());
    let r = file.render();
    let sampling = match adaptive_of(args) {
        None => format!("{}spp", r.spp),
        Some(a) => adaptive_name(&a),
    };
    let mut name = format!(
        "{name}-w{}-{sampling}-d{}-seed{}-{precision}",
        r.width, r.max_depth, r.seed
    );
    match (format, args.tile) {
        (Some(f), _) => {
            let picture = matches!(f, Format::Ppm | Format::Png);
            if picture && args.encoding == EncodingArg::Linear {
                name.push_str("-linear");
            }
            if picture && tonemap.exposure() != 0.0 {
                name.push_str(&format!("-ev{}", tonemap.exposure()));
            }
            if picture && tonemap.curve() == ToneCurve::Aces {
                name.push_str("-aces");
            }
            name.push('.');
            name.push_str(f.extension());
        }
        (None, Some((k, n))) => name.push_str(&format!("-tile{k}of{n}.{TILE_EXTENSION}")),
        (None, None) => unreachable!("a render without a format writes a tile"),
    }
    PathBuf::from(name)
}

/// An adaptive render's part of a file name: `e0.01` for a target error, `t30s` for a
/// time budget, then each limit that is not the default (`-min64`, `-max8192`,
/// `-floor0.02`).
fn adaptive_name(a: &Adaptive) -> String {
    let mut parts = Vec::new();
    if let Some(e) = a.target_error {
        parts.push(format!("e{e}"));
    }
    if let Some(t) = a.time_budget {
        parts.push(format!("t{}s", t.as_secs_f64()));
    }
    if a.min_spp != Adaptive::DEFAULT_MIN_SPP {
        parts.push(format!("min{}", a.min_spp));
    }
    if a.max_spp != Adaptive::DEFAULT_MAX_SPP {
        parts.push(format!("max{}", a.max_spp));
    }
    if a.error_floor != Adaptive::DEFAULT_FLOOR {
        parts.push(format!("floor{}", a.error_floor));
    }
    parts.join("-")
}

/// The extension of tile files.
pub const TILE_EXTENSION: &str = "rtile";
