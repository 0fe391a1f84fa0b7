//! Mesh loading: OBJ and PLY files become the same triangles, bad files are errors naming the
//! file and the element, and no input panics the loader.

use crate::common;

use proptest::prelude::*;
use raytrace::Error;
use raytrace::mesh::{MeshData, load};
use std::path::{Path, PathBuf};

/// A scratch folder for one test, named by the process and the test; removed on drop.
struct Scratch(PathBuf);

impl Scratch {
    fn new(test: &str) -> Self {
        let dir = std::env::temp_dir().join(format!("raytrace-meshes-{}-{test}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        Self(dir)
    }

    /// Writes `bytes` to the file `name` in the folder and returns its path.
    fn file(&self, name: &str, bytes: impl AsRef<[u8]>) -> PathBuf {
        let path = self.0.join(name);
        std::fs::write(&path, bytes).unwrap();
        path
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// The message of the `Error::Mesh` that loading `path` must give; its display names the file.
fn mesh_error(path: &Path) -> String {
    let error = load(path).expect_err(&path.display().to_string());
    assert!(error.to_string().starts_with(&path.display().to_string()));
    match error {
        Error::Mesh { path: named, message } => {
            assert_eq!(named, path);
            message
        }
        other => panic!("{}: expected Error::Mesh, got {other:?}", path.display()),
    }
}

/// Each triangle as its corners, independent of how the reader numbered the vertices.
fn corners(mesh: &MeshData) -> Vec<[[f64; 3]; 3]> {
    let p = |i: u32| mesh.positions[i as usize].to_f64();
    mesh.triangles.iter().map(|t| t.map(p)).collect()
}

const SQUARE_OBJ: &str = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";

#[test]
fn a_quad_is_two_triangles_and_a_pentagon_three() {
    let dir = Scratch::new("obj_polygons");
    let quad = load(&dir.file("quad.obj", format!("{SQUARE_OBJ}f 1 2 3 4\n"))).unwrap();
    assert_eq!(quad.positions.len(), 4);
    assert_eq!(quad.triangles, vec![[0, 1, 2], [0, 2, 3]]);
    assert_eq!(quad.skipped_degenerate, 0);

    let pentagon = "v 0 0 0\nv 2 0 0\nv 3 2 0\nv 1 3 0\nv -1 2 0\nf 1/1 2/1 3/1 4/1 5/1\nvt 0 0\n";
    let pentagon = load(&dir.file("pentagon.OBJ", pentagon)).unwrap();
    assert_eq!(pentagon.triangles, vec![[0, 1, 2], [0, 2, 3], [0, 3, 4]]);

    // The same pentagon in PLY, after a triangle: a face of more than four indices is held
    // apart from the short ones.
    let ply = "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\n\
        property float z\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n\
        0 0 0\n2 0 0\n3 2 0\n1 3 0\n-1 2 0\n3 4 0 1\n5 0 1 2 3 4\n";
    let pentagon = load(&dir.file("pentagon.ply", ply)).unwrap();
    assert_eq!(
        pentagon.triangles,
        vec![[4, 0, 1], [0, 1, 2], [0, 2, 3], [0, 3, 4]]
    );
}

#[test]
fn obj_objects_are_merged_and_a_missing_mtl_is_ignored() {
    let dir = Scratch::new("obj_objects");
    let text =
        format!("mtllib absent.mtl\no a\n{SQUARE_OBJ}usemtl red\nf 1 2 3\no b\nv 0 0 1\nf 1 3 5\nf -1 2 4\n");
    let mesh = load(&dir.file("two.obj", text)).unwrap();
    assert_eq!(mesh.triangles.len(), 3);
    let (o, x, y, z) = ([0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]);
    assert_eq!(
        corners(&mesh),
        vec![[o, x, [1.0, 1.0, 0.0]], [o, [1.0, 1.0, 0.0], z], [z, x, y]]
    );
}

/// A unit square (a quad) and a triangle on it, with an extra vertex property (`u`) and an
/// element (`edge`) of no interest, in PLY's ascii form.
const SQUARE_PLY: &str = "ply\nformat ascii 1.0\ncomment two faces\nelement vertex 5\n\
    property float x\nproperty float y\nproperty uchar u\nproperty float z\n\
    element face 2\nproperty list uchar int vertex_indices\n\
    element edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n\
    0 0 7 0\n1 0 7 0\n1 1 7 0\n0 1 7 0\n0.5 0.25 7 0.75\n4 0 1 2 3\n3 0 1 4\n0 1\n";

/// The vertices of [`SQUARE_PLY`].
const SQUARE_VERTICES: [[f32; 3]; 5] = [
    [0.0, 0.0, 0.0],
    [1.0, 0.0, 0.0],
    [1.0, 1.0, 0.0],
    [0.0, 1.0, 0.0],
    [0.5, 0.25, 0.75],
];

/// [`SQUARE_PLY`] in binary little endian, written byte by byte, with `vertices`.
fn square_ply_little_endian(vertices: [[f32; 3]; 5]) -> Vec<u8> {
    let header = "ply\nformat binary_little_endian 1.0\nelement vertex 5\n\
        property float x\nproperty float y\nproperty uchar u\nproperty float z\n\
        element face 2\nproperty list uchar int vertex_indices\n\
        element edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n";
    let mut bytes = header.as_bytes().to_vec();
    for [x, y, z] in vertices {
        bytes.extend(x.to_le_bytes());
        bytes.extend(y.to_le_bytes());
        bytes.push(7);
        bytes.extend(z.to_le_bytes());
    }
    for face in [&[0, 1, 2, 3][..], &[0, 1, 4]] {
        bytes.push(face.len() as u8);
        face.iter().for_each(|i: &i32| bytes.extend(i.to_le_bytes()));
    }
    bytes.extend(0i32.to_le_bytes());
    bytes.extend(1i32.to_le_bytes());
    bytes
}

/// The same mesh in binary big endian, as doubles, with the older `vertex_index` of `ushort`s.
fn square_ply_big_endian() -> Vec<u8> {
    let header = "ply\nformat binary_big_endian 1.0\nelement vertex 5\n\
        property double x\nproperty double y\nproperty double z\n\
        element face 2\nproperty list uint ushort vertex_index\nend_header\n";
    let mut bytes = header.as_bytes().to_vec();
    for vertex in SQUARE_VERTICES {
        vertex
            .iter()
            .for_each(|&c| bytes.extend(f64::from(c).to_be_bytes()));
    }
    for face in [&[0, 1, 2, 3][..], &[0, 1, 4]] {
        bytes.extend((face.len() as u32).to_be_bytes());
        face.iter().for_each(|i: &u16| bytes.extend(i.to_be_bytes()));
    }
    bytes
}

#[test]
fn ascii_and_binary_ply_give_the_same_mesh() {
    let dir = Scratch::new("ply_encodings");
    let ascii = load(&dir.file("ascii.ply", SQUARE_PLY)).unwrap();
    let little = load(&dir.file("little.ply", square_ply_little_endian(SQUARE_VERTICES))).unwrap();
    let big = load(&dir.file("big.PLY", square_ply_big_endian())).unwrap();
    let expected = MeshData {
        positions: SQUARE_VERTICES
            .iter()
            .map(|&[x, y, z]| raytrace::Vec3::new(x.into(), y.into(), z.into()))
            .collect(),
        triangles: vec![[0, 1, 2], [0, 2, 3], [0, 1, 4]],
        skipped_degenerate: 0,
        normals: None,
        uvs: None,
    };
    assert_eq!(ascii, expected);
    assert_eq!(little, expected);
    assert_eq!(big, expected);
}

#[test]
fn degenerate_faces_are_skipped_and_counted() {
    let dir = Scratch::new("degenerate");
    // A repeated index, three collinear points, then a quad whose fan has one flat half.
    let obj = format!("{SQUARE_OBJ}v 2 0 0\nf 1 1 2\nf 1 2 5\nf 1 2 3 4\nf 1 2 5 3\n");
    let mesh = load(&dir.file("flat.obj", obj)).unwrap();
    let (o, x, y, xy, x2) = (
        [0.0; 3],
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [1.0, 1.0, 0.0],
        [2.0, 0.0, 0.0],
    );
    assert_eq!(corners(&mesh), vec![[o, x, xy], [o, xy, y], [o, x2, xy]]);
    assert_eq!(mesh.skipped_degenerate, 3);

    let ply = SQUARE_PLY.replace("3 0 1 4\n", "3 0 0 4\n");
    let mesh = load(&dir.file("flat.ply", ply)).unwrap();
    assert_eq!(mesh.triangles.len(), 2);
    assert_eq!(mesh.skipped_degenerate, 1);
}

#[test]
fn bad_files_are_errors_naming_the_file_and_the_element() {
    let dir = Scratch::new("bad_files");
    // ply-rs-bw reads no `nan` or `inf` in ascii, so these are binary.
    let (mut nan, mut infinite) = (SQUARE_VERTICES, SQUARE_VERTICES);
    nan[2][1] = f32::NAN;
    infinite[3][0] = f32::INFINITY;
    let cases: Vec<(PathBuf, &str)> = vec![
        (dir.0.join("absent.obj"), "cannot open: No such file or directory"),
        (dir.0.join("absent.ply"), "cannot open: No such file or directory"),
        (dir.file("mesh.stl", "solid"), "unknown mesh format"),
        (dir.file("noext", "v 0 0 0"), "unknown mesh format"),
        (
            dir.file("range.obj", format!("{SQUARE_OBJ}f 1 2 3\nf 1 2 9000\n")),
            "line 6: face 2: vertex index 9000 out of range (the mesh has 4 vertices)",
        ),
        (
            dir.file("zero.obj", format!("{SQUARE_OBJ}f 0 1 2\n")),
            "line 5: face 1: vertex index 0 out of range",
        ),
        (
            dir.file("relative.obj", format!("{SQUARE_OBJ}f -1 -2 -5\n")),
            "line 5: face 1: vertex index -5 out of range",
        ),
        (
            dir.file("range.ply", SQUARE_PLY.replace("3 0 1 4", "3 0 9000 4")),
            "face 1: vertex index 9000 out of range (the mesh has 5 vertices)",
        ),
        (
            dir.file("negative.ply", SQUARE_PLY.replace("3 0 1 4", "3 0 -1 4")),
            "face 1: vertex index -1 out of range",
        ),
        (
            dir.file("nan.obj", "v 0 0 0\nv 1 0 0\n# a comment\nv 0 NaN 0\nf 1 2 3\n"),
            "line 4: vertex 3: coordinate y is NaN",
        ),
        (
            dir.file("inf.obj", format!("{SQUARE_OBJ}v 0 0 -inf\nf 1 2 5\n")),
            "line 5: vertex 5: coordinate z is -infinite",
        ),
        (
            dir.file("nan.ply", square_ply_little_endian(nan)),
            "vertex 2: coordinate y is NaN",
        ),
        (
            dir.file("inf.ply", square_ply_little_endian(infinite)),
            "vertex 3: coordinate x is infinite",
        ),
        (
            dir.file("short.obj", format!("{SQUARE_OBJ}f 1 2 3\nf 1 2\n")),
            "line 6: face 2: 2 vertices (a face needs at least 3)",
        ),
        (
            dir.file("short.ply", SQUARE_PLY.replace("3 0 1 4", "2 0 1")),
            "face 1: 2 vertices (a face needs at least 3)",
        ),
        (
            dir.file("flat.obj", format!("{SQUARE_OBJ}f 1 2 2\n")),
            "no triangles with area (1 degenerate faces skipped)",
        ),
        (dir.file("empty.ply", ""), "bad PLY header"),
        (
            dir.file("garbled.ply", SQUARE_PLY.replace("0.5 0.25", "0.5 zero")),
            "element vertex: line 19 does not hold the entry",
        ),
        (
            dir.file("garbled.obj", "v 0 0 0\nv 1 banana 0\n"),
            "position parse error",
        ),
        (
            dir.file(
                "noface.ply",
                "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\n\
                property float y\nproperty float z\nend_header\n",
            ),
            "no face element",
        ),
        (
            dir.file(
                "intx.ply",
                SQUARE_PLY.replace("property float y", "property int y"),
            ),
            "element vertex: property y is int, not float or double",
        ),
    ];
    let little = square_ply_little_endian(SQUARE_VERTICES);
    let truncated = dir.file("truncated.ply", &little[..little.len() - 10]);
    let truncated_faces = mesh_error(&truncated);
    assert!(truncated_faces.contains("element face"), "{truncated_faces}");
    let truncated = dir.file("cut.ply", &little[..little.len() - 70]);
    let truncated_vertices = mesh_error(&truncated);
    assert!(
        truncated_vertices.contains("element vertex"),
        "{truncated_vertices}"
    );
    for (path, expected) in cases {
        let message = mesh_error(&path);
        assert!(message.contains(expected), "{}: {message}", path.display());
    }
}

#[test]
fn messages_never_quote_the_file_nor_the_parsers_internals() {
    let dir = Scratch::new("quiet");
    // As `/etc/shadow` begins, behind a `.ply` name.
    let secret = "root:*:19000:0:99999:7:::\ndaemon:*:19000:0:99999:7:::\n";
    let cases = [
        dir.file("shadow.ply", secret),
        dir.file("shadow.obj", secret),
        dir.file("late.ply", format!("ply\nformat ascii 1.0\n{secret}")),
        dir.file("comment.ply", format!("comment {secret}")),
        dir.file("garbled.ply", SQUARE_PLY.replace("0.5 0.25", "0.5 root:*:19000")),
        dir.file("garbled.obj", format!("{SQUARE_OBJ}v 1 root:*:19000 0\n")),
    ];
    for path in cases {
        let message = mesh_error(&path);
        for leak in [
            "root",
            "daemon",
            "19000",
            "ParseError",
            "LineCol",
            "String:",
            "\n",
        ] {
            assert!(
                !message.contains(leak),
                "{}: {leak:?} in {message}",
                path.display()
            );
        }
    }
}

#[test]
fn a_file_that_never_ends_is_refused_before_it_is_read() {
    let dir = Scratch::new("endless");
    for name in ["zero.obj", "zero.ply"] {
        let link = dir.0.join(name);
        std::os::unix::fs::symlink("/dev/zero", &link).unwrap();
        let message = mesh_error(&link);
        assert!(message.contains("a mesh must be a regular file"), "{message}");
    }
    // A regular file of one line of a megabyte and more (sparse, so no disk is used).
    for name in ["long.obj", "long.ply"] {
        let path = dir.0.join(name);
        let file = std::fs::File::create(&path).unwrap();
        file.set_len(3 << 20).unwrap();
        let message = mesh_error(&path);
        assert!(
            message.contains("line 1 is longer than 1048576 bytes"),
            "{message}"
        );
    }
}

/// The start of a file that gets past the parsers' first checks, so that the random rest
/// reaches their payload code.
fn prefix() -> impl Strategy<Value = (&'static str, &'static str)> {
    prop_oneof![
        Just(("ply", "")),
        Just(("obj", "")),
        Just((
            "ply",
            "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n"
        )),
        Just((
            "ply",
            "ply\nformat binary_big_endian 1.0\nelement vertex 2\nproperty double x\nproperty double y\nproperty double z\nelement face 1\nproperty list int short vertex_index\nend_header\n"
        )),
        Just((
            "ply",
            "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
        )),
    ]
}

/// Bytes from an OBJ- and PLY-like alphabet, more likely than uniform bytes to parse a while.
fn body() -> impl Strategy<Value = Vec<u8>> {
    let alphabet = b"vfl/ -0123456789.e\n#nainfo\x00\xff";
    prop_oneof![
        proptest::collection::vec(any::<u8>(), 0..512),
        proptest::collection::vec(proptest::sample::select(&alphabet[..]), 0..512),
    ]
}

proptest! {
    #![proptest_config(common::config(256, 0x6d65_7368, "proptest-regressions/meshes.txt"))]

    #[test]
    fn arbitrary_bytes_never_panic_the_loader((extension, start) in prefix(), rest in body()) {
        let dir = Scratch::new("arbitrary");
        let mut bytes = start.as_bytes().to_vec();
        bytes.extend(rest);
        let path = dir.file(&format!("any.{extension}"), &bytes);
        if let Err(error) = load(&path) {
            prop_assert!(matches!(error, Error::Mesh { .. }), "{error:?}");
        }
    }
}
