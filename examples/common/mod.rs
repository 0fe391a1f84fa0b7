//! What every example shares: the options, the thread pool, writing the files and the
//! summary. Each example only builds its scene.

#![allow(dead_code)]

mod files;
mod options;

pub use options::{Example, Options};
use raytrace::advice::Precision;
use raytrace::{EnumScene, Render, ScreenCamera, render};
use std::process::ExitCode;
use std::time::Instant;

/// Parses the command line over the example's defaults; on `--help` prints the help and
/// exits successfully, on a mistake prints it and exits with code 2.
pub fn options(example: &Example) -> Options {
    example
        .try_parse_from(std::env::args_os())
        .unwrap_or_else(|e| e.exit())
}

/// The worker threads the options ask for (all cores if they name no number): the pool
/// the `raytrace` binary makes too ([`raytrace::cli::pool`]).
pub fn pool(opts: &Options) -> raytrace::Result<rayon::ThreadPool> {
    raytrace::cli::pool(opts.threads)
}

/// Parses the command line, renders with `render` on the requested number of threads,
/// writes `<out>/<name>.ppm` and `.png`, and prints where they went and what it cost. A
/// signal (Ctrl-C, SIGTERM, SIGHUP) stops it without leaving a temporary file.
pub fn main(example: Example, render: impl FnOnce(&Options) -> raytrace::Result<Render> + Send) -> ExitCode {
    let opts = options(&example);
    if let Err(e) = raytrace::cli::clean_up_on_signals(example.name) {
        eprintln!("error: cannot handle signals: {e}");
        return ExitCode::FAILURE;
    }
    match run(example.name, &opts, render) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}

/// A scene built in one scalar.
pub type Build<F> = fn() -> raytrace::Result<EnumScene<F>>;

/// [`main`] for a scene seen by the spec's camera, given its builder in each scalar.
pub fn spec_scene(example: Example, in_f32: Build<f32>, in_f64: Build<f64>) -> ExitCode {
    main(example, |o| {
        let camera = ScreenCamera::with_width(o.width)?;
        let settings = settings(o)?;
        match o.precision {
            Precision::F32 => render(&in_f32()?, &camera, &settings),
            Precision::F64 => render(&in_f64()?, &camera, &settings),
        }
    })
}

fn run(
    name: &str,
    opts: &Options,
    render: impl FnOnce(&Options) -> raytrace::Result<Render> + Send,
) -> raytrace::Result<()> {
    let start = Instant::now();
    let ppm = opts.out.join(format!("{name}.ppm"));
    let png = opts.out.join(format!("{name}.png"));
    // An output that cannot be written fails now, not after the render.
    raytrace::cli::check_output(&ppm)?;
    raytrace::cli::check_output(&png)?;
    raytrace::cli::set_activity(format!("rendering {name}"));
    let rendered = pool(opts)?.install(|| render(opts))?;
    raytrace::cli::set_activity(format!("writing {}", ppm.display()));
    let samples = rendered.image.to_u16(opts.encoding);
    files::write_both(&ppm, &png, &samples, opts.encoding)?;
    println!(
        "{name}: {}×{} pixels, {} spp, max depth {}, {}, seed {}",
        samples.width, samples.height, opts.spp, opts.max_depth, opts.precision, opts.seed
    );
    println!("  wrote {}", ppm.display());
    println!("  wrote {}", png.display());
    println!("  render: {}", rendered.stats);
    println!("  total (render + files): {:.3} s", start.elapsed().as_secs_f64());
    Ok(())
}

/// Render settings from the options (progress bar on, when stderr is a terminal).
pub fn settings(opts: &Options) -> raytrace::Result<raytrace::RenderSettings> {
    let mut s = raytrace::RenderSettings::new(opts.spp, opts.max_depth, opts.seed)?;
    s.progress = true;
    Ok(s)
}
