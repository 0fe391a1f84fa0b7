//! The mistakes a mesh object with `material = "mtl"` can meet, each an error that names
//! the scene file and key, then the OBJ or `.mtl` file and the line at fault: a face
//! without `usemtl`, a name no library defines, a missing library or image, a value out of
//! its domain (in `f64`, or only once rounded to `f32`), a PLY file, and a `[materials]`
//! entry named `mtl`.

use crate::common::Scratch;
use raytrace::scene_file::SceneFile;

const MESH: &str = "[[objects]]\ntype = \"mesh\"\nfile = \"m.obj\"\nmaterial = \"mtl\"\n";

/// A triangle after `head` (`mtllib` and `usemtl` lines).
fn obj(head: &str) -> String {
    format!("{head}v 0 0 -3\nv 1 0 -3\nv 0 1 -3\nf 1 2 3\n")
}

/// The error of building `scene` (with the files `files`) in `f64`, or in `f32` if asked.
fn error(name: &str, files: &[(&str, &str)], scene: &str, f32: bool) -> String {
    let dir = Scratch::new(&format!("obj-error-{name}"));
    for (file, text) in files {
        dir.file(file, text);
    }
    let path = dir.file("scene.toml", scene);
    let file = SceneFile::load(&path).unwrap();
    let built = if f32 {
        file.build::<f32>().map(drop)
    } else {
        file.build::<f64>().map(drop)
    };
    match built {
        Err(e) => e.to_string(),
        Ok(()) => panic!("{name}: built"),
    }
}

#[test]
fn each_mistake_names_its_file_and_line() {
    let lib = "newmtl red\nKd 1 0 0\n";
    for (name, files, words) in [
        (
            "bare",
            vec![("lib.mtl", lib.to_string()), ("m.obj", obj("mtllib lib.mtl\n"))],
            &[
                "objects[0].file",
                "m.obj: line 5: face 1 comes before any `usemtl`",
            ][..],
        ),
        (
            "unknown",
            vec![
                ("lib.mtl", lib.into()),
                ("m.obj", obj("mtllib lib.mtl\nusemtl green\n")),
            ],
            &[
                "objects[0].file",
                "m.obj: line 2: `usemtl green`: no such material: its libraries define `red`",
            ],
        ),
        (
            "missing library",
            vec![("m.obj", obj("mtllib gone.mtl\nusemtl red\n"))],
            &[
                "objects[0].file",
                "m.obj: line 1: `mtllib gone.mtl`:",
                "gone.mtl: cannot open",
            ],
        ),
        (
            "missing image",
            vec![
                ("lib.mtl", "newmtl red\n\nmap_Kd -s 2 2 gone.png\n".into()),
                ("m.obj", obj("mtllib lib.mtl\nusemtl red\n")),
            ],
            &[
                "objects[0].material",
                "lib.mtl: line 3: material `red`: `map_Kd`:",
                "gone.png",
            ],
        ),
        (
            "albedo",
            vec![
                ("lib.mtl", "newmtl red\n# too bright\nKd 1.5 0 0\n".into()),
                ("m.obj", obj("mtllib lib.mtl\nusemtl red\n")),
            ],
            &[
                "objects[0].material",
                "lib.mtl: line 3: material `red`: `Kd`: each channel must be in [0, 1]",
            ],
        ),
        (
            "specular",
            vec![
                ("lib.mtl", "newmtl red\nKd 0.5 0 0\nKs 2 2 2\n".into()),
                ("m.obj", obj("mtllib lib.mtl\nusemtl red\n")),
            ],
            &["objects[0].material", "lib.mtl: line 3: material `red`: `Ks`:"],
        ),
        (
            "index",
            vec![
                ("lib.mtl", "newmtl glass\nd 0.2\nNi -1\n".into()),
                ("m.obj", obj("mtllib lib.mtl\nusemtl glass\n")),
            ],
            &["objects[0].material", "lib.mtl: line 3: material `glass`: `Ni`:"],
        ),
        (
            "ply",
            vec![("m.ply", "ply\n".into())],
            &["objects[0].material", "is not an OBJ file"],
        ),
    ] {
        let scene = MESH.replace("m.obj", if name == "ply" { "m.ply" } else { "m.obj" });
        let files: Vec<(&str, &str)> = files.iter().map(|(f, t)| (*f, t.as_str())).collect();
        let message = error(name, &files, &scene, false);
        assert!(message.contains("scene.toml"), "{name}: {message}");
        for w in words {
            assert!(message.contains(w), "{name}: `{w}` not in {message}");
        }
    }
}

#[test]
fn a_value_only_f32_cannot_hold_says_so() {
    let files = [
        ("lib.mtl", "newmtl lamp\nKe 1e300 1 1\n"),
        ("m.obj", &obj("mtllib lib.mtl\nusemtl lamp\n")),
    ];
    let message = error("rounding", &files, MESH, true);
    assert!(
        message.contains("lib.mtl: line 2: material `lamp`: `Ke`:")
            && message.contains("in f32: the value as written is valid in f64"),
        "{message}"
    );
    let dir = Scratch::new("obj-error-rounding-f64");
    for (file, text) in files {
        dir.file(file, text);
    }
    let path = dir.file("scene.toml", MESH);
    assert!(SceneFile::load(&path).unwrap().build::<f64>().is_ok());
}

#[test]
fn a_materials_entry_named_mtl_is_ambiguous_for_a_mesh() {
    let files = [
        ("lib.mtl", "newmtl red\n"),
        ("m.obj", &obj("mtllib lib.mtl\nusemtl red\n")),
    ];
    let scene = format!("[materials.mtl]\ntype = \"lambertian\"\nalbedo = [0.5, 0.5, 0.5]\n\n{MESH}");
    let message = error("ambiguous", &files, &scene, false);
    assert!(
        message.contains("objects[0].material") && message.contains("rename the entry"),
        "{message}"
    );
    // A sphere may use such an entry: only a mesh takes its file's materials.
    let dir = Scratch::new("obj-error-sphere");
    let path = dir.file(
        "scene.toml",
        "[materials.mtl]\ntype = \"lambertian\"\nalbedo = [0.5, 0.5, 0.5]\n\n[[objects]]\n\
         type = \"sphere\"\ncenter = [0, 0, -3]\nradius = 1\nmaterial = \"mtl\"\n",
    );
    assert!(SceneFile::load(&path).unwrap().build::<f64>().is_ok());
}
