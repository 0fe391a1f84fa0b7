//! The specification's extension: matte spheres beside mirrors, many jittered rays per
//! pixel (antialiasing and a converged Lambertian estimate), the spec's camera.
//!
//! `cargo run --release --example matte_spheres` writes `output/matte_spheres.ppm` and `.png`.

mod common;

use raytrace::cli::{Options, Precision};
use raytrace::prelude::*;

fn scene<F: Float>() -> raytrace::Result<EnumScene<F>> {
    let mut scene = EnumScene::new(Background::default());
    let sphere = |x, y, z, r| Sphere::new(Vec3::from_f64(x, y, z), lit(r));
    let matte = |r, g, b| Lambertian::new(Vec3::from_f64(r, g, b));
    let mirror = |r, g, b| Mirror::new(Vec3::from_f64(r, g, b));
    scene.add(sphere(-2.6, 0.0, -4.0, 0.8)?, matte(0.8, 0.3, 0.3)?);
    scene.add(sphere(-0.9, 0.0, -4.0, 0.8)?, mirror(0.9, 0.9, 0.9)?);
    scene.add(sphere(0.9, 0.0, -4.0, 0.8)?, matte(0.3, 0.5, 0.85)?);
    scene.add(sphere(2.6, 0.0, -4.0, 0.8)?, mirror(0.95, 0.75, 0.4)?);
    scene.add(sphere(0.0, -0.55, -2.6, 0.25)?, matte(0.9, 0.9, 0.9)?);
    // A matte ground: a sphere so large it reads as a plane at y = −0.8.
    scene.add(sphere(0.0, -1000.8, -4.0, 1000.0)?, matte(0.5, 0.55, 0.45)?);
    Ok(scene)
}

fn run<F: Float>(o: &Options) -> raytrace::Result<raytrace::Render> {
    let camera = ScreenCamera::with_width(o.width)?;
    render(&scene::<F>()?, &camera, &common::settings(o)?)
}

fn main() -> std::process::ExitCode {
    common::main(
        common::Example {
            name: "matte_spheres",
            about: "Matte and mirror spheres, many jittered rays per pixel (the specification's extension).",
            defaults: Options::defaults(800, 16, 10),
        },
        |o| match o.precision {
            Precision::F32 => run::<f32>(o),
            Precision::F64 => run::<f64>(o),
        },
    )
}
