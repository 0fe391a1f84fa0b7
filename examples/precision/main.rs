//! The accuracy study: every scene of [`cases`] rendered in f32 and f64, with the stable
//! and the textbook intersection (and the stable one spawning the textbook way), each compared with a double-double reference along the
//! same random stream; then a convergence run of a Monte Carlo scene.
//!
//! `cargo run --release --features studies --example precision` writes `precision.csv` and the SVG charts
//! into `report/figures/` (`--out DIR` to change), and prints the per-scene advice.
//! `--spp` and `--max-depth` apply to the Monte Carlo cases and the convergence run; the
//! mirror scenes always use one ray per pixel centre and their own depth. `--precision`
//! is accepted and ignored: the study runs every scalar.

#[path = "../common/mod.rs"]
mod common;
#[path = "../scenes/mod.rs"]
mod scenes;

mod cases;
mod charts;
mod textbook;

use cases::{Cam, Case};
use common::Options;
use raytrace::metrics::ImageError;
use raytrace::prelude::*;
use raytrace::{Image, Render};
use std::fmt::Write as _;
use std::process::ExitCode;

/// One render of the study, measured against its reference.
pub struct Row {
    /// Scene name.
    pub scene: String,
    /// `f32`, `f64` or `dd`.
    pub scalar: &'static str,
    /// `stable`, `textbook` or `no-offset` (stable, spawned the textbook way).
    pub method: &'static str,
    /// Rays traced.
    pub rays: u64,
    /// Best wall time of the repeats, seconds.
    pub seconds: f64,
    /// Error against the reference.
    pub error: ImageError,
}

/// How the study's spheres are intersected and spawn their rays.
#[derive(Clone, Copy)]
enum Method {
    /// The library's.
    Stable,
    /// The textbook's ([`textbook::TextbookSphere`]).
    Textbook,
    /// The library's roots, the textbook's spawn ([`textbook::UnoffsetSphere`]).
    NoOffset,
}

impl Method {
    fn name(self) -> &'static str {
        match self {
            Self::Stable => "stable",
            Self::Textbook => "textbook",
            Self::NoOffset => "no-offset",
        }
    }
}

/// Renders `case` in scalar `F`, its spheres intersected by `method`.
fn render_case<F: Float>(case: &Case, method: Method, seed: u64) -> raytrace::Result<Render> {
    let scene = case.scene.cast::<F>()?;
    match method {
        Method::Stable => render_scene(case, &scene, seed),
        Method::Textbook => render_scene(case, &textbook::to_textbook(&scene), seed),
        Method::NoOffset => render_scene(case, &textbook::to_unoffset(&scene), seed),
    }
}

/// Renders `scene`, a case's scene in scalar `F`, with the case's camera and settings.
fn render_scene<F: Float, S: Layout<F> + Sync>(
    case: &Case,
    scene: &Scene<F, S, MaterialKind<F>>,
    seed: u64,
) -> raytrace::Result<Render> {
    let settings = RenderSettings::new(case.spp, case.max_depth, seed)?;
    match case.camera {
        Cam::Screen(c) => render(scene, &c, &settings),
        Cam::LookAt(c) => render(scene, &c.cast::<F>(), &settings),
    }
}

/// The best of `repeats` renders (the image is the same every time; the time varies).
fn timed<F: Float>(case: &Case, method: Method, seed: u64, repeats: usize) -> raytrace::Result<Render> {
    let mut best = render_case::<F>(case, method, seed)?;
    for _ in 1..repeats {
        let r = render_case::<F>(case, method, seed)?;
        if r.stats.elapsed < best.stats.elapsed {
            best = r;
        }
    }
    Ok(best)
}

fn study_case(case: &Case, seed: u64, rows: &mut Vec<Row>) -> raytrace::Result<()> {
    let reference: Image = if case.dd_reference {
        render_case::<raytrace::DoubleDouble>(case, Method::Stable, seed)?.image
    } else {
        render_case::<f64>(case, Method::Stable, seed)?.image
    };
    // The no-offset runs only explain the other two (their time is not charted): one each.
    let runs: [(&'static str, Method, Render); 6] = [
        (
            "f32",
            Method::Stable,
            timed::<f32>(case, Method::Stable, seed, 3)?,
        ),
        (
            "f64",
            Method::Stable,
            timed::<f64>(case, Method::Stable, seed, 3)?,
        ),
        (
            "f32",
            Method::Textbook,
            timed::<f32>(case, Method::Textbook, seed, 3)?,
        ),
        (
            "f64",
            Method::Textbook,
            timed::<f64>(case, Method::Textbook, seed, 3)?,
        ),
        (
            "f32",
            Method::NoOffset,
            timed::<f32>(case, Method::NoOffset, seed, 1)?,
        ),
        (
            "f64",
            Method::NoOffset,
            timed::<f64>(case, Method::NoOffset, seed, 1)?,
        ),
    ];
    for (scalar, method, r) in runs {
        rows.push(Row {
            scene: case.name.clone(),
            scalar,
            method: method.name(),
            rays: r.stats.rays,
            seconds: r.stats.elapsed.as_secs_f64(),
            error: ImageError::between(&r.image, &reference, Encoding::Srgb)?,
        });
    }
    Ok(())
}

fn csv(cases: &[Case], rows: &[Row], width: usize) -> String {
    let mut out = String::from(
        "scene,reference,scalar,method,width,height,spp,max_depth,rays,seconds,mrays_per_s,rmse,max_error,psnr_db,share_over_one_step\n",
    );
    for r in rows {
        let c = cases.iter().find(|c| c.name == r.scene).expect("row of a case");
        let height = match c.camera {
            Cam::Screen(s) => Camera::<f64>::height(&s),
            Cam::LookAt(l) => l.height(),
        };
        let _ = writeln!(
            out,
            "{},{},{},{},{},{},{},{},{},{:.6},{:.3},{:.3e},{:.3e},{:.2},{:.5}",
            r.scene,
            if c.dd_reference { "dd" } else { "f64-stable" },
            r.scalar,
            r.method,
            width,
            height,
            c.spp,
            c.max_depth,
            r.rays,
            r.seconds,
            r.rays as f64 / r.seconds / 1e6,
            r.error.rmse,
            r.error.max,
            r.error.psnr,
            r.error.over_one_step
        );
    }
    out
}

fn run(o: &Options) -> raytrace::Result<()> {
    let io = |path: &std::path::Path| {
        let path = path.to_path_buf();
        move |source| raytrace::Error::Io { path, source }
    };
    std::fs::create_dir_all(&o.out).map_err(io(&o.out))?;
    let mut cases = cases::all(o.width, o.seed)?;
    for c in cases.iter_mut().filter(|c| c.spp > 1) {
        c.spp = o.spp;
        c.max_depth = o.max_depth;
    }
    let mut rows = Vec::new();
    println!(
        "{:<15} {:<13} {:>9} {:>10} {:>10} {:>8} {:>8}",
        "scene", "run", "ms", "RMSE", "max", "PSNR", ">1 step"
    );
    for case in &cases {
        study_case(case, o.seed, &mut rows)?;
        for r in rows.iter().filter(|r| r.scene == case.name) {
            println!(
                "{:<15} {:<13} {:>9.2} {:>10.2e} {:>10.2e} {:>8.1} {:>7.3}%",
                r.scene,
                format!("{}/{}", r.scalar, r.method),
                r.seconds * 1e3,
                r.error.rmse,
                r.error.max,
                r.error.psnr,
                100.0 * r.error.over_one_step
            );
        }
    }
    println!("\nAdvice (stable method; cheapest scalar within one 8-bit step on 99 % of pixels):");
    for case in &cases {
        let f32_ok = rows.iter().any(|r| {
            r.scene == case.name && r.scalar == "f32" && r.method == "stable" && r.error.within_one_step()
        });
        println!(
            "  {:<15} {}   ({})",
            case.name,
            if f32_ok { "f32" } else { "f64" },
            case.about
        );
    }
    let csv_path = o.out.join("precision.csv");
    raytrace::image::write_atomic(&csv_path, |w| {
        std::io::Write::write_all(w, csv(&cases, &rows, o.width).as_bytes())
    })?;
    let chart = o.out.join("precision_time_vs_error.svg");
    charts::time_vs_error(&chart, &cases, &rows)
        .map_err(|e| raytrace::Error::InvalidSettings(format!("{}: {e}", chart.display())))?;
    let conv = charts::convergence(o)?;
    println!(
        "\nwrote {}\nwrote {}\nwrote {}",
        csv_path.display(),
        chart.display(),
        conv.display()
    );
    Ok(())
}

fn main() -> ExitCode {
    let mut defaults = Options::defaults(400, 4, 50);
    defaults.out = "report/figures".into();
    let about = "The accuracy study: f32 and f64, stable and textbook intersection, against a double-double reference.";
    let example = common::Example {
        name: "precision",
        about,
        defaults,
    };
    let o = common::options(&example);
    match common::pool(&o).and_then(|pool| pool.install(|| run(&o))) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}
