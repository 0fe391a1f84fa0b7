//! Mitsuba's materials take textures for their colours and roughnesses in scene files, as
//! the Lambertian's albedo does: what a file writes is the material the library makes
//! from the same textures, and a bad value inside a two-sided material is reported at its
//! own key.

use raytrace::material::{
    Coated, Distribution, MaterialKind, Metal, Plastic, RoughConductor, Roughness, TwoSided,
};
use raytrace::prelude::*;
use raytrace::scene_file::SceneFile;
use raytrace::texture::{Checkerboard, Texture};
use raytrace::{Error, lit};
use std::path::Path;

const TEXTURED: &str = r#"
[camera]
type = "look_at"
from = [0, 1, 4]
at = [0, 0, 0]
vfov = 40
aspect = 2

[textures.rough]
type = "checkerboard"
color0 = [0.05, 0.05, 0.05]
color1 = [0.5, 0.5, 0.5]

[materials.brushed]
type = "rough_conductor"
material = "Au"
distribution = "ggx"
alpha = "rough"

[materials.tiles]
type = "plastic"
diffuse_reflectance = { type = "checkerboard", color0 = [0.8, 0.1, 0.1], color1 = [0.1, 0.1, 0.8] }

[materials.sheet]
type = "two_sided"
front = { type = "rough_conductor", material = "Cu", alpha = "rough" }

[[objects]]
type = "sphere"
center = [-1, 0, 0]
radius = 0.5
material = "brushed"

[[objects]]
type = "sphere"
center = [0, 0, 0]
radius = 0.5
material = "tiles"

[[objects]]
type = "sphere"
center = [1, 0, 0]
radius = 0.5
material = "sheet"
"#;

fn checker<F: Float>(a: f64, b: f64) -> Texture<F> {
    let c = |x: f64| Color::new(lit(x), lit(x), lit(x));
    Checkerboard::new(c(a), c(b)).unwrap().into()
}

fn made<F: Float>() -> Vec<MaterialKind<F>> {
    let rough = |d| Roughness::isotropic(d, checker(0.05, 0.5)).unwrap();
    let colour = |r: f64, g: f64, b: f64| Color::new(lit(r), lit(g), lit(b));
    let tiles = Checkerboard::new(colour(0.8, 0.1, 0.1), colour(0.1, 0.1, 0.8)).unwrap();
    let coat = Coated::new(tiles.into(), "polypropylene", "air").unwrap();
    let copper = RoughConductor::new(Metal::named("Cu").unwrap(), rough(Distribution::Beckmann));
    vec![
        RoughConductor::new(Metal::named("Au").unwrap(), rough(Distribution::Ggx)).into(),
        Plastic::new(coat).into(),
        TwoSided::new(copper.into()).unwrap().into(),
    ]
}

fn textured_parameters_are_the_librarys<F: Float>() {
    let file = SceneFile::parse(TEXTURED, Path::new("textured.toml")).unwrap();
    let built = file.build::<F>().unwrap().scene;
    let got: Vec<_> = built
        .objects()
        .iter()
        .map(|o| built.material(o.material).clone())
        .collect();
    assert_eq!(got, made::<F>());
    for m in &got {
        assert!(m.reads_coordinates(), "{m:?}");
    }
    // And back through TOML.
    let back = SceneFile::parse(&file.to_toml(), Path::new("textured.toml")).unwrap();
    assert_eq!(back, file);
}

#[test]
fn textured_parameters_are_the_librarys_in_f32() {
    textured_parameters_are_the_librarys::<f32>();
}

#[test]
fn textured_parameters_are_the_librarys_in_f64() {
    textured_parameters_are_the_librarys::<f64>();
}

/// A roughness texture with a value of 0 somewhere, a reflectance above 1 in a texture, and
/// a bad value inside a two-sided material's front: each at its own key.
#[test]
fn bad_textured_values_are_named_at_their_keys() {
    let cases = [
        (
            TEXTURED.replace("color0 = [0.05, 0.05, 0.05]", "color0 = [0, 0, 0]"),
            "materials.brushed.alpha",
        ),
        (
            TEXTURED.replace("color0 = [0.8, 0.1, 0.1]", "color0 = [1.8, 0.1, 0.1]"),
            "materials.tiles.diffuse_reflectance",
        ),
        (
            TEXTURED.replace("material = \"Cu\"", "material = \"Fe\""),
            "materials.sheet.front.material",
        ),
    ];
    for (text, key) in cases {
        let file = SceneFile::parse(&text, Path::new("textured.toml")).unwrap();
        match file.build::<f64>().map(drop) {
            Err(e @ Error::SceneFile { .. }) => {
                let message = e.to_string();
                assert!(message.contains(key), "{key}: {message}");
            }
            other => panic!("{key}: {other:?}"),
        }
    }
}
