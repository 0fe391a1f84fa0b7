//! Disks in scene files and Mitsuba 3 XML: `type = "disk"` by its centre, normal and
//! radius or by a `matrix`, each the library's [`Disk`], its mistakes at their keys; and
//! Mitsuba's `<shape type="disk">`, placed by its `to_world` and turned over by
//! `flip_normals`, lighting (or not) the floor below it.

use raytrace::import;
use raytrace::scene_file::{ObjectSpec, SceneFile};
use raytrace::shape::Disk;
use raytrace::{Error, Hittable, ShapeKind, Vec3};
use std::collections::BTreeMap;
use std::path::Path;

const MATTE: &str = "[materials.m]\ntype = \"lambertian\"\nalbedo = [0.5, 0.5, 0.5]\n";

/// The disks the `[[objects]]` entries `objects` (each a table's keys) build, in `f64`.
fn disks(objects: &[&str]) -> Result<Vec<Disk<f64>>, Error> {
    let mut text = MATTE.to_string();
    for keys in objects {
        text += &format!("[[objects]]\ntype = \"disk\"\nmaterial = \"m\"\n{keys}\n");
    }
    let built = SceneFile::parse(&text, Path::new("disks.toml"))?.build::<f64>()?;
    assert_eq!(built.summary.disks, objects.len());
    Ok(built
        .scene
        .objects()
        .iter()
        .map(|o| match &o.shape {
            ShapeKind::Disk(d) => **d,
            other => panic!("{other:?}"),
        })
        .collect())
}

fn v(x: f64, y: f64, z: f64) -> Vec3<f64> {
    Vec3::new(x, y, z)
}

#[test]
fn a_disk_object_is_the_library_disk() {
    let got = disks(&[
        "",
        "matrix = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]]",
        "center = [1, 2, 3]\nnormal = [0, 0, 2]\nradius = 0.5",
        "center = [0, 1, 0]\nnormal = [0, -1, 0]\nradius = 2",
        // Scaled by (2, 3, 1), then moved by (1, 2, 3).
        "matrix = [[2, 0, 0, 1], [0, 3, 0, 2], [0, 0, 1, 3]]",
        // A mirror in z: the unit disk facing −z.
        "matrix = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, -1, 0]]",
    ])
    .unwrap();
    let unit = Disk::new(Vec3::zero(), v(0.0, 0.0, 1.0), 1.0).unwrap();
    assert_eq!(unit.axes(), [v(1.0, 0.0, 0.0), v(0.0, 1.0, 0.0)]);
    assert_eq!((got[0], got[1]), (unit, unit));
    assert_eq!(
        got[2],
        Disk::new(v(1.0, 2.0, 3.0), v(0.0, 0.0, 1.0), 0.5).unwrap()
    );
    assert_eq!(got[3].normal(), v(0.0, -1.0, 0.0));
    assert_eq!(got[3].center(), v(0.0, 1.0, 0.0));
    assert_eq!(
        got[4],
        Disk::with_axes(v(1.0, 2.0, 3.0), v(2.0, 0.0, 0.0), v(0.0, 3.0, 0.0)).unwrap()
    );
    assert_eq!(got[5], unit.flipped());
    assert_eq!(got[5].normal(), v(0.0, 0.0, -1.0));
}

#[test]
fn a_disks_mistakes_are_at_their_keys() {
    for (keys, at, words) in [
        ("radius = -1", "objects[0].radius", "> 0"),
        ("normal = [0, 0, 0]", "objects[0].normal", "non-zero"),
        (
            "radius = 2\nmatrix = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]]",
            "objects[0].matrix",
            "not both",
        ),
        (
            "matrix = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 0, 0]]",
            "objects[0].matrix",
            "invertible",
        ),
        ("center = [0, 0, nan]", "objects[0].center", "finite"),
    ] {
        match disks(&[keys]) {
            Err(Error::SceneFile {
                location, message, ..
            }) => assert!(
                location == at && message.contains(words),
                "{keys}: {location}: {message}"
            ),
            other => panic!("{keys}: {other:?}"),
        }
    }
}

/// A ceiling disk of radius 0.5 lighting a matte floor, seen from the side: Mitsuba's
/// unit disk scaled by ½, turned a quarter about x (so `+z` faces `−y`, down) and lifted
/// to `y = 2`; `FLIP` is `flip_normals`.
const LAMP: &str = r#"<scene version="3.0.0">
    <integrator type="path"><integer name="max_depth" value="2"/></integrator>
    <sensor type="perspective">
        <float name="fov" value="60"/>
        <transform name="to_world"><lookat origin="0, 1, 4" target="0, 0, 0" up="0, 1, 0"/></transform>
        <sampler type="independent"><integer name="sample_count" value="4"/></sampler>
        <film type="hdrfilm"><integer name="width" value="32"/><integer name="height" value="16"/></film>
    </sensor>
    <shape type="disk">
        <boolean name="flip_normals" value="FLIP"/>
        <transform name="to_world">
            <scale value="0.5"/>
            <rotate x="1" angle="90"/>
            <translate y="2"/>
        </transform>
        <emitter type="area"><rgb name="radiance" value="5"/></emitter>
    </shape>
    <shape type="rectangle">
        <transform name="to_world"><scale value="3"/><rotate x="1" angle="-90"/></transform>
    </shape>
</scene>
"#;

/// The imported lamp's disk, and the sum of the rendered image's values.
fn lamp(flip: bool) -> (ObjectSpec, Disk<f64>, f64) {
    let dir = std::env::temp_dir().join(format!("rt-disk-xml-{flip}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("lamp.xml");
    std::fs::write(&path, LAMP.replace("FLIP", &flip.to_string())).unwrap();
    let imported = import::mitsuba(&path, &BTreeMap::new()).unwrap();
    std::fs::remove_dir_all(&dir).unwrap();
    assert!(
        imported
            .read
            .iter()
            .any(|r| r.contains("disk") && r.contains("line 9")),
        "{:?}",
        imported.read
    );
    let spec = imported.file.objects[0].clone();
    let built = imported.file.build::<f64>().unwrap();
    assert_eq!((built.summary.disks, built.summary.sampled_emitters), (1, 1));
    let ShapeKind::Disk(disk) = &built.scene.objects()[0].shape else {
        panic!("{:?}", built.scene.objects()[0].shape)
    };
    let disk = **disk;
    let image = raytrace::render(&built.scene, &built.camera, &built.settings)
        .unwrap()
        .image;
    let sum: f64 = image.pixels().iter().flatten().sum();
    (spec, disk, sum)
}

#[test]
fn a_mitsuba_disk_is_placed_by_its_to_world_and_turned_by_flip_normals() {
    let (spec, disk, lit) = lamp(false);
    let ObjectSpec::Disk { matrix: Some(m), .. } = spec else {
        panic!("{spec:?}")
    };
    // Columns: x̂ ↦ (½, 0, 0), ŷ ↦ (0, 0, ½), ẑ ↦ (0, −½, 0), 0 ↦ (0, 2, 0).
    let close = |a: f64, b: f64| (a - b).abs() < 1e-12;
    let want = [[0.5, 0.0, 0.0, 0.0], [0.0, 0.0, -0.5, 2.0], [0.0, 0.5, 0.0, 0.0]];
    assert!(
        m.iter()
            .flatten()
            .zip(want.iter().flatten())
            .all(|(&a, &b)| close(a, b)),
        "{m:?}"
    );
    let n = disk.normal();
    assert!(close(n.y, -1.0) && close(disk.center().y, 2.0), "{disk:?}");
    assert!(close(disk.area().unwrap(), std::f64::consts::PI * 0.25));
    // Facing down it lights the floor; turned over it lights the ceiling, and the camera
    // below sees only its unlit back and a dark floor.
    let (_, flipped, dark) = lamp(true);
    assert!(close(flipped.normal().y, 1.0), "{flipped:?}");
    assert!(lit > 1.0 && dark == 0.0, "lit {lit}, flipped {dark}");
}

/// Twenty tilted disks, found through a BVH (built from 16 bounded objects) and by a loop
/// over them: the same bytes, so a disk's bounds hold every hit.
#[test]
fn a_bvh_of_disks_renders_the_loops_bytes() {
    let mut objects = String::new();
    for k in 0..20 {
        let (x, y) = ((k % 5) as f64 - 2.0, (k / 5) as f64 * 0.6 - 0.9);
        let n = [0.3 * (k as f64).sin(), 0.4 * (k as f64).cos(), 1.0];
        objects += &format!(
            "[[objects]]\ntype = \"disk\"\ncenter = [{x}, {y}, -3]\nnormal = {n:?}\nradius = 0.45\nmaterial = \"m\"\n\n"
        );
    }
    let render = |acceleration: &str| {
        let text =
            format!("[render]\nwidth = 64\nspp = 2\nacceleration = \"{acceleration}\"\n\n{MATTE}\n{objects}");
        let built = SceneFile::parse(&text, Path::new("disks.toml"))
            .unwrap()
            .build::<f64>()
            .unwrap();
        assert_eq!(built.summary.uses_bvh, acceleration == "bvh");
        raytrace::render(&built.scene, &built.camera, &built.settings)
            .unwrap()
            .image
    };
    let (bvh, linear) = (render("bvh"), render("linear"));
    assert_eq!(bvh.pixels(), linear.pixels());
    // The disks show: the matte grey under the sky differs from the sky around them.
    let centre = bvh.pixel(32, 16);
    assert!(bvh.pixels().iter().any(|p| *p != centre));
}

/// A disk object written back as TOML reads back the same, by its numbers or its matrix.
#[test]
fn disk_objects_round_trip_through_toml() {
    let text = format!(
        "{MATTE}[[objects]]\ntype = \"disk\"\ncenter = [0.1, 0.2, -3]\nnormal = [0, 1, 1]\nradius = 0.3\n\
         material = \"m\"\n\n[[objects]]\ntype = \"disk\"\nmatrix = [[0.5, 0, 0, 1], [0, 0, -1, 2], [0, 0.25, 0, 3]]\n\
         material = \"m\"\n"
    );
    let file = SceneFile::parse(&text, Path::new("a.toml")).unwrap();
    let again = SceneFile::parse(&file.to_toml(), Path::new("a.toml")).unwrap();
    assert_eq!(again.objects, file.objects);
    assert!(matches!(
        file.objects[1],
        ObjectSpec::Disk {
            matrix: Some(_),
            radius: 1.0,
            ..
        }
    ));
}
