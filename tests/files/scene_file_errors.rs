//! Every kind of mistake in a scene file is reported where it is: malformed TOML at its line
//! and column; a wrong type, an unknown key or a missing key at the field's path in every
//! section and the line and column of the value, key or table; an invalid value, an unknown
//! material or a mesh that cannot be loaded at its field path.

use raytrace::scene_file::SceneFile;
use std::path::Path;

const GOOD: &str = include_str!("../../scenes/four_mirrors.toml");

/// A scene file error's location and message.
fn error_at<T: std::fmt::Debug>(r: raytrace::Result<T>) -> (String, String) {
    match r {
        Err(raytrace::Error::SceneFile {
            path,
            location,
            message,
            ..
        }) => {
            assert_eq!(path, Path::new("bad.toml"));
            (location, message)
        }
        other => panic!("expected a scene file error, got {other:?}"),
    }
}

fn parse(text: &str) -> raytrace::Result<SceneFile> {
    SceneFile::parse(text, Path::new("bad.toml"))
}

#[test]
fn malformed_toml_is_reported_at_its_line_and_column() {
    let (location, message) = error_at(parse("[render]\nwidth = 800\nspp = [1, 2\n"));
    assert_eq!(location, "line 3, column 12");
    assert!(message.contains("unclosed array"), "{message}");
    let (location, _) = error_at(parse("[render]\n  width == 3\n"));
    assert!(location.starts_with("line 2, column"), "{location}");
}

#[test]
fn an_unknown_key_is_named() {
    let text = GOOD.replace("max_depth = 10", "max_dpeth = 10");
    let (location, message) = error_at(parse(&text));
    assert_eq!(location, "line 7, column 1");
    assert!(message.contains("unknown field `max_dpeth`"), "{message}");
    let text = GOOD.replace("radius = 0.6", "radius = 0.6\ncolour = 3");
    let (location, message) = error_at(parse(&text));
    assert!(
        message.starts_with("objects[1]: unknown field `colour`"),
        "{message}"
    );
    // The key under the second `[[objects]]`, the line after `radius = 0.6` (line 49).
    assert_eq!(location, "line 50, column 1");
}

#[test]
fn a_wrong_type_is_named() {
    let (location, message) = error_at(parse("[render]\nspp = \"many\"\n"));
    assert_eq!(location, "line 2, column 7");
    assert!(message.starts_with("render.spp: invalid type"), "{message}");
    let text = GOOD.replace("radius = 0.6", "radius = true");
    let (_, message) = error_at(parse(&text));
    assert!(
        message.starts_with("objects[1].radius: invalid type"),
        "{message}"
    );
}

/// `text`'s error: (location, message).
fn wrong(text: &str) -> (String, String) {
    error_at(parse(text))
}

#[test]
fn every_section_names_the_field_of_a_wrong_type_at_its_value() {
    let look_at =
        "[camera]\ntype = \"look_at\"\nfrom = [0, 0, 0]\nvfov = \"wide\"\nat = [0, 0, -1]\naspect = 2\n";
    assert_eq!(
        wrong(look_at),
        (
            "line 4, column 8".into(),
            "camera.vfov: invalid type: string \"wide\", expected a number".into()
        )
    );
    assert_eq!(
        wrong("[background]\ntype = \"solid\"\ncolor = \"red\"\n"),
        (
            "line 3, column 9".into(),
            "background.color: invalid type: string \"red\", expected an array of three numbers".into()
        )
    );
    assert_eq!(
        wrong("[materials.m]\ntype = \"mirror\"\nalbedo = \"grey\"\n"),
        (
            "line 3, column 10".into(),
            "materials.m.albedo: invalid type: string \"grey\", expected an array of three numbers".into()
        )
    );
    let sphere = "[[objects]]\ntype = \"sphere\"\nradius = 1\ncenter = [0, 0, \"far\"]\nmaterial = \"m\"\n";
    assert_eq!(
        wrong(sphere),
        (
            "line 4, column 10".into(),
            "objects[0].center: invalid type: string \"far\", expected a number".into()
        )
    );
    // In an inline table, and in the second of two entries that fail the same way.
    let (location, message) = wrong(&format!(
        "camera = {{ type = \"screen\", eye = 1 }}\n{sphere}{sphere}"
    ));
    assert_eq!(location, "line 1, column 35");
    assert!(
        message.starts_with("camera.eye: invalid type: integer `1`"),
        "{message}"
    );
    let second = format!("{}{sphere}", sphere.replace("\"far\"", "-3"));
    assert_eq!(wrong(&second).0, "line 9, column 10");
    assert!(wrong(&second).1.starts_with("objects[1].center:"));
    // Fields of plain tables are named down to the array element.
    assert_eq!(
        wrong("[[lights]]\nposition = [0, 1, \"up\"]\nintensity = [1, 1, 1]\n"),
        (
            "line 2, column 19".into(),
            "lights[0].position[2]: invalid type: string \"up\", expected a number".into()
        )
    );
    // A tag or a choice that does not exist, a mesh's scale that is neither form.
    let (location, message) = wrong("[[objects]]\ntype = \"cube\"\n");
    assert_eq!(location, "line 2, column 8");
    assert!(
        message.starts_with("objects[0].type: unknown variant `cube`"),
        "{message}"
    );
    let (location, message) = wrong("[render]\nwidth = 8\nbvh_quality = \"ultra\"\n");
    assert_eq!(location, "line 3, column 15");
    assert!(
        message.starts_with("render.bvh_quality: unknown variant `ultra`, expected `medium` or `high`"),
        "{message}"
    );
    let (location, message) =
        wrong("[materials.glass]\ntype = \"dielectric\"\nindex = 1.5\nfresnel = \"approx\"\n");
    assert_eq!(location, "line 4, column 11");
    assert!(
        message.starts_with("materials.glass.fresnel: unknown variant"),
        "{message}"
    );
    let mesh = "[[objects]]\ntype = \"mesh\"\nfile = \"a.obj\"\nscale = [1, \"2\", 1]\nmaterial = \"m\"\n";
    assert_eq!(
        wrong(mesh),
        (
            "line 4, column 9".into(),
            "objects[0].scale: expected a number or an array of three numbers".into()
        )
    );
}

#[test]
fn every_section_names_an_unknown_key_at_its_line() {
    let (location, message) = wrong("[camera]\ntype = \"screen\"\nfov = 40\n");
    assert_eq!(location, "line 3, column 1");
    assert!(message.starts_with("camera: unknown field `fov`"), "{message}");
    let (location, message) = wrong("[background]\ntype = \"sky\"\nhorizon = [1, 1, 1]\nsun = 1\n");
    assert_eq!(location, "line 4, column 1");
    assert!(
        message.starts_with("background: unknown field `sun`"),
        "{message}"
    );
    let (location, message) = wrong("[render]\nwidth = 8\n\ncolour = 1\n");
    assert_eq!(location, "line 4, column 1");
    assert!(message.starts_with("render: unknown field `colour`"), "{message}");
    let (location, message) = wrong("[[lights]]\nposition = [0, 1, 0]\nintensity = [1, 1, 1]\ncolor = 1\n");
    assert_eq!(location, "line 4, column 1");
    assert!(
        message.starts_with("lights[0]: unknown field `color`"),
        "{message}"
    );
    let (location, message) = wrong("[rendr]\nwidth = 8\n");
    assert_eq!(location, "line 1, column 2");
    assert!(message.starts_with("unknown field `rendr`"), "{message}");
    // A missing key is the entry's: at its header.
    let (location, message) =
        wrong("[render]\nwidth = 8\nspp = 2\n\n[[objects]]\ntype = \"sphere\"\nradius = 1\n");
    assert_eq!(location, "line 5, column 1");
    assert!(
        message.starts_with("objects[0]: missing field `center`"),
        "{message}"
    );
    let (location, message) = wrong(
        "[[objects]]\ntype = \"sphere\"\ncenter = [0, 0, 0]\nradius = 1\nmaterial = \"m\"\n\n[camera]\ntype = \"look_at\"\nfrom = [0, 0, 0]\n",
    );
    assert_eq!(location, "line 7, column 1");
    assert!(message.starts_with("camera: missing field `at`"), "{message}");
}

#[test]
fn an_invalid_value_is_reported_at_its_field_path() {
    let text = GOOD.replace("radius = 1.0\n", "radius = -1\n");
    assert_eq!(
        error_at(parse(&text).unwrap().build::<f64>()),
        ("objects[3].radius".into(), "must be > 0 (got -1)".into())
    );
    let text = GOOD.replace("albedo = [0.5, 0.65, 0.95]", "albedo = [0.5, nan, 0.95]");
    let (location, message) = error_at(parse(&text).unwrap().build::<f32>());
    assert_eq!(location, "materials.mirror_3.albedo");
    assert!(message.contains("[0, 1]") && message.contains("NaN"), "{message}");
    let text = GOOD.replace("width = 800", "width = 0");
    assert_eq!(error_at(parse(&text).unwrap().build::<f64>()).0, "render.width");
}

#[test]
fn an_unknown_material_is_reported_with_the_known_ones() {
    let text = GOOD.replace("material = \"mirror_2\"", "material = \"gold\"");
    let (location, message) = error_at(parse(&text).unwrap().build::<f64>());
    assert_eq!(location, "objects[2].material");
    assert!(
        message.contains("`gold`") && message.contains("`mirror_0`"),
        "{message}"
    );
}

#[test]
fn a_mesh_error_is_passed_through_with_the_file_field() {
    let text = format!(
        "{GOOD}\n[[objects]]\ntype = \"mesh\"\nfile = \"meshes/bunny.obj\"\nscale = 2\nmaterial = \"mirror_0\"\n"
    );
    let file = SceneFile::parse(&text, Path::new("bad.toml")).unwrap();
    let (location, message) = error_at(file.build::<f64>());
    assert_eq!(location, "objects[5].file");
    assert!(message.contains("bunny.obj"), "{message}");
}

#[test]
fn messages_speak_of_the_file_not_of_rust_types() {
    let cases = [
        "render = 3\n",
        "[render]\nspp = \"many\"\n",
        "[render]\nmax_depth = 1.5\n",
        "[render]\nprecision = 3\n",
        "camera = 3\n",
        "[camera]\ntype = 3\n",
        "background = \"sky\"\n",
        "[materials]\nm = 3\n",
        "objects = [1]\n",
        "objects = 1\n",
        "lights = [1]\n",
        "[[lights]]\nposition = [0, 0, \"a\"]\nintensity = [1, 1, 1]\n",
    ];
    for text in cases {
        let (location, message) = wrong(text);
        assert!(location.starts_with("line "), "{text}: {location}");
        for rust in [
            "internally tagged",
            "Spec",
            "struct",
            "RenderOptions",
            "u32",
            "f64",
            "variant identifier",
            "wanted",
            "sequence",
        ] {
            assert!(!message.contains(rust), "{text}: {rust:?} in {message}");
        }
    }
}

#[test]
fn a_point_is_three_numbers_exactly() {
    for (key, text) in [
        (
            "lights[0].position",
            "[[lights]]\nposition = [0, 1, 2, 3]\nintensity = [1, 1, 1]\n",
        ),
        ("camera.eye", "[camera]\ntype = \"screen\"\neye = [0, 0, 0, 0]\n"),
        (
            "materials.m.albedo",
            "[materials.m]\ntype = \"mirror\"\nalbedo = [1, 1, 1, 1]\n",
        ),
    ] {
        let (location, message) = wrong(text);
        assert!(location.starts_with("line "), "{location}");
        assert!(
            message.starts_with(&format!(
                "{key}: invalid length 4, expected an array of three numbers"
            )),
            "{message}"
        );
    }
}

#[test]
fn a_width_in_quotes_is_refused_as_spp_in_quotes_is() {
    for key in ["width", "spp", "max_depth", "seed"] {
        let (location, message) = wrong(&format!("[render]\n{key} = \"12\"\n"));
        assert_eq!(location, format!("line 2, column {}", key.len() + 4));
        assert!(message.starts_with(&format!("render.{key}: ")), "{message}");
    }
    // A seed beyond a TOML integer is still a string of digits.
    let file = parse("[render]\nseed = \"18446744073709551615\"\n").unwrap();
    assert_eq!(file.render().seed, u64::MAX);
}

/// A build error's `(location, line)`.
fn built_error_line(text: &str) -> (String, Option<(usize, usize)>) {
    match parse(text).unwrap().build::<f64>() {
        Err(raytrace::Error::SceneFile { location, line, .. }) => (location, line),
        other => panic!("expected a scene file error, got {other:?}"),
    }
}

#[test]
fn an_invalid_value_also_says_on_which_line_it_is_written() {
    let text = GOOD.replace("radius = 1.0\n", "radius = -1\n");
    let (location, line) = built_error_line(&text);
    assert_eq!(location, "objects[3].radius");
    let (l, c) = line.expect("a parsed file knows its lines");
    assert_eq!(&text.lines().nth(l - 1).unwrap()[c - 1..], "-1");
    let e = parse(&text).unwrap().build::<f64>().unwrap_err().to_string();
    assert_eq!(
        e,
        format!("bad.toml: line {l}, column {c}: objects[3].radius: must be > 0 (got -1)")
    );
    // A value left at its default is at the table it belongs to: the camera's height comes
    // from `[render] width`, here not written, so the `[render]` header.
    let look_at = "[render]\nspp = 1\n\n[camera]\ntype = \"look_at\"\nfrom = [0, 0, 0]\nat = [0, 0, -1]\nvfov = 40\naspect = 1e9\n";
    assert_eq!(built_error_line(look_at), ("render.width".into(), Some((1, 1))));
    // A file made in code has no text, hence no line.
    let mut file = raytrace::scene_file::SceneFile::default();
    file.render_mut().width = 0;
    match file.build::<f64>() {
        Err(raytrace::Error::SceneFile { location, line, .. }) => {
            assert_eq!((location.as_str(), line), ("render.width", None));
        }
        other => panic!("{other:?}"),
    }
}
