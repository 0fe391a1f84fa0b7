//! Glass (the spec's refraction extra): solid and hollow glass spheres refract by Snell's
//! law and reflect by Schlick's approximation, beside mirror and matte spheres.
//!
//! `cargo run --release --example glass` writes `output/glass.ppm` and `.png`.

mod common;
mod scenes;

use raytrace::cli::{Options, Precision};
use raytrace::prelude::*;

fn run<F: Float>(o: &Options) -> raytrace::Result<raytrace::Render> {
    let camera = ScreenCamera::with_width(o.width)?;
    render(&scenes::glass::<F>()?, &camera, &common::settings(o)?)
}

fn main() -> std::process::ExitCode {
    common::main(
        common::Example {
            name: "glass",
            about: "Solid and hollow glass spheres (Snell's law, Schlick's reflectance) beside mirror and matte ones.",
            defaults: Options::defaults(800, 32, 20),
        },
        |o| match o.precision {
            Precision::F32 => run::<f32>(o),
            Precision::F64 => run::<f64>(o),
        },
    )
}
