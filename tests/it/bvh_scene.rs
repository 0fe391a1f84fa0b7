//! A scene answers the same through its BVH as through the plain loop, and both answer as
//! the naive loop of the definition: same nearest hits, same shadow queries, same image bytes.

use crate::common::Alone;
use rand::{RngExt, SeedableRng};
use raytrace::prelude::*;
use raytrace::shape::Hit;
use raytrace::{Acceleration, DefaultRng};

/// 300 random spheres of random sizes, or spheres and triangles, around the origin, plus a
/// ground plane (unbounded) and a huge sphere (its box covers most of the scene's), which
/// both stay outside the BVH. (With spheres alone every leaf of the tree is one packet;
/// with triangles the leaves are general groups: both ways are tested.)
fn scene<F: Float>(acceleration: Acceleration, triangles: bool) -> EnumScene<F> {
    let mut rng = DefaultRng::seed_from_u64(17);
    let mut radii = DefaultRng::seed_from_u64(18);
    let mut scene = EnumScene::new(Background::default());
    let mut v = |s: f64| {
        Vec3::from_f64(
            rng.random_range(-s..s),
            rng.random_range(-s..s),
            rng.random_range(-s..s),
        )
    };
    for i in 0..300 {
        let c = v(6.0) + Vec3::from_f64(0.0, 0.0, -10.0);
        let m: MaterialKind<F> = if i % 3 == 0 {
            Mirror::new(Vec3::from_f64(0.9, 0.8, 0.7)).unwrap().into()
        } else {
            Lambertian::new(Vec3::from_f64(0.5, 0.6, 0.7)).unwrap().into()
        };
        if !triangles {
            let r = radii.random_range(0.05..0.8);
            scene.add(Sphere::new(c, lit(r)).unwrap(), m);
        } else if i % 2 == 0 {
            scene.add(Sphere::new(c, lit(0.4)).unwrap(), m);
        } else {
            scene.add(Triangle::new(c + v(0.7), c + v(0.7), c + v(0.7)).unwrap(), m);
        }
    }
    scene.add(
        Plane::new(Vec3::from_f64(0.0, -7.0, 0.0), Vec3::from_f64(0.0, 1.0, 0.0)).unwrap(),
        Lambertian::new(Vec3::splat(lit(0.5))).unwrap(),
    );
    scene.add(
        Sphere::new(Vec3::from_f64(3.0, -106.5, -10.0), lit(100.0)).unwrap(),
        Mirror::new(Vec3::splat(lit(0.6))).unwrap(),
    );
    scene.add_light(PointLight::new(Vec3::from_f64(0.0, 8.0, -8.0), Vec3::splat(lit(50.0))).unwrap());
    scene.set_acceleration(acceleration);
    scene
}

/// The oracle: every object's own `hit`, one by one in the order added, keeping the nearest
/// (a later object must be strictly nearer to win a tie), and `occluded` as "any object".
fn naive_hit<F: Float>(scene: &EnumScene<F>, ray: &Ray<F>) -> Option<(Hit<F>, MaterialKind<F>)> {
    let mut best: Option<(Hit<F>, MaterialKind<F>)> = None;
    for o in scene.objects() {
        let bound = best.as_ref().map_or(F::infinity(), |(h, _)| h.t);
        if let Some(hit) = o.shape.hit(ray, bound) {
            best = Some((hit, scene.material(o.material).clone()));
        }
    }
    best
}

fn naive_occluded<F: Float>(scene: &EnumScene<F>, ray: &Ray<F>, t_max: F) -> bool {
    scene.objects().iter().any(|o| o.shape.occluded(ray, t_max))
}

fn same_queries<F: Float>(triangles: bool) {
    let linear = scene::<F>(Acceleration::Linear, triangles);
    let bvh = scene::<F>(Acceleration::Bvh, triangles);
    assert!(!linear.uses_bvh() && bvh.uses_bvh());
    let mut rng = DefaultRng::seed_from_u64(3);
    let mut hits = 0;
    for _ in 0..20_000 {
        let o = Vec3::from_f64(rng.random_range(-3.0..3.0), rng.random_range(-3.0..3.0), 0.0);
        let target = Vec3::from_f64(rng.random_range(-8.0..8.0), rng.random_range(-8.0..8.0), -10.0);
        let ray = Ray::towards(o, target).unwrap();
        let a = linear.hit(&ray, F::infinity()).map(|(h, m)| (h, m.clone()));
        let b = bvh.hit(&ray, F::infinity()).map(|(h, m)| (h, m.clone()));
        assert_eq!(a, b, "{ray:?}");
        assert_eq!(a, naive_hit(&linear, &ray), "{ray:?}");
        hits += usize::from(a.is_some());
        let t_max = lit(rng.random_range(1.0..15.0));
        let blocked = naive_occluded(&linear, &ray, t_max);
        assert_eq!(linear.occluded(&ray, t_max), blocked);
        assert_eq!(bvh.occluded(&ray, t_max), blocked);
    }
    assert!(hits > 10_000, "the rays should mostly hit something ({hits})");
}

#[test]
fn bvh_answers_like_the_loop_f32() {
    same_queries::<f32>(true);
    same_queries::<f32>(false);
}

#[test]
fn bvh_answers_like_the_loop_f64() {
    same_queries::<f64>(true);
    same_queries::<f64>(false);
}

#[test]
fn bvh_renders_the_same_bytes() {
    let cam = ScreenCamera::new(48, 24).unwrap();
    let s = RenderSettings::new(2, 6, 1).unwrap();
    for triangles in [true, false] {
        let a = render(&scene::<f32>(Acceleration::Linear, triangles), &cam, &s).unwrap();
        let b = render(&scene::<f32>(Acceleration::Bvh, triangles), &cam, &s).unwrap();
        assert_eq!(a.image, b.image);
        assert_eq!(a.stats.rays, b.stats.rays);
    }
}

#[test]
fn auto_uses_a_bvh_only_from_the_threshold() {
    let mut small = EnumScene::<f64>::new(Background::default());
    for i in 0..Acceleration::AUTO_THRESHOLD {
        assert!(!small.uses_bvh(), "{i} objects");
        small.add(
            Sphere::new(Vec3::new(i as f64, 0.0, -5.0), 0.3).unwrap(),
            Mirror::new(Vec3::splat(0.5)).unwrap(),
        );
    }
    assert!(small.uses_bvh());
}

/// Objects hit at exactly the same distance inside one BVH leaf: the object added first
/// wins through the tree as through the loop. Each of 150 random spheres is added twice,
/// the copies after all the originals, so every pair shares a box and a leaf, in whatever
/// order the build's partitions leave them; every albedo is distinct, so the material
/// names the object that won.
#[test]
fn ties_inside_a_leaf_go_to_the_object_added_first() {
    fn check<F: Float>() {
        let mut rng = DefaultRng::seed_from_u64(29);
        let spheres: Vec<(Vec3<F>, F)> = (0..150)
            .map(|_| {
                let c = Vec3::from_f64(
                    rng.random_range(-6.0..6.0),
                    rng.random_range(-6.0..6.0),
                    rng.random_range(-16.0..-4.0),
                );
                (c, lit(rng.random_range(0.1..0.6)))
            })
            .collect();
        let build = |acceleration| {
            let mut scene = EnumScene::<F>::new(Background::default());
            for copy in 0..2 {
                for (i, &(c, r)) in spheres.iter().enumerate() {
                    let albedo = Vec3::from_f64((2 * i + copy) as f64 / 400.0, 0.5, 0.5);
                    scene.add(Sphere::new(c, r).unwrap(), Lambertian::new(albedo).unwrap());
                }
            }
            scene.set_acceleration(acceleration);
            scene
        };
        let (linear, bvh) = (build(Acceleration::Linear), build(Acceleration::Bvh));
        assert!(bvh.uses_bvh());
        let mut hits = 0;
        for &(c, _) in &spheres {
            let o = Vec3::from_f64(rng.random_range(-1.0..1.0), rng.random_range(-1.0..1.0), 0.0);
            let ray = Ray::towards(o, c).unwrap();
            let (a, b) = (linear.hit(&ray, F::infinity()), bvh.hit(&ray, F::infinity()));
            assert_eq!(
                a.map(|(h, m)| (h, m.clone())),
                b.map(|(h, m)| (h, m.clone())),
                "{ray:?}"
            );
            hits += usize::from(a.is_some());
        }
        assert_eq!(hits, spheres.len(), "every ray aims at a sphere's centre");
    }
    check::<f32>();
    check::<f64>();
}
