//! Whole-render benchmarks: small renders of the example scenes in f32 and f64, one
//! traced path, and the trait-object scene against the enum scene.

#[path = "../examples/scenes/mod.rs"]
mod scenes;

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use rand::SeedableRng;
use raytrace::DefaultRng;
use raytrace::prelude::*;
use raytrace::render::Tracer;
use std::hint::black_box;
use std::sync::Arc;

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

/// The same scene as trait objects: `Box<dyn Hittable>` and `Arc<dyn Material>`.
fn as_dyn<F: Float>(scene: &EnumScene<F>) -> DynScene<F, DefaultRng> {
    let mut d = DynScene::new(*scene.background());
    for o in scene.objects() {
        let shape: Box<dyn Hittable<F> + Send + Sync> = match o.shape {
            ShapeKind::Sphere(s) => Box::new(s) as Box<dyn Hittable<F> + Send + Sync>,
            #[allow(unreachable_patterns)]
            _ => unimplemented!("only spheres in the benched scenes"),
        };
        let material: Arc<dyn Material<F, DefaultRng> + Send + Sync> = match o.material {
            MaterialKind::Mirror(m) => Arc::new(m),
            MaterialKind::Lambertian(m) => Arc::new(m),
            #[allow(unreachable_patterns)]
            _ => unimplemented!("only mirrors and matte in the benched scenes"),
        };
        d.add(shape, material);
    }
    d
}

fn dispatch<F: Float>(c: &mut Criterion) {
    let mut g = c.benchmark_group("dispatch-matte_spheres-160x80-4spp");
    g.sample_size(10);
    let cam = ScreenCamera::new(160, 80).unwrap();
    let enum_scene = scenes::matte_spheres::<F>().unwrap();
    let dyn_scene = as_dyn(&enum_scene);
    let s = RenderSettings::new(4, 10, 0).unwrap();
    g.bench_function(BenchmarkId::new(F::NAME, "enum"), |b| {
        b.iter(|| single(|| render(&enum_scene, &cam, &s).unwrap().stats.rays))
    });
    g.bench_function(BenchmarkId::new(F::NAME, "dyn"), |b| {
        b.iter(|| single(|| render(&dyn_scene, &cam, &s).unwrap().stats.rays))
    });
    g.finish();
}

fn all(c: &mut Criterion) {
    small_renders::<f32>(c);
    small_renders::<f64>(c);
    one_path::<f32>(c);
    one_path::<f64>(c);
    dispatch::<f32>(c);
    dispatch::<f64>(c);
}

criterion_group!(benches, all);
criterion_main!(benches);
