//! Scene files with textures, normal maps and mesh attributes: the documented example builds
//! and shares its images; every mistake is an error at its key.

use crate::common::Scratch;
use raytrace::scene_file::SceneFile;
use raytrace::texture::Texture;
use raytrace::{Error, MaterialKind, ShapeKind};
use std::path::Path;

/// The example of docs/SCENE_FORMAT.md's "Example with textures".
fn documented_example() -> String {
    let doc = include_str!("../../../docs/SCENE_FORMAT.md");
    let (_, section) = doc.split_once("## Example with textures").unwrap();
    let (_, rest) = section.split_once("```toml\n").unwrap();
    rest.split_once("```").unwrap().0.to_owned()
}

/// The image and mesh files the documented example names, written into `dir`.
fn write_example_files(dir: &Scratch) {
    std::fs::create_dir_all(dir.path("textures")).unwrap();
    std::fs::create_dir_all(dir.path("meshes")).unwrap();
    let wood: Vec<[u8; 3]> = (0..16).map(|k| [120 + k as u8 * 5, 80, 40]).collect();
    dir.png8("textures/wood.png", 4, 4, &wood);
    let carving: Vec<[u8; 3]> = (0..4).map(|k| [128 + k as u8 * 20, 128, 240]).collect();
    dir.png8("textures/carving.png", 2, 2, &carving);
    let poster: Vec<u8> = (0..64)
        .flat_map(|k| [(k % 8) as u8 * 30, (k / 8) as u8 * 30, 90])
        .collect();
    dir.jpeg("textures/poster.jpg", 8, 8, &poster);
    let panel = "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n\
                 vn -0.2 -0.2 1\nvn 0.2 -0.2 1\nvn 0.2 0.2 1\nvn -0.2 0.2 1\n\
                 f 1/1/1 2/2/2 3/3/3 4/4/4\n";
    dir.file("meshes/panel.obj", panel);
}

#[test]
fn the_documented_example_builds_and_shares_its_images() {
    let dir = Scratch::new("example");
    write_example_files(&dir);
    let path = dir.file("scene.toml", documented_example());
    let mut file = SceneFile::load(&path).unwrap();
    (file.render_mut().width, file.render_mut().spp) = (40, 2);
    let images = file.image_files();
    let names: Vec<_> = images
        .iter()
        .map(|p| p.strip_prefix(&dir.0).unwrap().to_owned())
        .collect();
    assert_eq!(
        names,
        ["textures/wood.png", "textures/carving.png", "textures/poster.jpg"].map(Path::new)
    );
    let built = file.build::<f32>().unwrap();
    assert_eq!(
        (
            built.summary.spheres,
            built.summary.meshes,
            built.summary.triangles
        ),
        (2, 1, 2)
    );
    let objects = built.scene.objects();
    // The wood sphere and the carved one share one image, and the carving's map is raw.
    let material = |k: usize| built.scene.material(objects[k].material);
    let MaterialKind::Lambertian(wood) = material(1) else {
        panic!("{:?}", material(1))
    };
    let MaterialKind::NormalMap(carved) = material(2) else {
        panic!("{:?}", material(2))
    };
    let (Texture::Image(a), MaterialKind::Lambertian(inner)) = (wood.albedo(), carved.material()) else {
        panic!("the wood is an image")
    };
    let Texture::Image(b) = inner.albedo() else {
        panic!("the carved wood is the same image")
    };
    assert!(
        std::sync::Arc::ptr_eq(a.bitmap(), b.bitmap()),
        "one file, one copy"
    );
    let Texture::Image(map) = carved.map() else {
        panic!("the carving is an image")
    };
    let texel = map.bitmap().pixels()[0];
    assert_eq!(
        texel,
        [128.0 / 255.0, 128.0 / 255.0, 240.0 / 255.0].map(|c: f64| c as f32)
    );
    // The panel's texture coordinates are flipped (OBJ) and its normals kept.
    let ShapeKind::Mesh(panel) = &objects[3].shape else {
        panic!("the fourth object is the panel")
    };
    assert_eq!(panel.uvs().unwrap()[0], [0.0, 1.0]);
    assert!(panel.normals().is_some());
    let image = raytrace::render(&built.scene, &built.camera, &built.settings)
        .unwrap()
        .image;
    assert_eq!((image.width(), image.height()), (40, 20));
}

/// The error building `text` (saved as `scene.toml` in `dir`) gives: location and message.
fn build_error(dir: &Scratch, text: &str) -> (String, String) {
    let path = dir.file("scene.toml", text);
    match SceneFile::load(&path).and_then(|f| f.build::<f64>().map(drop)) {
        Err(Error::SceneFile {
            location, message, ..
        }) => (location, message),
        other => panic!("expected a scene file error, got {other:?}\n{text}"),
    }
}

const MATTE: &str = "[materials.m]\ntype = \"lambertian\"\n";

#[test]
fn every_texture_mistake_is_reported_at_its_key() {
    let dir = Scratch::new("errors");
    dir.png8("ok.png", 1, 1, &[[10, 20, 30]]);
    dir.file("broken.png", "not a picture");
    let huge = super::files::png_header(20_000, 20_000);
    dir.file("huge.png", huge);
    dir.hdr("bright.hdr", 1, 1, &[[2.0, 0.5, 0.5]]);
    let named = |file: &str| {
        format!("[textures.wood]\ntype = \"image\"\nfile = \"{file}\"\n{MATTE}albedo = \"wood\"\n")
    };
    let inline = |file: &str| format!("{MATTE}albedo = {{ type = \"image\", file = \"{file}\" }}\n");
    let cases: Vec<(String, &str, &[&str])> = vec![
        (
            named("missing.png"),
            "textures.wood.file",
            &["missing.png", "cannot open"],
        ),
        (
            inline("missing.png"),
            "materials.m.albedo.file",
            &["missing.png", "cannot open"],
        ),
        (
            named("broken.png"),
            "textures.wood.file",
            &["broken.png", "not an image"],
        ),
        (
            inline("huge.png"),
            "materials.m.albedo.file",
            &["too large for memory", "268435456"],
        ),
        (named("bright.hdr"), "materials.m.albedo", &["[0, 1]", "2"]),
        (
            format!(
                "[textures.checks]\ntype = \"checkerboard\"\n[textures.wood]\ntype = \"image\"\nfile = \"ok.png\"\n{MATTE}albedo = \"wod\"\n"
            ),
            "materials.m.albedo",
            &["no texture named `wod` (the file defines `checks`, `wood`)"],
        ),
        (
            format!("{MATTE}albedo = \"wood\"\n"),
            "materials.m.albedo",
            &["the file defines no [textures]"],
        ),
        (
            format!("{MATTE}albedo = {{ type = \"checkerboard\", offset = [0, nan] }}\n"),
            "materials.m.albedo.offset",
            &["finite"],
        ),
        (
            format!("{MATTE}albedo = {{ type = \"checkerboard\", color1 = [0, 1.5, 0] }}\n"),
            "materials.m.albedo",
            &["[0, 1]"],
        ),
        (
            "[materials.n]\ntype = \"normal_map\"\nnormal_map = [0.5, 0.5, 1]\nmaterial = \"nothing\"\n"
                .into(),
            "materials.n.material",
            &["no material named `nothing`"],
        ),
        (
            "[materials.a]\ntype = \"normal_map\"\nnormal_map = [0.5, 0.5, 1]\nmaterial = \"b\"\n\
             [materials.b]\ntype = \"normal_map\"\nnormal_map = [0.5, 0.5, 1]\nmaterial = \"a\"\n"
                .into(),
            "materials.b.material",
            &["`a` → `b` → `a`", "circle"],
        ),
    ];
    for (text, at, words) in cases {
        let (location, message) = build_error(&dir, &text);
        assert_eq!(location, at, "{message}\n{text}");
        for w in words {
            assert!(message.contains(w), "{w:?} not in {message}\n{text}");
        }
    }
    // An unused texture is checked too.
    let unused = "[textures.wood]\ntype = \"image\"\nfile = \"missing.png\"\n\
                  [materials.x]\ntype = \"mirror\"\nalbedo = [1, 1, 1]\n";
    assert_eq!(build_error(&dir, unused).0, "textures.wood.file");
}

#[test]
fn a_colour_key_of_the_wrong_form_is_reported_where_it_is_written() {
    let parse = |text: &str| match SceneFile::parse(text, Path::new("t.toml")) {
        Err(Error::SceneFile {
            location, message, ..
        }) => (location, message),
        other => panic!("{other:?}"),
    };
    let (location, message) = parse(&format!("{MATTE}albedo = 5\n"));
    assert_eq!(location, "line 3, column 10");
    assert!(
        message.starts_with(
            "materials.m.albedo: invalid type: integer `5`, expected an array of three numbers, \
             a texture's name or a texture table"
        ),
        "{message}"
    );
    let (location, message) = parse(&format!("{MATTE}albedo = [1, 1]\n"));
    assert!(location.starts_with("line 3"), "{location}");
    assert!(
        message.contains("invalid length 2, expected an array of three numbers"),
        "{message}"
    );
    let (location, message) = parse(&format!(
        "{MATTE}albedo = {{ type = \"checkerboard\", colour0 = [1, 1, 1] }}\n"
    ));
    assert!(location.starts_with("line 3"), "{location}");
    assert!(message.contains("unknown field `colour0`"), "{message}");
    let (_, message) = parse("[textures.t]\ntype = \"image\"\nfile = \"a.png\"\nwrap = \"mirror\"\n");
    assert!(
        message.starts_with("textures.t.wrap: unknown variant `mirror`"),
        "{message}"
    );
}
