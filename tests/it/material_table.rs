//! A scene's table of materials: objects that share one render as objects that each hold a
//! copy, scene files share a named material, and an identifier of another table is refused.

use raytrace::prelude::*;
use raytrace::scene_file::SceneFile;
use raytrace::{Acceleration, MaterialId};
use std::path::Path;

/// Objects that share a material through the table render the same bytes as objects that
/// each hold a copy (through the plain loop and through a BVH), with one material in the
/// table instead of one an object; the table survives `cast` and `to_dyn`.
#[test]
fn shared_materials_render_as_copies() {
    let matte = Lambertian::new(Vec3::splat(0.5)).unwrap();
    let centres: Vec<Vec3<f64>> = (0..40)
        .map(|i| Vec3::new(f64::from(i % 8) * 0.5 - 1.75, f64::from(i / 8) * 0.5 - 1.0, -4.0))
        .collect();
    let camera = ScreenCamera::new(32, 16).unwrap();
    for acceleration in [Acceleration::Linear, Acceleration::Bvh] {
        let mut copies = EnumScene::<f64>::new(Background::default());
        let mut shared = EnumScene::<f64>::new(Background::default());
        copies.set_acceleration(acceleration);
        shared.set_acceleration(acceleration);
        let id = shared.add_material(matte.clone());
        for &c in &centres {
            copies.add(Sphere::new(c, 0.2).unwrap(), matte.clone());
            shared.add_object(Sphere::new(c, 0.2).unwrap(), id);
        }
        assert_eq!((copies.materials().len(), shared.materials().len()), (40, 1));
        assert!(shared.objects().iter().all(|o| o.material == id));
        let image = |scene: &EnumScene<f64>| Renderer::new(scene, &camera).spp(2).render().unwrap().image;
        let want = image(&copies);
        assert_eq!(image(&shared), want, "{acceleration:?}");
        let dynamic = shared.to_dyn();
        assert_eq!(dynamic.materials().len(), 1);
        let got = Renderer::new(&dynamic, &camera).spp(2).render().unwrap().image;
        assert_eq!(got, want, "{acceleration:?}, trait objects");
        let single: EnumScene<f32> = shared.cast().unwrap();
        assert_eq!(single.materials().len(), 1);
    }
}

/// A scene file's objects made of one named material share its place in the table.
#[test]
fn a_named_material_is_one_entry() {
    let text = r#"
[materials.matte]
type = "lambertian"
albedo = [0.5, 0.5, 0.5]
[materials.gold]
type = "mirror"
albedo = [0.9, 0.7, 0.3]

[[objects]]
type = "sphere"
center = [0, 0, -3]
radius = 0.5
material = "matte"
[[objects]]
type = "sphere"
center = [1, 0, -3]
radius = 0.5
material = "gold"
[[objects]]
type = "sphere"
center = [-1, 0, -3]
radius = 0.5
material = "matte"
"#;
    let scene = SceneFile::parse(text, Path::new("shared.toml"))
        .unwrap()
        .build::<f64>()
        .unwrap()
        .scene;
    assert_eq!(scene.materials().len(), 2);
    let ids: Vec<MaterialId> = scene.objects().iter().map(|o| o.material).collect();
    assert_eq!(ids[0], ids[2]);
    assert_ne!(ids[0], ids[1]);
}

/// An identifier of another scene's table is refused, not read out of bounds.
#[test]
#[should_panic(expected = "is not in this scene's table of 1 materials")]
fn a_material_of_another_table_is_refused() {
    let mirror = || Mirror::new(Vec3::splat(0.5)).unwrap();
    let mut other = EnumScene::<f64>::new(Background::default());
    other.add_material(mirror());
    let id = other.add_material(mirror());
    let mut scene = EnumScene::<f64>::new(Background::default());
    scene.add_material(mirror());
    scene.add_object(Sphere::new(Vec3::zero(), 1.0).unwrap(), id);
}
