//! What scenes written by others asked of the Mitsuba importer (validate/foreign/: Mitsuba's
//! documentation scenes, its test suite, its sample scenes). Each test would have caught
//! one thing the importer got wrong or refused before: a top-level area emitter referred to
//! by id (Mitsuba's Cornell box), the `direct` and `moment` integrators, spheres and
//! rectangles in a shapegroup, a mesh without normals (Mitsuba shades it smooth), and the
//! one-sided `diffuse` (black from behind in Mitsuba, both faces lit here).

use raytrace::import::{self, Imported};
use raytrace::scene_file::{MaterialSpec, ObjectSpec, TextureRef};
use raytrace::vec3::Vec3;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// `body` inside a `<scene>`, written with the cube mesh (no normals) beside it, imported;
/// the folder stays for a build (removed by `done`).
fn import_in(name: &str, body: &str) -> (PathBuf, raytrace::Result<Imported>) {
    let dir = std::env::temp_dir().join(format!("rt-mitsuba-foreign-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let scene = format!("<scene version=\"3.0.0\">\n{body}\n</scene>\n");
    std::fs::write(dir.join("scene.xml"), scene).unwrap();
    let cube = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/meshes/cube.obj");
    std::fs::copy(cube, dir.join("cube.obj")).unwrap();
    let got = import::mitsuba(&dir.join("scene.xml"), &BTreeMap::new());
    (dir, got)
}

fn import(name: &str, body: &str) -> Imported {
    let (dir, got) = import_in(name, body);
    std::fs::remove_dir_all(&dir).unwrap();
    got.unwrap_or_else(|e| panic!("{name}: {e}"))
}

/// Mitsuba's `scenes/cbox/cbox-rgb.xml` declares its area emitter at the top level with an
/// id, after the lamp that puts it on by `<ref>` (both were refused: "not supported", "names
/// no plugin defined before it").
#[test]
fn an_area_emitter_declared_apart_lights_the_shape_that_refers_to_it() {
    let imported = import(
        "area-ref",
        r#"<shape type="sphere"><ref id="lamp"/></shape>
           <emitter type="area" id="lamp"><rgb name="radiance" value="4, 3, 2"/></emitter>
           <integrator type="path"><integer name="max_depth" value="3"/></integrator>"#,
    );
    let f = &imported.file;
    let [ObjectSpec::Sphere { material, .. }] = &f.objects[..] else {
        panic!("{:?}", f.objects)
    };
    // An emitter without a BSDF reflects nothing, as in Mitsuba (it reflected half here).
    assert!(matches!(
        f.materials[material.as_str()],
        MaterialSpec::Emissive {
            radiance: [4.0, 3.0, 2.0],
            albedo: None,
            ..
        }
    ));
    assert!(imported.warnings.is_empty(), "{:?}", imported.warnings);
    // A name no plugin has, and a plugin that holds itself: errors at the `<ref>`'s line.
    for (name, body) in [
        (
            "ref-unknown",
            "<shape type=\"sphere\">\n<ref id=\"nothing\"/></shape>",
        ),
        (
            "ref-cycle",
            "<bsdf type=\"twosided\" id=\"a\">\n<ref id=\"a\"/></bsdf>",
        ),
    ] {
        let (dir, got) = import_in(name, body);
        std::fs::remove_dir_all(&dir).unwrap();
        let e = got.unwrap_err().to_string();
        assert!(e.contains("line 3") && e.contains("<ref id="), "{name}: {e}");
    }
}

/// `direct` is Mitsuba's depth 2 (the light seen, then reflected once); a strategy with no
/// samples leaves light out in Mitsuba: a warning naming it. `moment` renders the image of
/// the integrator it holds.
#[test]
fn direct_and_moment_integrators_are_read() {
    let area = r#"<shape type="sphere"><emitter type="area"/></shape>"#;
    let direct =
        format!(r#"<integrator type="direct"><integer name="bsdf_samples" value="0"/></integrator>{area}"#);
    let imported = import("direct", &direct);
    assert_eq!(imported.file.render.max_depth, 2);
    let w = &imported.warnings;
    assert!(
        w.iter()
            .any(|w| w.contains("`bsdf_samples` 0") && w.contains("line 2")),
        "{w:?}"
    );
    let moment = format!(
        r#"<integrator type="moment"><integrator type="path"><integer name="max_depth" value="5"/></integrator></integrator>{area}"#
    );
    let imported = import("moment", &moment);
    assert_eq!(imported.file.render.max_depth, 5);
    assert!(imported.warnings.iter().any(|w| w.contains("moment")));
    let (dir, got) = import_in("volpath", r#"<integrator type="volpath"/>"#);
    std::fs::remove_dir_all(&dir).unwrap();
    let e = got.unwrap_err().to_string();
    assert!(e.contains("line 2") && e.contains("volpath"), "{e}");
}

/// Mitsuba's `tests/scenes/instancing` puts a sphere and a rectangle in a shapegroup (it
/// was refused: "holds obj and ply shapes only"). Each instance places them by its map
/// after their own: a sphere under a turn and a uniform scale is a sphere.
#[test]
fn spheres_and_rectangles_in_a_shapegroup_are_placed_by_each_instance() {
    let imported = import(
        "group",
        r#"<shape type="shapegroup" id="g">
             <shape type="sphere">
               <transform name="to_world"><scale value="0.5"/><translate x="-1"/></transform>
             </shape>
             <shape type="rectangle"/>
           </shape>
           <shape type="instance"><ref id="g"/></shape>
           <shape type="instance"><ref id="g"/>
             <transform name="to_world"><rotate y="1" angle="90"/><scale value="2"/><translate z="3"/></transform>
           </shape>"#,
    );
    let spheres: Vec<([f64; 3], f64)> = imported
        .file
        .objects
        .iter()
        .filter_map(|o| match o {
            ObjectSpec::Sphere { center, radius, .. } => Some((*center, *radius)),
            _ => None,
        })
        .collect();
    assert_eq!(spheres.len(), 2);
    assert_eq!(spheres[0], ([-1.0, 0.0, 0.0], 0.5));
    // (−1, 0, 0) turned 90° about y is (0, 0, 1), scaled by 2, moved up z by 3.
    let ([x, y, z], r) = spheres[1];
    assert!(x.abs() < 1e-12 && y.abs() < 1e-12 && (z - 5.0).abs() < 1e-12 && (r - 1.0).abs() < 1e-12);
    let triangles = imported
        .file
        .objects
        .iter()
        .filter(|o| matches!(o, ObjectSpec::Triangle { .. }));
    assert_eq!(triangles.count(), 4);
}

/// Mitsuba shades a mesh whose file has no normals smooth, with angle-weighted normals
/// (the teapot of `scenes/hello.xml`); it was shaded with its faces' normals here. The
/// cube's corners then point along its diagonals, also when the mesh is stretched (the
/// normals are those of the placed surface).
#[test]
fn a_mesh_without_normals_gets_mitsubas_smooth_normals() {
    let (dir, got) = import_in(
        "smooth",
        r#"<shape type="obj"><string name="filename" value="cube.obj"/>
             <transform name="to_world"><scale x="3"/></transform></shape>
           <shape type="obj"><string name="filename" value="cube.obj"/>
             <boolean name="face_normals" value="true"/></shape>
           <emitter type="constant"/>"#,
    );
    let imported = got.unwrap();
    let f = &imported.file;
    let ObjectSpec::Mesh { file, .. } = &f.objects[0] else {
        panic!()
    };
    let mesh = f
        .assets()
        .mesh(file)
        .expect("the smoothed mesh is held in memory");
    let normals = mesh.normals.as_ref().unwrap();
    for (p, n) in mesh.positions.iter().zip(normals) {
        // Carried back by the scale's transpose: (3x, y, z)/3 placed is the diagonal again.
        let placed = Vec3::new(n.x / 3.0, n.y, n.z).normalize();
        let diagonal = Vec3::new(p.x.signum(), p.y.signum(), p.z.signum()).normalize();
        assert!((placed - diagonal).length() < 1e-12, "{p:?}: {placed:?}");
    }
    // `face_normals` keeps the file as it is, and the scene builds.
    assert!(matches!(&f.objects[1], ObjectSpec::Mesh { file, .. } if file == "cube.obj"));
    assert!(f.build::<f32>().is_ok());
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Mitsuba's `diffuse` is one-sided: seen from behind, black. Here the matte material
/// reflects from both faces, so a plain `diffuse` is a two-sided material black behind and a
/// `twosided` `diffuse` is the matte material itself (the docs' two Cornell boxes differ by
/// this alone). A panel seen from its back, under a white sky: black, then lit.
#[test]
fn a_diffuse_is_black_from_behind_and_a_twosided_one_is_not() {
    let panel = |bsdf: &str| {
        format!(
            r#"<integrator type="path"><integer name="max_depth" value="2"/></integrator>
               <sensor type="perspective"><float name="fov" value="20"/>
                 <transform name="to_world"><lookat origin="0, 0, -5" target="0, 0, 0"/></transform>
                 <sampler type="independent"><integer name="sample_count" value="16"/></sampler>
                 <film type="hdrfilm"><integer name="width" value="8"/><integer name="height" value="8"/></film>
               </sensor>
               <emitter type="constant"/>
               <shape type="rectangle"><transform name="to_world"><scale value="4"/></transform>{bsdf}</shape>"#
        )
    };
    // The mean of the pixels (grey: their first channel) and its standard error.
    let mean = |name: &str, bsdf: &str| {
        let imported = import(name, &panel(bsdf));
        let built = imported.file.build::<f64>().unwrap();
        let render = raytrace::render::render(&built.scene, &built.camera, &built.settings).unwrap();
        let px: Vec<f64> = render.image.pixels().iter().map(|p| p[0]).collect();
        let n = px.len() as f64;
        let m = px.iter().sum::<f64>() / n;
        let var = px.iter().map(|x| (x - m) * (x - m)).sum::<f64>() / (n - 1.0);
        (m, (var / n).sqrt())
    };
    let diffuse = r#"<bsdf type="diffuse"><rgb name="reflectance" value="0.5"/></bsdf>"#;
    assert_eq!(mean("back", diffuse), (0.0, 0.0));
    // Under a constant sky of 1 with nothing else, a Lambertian of albedo 0.5 shows 0.5:
    // within 5 standard errors (a 6·10⁻⁷ chance to fail if right; the seed is fixed).
    let twosided = format!(r#"<bsdf type="twosided">{diffuse}</bsdf>"#);
    let (m, se) = mean("twosided", &twosided);
    assert!(
        (m - 0.5).abs() < 5.0 * se.max(1e-12) || (m - 0.5).abs() < 1e-12,
        "{m} ± {se}"
    );
    let spec = import("spec", diffuse);
    let MaterialSpec::TwoSided(t) = &spec.file.materials["diffuse_line2"] else {
        panic!()
    };
    assert!(matches!(
        t.back.as_deref(),
        Some(MaterialSpec::Lambertian {
            albedo: TextureRef::Color([0.0, 0.0, 0.0])
        })
    ));
}

/// Every scene of the foreign set is read, none with a parameter the importer does not know
/// beyond those listed here (clipping planes, film formats: they change no pixel there).
#[test]
fn the_foreign_scenes_are_read() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("validate/foreign");
    let scenes = [
        "mitsuba-data/scenes/cbox/cbox-rgb.xml",
        "mitsuba-data/docs/scenes/integrator_direct_both.xml",
        "mitsuba-data/scenes/hello.xml",
        "mitsuba-data/tests/scenes/floating_sphere/test_directional_direct.xml",
        "mitsuba-data/tests/scenes/instancing/test_instancing_path.xml",
        "mitsuba-data/tests/scenes/infinite_mirrors/scene_path.xml",
        "mitsuba-data/docs/scenes/bsdf_twosided_cbox.xml",
        "mitsuba-data/docs/scenes/bsdf_twosided_cbox_onesided.xml",
        "pointcloud/pointcloud.xml",
    ];
    // Clipping planes and film formats change no pixel there; `moment` adds channels only;
    // `hello`'s `bsdf_samples` 0 loses nothing (its lights are points), its turn about
    // (0, 1, 1) is Mitsuba's, and its `emitter_samples` 4 is the one difference (Mitsuba's:
    // validate/foreign/README.md); the point cloud's unbounded depth is 64 here (what paths
    // longer than that add is below the noise).
    let harmless = [
        "length is not 1",
        "`emitter_samples` 4",
        "near_clip",
        "far_clip",
        "pixel_format",
        "component_format",
        "focus_distance",
        "moment",
        "bsdf_samples",
        "unbounded",
    ];
    for scene in scenes {
        let imported = import::mitsuba(&root.join(scene), &BTreeMap::new()).unwrap_or_else(|e| panic!("{e}"));
        for w in &imported.warnings {
            assert!(harmless.iter().any(|h| w.contains(h)), "{scene}: {w}");
        }
        imported
            .file
            .build::<f32>()
            .unwrap_or_else(|e| panic!("{scene}: {e}"));
    }
}

/// A Mitsuba 0.x file (point-cloud figure scripts still write version 0.6.0 for Mitsuba 3)
/// is read as Mitsuba 3 reads it, its camelCase names in snake_case: its `toWorld`,
/// `intIOR`, `diffuseReflectance` and a texture's `uscale` were parameters not read
/// (the sphere stood at the origin, the plastic had its default index).
#[test]
fn a_version_0_6_scene_is_upgraded_as_mitsuba_upgrades_it() {
    let dir = std::env::temp_dir().join(format!("rt-mitsuba-foreign-v06-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let scene = r#"<scene version="0.6.0">
        <integrator type="path"><integer name="maxDepth" value="4"/></integrator>
        <bsdf type="plastic" id="p">
            <float name="intIOR" value="1.46"/><rgb name="diffuseReflectance" value="0.2"/>
        </bsdf>
        <bsdf type="diffuse" id="d">
            <texture type="checkerboard" name="diffuseReflectance">
                <float name="uscale" value="4"/><float name="voffset" value="0.5"/>
            </texture>
        </bsdf>
        <shape type="sphere">
            <transform name="toWorld"><translate x="1" y="2" z="3"/></transform>
            <ref id="p"/>
        </shape>
        <emitter type="constant"/>
    </scene>"#;
    std::fs::write(dir.join("scene.xml"), scene).unwrap();
    let imported = import::mitsuba(&dir.join("scene.xml"), &BTreeMap::new()).unwrap();
    std::fs::remove_dir_all(&dir).unwrap();
    assert!(imported.warnings.is_empty(), "{:?}", imported.warnings);
    let f = &imported.file;
    assert_eq!(f.render.max_depth, 4);
    assert!(matches!(
        f.objects[0],
        ObjectSpec::Sphere {
            center: [1.0, 2.0, 3.0],
            ..
        }
    ));
    let MaterialSpec::Plastic(p) = &f.materials["p"] else {
        panic!()
    };
    assert!(matches!(p.int_ior, raytrace::scene_file::IorSpec::Value(x) if x == 1.46));
    assert_eq!(p.diffuse_reflectance, TextureRef::Color([0.2; 3]));
    // The checkerboard's uv: scaled by (4, 1) after moved by (0, 0.5).
    let MaterialSpec::TwoSided(d) = &f.materials["d"] else {
        panic!()
    };
    let MaterialSpec::Lambertian {
        albedo: TextureRef::Inline(t),
    } = d.front.as_ref()
    else {
        panic!()
    };
    let text = format!("{t:?}");
    assert!(
        text.contains("PerAxis([4.0, 1.0])") && text.contains("offset: [0.0, 0.5]"),
        "{text}"
    );
}

/// Mitsuba 3.9.1 does not normalise a `<rotate>` axis: `scenes/hello.xml` turns its teapot
/// about (0, 1, 1), and Mitsuba's map then stretches as it turns (its matrix, printed by
/// Mitsuba itself: `mi.ScalarTransform4f().rotate([0, 1, 1], 15)`). The importer turned about
/// the unit axis: the teapots stood apart by a pixel's width. Now it follows Mitsuba, and
/// says so.
#[test]
fn a_rotation_axis_is_used_as_written_as_in_mitsuba() {
    let imported = import(
        "axis",
        r#"<shape type="obj"><string name="filename" value="cube.obj"/>
             <boolean name="face_normals" value="true"/>
             <transform name="to_world"><rotate x="0" y="1" z="1" angle="15"/></transform></shape>
           <emitter type="constant"/>"#,
    );
    let ObjectSpec::Mesh { matrix: Some(m), .. } = &imported.file.objects[0] else {
        panic!("{:?}", imported.file.objects[0])
    };
    let mitsuba = [
        [0.9659258, -0.25881904, 0.25881904],
        [0.25881904, 1.0, 0.03407419],
        [-0.25881904, 0.03407419, 1.0],
    ];
    for (row, want) in m.iter().zip(mitsuba) {
        for (got, want) in row.iter().zip(want) {
            assert!((got - want).abs() < 1e-7, "{m:?}");
        }
    }
    assert!(
        imported
            .warnings
            .iter()
            .any(|w| w.contains("length is not 1") && w.contains("line 4")),
        "{:?}",
        imported.warnings
    );
}
