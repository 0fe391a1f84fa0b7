//! What every example shares: the options, the thread pool, writing the files and the
//! summary. Each example only builds its scene.

#![allow(dead_code)]

use raytrace::Render;
use raytrace::cli::{self, Command, Options};
use raytrace::image::{write_png, write_ppm};
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

/// Parses the command line, renders with `render` on the requested number of threads,
/// writes `<out>/<name>.ppm` and `.png`, and prints where they went and what it cost.
pub fn main(example: Example, render: impl FnOnce(&Options) -> raytrace::Result<Render> + Send) -> ExitCode {
    let opts = match cli::parse(
        example.name,
        example.about,
        example.defaults,
        std::env::args().skip(1),
    ) {
        Ok(Command::Run(o)) => o,
        Ok(Command::Help(text)) => {
            println!("{text}");
            return ExitCode::SUCCESS;
        }
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::from(2);
        }
    };
    match run(example.name, &opts, render) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
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
