//! Point lights: matte spheres lit by three coloured point lights with hard shadows,
//! under a dim sky (the lights add to the sky, they do not replace it).
//!
//! `cargo run --release --example point_lights` writes `output/point_lights.ppm` and `.png`.

mod common;
mod scenes;

use raytrace::cli::{Options, Precision};
use raytrace::prelude::*;

fn run<F: Float>(o: &Options) -> raytrace::Result<raytrace::Render> {
    let camera = ScreenCamera::with_width(o.width)?;
    render(&scenes::point_lights::<F>()?, &camera, &common::settings(o)?)
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
