//! The triangle's tests: hits, misses, shared edges and vertices, degenerate input.

use super::*;
use crate::error::Field;
use crate::float::lit;
use crate::shape::Alone;

fn v<F: Float>(x: f64, y: f64, z: f64) -> Vec3<F> {
    Vec3::from_f64(x, y, z)
}

fn down<F: Float>(x: f64, y: f64) -> Ray<F> {
    Ray::new(v(x, y, 0.0), v(0.0, 0.0, -1.0))
}

/// Four triangles around `(0, 0, −2)` in the plane `z = −2`, counter-clockwise seen
/// from `+z`, covering the square `[−2, 2]²`: quadrants `+x+y`, `−x+y`, `−x−y`, `+x−y`.
fn quadrants<F: Float>() -> [Triangle<F>; 4] {
    let o = v(0.0, 0.0, -2.0);
    let ring = [
        v(2.0, 0.0, -2.0),
        v(0.0, 2.0, -2.0),
        v(-2.0, 0.0, -2.0),
        v(0.0, -2.0, -2.0),
    ];
    std::array::from_fn(|i| Triangle::new(o, ring[i], ring[(i + 1) % 4]).unwrap())
}

fn hits_inside<F: Float>() {
    let tri = Triangle::new(v::<F>(-1.0, -1.0, -5.0), v(1.0, -1.0, -5.0), v(0.0, 1.0, -5.0)).unwrap();
    assert_eq!(tri.normal(), v(0.0, 0.0, 1.0), "{}", F::NAME);
    let (t, b) = tri.intersect_watertight(&down(0.0, 0.0), F::infinity()).unwrap();
    assert_eq!(t, lit(5.0), "{}", F::NAME);
    assert!((b[0] + b[1] + b[2] - F::one()).abs() <= lit::<F>(4.0) * F::eps());
    for (bi, want) in b.into_iter().zip([0.25, 0.25, 0.5]) {
        assert!(
            (bi - lit(want)).abs() <= lit::<F>(4.0) * F::eps(),
            "{}: {b:?}",
            F::NAME
        );
    }
    let h = tri.hit(&down(0.0, 0.0), F::infinity()).unwrap();
    assert!((h.point - v(0.0, 0.0, -5.0)).abs().max_element() <= h.error.max_element());
    assert!(h.front_face && h.normal == v(0.0, 0.0, 1.0), "{}", F::NAME);
    // From behind: the same surface, the other face.
    let up = Ray::new(v(0.0, 0.0, -9.0), v(0.0, 0.0, 1.0));
    let h = tri.hit(&up, F::infinity()).unwrap();
    assert_eq!(h.t, lit(4.0), "{}", F::NAME);
    assert!(!h.front_face && h.normal == v(0.0, 0.0, -1.0), "{}", F::NAME);
    // t_max is exclusive.
    assert!(tri.hit(&down(0.0, 0.0), lit(5.0)).is_none());
    assert!(tri.occluded(&down(0.0, 0.0), lit::<F>(5.0).next_up()));
}

fn misses_outside_behind_and_parallel<F: Float>() {
    let tri = Triangle::new(v::<F>(-1.0, -1.0, -5.0), v(1.0, -1.0, -5.0), v(0.0, 1.0, -5.0)).unwrap();
    let inf = F::infinity();
    assert!(tri.hit(&down(0.8, 0.8), inf).is_none(), "{}", F::NAME);
    assert!(tri.hit(&down(0.0, -1.5), inf).is_none(), "{}", F::NAME);
    let away = Ray::new(Vec3::zero(), v(0.0, 0.0, 1.0));
    assert!(tri.hit(&away, inf).is_none(), "{}", F::NAME);
    let parallel = Ray::new(v(-3.0, 0.0, -5.0), v(1.0, 0.0, 0.0));
    assert!(tri.hit(&parallel, inf).is_none(), "{}", F::NAME);
    let nan = Ray {
        origin: v(F::nan().to_f64(), 0.0, 0.0),
        direction: v(0.0, 0.0, -1.0),
    };
    assert!(tri.hit(&nan, inf).is_none(), "{}", F::NAME);
}

/// A ray exactly through a shared edge hits both triangles at the same `t`; one
/// through the shared vertex hits all four; one a hair to either side of an edge
/// hits exactly one.
fn edges_and_vertices_count_consistently<F: Float>() {
    let quads = quadrants::<F>();
    let hits = |r: &Ray<F>| {
        quads
            .iter()
            .filter_map(|q| q.hit(r, F::infinity()))
            .collect::<Vec<_>>()
    };
    let on_vertex = hits(&down(0.0, 0.0));
    assert_eq!(on_vertex.len(), 4, "{}: vertex", F::NAME);
    for (x, y) in [(0.5, 0.0), (0.0, 1.25), (-0.75, 0.0), (0.0, -1.0)] {
        let on_edge = hits(&down(x, y));
        assert_eq!(on_edge.len(), 2, "{}: edge at ({x}, {y})", F::NAME);
        assert!(
            on_edge
                .iter()
                .all(|h| h.t == lit(2.0) && h.point == v(x, y, -2.0))
        );
    }
    for hair in [F::eps(), F::min_positive_value()] {
        for sign in [F::one(), -F::one()] {
            let r = Ray::new(Vec3::new(lit(0.5), hair * sign, F::zero()), v(0.0, 0.0, -1.0));
            assert_eq!(hits(&r).len(), 1, "{}: {:?}", F::NAME, r.origin);
        }
    }
    // The outer vertices and edges of the square belong to the mesh too.
    assert_eq!(hits(&down(2.0, 0.0)).len(), 2, "{}", F::NAME);
    assert_eq!(hits(&down(1.0, 1.0)).len(), 1, "{}", F::NAME);
    assert_eq!(hits(&down(1.0, 1.0 + 1e-6)).len(), 0, "{}", F::NAME);
}

fn rejects_degenerate_and_invalid<F: Float>() {
    let a = v::<F>(0.0, 0.0, 0.0);
    let b = v::<F>(1.0, 0.0, 0.0);
    let cases = [
        ("collinear", a, v(1.0, 1.0, 1.0), v(2.0, 2.0, 2.0)),
        ("coincident A = B", a, a, v(0.0, 1.0, 0.0)),
        ("all coincident", b, b, b),
        ("rounded collinear", a, v(0.1, 0.2, 0.3), v(0.3, 0.6, 0.9)),
        ("NaN", a, b, Vec3::new(F::nan(), F::zero(), F::zero())),
        ("infinite", a, b, Vec3::new(F::zero(), F::infinity(), F::zero())),
        (
            "thinner than γ(6)",
            a,
            b,
            Vec3::new(F::one(), F::gamma(6) * lit(0.5), F::zero()),
        ),
    ];
    for (why, a, b, c) in cases {
        match Triangle::new(a, b, c) {
            Err(Error::InvalidValue {
                field: Field::Triangle | Field::TriangleA | Field::TriangleB | Field::TriangleC,
                ..
            }) => {}
            other => panic!(
                "{}: {why}: expected InvalidValue(triangle), got {other:?}",
                F::NAME
            ),
        }
    }
    // Thin but above the threshold: valid, with the right normal.
    let thin = Triangle::new(a, b, Vec3::new(F::one(), F::gamma(6) * lit(4.0), F::zero())).unwrap();
    assert_eq!(thin.normal(), v(0.0, 0.0, 1.0), "{}", F::NAME);
}

mod scalars {
    use crate::float::for_each_scalar;

    for_each_scalar!(
        hits_inside,
        misses_outside_behind_and_parallel,
        edges_and_vertices_count_consistently,
        rejects_degenerate_and_invalid
    );
}
