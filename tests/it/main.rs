//! The integration tests, in one crate: one build and one link instead of one per topic
//! (a test crate per file compiled the generic renderer over again each time, and took
//! most of `cargo test`'s eleven minutes). A module per topic; `cargo test topic::` runs one.

// Shared helpers, and the examples' own code that the tests check.
mod common;
#[path = "../../examples/common/files.rs"]
mod files;
mod mesh_scene;
#[path = "../../examples/common/options.rs"]
mod options;
#[path = "../../examples/custom_shape/parts.rs"]
mod parts;
#[path = "../../examples/scenes/mod.rs"]
mod scenes;
mod textured_scene;

mod adaptive;
mod adaptive_calibration;
mod adaptive_cli;
mod adversarial_files;
mod adversarial_scenes;
mod advice;
mod aov;
mod bad_input;
mod bsdf_chi2;
mod bsdf_consistency;
mod bsdf_energy;
mod bsdf_mitsuba;
mod bsdf_scenes;
mod bsdf_textures;
mod bvh_scene;
mod cli;
mod committed_meshes;
mod custom_shape;
mod degenerate_scatter;
mod disk_files;
mod disk_light;
mod emission;
mod emission_analytic;
mod emitter_chi2;
mod environment;
mod example_files;
mod example_options;
mod flat_shapes;
mod glass;
mod gltf;
mod instance_files;
mod instances;
mod interrupt;
mod intersections;
mod lambertian_chi2;
mod light_files;
mod lights;
mod material_resolve;
mod material_table;
mod mesh_attributes;
mod meshes;
mod mis_unbiased;
mod mitsuba_extensions;
mod mitsuba_foreign;
mod mitsuba_import;
mod obj_material_errors;
mod obj_materials;
mod outputs;
mod random_scenes;
mod reference;
mod reflection;
mod refraction;
mod render_core;
mod scene_file_errors;
mod scene_files;
mod self_intersection;
mod spatial_splits;
mod sphere_stability;
mod sun_and_spot;
mod textures;
mod thin_lens;
mod tiles;
mod tone_mapping;
mod triangle_light_chi2;
mod uv_conventions;
mod value_stability;
mod watertight;
mod watertight_scene;
mod xml_twins;
