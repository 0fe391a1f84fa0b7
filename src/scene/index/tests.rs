//! The batch index against one-ray queries and the plain loop.

use super::*;
use crate::shape::{ShapeKind, Triangle};
use crate::vec3::Vec3;

/// `n` unit-spaced small spheres in a row, and a triangle after them if asked.
fn objects(n: usize, triangle: bool) -> Vec<Object<ShapeKind<f32>, ()>> {
    let mut objects: Vec<_> = (0..n)
        .map(|i| Object {
            shape: Sphere::new(Vec3::new(i as f32, 0.0, -5.0), 0.3).unwrap().into(),
            material: (),
        })
        .collect();
    if triangle {
        let v = |x: f32, y: f32| Vec3::new(x, y, -6.0);
        objects.push(Object {
            shape: Triangle::new(v(0.0, 0.0), v(1.0, 0.0), v(0.0, 1.0))
                .unwrap()
                .into(),
            material: (),
        });
    }
    objects
}

/// With spheres alone each leaf is one packet, lone spheres included (no singles in the
/// tree); with another shape in the tree the leaves are groups.
#[test]
fn leaves_are_packets_only_when_the_tree_holds_spheres_alone() {
    let index = Index::build(&objects(37, false), Acceleration::Bvh);
    let bvh = index.bvh.as_ref().unwrap();
    assert!(matches!(index.leaves, Leaves::Packets));
    assert_eq!(index.in_tree.packets.len(), bvh.leaf_count());
    assert!(index.in_tree.singles.is_empty() && index.in_tree.others.is_empty());
    let index = Index::build(&objects(37, true), Acceleration::Bvh);
    let Leaves::Groups(groups) = &index.leaves else {
        panic!("a triangle in the tree needs groups");
    };
    assert_eq!(groups.len(), index.bvh.as_ref().unwrap().leaf_count());
    assert_eq!(index.in_tree.others.len(), 1);
}

/// Spheres of random sizes (each added twice, so that exact ties happen), triangles and
/// a plane, through the plain loop and through a BVH.
fn mixed(seed: u64, triangles: bool) -> Vec<Object<ShapeKind<f64>, u32>> {
    use crate::shape::Plane;
    use rand::{RngExt, SeedableRng};
    let mut rng = crate::sampling::DefaultRng::seed_from_u64(seed);
    let mut v = |s: f64| {
        Vec3::new(
            rng.random_range(-s..s),
            rng.random_range(-s..s),
            rng.random_range(-s..s),
        )
    };
    let mut shapes: Vec<ShapeKind<f64>> = Vec::new();
    for i in 0..120 {
        let c = v(5.0);
        if triangles && i % 3 == 0 {
            shapes.push(Triangle::new(c + v(0.8), c + v(0.8), c + v(0.8)).unwrap().into());
        } else {
            let s: ShapeKind<f64> = Sphere::new(c, 0.05 + v(0.4).x.abs()).unwrap().into();
            shapes.push(s);
            shapes.push(s);
        }
    }
    shapes.push(
        Plane::new(Vec3::new(0.0, -6.0, 0.0), Vec3::new(0.0, 1.0, 0.0))
            .unwrap()
            .into(),
    );
    shapes.push(Sphere::new(Vec3::new(0.0, -1005.0, 0.0), 1000.0).unwrap().into());
    shapes
        .into_iter()
        .enumerate()
        .map(|(i, shape)| Object {
            shape,
            material: i as u32,
        })
        .collect()
}

/// The batch answers exactly as one ray at a time: the same record and object, for
/// rays from outside, from inside and from the surfaces, ties included. (It finds a
/// mismatch if a batch loop skips an object, tests a packet with the wrong ray, or
/// breaks ties the other way.)
#[test]
fn a_batch_answers_like_single_rays() {
    use rand::{RngExt, SeedableRng};
    for (seed, triangles, acceleration) in [
        (1, false, Acceleration::Linear),
        (2, true, Acceleration::Linear),
        (3, false, Acceleration::Bvh),
        (4, true, Acceleration::Bvh),
    ] {
        let objects = mixed(seed, triangles);
        let index = Index::build(&objects, acceleration);
        let mut rng = crate::sampling::DefaultRng::seed_from_u64(seed + 10);
        let mut v = |s: f64| {
            Vec3::new(
                rng.random_range(-s..s),
                rng.random_range(-s..s),
                rng.random_range(-s..s),
            )
        };
        let mut rays: Vec<Ray<f64>> = (0..3000).filter_map(|_| Ray::towards(v(9.0), v(5.0))).collect();
        // Rays leaving the surfaces the first rays hit, as secondary rays do.
        let firsts: Vec<_> = rays
            .iter()
            .filter_map(|r| index.hit(&objects, r, f64::INFINITY))
            .collect();
        rays.extend(firsts.iter().filter_map(|(h, _)| {
            let d = (h.normal + v(1.0)).try_normalize()?;
            Some(h.spawn(d))
        }));
        let (mut near, mut out) = (Nearests::default(), Vec::new());
        index.hit_all(&objects, &rays, &mut near, |i, hit| {
            assert_eq!(i, out.len(), "in the rays' order");
            out.push(hit);
        });
        assert_eq!(out.len(), rays.len());
        let mut hits = 0;
        for (ray, got) in rays.iter().zip(&out) {
            let want = index
                .hit(&objects, ray, f64::INFINITY)
                .map(|(h, o)| (h, o.material));
            assert_eq!(got.map(|(h, &m)| (h, m)), want, "{ray:?}");
            hits += usize::from(want.is_some());
        }
        assert!(hits > rays.len() / 2, "most rays should hit something ({hits})");
    }
}
