//! Instances in scene files: a `[meshes.NAME]` entry read once and placed by
//! `type = "instance"` objects, each with its own transform and material. An instance lands
//! where a `type = "mesh"` object with the same keys lands (the same convention: scale,
//! then x, y, z turns, then translate), shares one prototype with every other placement,
//! and a name or file that is wrong is an error at its key.

use raytrace::Error;
use raytrace::scene_file::SceneFile;
use raytrace::shape::ShapeKind;
use std::path::Path;
use std::sync::Arc;

/// The same cube placed twice as instances of `[meshes.cube]`, then twice as mesh objects
/// with the same keys.
const FILE: &str = r#"
[meshes.cube]
file = "meshes/cube.obj"

[materials.grey]
type = "lambertian"
albedo = [0.5, 0.5, 0.5]

[materials.red]
type = "lambertian"
albedo = [0.8, 0.1, 0.1]

[[objects]]
type = "instance"
mesh = "cube"
scale = [0.5, 0.25, 0.3]
rotate = [30, -45, 70]
translate = [0, 0, -3]
material = "grey"

[[objects]]
type = "instance"
mesh = "cube"
scale = 0.2
rotate = [0, 90, 0]
translate = [1, 0.5, -2]
material = "red"

[[objects]]
type = "mesh"
file = "meshes/cube.obj"
scale = [0.5, 0.25, 0.3]
rotate = [30, -45, 70]
translate = [0, 0, -3]
material = "grey"

[[objects]]
type = "mesh"
file = "meshes/cube.obj"
scale = 0.2
rotate = [0, 90, 0]
translate = [1, 0.5, -2]
material = "red"
"#;

fn parse(text: &str) -> SceneFile {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/instances.toml");
    SceneFile::parse(text, &path).unwrap()
}

#[test]
fn an_instance_lands_where_a_mesh_with_the_same_keys_does() {
    let built = parse(FILE).build::<f64>().unwrap();
    let objects = built.scene.objects();
    assert_eq!(built.summary.instances, 2);
    for k in 0..2 {
        let (ShapeKind::Instance(instance), ShapeKind::Mesh(mesh)) =
            (&objects[k].shape, &objects[k + 2].shape)
        else {
            panic!("objects {k} and {}: an instance and a mesh", k + 2);
        };
        assert_eq!(objects[k].material, objects[k + 2].material);
        let count = mesh.triangles().len() as u32;
        assert_eq!(count, 12);
        for t in 0..count {
            // The two compose the same map in another order of operations: equal to
            // rounding, far from any other convention (a turn the other way moves a
            // corner by a sizeable share of the cube).
            for (a, b) in instance.triangle(t).into_iter().zip(mesh.triangle(t)) {
                assert!(
                    (a - b).length() < 1e-12,
                    "object {k}, triangle {t}: {a:?} against {b:?}"
                );
            }
        }
    }
    // One prototype for both placements.
    let (ShapeKind::Instance(a), ShapeKind::Instance(b)) = (&objects[0].shape, &objects[1].shape) else {
        unreachable!()
    };
    assert!(Arc::ptr_eq(a.prototype(), b.prototype()));
}

#[test]
fn the_shared_mesh_is_an_input_of_the_scene() {
    let file = parse(FILE);
    let cube = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/meshes/cube.obj");
    assert!(file.input_files().contains(&cube), "{:?}", file.input_files());
    let back = SceneFile::parse(&file.to_toml(), file.path()).unwrap();
    assert_eq!(back, file);
}

#[test]
fn a_wrong_mesh_name_or_file_is_an_error_at_its_key() {
    let cases = [
        (
            FILE.replacen("mesh = \"cube\"", "mesh = \"cub\"", 1),
            "objects[0].mesh",
            "no mesh named `cub`",
        ),
        (
            FILE.replace(
                "file = \"meshes/cube.obj\"\n\n[materials",
                "file = \"meshes/nope.obj\"\n\n[materials",
            ),
            "meshes.cube.file",
            "nope.obj",
        ),
        (
            FILE.replacen("scale = 0.2", "scale = 0", 1),
            "objects[1].scale",
            "non-zero",
        ),
    ];
    for (text, key, words) in cases {
        match parse(&text).build::<f32>().map(drop) {
            Err(e @ Error::SceneFile { .. }) => {
                let message = e.to_string();
                assert!(
                    message.contains(key) && message.contains(words),
                    "{key}: {message}"
                );
            }
            other => panic!("{key}: {other:?}"),
        }
    }
}
