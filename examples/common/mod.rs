//! What every example shares: the options, the thread pool, writing the files and the
//! summary. Each example only builds its scene.

#![allow(dead_code)]

use raytrace::cli::{self, Command, Options, Precision};
use raytrace::image::{write_png, write_ppm};
use raytrace::{EnumScene, Render, ScreenCamera, render};
use std::process::ExitCode;
use std::time::Instant;

/// An example's name, one-line description and default options.
pub struct Example {
    /// The example's name, also the output files' stem.
    pub name: &'static str,
    /// What it renders.
    pub about: &'static str,
    /// Its default options.
    pub defaults: Options,
}

/// Parses the command line over the example's defaults. `Err` carries the exit code
/// after printing the help (success) or the mistake (2).
pub fn options(example: &Example) -> Result<Options, ExitCode> {
    let args = std::env::args().skip(1);
    match cli::parse(example.name, example.about, example.defaults.clone(), args) {
        Ok(Command::Run(o)) => Ok(o),
        Ok(Command::Help(text)) => {
            println!("{text}");
            Err(ExitCode::SUCCESS)
        }
        Err(e) => {
            eprintln!("error: {e}");
            Err(ExitCode::from(2))
        }
    }
}

/// Parses the command line, renders with `render` on the requested number of threads,
/// writes `<out>/<name>.ppm` and `.png`, and prints where they went and what it cost.
pub fn main(example: Example, render: impl FnOnce(&Options) -> raytrace::Result<Render> + Send) -> ExitCode {
    let opts = match options(&example) {
        Ok(o) => o,
        Err(code) => return code,
    };
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
    let mut pool = rayon::ThreadPoolBuilder::new();
    if let Some(t) = opts.threads {
        pool = pool.num_threads(t);
    }
    let pool = pool.build().map_err(|e| {
        raytrace::Error::InvalidSettings(format!("cannot start {:?} threads: {e}", opts.threads))
    })?;
    let rendered = pool.install(|| render(opts))?;
    let samples = rendered.image.to_u16(opts.encoding);
    std::fs::create_dir_all(&opts.out).map_err(|source| raytrace::Error::Io {
        path: opts.out.clone(),
        source,
    })?;
    let ppm = opts.out.join(format!("{name}.ppm"));
    let png = opts.out.join(format!("{name}.png"));
    write_ppm(&ppm, &samples)?;
    write_png(&png, &samples, opts.encoding)?;
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
