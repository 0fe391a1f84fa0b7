//! Emitting surfaces, exactly: what a ray that meets one brings back (`C = L_e + A ∘ C⁺`),
//! from which faces, and where `max_depth` stops it — past it an emitter is black, and an
//! emitter is sampled from a surface only where the ray it stands for would still count.
//! Every test runs in f32 and f64 and compares exact values (no statistics).

use rand::SeedableRng;
use raytrace::prelude::*;
use raytrace::render::Tracer;
use raytrace::scene_file::SceneFile;
use raytrace::{DefaultRng, Error};
use std::path::Path;

/// Each generic test `fn name<F: Float>()` as two tests, `name::f32` and `name::f64`.
macro_rules! float_tests {
    ($name:ident) => {
        mod $name {
            #[test]
            fn f32() {
                super::$name::<f32>();
            }
            #[test]
            fn f64() {
                super::$name::<f64>();
            }
        }
    };
}

fn v<F: Float>(x: f64, y: f64, z: f64) -> Vec3<F> {
    Vec3::from_f64(x, y, z)
}

fn black<F: Float>() -> EnumScene<F> {
    EnumScene::new(Background::solid(Vec3::zero()).unwrap())
}

/// The colour of `ray` traced with `max_depth` and `light_sampling`, seed `seed`.
fn trace<F: Float>(
    scene: &EnumScene<F>,
    ray: &Ray<F>,
    max_depth: u32,
    sampling: LightSampling,
    seed: u64,
) -> Color<F> {
    let mut rng = DefaultRng::seed_from_u64(seed);
    Tracer::new(scene, max_depth)
        .light_sampling(sampling)
        .trace(ray, 0, &mut rng)
}

const BOTH: [LightSampling; 2] = [LightSampling::Mis, LightSampling::Bsdf];

/// A ray that meets an emitter brings back its radiance, from the faces that emit.
fn emitters_seen_directly_give_their_radiance<F: Float>() {
    let l = v::<F>(1.0, 2.0, 3.0);
    let mut scene = black::<F>();
    scene.add(
        Sphere::new(v(0.0, 0.0, -4.0), lit(1.0)).unwrap(),
        Emissive::new(l).unwrap(),
    );
    let front = Ray::new(Vec3::zero(), v(0.0, 0.0, -1.0));
    let inside = Ray::new(v(0.0, 0.0, -4.0), v(0.0, 1.0, 0.0));
    for s in BOTH {
        assert_eq!(trace(&scene, &front, 1, s, 1), l, "{}", F::NAME);
        assert_eq!(
            trace(&scene, &inside, 1, s, 1),
            Vec3::zero(),
            "{}: back face",
            F::NAME
        );
    }
    let mut two_sided = black::<F>();
    two_sided.add(
        Sphere::new(v(0.0, 0.0, -4.0), lit(1.0)).unwrap(),
        Emissive::new(l).unwrap().two_sided(true),
    );
    assert_eq!(
        trace(&two_sided, &inside, 1, LightSampling::Mis, 1),
        l,
        "{}",
        F::NAME
    );
    // A triangle's front face is where A → B → C runs counter-clockwise.
    let mut panel = black::<F>();
    let t = Triangle::new(v(-1.0, -1.0, -3.0), v(1.0, -1.0, -3.0), v(0.0, 1.0, -3.0)).unwrap();
    panel.add(t, Emissive::new(l).unwrap());
    assert_eq!(trace(&panel, &front, 1, LightSampling::Mis, 1), l, "{}", F::NAME);
    let behind = Ray::new(v(0.0, 0.0, -6.0), v(0.0, 0.0, 1.0));
    assert_eq!(
        trace(&panel, &behind, 1, LightSampling::Mis, 1),
        Vec3::zero(),
        "{}",
        F::NAME
    );
}
float_tests!(emitters_seen_directly_give_their_radiance);

/// The spec's limit holds for light: an emitter met after `max_depth` bounces is black,
/// whether it is met by the camera ray, through a mirror, or sampled from a matte surface.
fn past_max_depth_an_emitter_is_black<F: Float>() {
    let l = v::<F>(4.0, 4.0, 4.0);
    let lamp = || Sphere::new(v(0.0, 3.0, -3.0), lit(1.0)).unwrap();
    let down = Ray::new(Vec3::zero(), v(0.0, -1.0, -1.0).normalize());
    // A camera ray straight at a lamp: black with no bounce allowed.
    let mut scene = black::<F>();
    scene.add(lamp(), Emissive::new(l).unwrap());
    let up = Ray::towards(Vec3::zero(), v(0.0, 3.0, -3.0)).unwrap();
    for s in BOTH {
        assert_eq!(trace(&scene, &up, 0, s, 1), Vec3::zero(), "{}", F::NAME);
        assert_eq!(trace(&scene, &up, 1, s, 1), l, "{}", F::NAME);
    }
    // Through a mirror floor: the reflected ray meets the lamp at depth 1.
    let mut mirrored = black::<F>();
    mirrored.add(lamp(), Emissive::new(l).unwrap());
    mirrored.add(
        Plane::new(v(0.0, -1.0, 0.0), v(0.0, 1.0, 0.0)).unwrap(),
        Mirror::new(v(0.5, 0.5, 0.5)).unwrap(),
    );
    let at_lamp_image = Ray::towards(Vec3::zero(), v(0.0, -5.0, -3.0)).unwrap();
    for s in BOTH {
        assert_eq!(
            trace(&mirrored, &at_lamp_image, 1, s, 1),
            Vec3::zero(),
            "{}",
            F::NAME
        );
        assert_eq!(
            trace(&mirrored, &at_lamp_image, 2, s, 1),
            l * lit::<F>(0.5),
            "{}",
            F::NAME
        );
    }
    // A matte floor lit only by the lamp: with one bounce allowed the light it would need a
    // second for is not sampled either, so every sample is black, both ways.
    let mut matte = black::<F>();
    matte.add(lamp(), Emissive::new(l).unwrap());
    matte.add(
        Plane::new(v(0.0, -1.0, 0.0), v(0.0, 1.0, 0.0)).unwrap(),
        Lambertian::new(v(0.5, 0.5, 0.5)).unwrap(),
    );
    for s in BOTH {
        for seed in 0..200 {
            assert_eq!(trace(&matte, &down, 1, s, seed), Vec3::zero(), "{}", F::NAME);
        }
        let lit_samples = (0..200)
            .filter(|&seed| trace(&matte, &down, 2, s, seed) != Vec3::zero())
            .count();
        assert!(lit_samples > 0, "{} {s:?}: two bounces see the lamp", F::NAME);
    }
    // A point light beside the lamp still lights the floor at depth 0 with max_depth 1: its
    // light is not a bounce (A/π·I·cos θ/d², exactly what it gave before emitters existed).
    matte.add_light(PointLight::new(v(0.0, 1.0, -1.0), v(2.0, 2.0, 2.0)).unwrap());
    let mut only_point = black::<F>();
    only_point.add(
        Plane::new(v(0.0, -1.0, 0.0), v(0.0, 1.0, 0.0)).unwrap(),
        Lambertian::new(v(0.5, 0.5, 0.5)).unwrap(),
    );
    only_point.add_light(PointLight::new(v(0.0, 1.0, -1.0), v(2.0, 2.0, 2.0)).unwrap());
    let want = trace(&only_point, &down, 1, LightSampling::Mis, 3);
    assert!(want.x > F::zero());
    for s in BOTH {
        assert_eq!(trace(&matte, &down, 1, s, 3), want, "{}", F::NAME);
    }
}
float_tests!(past_max_depth_an_emitter_is_black);

/// An emitting plane cannot be sampled (its area is infinite): scattered rays find it.
/// Under a plane sky of radiance `L` every upward ray meets it, so a matte floor of
/// albedo `A` returns exactly `A·L` at every sample (one bounce, no sampled light).
fn an_emitting_plane_is_found_by_scattered_rays<F: Float>() {
    let l = v::<F>(0.5, 1.0, 2.0);
    let a = v::<F>(0.25, 0.5, 0.75);
    let mut scene = black::<F>();
    scene.add(
        Plane::new(v(0.0, 10.0, 0.0), v(0.0, -1.0, 0.0)).unwrap(),
        Emissive::new(l).unwrap(),
    );
    scene.add(
        Plane::new(v(0.0, -1.0, 0.0), v(0.0, 1.0, 0.0)).unwrap(),
        Lambertian::new(a).unwrap(),
    );
    assert!(scene.emitters().is_empty());
    let down = Ray::new(Vec3::zero(), v(0.0, -1.0, -1.0).normalize());
    for seed in 0..100 {
        assert_eq!(
            trace(&scene, &down, 2, LightSampling::Mis, seed),
            a * l,
            "{}",
            F::NAME
        );
    }
}
float_tests!(an_emitting_plane_is_found_by_scattered_rays);

/// Extreme emitters stay finite: a lamp 10⁴ radii away (its cone 10⁻⁴ rad), one of
/// radiance 10³⁰ (past f32's range once multiplied out), and a black one (never sampled).
fn extreme_emitters_give_finite_pixels<F: Float>() {
    let mut scene = black::<F>();
    scene.add(
        Plane::new(v(0.0, -1.0, 0.0), v(0.0, 1.0, 0.0)).unwrap(),
        Lambertian::new(v(0.5, 0.5, 0.5)).unwrap(),
    );
    scene.add(
        Sphere::new(v(0.0, 5e3, -3.0), lit(0.5)).unwrap(),
        Emissive::new(v(1e8, 1e8, 1e8)).unwrap(),
    );
    scene.add(
        Sphere::new(v(3.0, 1.0, -4.0), lit(0.5)).unwrap(),
        Emissive::new(v(1e30, 1.0, 1.0)).unwrap(),
    );
    scene.add(
        Sphere::new(v(-3.0, 1.0, -4.0), lit(0.5)).unwrap(),
        Emissive::new(Vec3::zero()).unwrap(),
    );
    assert_eq!(scene.emitters().len(), 2);
    let camera = ScreenCamera::new(24, 12).unwrap();
    let render = Renderer::new(&scene, &camera).spp(4).render().unwrap();
    assert!(
        render
            .image
            .pixels()
            .iter()
            .flatten()
            .all(|c| c.is_finite() && *c >= 0.0)
    );
}
float_tests!(extreme_emitters_give_finite_pixels);

/// Scene files: the emissive material and its errors, located.
#[test]
fn scene_files_describe_emitters() {
    let head = "[background]\ntype = \"solid\"\ncolor = [0, 0, 0]\n";
    let object = "[[objects]]\ntype = \"sphere\"\ncenter = [0, 0, -3]\nradius = 1\nmaterial = \"lamp\"\n";
    let parse = |material: &str| {
        let text = format!("{head}[materials.lamp]\n{material}\n{object}");
        SceneFile::parse(&text, Path::new("lamp.toml")).and_then(|f| f.build::<f32>())
    };
    let built =
        parse("type = \"emissive\"\nradiance = [1, 2, 3]\ntwo_sided = true\nalbedo = [0.5, 0.5, 0.5]")
            .unwrap();
    let want = Emissive::new(v(1.0, 2.0, 3.0))
        .unwrap()
        .two_sided(true)
        .with_albedo(v(0.5, 0.5, 0.5))
        .unwrap();
    assert_eq!(built.scene.materials(), [MaterialKind::from(want)]);
    assert_eq!((built.summary.emitters, built.summary.sampled_emitters), (1, 1));
    let defaults = parse("type = \"emissive\"\nradiance = [1, 2, 3]").unwrap();
    assert_eq!(
        defaults.scene.materials(),
        [MaterialKind::from(Emissive::new(v(1.0, 2.0, 3.0)).unwrap())]
    );
    let message = |material: &str| match parse(material) {
        Err(e @ Error::SceneFile { .. }) => e.to_string(),
        other => panic!("{other:?}"),
    };
    let m = message("type = \"emissive\"\nradiance = [1, -2, 3]");
    assert!(m.contains("materials.lamp.radiance") && m.contains("≥ 0"), "{m}");
    let m = message("type = \"emissive\"\nradiance = [1e39, 1, 1]");
    assert!(m.contains("materials.lamp.radiance") && m.contains("f32"), "{m}");
    let m = message("type = \"emissive\"\nradiance = [1, 1, 1]\nalbedo = [2, 0, 0]");
    assert!(m.contains("materials.lamp.albedo"), "{m}");
    let m = message("type = \"emissive\"");
    assert!(m.contains("radiance"), "{m}");
    let m = message("type = \"emissive\"\nradiance = [1, 1, 1]\ntwo_sided = \"yes\"");
    assert!(m.contains("two_sided"), "{m}");
}
