//! The test scene (mirror, matte, ground) on both dispatch paths, and shared render helpers.

use raytrace::prelude::*;
use raytrace::{Image, SharedMaterial};
use std::sync::Arc;

/// The materials of the test scene, kept concrete so each path can wrap them its own way.
pub(crate) enum Part<F> {
    Mirror(Mirror<F>),
    Matte(Lambertian<F>),
}

/// A small scene with every core material: mirror, matte, and a matte ground.
pub(crate) fn parts<F: Float>() -> Vec<(Sphere<F>, Part<F>)> {
    let s = |x, y, z, r| Sphere::new(Vec3::from_f64(x, y, z), lit(r)).unwrap();
    vec![
        (
            s(-1.2, 0.0, -3.0, 0.8),
            Part::Mirror(Mirror::new(Vec3::from_f64(0.9, 0.7, 0.4)).unwrap()),
        ),
        (
            s(1.0, 0.0, -3.5, 0.8),
            Part::Matte(Lambertian::new(Vec3::from_f64(0.3, 0.5, 0.8)).unwrap()),
        ),
        (
            s(0.0, -100.8, -3.0, 100.0),
            Part::Matte(Lambertian::new(Vec3::from_f64(0.5, 0.5, 0.5)).unwrap()),
        ),
    ]
}

/// The fast path: enums stored inline.
pub(crate) fn enum_scene<F: Float>() -> EnumScene<F> {
    let mut scene = EnumScene::new(Background::default());
    for (shape, part) in parts::<F>() {
        let material: MaterialKind<F> = match part {
            Part::Mirror(m) => m.into(),
            Part::Matte(m) => m.into(),
        };
        scene.add(shape, material);
    }
    scene
}

/// The spec's path: a vector of smart pointers to trait objects.
pub(crate) fn dyn_scene<F: Float>() -> DynScene<F> {
    let mut scene = DynScene::new(Background::default());
    for (shape, part) in parts::<F>() {
        let material: SharedMaterial<F> = match part {
            Part::Mirror(m) => Arc::new(m).into(),
            Part::Matte(m) => Arc::new(m).into(),
        };
        scene.add(Box::new(shape), material);
    }
    scene
}

pub(crate) fn bytes(image: &Image) -> Vec<u8> {
    let mut out = Vec::new();
    raytrace::image::write_ppm_to(&mut out, &image.to_u16(Encoding::Srgb)).unwrap();
    out
}

pub(crate) fn settings(spp: u32, seed: u64) -> RenderSettings {
    RenderSettings::new(spp, 10, seed).unwrap()
}

pub(crate) fn in_pool<T: Send>(threads: usize, f: impl FnOnce() -> T + Send) -> T {
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .unwrap()
        .install(f)
}
