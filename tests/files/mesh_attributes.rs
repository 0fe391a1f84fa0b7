//! Mesh normals and texture coordinates: read from OBJ (`vn`, `vt`) and PLY (`nx ny nz`,
//! `u v` / `s t` / `texture_u texture_v`) as written, refused when broken, and taken into a
//! scene file's mesh: normals placed as normals (perpendicular under any scale), `v`
//! flipped as Mitsuba flips it by default, dropped with `face_normals`.

use crate::common::Scratch;
use raytrace::mesh::{MeshData, load};
use raytrace::scene_file::SceneFile;
use raytrace::{Error, ShapeKind, Vec3};
use std::path::Path;

fn mesh_error(path: &Path) -> String {
    match load(path) {
        Err(Error::Mesh { message, .. }) => message,
        other => panic!("{}: expected Error::Mesh, got {other:?}", path.display()),
    }
}

/// A corner of a triangle: position, normal, texture coordinates.
type Corner = ([f64; 3], [f64; 3], [f64; 2]);

/// Each triangle's corners, however the reader numbered them.
fn corners(m: &MeshData) -> Vec<[Corner; 3]> {
    let n = m.normals.as_ref().unwrap();
    let uv = m.uvs.as_ref().unwrap();
    let corner = |i: u32| {
        let i = i as usize;
        (m.positions[i].to_f64(), n[i].to_f64(), uv[i])
    };
    m.triangles.iter().map(|t| t.map(corner)).collect()
}

#[test]
fn obj_normals_and_texture_coordinates_are_read_as_written() {
    let dir = Scratch::new("obj_attributes");
    // Two triangles sharing the edge 1–3, whose vertex 1 has a different vt in each: a seam.
    let text = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n\
                vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0.5 0.5\n\
                vn 0 0 1\nvn 0.6 0 0.8\n\
                f 1/1/1 2/2/2 3/3/1\nf 1/5/1 3/3/1 4/4/2\n";
    let m = load(&dir.file("seam.obj", text)).unwrap();
    // Vertex 1 is used with two texture coordinates: two vertices.
    assert_eq!(m.positions.len(), 5);
    let (o, x, xy, y) = ([0.0; 3], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]);
    let (up, lean) = ([0.0, 0.0, 1.0], [0.6, 0.0, 0.8]);
    assert_eq!(
        corners(&m),
        vec![
            [(o, up, [0.0, 0.0]), (x, lean, [1.0, 0.0]), (xy, up, [1.0, 1.0])],
            [(o, up, [0.5, 0.5]), (xy, up, [1.0, 1.0]), (y, lean, [0.0, 1.0])],
        ]
    );
    // Normals alone.
    let normals_only =
        load(&dir.file("n.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 2\nf 1//1 2//1 3//1\n")).unwrap();
    assert_eq!(normals_only.uvs, None);
    assert_eq!(normals_only.normals, Some(vec![Vec3::new(0.0, 0.0, 2.0); 3]));
    // Neither.
    let plain = load(&dir.file("p.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")).unwrap();
    assert_eq!((plain.normals, plain.uvs), (None, None));
}

#[test]
fn an_obj_object_without_texture_coordinates_gets_zeros_but_a_partial_one_is_refused() {
    let dir = Scratch::new("obj_partial");
    let two = "o a\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0.5 0.25\nf 1/1 2/1 3/1\n\
               o b\nv 0 0 1\nv 1 0 1\nv 0 1 1\nf 4 5 6\n";
    let m = load(&dir.file("two.obj", two)).unwrap();
    assert_eq!(
        m.uvs,
        Some(vec![
            [0.5, 0.25],
            [0.5, 0.25],
            [0.5, 0.25],
            [0.0; 2],
            [0.0; 2],
            [0.0; 2]
        ])
    );
    let partial = "o a\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0.5 0.25\nf 1/1 2/1 3/1\nf 2 4 3\n";
    let message = mesh_error(&dir.file("partial.obj", partial));
    assert!(
        message.contains("object `a`") && message.contains("texture coordinates (`vt`)"),
        "{message}"
    );
    let nan = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 nan 1\nf 1//1 2//1 3//1\n";
    let message = mesh_error(&dir.file("nan.obj", nan));
    assert!(message.starts_with("line 4: a normal (vn) is NaN"), "{message}");
}

/// A PLY triangle with the vertex properties `props` (after `x y z`), each vertex's values
/// `rows`.
fn ply(props: &[&str], rows: [&str; 3]) -> String {
    let mut text = String::from(
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n",
    );
    for p in props {
        text += &format!("property {p}\n");
    }
    text += "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
    for (k, row) in rows.iter().enumerate() {
        let position = ["0 0 0", "1 0 0", "0 1 0"][k];
        text += &format!("{position} {row}\n");
    }
    text + "3 0 1 2\n"
}

#[test]
fn ply_normals_and_texture_coordinates_go_by_any_of_their_names() {
    let dir = Scratch::new("ply_attributes");
    let rows = ["0 0 1 0.1 0.2", "0 0.6 0.8 0.3 0.4", "0 0 2 0.5 0.6"];
    for (k, (u, v)) in [("u", "v"), ("s", "t"), ("texture_u", "texture_v")]
        .into_iter()
        .enumerate()
    {
        let props = [
            "float nx",
            "float ny",
            "float nz",
            &format!("float {u}"),
            &format!("double {v}"),
        ];
        let m = load(&dir.file(&format!("t{k}.ply"), ply(&props, rows))).unwrap();
        assert_eq!(
            m.normals,
            Some(vec![
                Vec3::new(0.0, 0.0, 1.0),
                Vec3::new(0.0, 0.6f32.into(), 0.8f32.into()),
                Vec3::new(0.0, 0.0, 2.0)
            ]),
            "{u} {v}"
        );
        let uv = |a: f32, b: f64| [f64::from(a), b];
        assert_eq!(
            m.uvs,
            Some(vec![uv(0.1, 0.2), uv(0.3, 0.4), uv(0.5, 0.6)]),
            "{u} {v}"
        );
    }
    // Only some of a normal's components, or one texture coordinate: none is taken.
    let m = load(&dir.file(
        "some.ply",
        ply(&["float nx", "float ny", "float u"], ["0 0 1", "0 0 1", "0 0 1"]),
    ))
    .unwrap();
    assert_eq!((m.normals, m.uvs), (None, None));
    // A broken value is named by vertex and component (a NaN is written in binary: the
    // ASCII reader takes no `nan`).
    let mut bad = b"ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n\
        property float y\nproperty float z\nproperty float nx\nproperty float ny\nproperty float nz\n\
        element face 1\nproperty list uchar int vertex_indices\nend_header\n"
        .to_vec();
    for v in [
        [0.0, 0.0, 0.0, 0.0, 0.0, 1.0],
        [1.0, 0.0, 0.0, 0.0, f32::NAN, 1.0],
        [0.0, 1.0, 0.0, 0.0, 0.0, 1.0],
    ] {
        v.iter().for_each(|c: &f32| bad.extend(c.to_le_bytes()));
    }
    bad.push(3);
    [0i32, 1, 2].iter().for_each(|i| bad.extend(i.to_le_bytes()));
    assert_eq!(mesh_error(&dir.file("bad.ply", bad)), "vertex 1: ny is NaN");
    let list = ply(&["list uchar float u", "float v"], ["1 0 0", "1 0 0", "1 0 0"]);
    assert!(mesh_error(&dir.file("list.ply", list)).contains("property u is a list"));
}

/// A scene file of one mesh object with `keys`, the mesh written into `dir` as `name`.
fn built_mesh(dir: &Scratch, name: &str, mesh: &str, keys: &str) -> raytrace::Mesh<f64> {
    dir.file(name, mesh);
    let text = format!(
        "[materials.m]\ntype = \"lambertian\"\nalbedo = [0.5, 0.5, 0.5]\n\
         [[objects]]\ntype = \"mesh\"\nfile = \"{name}\"\nmaterial = \"m\"\n{keys}\n"
    );
    let path = dir.file("scene.toml", text);
    let built = SceneFile::load(&path).unwrap().build::<f64>().unwrap();
    match &built.scene.objects()[0].shape {
        ShapeKind::Mesh(m) => (**m).clone(),
        other => panic!("{other:?}"),
    }
}

const TILTED: &str = "v 0 0 0\nv 1 0 1\nv 0 1 1\nv 1 1 2\nvt 0 0\nvt 1 0\nvt 0 0.25\nvt 1 1\n\
                      vn 1 1 -1\nf 1/1/1 2/2/1 3/3/1\nf 2/2/1 4/4/1 3/3/1\n";

#[test]
fn a_scene_files_mesh_places_its_normals_as_normals_and_flips_v_as_mitsuba_does() {
    let dir = Scratch::new("placed");
    // The plane x + y − z = 0 (normal (1, 1, −1)), stretched, turned and moved.
    let mesh = built_mesh(
        &dir,
        "tilted.obj",
        TILTED,
        "scale = [3, 0.5, 2]\nrotate = [30, -45, 10]\ntranslate = [1, 2, -6]",
    );
    let [a, b, c] = mesh.triangle(0);
    let normal = mesh.normals().unwrap()[0];
    assert!((normal.length() - 1.0).abs() < 1e-12);
    for edge in [b - a, c - a] {
        assert!(normal.dot(edge).abs() < 1e-12, "{}", normal.dot(edge));
    }
    // OBJ: v flipped (Mitsuba's default for OBJ).
    assert_eq!(mesh.uvs().unwrap()[2], [0.0, 0.75]);
    let kept = built_mesh(
        &dir,
        "tilted.obj",
        TILTED,
        "flip_tex_coords = false\nface_normals = true",
    );
    assert_eq!(kept.uvs().unwrap()[2], [0.0, 0.25]);
    assert!(kept.normals().is_none());
    // PLY: as written unless asked.
    let tri = ply(&["float u", "float v"], ["0 0", "1 0", "0 0.25"]);
    assert_eq!(built_mesh(&dir, "t.ply", &tri, "").uvs().unwrap()[2], [0.0, 0.25]);
    assert_eq!(
        built_mesh(&dir, "t.ply", &tri, "flip_tex_coords = true")
            .uvs()
            .unwrap()[2],
        [0.0, 0.75]
    );
}

#[test]
fn a_zero_normal_adds_nothing_and_three_shade_with_the_face() {
    use raytrace::{Mesh, Ray};
    let v = vec![
        Vec3::new(0.0, 0.0, -2.0),
        Vec3::new(1.0, 0.0, -2.0),
        Vec3::new(0.0, 1.0, -2.0),
    ];
    let lean = Vec3::new(0.6, 0.0, 0.8);
    let centre = Vec3::new(1.0 / 3.0, 1.0 / 3.0, -2.0);
    let ray = Ray::new(
        Vec3::new(0.3, 0.3, 0.0),
        (centre - Vec3::new(0.3, 0.3, 0.0)).normalize(),
    );
    let shade = |normals: Vec<Vec3<f64>>| {
        let mesh = Mesh::new(v.clone(), vec![[0, 1, 2]])
            .unwrap()
            .with_normals(normals)
            .unwrap();
        raytrace::shape::hit(&mesh, &ray, f64::INFINITY).unwrap()
    };
    let one_zero = shade(vec![Vec3::zero(), lean, lean * 3.0]);
    assert!((one_zero.shading_normal - lean).length() < 1e-15 && one_zero.smooth);
    let all_zero = shade(vec![Vec3::zero(); 3]);
    assert_eq!(all_zero.shading_normal, all_zero.normal);
    assert!(!all_zero.smooth);
    let nan = Mesh::new(v.clone(), vec![[0, 1, 2]])
        .unwrap()
        .with_normals(vec![Vec3::new(f64::NAN, 0.0, 1.0); 3]);
    assert!(nan.unwrap_err().to_string().contains("vertex 0 is not finite"));
}
