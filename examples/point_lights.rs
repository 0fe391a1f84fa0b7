//! Point lights: matte spheres lit by three coloured point lights with hard shadows,
//! under a dim sky (the lights add to the sky, they do not replace it).
//!
//! `cargo run --release --example point_lights` writes `output/point_lights.ppm` and `.png`.

mod common;

use raytrace::cli::{Options, Precision};
use raytrace::prelude::*;

fn scene<F: Float>() -> raytrace::Result<EnumScene<F>> {
    let dim = |r, g, b| Vec3::from_f64(r, g, b);
    let mut scene = EnumScene::new(Background::sky(dim(0.02, 0.02, 0.025), dim(0.04, 0.05, 0.08))?);
    let sphere = |x, y, z, r| Sphere::new(Vec3::from_f64(x, y, z), lit(r));
    let matte = |r, g, b| Lambertian::new(Vec3::from_f64(r, g, b));
    scene.add(sphere(-1.8, -0.1, -4.2, 0.7)?, matte(0.85, 0.85, 0.85)?);
    scene.add(sphere(0.0, 0.1, -4.6, 0.9)?, matte(0.8, 0.6, 0.4)?);
    scene.add(sphere(1.8, -0.1, -4.2, 0.7)?, matte(0.85, 0.85, 0.85)?);
    scene.add(sphere(0.9, 0.3, -3.0, 0.25)?, Mirror::new(Vec3::from_f64(0.9, 0.9, 0.9))?);
    scene.add(sphere(0.0, -1000.8, -4.0, 1000.0)?, matte(0.6, 0.6, 0.6)?);
    let light = |x, y, z, r, g, b| PointLight::new(Vec3::from_f64(x, y, z), Vec3::from_f64(r, g, b));
    scene.add_light(light(-3.0, 3.0, -2.0, 36.0, 15.0, 9.0)?);
    scene.add_light(light(3.0, 2.5, -2.5, 9.0, 18.0, 36.0)?);
    scene.add_light(light(0.0, 4.0, -6.0, 15.0, 15.0, 15.0)?);
    Ok(scene)
}

fn run<F: Float>(o: &Options) -> raytrace::Result<raytrace::Render> {
    let camera = ScreenCamera::with_width(o.width)?;
    render(&scene::<F>()?, &camera, &common::settings(o)?)
}

fn main() -> std::process::ExitCode {
    common::main(
        common::Example {
            name: "point_lights",
            about: "Matte spheres lit by three coloured point lights, with shadows, under a dim sky.",
            defaults: Options::defaults(800, 16, 10),
        },
        |o| match o.precision {
            Precision::F32 => run::<f32>(o),
            Precision::F64 => run::<f64>(o),
        },
    )
}
