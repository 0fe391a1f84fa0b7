//! The scaling benchmark's Rust side: one scene (a cloud of random spheres or the Stanford
//! dragon at one resolution), every surface matte with albedo 0.5 under the default sky, seen
//! by the spec's camera, rendered once. It prints the BVH build time, the render's Mrays/s,
//! the rays traced and the process's peak memory, in the format `bench/embree/scale.cpp`
//! prints too, so `bench/scale.py` can set them side by side. Run each scene in its own
//! process: the peak memory is the process's.
//!
//! ```text
//! cargo run --release --example scale -- --scene spheres:10000 --threads 1
//! cargo run --release --example scale -- --scene dragon:res2 --export /tmp/dragon2.bin
//! ```

mod export;
mod geometry;
mod report;

use clap::Parser;
use geometry::Geometry;
use raytrace::prelude::*;
use raytrace::{BvhQuality, EnumScene, RenderStats};
use report::Measurement;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

/// Renders one scaling-benchmark scene and reports build time, speed, rays and peak memory.
#[derive(Parser, Debug)]
#[command(name = "scale", bin_name = "cargo run --release --example scale --")]
struct Args {
    /// `spheres:N` (N random small spheres), `needles:N` (N random long thin triangles) or
    /// `dragon:res4|res3|res2|full` (11k, 48k, 203k or 871k triangles)
    #[arg(long, value_name = "SCENE", value_parser = SceneChoice::parse)]
    scene: SceneChoice,
    /// Worker threads for the render
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u16).range(1..=256))]
    threads: u16,
    /// Samples (jittered rays) per pixel
    #[arg(long, default_value_t = 8, value_parser = clap::value_parser!(u32).range(1..))]
    spp: u32,
    /// Image width in pixels; the height is half of it
    #[arg(long, default_value_t = 400)]
    width: usize,
    /// Most bounces per path
    #[arg(long, default_value_t = 10)]
    max_depth: u32,
    /// Seed of the render's random streams (the sphere cloud always uses seed 1)
    #[arg(long, default_value_t = 0)]
    seed: u64,
    /// Scalar of the render: f32 (as Embree) or f64
    #[arg(long, default_value = "f32", value_parser = ["f32", "f64"])]
    precision: String,
    /// BVH build quality: medium (binned SAH) or high (with spatial splits), Embree's names
    #[arg(long, default_value = "medium", value_parser = ["medium", "high"])]
    bvh_quality: String,
    /// Folder of the dragon meshes (`tools/fetch_meshes.sh` fetches them)
    #[arg(long, value_name = "DIR", default_value = "assets/meshes")]
    assets: PathBuf,
    /// Write the scene for the Embree program to FILE and exit without rendering
    #[arg(long, value_name = "FILE")]
    export: Option<PathBuf>,
    /// Print one CSV line (scene,primitives,program,threads,build_s,mrays_s,rays,peak_mb) on
    /// stdout and the readable summary on stderr
    #[arg(long)]
    csv: bool,
    /// Also write the render to FILE as PNG (sRGB), to check what was traced
    #[arg(long, value_name = "FILE")]
    image: Option<PathBuf>,
}

/// The seed of the sphere clouds, fixed so every run and both programs see the same spheres.
const SPHERE_SEED: u64 = 1;

/// A scene of the benchmark.
#[derive(Clone, Debug)]
enum SceneChoice {
    /// This many random spheres.
    Spheres(usize),
    /// The dragon at a resolution: `res4`, `res3`, `res2` or `full`.
    Dragon(String),
    /// This many long thin triangles, every way oriented.
    Needles(usize),
}

impl SceneChoice {
    fn parse(s: &str) -> Result<Self, String> {
        match s.split_once(':') {
            Some(("spheres", n)) => match n.parse::<usize>() {
                Ok(n) if n >= 1 => Ok(Self::Spheres(n)),
                _ => Err(format!("expected spheres:N with N ≥ 1, got {s:?}")),
            },
            Some(("needles", n)) => match n.parse::<usize>() {
                Ok(n) if n >= 1 => Ok(Self::Needles(n)),
                _ => Err(format!("expected needles:N with N ≥ 1, got {s:?}")),
            },
            Some(("dragon", res @ ("res4" | "res3" | "res2" | "full"))) => Ok(Self::Dragon(res.into())),
            _ => Err(format!(
                "expected spheres:N, needles:N or dragon:res4|res3|res2|full, got {s:?}"
            )),
        }
    }

    fn name(&self) -> String {
        match self {
            Self::Spheres(n) => format!("spheres:{n}"),
            Self::Dragon(res) => format!("dragon:{res}"),
            Self::Needles(n) => format!("needles:{n}"),
        }
    }

    fn geometry(&self, assets: &Path) -> raytrace::Result<Geometry> {
        match self {
            Self::Spheres(n) => Ok(Geometry::spheres(*n, SPHERE_SEED)),
            Self::Needles(n) => Ok(Geometry::needles(*n, SPHERE_SEED)),
            Self::Dragon(res) => {
                let file = match res.as_str() {
                    "full" => "dragon_vrip.ply".to_string(),
                    res => format!("dragon_vrip_{res}.ply"),
                };
                Geometry::placed_mesh(&assets.join(file))
            }
        }
    }
}

fn main() -> ExitCode {
    let args = Args::parse();
    match run(&args) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}

fn run(args: &Args) -> raytrace::Result<()> {
    let geometry = args.scene.geometry(&args.assets)?;
    if let Some(path) = &args.export {
        export::write(&geometry, path)
            .map_err(|e| raytrace::Error::InvalidSettings(format!("cannot write {}: {e}", path.display())))?;
        println!(
            "{}: {} primitives written to {}",
            args.scene.name(),
            geometry.primitives(),
            path.display()
        );
        return Ok(());
    }
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(args.threads.into())
        .build()
        .map_err(|e| raytrace::Error::InvalidSettings(format!("cannot start the threads: {e}")))?;
    let primitives = geometry.primitives();
    let (build_s, stats) = pool.install(|| match args.precision.as_str() {
        "f32" => measure::<f32>(args, geometry),
        _ => measure::<f64>(args, geometry),
    })?;
    let measurement = Measurement {
        scene: args.scene.name(),
        primitives,
        program: match args.bvh_quality.as_str() {
            "high" => format!("raytrace-{}-high", args.precision),
            _ => format!("raytrace-{}", args.precision),
        },
        threads: stats.threads,
        build_s,
        render_s: stats.elapsed.as_secs_f64(),
        rays: stats.rays,
        peak_mb: report::peak_mb(),
    };
    measurement.print(args.csv);
    Ok(())
}

/// Builds the scene in `F` and its BVH (timed alone: the scene builds it lazily on the first
/// query, so `uses_bvh` forces it before the render starts), then renders it. The geometry
/// is dropped once the scene holds its copy, as the Embree program drops its own.
fn measure<F: Float>(args: &Args, geometry: Geometry) -> raytrace::Result<(f64, RenderStats)> {
    let mut scene: EnumScene<F> = geometry.scene()?;
    drop(geometry);
    if args.bvh_quality == "high" {
        scene.set_bvh_quality(BvhQuality::High);
    }
    let start = Instant::now();
    let bvh = scene.uses_bvh();
    let build_s = start.elapsed().as_secs_f64();
    assert!(bvh, "the benchmark's scenes always intersect through a BVH");
    let camera = ScreenCamera::with_width(args.width)?;
    let settings = RenderSettings::new(args.spp, args.max_depth, args.seed)?;
    let rendered = Renderer::new(&scene, &camera).settings(settings).render()?;
    if let Some(path) = &args.image {
        write_png(path, &rendered.image.to_u16(Encoding::Srgb), Encoding::Srgb)?;
    }
    Ok((build_s, rendered.stats))
}
