//! The batch query ([`Index::hit_all`], [`Index::occluded_all`]) against one ray at a time.

use super::*;

/// The batch answers exactly as one ray at a time: the same record and object, for
/// rays from outside, from inside and from the surfaces, ties included. (It finds a
/// mismatch if a batch loop skips an object, tests a packet with the wrong ray, or
/// breaks ties the other way.) So does the batch's occlusion query. The last case has
/// more objects than stay cached, which the batch reads ahead.
#[test]
fn a_batch_answers_like_single_rays() {
    use rand::{RngExt, SeedableRng};
    for (seed, triangles, acceleration, n) in [
        (1, false, Acceleration::Linear, 120),
        (2, true, Acceleration::Linear, 120),
        (3, false, Acceleration::Bvh, 120),
        (4, true, Acceleration::Bvh, 120),
        (5, true, Acceleration::Bvh, 30_000),
    ] {
        let objects = mixed_of(seed, triangles, n);
        assert_eq!(size_of_val(&objects[..]) > super::CACHED, n > 120);
        let tags = tags(&objects);
        let index = Index::build(&objects, acceleration, BvhQuality::Medium);
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
            .filter_map(|r| index.hit(&objects, &tags, r, f64::INFINITY))
            .collect();
        rays.extend(firsts.iter().filter_map(|(h, _, _)| {
            let d = (h.normal + v(1.0)).try_normalize()?;
            Some(h.spawn(d))
        }));
        let (mut near, mut out) = (Nearests::default(), Vec::new());
        index.hit_all(&objects, &tags, &rays, &mut near, |i, hit| {
            assert_eq!(i, out.len(), "in the rays' order");
            out.push(hit);
        });
        assert_eq!(out.len(), rays.len());
        let mut hits = 0;
        for (ray, got) in rays.iter().zip(&out) {
            let want = index
                .hit(&objects, &tags, ray, f64::INFINITY)
                .map(|(h, o, _)| (h, o.material));
            assert_eq!(got.map(|(h, o, _)| (h, o.material)), want, "{ray:?}");
            hits += usize::from(want.is_some());
        }
        assert!(hits > rays.len() / 2, "most rays should hit something ({hits})");
        // A smaller batch after it, in buffers kept from the larger one, answers the same.
        let (fewer, mut again) = (&rays[rays.len() / 3..rays.len() / 2], Vec::new());
        index.hit_all(&objects, &tags, fewer, &mut near, |_, hit| again.push(hit));
        let same = |h: Option<HitOn<'_, f64, ShapeKind<f64>, Tag>>| h.map(|(h, o, _)| (h, o.material));
        assert!(
            again
                .into_iter()
                .map(same)
                .eq(out[rays.len() / 3..rays.len() / 2].iter().map(|&h| same(h)))
        );
        // Occlusion of the whole batch, each ray to its own reach.
        let reach: Vec<f64> = (0..rays.len())
            .map(|i| [1.0, 5.0, 12.0, f64::INFINITY][i % 4])
            .collect();
        let mut blocked = Vec::new();
        let aimed = vec![None; rays.len()];
        index.occluded_all(&objects, &rays, &reach, &aimed, &mut near, &mut blocked);
        assert_eq!(blocked.len(), rays.len());
        for ((ray, &t_max), &got) in rays.iter().zip(&reach).zip(&blocked) {
            assert_eq!(got, index.occluded(&objects, ray, t_max), "{ray:?} to {t_max}");
        }
        let count = blocked.iter().filter(|&&b| b).count();
        assert!(
            count > rays.len() / 4 && count < rays.len() * 3 / 4,
            "{count} of {} blocked",
            rays.len()
        );
    }
}
