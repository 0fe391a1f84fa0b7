//! The specification's minimum scene: four mirror spheres with different albedos above a
//! mirror floor, seen by the spec's camera at 800×400, one ray per pixel centre, depth 10.
//!
//! `cargo run --release --example four_mirrors` writes `output/four_mirrors.ppm` and `.png`.

mod common;
mod scenes;

use common::Options;

fn main() -> std::process::ExitCode {
    common::spec_scene(
        common::Example {
            name: "four_mirrors",
            about: "Four mirror spheres with different albedos (the specification's minimum scene).",
            defaults: Options::defaults(800, 1, 10),
        },
        scenes::four_mirrors,
        scenes::four_mirrors,
    )
}
