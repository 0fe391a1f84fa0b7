//! Splitting an OBJ file by material: each part's faces and vertices, the order of the
//! parts, and the errors named at their line.

use super::*;
use std::path::PathBuf;

/// A folder of this process holding `files` (name, text).
fn folder(name: &str, files: &[(&str, &str)]) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("raytrace-objparts-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for (file, text) in files {
        std::fs::write(dir.join(file), text).unwrap();
    }
    dir
}

const LIB: &str = "newmtl red\nKd 1 0 0\nnewmtl blue\nKd 0 0 1\nnewmtl unused\n";

/// Two quads side by side and a triangle; `usemtl` switches red, blue, back to red.
const OBJ: &str = "mtllib lib.mtl\n\
    v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nv 2 1 0\n\
    g left\nusemtl red\nf 1 2 3 4\n\
    g right\nusemtl blue\nf 2 5 6 3\n\
    usemtl red\nf 1 2 2\nf 4 3 5\n";

#[test]
fn faces_go_to_the_part_of_their_material() {
    let dir = folder("split", &[("lib.mtl", LIB), ("m.obj", OBJ)]);
    let read = load_parts(&dir.join("m.obj")).unwrap();
    let names: Vec<&str> = read.parts.iter().map(|p| p.material.name.as_str()).collect();
    assert_eq!(names, ["red", "blue"]);
    let [red, blue] = &read.parts[..] else {
        unreachable!()
    };
    // The red quad's fan, then (the degenerate face skipped) the last triangle.
    let v = |i: u32, p: &ObjPart| p.mesh.positions[i as usize].to_f64();
    let red_tris: Vec<[[f64; 3]; 3]> = red.mesh.triangles.iter().map(|t| t.map(|i| v(i, red))).collect();
    assert_eq!(
        red_tris,
        [
            [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0]],
            [[0.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]],
            [[0.0, 1.0, 0.0], [1.0, 1.0, 0.0], [2.0, 0.0, 0.0]],
        ]
    );
    // Only the vertices a part uses, in the order first used: the reader's vertices are
    // per object and material run, so the red quad's and the red triangle's are apart.
    assert_eq!((red.mesh.positions.len(), blue.mesh.positions.len()), (7, 4));
    assert_eq!(blue.mesh.triangles, [[0, 1, 2], [0, 2, 3]]);
    assert_eq!(
        (red.mesh.skipped_degenerate, blue.mesh.skipped_degenerate),
        (1, 0)
    );
    assert_eq!(read.libraries.len(), 1);
    assert_eq!(read.libraries[0].materials.len(), 3);
    assert_eq!(usemtl_names(&dir.join("m.obj")).unwrap(), ["red", "blue"]);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn normals_and_texture_coordinates_follow_their_vertices() {
    let obj = "mtllib lib.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvt 1 1\n\
               vn 0 0 1\nusemtl blue\nf 2/2/1 4/4/1 3/3/1\nusemtl red\nf 1/1/1 2/2/1 3/3/1\n";
    let dir = folder("attributes", &[("lib.mtl", LIB), ("m.obj", obj)]);
    let read = load_parts(&dir.join("m.obj")).unwrap();
    let blue = &read.parts[0].mesh;
    assert_eq!(
        blue.uvs.as_deref(),
        Some(&[[1.0, 0.0], [1.0, 1.0], [0.0, 1.0]][..])
    );
    assert_eq!(blue.normals.as_ref().map(Vec::len), Some(3));
    let red = &read.parts[1].mesh;
    assert_eq!(
        red.uvs.as_deref(),
        Some(&[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]][..])
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn material_mistakes_are_named_at_their_line() {
    let quad = "v 0 0 0\nv 1 0 0\nv 1 1 0\n";
    for (name, files, words) in [
        (
            "bare",
            vec![
                ("lib.mtl", LIB),
                ("m.obj", "mtllib lib.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\n"),
            ],
            "line 5: face 1 comes before any `usemtl`",
        ),
        (
            "unknown",
            vec![
                ("lib.mtl", LIB),
                (
                    "m.obj",
                    "mtllib lib.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nusemtl green\nf 1 2 3\n",
                ),
            ],
            "line 5: `usemtl green`: no such material: its libraries define `red`, `blue`, `unused`",
        ),
        (
            "nolib",
            vec![("m.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nusemtl red\nf 1 2 3\n")],
            "line 4: `usemtl red`: no such material: the file names no material library (`mtllib`)",
        ),
        (
            "missing",
            vec![(
                "m.obj",
                "\nmtllib gone.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nusemtl red\nf 1 2 3\n",
            )],
            "line 2: `mtllib gone.mtl`:",
        ),
        (
            "twice",
            vec![
                ("a.mtl", "newmtl red\n"),
                ("b.mtl", "\nnewmtl red\n"),
                (
                    "m.obj",
                    "mtllib a.mtl b.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nusemtl red\nf 1 2 3\n",
                ),
            ],
            "line 1: material `red` is defined in",
        ),
        (
            "empty",
            vec![("m.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nusemtl\nf 1 2 3\n")],
            "line 4: cannot parse",
        ),
    ] {
        let dir = folder(name, &files);
        let got = load_parts(&dir.join("m.obj"));
        std::fs::remove_dir_all(&dir).unwrap();
        match got {
            Err(Error::Mesh { message, path }) => {
                assert!(message.contains(words), "{name}: {message}");
                assert!(path.ends_with("m.obj"), "{name}: {path:?}");
            }
            other => panic!("{name}: {other:?}"),
        }
    }
    // A malformed library is named by its own file and line.
    let dir = folder(
        "badlib",
        &[
            ("lib.mtl", "newmtl red\nKd red\n"),
            ("m.obj", &format!("mtllib lib.mtl\n{quad}usemtl red\nf 1 2 3\n")),
        ],
    );
    let message = load_parts(&dir.join("m.obj")).unwrap_err().to_string();
    std::fs::remove_dir_all(&dir).unwrap();
    assert!(message.contains("lib.mtl: line 2: `Kd`"), "{message}");
}
