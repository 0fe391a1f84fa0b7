//! Glass (the spec's refraction extra): solid and hollow glass spheres refract by Snell's
//! law and reflect by Schlick's approximation, beside mirror and matte spheres.
//!
//! `cargo run --release --example glass` writes `output/glass.ppm` and `.png`.

mod common;
mod scenes;

use common::Options;

fn main() -> std::process::ExitCode {
    common::spec_scene(
        common::Example {
            name: "glass",
            about: "Solid and hollow glass spheres (Snell's law, Schlick's reflectance) beside mirror and matte ones.",
            defaults: Options::defaults(800, 32, 20),
        },
        scenes::glass,
        scenes::glass,
    )
}
