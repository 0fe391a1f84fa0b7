//! The report's failure figures: the accuracy study's scenes where a textbook method fails,
//! rendered with the textbook method and with the library's, beside their reference.
//!
//! Writes into `report/figures/failures/` (or the folder given as the only argument):
//! - `<case>-<run>.png`: the renders the report shows (16-bit sRGB PNG), and
//!   `<case>-<run>-diff.png`: the reference dimmed to grey with every pixel off by more than
//!   one 8-bit step in red;
//! - `failures.csv`: per render, its error against the double-double reference (the study's
//!   measures).
//!
//! The cases, scenes and settings are the accuracy study's own (`examples/precision`, at
//! 400×200, seed 0, 4 spp and depth 50 for the Monte Carlo case), so the shares printed
//! here are those of `report/figures/precision.csv`; one more case, `self_hit`, renders the
//! spec's four mirrors with the textbook intersection and *no* `t_min` (rays leave from the
//! rounded hit point), which the study does not run.
//!
//! Run from the repository root:
//! `CARGO_TARGET_DIR=target cargo run --release --manifest-path report/failures/Cargo.toml`

#[path = "../../../examples/scenes/mod.rs"]
mod scenes;

#[allow(dead_code)]
#[path = "../../../examples/precision/cases.rs"]
mod cases;

#[path = "../../../examples/precision/textbook.rs"]
mod textbook;

use cases::{Cam, Case};
use raytrace::metrics::ImageError;
use raytrace::prelude::*;
use raytrace::shape::{Hit, textbook_sphere_hit};
use raytrace::{DoubleDouble, Image, Scene};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

const WIDTH: usize = 400;
const SEED: u64 = 0;

/// The textbook sphere with `t_min = 0`: the hit point is `O + tD` rounded, with no error
/// bound, so a spawned ray starts exactly there (the "shadow acne" set-up).
#[derive(Clone, Copy, Debug)]
struct NoTMinSphere<F>(Sphere<F>);

impl<F: Float> Hittable<F> for NoTMinSphere<F> {
    fn hit(&self, ray: &Ray<F>, t_max: F) -> Option<Hit<F>> {
        textbook_sphere_hit(&self.0, ray, F::zero(), t_max)
    }
}

/// One render of a case, by scalar and method.
fn render_case<F: Float>(case: &Case, textbook: bool) -> raytrace::Result<Image> {
    let scene = case.scene.cast::<F>()?;
    if textbook {
        render_scene(case, &textbook::to_textbook(&scene))
    } else {
        render_scene(case, &scene)
    }
}

/// Renders `scene`, a case's scene in scalar `F`, with the case's camera and settings.
fn render_scene<F: Float, S: Hittable<F> + Sync>(
    case: &Case,
    scene: &Scene<F, S, MaterialKind<F>>,
) -> raytrace::Result<Image> {
    let settings = RenderSettings::new(case.spp, case.max_depth, SEED)?;
    Ok(match case.camera {
        Cam::Screen(c) => render(scene, &c, &settings)?.image,
        Cam::LookAt(c) => render(scene, &c.cast::<F>(), &settings)?.image,
    })
}

/// The spec's four mirrors in `F` with every sphere intersected with `t_min = 0`.
fn render_no_t_min<F: Float>(case: &Case) -> raytrace::Result<Image> {
    let scene = case.scene.cast::<F>()?;
    let mut naive: Scene<F, NoTMinSphere<F>, MaterialKind<F>> = Scene::new(*scene.background());
    for o in scene.objects() {
        let ShapeKind::Sphere(s) = o.shape else {
            unreachable!("four_mirrors holds spheres only")
        };
        naive.add(NoTMinSphere(s), o.material);
    }
    let Cam::Screen(camera) = case.camera else {
        unreachable!("four_mirrors uses the spec's camera")
    };
    let settings = RenderSettings::new(case.spp, case.max_depth, SEED)?;
    Ok(render(&naive, &camera, &settings)?.image)
}

/// The reference dimmed to grey, with the pixels where `image` is off by more than one
/// 8-bit step (sRGB-encoded, as the study counts them) in red.
fn diff_map(image: &Image, reference: &Image) -> Image {
    let enc = Encoding::Srgb;
    let pixels = image
        .pixels()
        .iter()
        .zip(reference.pixels())
        .map(|(p, q)| {
            let off = (0..3).any(|k| (enc.encode(p[k]) - enc.encode(q[k])).abs() > 1.0 / 255.0);
            if off {
                [0.9, 0.0, 0.0]
            } else {
                let grey = (0.2126 * q[0] + 0.7152 * q[1] + 0.0722 * q[2]).clamp(0.0, 1.0);
                [0.05 + 0.3 * grey; 3]
            }
        })
        .collect();
    Image::from_pixels(image.width(), image.height(), pixels).expect("same size")
}

/// The panels the report shows; the other renders are measured but not written.
const SHOWN: [&str; 12] = [
    "tiny_far-f32-stable",
    "tiny_far-f32-textbook",
    "tiny_far-f32-textbook-diff",
    "far_1e4-f32-textbook",
    "far_1e4-f32-textbook-diff",
    "far_1e4-f32-stable-diff",
    "self_hit-f32-t_min0",
    "self_hit-f32-t_min0-diff",
    "self_hit-f64-t_min0-diff",
    "small_glass-f64-stable",
    "small_glass-f64-textbook",
    "small_glass-f64-textbook-diff",
];

fn save(dir: &Path, name: &str, image: &Image) -> raytrace::Result<()> {
    if !SHOWN.contains(&name) {
        return Ok(());
    }
    let path = dir.join(format!("{name}.png"));
    raytrace::image::write_png(&path, &image.to_u16(Encoding::Srgb), Encoding::Srgb)
}

fn run(dir: &Path) -> raytrace::Result<()> {
    std::fs::create_dir_all(dir).map_err(|source| raytrace::Error::Io {
        path: dir.to_path_buf(),
        source,
    })?;
    let mut cases = cases::all(WIDTH, SEED)?;
    // As the study runs them: its defaults, 4 spp and depth 50, for the Monte Carlo cases.
    for c in cases.iter_mut().filter(|c| c.spp > 1) {
        c.spp = 4;
        c.max_depth = 50;
    }
    let find = |name: &str| cases.iter().find(|c| c.name == name).expect("a study case");
    let mut csv = String::from("case,scalar,method,rmse,max_error,share_over_one_step\n");
    let mut record = |case: &str, scalar: &str, method: &str, image: &Image, reference: &Image| {
        let e = ImageError::between(image, reference, Encoding::Srgb)?;
        let _ = writeln!(
            csv,
            "{case},{scalar},{method},{:.3e},{:.3e},{:.5}",
            e.rmse, e.max, e.over_one_step
        );
        println!(
            "{case:<13} {scalar} {method:<9} {:>7.3} % of pixels off by more than one 8-bit step",
            100.0 * e.over_one_step
        );
        raytrace::Result::Ok(())
    };

    // Cancellation: small spheres far away (f32), and a tiny glass sphere (f64).
    for (name, scalar) in [("tiny_far", "f32"), ("far_1e4", "f32"), ("small_glass", "f64")] {
        let case = find(name);
        let reference = render_case::<DoubleDouble>(case, false)?;
        for textbook in [false, true] {
            let image = match scalar {
                "f32" => render_case::<f32>(case, textbook)?,
                _ => render_case::<f64>(case, textbook)?,
            };
            let method = if textbook { "textbook" } else { "stable" };
            record(name, scalar, method, &image, &reference)?;
            save(dir, &format!("{name}-{scalar}-{method}"), &image)?;
            save(
                dir,
                &format!("{name}-{scalar}-{method}-diff"),
                &diff_map(&image, &reference),
            )?;
        }
    }

    // Self-intersection: the spec's scene, rays leaving from the rounded hit point.
    let case = find("four_mirrors");
    let reference = render_case::<DoubleDouble>(case, false)?;
    for (scalar, image) in [
        ("f32", render_no_t_min::<f32>(case)?),
        ("f64", render_no_t_min::<f64>(case)?),
    ] {
        record("self_hit", scalar, "t_min=0", &image, &reference)?;
        save(dir, &format!("self_hit-{scalar}-t_min0"), &image)?;
        save(
            dir,
            &format!("self_hit-{scalar}-t_min0-diff"),
            &diff_map(&image, &reference),
        )?;
    }
    let stable = render_case::<f32>(case, false)?;
    record("self_hit", "f32", "stable", &stable, &reference)?;

    let path = dir.join("failures.csv");
    raytrace::image::write_atomic(&path, |w| std::io::Write::write_all(w, csv.as_bytes()))?;
    println!("wrote {}", path.display());
    Ok(())
}

fn main() -> ExitCode {
    let dir = std::env::args()
        .nth(1)
        .map_or_else(|| PathBuf::from("report/figures/failures"), PathBuf::from);
    match run(&dir) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}
