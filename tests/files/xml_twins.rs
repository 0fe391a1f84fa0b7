//! Every scene file `scenes/NAME.toml` has an XML twin `scenes/NAME.xml` (a Mitsuba 3
//! scene, with this renderer's `raytrace_` extensions where Mitsuba has no word) that the
//! `raytrace` binary renders to the same bytes, with the same flags: a linear PFM and a
//! tone-mapped PPM, small and with few samples so it runs in seconds. A scene with no twin
//! fails the test unless [`NO_TWIN`] names it with its reason.
//!
//! The twins are written by `tools/xml_twins.py`. The meshes `tools/fetch_meshes.sh`
//! fetches (git-ignored, absent in CI) are replaced, for both files alike, by small stand-ins
//! of the same kind (positions and faces): what is compared is what the two files say
//! (placements, materials, camera, lights, settings), not the mesh.

use raytrace::scene_file::SceneFile;
use std::fs;
use std::path::{Path, PathBuf};
use std::process::Command;

const BIN: &str = env!("CARGO_BIN_EXE_raytrace");

/// The scene files that have no twin, each with the reason: none. (A scene that needs one
/// lists it here with what Mitsuba's format and the extensions cannot say exactly.)
const NO_TWIN: &[(&str, &str)] = &[];

/// The flags both files are rendered with: small, few samples.
const FLAGS: [&str; 5] = ["--width", "48", "--spp", "3", "--quiet"];

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// The scene files, by name (`cornell_box`), in order.
fn scene_names() -> Vec<String> {
    let mut names: Vec<String> = fs::read_dir(root().join("scenes"))
        .unwrap()
        .filter_map(|e| {
            let path = e.unwrap().path();
            let stem = path.file_stem()?.to_str()?.to_owned();
            (path.extension()? == "toml").then_some(stem)
        })
        .collect();
    names.sort();
    names
}

/// A folder holding `scenes/NAME.toml`, `scenes/NAME.xml` and every file the TOML reads, at
/// the same relative places; a fetched mesh (under `assets/`) is a small stand-in.
fn mirror(name: &str, xml: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("raytrace-twins-{name}-{}", std::process::id()));
    let _ = fs::remove_dir_all(&dir);
    let scenes = dir.join("scenes");
    fs::create_dir_all(&scenes).unwrap();
    let toml = root().join("scenes").join(format!("{name}.toml"));
    fs::copy(&toml, scenes.join(format!("{name}.toml"))).unwrap();
    fs::write(scenes.join(format!("{name}.xml")), xml).unwrap();
    let file = SceneFile::load(&toml).unwrap();
    for input in file.input_files() {
        let relative = input.strip_prefix(root().join("scenes")).unwrap();
        let to = scenes.join(relative);
        fs::create_dir_all(to.parent().unwrap()).unwrap();
        if relative.starts_with("../assets") {
            stand_in(&to);
        } else {
            fs::copy(&input, &to).unwrap_or_else(|e| panic!("{}: {e}", input.display()));
        }
    }
    dir
}

/// A small mesh at `path`, of its format (OBJ or PLY): an octahedron a fifth of a unit
/// across, above `y = 0`, of positions and faces only, as the fetched meshes are (so a twin
/// says `face_normals = true` for it, as for them).
fn stand_in(path: &Path) {
    let corners = [
        [1, 0, 0],
        [-1, 0, 0],
        [0, 1, 0],
        [0, -1, 0],
        [0, 0, 1],
        [0, 0, -1],
    ]
    .map(|c: [i32; 3]| c.map(|x| 0.1 * f64::from(x)))
    .map(|[x, y, z]| [x, y + 0.1, z]);
    let faces = [
        [0, 2, 4],
        [2, 1, 4],
        [1, 3, 4],
        [3, 0, 4],
        [2, 0, 5],
        [1, 2, 5],
        [3, 1, 5],
        [0, 3, 5],
    ];
    let text = if path.extension().is_some_and(|e| e == "obj") {
        let v = corners.map(|[x, y, z]| format!("v {x} {y} {z}\n")).concat();
        v + &faces
            .map(|[a, b, c]| format!("f {} {} {}\n", a + 1, b + 1, c + 1))
            .concat()
    } else {
        let head = "ply\nformat ascii 1.0\nelement vertex 6\nproperty float x\nproperty float y\n\
                    property float z\nelement face 8\nproperty list uchar int vertex_indices\nend_header\n";
        let v = corners.map(|[x, y, z]| format!("{x} {y} {z}\n")).concat();
        head.to_owned() + &v + &faces.map(|[a, b, c]| format!("3 {a} {b} {c}\n")).concat()
    };
    fs::write(path, text).unwrap();
}

/// The bytes the binary writes for `scene` in `format` (`pfm`, `ppm`), with [`FLAGS`] and
/// `more`.
fn render(scene: &Path, format: &str, more: &[&str]) -> Vec<u8> {
    let out = scene.with_extension(format!(
        "{}.{format}",
        scene.extension().unwrap().to_str().unwrap()
    ));
    let o = Command::new(BIN)
        .args(["render", scene.to_str().unwrap(), "--format", format, "--out"])
        .arg(&out)
        .args(FLAGS)
        .args(more)
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{}: {text}", scene.display());
    fs::read(out).unwrap()
}

#[test]
fn every_scene_file_has_an_xml_twin_that_renders_its_bytes() {
    let mut missing = Vec::new();
    for name in scene_names() {
        let xml = root().join("scenes").join(format!("{name}.xml"));
        if let Some((_, why)) = NO_TWIN.iter().find(|(n, _)| *n == name) {
            assert!(!xml.exists(), "{name} is listed with no twin ({why}) but has one");
            continue;
        }
        let Ok(text) = fs::read_to_string(&xml) else {
            missing.push(name);
            continue;
        };
        let dir = mirror(&name, &text);
        let (toml, xml) = (
            dir.join(format!("scenes/{name}.toml")),
            dir.join(format!("scenes/{name}.xml")),
        );
        for format in ["pfm", "ppm"] {
            assert!(
                render(&toml, format, &[]) == render(&xml, format, &[]),
                "{name}.xml renders other {format} bytes than {name}.toml"
            );
        }
        fs::remove_dir_all(&dir).unwrap();
    }
    assert!(
        missing.is_empty(),
        "no XML twin for {missing:?}: write it (python3 tools/xml_twins.py) or list it in NO_TWIN with the reason"
    );
}

/// The comparison sees a twin's likeliest mistake: `max_depth` written as the scene file's
/// number, where Mitsuba's counts one more (the spec's scenes have no light on a surface).
#[test]
fn a_twin_with_the_scene_files_depth_renders_other_bytes() {
    let name = "four_mirrors";
    let text = fs::read_to_string(root().join(format!("scenes/{name}.xml"))).unwrap();
    let wrong = text.replace(
        r#"<integer name="max_depth" value="11"/>"#,
        r#"<integer name="max_depth" value="10"/>"#,
    );
    assert_ne!(wrong, text, "the twin's depth is no longer 11");
    let dir = mirror(name, &wrong);
    let toml = dir.join(format!("scenes/{name}.toml"));
    let xml = dir.join(format!("scenes/{name}.xml"));
    assert!(render(&toml, "ppm", &[]) != render(&xml, "ppm", &[]));
    // And with the depth set right on the command line, the bytes are the same again.
    assert!(render(&toml, "ppm", &[]) == render(&xml, "ppm", &["--max-depth", "10"]));
    fs::remove_dir_all(&dir).unwrap();
}

/// The scene format's page shows `point_lights` in both forms as the files are, so the
/// example cannot drift from what the test above proves; the README's excerpt of the
/// Cornell box is in its twin.
#[test]
fn the_docs_show_a_scene_file_and_its_twin_as_they_are() {
    let docs = fs::read_to_string(root().join("docs/SCENE_FORMAT.md")).unwrap();
    for file in ["point_lights.toml", "point_lights.xml"] {
        let text = fs::read_to_string(root().join("scenes").join(file)).unwrap();
        assert!(
            docs.contains(&text),
            "docs/SCENE_FORMAT.md does not show scenes/{file} as it is"
        );
    }
    let readme = fs::read_to_string(root().join("README.md")).unwrap();
    let twin = fs::read_to_string(root().join("scenes/cornell_box.xml")).unwrap();
    let excerpt = readme
        .split("```xml\n")
        .nth(1)
        .and_then(|rest| rest.split("```").next())
        .unwrap();
    for line in excerpt.lines() {
        assert!(
            twin.contains(line.trim()),
            "README's XML line `{line}` is not in the twin"
        );
    }
}
