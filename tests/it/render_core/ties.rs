//! Ties: at equal distance the object added first wins, on the loop, the BVH and the trait objects.

use rand::SeedableRng;
use raytrace::DefaultRng;
use raytrace::prelude::*;
use raytrace::shape::{Hit, Surface};
use std::sync::Arc;

/// Objects hit at exactly the same distance: the one added first wins, through the plain
/// loop (spheres packed four at a time; the leftover one, and in f64 two, tested alone),
/// the BVH, and the trait objects alike.
#[test]
fn ties_go_to_the_object_added_first_on_every_path() {
    use raytrace::Acceleration;
    let ray = Ray::new(Vec3::zero(), Vec3::new(0.0, 0.0, -1.0));
    for (n, first) in [9usize, 10]
        .into_iter()
        .flat_map(|n| [0, 3, 5, n - 2, n - 1].map(|f| (n, f)))
    {
        // `n` spheres; two of them, `first` and the last, are the same sphere in front.
        let build = || {
            (0..n).map(move |i| {
                let c = if i == first || i == n - 1 {
                    Vec3::new(0.0, 0.0, -4.0)
                } else {
                    Vec3::new(i as f64, 3.0, -4.0)
                };
                (
                    Sphere::new(c, 1.0).unwrap(),
                    Mirror::new(Vec3::splat(0.01 * i as f64)).unwrap(),
                )
            })
        };
        for acceleration in [Acceleration::Linear, Acceleration::Bvh] {
            let mut scene = EnumScene::<f64>::new(Background::default());
            let mut dyn_scene = DynScene::<f64>::new(Background::default());
            for (s, m) in build() {
                scene.add(s, m);
                dyn_scene.add(Box::new(s), Arc::new(m));
            }
            scene.set_acceleration(acceleration);
            dyn_scene.set_acceleration(acceleration);
            let (hit, material) = scene.hit(&ray, f64::INFINITY).unwrap();
            assert_eq!(hit.t, 3.0);
            let want = Mirror::new(Vec3::splat(0.01 * first as f64)).unwrap();
            assert_eq!(
                *material,
                MaterialKind::from(want),
                "{acceleration:?}, {n} spheres, first {first}"
            );
            let (dyn_hit, dyn_material) = dyn_scene.hit(&ray, f64::INFINITY).unwrap();
            assert_eq!(dyn_hit, hit);
            let probe = Hit::new(
                Surface::bare(1.0, Vec3::zero(), Vec3::new(0.0, 0.0, 1.0)),
                ray.direction,
            );
            let mut rng = DefaultRng::seed_from_u64(0);
            let got = dyn_material
                .sample(&probe, -ray.direction, &mut rng)
                .unwrap()
                .weight;
            assert_eq!(
                got,
                want.albedo(),
                "dyn {acceleration:?}, {n} spheres, first {first}"
            );
        }
    }
}
