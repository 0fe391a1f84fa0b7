//! Scene files: each example's file builds the example's scene (the same image bits as
//! the code, in f32 and f64), no input makes the parser panic, and what it accepts reads
//! back from its TOML. Where mistakes are reported: tests/scene_file_errors.rs.

use crate::common;
use crate::scenes;

use proptest::prelude::*;
use raytrace::image::ToneCurve;
use raytrace::prelude::*;
use raytrace::scene_file::{
    BackgroundSpec, CameraSpec, FilePrecision, FresnelSpec, LightSpec, MaterialSpec, ObjectSpec,
    RenderOptions, Scale, SceneFile,
};
use raytrace::{Acceleration, BvhQuality, Image};
use std::path::{Path, PathBuf};

const WIDTH: usize = 48;
const SPP: u32 = 2;

fn scene_path(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("scenes")
        .join(format!("{name}.toml"))
}

/// The example's file rendered small, in `F`.
fn from_file<F: Float>(name: &str) -> (Image, RenderOptions) {
    let mut file = SceneFile::load(&scene_path(name)).unwrap();
    let defaults = file.render().clone();
    file.render_mut().width = WIDTH;
    file.render_mut().spp = SPP;
    let built = file.build::<F>().unwrap();
    (
        render(&built.scene, &built.camera, &built.settings)
            .unwrap()
            .image,
        defaults,
    )
}

/// The code-built scene rendered the same way, in `F`.
fn from_code<F: Float>(name: &str, max_depth: u32) -> Image {
    let settings = RenderSettings::new(SPP, max_depth, 0).unwrap();
    let spec = |scene: raytrace::Result<EnumScene<F>>| {
        render(
            &scene.unwrap(),
            &ScreenCamera::with_width(WIDTH).unwrap(),
            &settings,
        )
    };
    let rendered = match name {
        "four_mirrors" => spec(scenes::four_mirrors()),
        "matte_spheres" => spec(scenes::matte_spheres()),
        "glass" => spec(scenes::glass()),
        "plane_and_triangles" => spec(scenes::plane_and_triangles()),
        "point_lights" => spec(scenes::point_lights()),
        "random_spheres" => render(
            &scenes::random_spheres::<F>(0).unwrap(),
            &scenes::random_spheres_camera::<F>(WIDTH).unwrap(),
            &settings,
        ),
        _ => unreachable!("{name}"),
    };
    rendered.unwrap().image
}

/// Each example's name and its defaults (examples/*.rs): width, spp, max depth.
const EXAMPLES: [(&str, usize, u32, u32); 6] = [
    ("four_mirrors", 800, 1, 10),
    ("matte_spheres", 800, 16, 10),
    ("glass", 800, 32, 20),
    ("plane_and_triangles", 800, 32, 20),
    ("point_lights", 800, 16, 10),
    ("random_spheres", 400, 10, 50),
];

fn same_image_as_code<F: Float>() {
    for (name, width, spp, max_depth) in EXAMPLES {
        let (file, defaults) = from_file::<F>(name);
        assert_eq!(
            (defaults.width, defaults.spp, defaults.max_depth, defaults.seed),
            (width, spp, max_depth, 0),
            "{name}: the file's [render] is the example's defaults"
        );
        assert_eq!(file, from_code::<F>(name, max_depth), "{name} in {}", F::NAME);
    }
}

#[test]
fn every_example_file_renders_the_code_built_image_in_f64() {
    same_image_as_code::<f64>();
}

#[test]
fn every_example_file_renders_the_code_built_image_in_f32() {
    same_image_as_code::<f32>();
}

#[test]
fn summaries_count_what_the_files_hold() {
    let built = SceneFile::load(&scene_path("plane_and_triangles"))
        .unwrap()
        .build::<f64>()
        .unwrap();
    let s = built.summary;
    assert_eq!(
        (s.spheres, s.planes, s.triangles, s.meshes, s.lights),
        (2, 1, 8, 0, 0)
    );
    let b = s.bounds.unwrap();
    // Shapes pad their boxes by a few units of rounding.
    assert!((b.min.y + 0.8).abs() < 1e-12, "{b:?}");
    assert!(
        (b.max.x - 4.5).abs() < 1e-12,
        "the sphere at x = 3.5 of radius 1: {b:?}"
    );
    assert!(!s.uses_bvh);
    let many = SceneFile::load(&scene_path("random_spheres"))
        .unwrap()
        .build::<f32>()
        .unwrap();
    assert!(many.summary.uses_bvh && many.summary.spheres > 400);
}

/// `bvh_quality = "high"` reaches the scene: its spatial splits cut the long triangles among
/// small ones (the references exceed the parts), where `"medium"` (the default) cuts none.
#[test]
fn the_bvh_quality_reaches_the_scene() {
    let mut objects = String::new();
    for i in 0..60 {
        let (x, y) = ((i % 8) as f64 - 4.0, (i / 8) as f64 - 4.0);
        let (a, b, c) = if i % 10 == 0 {
            (
                [x - 3.0, y - 3.0, -9.0],
                [x + 3.0, y + 3.0, -3.0],
                [x, y + 0.1, -6.0],
            )
        } else {
            ([x, y, -6.0], [x + 0.3, y, -6.0], [x, y + 0.3, -6.2])
        };
        objects +=
            &format!("[[objects]]\ntype = \"triangle\"\na = {a:?}\nb = {b:?}\nc = {c:?}\nmaterial = \"m\"\n");
    }
    let built = |quality: &str| {
        let text = format!(
            "[render]\nwidth = 8\nbvh_quality = \"{quality}\"\n[materials.m]\ntype = \"lambertian\"\nalbedo = [0.5, 0.5, 0.5]\n{objects}"
        );
        let built = SceneFile::parse(&text, Path::new("splits.toml"))
            .unwrap()
            .build::<f32>()
            .unwrap();
        assert_eq!(format!("{:?}", built.scene.bvh_quality()).to_lowercase(), quality);
        built.summary.bvh_references.unwrap()
    };
    assert_eq!(built("medium"), 60);
    let high = built("high");
    assert!(high > 70, "the six long triangles cut: {high} references");
}

const GOOD: &str = include_str!("../../scenes/four_mirrors.toml");

fn triple(range: std::ops::Range<f64>) -> impl Strategy<Value = [f64; 3]> {
    [range.clone(), range.clone(), range]
}

/// Any finite `f64`, tiny and huge ones included.
fn finite() -> impl Strategy<Value = f64> {
    prop_oneof![
        -1e3..1e3f64,
        any::<f64>().prop_filter("finite", |x| x.is_finite())
    ]
}

fn any_file() -> impl Strategy<Value = SceneFile> {
    let render = (
        1..5000usize,
        1..100u32,
        0..1000u32,
        any::<u64>(),
        0..3u8,
        0..3u8,
        prop_oneof![Just(0.0), finite()],
        any::<bool>(),
        any::<bool>(),
    )
        .prop_map(
            |(width, spp, max_depth, seed, p, a, exposure, aces, high)| RenderOptions {
                width,
                spp,
                max_depth,
                seed,
                precision: [FilePrecision::F32, FilePrecision::F64, FilePrecision::Auto][p as usize],
                acceleration: [Acceleration::Auto, Acceleration::Linear, Acceleration::Bvh][a as usize],
                bvh_quality: if high {
                    BvhQuality::High
                } else {
                    BvhQuality::Medium
                },
                exposure,
                tonemap: if aces { ToneCurve::Aces } else { ToneCurve::None },
            },
        );
    let camera = prop_oneof![
        proptest::option::of([finite(), finite(), finite()]).prop_map(|eye| CameraSpec::Screen { eye }),
        (
            [finite(), finite(), finite()],
            triple(-5.0..5.0),
            triple(-1.0..1.0),
            1.0..179.0f64,
            0.1..10.0f64,
            prop_oneof![Just(0.0), finite()],
            proptest::option::of(finite())
        )
            .prop_map(
                |(from, at, up, vfov, aspect, aperture, focus_distance)| CameraSpec::LookAt {
                    from,
                    at,
                    up,
                    vfov,
                    aspect,
                    aperture,
                    focus_distance
                }
            ),
    ];
    let background = prop_oneof![
        (triple(0.0..2.0), triple(0.0..2.0)).prop_map(|(horizon, zenith)| BackgroundSpec::Sky {
            horizon,
            zenith,
            light: false
        }),
        triple(0.0..1.0).prop_map(|color| BackgroundSpec::Solid { color, light: false }),
    ];
    let material = prop_oneof![
        triple(0.0..1.0).prop_map(|albedo| MaterialSpec::Mirror { albedo }),
        triple(0.0..1.0).prop_map(|albedo| MaterialSpec::Lambertian {
            albedo: albedo.into()
        }),
        (finite(), proptest::option::of(triple(0.0..1.0)), any::<bool>()).prop_map(
            |(index, albedo, exact)| {
                MaterialSpec::Dielectric {
                    index,
                    albedo,
                    fresnel: if exact {
                        FresnelSpec::Exact
                    } else {
                        FresnelSpec::Schlick
                    },
                }
            }
        ),
    ];
    let name = "\\PC{1,10}";
    let object = prop_oneof![
        ([finite(), finite(), finite()], finite(), name).prop_map(|(center, radius, material)| {
            ObjectSpec::Sphere {
                center,
                radius,
                material,
            }
        }),
        (triple(-9.0..9.0), triple(-1.0..1.0), name).prop_map(|(point, normal, material)| {
            ObjectSpec::Plane {
                point,
                normal,
                material,
            }
        }),
        (triple(-9.0..9.0), triple(-9.0..9.0), triple(-9.0..9.0), name)
            .prop_map(|(a, b, c, material)| ObjectSpec::Triangle { a, b, c, material }),
        (
            name,
            prop_oneof![
                finite().prop_map(Scale::Uniform),
                triple(-3.0..3.0).prop_map(Scale::PerAxis)
            ],
            triple(-360.0..360.0),
            triple(-9.0..9.0),
            name
        )
            .prop_map(|(file, scale, rotate, translate, material)| ObjectSpec::Mesh {
                file,
                scale,
                rotate,
                translate,
                material,
                face_normals: false,
                flip_tex_coords: None,
                matrix: None,
            }),
    ];
    let light = prop_oneof![
        (triple(-9.0..9.0), triple(0.0..50.0))
            .prop_map(|(position, intensity)| LightSpec::Point { position, intensity }),
        (
            triple(-9.0..9.0),
            triple(-1.0..1.0),
            triple(0.0..50.0),
            finite(),
            proptest::option::of(finite())
        )
            .prop_map(
                |(position, direction, intensity, cutoff_angle, beam_width)| LightSpec::Spot {
                    position,
                    direction,
                    intensity,
                    cutoff_angle,
                    beam_width
                }
            ),
        (triple(-1.0..1.0), triple(0.0..5.0)).prop_map(|(direction, irradiance)| LightSpec::Directional {
            direction,
            irradiance
        }),
    ];
    (
        render,
        camera,
        background,
        proptest::collection::btree_map(name, material, 0..4),
        proptest::collection::vec(object, 0..5),
        proptest::collection::vec(light, 0..3),
    )
        .prop_map(|(render, camera, background, materials, objects, lights)| {
            let mut file = SceneFile::parse("", Path::new("p.toml")).unwrap();
            *file.render_mut() = render;
            file.camera = camera;
            file.background = background;
            file.materials = materials;
            file.objects = objects;
            file.lights = lights;
            file
        })
}

proptest! {
    #![proptest_config(common::config(256, 0x5CE4_E000, "proptest-regressions/scene_files.txt"))]

    #[test]
    fn any_text_is_parsed_or_refused_without_panicking(text in "\\PC{0,200}") {
        let _ = SceneFile::parse(&text, Path::new("p.toml")).map(|f| f.build::<f32>().map(|b| b.summary));
    }

    #[test]
    fn any_edit_of_a_real_file_is_refused_without_panicking_or_read_back_from_its_toml(
        at in 0..GOOD.len(), cut in 0..20usize, insert in "[\\[\\]=\"a-z0-9.,\\n -]{0,12}",
    ) {
        let mut text = GOOD.as_bytes()[..at].to_vec();
        text.extend_from_slice(insert.as_bytes());
        text.extend_from_slice(&GOOD.as_bytes()[(at + cut).min(GOOD.len())..]);
        let text = String::from_utf8_lossy(&text);
        if let Ok(file) = SceneFile::parse(&text, Path::new("p.toml")) {
            let _ = file.build::<f64>().map(|b| b.summary);
            // What is accepted reads back from its TOML (compared in Debug form, where a
            // NaN the edit made, `nan`, equals itself and -0 differs from 0).
            let toml = file.to_toml();
            let back = SceneFile::parse(&toml, Path::new("p.toml"));
            prop_assert!(back.is_ok(), "{:?} from {}", back, toml);
            prop_assert_eq!(format!("{:?}", back.unwrap()), format!("{file:?}"), "{}", toml);
        }
    }

    #[test]
    fn every_file_reads_back_from_its_toml(file in any_file()) {
        let text = file.to_toml();
        prop_assert_eq!(SceneFile::parse(&text, Path::new("p.toml")).unwrap(), file, "{}", text);
    }
}

#[test]
fn the_format_documents_example_parses() {
    let doc = include_str!("../../docs/SCENE_FORMAT.md");
    let (_, example) = doc.split_once("\n## Example\n").unwrap();
    let (_, rest) = example.split_once("```toml\n").unwrap();
    let (example, _) = rest.split_once("```").unwrap();
    let file = SceneFile::parse(example, Path::new("docs/example.toml")).unwrap();
    assert_eq!(
        (file.objects.len(), file.materials.len(), file.lights.len()),
        (4, 3, 1)
    );
    // Saved in scenes/, as the page says, it names the file the fetch script writes.
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let script = include_str!("../../tools/fetch_meshes.sh");
    assert!(script.contains("dest=assets/meshes\n") && script.contains("\"$dest/bunny.obj\""));
    let ObjectSpec::Mesh { file: mesh, .. } = &file.objects[3] else {
        panic!("the example's fourth object is the bunny")
    };
    let resolved = Path::new("scenes")
        .join(mesh)
        .components()
        .fold(PathBuf::new(), |mut path, part| {
            match part {
                std::path::Component::ParentDir => {
                    path.pop();
                }
                part => path.push(part),
            }
            path
        });
    assert_eq!(resolved, Path::new("assets/meshes/bunny.obj"), "{mesh}");
    let bunny = root.join("scenes").join(mesh);
    // With the bunny fetched it builds as written; without, with the committed
    // tetrahedron in its place, beside a file in tests/data/.
    if bunny.exists() {
        let file = SceneFile::parse(example, &root.join("scenes/example.toml")).unwrap();
        assert_eq!(file.build::<f32>().unwrap().summary.meshes, 1);
    }
    let example = example.replace("../assets/meshes/bunny.obj", "meshes/tetrahedron.obj");
    let file = SceneFile::parse(&example, Path::new("tests/data/example.toml")).unwrap();
    let summary = file.build::<f32>().unwrap().summary;
    assert_eq!(
        (summary.spheres, summary.planes, summary.meshes, summary.triangles),
        (2, 1, 1, 4)
    );
}

#[test]
fn auto_precision_is_advised_on_the_files_scene() {
    let mut file = SceneFile::load(&scene_path("four_mirrors")).unwrap();
    file.render_mut().width = 16;
    let advice = raytrace::scene_file::advise_precision(&file).unwrap();
    // The spec's scene near the origin is within one 8-bit step in f64 at least.
    assert!(advice.f64.error.within_one_step(), "{advice:?}");
}

#[test]
fn auto_precision_picks_f64_for_a_scene_only_f64_holds_and_names_the_key() {
    let text = GOOD.replace("radius = 1.0\n", "radius = 1e-60\n");
    let mut file = SceneFile::parse(&text, Path::new("tiny.toml")).unwrap();
    file.render_mut().width = 16;
    let advice = raytrace::scene_file::advise_precision(&file).expect("advice, not an error");
    assert_eq!(advice.recommended, raytrace::advice::Precision::F64);
    let why = advice.reason.to_string();
    assert!(
        why.contains("cannot be built in f32")
            && why.contains("tiny.toml: line 61, column 10: objects[3].radius"),
        "{why}"
    );
}
