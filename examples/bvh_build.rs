//! Builds a BVH over the boxes of many random spheres (or of a mesh's triangles) and prints
//! how long the build took and the tree's size and SAH cost: a driver for profiling the
//! build (`valgrind --tool=callgrind`) and for comparing trees.
//!
//! `cargo run --release --features studies --example bvh_build -- --spheres 100000 --threads 2`
//! `cargo run --release --features studies --example bvh_build -- --mesh assets/meshes/dragon_vrip.ply`

use clap::Parser;
use rand::{RngExt, SeedableRng};
use rayon::prelude::*;
use raytrace::DefaultRng;
use raytrace::aabb::Aabb;
use raytrace::bvh::Bvh;
use raytrace::vec3::Vec3;
use std::hash::{Hash, Hasher};
use std::path::PathBuf;
use std::time::Instant;

/// Builds one BVH and reports on it.
#[derive(Parser)]
struct Args {
    /// Random spheres in a cube of side 100, radii 0.05 to 1 (ignored with `--mesh`).
    #[arg(long, default_value_t = 100_000)]
    spheres: usize,
    /// Build over this mesh's triangles instead (`.obj` or `.ply`).
    #[arg(long)]
    mesh: Option<PathBuf>,
    /// Threads of the rayon pool the build runs in.
    #[arg(long, default_value_t = 1)]
    threads: usize,
    /// With spatial splits (`Bvh::build_split`): the mesh's triangles may be cut.
    #[arg(long)]
    split: bool,
    /// Also print a hash of the whole tree, to compare builds on different pools.
    #[arg(long)]
    fingerprint: bool,
    /// Seed of the sphere positions.
    #[arg(long, default_value_t = 1)]
    seed: u64,
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args = Args::parse();
    let mut triangles: Vec<[Vec3<f32>; 3]> = Vec::new();
    let boxes: Vec<Aabb<f32>> = match &args.mesh {
        Some(path) => {
            let mesh = raytrace::mesh::load(path)?;
            let p = |i: u32| {
                let v = mesh.positions[i as usize];
                Vec3::new(v.x as f32, v.y as f32, v.z as f32)
            };
            triangles = mesh.triangles.iter().map(|t| t.map(p)).collect();
            triangles
                .iter()
                .map(|t| Aabb::new(t[0], t[1]).union(Aabb::new(t[2], t[2])))
                .collect()
        }
        None => {
            let mut rng = DefaultRng::seed_from_u64(args.seed);
            (0..args.spheres)
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
    };
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(args.threads)
        .build()?;
    let start = Instant::now();
    let bvh = pool.install(|| match args.split {
        false => Bvh::build_classes(boxes.par_iter().map(|&b| (b, 0))),
        true => Bvh::build_split(boxes.par_iter().map(|&b| (b, 0)), |i| {
            triangles.get(i as usize).copied()
        }),
    });
    let references: usize = (0..bvh.leaf_count()).map(|k| bvh.leaf(k).len()).sum();
    let seconds = start.elapsed().as_secs_f64();
    print!(
        "{} boxes, {} references, {} threads: {seconds:.4} s, {} nodes, {} leaves, SAH cost {:.4}",
        boxes.len(),
        references,
        args.threads,
        bvh.node_count(),
        bvh.leaf_count(),
        bvh.sah_cost(),
    );
    if args.fingerprint {
        let mut hasher = std::collections::hash_map::DefaultHasher::new();
        format!("{bvh:?}").hash(&mut hasher);
        print!(", tree {:016x}", hasher.finish());
    }
    println!();
    Ok(())
}
