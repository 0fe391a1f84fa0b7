//! The specification's minimum scene: four mirror spheres with different albedos above a
//! mirror floor, seen by the spec's camera at 800×400, one ray per pixel centre, depth 10.
//!
//! `cargo run --release --example four_mirrors` writes `output/four_mirrors.ppm` and `.png`.

mod common;

use raytrace::cli::{Options, Precision};
use raytrace::prelude::*;

fn scene<F: Float>() -> raytrace::Result<EnumScene<F>> {
    let mut scene = EnumScene::new(Background::default());
    let mirror = |r, g, b| Mirror::new(Vec3::from_f64(r, g, b));
    let sphere = |x, y, z, r| Sphere::new(Vec3::from_f64(x, y, z), lit(r));
    // Four mirrors, left to right: gold, rose, green, steel blue.
    scene.add(sphere(-2.7, 0.0, -4.0, 0.8)?, mirror(0.95, 0.78, 0.35)?);
    scene.add(sphere(-0.9, -0.2, -3.2, 0.6)?, mirror(0.92, 0.45, 0.45)?);
    scene.add(sphere(0.9, 0.0, -4.0, 0.8)?, mirror(0.45, 0.85, 0.5)?);
    scene.add(sphere(2.7, 0.2, -4.8, 1.0)?, mirror(0.5, 0.65, 0.95)?);
    // A dim mirror floor: a sphere so large it reads as a plane at y = −0.8.
    scene.add(sphere(0.0, -1000.8, -4.0, 1000.0)?, mirror(0.55, 0.55, 0.6)?);
    Ok(scene)
}

fn run<F: Float>(o: &Options) -> raytrace::Result<raytrace::Render> {
    let camera = ScreenCamera::with_width(o.width)?;
    render(&scene::<F>()?, &camera, &common::settings(o)?)
}

fn main() -> std::process::ExitCode {
    common::main(
        common::Example {
            name: "four_mirrors",
            about: "Four mirror spheres with different albedos (the specification's minimum scene).",
            defaults: Options::defaults(800, 1, 10),
        },
        |o| match o.precision {
            Precision::F32 => run::<f32>(o),
            Precision::F64 => run::<f64>(o),
        },
    )
}
