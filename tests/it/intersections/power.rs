//! Power: wrong Möller–Trumbore variants the decision check must catch, and the strategies' coverage.

use super::planes::*;
use super::spheres::*;
use super::triangles::*;
use crate::common::Alone;
use proptest::prelude::*;
use proptest::test_runner::{RngSeed, TestRunner};
use raytrace::{Float, Ray, Triangle, lit};

/// A Möller–Trumbore test that closes cracks with a tolerance, accepting `u, v ≥ −10⁻³`
/// and `u + v ≤ 1 + 10⁻³` (common in hobby tracers): a wrong method the decision check
/// must catch.
pub(crate) fn moller_trumbore_lenient<F: Float>(tri: &Triangle<F>, ray: &Ray<F>) -> Option<F> {
    moller_trumbore(tri, ray, -1e-3)
}

/// Möller–Trumbore requiring `u, v > 10⁻³` and `u + v < 1 − 10⁻³`: too strict, so it
/// misses clearly inside rays near the edges.
pub(crate) fn moller_trumbore_strict<F: Float>(tri: &Triangle<F>, ray: &Ray<F>) -> Option<F> {
    moller_trumbore(tri, ray, 1e-3)
}

/// The textbook Möller–Trumbore test with the inside test shifted by `tol` in
/// barycentric units (`u ≥ tol`, `v ≥ tol`, `u + v ≤ 1 − tol`).
pub(crate) fn moller_trumbore<F: Float>(tri: &Triangle<F>, ray: &Ray<F>, tol: f64) -> Option<F> {
    let [a, b, c] = tri.vertices();
    let (e1, e2) = (b - a, c - a);
    let p = ray.direction.cross(e2);
    let det = e1.dot(p);
    if det == F::zero() {
        return None;
    }
    let inv = F::one() / det;
    let s = ray.origin - a;
    let u = s.dot(p) * inv;
    let q = s.cross(e1);
    let v = ray.direction.dot(q) * inv;
    let tol = lit::<F>(tol);
    if u < tol || v < tol || u + v > F::one() - tol {
        return None;
    }
    let t = e2.dot(q) * inv;
    (t > F::zero()).then_some(t)
}

/// The strategies are not vacuous: among 4000 cases of each, enough are decided by the
/// exact geometry, near the edges, from inside the sphere, cut by `t_max`, or grazing,
/// for the checks above to bite (each threshold is about half of what the seeds give).
pub(crate) fn check_coverage<F: Float>() {
    use proptest::strategy::ValueTree;
    let mut runner = TestRunner::new(ProptestConfig {
        rng_seed: RngSeed::Fixed(0xC0_7E),
        ..ProptestConfig::default()
    });
    let n = 4000;
    let mut sample = |f: &mut dyn FnMut(&mut TestRunner)| (0..n).for_each(|_| f(&mut runner));
    let (mut hits, mut misses, mut near_hits, mut near_misses) = (0, 0, 0, 0);
    sample(&mut |runner| {
        let c = tri_case::<F>().new_tree(runner).unwrap().current();
        let ex = c.exact();
        let b_min = ex
            .tri
            .iter()
            .map(|e| (*e / ex.det).to_f64())
            .fold(f64::INFINITY, f64::min);
        match classify::<F>(&ex) {
            Some((true, ..)) => {
                hits += 1;
                near_hits += usize::from(b_min < 1e-3);
            }
            Some((false, ..)) => {
                misses += 1;
                near_misses += usize::from(b_min < 0.0 && b_min > -1e-3);
            }
            None => {}
        }
    });
    let (mut sphere_hits, mut inside, mut cut) = (0, 0, 0);
    sample(&mut |runner| {
        let c = sphere_case::<F>().new_tree(runner).unwrap().current();
        match c.sphere.hit(&c.ray, c.t_max) {
            Some(h) => {
                sphere_hits += 1;
                inside += usize::from(!h.front_face);
            }
            None => cut += usize::from(c.sphere.hit(&c.ray, F::infinity()).is_some()),
        }
    });
    let (mut plane_hits, mut grazing_hits) = (0, 0);
    sample(&mut |runner| {
        let c = plane_case::<F>().new_tree(runner).unwrap().current();
        if c.plane.hit(&c.ray, F::infinity()).is_some() {
            plane_hits += 1;
            grazing_hits += usize::from(c.ray.direction.dot(c.plane.normal()).abs() < lit(1e-3));
        }
    });
    let counts = [
        ("triangle: clear hits", hits, 150),
        ("triangle: clear hits within 10⁻³ of an edge", near_hits, 10),
        ("triangle: clear misses", misses, 1000),
        ("triangle: clear misses within 10⁻³ of an edge", near_misses, 20),
        ("sphere: hits", sphere_hits, 1500),
        ("sphere: hits from inside", inside, 800),
        ("sphere: hits cut off by t_max", cut, 150),
        ("plane: hits", plane_hits, 1500),
        ("plane: hits within 10⁻³ rad of grazing", grazing_hits, 100),
    ];
    for (what, got, want) in counts {
        println!("{}: {what}: {got} of {n}", F::NAME);
        assert!(
            got >= want,
            "{}: {what}: only {got} of {n} (want ≥ {want})",
            F::NAME
        );
    }
}
