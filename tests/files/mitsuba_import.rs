//! Mitsuba 3 XML scenes read into scene files: structure (`<default>`, `$name`, `-D`,
//! `<include>`, `id` and `<ref>`), transforms, sensors, shapes, BSDFs, textures and
//! emitters land as the scene file's own keys; what is not read is an error naming the
//! plugin, the file and the line; what differs is a warning naming it.

use raytrace::Error;
use raytrace::import;
use raytrace::scene_file::{
    BackgroundSpec, CameraSpec, LightSpec, MaterialSpec, ObjectSpec, TextureRef, TextureSpec,
};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

const SCENE: &str = r#"<scene version="3.0.0">
    <default name="spp" value="4"/>
    <default name="radius" value="0.5"/>
    <integrator type="path">
        <integer name="max_depth" value="3"/>
    </integrator>
    <sensor type="perspective">
        <float name="fov" value="40"/>
        <transform name="to_world">
            <lookat origin="0, 1, 5" target="0, 0.5, 0" up="0, 1, 0"/>
        </transform>
        <sampler type="independent">
            <integer name="sample_count" value="$spp"/>
        </sampler>
        <film type="hdrfilm">
            <integer name="width" value="64"/>
            <integer name="height" value="32"/>
            <rfilter type="gaussian"/>
        </film>
    </sensor>
    <bsdf type="diffuse" id="checks">
        <texture type="checkerboard" name="reflectance">
            <rgb name="color0" value="0.8, 0.1, 0.1"/>
            <rgb name="color1" value="0.1"/>
            <transform name="to_uv">
                <scale x="4" y="2"/>
            </transform>
        </texture>
    </bsdf>
    <include filename="metal.xml"/>
    <shape type="sphere">
        <float name="radius" value="$radius"/>
        <transform name="to_world">
            <scale value="2"/>
            <translate x="1" y="1"/>
        </transform>
        <ref id="gold"/>
    </shape>
    <shape type="rectangle">
        <transform name="to_world">
            <rotate x="1" angle="90"/>
            <translate y="3"/>
        </transform>
        <emitter type="area">
            <rgb name="radiance" value="10"/>
        </emitter>
    </shape>
    <shape type="obj">
        <string name="filename" value="cube.obj"/>
        <transform name="to_world">
            <matrix value="1 0 0 2  0 2 0 0  0 0 1 0  0 0 0 1"/>
        </transform>
        <ref id="checks"/>
    </shape>
    <emitter type="point">
        <point name="position" x="0" y="4" z="0"/>
        <rgb name="intensity" value="5"/>
    </emitter>
</scene>
"#;

const METAL: &str = r#"<scene version="3.0.0">
    <bsdf type="roughconductor" id="gold">
        <string name="material" value="Au"/>
        <string name="distribution" value="ggx"/>
        <float name="alpha" value="0.2"/>
    </bsdf>
</scene>
"#;

/// A folder holding the scene, its include and a copy of the cube mesh.
fn folder(name: &str, scene: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("rt-mitsuba-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("scene.xml"), scene).unwrap();
    std::fs::write(dir.join("metal.xml"), METAL).unwrap();
    let cube = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/meshes/cube.obj");
    std::fs::copy(cube, dir.join("cube.obj")).unwrap();
    dir
}

fn import_error(scene: &str, name: &str) -> String {
    let dir = folder(name, scene);
    let got = import::mitsuba(&dir.join("scene.xml"), &BTreeMap::new()).map(drop);
    std::fs::remove_dir_all(&dir).unwrap();
    match got {
        Err(e @ Error::SceneFile { .. }) => e.to_string(),
        other => panic!("{name}: {other:?}"),
    }
}

#[test]
fn a_scene_lands_as_the_scene_files_own_keys() {
    let dir = folder("whole", SCENE);
    let defines = BTreeMap::from([("spp".to_string(), "8".to_string())]);
    let imported = import::mitsuba(&dir.join("scene.xml"), &defines).unwrap();
    let f = &imported.file;
    // -D over <default>; an area light: Mitsuba's depth as is.
    assert_eq!((f.render.width, f.render.spp, f.render.max_depth), (64, 8, 3));
    let CameraSpec::LookAt {
        from,
        at,
        up,
        vfov,
        aspect,
        ..
    } = f.camera
    else {
        panic!("{:?}", f.camera)
    };
    // A lone <lookat> keeps its origin, target and up as written.
    assert_eq!(
        (from, at, up, aspect),
        ([0.0, 1.0, 5.0], [0.0, 0.5, 0.0], [0.0, 1.0, 0.0], 2.0)
    );
    // fov 40 along x, aspect 2: tan(v/2) = tan(20°)/2.
    assert!((vfov - 2.0 * (20f64.to_radians().tan() / 2.0).atan().to_degrees()).abs() < 1e-12);
    assert_eq!(
        f.background,
        BackgroundSpec::Solid {
            color: [0.0; 3],
            light: false
        }
    );
    // The sphere: radius 0.5 scaled by 2, centre moved.
    assert_eq!(
        f.objects[0],
        ObjectSpec::Sphere {
            center: [1.0, 1.0, 0.0],
            radius: 1.0,
            material: "gold".into()
        }
    );
    assert!(
        matches!(&f.materials["gold"], MaterialSpec::RoughConductor(c) if c.material.as_deref() == Some("Au"))
    );
    // The rectangle: two triangles turned to face down (+z to −y), at y = 3, emitting.
    let ObjectSpec::Triangle { a, b, c, material } = &f.objects[1] else {
        panic!("{:?}", f.objects[1])
    };
    assert!(
        [a, b, c].iter().all(|p| (p[1] - 3.0).abs() < 1e-12),
        "{a:?} {b:?} {c:?}"
    );
    let n = cross(sub(*b, *a), sub(*c, *a));
    assert!(n[1] < 0.0 && n[0].abs() < 1e-12 && n[2].abs() < 1e-12, "{n:?}");
    assert!(matches!(
        f.materials[material.as_str()],
        MaterialSpec::Emissive {
            radiance: [10.0, 10.0, 10.0],
            ..
        }
    ));
    // The mesh keeps its matrix; its material (a one-sided diffuse: matte in front, black
    // behind) has the checkerboard with its to_uv.
    let ObjectSpec::Mesh { matrix, material, .. } = &f.objects[3] else {
        panic!("{:?}", f.objects[3])
    };
    assert_eq!(
        *matrix,
        Some([[1.0, 0.0, 0.0, 2.0], [0.0, 2.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0]])
    );
    let MaterialSpec::TwoSided(sides) = &f.materials[material.as_str()] else {
        panic!()
    };
    let MaterialSpec::Lambertian {
        albedo: TextureRef::Inline(t),
    } = sides.front.as_ref()
    else {
        panic!()
    };
    assert!(matches!(
        **t,
        TextureSpec::Checkerboard {
            color1: [0.1, 0.1, 0.1],
            ..
        }
    ));
    assert!(matches!(
        f.lights[..],
        [LightSpec::Point {
            position: [0.0, 4.0, 0.0],
            intensity: [5.0, 5.0, 5.0]
        }]
    ));
    // The Gaussian filter is named in a warning; the included file's plugin among those read.
    assert!(
        imported
            .warnings
            .iter()
            .any(|w| w.contains("gaussian") && w.contains("line 18")),
        "{:?}",
        imported.warnings
    );
    assert!(
        imported.read.iter().any(|r| r.contains("metal.xml")),
        "{:?}",
        imported.read
    );
    // And it builds and renders.
    let built = f.build::<f32>().unwrap();
    assert_eq!(built.summary.sampled_emitters, 2);
    let image = raytrace::render(&built.scene, &built.camera, &built.settings)
        .unwrap()
        .image;
    assert_eq!((image.width(), image.height()), (64, 32));
    let lit = image
        .pixels()
        .iter()
        .filter(|p| p.iter().any(|&c| c > 0.0))
        .count();
    // Under a black sky the gold shows only the lights it reflects: a tenth of the image.
    assert!(lit > 100, "{lit} pixels lit");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn what_is_not_read_is_an_error_naming_the_plugin_file_and_line() {
    let cylinder = SCENE.replace("<shape type=\"rectangle\">", "<shape type=\"cylinder\">");
    let message = import_error(&cylinder, "cylinder");
    assert!(
        message.contains("scene.xml") && message.contains("line 39") && message.contains("cylinder"),
        "{message}"
    );
    let undefined = SCENE.replace("$radius", "$size");
    let message = import_error(&undefined, "undefined");
    assert!(
        message.contains("$size") && message.contains("line 32"),
        "{message}"
    );
    let dangling = SCENE.replace("<ref id=\"gold\"/>", "<ref id=\"silver\"/>");
    let message = import_error(&dangling, "dangling");
    assert!(message.contains("silver"), "{message}");
    let broken = SCENE.replace("</sensor>", "");
    let message = import_error(&broken, "broken");
    assert!(message.contains("not well-formed XML"), "{message}");
}

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

proptest::proptest! {
    #![proptest_config(crate::common::config(128, 0x3175_0BA0, "proptest-regressions/mitsuba_import.txt"))]

    /// Arbitrary text, and edits of a real scene (a cut and an insertion of XML-ish
    /// characters), are imported or refused with an error, never a panic; what imports
    /// builds or is refused too.
    #[test]
    fn any_edit_of_a_real_scene_is_refused_or_read_without_panicking(
        at in 0..SCENE.len(), cut in 0..24usize, insert in "[<>/=\"a-z0-9.,$ \\n-]{0,16}",
        junk in "\\PC{0,120}",
    ) {
        let mut text = SCENE.as_bytes()[..at].to_vec();
        text.extend_from_slice(insert.as_bytes());
        text.extend_from_slice(&SCENE.as_bytes()[(at + cut).min(SCENE.len())..]);
        let dir = folder("edit", &String::from_utf8_lossy(&text));
        for scene in [None, Some(junk.as_str())] {
            if let Some(junk) = scene {
                std::fs::write(dir.join("scene.xml"), junk).unwrap();
            }
            if let Ok(imported) = import::mitsuba(&dir.join("scene.xml"), &BTreeMap::new()) {
                let _ = imported.file.build::<f32>().map(|b| b.summary);
            }
        }
        std::fs::remove_dir_all(&dir).unwrap();
    }
}

#[test]
fn a_shapegroup_is_read_once_and_placed_by_each_instance() {
    let group = r#"<scene version="3.0.0">
    <include filename="metal.xml"/>
    <shape type="shapegroup" id="crate">
        <shape type="obj">
            <string name="filename" value="cube.obj"/>
            <transform name="to_world"><scale value="0.5"/></transform>
            <ref id="gold"/>
        </shape>
    </shape>
    <shape type="instance">
        <ref id="crate"/>
        <transform name="to_world"><translate x="3"/></transform>
    </shape>
    <shape type="instance">
        <ref id="crate"/>
        <transform name="to_world"><rotate y="1" angle="90"/></transform>
    </shape>
</scene>
"#;
    let dir = folder("group", group);
    let imported = import::mitsuba(&dir.join("scene.xml"), &BTreeMap::new()).unwrap();
    let f = &imported.file;
    assert_eq!(f.meshes.len(), 1);
    let matrices: Vec<_> = f
        .objects
        .iter()
        .map(|o| match o {
            ObjectSpec::Instance {
                mesh,
                matrix,
                material,
                ..
            } => {
                assert_eq!((mesh.as_str(), material.as_str()), ("crate_0", "gold"));
                matrix.unwrap()
            }
            other => panic!("{other:?}"),
        })
        .collect();
    // Scaled by ½ first, then moved; scaled, then turned a quarter about y.
    assert_eq!(
        matrices[0],
        [[0.5, 0.0, 0.0, 3.0], [0.0, 0.5, 0.0, 0.0], [0.0, 0.0, 0.5, 0.0]]
    );
    let r = matrices[1];
    assert!(
        (r[0][2] - 0.5).abs() < 1e-12 && (r[2][0] + 0.5).abs() < 1e-12 && r[0][0].abs() < 1e-12,
        "{r:?}"
    );
    let built = f.build::<f64>().unwrap();
    assert_eq!(built.summary.instances, 2);
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A parameter nothing reads (unknown, or misspelt) is a warning naming it, its plugin, file
/// and line; the scene's own parameters, all read, give none.
#[test]
fn a_parameter_nothing_reads_is_a_warning_naming_it() {
    let unread = |scene: &str, name: &str| {
        let dir = folder(name, scene);
        let imported = import::mitsuba(&dir.join("scene.xml"), &BTreeMap::new()).unwrap();
        std::fs::remove_dir_all(&dir).unwrap();
        let notes: Vec<String> = imported
            .warnings
            .into_iter()
            .filter(|w| w.contains("is not read"))
            .collect();
        notes
    };
    assert_eq!(unread(SCENE, "all-read"), Vec::<String>::new());
    let misspelt = SCENE.replace(
        "<shape type=\"rectangle\">",
        "<shape type=\"rectangle\">\n        <float name=\"radiuss\" value=\"2\"/>",
    );
    let notes = unread(&misspelt, "misspelt");
    assert_eq!(notes.len(), 1, "{notes:?}");
    let note = &notes[0];
    for words in ["<shape type=\"rectangle\">", "scene.xml", "line 40", "`radiuss`"] {
        assert!(note.contains(words), "{words}: {note}");
    }
}
