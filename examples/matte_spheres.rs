//! The specification's extension: matte spheres beside mirrors, many jittered rays per
//! pixel (antialiasing and a converged Lambertian estimate), the spec's camera.
//!
//! `cargo run --release --example matte_spheres` writes `output/matte_spheres.ppm` and `.png`.

mod common;
mod scenes;

use common::Options;

fn main() -> std::process::ExitCode {
    common::spec_scene(
        common::Example {
            name: "matte_spheres",
            about: "Matte and mirror spheres, many jittered rays per pixel (the specification's extension).",
            defaults: Options::defaults(800, 16, 10),
        },
        scenes::matte_spheres,
        scenes::matte_spheres,
    )
}
