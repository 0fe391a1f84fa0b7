//! Point lights: matte spheres lit by three coloured point lights with hard shadows,
//! under a dim sky (the lights add to the sky, they do not replace it).
//!
//! `cargo run --release --example point_lights` writes `output/point_lights.ppm` and `.png`.

mod common;
mod scenes;

use common::Options;

fn main() -> std::process::ExitCode {
    common::spec_scene(
        common::Example {
            name: "point_lights",
            about: "Matte spheres lit by three coloured point lights, with shadows, under a dim sky.",
            defaults: Options::defaults(800, 16, 10),
        },
        scenes::point_lights,
        scenes::point_lights,
    )
}
