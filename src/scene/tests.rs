//! The scene's own bookkeeping: casting between scalars and the table of materials.

use super::*;
use crate::light::PointLight;
use crate::material::{Dielectric, Mirror};
use crate::shape::{Sphere, Triangle};
use crate::vec3::Vec3;

#[test]
fn cast_round_trip_and_rounding_failures() {
    let mut scene = EnumScene::<f64>::new(Background::default());
    scene.add(
        Sphere::new(Vec3::new(0.1, 0.2, -3.0), 0.5).unwrap(),
        Mirror::new(Vec3::splat(0.5)).unwrap(),
    );
    scene.add(
        Triangle::new(Vec3::zero(), Vec3::new(1.0, 0.0, 0.0), Vec3::new(0.0, 1.0, 0.0)).unwrap(),
        Dielectric::new(1.5).unwrap(),
    );
    scene.add_light(PointLight::new(Vec3::new(0.0, 5.0, 0.0), Vec3::splat(3.0)).unwrap());
    let single: EnumScene<f32> = scene.cast().unwrap();
    let back: EnumScene<f64> = single.cast().unwrap();
    assert_eq!(back.objects().len(), 2);
    assert_eq!(back.lights().len(), 1);
    let ShapeKind::Sphere(s) = back.objects()[0].shape else {
        panic!()
    };
    assert_eq!(s.radius(), 0.5);
    assert_eq!(s.center().x, f64::from(0.1f32));

    let mut tiny = EnumScene::<f64>::new(Background::default());
    tiny.add(
        Sphere::new(Vec3::zero(), 1e-50).unwrap(),
        Mirror::new(Vec3::splat(0.5)).unwrap(),
    );
    assert!(
        tiny.cast::<f32>().is_err(),
        "a radius that underflows in f32 is an error"
    );
}

/// Objects that share a material through the table render the same bytes as objects that
/// each hold a copy, with one material in the table instead of one an object; the table's
/// identifiers survive `cast` and `to_dyn`.
#[test]
fn shared_materials_render_as_copies() {
    use crate::camera::ScreenCamera;
    use crate::material::Lambertian;
    use crate::render::Renderer;
    let matte = Lambertian::new(Vec3::splat(0.5)).unwrap();
    let centres = [-1.0, 0.0, 1.0].map(|x| Vec3::new(x, 0.0, -3.0));
    let mut copies = EnumScene::<f64>::new(Background::default());
    let mut shared = EnumScene::<f64>::new(Background::default());
    let id = shared.add_material(matte.clone());
    for c in centres {
        copies.add(Sphere::new(c, 0.4).unwrap(), matte.clone());
        shared.add_object(Sphere::new(c, 0.4).unwrap(), id);
    }
    assert_eq!((copies.materials().len(), shared.materials().len()), (3, 1));
    assert!(shared.objects().iter().all(|o| o.material == id));
    let camera = ScreenCamera::new(24, 12).unwrap();
    let image = |scene: &EnumScene<f64>| Renderer::new(scene, &camera).spp(2).render().unwrap().image;
    let want = image(&copies);
    assert_eq!(image(&shared), want);
    let single: EnumScene<f32> = shared.cast().unwrap();
    assert_eq!(single.materials().len(), 1);
    assert_eq!(shared.to_dyn().materials().len(), 1);
}

/// An identifier of another scene's table is refused, not read out of bounds.
#[test]
#[should_panic(expected = "is not in this scene's table of 1 materials")]
fn a_material_of_another_table_is_refused() {
    let mut other = EnumScene::<f64>::new(Background::default());
    other.add_material(Mirror::new(Vec3::splat(0.5)).unwrap());
    let id = other.add_material(Mirror::new(Vec3::splat(0.5)).unwrap());
    let mut scene = EnumScene::<f64>::new(Background::default());
    scene.add_material(Mirror::new(Vec3::splat(0.5)).unwrap());
    scene.add_object(Sphere::new(Vec3::zero(), 1.0).unwrap(), id);
}
