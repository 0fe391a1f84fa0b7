//! The specification's extension: matte spheres beside mirrors, many jittered rays per
//! pixel (antialiasing and a converged Lambertian estimate), the spec's camera.
//!
//! `cargo run --release --example matte_spheres` writes `output/matte_spheres.ppm` and `.png`.

mod common;
mod scenes;

use raytrace::cli::{Options, Precision};
use raytrace::prelude::*;

fn run<F: Float>(o: &Options) -> raytrace::Result<raytrace::Render> {
    let camera = ScreenCamera::with_width(o.width)?;
    render(&scenes::matte_spheres::<F>()?, &camera, &common::settings(o)?)
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
