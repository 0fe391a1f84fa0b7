//! Next-event estimation with MIS against scattered rays alone on the Cornell box: error
//! against samples and against time, with the Monte Carlo rate `1/√N`.
//!
//! `cargo run --release --features studies --example nee_efficiency` renders `scenes/cornell_box.toml`
//! (64 × 64 by default) once as a reference with MIS (`--spp`, default 4096, its own seed)
//! and then with each technique at 1, 2, 4 … 256 samples per pixel, and writes
//! `nee_efficiency.csv` and `nee_efficiency.svg` into `report/figures/` (`--out DIR` to
//! change). The error is the RMSE of the linear radiance against the reference, over every
//! pixel but the light seen directly ([`measured`]); the
//! reference's own noise (its variance is 1/16 of the 256-sample renders') adds a little
//! at the right end. Times are wall-clock render times on the threads given (`--threads`;
//! renders under half a second the fastest of five), so they carry the machine's noise.

#[path = "common/mod.rs"]
mod common;
#[path = "scenes/mod.rs"]
mod scenes;

use common::{Example, Options};
use plotters::coord::Shift;
use plotters::prelude::*;
use raytrace::advice::Precision;
use raytrace::{Float, LightSampling, Renderer};
use raytrace::{Image, Render};
use std::fmt::Write as _;
use std::path::Path;
use std::process::ExitCode;

/// One render of the sweep.
struct Point {
    method: &'static str,
    spp: u32,
    seconds: f64,
    rays: u64,
    rmse: f64,
}

/// The two techniques, as the chart names and colours them.
const METHODS: [(&str, LightSampling, RGBColor); 2] = [
    ("NEE + MIS", LightSampling::Mis, RGBColor(214, 39, 40)),
    ("scattered rays only", LightSampling::Bsdf, RGBColor(31, 119, 180)),
];

/// The pixels the error is measured on: all but the light seen directly and its border
/// (within a pixel of a reference pixel brighter than 1). There a pixel's samples are 18
/// or under 1 by where the jitter falls, antialiasing noise alike for both techniques,
/// which would otherwise dominate both errors.
fn measured(reference: &Image) -> Vec<bool> {
    let (w, h) = (reference.width(), reference.height());
    let bright = |x: usize, y: usize| reference.pixel(x, y).iter().any(|&c| c > 1.0);
    (0..w * h)
        .map(|i| {
            let (x, y) = (i % w, i / w);
            let near = |c: usize, n: usize| c.saturating_sub(1)..=(c + 1).min(n - 1);
            !near(y, h).any(|y| near(x, w).any(|x| bright(x, y)))
        })
        .collect()
}

/// The root-mean-square difference of the linear radiance over the `measured` pixels,
/// every channel.
fn rmse(a: &Image, b: &Image, measured: &[bool]) -> f64 {
    let (mut sum, mut n) = (0.0, 0usize);
    for ((p, q), _) in a
        .pixels()
        .iter()
        .zip(b.pixels())
        .zip(measured)
        .filter(|(_, m)| **m)
    {
        sum += (0..3).map(|k| (p[k] - q[k]).powi(2)).sum::<f64>();
        n += 3;
    }
    (sum / n as f64).sqrt()
}

fn render_in<F: Float>(
    o: &Options,
    spp: u32,
    seed: u64,
    sampling: LightSampling,
) -> raytrace::Result<Render> {
    let (scene, camera, _) = scenes::cornell_box::<F>(o.width)?;
    Renderer::new(&scene, &camera)
        .spp(spp)
        .max_depth(o.max_depth)
        .seed(seed)
        .light_sampling(sampling)
        .render()
}

fn render_one(o: &Options, spp: u32, seed: u64, sampling: LightSampling) -> raytrace::Result<Render> {
    match o.precision {
        Precision::F32 => render_in::<f32>(o, spp, seed, sampling),
        Precision::F64 => render_in::<f64>(o, spp, seed, sampling),
    }
}

fn sweep(o: &Options) -> raytrace::Result<Vec<Point>> {
    let reference = render_one(o, o.spp, o.seed.wrapping_add(1), LightSampling::Mis)?;
    println!("reference: {} spp, {}", o.spp, reference.stats);
    let measured = measured(&reference.image);
    let mut points = Vec::new();
    for spp in (0..=8).map(|k| 1u32 << k) {
        for (method, sampling, _) in METHODS {
            // Short renders are timed as the fastest of five: the same image each time.
            let r = render_one(o, spp, o.seed, sampling)?;
            let mut seconds = r.stats.elapsed.as_secs_f64();
            if seconds < 0.5 {
                for _ in 0..4 {
                    seconds = seconds.min(render_one(o, spp, o.seed, sampling)?.stats.elapsed.as_secs_f64());
                }
            }
            let point = Point {
                method,
                spp,
                seconds,
                rays: r.stats.rays,
                rmse: rmse(&r.image, &reference.image, &measured),
            };
            println!(
                "{method:>20}: {spp:>3} spp, {:.3} s, RMSE {:.4e}",
                point.seconds, point.rmse
            );
            points.push(point);
        }
    }
    Ok(points)
}

type Plot<T> = Result<T, Box<dyn std::error::Error>>;

/// Two panels: error against samples per pixel, and against time.
fn draw(path: &Path, points: &[Point], width: usize) -> Plot<()> {
    let root = SVGBackend::new(path, (1100, 440)).into_drawing_area();
    root.fill(&WHITE)?;
    let (left, right) = root.split_horizontally(550);
    let e_min = points.iter().map(|p| p.rmse).fold(f64::INFINITY, f64::min) * 0.5;
    let e_max = points.iter().map(|p| p.rmse).fold(0.0, f64::max) * 2.0;
    let t_min = points.iter().map(|p| p.seconds).fold(f64::INFINITY, f64::min) * 0.5;
    let t_max = points.iter().map(|p| p.seconds).fold(0.0, f64::max) * 2.0;
    let caption = |what: &str| format!("{what} (Cornell box, {width}×{width})");
    let per_sample = Axis {
        caption: caption("error vs samples per pixel"),
        name: "samples per pixel",
        range: (0.7, 400.0),
        of: |p| f64::from(p.spp),
    };
    panel(&left, &per_sample, points, (e_min, e_max))?;
    let per_second = Axis {
        caption: caption("error vs render time"),
        name: "seconds",
        range: (t_min, t_max),
        of: |p| p.seconds,
    };
    panel(&right, &per_second, points, (e_min, e_max))?;
    root.present()?;
    Ok(())
}

/// A panel's x axis: its caption and name, its range, and each point's value on it.
struct Axis {
    caption: String,
    name: &'static str,
    range: (f64, f64),
    of: fn(&Point) -> f64,
}

/// Error (log) against `x` (log), each technique with the line `1/√x` through its last
/// point, the one measured best.
fn panel(area: &DrawingArea<SVGBackend<'_>, Shift>, x: &Axis, points: &[Point], e: (f64, f64)) -> Plot<()> {
    let mut chart = ChartBuilder::on(area)
        .caption(&x.caption, ("sans-serif", 16))
        .margin(10)
        .x_label_area_size(35)
        .y_label_area_size(65)
        .build_cartesian_2d((x.range.0..x.range.1).log_scale(), (e.0..e.1).log_scale())?;
    chart
        .configure_mesh()
        .x_desc(x.name)
        .y_desc("RMSE of linear radiance vs reference")
        .y_label_formatter(&|y| format!("{y:.0e}"))
        .draw()?;
    for (method, _, colour) in METHODS {
        let series: Vec<(f64, f64)> = points
            .iter()
            .filter(|p| p.method == method)
            .map(|p| ((x.of)(p), p.rmse))
            .collect();
        let (first, (xb, eb)) = (series[0].0, series[series.len() - 1]);
        let ideal = (0..=40).map(|k| first * (xb / first).powf(f64::from(k) / 40.0));
        let ideal: Vec<(f64, f64)> = ideal.map(|x| (x, eb * (xb / x).sqrt())).collect();
        chart.draw_series(LineSeries::new(ideal, colour.mix(0.35).stroke_width(1)))?;
        chart
            .draw_series(LineSeries::new(series.clone(), colour.stroke_width(2)))?
            .label(method)
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 15, y)], colour.stroke_width(2)));
        chart.draw_series(series.into_iter().map(|p| Circle::new(p, 4, colour.filled())))?;
    }
    chart
        .draw_series(std::iter::empty::<Circle<(f64, f64), i32>>())?
        .label("1/√N through the last point")
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 15, y)], BLACK.mix(0.35)));
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::LowerLeft)
        .border_style(BLACK)
        .background_style(WHITE.mix(0.8))
        .draw()?;
    Ok(())
}

/// `σ²·t` of a technique, the inverse of its efficiency, from its largest render: the
/// variance (RMSE², which falls as `1/N`) times the time it took.
fn cost(points: &[Point], method: &str) -> f64 {
    let p = points
        .iter()
        .rfind(|p| p.method == method)
        .expect("a point per method");
    p.rmse * p.rmse * p.seconds
}

fn run(o: &Options) -> raytrace::Result<()> {
    let points = common::pool(o)?.install(|| sweep(o))?;
    let mut csv = String::from("method,spp,seconds,rays,rmse\n");
    for p in &points {
        let _ = writeln!(
            csv,
            "{},{},{:.6},{},{:.6e}",
            p.method, p.spp, p.seconds, p.rays, p.rmse
        );
    }
    std::fs::create_dir_all(&o.out).map_err(|source| raytrace::Error::Io {
        path: o.out.clone(),
        source,
    })?;
    let csv_path = o.out.join("nee_efficiency.csv");
    raytrace::image::write_atomic(&csv_path, |w| std::io::Write::write_all(w, csv.as_bytes()))?;
    let svg = o.out.join("nee_efficiency.svg");
    draw(&svg, &points, o.width)
        .map_err(|e| raytrace::Error::InvalidSettings(format!("{}: {e}", svg.display())))?;
    let ratio = cost(&points, METHODS[1].0) / cost(&points, METHODS[0].0);
    println!("NEE + MIS is {ratio:.1}× as efficient (1/σ²t) at 256 spp");
    println!("wrote {} and {}", csv_path.display(), svg.display());
    Ok(())
}

fn main() -> ExitCode {
    let mut defaults = Options::defaults(64, 4096, 8);
    defaults.precision = Precision::F32;
    defaults.out = "report/figures".into();
    let example = Example {
        name: "nee_efficiency",
        about: "Error against time on the Cornell box: NEE + MIS against scattered rays alone \
                (--spp is the reference's samples per pixel)",
        defaults,
    };
    let o = common::options(&example);
    match run(&o) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}
