//! The equal-time chart: per scene, relative squared error against render time, uniform
//! and adaptive, both axes logarithmic.

use crate::Run;
use plotters::prelude::*;
use std::path::Path;

type Plot<T> = Result<T, Box<dyn std::error::Error>>;

const UNIFORM: RGBColor = RGBColor(120, 120, 120);
const ADAPTIVE: RGBColor = RGBColor(214, 39, 40);

/// Writes the chart to `path`: one panel per scene, three to a row.
pub fn draw(path: &Path, runs: &[Run]) -> Plot<()> {
    if let Some(dir) = path.parent() {
        std::fs::create_dir_all(dir)?;
    }
    let mut scenes: Vec<&str> = runs.iter().map(|r| r.scene).collect();
    scenes.dedup();
    let cols = 3;
    let rows = scenes.len().div_ceil(cols);
    let root = SVGBackend::new(path, (1200, 300 * rows as u32 + 40)).into_drawing_area();
    root.fill(&WHITE)?;
    let (title, body) = root.split_vertically(40);
    title.titled(
        "relative squared error against time: uniform (grey) and adaptive with a time budget (red)",
        ("sans-serif", 18),
    )?;
    for (panel, scene) in body.split_evenly((rows, cols)).iter().zip(&scenes) {
        let mine: Vec<&Run> = runs.iter().filter(|r| r.scene == *scene).collect();
        let series = |method: &str| -> Vec<(f64, f64)> {
            mine.iter()
                .filter(|r| r.method == method && r.rel_mse > 0.0)
                .map(|r| (r.seconds, r.rel_mse))
                .collect()
        };
        let (uniform, adaptive) = (series("uniform"), series("adaptive"));
        let all = || uniform.iter().chain(&adaptive);
        let (t_min, t_max) = all().fold((f64::INFINITY, 0.0f64), |(a, b), p| (a.min(p.0), b.max(p.0)));
        let (e_min, e_max) = all().fold((f64::INFINITY, 0.0f64), |(a, b), p| (a.min(p.1), b.max(p.1)));
        if !(t_min.is_finite() && e_min.is_finite()) {
            continue;
        }
        // The ratio at the largest budget, in the caption.
        let last = mine
            .iter()
            .filter(|r| r.method == "adaptive")
            .max_by_key(|r| r.level)
            .and_then(|a| {
                mine.iter()
                    .find(|u| u.method == "uniform" && u.level == a.level)
                    .map(|u| u.rel_mse / a.rel_mse)
            });
        let caption = match last {
            Some(ratio) => format!("{scene}: {ratio:.2}× lower at the longest time"),
            None => (*scene).to_string(),
        };
        let mut chart = ChartBuilder::on(panel)
            .caption(caption, ("sans-serif", 15))
            .margin(8)
            .x_label_area_size(32)
            .y_label_area_size(58)
            .build_cartesian_2d(
                (t_min * 0.8..t_max * 1.25).log_scale(),
                (e_min * 0.7..e_max * 1.4).log_scale(),
            )?;
        chart
            .configure_mesh()
            .x_desc("seconds")
            .y_desc("rel. squared error")
            .x_label_formatter(&|x| format!("{x:.2}"))
            .y_label_formatter(&|y| format!("{y:.0e}"))
            .label_style(("sans-serif", 11))
            .draw()?;
        for (points, colour, label) in [(uniform, UNIFORM, "uniform"), (adaptive, ADAPTIVE, "adaptive")] {
            chart
                .draw_series(LineSeries::new(points.clone(), colour.stroke_width(2)))?
                .label(label)
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 15, y)], colour.stroke_width(2)));
            chart.draw_series(points.iter().map(|&p| Circle::new(p, 4, colour.filled())))?;
        }
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::UpperRight)
            .background_style(WHITE.mix(0.8))
            .border_style(BLACK)
            .label_font(("sans-serif", 11))
            .draw()?;
    }
    root.present()?;
    Ok(())
}
