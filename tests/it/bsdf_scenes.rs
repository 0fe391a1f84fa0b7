//! Mitsuba's materials in a scene: one scene file with every one of them (named metals
//! and media, textures-free), built in f32 and f64, renders through the batched renderer
//! to the reference renderer's bytes, through the trait-object path to the enum path's
//! bytes, with finite, non-negative pixels; it reads back from its own TOML, and each
//! material cast from f64 to f32 is the material made in f32.

use raytrace::material::{Material, MaterialKind};
use raytrace::prelude::*;
use raytrace::scene_file::SceneFile;
use raytrace::{Image, LightSampling};
use std::path::Path;

/// Every material the scene file knows beyond the specification's, lit by an emitting
/// sphere and a point light, above a two-sided plastic floor.
pub const SCENE: &str = r#"
[render]
width = 24
spp = 2
max_depth = 8

[camera]
type = "look_at"
from = [0, 1.5, 4]
at = [0, 0.5, 0]
vfov = 50
aspect = 2

[background]
type = "solid"
color = [0.05, 0.05, 0.05]

[materials.gold]
type = "rough_conductor"
material = "Au"
distribution = "ggx"
alpha = 0.2

[materials.brushed]
type = "rough_conductor"
eta = [0.2, 0.9, 1.1]
k = [3.9, 2.4, 2.1]
alpha_u = 0.05
alpha_v = 0.3
specular_reflectance = [0.9, 0.9, 0.8]

[materials.silver]
type = "conductor"
material = "Ag"

[materials.frosted]
type = "rough_dielectric"
distribution = "ggx"
alpha = 0.1
int_ior = "bk7"
ext_ior = 1.0

[materials.pane]
type = "thin_dielectric"
int_ior = "acrylic glass"

[materials.red]
type = "plastic"
diffuse_reflectance = [0.6, 0.1, 0.1]
nonlinear = true

[materials.blue]
type = "rough_plastic"
distribution = "ggx"
alpha = 0.3
diffuse_reflectance = [0.1, 0.2, 0.6]

[materials.floor]
type = "two_sided"
front = { type = "plastic", diffuse_reflectance = [0.5, 0.5, 0.5] }
back = { type = "rough_conductor", material = "Cu", distribution = "ggx", alpha = 0.3 }

[materials.lamp]
type = "emissive"
radiance = [8, 8, 8]

[[objects]]
type = "sphere"
center = [-1.5, 0.5, 0]
radius = 0.5
material = "gold"

[[objects]]
type = "sphere"
center = [-0.5, 0.5, -0.5]
radius = 0.5
material = "brushed"

[[objects]]
type = "sphere"
center = [0.5, 0.5, 0]
radius = 0.5
material = "frosted"

[[objects]]
type = "sphere"
center = [1.5, 0.5, -0.5]
radius = 0.5
material = "red"

[[objects]]
type = "sphere"
center = [0, 1.3, -1]
radius = 0.4
material = "blue"

[[objects]]
type = "sphere"
center = [-1, 1.4, -1]
radius = 0.3
material = "silver"

[[objects]]
type = "triangle"
a = [0.8, 0, 1]
b = [1.8, 0, 1]
c = [1.3, 1, 1]
material = "pane"

[[objects]]
type = "plane"
point = [0, 0, 0]
normal = [0, 1, 0]
material = "floor"

[[objects]]
type = "sphere"
center = [0, 3, 1]
radius = 0.5
material = "lamp"

[[lights]]
position = [2, 3, 2]
intensity = [5, 5, 5]
"#;

fn file() -> SceneFile {
    SceneFile::parse(SCENE, Path::new("bsdfs.toml")).unwrap()
}

/// The image of `scene` at 2 spp, depth 8, by the batched renderer or the reference one.
fn image_of<F: Float, S, M>(scene: &Scene<F, S, M>, camera: &(impl Camera<F> + Sync), fast: bool) -> Image
where
    S: Layout<F> + Sync,
    M: Scatter<F, raytrace::DefaultRng> + Sync,
{
    let r = Renderer::new(scene, camera)
        .spp(2)
        .max_depth(8)
        .seed(3)
        .light_sampling(LightSampling::Mis);
    if fast { r.render() } else { r.render_reference() }
        .unwrap()
        .image
}

/// The rendered image by each renderer and path must be the same bytes.
fn renders_alike<F: Float>() {
    let built = file().build::<F>().unwrap();
    assert_eq!(built.summary.spheres, 7);
    let dynamic = built.scene.to_dyn();
    let image = |fast: bool, dyn_path: bool| -> Image {
        if dyn_path {
            image_of(&dynamic, &built.camera, fast)
        } else {
            image_of(&built.scene, &built.camera, fast)
        }
    };
    let reference = image(false, false);
    let bits = |i: &Image| i.pixels().iter().map(|p| p.map(f64::to_bits)).collect::<Vec<_>>();
    assert_eq!(
        bits(&image(true, false)),
        bits(&reference),
        "{}: fast vs reference",
        F::NAME
    );
    assert_eq!(
        bits(&image(false, true)),
        bits(&reference),
        "{}: dyn vs enum",
        F::NAME
    );
    let lit = reference
        .pixels()
        .iter()
        .filter(|p| p.iter().any(|c| *c > 0.0))
        .count();
    assert!(
        reference
            .pixels()
            .iter()
            .flatten()
            .all(|c| c.is_finite() && *c >= 0.0),
        "{}",
        F::NAME
    );
    assert!(
        lit > reference.pixels().len() / 2,
        "{}: {lit} lit pixels",
        F::NAME
    );
}

#[test]
fn every_material_renders_alike_on_every_path_in_f32() {
    renders_alike::<f32>();
}

#[test]
fn every_material_renders_alike_on_every_path_in_f64() {
    renders_alike::<f64>();
}

#[test]
fn the_scene_reads_back_from_its_toml() {
    let f = file();
    let text = f.to_toml();
    let back = SceneFile::parse(&text, Path::new("bsdfs.toml")).unwrap();
    assert_eq!(back, f, "{text}");
}

#[test]
fn cast_materials_are_the_materials_made_in_the_scalar() {
    let wide = file().build::<f64>().unwrap().scene;
    let narrow = file().build::<f32>().unwrap().scene;
    for (w, n) in wide.objects().iter().zip(narrow.objects()) {
        let (w, n) = (wide.material(w.material), narrow.material(n.material));
        let cast: MaterialKind<f32> = w.cast().unwrap();
        assert_eq!(&cast, n);
        assert_eq!(cast.lobes(), w.lobes());
    }
}

/// The examples of `docs/SCENE_FORMAT.md`'s section on these materials build as written.
#[test]
fn the_format_docs_examples_build() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/SCENE_FORMAT.md");
    let doc = std::fs::read_to_string(&path).unwrap();
    let start = doc.find("### Mitsuba 3's materials").unwrap();
    let end = start + doc[start..].find("## `[[objects]]`").unwrap();
    let blocks: Vec<&str> = doc[start..end]
        .split("```toml\n")
        .skip(1)
        .map(|b| b.split("```").next().unwrap())
        .collect();
    assert_eq!(blocks.len(), 3);
    for block in blocks {
        let file = SceneFile::parse(block, &path).unwrap_or_else(|e| panic!("{e}\n{block}"));
        file.build::<f32>().unwrap_or_else(|e| panic!("{e}\n{block}"));
        file.build::<f64>().unwrap_or_else(|e| panic!("{e}\n{block}"));
    }
}
