//! Micro-benchmarks: vector operations, ray–sphere (textbook vs stable, one sphere vs four
//! at once, f32 vs f64), ray–triangle, each material's sample, and the spec's rejection
//! sampler against its alternatives.

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use rand::{RngExt, SeedableRng};
use rand_distr::{Distribution, UnitSphere};
use raytrace::prelude::*;
use raytrace::sampling::{cosine_direction, lambertian_direction, unit_sphere_rejection};
use raytrace::shape::{Hit, Sphere4, Surface, hit, textbook_sphere_hit};
use raytrace::{DefaultRng, Scatter};
use std::hint::black_box;

/// 1024 seeded rays from around the origin towards a unit sphere at distance 4.
fn rays<F: Float>() -> Vec<Ray<F>> {
    let mut rng = DefaultRng::seed_from_u64(1);
    (0..1024)
        .map(|_| {
            let target = Vec3::from_f64(rng.random_range(-1.5..1.5), rng.random_range(-1.5..1.5), -4.0);
            Ray::towards(Vec3::zero(), target).unwrap()
        })
        .collect()
}

fn vec3_ops<F: Float>(c: &mut Criterion) {
    let mut g = c.benchmark_group("vec3");
    let v: Vec<Vec3<F>> = rays::<F>().iter().map(|r| r.direction).collect();
    g.bench_function(BenchmarkId::new(F::NAME, "dot+cross+normalize"), |b| {
        b.iter(|| {
            let mut acc = Vec3::zero();
            for w in v.windows(2) {
                acc = acc + w[0].cross(w[1]).normalize() * w[0].dot(w[1]);
            }
            black_box(acc)
        })
    });
    g.finish();
}

fn sphere<F: Float>(c: &mut Criterion) {
    let mut g = c.benchmark_group("ray-sphere");
    let s = Sphere::new(Vec3::from_f64(0.0, 0.0, -4.0), lit(1.0)).unwrap();
    let rays = rays::<F>();
    g.bench_function(BenchmarkId::new(F::NAME, "stable"), |b| {
        b.iter(|| {
            rays.iter()
                .filter(|r| hit(&s, black_box(r), F::infinity()).is_some())
                .count()
        })
    });
    g.bench_function(BenchmarkId::new(F::NAME, "textbook"), |b| {
        b.iter(|| {
            rays.iter()
                .filter(|r| textbook_sphere_hit(&s, black_box(r), lit(1e-3), F::infinity()).is_some())
                .count()
        })
    });
    // Four spheres per ray: one at a time (full hit records) against one packet.
    let four: Vec<Sphere<F>> = (0..4)
        .map(|i| Sphere::new(Vec3::from_f64(f64::from(i) - 1.5, 0.0, -4.0), lit(0.6)).unwrap())
        .collect();
    let packet = Sphere4::new(four.iter().copied());
    g.bench_function(BenchmarkId::new(F::NAME, "4-spheres-one-by-one"), |b| {
        b.iter(|| {
            rays.iter()
                .filter(|r| four.iter().any(|s| hit(s, black_box(r), F::infinity()).is_some()))
                .count()
        })
    });
    g.bench_function(BenchmarkId::new(F::NAME, "4-spheres-packet"), |b| {
        b.iter(|| {
            rays.iter()
                .filter(|r| packet.any(black_box(r), F::infinity()))
                .count()
        })
    });
    g.finish();
}

fn triangle<F: Float>(c: &mut Criterion) {
    let mut g = c.benchmark_group("ray-triangle");
    let p = |x, y, z| Vec3::from_f64(x, y, z);
    let t = Triangle::new(p(-1.5, -1.0, -4.0), p(1.5, -1.0, -4.0), p(0.0, 1.5, -4.0)).unwrap();
    let rays = rays::<F>();
    g.bench_function(BenchmarkId::new(F::NAME, "watertight"), |b| {
        b.iter(|| {
            rays.iter()
                .filter(|r| hit(&t, black_box(r), F::infinity()).is_some())
                .count()
        })
    });
    g.finish();
}

fn scatter<F: Float>(c: &mut Criterion) {
    let mut g = c.benchmark_group("scatter");
    let ray = Ray::new(Vec3::zero(), Vec3::from_f64(0.0, -0.6, -0.8));
    let n = Vec3::from_f64(0.0, 1.0, 0.0);
    let at = Hit::new(Surface::bare(lit(2.0), ray.at(lit(2.0)), n), ray.direction);
    let mut rng = DefaultRng::seed_from_u64(2);
    let materials: [(&str, MaterialKind<F>); 3] = [
        ("mirror", Mirror::new(Vec3::splat(lit(0.9))).unwrap().into()),
        (
            "lambertian",
            Lambertian::new(Vec3::splat(lit(0.5))).unwrap().into(),
        ),
        ("dielectric", Dielectric::new(lit(1.5)).unwrap().into()),
    ];
    for (name, m) in materials {
        g.bench_function(BenchmarkId::new(F::NAME, name), |b| {
            b.iter(|| Scatter::<F, DefaultRng>::sample(&m, &at, black_box(-ray.direction), &mut rng))
        });
    }
    g.finish();
}

fn samplers(c: &mut Criterion) {
    let mut g = c.benchmark_group("unit-sphere-sampler");
    let mut rng = DefaultRng::seed_from_u64(3);
    g.bench_function("spec-cube-rejection", |b| {
        b.iter(|| unit_sphere_rejection(&mut rng))
    });
    g.bench_function("rand_distr-UnitSphere", |b| {
        b.iter(|| -> [f64; 3] { UnitSphere.sample(&mut rng) })
    });
    let n = Vec3::new(0.0f64, 1.0, 0.0);
    g.bench_function("lambertian-spec-tangent-sphere", |b| {
        b.iter(|| lambertian_direction(black_box(n), &mut rng))
    });
    g.bench_function("lambertian-closed-form", |b| {
        b.iter(|| cosine_direction(black_box(n), &mut rng))
    });
    g.finish();
}

fn all(c: &mut Criterion) {
    vec3_ops::<f32>(c);
    vec3_ops::<f64>(c);
    sphere::<f32>(c);
    sphere::<f64>(c);
    triangle::<f32>(c);
    triangle::<f64>(c);
    scatter::<f32>(c);
    scatter::<f64>(c);
    samplers(c);
}

criterion_group!(benches, all);
criterion_main!(benches);
