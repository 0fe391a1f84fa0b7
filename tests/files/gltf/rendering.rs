//! glTF scenes rendered, each against a fact known without the importer: an emitter seen
//! straight on shows its radiance, a camera's `yfov` spans the image plane it should, a
//! base-colour texture's texels land where `uv` puts them, and a quad lit by a point
//! light renders the bytes of the same scene written as TOML by hand.

use super::import;
use super::write::{Gltf, folder};
use raytrace::Image;
use raytrace::scene_file::SceneFile;
use serde_json::json;

/// `file` rendered `width` pixels wide with `spp` samples per pixel, in f64.
fn render(mut file: SceneFile, width: usize, spp: u32) -> Image {
    file.render.width = width;
    file.render.spp = spp;
    let built = file.build::<f64>().unwrap();
    raytrace::render(&built.scene, &built.camera, &built.settings)
        .unwrap()
        .image
}

/// A square `[−h, h]²` at depth `z` facing +z, with uv `(0, 0)` at its top-left corner.
fn square(g: &mut Gltf, h: f32, z: f32, material: usize) -> usize {
    let corners = [[-h, h, z], [h, h, z], [h, -h, z], [-h, -h, z]];
    let uv = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
    let normals = [[0.0, 0.0, 1.0]; 4];
    g.mesh(
        &corners,
        Some(&normals),
        Some(&uv),
        &[0, 3, 2, 0, 2, 1],
        Some(material),
    )
}

/// A camera node at `at` looking down −z.
fn camera(g: &mut Gltf, yfov: f64, aspect: f64, at: [f64; 3]) -> usize {
    let c = g.push(
        "cameras",
        json!({ "type": "perspective", "perspective": { "yfov": yfov, "aspectRatio": aspect, "znear": 0.01 } }),
    );
    g.node(json!({ "camera": c, "translation": at }))
}

/// A black material giving off `factor · strength`.
fn emitter(g: &mut Gltf, factor: [f64; 3], strength: f64) -> usize {
    g.uses("KHR_materials_emissive_strength");
    g.push(
        "materials",
        json!({
            "pbrMetallicRoughness": { "baseColorFactor": [0, 0, 0, 1] },
            "emissiveFactor": factor,
            "extensions": { "KHR_materials_emissive_strength": { "emissiveStrength": strength } }
        }),
    )
}

#[test]
fn an_emitter_seen_straight_on_shows_its_factor_times_its_strength() {
    let mut g = Gltf::new();
    let m = emitter(&mut g, [1.0, 0.5, 0.25], 4.0);
    let mesh = square(&mut g, 1.0, 0.0, m);
    let quad = g.node(json!({ "mesh": mesh }));
    let cam = camera(&mut g, 0.5, 1.0, [0.0, 0.0, 2.0]);
    g.scene(&[quad, cam]);
    let dir = folder("emitter");
    let image = render(import(&g.save_glb(&dir, "e")).file, 8, 2);
    // A black emitter reflects nothing, and the background behind a lit scene is black:
    // every pixel is L_e = (1, 0.5, 0.25) · 4 (the quad fills the view).
    for p in image.pixels() {
        assert_eq!(*p, [4.0, 2.0, 1.0]);
    }
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn the_cameras_yfov_and_aspect_ratio_span_the_image_plane() {
    let dir = folder("yfov");
    // At distance 2, yfov = 2·atan(½) sees y ∈ [−1, 1]: a square of half-size 0.89 covers
    // the pixel rows whose centres lie within it. Row j's band of y is
    // [1 − (j + 1)/(H/2), 1 − j/(H/2)].
    let yfov = 2.0 * 0.5f64.atan();
    for (aspect, width) in [(1.0, 100), (2.0, 100)] {
        let mut g = Gltf::new();
        let m = emitter(&mut g, [1.0, 1.0, 1.0], 1.0);
        let mesh = square(&mut g, 0.89, -2.0, m);
        let quad = g.node(json!({ "mesh": mesh }));
        let cam = camera(&mut g, yfov, aspect, [0.0; 3]);
        g.scene(&[quad, cam]);
        let image = render(import(&g.save_gltf(&dir, "c")).file, width, 1);
        let (w, h) = (image.width(), image.height());
        assert_eq!((w, h), (width, (width as f64 / aspect) as usize));
        // Rows: y ∈ [−1, 1] over H pixels; the band of row j is entirely above 0.89 for
        // j + 1 ≤ 0.11·H/2 and entirely below for j ≥ 0.11·H/2 (rounded inward).
        let half = h as f64 / 2.0;
        let edge = 0.11 * half;
        let (dark, bright) = ((edge.floor() as usize).saturating_sub(1), edge.ceil() as usize);
        let column = w / 2;
        assert_eq!(
            image.pixel(column, dark)[0],
            0.0,
            "row {dark} of {h} sees past the square"
        );
        assert_eq!(
            image.pixel(column, bright)[0],
            1.0,
            "row {bright} of {h} sees the square"
        );
        assert_eq!(image.pixel(column, h - 1 - dark)[0], 0.0);
        assert_eq!(image.pixel(column, h - 1 - bright)[0], 1.0);
        // Columns: x ∈ [−aspect, aspect] over W pixels.
        let half_w = w as f64 / 2.0;
        let edge = (aspect - 0.89) / aspect * half_w;
        let (dark, bright) = ((edge.floor() as usize).saturating_sub(1), edge.ceil() as usize);
        let row = h / 2;
        assert_eq!(
            image.pixel(dark, row)[0],
            0.0,
            "column {dark} of {w} sees past the square"
        );
        assert_eq!(
            image.pixel(bright, row)[0],
            1.0,
            "column {bright} of {w} sees the square"
        );
    }
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn a_base_colour_textures_texels_land_where_uv_puts_them() {
    let mut g = Gltf::new();
    // Red, green / blue, white: uv (0, 0) is the image's top-left texel (glTF's convention).
    let image = g.png(2, 2, &[[255, 0, 0], [0, 255, 0], [0, 0, 255], [255, 255, 255]]);
    let sampler = g.push("samplers", json!({ "wrapS": 33071, "wrapT": 33071 }));
    let texture = g.push("textures", json!({ "source": image, "sampler": sampler }));
    let m = g.push(
        "materials",
        json!({ "pbrMetallicRoughness": {
            "baseColorTexture": { "index": texture }, "metallicFactor": 0, "roughnessFactor": 1 } }),
    );
    let mesh = square(&mut g, 1.0, 0.0, m);
    let quad = g.node(json!({ "mesh": mesh }));
    let cam = camera(&mut g, 2.0 * 0.4f64.atan(), 1.0, [0.0, 0.0, 3.0]);
    let sun = g.light(json!({ "type": "directional", "intensity": 683.0 }));
    let light = g.node(json!({ "extensions": { "KHR_lights_punctual": { "light": sun } } }));
    g.scene(&[quad, cam, light]);
    let dir = folder("texels");
    let imported = import(&g.save_glb(&dir, "t"));
    let image = render(imported.file, 40, 4);
    // The quadrants' centres: each is lit alike, so its colour is its texel's.
    let [tl, tr, bl, br] = [(10, 10), (30, 10), (10, 30), (30, 30)].map(|(x, y)| image.pixel(x, y));
    let dominant = |p: [f64; 3], k: usize| (0..3).all(|j| j == k || p[k] > 3.0 * p[j]);
    assert!(dominant(tl, 0), "top left is red: {tl:?}");
    assert!(dominant(tr, 1), "top right is green: {tr:?}");
    assert!(dominant(bl, 2), "bottom left is blue: {bl:?}");
    assert!(
        br.iter().all(|&c| c > 0.5 * br[0] && c > 0.05),
        "bottom right is white: {br:?}"
    );
    std::fs::remove_dir_all(dir).unwrap();
}

/// The exact decimal of an f32, as a TOML number: the value glTF's f32 becomes in f64.
fn f(x: f32) -> String {
    format!("{:?}", f64::from(x))
}

#[test]
fn a_quad_under_a_point_light_renders_the_bytes_of_its_toml_twin() {
    let (base, roughness, intensity, yfov) = ([0.8f32, 0.6, 0.4], 0.5f32, 2049.0f32, 0.9f32);
    let light_at = [0.3f32, 0.2, 1.0];
    let mut g = Gltf::new();
    let m = g.push(
        "materials",
        json!({ "pbrMetallicRoughness": { "baseColorFactor": [base[0], base[1], base[2], 1.0],
                 "metallicFactor": 0.0, "roughnessFactor": roughness } }),
    );
    let corners = [
        [-1.0, -1.0, 0.0],
        [1.0, -1.0, 0.0],
        [1.0, 1.0, 0.0],
        [-1.0, 1.0, 0.0],
    ];
    let mesh = g.mesh(&corners, None, None, &[0, 1, 2, 0, 2, 3], Some(m));
    let quad = g.node(json!({ "mesh": mesh }));
    let c = g.push(
        "cameras",
        json!({ "type": "perspective", "perspective": { "yfov": yfov, "aspectRatio": 1.0, "znear": 0.1 } }),
    );
    let cam = g.node(json!({ "camera": c, "translation": [0.0, 0.0, 3.0] }));
    let lamp = g.light(json!({ "type": "point", "intensity": intensity, "color": [1.0, 1.0, 1.0] }));
    let light = g
        .node(json!({ "translation": light_at, "extensions": { "KHR_lights_punctual": { "light": lamp } } }));
    g.scene(&[quad, cam, light]);
    let dir = folder("twin");
    let from_gltf = render(import(&g.save_glb(&dir, "quad")).file, 24, 3);

    // The twin, by hand: the quad as an OBJ file, the material the documented mapping
    // gives (rough plastic: the base colour under a coat of index 1.5, GGX, α = 0.5²),
    // the light's 2049 cd at 683 lm/W (3 W/sr), the camera at its node looking down −z.
    std::fs::write(
        dir.join("quad.obj"),
        "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3\nf 1 3 4\n",
    )
    .unwrap();
    let toml = format!(
        r#"
[camera]
type = "look_at"
from = [0.0, 0.0, 3.0]
at = [0.0, 0.0, 2.0]
vfov = {}
aspect = 1.0

[background]
type = "solid"
color = [0.0, 0.0, 0.0]

[materials.plastic]
type = "rough_plastic"
diffuse_reflectance = [{}, {}, {}]
int_ior = 1.5
ext_ior = 1.0
distribution = "ggx"
alpha = {}

[[objects]]
type = "mesh"
file = "quad.obj"
material = "plastic"

[[lights]]
type = "point"
position = [{}, {}, {}]
intensity = [3.0, 3.0, 3.0]
"#,
        f64::from(yfov).to_degrees(),
        f(base[0]),
        f(base[1]),
        f(base[2]),
        f64::from(roughness) * f64::from(roughness),
        f(light_at[0]),
        f(light_at[1]),
        f(light_at[2]),
    );
    let path = dir.join("twin.toml");
    std::fs::write(&path, toml).unwrap();
    let twin = render(SceneFile::load(&path).unwrap(), 24, 3);
    assert!(
        from_gltf.pixels().iter().filter(|p| p[0] > 0.0).count() > 100,
        "the quad is lit"
    );
    assert!(
        from_gltf.pixels() == twin.pixels(),
        "the glTF scene and its TOML twin differ"
    );
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn without_a_camera_the_scene_is_framed_and_without_lights_the_sky_lights_it() {
    use raytrace::scene_file::{BackgroundSpec, CameraSpec};
    let dir = folder("framed");
    for emits in [true, false] {
        let mut g = Gltf::new();
        let m = if emits {
            emitter(&mut g, [1.0, 1.0, 1.0], 1.0)
        } else {
            g.push(
                "materials",
                json!({ "pbrMetallicRoughness": { "metallicFactor": 0 } }),
            )
        };
        let mesh = square(&mut g, 1.0, 0.0, m);
        let quad = g.node(json!({ "mesh": mesh, "translation": [5.0, 1.0, 0.0] }));
        g.scene(&[quad]);
        let file = import(&g.save_glb(&dir, "f")).file;
        // The box around the square: centre (5, 1, 0), half its diagonal √2; seen whole
        // in 40° from √2 / sin 20° along +z.
        let CameraSpec::LookAt {
            from,
            at,
            vfov,
            aspect,
            ..
        } = file.camera
        else {
            panic!()
        };
        let d = 2f64.sqrt() / 20f64.to_radians().sin();
        assert_eq!(at, [5.0, 1.0, 0.0]);
        assert!((from[2] - d).abs() < 1e-12 && from[..2] == [5.0, 1.0], "{from:?}");
        assert_eq!((vfov, aspect), (40.0, 4.0 / 3.0));
        let lit_by_sky = matches!(file.background, BackgroundSpec::Sky { light: true, .. });
        assert_eq!(lit_by_sky, !emits, "{:?}", file.background);
        let image = render(file, 40, 4);
        assert_eq!((image.width(), image.height()), (40, 30));
        // The square fills the middle: ±1 of the ±d·tan 20° = ±1.51 the rows span.
        let centre = image.pixel(20, 15);
        assert!(
            centre.iter().all(|&c| c > 0.05),
            "the square is seen and lit: {centre:?}"
        );
        if emits {
            assert_eq!(centre, [1.0; 3]);
            assert_eq!(image.pixel(20, 1), [0.0; 3], "above the square, black");
        }
    }
    std::fs::remove_dir_all(dir).unwrap();
}
