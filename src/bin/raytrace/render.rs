//! `raytrace render`: a scene file, the command line's overrides, one image or tile.

use crate::Failure;
use crate::args::{PrecisionArg, QualityArg, RenderArgs};
use crate::names;
use crate::output::{self, Target};
use raytrace::advice::Precision;
use raytrace::cli::check_memory;
use raytrace::error::Field;
use raytrace::image::TileHeader;
use raytrace::scene_file::{FilePrecision, SceneFile, advise_precision};
use raytrace::{Camera, Error, Float, Rect, Render, Renderer, Result};

/// Loads the scene, applies the overrides, checks the output before rendering, renders
/// and writes.
///
/// # Errors
/// A value the command line gave that the scene cannot take (an odd `--width` for the
/// spec's camera) is a usage error naming the option; anything else a failure.
pub fn run(args: &RenderArgs) -> Result<(), Failure> {
    let (mut file, imported) = crate::inspect::load(&args.scene, &args.define)?;
    for warning in imported.iter().flat_map(|i| &i.warnings) {
        eprintln!("warning: {}: {warning}", crate::inspect::differs(&args.scene));
    }
    override_settings(&mut file, args)?;
    render(args, &file).map_err(|e| blame_option(e, args))
}

/// The precision resolved, the output checked, the render and its file.
fn render(args: &RenderArgs, file: &SceneFile) -> Result<()> {
    let precision = match file.render().precision {
        FilePrecision::F32 => Precision::F32,
        FilePrecision::F64 => Precision::F64,
        FilePrecision::Auto => {
            let advice = advise_precision(file)?;
            eprintln!("precision auto: {} ({})", advice.recommended, summary(&advice));
            advice.recommended
        }
    };
    let target = Target::for_render(args, file, precision)?;
    target.check_writable()?;
    // Hashed before the build reads the meshes: a tile names the files it was made from.
    let hash = args.tile.map(|_| output::scene_hash(file));
    let pool = output::pool(args.threads)?;
    let (render, camera) = pool.install(|| match precision {
        Precision::F32 => render_in::<f32>(file, args),
        Precision::F64 => render_in::<f64>(file, args),
    })?;
    let adaptive = names::adaptive_of(args);
    let settings = names::describe(file.render(), adaptive.as_ref(), precision);
    let mut beside = None;
    match args.tile {
        None => beside = target.write_image(&render.image, &render.layers())?,
        Some(_) => {
            let header = TileHeader {
                scene: hash.transpose()?.unwrap_or_default(),
                settings: settings.clone(),
                image_width: camera.0,
                image_height: camera.1,
                rect: tile_rect(args, camera.0, camera.1)?,
            };
            target.write_tile(&header, &render.image)?;
        }
    }
    target.say(&format!(
        "wrote {}: {}×{} pixels, {settings}: {}",
        target.name(),
        render.image.width(),
        render.image.height(),
        render.stats
    ));
    if let Some(c) = &render.convergence {
        target.say(&c.summary().to_string());
    }
    if let Some(path) = beside {
        target.say(&format!("wrote {}: the layers", path.display()));
    } else if render.convergence.is_some() && args.tile.is_none() && target.name() == "standard output" {
        eprintln!("note: the sample-count and error maps are not written: --out - is not an EXR");
    }
    Ok(())
}

/// An error about a value the command line set, as a usage error naming the option: the
/// error's typed field says which value it was.
fn blame_option(e: Error, args: &RenderArgs) -> Failure {
    if let Error::SceneFile {
        message,
        field: Some(field),
        ..
    } = &e
    {
        let option = match field {
            Field::ImageWidth | Field::ImageSize => args.width.map(|w| ("--width", w.to_string())),
            Field::SamplesPerPixel => args.spp.map(|n| ("--spp", n.to_string())),
            Field::MaxDepth => args.max_depth.map(|d| ("--max-depth", d.to_string())),
            Field::Exposure => args.exposure.map(|s| ("--exposure", s.to_string())),
            _ => None,
        };
        if let Some((option, value)) = option {
            return Failure::Usage(format!("invalid value '{value}' for '{option}': {message}"));
        }
    }
    Failure::Work(e)
}

/// The command line's values replace the scene file's.
fn override_settings(file: &mut SceneFile, args: &RenderArgs) -> Result<(), Failure> {
    let r = file.render_mut();
    if let Some(w) = args.width {
        r.width = usize::try_from(w)
            .map_err(|_| Failure::Usage(format!("invalid value '{w}' for '--width': too large")))?;
    }
    if let Some(spp) = args.spp {
        r.spp = spp;
    }
    if let Some(d) = args.max_depth {
        r.max_depth = d;
    }
    if let Some(s) = args.seed {
        r.seed = s;
    }
    if let Some(s) = args.exposure {
        r.exposure = s;
    }
    if let Some(t) = args.tonemap {
        r.tonemap = t.curve();
    }
    if let Some(q) = args.bvh_quality {
        r.bvh_quality = match q {
            QualityArg::Medium => raytrace::BvhQuality::Medium,
            QualityArg::High => raytrace::BvhQuality::High,
        };
    }
    if let Some(p) = args.precision {
        r.precision = match p {
            PrecisionArg::F32 => FilePrecision::F32,
            PrecisionArg::F64 => FilePrecision::F64,
            PrecisionArg::Auto => FilePrecision::Auto,
        };
    }
    Ok(())
}

/// Builds the scene in `F` and renders it (or the tile asked for). Also returns the whole
/// image's size.
fn render_in<F: Float>(file: &SceneFile, args: &RenderArgs) -> Result<(Render, (usize, usize))> {
    let built = file.build::<F>()?;
    for w in file.warnings() {
        eprintln!("warning: {}: {w}", file.path().display());
    }
    for note in &built.summary.notes {
        eprintln!("warning: {note}");
    }
    if built.summary.skipped_degenerate > 0 {
        eprintln!(
            "note: skipped {} mesh faces without area",
            built.summary.skipped_degenerate
        );
    }
    let (width, height) = (built.camera.width(), built.camera.height());
    let tile = tile_rect(args, width, height)?;
    check_memory(tile.width, tile.height)?;
    let mut settings = built.settings;
    settings.progress = !args.quiet;
    let render = Renderer::new(&built.scene, &built.camera)
        .settings(settings)
        .adaptive(names::adaptive_of(args))
        .aov(args.aov)
        .tile(tile)
        .render()?;
    Ok((render, (width, height)))
}

/// The region to render: tile `K/N` of the image, or all of it.
fn tile_rect(args: &RenderArgs, width: usize, height: usize) -> Result<Rect> {
    match args.tile {
        Some((k, n)) => Rect::tile(k - 1, n, width, height),
        None => Ok(Rect::full(width, height)),
    }
}

/// The advice in a few words: each scalar's share of pixels off by more than one step,
/// or why f32 was not tried.
fn summary(advice: &raytrace::advice::Advice) -> String {
    match &advice.f32 {
        Some(f32) => format!(
            "f32 {:.3} %, f64 {:.3} % of pixels more than one 8-bit step off",
            100.0 * f32.error.over_one_step,
            100.0 * advice.f64.error.over_one_step
        ),
        None => advice.reason.to_string(),
    }
}
