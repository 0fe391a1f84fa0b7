//! What the Mitsuba importer reads beyond Mitsuba's own plugins, and how exactly: the
//! `raytrace_` extensions (the scene file's features Mitsuba has no word for), placements
//! read in the scene file's own keys, and the defaults and conventions in which the
//! importer follows Mitsuba 3.9.1 (each checked against Mitsuba itself: see the comments).

use raytrace::image::ToneCurve;
use raytrace::import::{self, Imported};
use raytrace::scene_file::{
    BackgroundSpec, CameraSpec, FilePrecision, FresnelSpec, MaterialSpec, ObjectSpec, ScalarRef, Scale,
    TextureRef, TextureSpec,
};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;

/// `scene` written as `scene.xml` in a fresh folder (with the cube mesh beside it).
fn folder(name: &str, scene: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("rt-mitsuba-ext-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("scene.xml"), scene).unwrap();
    let cube = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/meshes/cube.obj");
    std::fs::copy(cube, dir.join("cube.obj")).unwrap();
    dir
}

/// `body` inside a `<scene>`, imported with `defines`.
fn import(name: &str, body: &str, defines: &[(&str, &str)]) -> raytrace::Result<Imported> {
    let dir = folder(name, &format!("<scene version=\"3.0.0\">\n{body}\n</scene>\n"));
    let defines: BTreeMap<String, String> = defines
        .iter()
        .map(|(k, v)| (k.to_string(), v.to_string()))
        .collect();
    let got = import::mitsuba(&dir.join("scene.xml"), &defines);
    std::fs::remove_dir_all(&dir).unwrap();
    got
}

fn error(name: &str, body: &str) -> String {
    match import(name, body, &[]) {
        Err(e) => e.to_string(),
        Ok(i) => panic!("{name}: imported {:?}", i.file),
    }
}

const EXTENSIONS: &str = r#"
    <default name="raytrace_precision" value="f32"/>
    <default name="raytrace_exposure" value="-1.5"/>
    <default name="raytrace_tonemap" value="aces"/>
    <integrator type="path"><integer name="max_depth" value="6"/></integrator>
    <sensor type="raytrace_screen">
        <point name="eye" value="0, 1, 0"/>
        <film type="hdrfilm"><integer name="width" value="64"/><integer name="height" value="32"/></film>
    </sensor>
    <emitter type="raytrace_sky"><rgb name="zenith" value="0.1, 0.2, 0.9"/></emitter>
    <bsdf type="raytrace_mirror" id="m"><rgb name="albedo" value="0.9, 0.8, 0.7"/></bsdf>
    <bsdf type="dielectric" id="g">
        <float name="int_ior" value="1.5"/><float name="ext_ior" value="1"/>
        <string name="raytrace_fresnel" value="schlick"/>
    </bsdf>
    <shape type="raytrace_plane">
        <point name="point" value="0, -1, 0"/><vector name="normal" value="0, 1, 0"/><ref id="m"/>
    </shape>
    <shape type="raytrace_triangle">
        <point name="a" value="0, 0, -3"/><point name="b" value="1, 0, -3"/><point name="c" value="0, 1, -3"/>
        <ref id="g"/>
    </shape>
"#;

#[test]
fn the_extensions_are_the_scene_files_own_keys() {
    let f = import("ext", EXTENSIONS, &[]).unwrap().file;
    let r = &f.render;
    assert_eq!(
        (r.precision, r.exposure, r.tonemap),
        (FilePrecision::F32, -1.5, ToneCurve::Aces)
    );
    // The sky is no light: Mitsuba's depth counts one segment more than the bounces here.
    assert_eq!((r.width, r.max_depth), (64, 5));
    assert_eq!(
        f.camera,
        CameraSpec::Screen {
            eye: Some([0.0, 1.0, 0.0])
        }
    );
    assert_eq!(
        f.background,
        BackgroundSpec::Sky {
            horizon: [1.0; 3],
            zenith: [0.1, 0.2, 0.9],
            light: false
        }
    );
    assert_eq!(
        f.materials["m"],
        MaterialSpec::Mirror {
            albedo: [0.9, 0.8, 0.7]
        }
    );
    assert_eq!(
        f.materials["g"],
        MaterialSpec::Dielectric {
            index: 1.5,
            albedo: None,
            fresnel: FresnelSpec::Schlick
        }
    );
    assert!(matches!(
        f.objects[0],
        ObjectSpec::Plane {
            normal: [0.0, 1.0, 0.0],
            ..
        }
    ));
    assert!(matches!(
        f.objects[1],
        ObjectSpec::Triangle {
            c: [0.0, 1.0, -3.0],
            ..
        }
    ));
    // -D sets them too; a sky that is a light counts depth as Mitsuba's emitters do.
    let lit = EXTENSIONS.replace(
        r#"<rgb name="zenith" value="0.1, 0.2, 0.9"/>"#,
        r#"<boolean name="light" value="true"/>"#,
    );
    let f = import("ext-lit", &lit, &[("raytrace_precision", "auto")])
        .unwrap()
        .file;
    assert_eq!((f.render.precision, f.render.max_depth), (FilePrecision::Auto, 6));
    assert!(f.build::<f64>().is_ok());
}

#[test]
fn a_bad_extension_is_an_error_naming_it() {
    let cases = [
        (
            "precision",
            r#"value="f32""#,
            r#"value="f16""#,
            "raytrace_precision",
        ),
        (
            "tonemap",
            r#"value="aces""#,
            r#"value="filmic""#,
            "raytrace_tonemap",
        ),
        (
            "fresnel",
            r#"value="schlick""#,
            r#"value="fast""#,
            "raytrace_fresnel",
        ),
        (
            "height",
            r#"name="height" value="32""#,
            r#"name="height" value="30""#,
            "width × width/2",
        ),
        (
            "plane",
            r#"<vector name="normal" value="0, 1, 0"/>"#,
            r#"<vector name="normal" value="0, 1, 0"/><transform name="to_world"><translate x="1"/></transform>"#,
            "to_world",
        ),
        (
            "triangle",
            r#"<point name="c" value="0, 1, -3"/>"#,
            "",
            "needs `c`",
        ),
    ];
    for (name, from, to, words) in cases {
        let message = error(name, &EXTENSIONS.replacen(from, to, 1));
        assert!(
            message.contains(words) && message.contains("scene.xml"),
            "{name}: {message}"
        );
    }
}

#[test]
fn placements_in_the_scene_files_order_are_read_as_its_keys() {
    let mesh = |steps: &str| {
        format!(
            r#"<shape type="obj"><string name="filename" value="cube.obj"/>
                <transform name="to_world">{steps}</transform></shape>
               <emitter type="envmap"><string name="filename" value="sky.hdr"/>
                <transform name="to_world"><rotate x="1" angle="10"/><rotate z="1" angle="-20"/></transform>
               </emitter>"#
        )
    };
    let srt =
        r#"<scale x="0.3" y="0.61" z="0.3"/><rotate y="1" angle="18.25"/><translate x="-0.33" y="-0.4"/>"#;
    let f = import("srt", &mesh(srt), &[]).unwrap().file;
    let ObjectSpec::Mesh {
        scale,
        rotate,
        translate,
        matrix,
        ..
    } = &f.objects[0]
    else {
        panic!("{:?}", f.objects)
    };
    assert_eq!(
        (*scale, *rotate, *translate, *matrix),
        (
            Scale::PerAxis([0.3, 0.61, 0.3]),
            [0.0, 18.25, 0.0],
            [-0.33, -0.4, 0.0],
            None
        )
    );
    assert!(matches!(
        f.background,
        BackgroundSpec::Envmap {
            rotate: [10.0, 0.0, -20.0],
            ..
        }
    ));
    // Another order is the same kind of map but not these keys: its matrix is kept.
    let f = import("trs", &mesh(r#"<translate x="1"/><scale value="2"/>"#), &[])
        .unwrap()
        .file;
    assert!(matches!(
        f.objects[0],
        ObjectSpec::Mesh {
            matrix: Some([[2.0, 0.0, 0.0, 2.0], _, _]),
            ..
        }
    ));
}

/// Mitsuba 3.9.1's own numbers, printed by `mi.load_dict`: a `perspective` with no `fov` on
/// a 100 × 50 film has `x_fov = 42.3117` (50 mm on a 36 × 24 mm film, along its
/// diagonal); a `thinlens` with no `focus_distance` focuses at `far_clip` (default 10⁴).
#[test]
fn sensor_defaults_are_mitsubas() {
    let sensor = |kind: &str, more: &str| {
        format!(
            r#"<sensor type="{kind}">{more}
                <film type="hdrfilm"><integer name="width" value="100"/><integer name="height" value="50"/></film>
               </sensor>"#
        )
    };
    let camera = |body: &str| import("sensor", body, &[]).unwrap().file.camera;
    let CameraSpec::LookAt { vfov, aspect, .. } = camera(&sensor("perspective", "")) else {
        panic!()
    };
    let x_fov = 2.0 * ((vfov.to_radians() / 2.0).tan() * aspect).atan().to_degrees();
    assert!((x_fov - 42.3117).abs() < 1e-4, "{x_fov}");
    let CameraSpec::LookAt { focus_distance, .. } =
        camera(&sensor("thinlens", r#"<float name="far_clip" value="500"/>"#))
    else {
        panic!()
    };
    assert_eq!(focus_distance, Some(500.0));
    // A fov along the vertical axis is kept as written (2·atan(tan(v/2)) need not be v).
    let y = r#"<float name="fov" value="39.3077"/><string name="fov_axis" value="y"/>"#;
    let CameraSpec::LookAt { vfov, .. } = camera(&sensor("perspective", y)) else {
        panic!()
    };
    assert_eq!(vfov, 39.3077);
}

/// Mitsuba 3.9.1's scalar lookup of a checkerboard returns `color1` where its colour lookup
/// returns `color0`, and averages an RGB colour's channels (validate/tests/test_textures.py);
/// a bitmap is sRGB-decoded unless `raw`; a normal map is shadowed and flipped unless told
/// not to (its `eval` differs in 856 of 2000 random directions with the flags left out).
#[test]
fn textures_and_normal_maps_follow_mitsubas_conventions() {
    let body = r#"
        <bsdf type="roughconductor" id="r">
            <texture type="checkerboard" name="alpha">
                <rgb name="color0" value="0.1, 0.2, 0.3"/><float name="color1" value="0.4"/>
            </texture>
        </bsdf>
        <bsdf type="normalmap" id="n">
            <boolean name="flip_invalid_normals" value="false"/>
            <texture type="bitmap" name="normalmap"><string name="filename" value="bumps.png"/></texture>
            <ref id="r"/>
        </bsdf>"#;
    let imported = import("conventions", body, &[]).unwrap();
    let MaterialSpec::RoughConductor(r) = &imported.file.materials["r"] else {
        panic!()
    };
    let Some(ScalarRef(TextureRef::Inline(t))) = &r.alpha else {
        panic!("{:?}", r.alpha)
    };
    let TextureSpec::Checkerboard { color0, color1, .. } = **t else {
        panic!()
    };
    assert_eq!(color0, [0.4; 3]);
    assert!(color1.iter().all(|c| (c - 0.2).abs() < 1e-15), "{color1:?}");
    let MaterialSpec::NormalMap {
        normal_map: TextureRef::Inline(map),
        ..
    } = &imported.file.materials["n"]
    else {
        panic!()
    };
    assert!(matches!(**map, TextureSpec::Image { raw: Some(false), .. }));
    let w = &imported.warnings;
    assert!(
        w.iter().any(|w| w.contains("use_shadowing_function"))
            && !w.iter().any(|w| w.contains("flip_invalid")),
        "{w:?}"
    );
}

#[test]
fn point_lights_beside_area_emitters_are_a_warning() {
    let body = r#"
        <shape type="sphere"><emitter type="area"/></shape>
        <emitter type="point"><point name="position" value="0, 3, 0"/></emitter>"#;
    let warnings = import("mixed", body, &[]).unwrap().warnings;
    assert!(
        warnings.iter().any(|w| w.contains("max_depth + 1")),
        "{warnings:?}"
    );
    let lit = format!("{body}<emitter type=\"constant\"/>");
    let warnings = import("mixed-lit", &lit, &[]).unwrap().warnings;
    assert!(
        !warnings.iter().any(|w| w.contains("max_depth + 1")),
        "{warnings:?}"
    );
}

/// A scene named by a relative path finds its mesh beside it (it was looked for in its
/// folder's folder of the same name).
#[test]
fn a_scene_given_by_a_relative_path_finds_its_files() {
    let dir = folder("relative", "");
    std::fs::create_dir_all(dir.join("sub")).unwrap();
    std::fs::rename(dir.join("cube.obj"), dir.join("sub/cube.obj")).unwrap();
    let scene = r#"<scene version="3.0.0">
        <shape type="obj"><string name="filename" value="cube.obj"/></shape>
        <emitter type="constant"/></scene>"#;
    std::fs::write(dir.join("sub/scene.xml"), scene).unwrap();
    let o = Command::new(env!("CARGO_BIN_EXE_raytrace"))
        .current_dir(&dir)
        .args(["check", "sub/scene.xml"])
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&o.stdout).to_string() + &String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success() && text.contains("valid"), "{text}");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Mitsuba 3.9.1 shades an instance with its file's normals and runs a `rectangle`'s uv
/// over the whole face: each is a warning unless the file says what renders alike. (An OBJ
/// without normals, which Mitsuba shades smooth, gets smooth normals here too: no warning;
/// `mitsuba_foreign.rs` tests them.)
#[test]
fn shading_that_differs_from_mitsubas_is_a_warning() {
    let warned = |body: &str, words: &str| {
        let w = import("shading", body, &[]).unwrap().warnings;
        w.iter().any(|w| w.contains(words))
    };
    let mesh =
        |more: &str| format!(r#"<shape type="obj"><string name="filename" value="cube.obj"/>{more}</shape>"#);
    assert!(!warned(&mesh(""), "normals"));
    let group = |more: &str| {
        format!(
            r#"<shape type="shapegroup" id="g">{}</shape><shape type="instance"><ref id="g"/></shape>"#,
            mesh(more)
        )
    };
    assert!(warned(&group(""), "an instance"));
    assert!(!warned(
        &group(r#"<boolean name="face_normals" value="true"/>"#),
        "an instance"
    ));
    let rectangle = |reflectance: &str| {
        format!(r#"<shape type="rectangle"><bsdf type="diffuse">{reflectance}</bsdf></shape>"#)
    };
    let checks = r#"<texture type="checkerboard" name="reflectance"/>"#;
    assert!(warned(&rectangle(checks), "their own uv"));
    assert!(!warned(
        &rectangle(r#"<rgb name="reflectance" value="0.5"/>"#),
        "their own uv"
    ));
}
