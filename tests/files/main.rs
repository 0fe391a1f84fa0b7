//! The integration tests of what goes in and out: scene files and meshes on disk, imported
//! glTF and Mitsuba scenes, the `raytrace` binary's command line, outputs and signals. A
//! module per topic; `cargo test --test files topic::` runs one.
//!
//! The renderer's own tests are the other crate, `tests/it`; why two, its root says.

// Shared helpers, and the examples' own code that the tests check.
#[path = "../common/mod.rs"]
mod common;
#[path = "../../examples/common/files.rs"]
mod files;
#[path = "../../examples/common/options.rs"]
mod options;
#[path = "../../examples/scenes/mod.rs"]
mod scenes;

mod adaptive_cli;
mod adversarial_files;
mod adversarial_scenes;
mod bad_input;
mod cli;
mod committed_meshes;
mod disk_files;
mod example_files;
mod example_options;
mod gltf;
mod instance_files;
mod interrupt;
mod light_files;
mod mesh_attributes;
mod mitsuba_extensions;
mod mitsuba_foreign;
mod mitsuba_import;
mod obj_material_errors;
mod obj_materials;
mod outputs;
mod scene_file_errors;
mod scene_files;

mod tiles;
mod xml_twins;
