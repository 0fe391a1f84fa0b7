//! Planes: the cases (axis-aligned to grazing rays) and the check of hits and decisions against exact `t`.

use super::{axpy, gamma, pow10, vec, zero};
use crate::common::Alone;
use crate::common::*;
use proptest::prelude::*;
use raytrace::{Float, Plane, Ray};
use std::f64::consts::TAU;

#[derive(Clone, Copy, Debug)]
pub(crate) struct PlaneCase<F> {
    pub(crate) plane: Plane<F>,
    pub(crate) ray: Ray<F>,
}

/// Planes through a point `10^U(−1, 5)·s` from the world origin (`s = 10^U(−3, 3)` the
/// scene's scale), normal along an axis (1 in 4) or random, given with a length
/// `10^U(−3, 3)` (the constructor normalizes it); ray origins at height `±10^U(−3, 2)·s`
/// above a point of the plane; directions aimed at a point of the plane, random, or grazing
/// (`10^U(−12, −1)` radians from the plane, or exactly in it, towards or away from it).
pub(crate) fn plane_case<F: Float>() -> impl Strategy<Value = PlaneCase<F>> {
    let normal = prop_oneof![1 => axis::<f64>().prop_map(|v| v.to_f64()), 3 => unit_f64()];
    let grazing = prop_oneof![Just(0.0), pow10(-12.0, -1.0)];
    let dir = (
        0usize..3,
        [-2.0f64..2.0, -2.0f64..2.0],
        unit_f64(),
        grazing,
        0.0..TAU,
        any::<bool>(),
    );
    (
        pow10(-3.0, 3.0),
        unit_f64(),
        pow10(-1.0, 5.0),
        normal,
        pow10(-3.0, 3.0),
        [-1.0f64..1.0, -1.0f64..1.0],
        (pow10(-3.0, 2.0), any::<bool>()),
        dir,
    )
        .prop_map(
            |(s, up, k, n, n_len, [x, y], (h, below), (kind, [qx, qy], u, alpha, phi, flip))| {
                let p0 = up.map(|c| c * k * s);
                let (t, b) = frame(n);
                let h = if below { -h } else { h };
                let on = |x: f64, y: f64| axpy(axpy(p0, x * s, t), y * s, b);
                let o = axpy(on(x, y), h * s, n);
                let d = match kind {
                    0 => {
                        let q = on(qx, qy);
                        std::array::from_fn(|i| q[i] - o[i])
                    }
                    1 => u,
                    _ => {
                        // Towards the plane (or away, flipped) at angle alpha from it.
                        let side = if (h > 0.0) != flip { -1.0 } else { 1.0 };
                        std::array::from_fn(|i| {
                            alpha.cos() * (phi.cos() * t[i] + phi.sin() * b[i]) + side * alpha.sin() * n[i]
                        })
                    }
                };
                PlaneCase {
                    plane: Plane::new(vec(p0), vec(n.map(|c| c * n_len))).unwrap(),
                    ray: Ray::new(vec(o), unit_from(d)),
                }
            },
        )
}

/// A plane hit lies on the plane within its error: the exact plane `(X − P₀)·n = 0` of the
/// stored point and normal passes through the box `P ± error`, i.e.
/// `|(P − P₀)·n| ≤ Σ|nᵢ|errorᵢ`. A hit has `t > 0` in exact arithmetic (the conservative
/// test), a normal `±n` facing the ray. Where the decision is clear — `|(P₀ − O)·n|` and
/// `|D·n|` both above twice the library's own rounding bounds `γ(7)Σ|P₀ᵢ − Oᵢ||nᵢ|` and
/// `γ(5)Σ|Dᵢnᵢ|` — the ray hits exactly when the exact `t = ((P₀ − O)·n)/(D·n)` is positive.
pub(crate) fn check_plane<F: Float>(case: &PlaneCase<F>) -> Result<(), TestCaseError> {
    let (pl, ray) = (&case.plane, &case.ray);
    let n = dd(pl.normal());
    let p0 = dd(pl.point());
    let (o, d) = (dd(ray.origin), dd(ray.direction));
    let num = (p0 - o).dot(n);
    let den = d.dot(n);
    let h = pl.hit(ray, F::infinity());
    prop_assert_eq!(pl.occluded(ray, F::infinity()), h.is_some());
    if let Some(h) = h {
        prop_assert!(h.t > F::zero() && h.t.is_finite() && h.point.is_finite() && h.error.is_finite());
        prop_assert!(num * den > zero(), "hit at t = {} although the exact t ≤ 0", h.t);
        let off = (dd(h.point) - p0).dot(n).to_f64().abs();
        let reach = dd(pl.normal().abs()).dot(dd(h.error)).to_f64();
        prop_assert!(
            off <= reach,
            "{case:?}: {off:e} off the plane, the error box reaches {reach:e}"
        );
        prop_assert!(h.normal == pl.normal() || h.normal == -pl.normal());
        prop_assert!(h.normal.dot(ray.direction) <= F::zero());
    }
    let diff = pl.point() - ray.origin; // only for the size of the bound
    let num_bound = 2.0 * gamma::<F>(7) * dd(diff.abs()).dot(n.map(|c| c.abs())).to_f64();
    let den_bound = 2.0 * gamma::<F>(5) * d.map(|c| c.abs()).dot(n.map(|c| c.abs())).to_f64();
    if num.to_f64().abs() > num_bound && den.to_f64().abs() > den_bound {
        let ahead = num * den > zero();
        prop_assert_eq!(
            h.is_some(),
            ahead,
            "clear case decided wrongly: exact t = {}",
            (num / den).to_f64()
        );
    }
    Ok(())
}
