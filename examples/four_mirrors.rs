//! The specification's minimum scene: four mirror spheres with different albedos above a
//! mirror floor, seen by the spec's camera at 800×400, one ray per pixel centre, depth 10.
//!
//! `cargo run --release --example four_mirrors` writes `output/four_mirrors.ppm` and `.png`.

mod common;
mod scenes;

use raytrace::cli::{Options, Precision};
use raytrace::prelude::*;

fn run<F: Float>(o: &Options) -> raytrace::Result<raytrace::Render> {
    let camera = ScreenCamera::with_width(o.width)?;
    render(&scenes::four_mirrors::<F>()?, &camera, &common::settings(o)?)
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
