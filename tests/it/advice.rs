//! The precision advice is measured: f32 is advised where its image matches the
//! double-double reference, f64 where f32 visibly fails (a scene far from the origin).

use raytrace::LookAtCamera;
use raytrace::advice::{Precision, Reason, advise};
use raytrace::prelude::*;

/// Mirror spheres on a mirror floor, everything moved by `offset` along each axis.
fn mirrors(offset: f64) -> EnumScene<f64> {
    let mut scene = EnumScene::new(Background::default());
    let at = |x: f64, y: f64, z: f64| Vec3::new(x + offset, y + offset, z + offset);
    scene.add(
        Sphere::new(at(-1.0, 0.0, -4.0), 0.8).unwrap(),
        Mirror::new(Vec3::new(0.9, 0.7, 0.4)).unwrap(),
    );
    scene.add(
        Sphere::new(at(1.0, 0.0, -4.0), 0.8).unwrap(),
        Mirror::new(Vec3::new(0.4, 0.7, 0.9)).unwrap(),
    );
    scene.add(
        Sphere::new(at(0.0, -100.8, -4.0), 100.0).unwrap(),
        Mirror::new(Vec3::splat(0.5)).unwrap(),
    );
    scene
}

#[test]
fn f32_is_advised_near_the_origin() {
    let camera = ScreenCamera::new(64, 32).unwrap();
    let advice = advise(&mirrors(0.0), &camera, &RenderSettings::default()).unwrap();
    assert_eq!(advice.recommended, Precision::F32, "{advice:?}");
    assert!(
        advice.f64.error.within_one_step() && advice.f32.expect("rendered in f32").error.within_one_step(),
        "{advice:?}"
    );
}

#[test]
fn f64_is_advised_far_from_the_origin() {
    let offset = 1e5;
    let camera = ScreenCamera::new(64, 32)
        .unwrap()
        .translated([offset; 3])
        .unwrap();
    let advice = advise(&mirrors(offset), &camera, &RenderSettings::default()).unwrap();
    assert_eq!(advice.recommended, Precision::F64, "{advice:?}");
    assert!(advice.f64.error.within_one_step(), "{advice:?}");
    // The look-at camera takes the same path.
    let look = LookAtCamera::new(
        Vec3::splat(offset),
        Vec3::new(offset, offset, offset - 4.0),
        Vec3::new(0.0, 1.0, 0.0),
        60.0,
        48,
        24,
    )
    .unwrap();
    assert_eq!(
        advise(&mirrors(offset), &look, &RenderSettings::default())
            .unwrap()
            .recommended,
        Precision::F64
    );
}

#[test]
fn f64_is_advised_when_only_f64_holds_the_scene() {
    let mut scene = mirrors(0.0);
    scene.add(
        Sphere::new(Vec3::new(0.0, 0.0, -2.0), 1e-60).unwrap(),
        Mirror::new(Vec3::splat(0.5)).unwrap(),
    );
    let camera = ScreenCamera::new(16, 8).unwrap();
    let advice = advise(&scene, &camera, &RenderSettings::default()).expect("advice, not an error");
    assert_eq!(advice.recommended, Precision::F64, "{advice:?}");
    assert_eq!(advice.f32, None);
    let Reason::F32CannotHold(why) = &advice.reason else {
        panic!("{advice:?}")
    };
    assert!(why.contains("sphere radius"), "{why}");
}
