//! OBJ materials: a mesh object with `material = "mtl"` shades each of its OBJ file's
//! `usemtl` groups with the material its `.mtl` library defines.
//!
//! - **Each group its material.** A quad of two groups (red and blue matte) lit by a point
//!   light renders every pixel at the closed form `A/π·I·cos θ/d²` for its half's albedo,
//!   and the same bytes as the scene built from two OBJ files with two named materials.
//! - **Images beside the library.** `map_Kd` is found relative to the `.mtl` file (in
//!   another folder than the OBJ file), and renders the bytes of the same image named by
//!   a scene file's texture.
//! - **Emitters.** `Ke` makes an emitter that is sampled as a light and lights the floor
//!   of the same OBJ file; the same file with `Ke 0` leaves it black.
//! - **Notes.** Keys that are not read, a height map given as `map_Bump`, and a named
//!   material covering a file's `usemtl` groups are reported with their file and line.
//!
//! The mistakes, each an error naming the file and line, are in `obj_material_errors.rs`.

use crate::common::Scratch;
use raytrace::scene_file::{Built, SceneFile};
use raytrace::{MaterialKind, render};
use std::f64::consts::PI;

/// Builds the scene file `text` in the folder `dir` and renders it.
pub fn built(dir: &Scratch, text: &str) -> Built<f64> {
    let path = dir.file("scene.toml", text);
    SceneFile::load(&path).unwrap().build::<f64>().unwrap()
}

fn image(built: &Built<f64>) -> raytrace::Image {
    render(&built.scene, &built.camera, &built.settings)
        .unwrap()
        .image
}

/// The spec's camera (16 × 8, one ray through each pixel centre, no bounce after the
/// first hit), a black background and a point light of intensity 2 at the eye.
const LIT: &str = "[render]\nwidth = 16\nmax_depth = 1\n\n[background]\ntype = \"solid\"\n\
    color = [0, 0, 0]\n\n[[lights]]\nposition = [0, 0, 0]\nintensity = [2, 2, 2]\n";

const RED: [f64; 3] = [0.7, 0.2, 0.1];
const BLUE: [f64; 3] = [0.1, 0.3, 0.6];

/// Two quads beyond the view at `z = −2` (which spans `[−4, 4] × [−2, 2]` there): `x < 0`
/// in group `left`, `x > 0` in `right`.
fn halves(left: &str, right: &str) -> (String, String) {
    let l = format!("v -5 -3 -2\nv 0 -3 -2\nv 0 3 -2\nv -5 3 -2\ng left\n{left}f 1 2 3 4\n");
    let r = format!("v 0 -3 -2\nv 5 -3 -2\nv 5 3 -2\nv 0 3 -2\ng right\n{right}f 1 2 3 4\n");
    (l, r)
}

#[test]
fn each_group_gets_its_material() {
    let dir = Scratch::new("obj-halves");
    let mtl = format!(
        "newmtl red\nKd {} {} {}\nillum 1\n\nnewmtl blue\nKd {} {} {}\n",
        RED[0], RED[1], RED[2], BLUE[0], BLUE[1], BLUE[2]
    );
    dir.file("halves.mtl", mtl);
    let (left, right) = halves("usemtl red\n", "usemtl blue\n");
    // One file: the right quad's vertices are numbered after the left's.
    let right_shifted = right.replace("f 1 2 3 4", "f 5 6 7 8");
    dir.file("both.obj", format!("mtllib halves.mtl\n{left}{right_shifted}"));
    let from_mtl = built(
        &dir,
        &format!("{LIT}\n[[objects]]\ntype = \"mesh\"\nfile = \"both.obj\"\nmaterial = \"mtl\"\n"),
    );
    assert_eq!((from_mtl.summary.meshes, from_mtl.summary.triangles), (2, 4));
    let got = image(&from_mtl);

    // Every pixel: the hit point P = 2·(x, y, −1) of the pixel centre (x, y) on the spec's
    // screen, d = |P|, cos θ = 2/d, so A/π·I·cos θ/d² = 2A·I/(π d³).
    let (w, h) = (got.width(), got.height());
    for j in 0..h {
        for i in 0..w {
            let x = -2.0 + 4.0 * i as f64 / (w - 1) as f64;
            let y = 1.0 - 2.0 * j as f64 / (h - 1) as f64;
            let d = 2.0 * (x * x + y * y + 1.0).sqrt();
            let albedo = if x < 0.0 { RED } else { BLUE };
            let want = albedo.map(|a| 2.0 * a * 2.0 / (PI * d * d * d));
            let p = got.pixel(i, j);
            for k in 0..3 {
                assert!(
                    (p[k] - want[k]).abs() <= 1e-12 * want[k],
                    "pixel ({i}, {j}): {p:?}, want {want:?}"
                );
            }
        }
    }

    // The same scene from two files, each with a named material: the same bytes.
    dir.file("left.obj", &left);
    dir.file("right.obj", &right);
    let named = built(
        &dir,
        &format!(
            "{LIT}\n[materials.r]\ntype = \"lambertian\"\nalbedo = {RED:?}\n\n\
             [materials.b]\ntype = \"lambertian\"\nalbedo = {BLUE:?}\n\n\
             [[objects]]\ntype = \"mesh\"\nfile = \"left.obj\"\nmaterial = \"r\"\n\n\
             [[objects]]\ntype = \"mesh\"\nfile = \"right.obj\"\nmaterial = \"b\"\n"
        ),
    );
    assert_eq!(image(&named).pixels(), got.pixels());
}

#[test]
fn map_kd_is_found_beside_the_mtl_file() {
    let dir = Scratch::new("obj-map-kd");
    std::fs::create_dir_all(dir.path("models/looks/tex")).unwrap();
    let texels: Vec<[u8; 3]> = (0..16)
        .map(|k| [20 + 14 * k as u8, 200 - 10 * k as u8, 90])
        .collect();
    dir.png8("models/looks/tex/grain.png", 4, 4, &texels);
    dir.file(
        "models/looks/wood.mtl",
        "newmtl wood\nKa 1 1 1\nKd 1 1 1\nmap_Kd tex/grain.png\n",
    );
    let quad = "v -5 -3 -2\nv 5 -3 -2\nv 5 3 -2\nv -5 3 -2\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n\
                f 1/1 2/2 3/3 4/4\n";
    dir.file(
        "models/quad.obj",
        format!("mtllib looks/wood.mtl\nusemtl wood\n{quad}"),
    );
    let from_mtl = built(
        &dir,
        &format!("{LIT}\n[[objects]]\ntype = \"mesh\"\nfile = \"models/quad.obj\"\nmaterial = \"mtl\"\n"),
    );
    // The library and its image are inputs of the scene (hashed into tiles, never
    // overwritten by an output).
    let file = SceneFile::load(&dir.path("scene.toml")).unwrap();
    let want = [
        "models/quad.obj",
        "models/looks/wood.mtl",
        "models/looks/tex/grain.png",
    ];
    assert_eq!(file.input_files(), want.map(|f| dir.path(f)));
    // Ka is read but has no counterpart: a note naming the file and line.
    let notes = &from_mtl.summary.notes;
    assert!(
        notes.len() == 1 && notes[0].contains("wood.mtl: not read: `Ka` (line 2)"),
        "{notes:?}"
    );
    dir.file("models/plain.obj", quad);
    let named = built(
        &dir,
        &format!(
            "{LIT}\n[materials.w]\ntype = \"lambertian\"\n\
             albedo = {{ type = \"image\", file = \"models/looks/tex/grain.png\" }}\n\n\
             [[objects]]\ntype = \"mesh\"\nfile = \"models/plain.obj\"\nmaterial = \"w\"\n"
        ),
    );
    let got = image(&from_mtl);
    assert_eq!(image(&named).pixels(), got.pixels());
    // The image shows: neither a constant colour nor black.
    let first = got.pixel(0, 0);
    assert!(first[0] > 0.0 && got.pixels().iter().any(|p| *p != first));
}

/// A floor quad (`usemtl floor`, matte) facing up and a lamp quad above it (`usemtl lamp`,
/// `Ke` as given) facing down (its face runs counter-clockwise seen from below), seen from
/// the side.
fn lamp_scene(dir: &Scratch, ke: &str) -> Built<f64> {
    dir.file(
        "room.mtl",
        format!("newmtl floor\nKd 0.5 0.5 0.5\n\nnewmtl lamp\nKd 0 0 0\nKe {ke}\n"),
    );
    let obj = "mtllib room.mtl\nv -2 0 -2\nv 2 0 -2\nv 2 0 2\nv -2 0 2\n\
               v -0.5 2 -0.5\nv 0.5 2 -0.5\nv 0.5 2 0.5\nv -0.5 2 0.5\n\
               usemtl floor\nf 1 4 3 2\nusemtl lamp\nf 5 6 7 8\n";
    dir.file("room.obj", obj);
    built(
        dir,
        "[render]\nwidth = 32\nspp = 4\nmax_depth = 2\n\n[camera]\ntype = \"look_at\"\n\
         from = [0, 1, 5]\nat = [0, 0, 0]\nvfov = 50\naspect = 2\n\n[background]\n\
         type = \"solid\"\ncolor = [0, 0, 0]\n\n[[objects]]\ntype = \"mesh\"\nfile = \"room.obj\"\n\
         material = \"mtl\"\n",
    )
}

#[test]
fn ke_makes_an_emitter_that_lights_another_surface() {
    let dir = Scratch::new("obj-lamp");
    let lit = lamp_scene(&dir, "4 4 4");
    assert_eq!((lit.summary.emitters, lit.summary.sampled_emitters), (1, 1));
    let floor = lit.scene.material(lit.scene.objects()[0].material);
    assert!(matches!(floor, MaterialKind::Lambertian(_)), "{floor:?}");
    let sum = |b: &Built<f64>| -> f64 { image(b).pixels().iter().flatten().sum() };
    assert!(sum(&lit) > 1.0, "the floor is lit");
    let dark = lamp_scene(&dir, "0 0 0");
    assert_eq!(dark.summary.emitters, 0);
    assert_eq!(sum(&dark), 0.0);
}

#[test]
fn what_is_not_used_is_noted_with_its_file_and_line() {
    let dir = Scratch::new("obj-notes");
    dir.png8("height.png", 2, 1, &[[10, 10, 10], [200, 200, 200]]);
    dir.png8("normals.png", 1, 1, &[[128, 128, 255]]);
    dir.file(
        "looks.mtl",
        "newmtl bumpy\nKd 0.5 0.5 0.5\nmap_Bump height.png\n\n\
         newmtl mapped\nKd 0.5 0.5 0.5\nmap_Bump -bm 0.3 normals.png\nTf 1 0 0\n",
    );
    let (left, right) = halves("usemtl bumpy\n", "usemtl mapped\n");
    let right = right.replace("f 1 2 3 4", "f 5 6 7 8");
    dir.file("both.obj", format!("mtllib looks.mtl\n{left}{right}"));
    let b = built(
        &dir,
        &format!("{LIT}\n[[objects]]\ntype = \"mesh\"\nfile = \"both.obj\"\nmaterial = \"mtl\"\n"),
    );
    let notes = b.summary.notes.join("\n");
    for words in [
        "looks.mtl: line 3: material `bumpy`: `map_Bump` is a height map",
        "looks.mtl: line 7: material `mapped`: `-bm` 0.3 is not applied",
        "looks.mtl: line 8: material `mapped`: `Tf` is not used",
    ] {
        assert!(notes.contains(words), "{words}\n{notes}");
    }
    let materials: Vec<_> = b
        .scene
        .objects()
        .iter()
        .map(|o| b.scene.material(o.material))
        .collect();
    assert!(
        matches!(materials[0], MaterialKind::Lambertian(_)),
        "{materials:?}"
    );
    assert!(
        matches!(materials[1], MaterialKind::NormalMap(_)),
        "{materials:?}"
    );

    // A named material covers the file: its `usemtl` groups are named as unused.
    let path = dir.file(
        "named.toml",
        format!(
            "{LIT}\n[materials.m]\ntype = \"lambertian\"\nalbedo = [0.5, 0.5, 0.5]\n\n\
             [[objects]]\ntype = \"mesh\"\nfile = \"both.obj\"\nmaterial = \"m\"\n"
        ),
    );
    let file = SceneFile::load(&path).unwrap();
    let unused = file.unused_obj_materials();
    assert!(
        unused.len() == 1
            && unused[0].starts_with("objects[0]: ")
            && unused[0].contains("both.obj names 2 materials with `usemtl` (`bumpy`, `mapped`)"),
        "{unused:?}"
    );
    // It renders as before, with one material and no note.
    let b = file.build::<f64>().unwrap();
    assert!(b.summary.notes.is_empty() && b.summary.meshes == 1);
    // `raytrace check` says so, as a warning naming the scene file.
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_raytrace"))
        .args(["check".as_ref(), path.as_os_str()])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    assert!(
        stderr.contains("named.toml: objects[0]: ") && stderr.contains("`material = \"mtl\"` takes them"),
        "{stderr}"
    );
}

/// The example of `docs/SCENE_FORMAT.md` ("OBJ materials") builds as it says.
#[test]
fn the_documented_example_builds() {
    let dir = Scratch::new("obj-doc");
    std::fs::create_dir_all(dir.path("textures")).unwrap();
    dir.png8(
        "textures/shade_normals.png",
        2,
        1,
        &[[128, 128, 255], [150, 128, 240]],
    );
    dir.file(
        "lamp.mtl",
        "newmtl shade\nKd 0.6 0.1 0.1\nKs 0.5 0.5 0.5\nNs 200\nillum 2\n\
         map_Bump -bm 1.0 textures/shade_normals.png\n\nnewmtl bulb\nKd 0.9 0.9 0.9\nKe 20 18 14\n",
    );
    dir.file(
        "lamp.obj",
        "mtllib lamp.mtl\nv -1 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n\
         usemtl shade\nf 1 2 3\nusemtl bulb\nf 1 4 2\n",
    );
    let b = built(
        &dir,
        "[[objects]]\ntype = \"mesh\"\nfile = \"lamp.obj\"\ntranslate = [0, 0, -3]\nmaterial = \"mtl\"\n",
    );
    let materials: Vec<_> = b
        .scene
        .objects()
        .iter()
        .map(|o| b.scene.material(o.material))
        .collect();
    assert!(
        matches!(materials[0], MaterialKind::NormalMap(_)),
        "{materials:?}"
    );
    assert!(matches!(materials[1], MaterialKind::Emissive(_)), "{materials:?}");
    assert!(b.summary.notes.is_empty(), "{:?}", b.summary.notes);
}
