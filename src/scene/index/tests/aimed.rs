//! Shadow rays aimed at a part ([`Index::occluded_all`] with `aimed`): the answer of the
//! exact reach, whatever bound the ray carries.

use super::*;
use rand::{RngExt, SeedableRng};

/// Every aimed ray is blocked exactly when [`Index::occluded`] to the part's own distance
/// says so, and one that misses its part is blocked and counted, with the bound past the
/// part, short of it or infinite, beside rays with an exact reach in the same batch. The
/// parts include spheres and meshes added twice, so that an aimed part ties with another
/// that comes first. (It fails if the part found nearest is taken for the aimed one by
/// object alone, if a bound short of the part counts as clear, or if the exact reach is
/// compared the wrong way.)
#[test]
fn aimed_rays_answer_as_their_exact_reach() {
    for (seed, triangles, acceleration, n) in [
        (21, true, Acceleration::Bvh, 120),
        (22, false, Acceleration::Bvh, 120),
        (23, true, Acceleration::Linear, 120),
        (24, true, Acceleration::Bvh, 3000),
    ] {
        let objects = mixed_of(seed, triangles, n);
        let index = Index::build(&objects, acceleration, BvhQuality::Medium);
        let parts: Vec<(u32, u32)> = (0..objects.len() as u32)
            .flat_map(|o| (0..objects[o as usize].shape.parts()).map(move |p| (o, p)))
            .collect();
        let mut rng = crate::sampling::DefaultRng::seed_from_u64(seed);
        let mut v = |s: f64| {
            Vec3::new(
                rng.random_range(-s..s),
                rng.random_range(-s..s),
                rng.random_range(-s..s),
            )
        };
        let rays: Vec<Ray<f64>> = (0..3000).filter_map(|_| Ray::towards(v(9.0), v(5.0))).collect();
        let distance = |(o, p): (u32, u32), ray: &Ray<f64>| {
            let shape = &objects[o as usize].shape;
            shape.intersect_part(p, ray, f64::INFINITY).map(|i| i.t)
        };
        let (mut reach, mut aimed, mut want, mut want_missed) = (vec![], vec![], vec![], 0);
        for (i, ray) in rays.iter().enumerate() {
            let met: Vec<_> = parts
                .iter()
                .copied()
                .filter(|&k| distance(k, ray).is_some())
                .collect();
            // Every fifth ray has an exact reach and no part; one in eight of the others is
            // aimed at a part it may well miss.
            if i % 5 == 0 || met.is_empty() {
                let t = rng.random_range(0.0..15.0);
                reach.push(t);
                aimed.push(None);
                want.push(index.occluded(&objects, ray, t));
                continue;
            }
            let key = if rng.random_range(0..8) == 0 {
                parts[rng.random_range(0..parts.len())]
            } else {
                met[rng.random_range(0..met.len())]
            };
            let exact = distance(key, ray);
            let bound = match (exact, rng.random_range(0..3)) {
                (Some(t), 0) => t * 1.01,
                (Some(t), 1) => t * 0.99,
                _ => f64::INFINITY,
            };
            reach.push(bound);
            aimed.push(Some(key));
            want.push(exact.is_none_or(|t| index.occluded(&objects, ray, t)));
            want_missed += usize::from(exact.is_none());
        }
        let (mut near, mut blocked) = (Nearests::default(), Vec::new());
        let missed = index.occluded_all(&objects, &rays, &reach, &aimed, &mut near, &mut blocked);
        assert_eq!(missed, want_missed, "seed {seed}");
        for (i, (&got, &want)) in blocked.iter().zip(&want).enumerate() {
            assert_eq!(
                got, want,
                "seed {seed}, ray {i} aimed at {:?} within {}",
                aimed[i], reach[i]
            );
        }
        // Every case is met: clear and blocked aimed rays, and missed parts.
        let aimed_clear = (0..rays.len())
            .filter(|&i| aimed[i].is_some() && !blocked[i])
            .count();
        let aimed_blocked = (0..rays.len())
            .filter(|&i| aimed[i].is_some() && blocked[i])
            .count();
        assert!(
            aimed_clear > 200 && aimed_blocked > 200 && missed > 20,
            "{aimed_clear}, {aimed_blocked}, {missed}"
        );
    }
}
