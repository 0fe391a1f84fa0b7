//! Adaptive against uniform sampling at equal time, on the gallery's scenes.
//!
//! For each scene, uniform renders at 16…512 samples per pixel and adaptive renders with a
//! time budget equal to the uniform renders' times at 64…512 spp: at each level three
//! pairs, a uniform render then an adaptive one given the time it just took, with seeds
//! 1, 2, 3; times and errors are means over the three. Each image's squared
//! error is measured against two independent references `r₁`, `r₂` (uniform, 2048 spp
//! each, their own seeds) as the mean of `(x − r₁)(x − r₂)`: an unbiased estimate of the
//! squared error against the true image, which the references' own noise does not inflate.
//!
//! - `rel_mse`: the renderer's own measure, the mean over pixels of
//!   `(Y − R₁)(Y − R₂)/max(R̄, 0.01)²` (luminance, floor 0.01);
//! - `display_mse`: what a viewer sees, the same product of each channel sRGB-encoded and
//!   clamped to `[0, 1]` (as the PNG stores it), averaged over pixels and channels;
//! - `mse`: the same in linear RGB, unclamped: dominated by the few pixels far above
//!   display white (a lamp's edge), which no image file shows.
//!
//! Writes `bench/results/equal_time.csv` (every run), `equal_time.md` (the table at each
//! budget, with the machine's load before and after) and `docs/images/equal_time.svg`.
//!
//! ```sh
//! cargo run --release --features studies --example equal_time            # about 3 minutes on 2 cores
//! cargo run --release --features studies --example equal_time -- --quick # a smoke test in seconds, to /tmp
//! ```
//!
//! Timing on a shared machine is noisy: run it on an idle one, and read the load the
//! `.md` file records.

mod bound;
mod chart;
#[path = "../scenes/mod.rs"]
mod scenes;
mod table;

use raytrace::image::write_atomic;
use raytrace::prelude::*;
use raytrace::render::adaptive::luminance;
use raytrace::{Image, Render};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

/// One measured render.
#[derive(Clone, Debug)]
pub struct Run {
    pub scene: &'static str,
    /// `uniform` or `adaptive`.
    pub method: &'static str,
    /// The uniform render's spp, or the uniform spp whose time the adaptive budget matches.
    pub level: u32,
    pub seconds: f64,
    pub spp: f64,
    /// Rays traced (of every kind).
    pub rays: f64,
    pub rel_mse: f64,
    pub display_mse: f64,
    pub mse: f64,
}

/// A scene of the gallery, built in f32, with its camera and recursion limit.
struct Case {
    name: &'static str,
    scene: EnumScene<f32>,
    camera: Box<dyn Camera<f32> + Sync>,
    max_depth: u32,
}

struct Plan {
    width: usize,
    reference_spp: u32,
    uniform: Vec<u32>,
    adaptive: Vec<u32>,
    repeats: usize,
    results: PathBuf,
    figure: PathBuf,
}

fn cases(width: usize) -> raytrace::Result<Vec<Case>> {
    let spec = |name, scene, max_depth| -> raytrace::Result<Case> {
        Ok(Case {
            name,
            scene,
            camera: Box::new(ScreenCamera::new(width, width / 2)?),
            max_depth,
        })
    };
    let (cornell, cornell_camera, _) = scenes::cornell_box::<f32>(width * 3 / 5)?;
    let mut cases = vec![
        spec("four_mirrors", scenes::four_mirrors()?, 10)?,
        spec("matte_spheres", scenes::matte_spheres()?, 10)?,
        spec("glass", scenes::glass()?, 20)?,
        spec("plane_and_triangles", scenes::plane_and_triangles()?, 20)?,
        spec("point_lights", scenes::point_lights()?, 10)?,
        Case {
            name: "random_spheres",
            scene: scenes::random_spheres(0)?,
            camera: Box::new(scenes::random_spheres_camera(width)?),
            max_depth: 50,
        },
        Case {
            name: "cornell_box",
            scene: cornell,
            camera: Box::new(cornell_camera),
            max_depth: 8,
        },
        spec("caustic", scenes::caustic()?, 8)?,
    ];
    // The dragon, if its mesh has been fetched (tools/fetch_meshes.sh).
    let dragon = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/dragon.toml");
    if let Ok(mut file) = raytrace::scene_file::SceneFile::load(&dragon) {
        file.render_mut().width = width;
        if let Ok(built) = file.build::<f32>() {
            cases.push(Case {
                name: "dragon",
                scene: built.scene,
                camera: Box::new(built.camera),
                max_depth: built.settings.max_depth,
            });
        }
    }
    Ok(cases)
}

fn uniform(case: &Case, spp: u32, seed: u64) -> raytrace::Result<Render> {
    let camera = &*case.camera;
    Renderer::new(&case.scene, &camera)
        .max_depth(case.max_depth)
        .seed(seed)
        .spp(spp)
        .render()
}

fn adaptive(case: &Case, budget: Duration, seed: u64) -> raytrace::Result<Render> {
    let camera = &*case.camera;
    Renderer::new(&case.scene, &camera)
        .max_depth(case.max_depth)
        .seed(seed)
        .time_budget(budget)
        .render()
}

/// The squared errors of `image` against the references, as the module docs define them.
#[derive(Clone, Copy, Debug)]
struct Errors {
    rel_mse: f64,
    display_mse: f64,
    mse: f64,
}

fn errors(image: &Image, r1: &Image, r2: &Image) -> Errors {
    let (mut rel, mut display, mut abs) = (0.0, 0.0, 0.0);
    let shown = |c: f64| Encoding::Srgb.encode(c);
    for ((x, a), b) in image.pixels().iter().zip(r1.pixels()).zip(r2.pixels()) {
        let (y, ya, yb) = (luminance(*x), luminance(*a), luminance(*b));
        let scale = (0.5 * (ya + yb)).max(0.01);
        rel += (y - ya) * (y - yb) / (scale * scale);
        for k in 0..3 {
            display += (shown(x[k]) - shown(a[k])) * (shown(x[k]) - shown(b[k])) / 3.0;
            abs += (x[k] - a[k]) * (x[k] - b[k]) / 3.0;
        }
    }
    let n = image.pixels().len() as f64;
    Errors {
        rel_mse: rel / n,
        display_mse: display / n,
        mse: abs / n,
    }
}

/// What one render measured: `[seconds, spp, rays]` and its errors.
type Measured = ([f64; 3], Errors);

/// The mean of each measure over the runs.
fn mean(runs: &[Measured]) -> Measured {
    let n = runs.len() as f64;
    let m = |f: &dyn Fn(&Measured) -> f64| runs.iter().map(f).sum::<f64>() / n;
    (
        [m(&|r| r.0[0]), m(&|r| r.0[1]), m(&|r| r.0[2])],
        Errors {
            rel_mse: m(&|r| r.1.rel_mse),
            display_mse: m(&|r| r.1.display_mse),
            mse: m(&|r| r.1.mse),
        },
    )
}

/// One scene: the references, then at each level `repeats` pairs of a uniform render and
/// (at the adaptive levels) an adaptive render given the time that uniform render just
/// took, pair `k` with seed `k + 1` for both: the pair shares the machine's load, and the
/// errors are means over seeds (a caustic's error is a few fireflies: one seed is luck).
/// Returns the scene's [`bound`](bound::bound).
fn measure(case: &Case, plan: &Plan, runs: &mut Vec<Run>) -> raytrace::Result<bound::Bounds> {
    let start = Instant::now();
    let r1 = uniform(case, plan.reference_spp, 1_000_001)?.image;
    let r2 = uniform(case, plan.reference_spp, 1_000_002)?.image;
    let pixels = r1.pixels().len() as f64;
    for &spp in &plan.uniform {
        let (mut u, mut a) = (Vec::new(), Vec::new());
        for k in 0..plan.repeats as u64 {
            let r = uniform(case, spp, k + 1)?;
            let t = r.stats.elapsed;
            u.push((
                [t.as_secs_f64(), f64::from(spp), r.stats.rays as f64],
                errors(&r.image, &r1, &r2),
            ));
            if plan.adaptive.contains(&spp) {
                let r = adaptive(case, t, k + 1)?;
                let samples = r.convergence.as_ref().map_or(0, |c| c.summary().samples);
                a.push((
                    [
                        r.stats.elapsed.as_secs_f64(),
                        samples as f64 / pixels,
                        r.stats.rays as f64,
                    ],
                    errors(&r.image, &r1, &r2),
                ));
            }
        }
        let (m, e) = mean(&u);
        push(runs, case, "uniform", spp, m, e);
        if !a.is_empty() {
            let (m, e) = mean(&a);
            push(runs, case, "adaptive", spp, m, e);
        }
    }
    let bound = bound::bound(case, &r1, &r2)?;
    eprintln!(
        "{}: {:.1} s, bounds {:.2} (samples), {:.2} (rays)",
        case.name,
        start.elapsed().as_secs_f64(),
        bound.samples,
        bound.rays
    );
    Ok(bound)
}

fn push(
    runs: &mut Vec<Run>,
    case: &Case,
    method: &'static str,
    level: u32,
    [seconds, spp, rays]: [f64; 3],
    e: Errors,
) {
    let run = Run {
        scene: case.name,
        method,
        level,
        seconds,
        spp,
        rays,
        rel_mse: e.rel_mse,
        display_mse: e.display_mse,
        mse: e.mse,
    };
    eprintln!("  {run:?}");
    runs.push(run);
}

fn load() -> String {
    std::fs::read_to_string("/proc/loadavg").map_or_else(|_| "unknown".into(), |l| l.trim().to_string())
}

fn write(path: &Path, text: &str) -> raytrace::Result<()> {
    if let Some(dir) = path.parent() {
        std::fs::create_dir_all(dir).map_err(|source| raytrace::Error::Io {
            path: dir.to_path_buf(),
            source,
        })?;
    }
    write_atomic(path, |w| std::io::Write::write_all(w, text.as_bytes()))
}

fn main() -> raytrace::Result<()> {
    let args: Vec<String> = std::env::args().collect();
    let quick = args.iter().any(|a| a == "--quick");
    let only: Vec<&str> = args
        .iter()
        .position(|a| a == "--scenes")
        .and_then(|i| args.get(i + 1))
        .map_or_else(Vec::new, |s| s.split(',').collect());
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut plan = if quick {
        Plan {
            width: 48,
            reference_spp: 256,
            uniform: vec![16, 32, 64],
            adaptive: vec![64],
            repeats: 1,
            results: std::env::temp_dir().join("equal_time"),
            figure: std::env::temp_dir().join("equal_time/equal_time.svg"),
        }
    } else {
        Plan {
            width: 160,
            reference_spp: 2048,
            uniform: vec![16, 32, 64, 128, 256, 512],
            adaptive: vec![64, 128, 256, 512],
            repeats: 3,
            results: root.join("bench/results"),
            figure: root.join("docs/images/equal_time.svg"),
        }
    };
    if let Some(w) = args
        .iter()
        .position(|a| a == "--width")
        .and_then(|i| args.get(i + 1))
    {
        plan.width = w
            .parse()
            .map_err(|_| raytrace::Error::InvalidSettings(format!("--width {w}")))?;
        plan.results = std::env::temp_dir().join("equal_time");
        plan.figure = plan.results.join("equal_time.svg");
    }
    let before = load();
    let (mut runs, mut bounds) = (Vec::new(), Vec::new());
    for case in cases(plan.width)? {
        if only.is_empty() || only.contains(&case.name) {
            bounds.push((case.name, measure(&case, &plan, &mut runs)?));
        }
    }
    let after = load();
    let mut csv = String::from("scene,method,level,seconds,spp,rays,rel_mse,display_mse,mse\n");
    for r in &runs {
        let _ = writeln!(
            csv,
            "{},{},{},{:.6},{:.2},{},{:.6e},{:.6e},{:.6e}",
            r.scene, r.method, r.level, r.seconds, r.spp, r.rays, r.rel_mse, r.display_mse, r.mse
        );
    }
    write(&plan.results.join("equal_time.csv"), &csv)?;
    let md = table::table(
        &runs,
        &bounds,
        &plan,
        (&before, &after),
        rayon::current_num_threads(),
    );
    write(&plan.results.join("equal_time.md"), &md)?;
    chart::draw(&plan.figure, &runs).map_err(|e| raytrace::Error::InvalidSettings(format!("chart: {e}")))?;
    println!("{md}");
    println!(
        "wrote {}, equal_time.md and {}",
        plan.results.join("equal_time.csv").display(),
        plan.figure.display()
    );
    Ok(())
}
