//! The integration tests of the renderer itself: geometry, materials, lights, sampling and
//! the images. A module per topic; `cargo test --test it topic::` runs one.
//!
//! The integration tests are two crates, this one and `tests/files` (scene files, meshes,
//! imported scenes, the command line and outputs): a test crate per file compiled the
//! generic renderer over again each time, and one crate for all of them built on one core
//! while the other waited. Two build side by side.

// Shared helpers, and the examples' own code that the tests check.
#[path = "../common/mod.rs"]
mod common;
mod mesh_scene;
#[path = "../../examples/custom_shape/parts.rs"]
mod parts;
#[path = "../../examples/scenes/mod.rs"]
mod scenes;
mod textured_scene;

mod adaptive;
mod adaptive_calibration;
mod advice;
mod aov;
mod bsdf_chi2;
mod bsdf_consistency;
mod bsdf_energy;
mod bsdf_mitsuba;
mod bsdf_scenes;
mod bsdf_textures;
mod bvh_scene;
mod chi2_sf;
mod custom_shape;
mod degenerate_scatter;
mod disk_light;
mod emission;
mod emission_analytic;
mod emitter_chi2;
mod environment;
mod flat_shapes;
mod glass;
mod instances;
mod intersections;
mod lambertian_chi2;
mod lights;
mod material_resolve;
mod material_table;
mod meshes;
mod mis_unbiased;
mod random_scenes;
mod reference;
mod reflection;
mod refraction;
mod render_core;
mod self_intersection;
mod spatial_splits;
mod sphere_stability;
mod sun_and_spot;
mod textures;
mod thin_lens;
mod tone_mapping;
mod triangle_light_chi2;
mod uv_conventions;
mod value_stability;
mod watertight;
mod watertight_scene;
