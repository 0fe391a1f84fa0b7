//! The spec's new shapes: an infinite plane and triangles (a mirror pyramid, a matte
//! tetrahedron), each with an analytic intersection, beside spheres.
//!
//! `cargo run --release --example plane_and_triangles` writes `output/plane_and_triangles.ppm` and `.png`.

mod common;
mod scenes;

use raytrace::cli::{Options, Precision};
use raytrace::prelude::*;

fn run<F: Float>(o: &Options) -> raytrace::Result<raytrace::Render> {
    let camera = ScreenCamera::with_width(o.width)?;
    render(
        &scenes::plane_and_triangles::<F>()?,
        &camera,
        &common::settings(o)?,
    )
}

fn main() -> std::process::ExitCode {
    common::main(
        common::Example {
            name: "plane_and_triangles",
            about: "An infinite plane and triangles (a mirror pyramid and a matte tetrahedron) beside spheres.",
            defaults: Options::defaults(800, 32, 20),
        },
        |o| match o.precision {
            Precision::F32 => run::<f32>(o),
            Precision::F64 => run::<f64>(o),
        },
    )
}
