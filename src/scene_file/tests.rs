//! Parsing and building small files: each error class at its place.

use super::*;

fn parse(text: &str) -> Result<SceneFile> {
    SceneFile::parse(text, Path::new("t.toml"))
}

/// The location and message of a scene file error.
fn at(r: Result<impl std::fmt::Debug>) -> (String, String) {
    match r {
        Err(Error::SceneFile {
            location, message, ..
        }) => (location, message),
        other => panic!("expected a scene file error, got {other:?}"),
    }
}

const SPHERE: &str = "[materials.m]\ntype = \"mirror\"\nalbedo = [0.5, 0.5, 0.5]\n\n[[objects]]\ntype = \"sphere\"\ncenter = [0, 0, -3]\nradius = 1\nmaterial = \"m\"\n";

#[test]
fn an_empty_file_is_the_defaults() {
    let f = parse("").unwrap();
    assert_eq!(f.render, RenderOptions::default());
    assert_eq!(f.camera, CameraSpec::Screen { eye: None });
    let built = f.build::<f64>().unwrap();
    assert_eq!(built.scene.background(), &crate::Background::default());
    assert_eq!(built.summary, Summary::default());
}

#[test]
fn errors_inside_entries_point_at_the_entry_and_key() {
    let text = format!(
        "{SPHERE}\n[[objects]]\ntype = \"sphere\"\ncenter = [0, 0, 0]\nradius = \"big\"\nmaterial = \"m\"\n"
    );
    assert_eq!(
        at(parse(&text)),
        (
            "line 14, column 10".into(),
            "objects[1].radius: invalid type: string \"big\", expected a number".into()
        )
    );
    let text = text.replace("radius = \"big\"", "radus = 2");
    let (location, message) = at(parse(&text));
    assert_eq!(location, "line 14, column 1");
    assert!(
        message.starts_with("objects[1]: unknown field `radus`"),
        "{message}"
    );
}

#[test]
fn values_are_checked_at_their_field_path() {
    let text = SPHERE.replace("radius = 1", "radius = -1");
    assert_eq!(
        at(parse(&text).unwrap().build::<f64>()),
        ("objects[0].radius".into(), "must be > 0 (got -1)".into())
    );
    let text = SPHERE.replace("0.5, 0.5, 0.5", "0.5, 1.5, 0.5");
    assert_eq!(at(parse(&text).unwrap().build::<f32>()).0, "materials.m.albedo");
    let text = SPHERE.replace("material = \"m\"", "material = \"gold\"");
    let (location, message) = at(parse(&text).unwrap().build::<f64>());
    assert_eq!(location, "objects[0].material");
    assert!(message.contains("`gold`") && message.contains("`m`"), "{message}");
    let text = format!("[render]\nwidth = 7\n{SPHERE}");
    assert_eq!(at(parse(&text).unwrap().build::<f64>()).0, "render.width");
    let text = format!("[render]\nspp = 0\n{SPHERE}");
    assert_eq!(at(parse(&text).unwrap().build::<f64>()).0, "render.spp");
}

#[test]
fn a_value_lost_in_rounding_is_blamed_on_its_field() {
    let text = SPHERE.replace("radius = 1", "radius = 1e-60");
    let file = parse(&text).unwrap();
    assert!(file.build::<f64>().is_ok());
    let (location, message) = at(file.build::<f32>());
    assert_eq!(location, "objects[0].radius");
    assert!(message.contains("in f32"), "{message}");
}

#[test]
fn look_at_height_floors_width_over_aspect() {
    assert_eq!(build::look_at_height(400, 16.0 / 9.0), 225.0);
    assert_eq!(build::look_at_height(48, 16.0 / 9.0), 27.0);
    assert_eq!(build::look_at_height(10, 16.0 / 9.0), 5.0);
    assert_eq!(build::look_at_height(3, 4.0), 0.0);
}

#[test]
fn everything_round_trips_through_toml() {
    let mut f = SceneFile::parse("", Path::new("t.toml")).unwrap();
    f.render.seed = u64::MAX;
    f.render.acceleration = crate::Acceleration::Linear;
    f.camera = CameraSpec::LookAt {
        from: [13.0, 2.0, 3.0],
        at: [0.0; 3],
        up: [0.0, 1.0, 0.0],
        vfov: 20.0,
        aspect: 16.0 / 9.0,
        aperture: 0.1,
        focus_distance: Some(10.0),
    };
    f.background = BackgroundSpec::Solid {
        color: [0.1, 0.2, 0.3],
        light: true,
    };
    f.materials.insert(
        "glass with spaces".into(),
        MaterialSpec::Dielectric {
            index: 1.0 / 1.5,
            albedo: Some([0.9, 1.0, 0.9]),
            fresnel: FresnelSpec::Exact,
        },
    );
    f.objects.push(ObjectSpec::Mesh {
        file: "bunny.obj".into(),
        scale: Scale::PerAxis([1.0, 2.0, 3.0]),
        rotate: [0.0, 90.0, 0.0],
        translate: [0.1, 0.2, 0.3],
        material: "glass with spaces".into(),
        face_normals: true,
        flip_tex_coords: Some(false),
        matrix: None,
    });
    f.objects.push(ObjectSpec::Mesh {
        file: "bunny.obj".into(),
        scale: Scale::Uniform(1.0),
        rotate: [0.0; 3],
        translate: [0.0; 3],
        material: "glass with spaces".into(),
        face_normals: false,
        flip_tex_coords: None,
        matrix: Some([
            [0.0, -1.0, 0.0, 1.5],
            [1.0, 0.0, 0.0, 0.0],
            [0.0, 0.0, 2.0, -0.25],
        ]),
    });
    f.textures.insert(
        "wood".into(),
        TextureSpec::Image {
            file: "wood.png".into(),
            wrap: WrapSpec::Clamp,
            raw: Some(true),
            scale: UvScale::PerAxis([2.0, 3.0]),
            offset: [0.25, -0.5],
        },
    );
    let checks = TextureSpec::Checkerboard {
        color0: [0.1, 0.2, 0.3],
        color1: [0.9, 0.8, 0.7],
        scale: UvScale::Uniform(8.0),
        offset: [0.0, 0.5],
    };
    for (name, albedo) in [
        ("named", TextureRef::Named("wood".into())),
        ("inline", TextureRef::Inline(Box::new(checks))),
    ] {
        f.materials
            .insert(name.into(), MaterialSpec::Lambertian { albedo });
    }
    f.materials.insert(
        "bumpy".into(),
        MaterialSpec::NormalMap {
            normal_map: TextureRef::Color([0.5, 0.5, 1.0]),
            material: "named".into(),
        },
    );
    f.lights.push(LightSpec::Point {
        position: [1.0, 2.0, 3.0],
        intensity: [4.0, 5.0, 6.0],
    });
    f.lights.push(LightSpec::Spot {
        position: [1.0, 2.0, 3.0],
        direction: [0.0, -1.0, 0.0],
        intensity: [4.0, 5.0, 6.0],
        cutoff_angle: 30.0,
        beam_width: None,
    });
    f.lights.push(LightSpec::Directional {
        direction: [1.0, -1.0, 0.5],
        irradiance: [2.0, 2.0, 1.5],
    });
    let text = f.to_toml();
    assert_eq!(parse(&text).unwrap(), f, "{text}");
    assert!(text.contains("seed = \"18446744073709551615\""), "{text}");
}

#[test]
fn a_mesh_error_keeps_its_message_under_the_file_field() {
    let text = "[materials.m]\ntype = \"lambertian\"\nalbedo = [0.5, 0.5, 0.5]\n[[objects]]\ntype = \"mesh\"\nfile = \"missing.stl\"\nmaterial = \"m\"\n";
    let (location, message) = at(SceneFile::parse(text, Path::new("dir/s.toml"))
        .unwrap()
        .build::<f64>());
    assert_eq!(location, "objects[0].file");
    assert!(
        message.contains("missing.stl") && message.contains(".obj or .ply"),
        "{message}"
    );
}

#[test]
fn warnings_say_what_a_valid_file_probably_did_not_mean() {
    let empty = parse("").unwrap();
    assert_eq!(empty.warnings(), [Warning::NoObjects]);
    let dark = format!("[background]\ntype = \"solid\"\ncolor = [0, 0, 0]\n{SPHERE}");
    assert_eq!(parse(&dark).unwrap().warnings(), [Warning::NoLight]);
    let lit = format!("{dark}[[lights]]\nposition = [0, 2, 0]\nintensity = [1, 1, 1]\n");
    assert_eq!(parse(&lit).unwrap().warnings(), []);
    assert_eq!(parse(SPHERE).unwrap().warnings(), [], "the default sky lights it");
}

#[test]
fn a_panel_facing_away_is_a_dark_preview() {
    // A one-sided emissive triangle at z = −3; `a → b → c` counter-clockwise seen from
    // the camera faces it, clockwise faces away.
    let panel = |b: &str, c: &str| {
        format!(
            "[background]\ntype = \"solid\"\ncolor = [0, 0, 0]\n[materials.e]\ntype = \"emissive\"\n\
             radiance = [1, 1, 1]\n[[objects]]\ntype = \"triangle\"\na = [-1, -1, -3]\nb = {b}\nc = {c}\n\
             material = \"e\"\n"
        )
    };
    let toward = parse(&panel("[1, -1, -3]", "[-1, 1, -3]")).unwrap();
    let away = parse(&panel("[-1, 1, -3]", "[1, -1, -3]")).unwrap();
    assert_eq!(toward.warnings(), []);
    assert_eq!(away.warnings(), []);
    let built = toward.build::<f64>().unwrap();
    assert_eq!(toward.preview_warning(&built).unwrap(), None);
    let built = away.build::<f64>().unwrap();
    assert_eq!(away.preview_warning(&built).unwrap(), Some(Warning::DarkPreview));
}
