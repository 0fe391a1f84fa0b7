//! The batch index against one-ray queries and the plain loop.

use super::packet::NONE;
use super::*;
use crate::scene::MaterialId;
use crate::shape::{Alone, Hittable, Mesh, Plane, ShapeKind, Sphere, Triangle};
use crate::vec3::Vec3;

/// `n` unit-spaced small spheres in a row, and after them, where asked, a triangle and a
/// plane.
fn objects(n: usize, others: bool) -> Vec<Object<ShapeKind<f32>, ()>> {
    let mut shapes: Vec<ShapeKind<f32>> = (0..n)
        .map(|i| Sphere::new(Vec3::new(i as f32, 0.0, -5.0), 0.3).unwrap().into())
        .collect();
    if others {
        let v = |x: f32, y: f32| Vec3::new(x, y, -6.0);
        shapes.push(
            Triangle::new(v(0.0, 0.0), v(1.0, 0.0), v(0.0, 1.0))
                .unwrap()
                .into(),
        );
        shapes.push(Plane::new(v(0.0, -3.0), Vec3::new(0.0, 1.0, 0.0)).unwrap().into());
    }
    shapes
        .into_iter()
        .map(|shape| Object { shape, material: () })
        .collect()
}

/// Every BVH leaf is one packet of one kind (a sphere and a triangle never share one), its
/// lanes in key order; the plane stays in the loop, alone in its packet.
#[test]
fn a_leaf_is_one_packet_of_one_kind() {
    for others in [false, true] {
        let objects = objects(40, others);
        let index = Index::build(&objects, Acceleration::Bvh, BvhQuality::Medium);
        let bvh = index.bvh.as_ref().unwrap();
        assert_eq!(index.leaves.len(), bvh.leaf_count());
        for k in 0..bvh.leaf_count() {
            // Tree part 40 is the triangle (the plane, unbounded, is not in the tree).
            let kinds: std::collections::BTreeSet<_> = bvh.leaf(k).iter().map(|&i| i >= 40).collect();
            assert_eq!(kinds.len(), 1, "leaf {k} mixes kinds");
        }
        assert_eq!(
            index.looped.len(),
            usize::from(others),
            "the plane alone is looped"
        );
        for p in index.looped.iter().map(Looped::packet).chain(index.leaves.iter()) {
            let used: Vec<_> = p.keys().iter().filter(|k| k.0 != NONE).collect();
            assert!(used.windows(2).all(|w| w[0] < w[1]), "lanes in key order");
        }
    }
}

/// The index, built on rayon's threads, is the same on any number of them: its passes
/// and its leaves' packets come out in the order of a sequential build.
#[test]
fn the_index_is_the_same_on_any_number_of_threads() {
    let objects = mixed(7, true);
    let on = |threads| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        let index = pool.install(|| Index::build(&objects, Acceleration::Bvh, BvhQuality::Medium));
        format!("{index:?}")
    };
    let one = on(1);
    assert!(
        one.contains("Triangle4") && one.contains("Sphere4"),
        "both kinds are packed"
    );
    assert_eq!(one, on(2));
    assert_eq!(one, on(3));
}

/// A material that only names its object, for telling which object a query found.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Tag(u32);

impl crate::material::Material<f64> for Tag {
    fn lobes(&self) -> crate::material::Lobes {
        crate::material::Lobes::NONE
    }
    fn reads_coordinates(&self) -> bool {
        false
    }
    fn eval(&self, _: &Hit<f64>, _: Vec3<f64>, _: Vec3<f64>) -> Option<crate::material::Eval<f64>> {
        None
    }
    fn pdf(&self, _: &Hit<f64>, _: Vec3<f64>, _: Vec3<f64>) -> f64 {
        0.0
    }
    fn emits(&self) -> Option<crate::material::Emission<f64>> {
        None
    }
}

/// Spheres of random sizes (each added twice, so that exact ties happen), triangles, a
/// mesh (added twice too) and a plane, through the plain loop and through a BVH.
fn mixed(seed: u64, triangles: bool) -> Vec<Object<ShapeKind<f64>>> {
    mixed_of(seed, triangles, 120)
}

/// [`mixed`] with `n` spheres or triangles at random places.
fn mixed_of(seed: u64, triangles: bool, n: usize) -> Vec<Object<ShapeKind<f64>>> {
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
    // Smaller where there are more, so that as many rays are blocked (exactly 1 for 120).
    let size = (120.0 / n as f64).cbrt();
    for i in 0..n {
        let c = v(5.0);
        if triangles && i % 3 == 0 {
            let corner = |v: Vec3<f64>| c + v * size;
            shapes.push(
                Triangle::new(corner(v(0.8)), corner(v(0.8)), corner(v(0.8)))
                    .unwrap()
                    .into(),
            );
        } else {
            let s: ShapeKind<f64> = Sphere::new(c, size * (0.05 + v(0.4).x.abs())).unwrap().into();
            shapes.push(s.clone());
            shapes.push(s);
        }
    }
    shapes.push(
        Plane::new(Vec3::new(0.0, -6.0, 0.0), Vec3::new(0.0, 1.0, 0.0))
            .unwrap()
            .into(),
    );
    shapes.push(Sphere::new(Vec3::new(0.0, -1005.0, 0.0), 1000.0).unwrap().into());
    if triangles {
        // A ring of triangles around a shared centre: rays through shared edges and the
        // centre meet several at once.
        let (centre, ring) = (v(4.0), 12);
        let mut vertices = vec![centre];
        vertices.extend((0..ring).map(|_| centre + v(2.0)));
        let faces = (0..ring).map(|i| [0, 1 + i, 1 + (i + 1) % ring]).collect();
        let mesh: ShapeKind<f64> = Mesh::new(vertices, faces).unwrap().into();
        shapes.push(mesh.clone());
        shapes.push(mesh);
    }
    shapes
        .into_iter()
        .enumerate()
        .map(|(i, shape)| Object {
            shape,
            material: MaterialId(i as u32),
        })
        .collect()
}

/// The table of materials for `objects`: object `i` is made of `Tag(i)`.
fn tags<S>(objects: &[Object<S>]) -> Vec<Tag> {
    (0..objects.len() as u32).map(Tag).collect()
}

/// The definition the index must give, bit for bit: every object's shape asked whole
/// ([`Hittable::hit`]), the nearest kept, of equally near ones the first.
fn naive_loop<S: Hittable<f64>, M: Copy>(objects: &[Object<S, M>], ray: &Ray<f64>) -> Option<(Hit<f64>, M)> {
    let mut best: Option<(Hit<f64>, M)> = None;
    for o in objects {
        // Intersect and record, as the scene does for a material that reads no coordinates.
        if let Some(h) = o
            .shape
            .intersect(ray, f64::INFINITY)
            .map(|i| o.shape.finish(ray, &i))
            && best.as_ref().is_none_or(|(b, _)| h.t < b.t)
        {
            best = Some((h, o.material));
        }
    }
    best
}

/// Asserts that `index` answers `ray` as the naive loop does, for the nearest hit and for
/// occlusion up to three distances; returns whether the ray hits something.
fn answers_as_the_naive_loop(
    index: &Index<f64>,
    objects: &[Object<ShapeKind<f64>>],
    tags: &[Tag],
    ray: &Ray<f64>,
) -> bool {
    let want = naive_loop(objects, ray);
    let got = index
        .hit(objects, tags, ray, f64::INFINITY)
        .map(|(h, o, _)| (h, o.material));
    assert_eq!(got, want, "{ray:?}");
    for t_max in [1.0, 5.0, 12.0] {
        let blocked = objects.iter().any(|o| o.shape.occluded(ray, t_max));
        assert_eq!(index.occluded(objects, ray, t_max), blocked, "{ray:?} to {t_max}");
    }
    want.is_some()
}

/// The index, through the loop and through a BVH, answers as the naive loop over the
/// objects does, ties and meshes included, and so does the occlusion query.
#[test]
fn the_index_is_the_naive_loop() {
    use rand::{RngExt, SeedableRng};
    for (seed, acceleration) in [(5, Acceleration::Linear), (6, Acceleration::Bvh)] {
        let objects = mixed(seed, true);
        let tags = tags(&objects);
        let index = Index::build(&objects, acceleration, BvhQuality::Medium);
        let mut rng = crate::sampling::DefaultRng::seed_from_u64(seed);
        let mut v = |s: f64| {
            Vec3::new(
                rng.random_range(-s..s),
                rng.random_range(-s..s),
                rng.random_range(-s..s),
            )
        };
        let mut hits = 0;
        for _ in 0..4000 {
            let Some(ray) = Ray::towards(v(9.0), v(5.0)) else {
                continue;
            };
            hits += usize::from(answers_as_the_naive_loop(&index, &objects, &tags, &ray));
        }
        assert!(hits > 2000, "most rays should hit something ({hits})");
    }
}

/// The sizes docs/PERFORMANCE.md gives for a scene's memory per part: a change of layout
/// must update the document too.
#[test]
fn sizes_are_the_documented_ones() {
    fn sizes<F: Float>() -> [usize; 4] {
        let [spheres, triangles] = packet::packet_bytes::<F>();
        let object = size_of::<Object<ShapeKind<F>>>();
        let sizes = [object, spheres, triangles, crate::bvh::wide_node_bytes::<F>()];
        println!("object, sphere packet, triangle packet, wide node: {sizes:?} B");
        sizes
    }
    assert_eq!(sizes::<f32>(), [32, 100, 176, 320]);
    // A node on cache lines spans four in f32 (eight children), not five.
    assert_eq!(crate::bvh::wide_node_align::<f32>(), 64);
    assert_eq!(sizes::<f64>(), [48, 168, 320, 288]);
}

/// The plain loop over the objects (`Acceleration::Linear`) and the packets in lanes a
/// small scene gets (`Auto` below its threshold) answer every query alike, ties included.
#[test]
fn the_plain_loop_is_the_packed_loop() {
    use rand::{RngExt, SeedableRng};
    let objects: Vec<_> = mixed(7, true).into_iter().take(12).collect();
    let tags = tags(&objects);
    let parts: u32 = objects.iter().map(|o| o.shape.parts()).sum();
    assert!(parts < Acceleration::AUTO_THRESHOLD as u32, "{parts} parts");
    let plain = Index::build(&objects, Acceleration::Linear, BvhQuality::Medium);
    let packed = Index::build(&objects, Acceleration::Auto, BvhQuality::Medium);
    assert!(plain.plain && !packed.plain && packed.bvh.is_none());
    let mut rng = crate::sampling::DefaultRng::seed_from_u64(7);
    let mut v = |s: f64| {
        Vec3::new(
            rng.random_range(-s..s),
            rng.random_range(-s..s),
            rng.random_range(-s..s),
        )
    };
    let centres: Vec<_> = objects
        .iter()
        .filter_map(|o| o.shape.bounds())
        .map(|b| (b.min + b.max) * 0.5)
        .collect();
    let mut hits = 0;
    for k in 0..4000 {
        // Aimed near an object, so most rays meet one.
        let Some(ray) = Ray::towards(v(9.0), centres[k % centres.len()] + v(0.2)) else {
            continue;
        };
        let want = packed
            .hit(&objects, &tags, &ray, f64::INFINITY)
            .map(|(h, o, _)| (h, o.material));
        let got = plain
            .hit(&objects, &tags, &ray, f64::INFINITY)
            .map(|(h, o, _)| (h, o.material));
        assert_eq!(got, want, "{ray:?}");
        hits += usize::from(want.is_some());
        for t_max in [1.0, 5.0, 12.0] {
            assert_eq!(
                plain.occluded(&objects, &ray, t_max),
                packed.occluded(&objects, &ray, t_max),
                "{ray:?} to {t_max}"
            );
        }
    }
    assert!(hits > 2000, "most rays should hit something ({hits})");
}

/// Long thin triangles every way oriented, alone and in a mesh, with spheres among them:
/// the high-quality build cuts most of the triangles into pieces ([`BvhQuality::High`]),
/// and still answers as the naive loop, for the nearest hit, in batches and for occlusion.
#[test]
fn cut_triangles_answer_as_the_naive_loop() {
    use rand::{RngExt, SeedableRng};
    let mut rng = crate::sampling::DefaultRng::seed_from_u64(12);
    let mut v = |s: f64| {
        Vec3::new(
            rng.random_range(-s..s),
            rng.random_range(-s..s),
            rng.random_range(-s..s),
        )
    };
    let (mut shapes, mut vertices): (Vec<ShapeKind<f64>>, Vec<Vec3<f64>>) = (Vec::new(), Vec::new());
    let mut targets = Vec::new();
    for i in 0..300 {
        // Mostly small triangles, every twentieth a needle: the needles are cut until their
        // pieces' boxes are full enough, within the budget.
        let c = v(5.0);
        let corners = if i % 20 == 0 {
            let d = v(1.0);
            [c - d, c + d, c + v(0.05)]
        } else {
            [c + v(0.3), c + v(0.3), c + v(0.3)]
        };
        targets.push(corners);
        match i % 3 {
            0 => shapes.push(Triangle::new(corners[0], corners[1], corners[2]).unwrap().into()),
            1 => vertices.extend(corners),
            _ => shapes.push(Sphere::new(c, 0.1).unwrap().into()),
        }
    }
    let faces = (0..vertices.len() as u32 / 3)
        .map(|i| [3 * i, 3 * i + 1, 3 * i + 2])
        .collect();
    shapes.push(Mesh::new(vertices, faces).unwrap().into());
    let objects: Vec<Object<ShapeKind<f64>>> = shapes
        .into_iter()
        .enumerate()
        .map(|(i, shape)| Object {
            shape,
            material: MaterialId(i as u32),
        })
        .collect();
    let tags = tags(&objects);
    let index = Index::build(&objects, Acceleration::Bvh, BvhQuality::High);
    let bvh = index.bvh.as_ref().expect("a BVH");
    let references: usize = (0..bvh.leaf_count()).map(|k| bvh.leaf(k).len()).sum();
    assert!(
        (310..500).contains(&references),
        "the needles cut, within the budget: {references} references"
    );
    let mut rays = Vec::new();
    let mut hits = 0;
    // Each ray aimed at a random point of a random triangle (a sphere's centre for every
    // third), so that every piece of every triangle is probed.
    for i in 0..20000 {
        let [a, b, c] = targets[i % targets.len()];
        let (s, t) = (v(1.0).x.abs(), v(1.0).y.abs());
        let (s, t) = if s + t > 1.0 { (1.0 - s, 1.0 - t) } else { (s, t) };
        let Some(ray) = Ray::towards(v(9.0), a + (b - a) * s + (c - a) * t) else {
            continue;
        };
        hits += usize::from(answers_as_the_naive_loop(&index, &objects, &tags, &ray));
        rays.push(ray);
    }
    assert!(hits > 15000, "most rays should hit something ({hits})");
    let mut near = Nearests::default();
    index.hit_all(&objects, &tags, &rays, &mut near, |i, hit| {
        let want = naive_loop(&objects, &rays[i]);
        assert_eq!(hit.map(|(h, o, _)| (h, o.material)), want, "{:?}", rays[i]);
    });
}

mod aimed;
mod batch;
