//! A scene cast between scalars.

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
