//! Every material and texture kind, one sphere each, and a rough gold bunny: the scene file
//! `scenes/materials.toml` (like Mitsuba's `bsdf_spheres`), read and rendered through the
//! library as the `raytrace` binary does.
//!
//! `cargo run --release --example materials` writes `output/materials.ppm` and `.png`
//! (fetch the bunny first: `bash tools/fetch_meshes.sh`). The scene's own width, samples
//! and depth are the defaults; the options override them.

mod common;

use common::Options;
use raytrace::advice::Precision;
use raytrace::scene_file::SceneFile;
use raytrace::{Float, Render, render};
use std::path::Path;

fn main() -> std::process::ExitCode {
    let mut defaults = Options::defaults(800, 64, 12);
    defaults.precision = Precision::F32;
    common::main(
        common::Example {
            name: "materials",
            about: "Every material and texture kind on a grid of spheres, and a rough gold bunny.",
            defaults,
        },
        |o| {
            let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/materials.toml");
            let mut file = SceneFile::load(&path)?;
            let r = file.render_mut();
            (r.width, r.spp, r.max_depth, r.seed) = (o.width, o.spp, o.max_depth, o.seed);
            match o.precision {
                Precision::F32 => scene_file::<f32>(&file),
                Precision::F64 => scene_file::<f64>(&file),
            }
        },
    )
}

/// The file's scene, camera and settings in scalar `F`, rendered (progress bar on).
fn scene_file<F: Float>(file: &SceneFile) -> raytrace::Result<Render> {
    let built = file.build::<F>()?;
    let mut settings = built.settings;
    settings.progress = true;
    render(&built.scene, &built.camera, &settings)
}
