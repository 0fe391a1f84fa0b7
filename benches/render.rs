//! Whole-render benchmarks: small renders of the example scenes in f32 and f64, one
//! traced path, and the trait-object scene against the enum scene.

#[path = "../examples/scenes/mod.rs"]
mod scenes;

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use rand::SeedableRng;
use raytrace::prelude::*;
use raytrace::render::Tracer;
use raytrace::{Acceleration, DefaultRng};
use std::hint::black_box;

/// One thread, so the numbers compare code, not scheduling.
fn single<T: Send>(f: impl FnOnce() -> T + Send) -> T {
    rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .unwrap()
        .install(f)
}

fn small_renders<F: Float>(c: &mut Criterion) {
    let mut g = c.benchmark_group("render-160x80");
    g.sample_size(10);
    let cam = ScreenCamera::new(160, 80).unwrap();
    let mirrors = scenes::four_mirrors::<F>().unwrap();
    let matte = scenes::matte_spheres::<F>().unwrap();
    let s1 = RenderSettings::new(1, 10, 0).unwrap();
    let s10 = RenderSettings::new(10, 10, 0).unwrap();
    g.bench_function(BenchmarkId::new(F::NAME, "four_mirrors/1spp"), |b| {
        b.iter(|| single(|| render(&mirrors, &cam, &s1).unwrap().stats.rays))
    });
    g.bench_function(BenchmarkId::new(F::NAME, "matte_spheres/10spp"), |b| {
        b.iter(|| single(|| render(&matte, &cam, &s10).unwrap().stats.rays))
    });
    g.finish();
    // The book's final scene through its BVH, at depth 50 as in the example.
    let mut g = c.benchmark_group("render-160x90");
    g.sample_size(10);
    let look = scenes::random_spheres_camera::<F>(160).unwrap();
    let random = scenes::random_spheres::<F>(0).unwrap();
    let s4 = RenderSettings::new(4, 50, 0).unwrap();
    g.bench_function(BenchmarkId::new(F::NAME, "random_spheres/4spp"), |b| {
        b.iter(|| single(|| render(&random, &look, &s4).unwrap().stats.rays))
    });
    g.finish();
}

fn one_path<F: Float>(c: &mut Criterion) {
    let mut g = c.benchmark_group("trace-one-path");
    let scene = scenes::matte_spheres::<F>().unwrap();
    let ray = Ray::towards(Vec3::zero(), Vec3::from_f64(0.3, -0.4, -1.0)).unwrap();
    let mut rng = DefaultRng::seed_from_u64(5);
    g.bench_function(BenchmarkId::new(F::NAME, "matte_spheres"), |b| {
        b.iter(|| Tracer::new(&scene, 10).trace(black_box(&ray), 0, &mut rng))
    });
    g.finish();
}

/// The same scenes through both dispatch paths, one thread: the enum fast path against
/// boxed trait objects (the spec's vector of smart pointers).
fn dispatch<F: Float>(c: &mut Criterion) {
    let mut g = c.benchmark_group("dispatch");
    g.sample_size(10);
    let s4 = RenderSettings::new(4, 10, 0).unwrap();
    let spec = ScreenCamera::new(160, 80).unwrap();
    let matte = scenes::matte_spheres::<F>().unwrap();
    let matte_dyn: DynScene<F> = matte.to_dyn();
    g.bench_function(
        BenchmarkId::new(format!("{}/enum", F::NAME), "matte_spheres-160x80-4spp"),
        |b| b.iter(|| single(|| render(&matte, &spec, &s4).unwrap().stats.rays)),
    );
    g.bench_function(
        BenchmarkId::new(format!("{}/dyn", F::NAME), "matte_spheres-160x80-4spp"),
        |b| b.iter(|| single(|| render(&matte_dyn, &spec, &s4).unwrap().stats.rays)),
    );
    let look = scenes::random_spheres_camera::<F>(160).unwrap();
    let random = scenes::random_spheres::<F>(0).unwrap();
    let random_dyn: DynScene<F> = random.to_dyn();
    let s2 = RenderSettings::new(2, 50, 0).unwrap();
    g.bench_function(
        BenchmarkId::new(format!("{}/enum", F::NAME), "random_spheres-160x90-2spp"),
        |b| b.iter(|| single(|| render(&random, &look, &s2).unwrap().stats.rays)),
    );
    g.bench_function(
        BenchmarkId::new(format!("{}/dyn", F::NAME), "random_spheres-160x90-2spp"),
        |b| b.iter(|| single(|| render(&random_dyn, &look, &s2).unwrap().stats.rays)),
    );
    g.finish();
}

/// `n` random small spheres (matte and mirror) in front of the spec's camera.
fn spheres(n: usize) -> EnumScene<f32> {
    use rand::RngExt;
    let mut rng = DefaultRng::seed_from_u64(n as u64);
    let mut scene = EnumScene::new(Background::default());
    for i in 0..n {
        let c = Vec3::new(
            rng.random_range(-3.0..3.0),
            rng.random_range(-1.5..1.5),
            rng.random_range(-8.0..-3.0),
        );
        let m: MaterialKind<f32> = if i % 2 == 0 {
            Lambertian::new(Vec3::new(0.7, 0.5, 0.3)).unwrap().into()
        } else {
            Mirror::new(Vec3::splat(0.8)).unwrap().into()
        };
        scene.add(Sphere::new(c, rng.random_range(0.1..0.6)).unwrap(), m);
    }
    scene
}

/// Where the BVH starts to pay: the same scene of `n` spheres, plain loop against BVH.
fn bvh_threshold(c: &mut Criterion) {
    let mut g = c.benchmark_group("bvh-threshold-160x80-2spp");
    g.sample_size(10);
    let cam = ScreenCamera::new(160, 80).unwrap();
    let s = RenderSettings::new(2, 10, 0).unwrap();
    for n in [1, 2, 4, 6, 8, 12, 16, 20, 24, 32, 64] {
        for (name, acc) in [("loop", Acceleration::Linear), ("bvh", Acceleration::Bvh)] {
            let mut scene = spheres(n);
            scene.set_acceleration(acc);
            g.bench_function(BenchmarkId::new(name, n), |b| {
                b.iter(|| single(|| render(&scene, &cam, &s).unwrap().stats.rays))
            });
        }
    }
    g.finish();
    let mut g = c.benchmark_group("bvh-or-loop-spec-scenes-160x80-2spp");
    g.sample_size(10);
    for (name, scene) in [
        ("four_mirrors", scenes::four_mirrors::<f32>().unwrap()),
        ("matte_spheres", scenes::matte_spheres::<f32>().unwrap()),
    ] {
        for (how, acc) in [("loop", Acceleration::Linear), ("bvh", Acceleration::Bvh)] {
            let mut scene = scene.clone();
            scene.set_acceleration(acc);
            g.bench_function(BenchmarkId::new(how, name), |b| {
                b.iter(|| single(|| render(&scene, &cam, &s).unwrap().stats.rays))
            });
        }
    }
    g.finish();
}

fn all(c: &mut Criterion) {
    bvh_threshold(c);
    small_renders::<f32>(c);
    small_renders::<f64>(c);
    one_path::<f32>(c);
    one_path::<f64>(c);
    dispatch::<f32>(c);
    dispatch::<f64>(c);
}

criterion_group!(benches, all);
criterion_main!(benches);
