//! Triangles: the cases (near edges, grazing), their exact barycentrics, and the decision and hit checks.

use super::{axpy, gamma, pow10, vec, zero};
use crate::common::*;
use proptest::prelude::*;
use raytrace::{Float, Ray, Triangle, Vec3};
use std::f64::consts::TAU;
use twofloat::TwoFloat;

#[derive(Clone, Copy, Debug)]
pub(crate) struct TriCase<F> {
    tri: Triangle<F>,
    ray: Ray<F>,
}

/// A coordinate of the target's barycentrics close to an edge: exactly 0, or
/// `±10^U(−8, −1)` (inside or outside by a little).
pub(crate) fn near_zero() -> impl Strategy<Value = f64> {
    prop_oneof![
        1 => Just(0.0),
        6 => (-8.0f64..-1.0, any::<bool>()).prop_map(|(e, neg)| if neg { -10f64.powf(e) } else { 10f64.powf(e) }),
    ]
}

/// Triangles of size `s = 10^U(−3, 3)` centred `10^U(−1, 4)·s` from the world origin, in a
/// random plane, vertices at `0.2s` to `s` from the centre in random directions. The ray is
/// aimed at the point of target barycentrics `β`: `(β₁, β₂)` random in `[−0.25, 1.25]²`, or with one
/// coordinate [`near_zero`] (the others random); from `10^U(−2, 1.5)·s` away, at an angle
/// whose cosine to the normal is `10^U(−2, 0)`, from either side; one ray in four points
/// away from the target (the triangle is behind it).
pub(crate) fn tri_case<F: Float>() -> impl Strategy<Value = TriCase<F>> {
    let random = [-0.25f64..1.25, -0.25f64..1.25].prop_map(|[b1, b2]| [1.0 - b1 - b2, b1, b2]);
    let edge = (0usize..3, near_zero(), -0.3f64..1.3).prop_map(|(i, z, u)| {
        let mut beta = [0.0; 3];
        beta[i] = z;
        beta[(i + 1) % 3] = u;
        beta[(i + 2) % 3] = 1.0 - z - u;
        beta
    });
    let verts = [
        (0.0..TAU, 0.2f64..1.0),
        (0.0..TAU, 0.2f64..1.0),
        (0.0..TAU, 0.2f64..1.0),
    ];
    let approach = (
        pow10(-2.0, 1.5),
        pow10(-2.0, 0.0),
        0.0..TAU,
        any::<bool>(),
        0u8..4,
    );
    (
        pow10(-3.0, 3.0),
        unit_f64(),
        pow10(-1.0, 4.0),
        unit_f64(),
        verts,
        prop_oneof![random, edge],
        approach,
    )
        .prop_filter_map(
            "degenerate triangle",
            |(s, uc, k, n, verts, beta, (h, cos_a, phi, side, away))| {
                let centre = uc.map(|c| c * k * s);
                let (t, b) = frame(n);
                let v =
                    verts.map(|(th, rho)| axpy(axpy(centre, s * rho * th.cos(), t), s * rho * th.sin(), b));
                let q: [f64; 3] =
                    std::array::from_fn(|i| beta[0] * v[0][i] + beta[1] * v[1][i] + beta[2] * v[2][i]);
                let sin_a = (1.0 - cos_a * cos_a).sqrt();
                let sign = if side { 1.0 } else { -1.0 };
                let w: [f64; 3] = std::array::from_fn(|i| {
                    sign * cos_a * n[i] + sin_a * (phi.cos() * t[i] + phi.sin() * b[i])
                });
                let o = axpy(q, h * s, w);
                let d = if away == 0 { w } else { w.map(|c| -c) };
                let tri = Triangle::new(vec(v[0]), vec(v[1]), vec(v[2])).ok()?;
                Some(TriCase {
                    tri,
                    ray: Ray::new(vec(o), unit_from(d)),
                })
            },
        )
}

/// The exact geometry of a triangle case, in double-double.
pub(crate) struct TriExact {
    /// The triple products `Tᵢ = D·((Vⱼ − O)×(Vₖ − O))`, `(i, j, k)` cyclic: the
    /// unnormalized barycentric coordinates of the ray's line.
    pub(crate) tri: [TwoFloat; 3],
    /// `ΣTᵢ = D·N`, `N = (B − A)×(C − A)`.
    pub(crate) det: TwoFloat,
    /// The ray parameter of the plane crossing, `((A − O)·N)/(D·N)`.
    pub(crate) t: f64,
    /// `M`, the largest coordinate of `Vᵢ − O`.
    pub(crate) m: f64,
    /// `N`.
    pub(crate) normal: Vec3<TwoFloat>,
}

impl<F: Float> TriCase<F> {
    pub(crate) fn exact(&self) -> TriExact {
        let [a, b, c] = self.tri.vertices().map(dd);
        let (o, d) = (dd(self.ray.origin), dd(self.ray.direction));
        let (ao, bo, co) = (a - o, b - o, c - o);
        let tri = [d.dot(bo.cross(co)), d.dot(co.cross(ao)), d.dot(ao.cross(bo))];
        let det = tri[0] + tri[1] + tri[2];
        let normal = (b - a).cross(c - a);
        let t = (ao.dot(normal) / d.dot(normal)).to_f64();
        let m = [ao, bo, co]
            .iter()
            .map(|v| v.abs().max_element().to_f64())
            .fold(0.0, f64::max);
        TriExact {
            tri,
            det,
            t,
            m,
            normal,
        }
    }
}

/// The classification of a triangle case by its exact barycentrics (see the module's
/// *Margins*): `Some(false)` if the ray must miss, `Some(true)` (with the exact `t` and
/// its tolerance) if it must hit, `None` if rounding may decide either way.
pub(crate) fn classify<F: Float>(ex: &TriExact) -> Option<(bool, f64, f64)> {
    if ex.det == zero() {
        return None;
    }
    let margin = 128.0 * eps::<F>() * ex.m * ex.m;
    let det = ex.det.to_f64();
    let clearly = |e: &TwoFloat| e.to_f64().abs() > margin;
    let t_margin = 32.0 * eps::<F>() * ex.m * (1.0 + 32.0 * ex.m * ex.m / det.abs());
    let outside = ex.tri.iter().any(|e| (*e * ex.det) < zero() && clearly(e));
    let inside = ex.tri.iter().all(|e| (*e * ex.det) > zero() && clearly(e));
    if outside || (inside && ex.t < -t_margin) {
        Some((false, ex.t, t_margin))
    } else if inside && ex.t > t_margin {
        Some((true, ex.t, t_margin))
    } else {
        None
    }
}

/// The hit/miss decision of `intersect` (the method under test, returning `t`) agrees with
/// the exact barycentrics wherever they are clear: a miss whenever one coordinate is
/// clearly negative (`bᵢ < −mᵢ`) or the triangle is clearly behind; a hit, within `t_m` of
/// the exact `t`, whenever all three are clearly positive and it is clearly ahead.
pub(crate) fn check_triangle_decision<F: Float>(
    case: &TriCase<F>,
    intersect: impl Fn(&Triangle<F>, &Ray<F>) -> Option<F>,
) -> Result<(), TestCaseError> {
    let ex = case.exact();
    let got = intersect(&case.tri, &case.ray);
    let bary = ex.tri.map(|e| (e / ex.det).to_f64());
    match classify::<F>(&ex) {
        Some((false, t, _)) => {
            prop_assert!(
                got.is_none(),
                "{case:?}: hit at {got:?}, but barycentrics {bary:?}, t = {t:e}"
            )
        }
        Some((true, t, tol)) => {
            prop_assert!(
                got.is_some(),
                "{case:?}: missed, but barycentrics {bary:?}, t = {t:e}"
            );
            let t_got = got.unwrap().to_f64();
            prop_assert!(
                (t_got - t).abs() <= tol,
                "t = {t_got:e}, exact {t:e}, tolerance {tol:e}"
            );
        }
        None => {}
    }
    Ok(())
}

/// A triangle hit of the library: finite, `t > 0`, on the exact plane of the vertices
/// within its error box (`|(P − A)·N| ≤ Σ|Nᵢ|errorᵢ`), normal `±n` facing the ray, and
/// barycentrics that are non-negative, sum to 1 within `γ(4)`, and lie within
/// `4mᵢ + 4ε` of the exact ones (the edge functions are off by `≤ δe`, the ratio by
/// `≤ 4δe/|D·N|` plus the division's rounding).
pub(crate) fn check_triangle_hit<F: Float>(case: &TriCase<F>) -> Result<(), TestCaseError> {
    let (tri, ray) = (&case.tri, &case.ray);
    let Some(h) = tri.hit(ray, F::infinity()) else {
        return Ok(());
    };
    prop_assert!(h.t > F::zero() && h.t.is_finite() && h.point.is_finite() && h.error.is_finite());
    let ex = case.exact();
    let a = dd(tri.vertices()[0]);
    let off = (dd(h.point) - a).dot(ex.normal).to_f64().abs();
    let reach = ex.normal.abs().dot(dd(h.error)).to_f64();
    prop_assert!(
        off <= reach,
        "{case:?}: {off:e} off the plane (|N|-scaled), box reaches {reach:e}"
    );
    prop_assert!(h.normal == tri.normal() || h.normal == -tri.normal());
    prop_assert!(h.normal.dot(ray.direction) <= F::zero());
    let (_, b) = tri
        .intersect_watertight(ray, F::infinity())
        .expect("hit implies intersect");
    let sum: f64 = b.iter().map(|&x| Float::to_f64(x)).sum();
    prop_assert!(b.iter().all(|&x| x >= F::zero()), "negative barycentric {b:?}");
    prop_assert!((sum - 1.0).abs() <= gamma::<F>(4) + 2.0 * eps::<F>(), "sum {sum}");
    let margin = 128.0 * eps::<F>() * ex.m * ex.m / ex.det.to_f64().abs();
    for (bi, e) in b.iter().zip(ex.tri) {
        let exact = (e / ex.det).to_f64();
        prop_assert!(
            (Float::to_f64(*bi) - exact).abs() <= 4.0 * margin + 4.0 * eps::<F>(),
            "barycentric {bi} vs exact {exact}, margin {margin:e}"
        );
    }
    Ok(())
}
