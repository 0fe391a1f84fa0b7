//! The study's SVG charts: speed against accuracy per scene, and Monte Carlo convergence.

use crate::cases::Case;
use crate::common::Options;
use crate::{Row, scenes};
use plotters::prelude::*;
use raytrace::metrics::ImageError;
use raytrace::{Encoding, RenderSettings, ScreenCamera, render};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

type Plot<T> = Result<T, Box<dyn std::error::Error>>;

/// Errors of zero (identical images) are drawn at this floor on the log axis.
const FLOOR: f64 = 1e-17;

/// The colour and label of a (scalar, method) run.
fn style(scalar: &str, method: &str) -> (RGBColor, String) {
    let colour = match (scalar, method) {
        ("f32", "stable") => RGBColor(31, 119, 180),
        ("f64", "stable") => RGBColor(214, 39, 40),
        ("f32", _) => RGBColor(140, 190, 230),
        _ => RGBColor(240, 150, 150),
    };
    (colour, format!("{scalar} {method}"))
}

/// One panel per scene: render time (x) against RMSE to the reference (y, log), one point
/// per (scalar, method).
pub fn time_vs_error(path: &Path, cases: &[Case], rows: &[Row]) -> Plot<()> {
    let cols = 3;
    let rows_n = cases.len().div_ceil(cols);
    let root = SVGBackend::new(path, (1200, 330 * rows_n as u32)).into_drawing_area();
    root.fill(&WHITE)?;
    let panels = root.split_evenly((rows_n, cols));
    for (panel, case) in panels.iter().zip(cases) {
        // The two methods; the no-offset runs are in the CSV only.
        let mine: Vec<&Row> = rows
            .iter()
            .filter(|r| r.scene == case.name && r.method != "no-offset")
            .collect();
        let ms = |r: &Row| r.seconds * 1e3;
        let t_max = mine.iter().map(|r| ms(r)).fold(0.0, f64::max) * 1.15;
        let e_max = mine.iter().map(|r| r.error.rmse).fold(1e-6, f64::max) * 10.0;
        let mut chart = ChartBuilder::on(panel)
            .caption(&case.name, ("sans-serif", 18))
            .margin(10)
            .x_label_area_size(35)
            .y_label_area_size(60)
            .build_cartesian_2d(0.0..t_max, (FLOOR..e_max).log_scale())?;
        chart
            .configure_mesh()
            .x_desc("render time (ms)")
            .y_desc("RMSE vs reference (0 drawn at 1e-17)")
            .y_label_formatter(&|y| format!("{y:.0e}"))
            .draw()?;
        for r in &mine {
            let (colour, label) = style(r.scalar, r.method);
            let point = (ms(r), r.error.rmse.max(FLOOR));
            chart
                .draw_series([Circle::new(point, 6, colour.filled())])?
                .label(label)
                .legend(move |(x, y)| Circle::new((x, y), 5, colour.filled()));
        }
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::LowerLeft)
            .background_style(WHITE.mix(0.8))
            .border_style(BLACK)
            .label_font(("sans-serif", 12))
            .draw()?;
    }
    root.present()?;
    Ok(())
}

/// Error against a converged reference as the samples per pixel grow, for f32 and f64,
/// on the matte scene; also against time. Writes `convergence.svg` and `convergence.csv`.
pub fn convergence(o: &Options) -> raytrace::Result<PathBuf> {
    let camera = ScreenCamera::with_width(o.width)?;
    let scene = scenes::matte_spheres::<f64>()?;
    let reference = render(
        &scene,
        &camera,
        &RenderSettings::new(1024, o.max_depth, o.seed + 1)?,
    )?
    .image;
    let mut points: Vec<(&'static str, u32, f64, f64)> = Vec::new();
    for spp in (0..=8).map(|k| 1u32 << k) {
        let settings = RenderSettings::new(spp, o.max_depth, o.seed)?;
        let r32 = render(&scene.cast::<f32>()?, &camera, &settings)?;
        let r64 = render(&scene, &camera, &settings)?;
        for (name, r) in [("f32", r32), ("f64", r64)] {
            let e = ImageError::between(&r.image, &reference, Encoding::Srgb)?;
            points.push((name, spp, r.stats.elapsed.as_secs_f64(), e.rmse));
        }
    }
    let mut csv = String::from("scalar,spp,seconds,rmse\n");
    for (s, n, t, e) in &points {
        let _ = writeln!(csv, "{s},{n},{t:.6},{e:.4e}");
    }
    let csv_path = o.out.join("convergence.csv");
    raytrace::image::write_atomic(&csv_path, |w| std::io::Write::write_all(w, csv.as_bytes()))?;
    let path = o.out.join("convergence.svg");
    draw_convergence(&path, &points)
        .map_err(|e| raytrace::Error::InvalidSettings(format!("{}: {e}", path.display())))?;
    Ok(path)
}

fn draw_convergence(path: &Path, points: &[(&'static str, u32, f64, f64)]) -> Plot<()> {
    let root = SVGBackend::new(path, (1100, 420)).into_drawing_area();
    root.fill(&WHITE)?;
    let (left, right) = root.split_horizontally(550);
    let e_min = points.iter().map(|p| p.3).fold(f64::INFINITY, f64::min) * 0.5;
    let e_max = points.iter().map(|p| p.3).fold(0.0, f64::max) * 2.0;
    let first = points
        .iter()
        .find(|p| p.0 == "f64" && p.1 == 1)
        .map_or(e_max, |p| p.3);
    // Error against samples per pixel, with the Monte Carlo rate 1/√N through the first point.
    let mut chart = ChartBuilder::on(&left)
        .caption("error vs samples per pixel (matte_spheres)", ("sans-serif", 16))
        .margin(10)
        .x_label_area_size(35)
        .y_label_area_size(60)
        .build_cartesian_2d((1.0..300.0).log_scale(), (e_min..e_max).log_scale())?;
    chart
        .configure_mesh()
        .x_desc("samples per pixel")
        .y_desc("RMSE vs 1024 spp")
        .draw()?;
    let ideal: Vec<(f64, f64)> = (0..=8)
        .map(|k| f64::from(1u32 << k))
        .map(|n| (n, first / n.sqrt()))
        .collect();
    chart
        .draw_series(LineSeries::new(ideal, BLACK.stroke_width(1)))?
        .label("1/√N")
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 15, y)], BLACK));
    for scalar in ["f32", "f64"] {
        let (colour, _) = style(scalar, "stable");
        let series: Vec<(f64, f64)> = points
            .iter()
            .filter(|p| p.0 == scalar)
            .map(|p| (f64::from(p.1), p.3))
            .collect();
        chart
            .draw_series(LineSeries::new(series.clone(), colour.stroke_width(2)))?
            .label(scalar)
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 15, y)], colour.stroke_width(2)));
        chart.draw_series(series.into_iter().map(|p| Circle::new(p, 4, colour.filled())))?;
    }
    chart
        .configure_series_labels()
        .border_style(BLACK)
        .background_style(WHITE.mix(0.8))
        .draw()?;
    // Error against time.
    let t_min = points.iter().map(|p| p.2).fold(f64::INFINITY, f64::min) * 0.5;
    let t_max = points.iter().map(|p| p.2).fold(0.0, f64::max) * 2.0;
    let mut chart = ChartBuilder::on(&right)
        .caption("error vs render time", ("sans-serif", 16))
        .margin(10)
        .x_label_area_size(35)
        .y_label_area_size(60)
        .build_cartesian_2d((t_min..t_max).log_scale(), (e_min..e_max).log_scale())?;
    chart
        .configure_mesh()
        .x_desc("seconds")
        .y_desc("RMSE vs 1024 spp")
        .draw()?;
    for scalar in ["f32", "f64"] {
        let (colour, _) = style(scalar, "stable");
        let series: Vec<(f64, f64)> = points
            .iter()
            .filter(|p| p.0 == scalar)
            .map(|p| (p.2, p.3))
            .collect();
        chart
            .draw_series(LineSeries::new(series.clone(), colour.stroke_width(2)))?
            .label(scalar)
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 15, y)], colour.stroke_width(2)));
        chart.draw_series(series.into_iter().map(|p| Circle::new(p, 4, colour.filled())))?;
    }
    chart
        .configure_series_labels()
        .border_style(BLACK)
        .background_style(WHITE.mix(0.8))
        .draw()?;
    root.present()?;
    Ok(())
}
