//! The final scene of *Ray Tracing in One Weekend*: about 480 random small spheres (matte,
//! mirror, glass) around three big ones, seen from above by a look-at camera, generated from
//! the seed. With this many objects the scene intersects through a BVH.
//!
//! `cargo run --release --example random_spheres` writes `output/random_spheres.ppm` and `.png`.

mod common;
mod scenes;

use common::Options;
use raytrace::advice::Precision;
use raytrace::prelude::*;

fn run<F: Float>(o: &Options) -> raytrace::Result<raytrace::Render> {
    let camera = scenes::random_spheres_camera::<F>(o.width)?;
    render(
        &scenes::random_spheres::<F>(o.seed)?,
        &camera,
        &common::settings(o)?,
    )
}

fn main() -> std::process::ExitCode {
    common::main(
        common::Example {
            name: "random_spheres",
            about: "Ray Tracing in One Weekend's final scene: ~480 random spheres, 16:9, look-at camera.",
            defaults: Options::defaults(400, 10, 50),
        },
        |o| match o.precision {
            Precision::F32 => run::<f32>(o),
            Precision::F64 => run::<f64>(o),
        },
    )
}
