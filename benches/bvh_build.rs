//! The BVH build over the boxes of 10⁴, 10⁵ and 10⁶ random spheres, on one and on two
//! threads (the build gives the same tree on both).

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use rand::{RngExt, SeedableRng};
use raytrace::DefaultRng;
use raytrace::aabb::Aabb;
use raytrace::bvh::Bvh;
use raytrace::vec3::Vec3;
use std::hint::black_box;

/// Boxes of `n` seeded random spheres in a cube of side 100, radii 0.05 to 1.
fn sphere_boxes(n: usize) -> Vec<Aabb<f32>> {
    let mut rng = DefaultRng::seed_from_u64(1);
    (0..n)
        .map(|_| {
            let c = Vec3::new(
                rng.random_range(-50.0..50.0f32),
                rng.random_range(-50.0..50.0),
                rng.random_range(-50.0..50.0),
            );
            let r = Vec3::splat(rng.random_range(0.05..1.0f32));
            Aabb::new(c - r, c + r)
        })
        .collect()
}

fn build(c: &mut Criterion) {
    let mut g = c.benchmark_group("bvh-build");
    g.sample_size(10);
    for n in [10_000, 100_000, 1_000_000] {
        let boxes = sphere_boxes(n);
        for threads in [1, 2] {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap();
            let id = BenchmarkId::new(format!("f32/spheres/{threads}-thread"), n);
            g.bench_function(id, |b| {
                b.iter(|| pool.install(|| Bvh::build(black_box(&boxes).iter().copied()).node_count()))
            });
        }
    }
    g.finish();
}

criterion_group!(benches, build);
criterion_main!(benches);
