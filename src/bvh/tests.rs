//! The BVH's tests: builds, traversals and the leaves they reach against brute force.

use super::*;
use rand::{RngExt, SeedableRng};

/// The primitives whose boxes `ray` meets, found through the BVH's leaves and by brute
/// force, each sorted.
fn through_bvh_and_brute_force<F: Float>(
    bvh: &Bvh<F>,
    boxes: &[Aabb<F>],
    ray: &Ray<F>,
) -> (Vec<usize>, Vec<usize>) {
    let meets = |i: usize| boxes[i].hit(ray, F::infinity());
    let mut got = Vec::new();
    bvh.traverse(ray, F::infinity(), |k, _| {
        got.extend(bvh.leaf(k).iter().map(|&i| i as usize).filter(|&i| meets(i)));
        None
    });
    got.sort();
    (got, (0..boxes.len()).filter(|&i| meets(i)).collect())
}

/// Random little boxes; every ray's BVH answer must equal brute force.
#[test]
fn matches_brute_force() {
    let mut rng = rand::rngs::Xoshiro256PlusPlus::seed_from_u64(1);
    let boxes: Vec<Aabb<f64>> = (0..300)
        .map(|_| {
            let c = Vec3::new(
                rng.random_range(-10.0..10.0),
                rng.random_range(-10.0..10.0),
                rng.random_range(-10.0..10.0),
            );
            Aabb::new(c - Vec3::splat(0.3), c + Vec3::splat(rng.random_range(0.01..0.6)))
        })
        .collect();
    let bvh = Bvh::build(boxes.iter().copied());
    assert!(bvh.node_count() < 2 * boxes.len());
    for _ in 0..2000 {
        let o = Vec3::new(
            rng.random_range(-15.0..15.0),
            rng.random_range(-15.0..15.0),
            rng.random_range(-15.0..15.0),
        );
        let Some(d) = Vec3::new(
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
        )
        .try_normalize() else {
            continue;
        };
        let ray = Ray::new(o, d);
        let (got, want) = through_bvh_and_brute_force(&bvh, &boxes, &ray);
        assert_eq!(got, want);
        let any_box = |k: usize| {
            bvh.leaf(k)
                .iter()
                .any(|&i| boxes[i as usize].hit(&ray, f64::INFINITY))
        };
        assert_eq!(bvh.any(&ray, f64::INFINITY, any_box), !want.is_empty());
    }
}

/// Axis-aligned rays (zero direction components, infinite reciprocals) along the
/// faces and edges of boxes: the wide traversal must agree with the single-box test.
#[test]
fn axis_aligned_rays_on_faces() {
    let boxes: Vec<Aabb<f32>> = (0..40)
        .map(|i| {
            let c = Vec3::new((i % 5) as f32, ((i / 5) % 4) as f32, -((i / 20) as f32) - 3.0);
            Aabb::new(c, c + Vec3::splat(0.5))
        })
        .collect();
    let bvh = Bvh::build(boxes.iter().copied());
    for x in [0.0f32, 0.25, 0.5, 1.0, 2.5] {
        for y in [0.0f32, 0.5, 1.0, 3.5] {
            for d in [
                Vec3::new(0.0, 0.0, -1.0),
                Vec3::new(0.0, 0.0, 1.0),
                Vec3::new(1.0, 0.0, 0.0),
            ] {
                let ray = Ray::new(Vec3::new(x, y, if d.z > 0.0 { -10.0 } else { 1.0 }), d);
                let (got, want) = through_bvh_and_brute_force(&bvh, &boxes, &ray);
                assert_eq!(got, want, "{ray:?}");
            }
        }
    }
}

/// Random boxes: `n` little ones in a cube of side 100.
fn random_boxes(n: usize, seed: u64) -> Vec<Aabb<f32>> {
    let mut rng = rand::rngs::Xoshiro256PlusPlus::seed_from_u64(seed);
    (0..n)
        .map(|_| {
            let c = Vec3::new(
                rng.random_range(-50.0..50.0),
                rng.random_range(-50.0..50.0),
                rng.random_range(-50.0..50.0),
            );
            Aabb::new(c, c + Vec3::splat(rng.random_range(0.1..2.0)))
        })
        .collect()
}

/// Pools of one, two and three threads build the same tree, bit for bit (the node
/// arrays, leaves, primitive order and the wide tree). 100 000 boxes, so the top
/// nodes bin in chunks and the subtrees are built as separate tasks.
#[test]
fn same_tree_on_any_number_of_threads() {
    let boxes = random_boxes(100_000, 7);
    let on = |threads: usize| {
        let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build();
        pool.expect("a thread pool")
            .install(|| Bvh::build(boxes.iter().copied()))
    };
    let one = on(1);
    for threads in [2, 3] {
        let other = on(threads);
        assert_eq!(one.node_count, other.node_count, "nodes on {threads} threads");
        assert_eq!(one.leaves, other.leaves, "leaves on {threads} threads");
        assert_eq!(one.indices, other.indices, "primitives on {threads} threads");
        assert_eq!(format!("{one:?}"), format!("{other:?}"), "{threads} threads");
    }
}

/// No leaf mixes classes, even where boxes of both classes overlap exactly, and the
/// leaves are numbered class by class.
#[test]
fn leaves_hold_one_class() {
    let boxes = random_boxes(2_000, 3);
    let class = |i: usize| (i % 3) as u8;
    let prims = boxes
        .iter()
        .enumerate()
        .flat_map(|(i, &b)| [(b, class(i)), (b, class(i + 1))])
        .collect::<Vec<_>>();
    let bvh = Bvh::build_classes(prims);
    let mut last = 0;
    for k in 0..bvh.leaf_count() {
        let classes: Vec<u8> = bvh
            .leaf(k)
            .iter()
            .map(|&p| class(p as usize / 2 + p as usize % 2))
            .collect();
        assert!(classes.windows(2).all(|w| w[0] == w[1]), "leaf {k}: {classes:?}");
        assert!(
            classes[0] >= last,
            "leaf {k} of class {} after class {last}",
            classes[0]
        );
        last = classes[0];
    }
    assert_eq!(last, 2, "all three classes seen");
}

#[test]
fn empty_and_single() {
    let none = Bvh::<f32>::build([]);
    let ray = Ray::new(Vec3::zero(), Vec3::new(0.0, 0.0, -1.0));
    assert!(!none.any(&ray, f32::INFINITY, |_| true));
    let one = Bvh::build([Aabb::new(Vec3::new(-1.0, -1.0, -3.0), Vec3::new(1.0, 1.0, -2.0))]);
    assert_eq!((one.leaf_count(), one.leaf(0)), (1, &[0u32][..]));
    assert!(one.any(&ray, f32::INFINITY, |k| k == 0));
}
