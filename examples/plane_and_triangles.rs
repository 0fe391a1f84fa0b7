//! The spec's new shapes: an infinite plane and triangles (a mirror pyramid, a matte
//! tetrahedron), each with an analytic intersection, beside spheres.
//!
//! `cargo run --release --example plane_and_triangles` writes `output/plane_and_triangles.ppm` and `.png`.

mod common;
mod scenes;

use common::Options;

fn main() -> std::process::ExitCode {
    common::spec_scene(
        common::Example {
            name: "plane_and_triangles",
            about: "An infinite plane and triangles (a mirror pyramid and a matte tetrahedron) beside spheres.",
            defaults: Options::defaults(800, 32, 20),
        },
        scenes::plane_and_triangles,
        scenes::plane_and_triangles,
    )
}
