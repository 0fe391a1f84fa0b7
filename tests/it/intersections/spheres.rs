//! Spheres far from the world origin: the cases, their exact geometry, and the surface and root checks.

use super::{axpy, pow10, vec, zero};
use crate::common::*;
use proptest::prelude::*;
use raytrace::{Float, Hit, Ray, Sphere, lit};
use std::f64::consts::TAU;

/// A sphere, a ray and the `t_max` it is cast with.
#[derive(Clone, Copy, Debug)]
pub(crate) struct SphereCase<F> {
    pub(crate) sphere: Sphere<F>,
    pub(crate) ray: Ray<F>,
    pub(crate) t_max: F,
}

/// Spheres of radius `10^U(−3, 3)` whose centre lies `10^U(−1, 5)` radii from the world
/// origin; ray origins `10^U(−2, 2)` radii from the centre (inside when below 1). Three
/// rays in four are aimed at a point up to `1.5r` from the centre (so they hit or miss,
/// and one in two of those points away from it); one in four is tangent or nearly so
/// (its line `r(1 + s)` from the centre, `s = 0` or `±10^U(−16, −1)`). `t_max` is `∞` or
/// a random distance up to three times the origin's distance from the far side.
pub(crate) fn sphere_case<F: Float>() -> impl Strategy<Value = SphereCase<F>> {
    let aimed = (
        unit_f64(),
        pow10(-2.0, 2.0),
        unit_f64(),
        0.0f64..1.5,
        any::<bool>(),
    )
        .prop_map(|(u1, rho, u2, sigma, back)| {
            let o = u1.map(|x| x * rho);
            let d: [f64; 3] = std::array::from_fn(|i| u2[i] * sigma - o[i]);
            (o, if back { d.map(|x| -x) } else { d })
        });
    let offset = prop_oneof![
        Just(0.0),
        (-16.0f64..-1.0, any::<bool>()).prop_map(|(e, up)| if up { 10f64.powf(e) } else { -10f64.powf(e) }),
    ];
    let tangent = (unit_f64(), 0.0..TAU, pow10(-1.0, 2.0), offset).prop_map(|(a, psi, mu, s)| {
        let (t, b) = frame(a);
        let p: [f64; 3] = std::array::from_fn(|i| psi.cos() * t[i] + psi.sin() * b[i]);
        (axpy(p.map(|x| x * (1.0 + s)), -mu, a), a)
    });
    let t_max = prop_oneof![1 => Just(f64::INFINITY), 1 => 0.0f64..3.0];
    (
        pow10(-3.0, 3.0),
        unit_f64(),
        pow10(-1.0, 5.0),
        prop_oneof![3 => aimed, 1 => tangent],
        t_max,
    )
        .prop_map(|(r, uc, k, (o_rel, d), t_max)| {
            let c = uc.map(|x| x * k * r);
            let o = axpy(c, r, o_rel);
            let reach = (dot(o_rel, o_rel).sqrt() + 1.0) * r;
            SphereCase {
                sphere: Sphere::new(vec(c), lit(r)).unwrap(),
                ray: Ray::new(vec(o), unit_from(d)),
                t_max: lit(if t_max.is_finite() { t_max * reach } else { t_max }),
            }
        })
}

/// The exact geometry of a sphere case (double-double, from the rounded inputs).
pub(crate) struct SphereExact {
    /// `|f|`, `f = O − C`.
    dist: f64,
    /// The distance from the centre to the ray's line, `|f − (f·D̂)D̂|`.
    perp: f64,
    /// The roots along the exactly normalized direction `D̂`, nearer first, if the line
    /// meets the sphere.
    roots: Option<(f64, f64)>,
    /// `|D|` (the `F` direction is unit only within rounding; `t` is measured along `D`).
    dir_len: f64,
}

impl<F: Float> SphereCase<F> {
    fn exact(&self) -> SphereExact {
        let d = dd(self.ray.direction);
        let dir_len = d.length();
        let d = d / dir_len;
        let f = dd(self.ray.origin) - dd(self.sphere.center());
        let r = dd1(self.sphere.radius());
        let b = f.dot(d);
        let l = f - d * b;
        let disc = r * r - l.length_squared();
        let roots = (disc >= zero()).then(|| {
            let s = disc.sqrt();
            ((-b - s).to_f64(), (-b + s).to_f64())
        });
        SphereExact {
            dist: f.length().to_f64(),
            perp: l.length().to_f64(),
            roots,
            dir_len: dir_len.to_f64(),
        }
    }
}

/// A hit of `sphere` is on its surface within the reported error, `| |P − C| − r | ≤ ‖error‖`
/// (the Euclidean length of the per-component bound), and the bound is not vacuous:
/// `‖error‖ ≤ 4ε(r + |P|)` (the library reports `γ(6)|P − C| + γ(2)|P|` per component, whose
/// length is `≈ 3εr + ε|P|`). Also finite, in `(0, t_max)`, with a unit normal facing the
/// ray and `front_face` telling which side was hit.
///
/// `hit_fn` is the method under test, so the power test can run the textbook method here.
pub(crate) fn check_sphere_surface<F: Float>(
    case: &SphereCase<F>,
    hit_fn: impl Fn(&Sphere<F>, &Ray<F>, F) -> Option<Hit<F>>,
) -> Result<(), TestCaseError> {
    let Some(h) = hit_fn(&case.sphere, &case.ray, case.t_max) else {
        return Ok(());
    };
    prop_assert!(
        h.t.is_finite() && h.point.is_finite() && h.error.is_finite() && h.normal.is_finite(),
        "{h:?}"
    );
    prop_assert!(
        h.t > F::zero() && h.t < case.t_max,
        "t = {} outside (0, {})",
        h.t,
        case.t_max
    );
    let c = dd(case.sphere.center());
    let r = dd1(case.sphere.radius());
    let off = ((dd(h.point) - c).length() - r).to_f64().abs();
    let bound = length_dd(h.error);
    prop_assert!(
        off <= bound,
        "{case:?}: {off:e} off the surface, error bound {bound:e} ({:.2}ε·r)",
        off / eps::<F>() / r.to_f64()
    );
    let scale = r.to_f64() + length_dd(h.point);
    prop_assert!(
        bound <= 4.0 * eps::<F>() * scale,
        "error bound {bound:e} = {:.1}ε(r + |P|)",
        bound / eps::<F>() / scale
    );
    prop_assert!(
        (length_dd(h.normal) - 1.0).abs() <= 4.0 * eps::<F>(),
        "normal {:?}",
        h.normal
    );
    prop_assert!(
        h.normal.dot(case.ray.direction) <= F::zero(),
        "normal faces away from the ray"
    );
    let outward = (dd(h.point) - c).dot(dd(h.normal)) > zero();
    prop_assert_eq!(
        outward,
        h.front_face,
        "front_face disagrees with the normal's side"
    );
    Ok(())
}

/// [`Sphere::roots`] and [`Sphere::hit`] against each other and against the exact roots:
/// - the roots are finite and ordered `t₀ ≤ t₁`;
/// - `hit(ray, t_max)` returns exactly (bit for bit) the smallest positive root if it is
///   below `t_max`, and nothing otherwise; `occluded` agrees with `hit`;
/// - tangent rays: roots exist only if the exact discriminant is not clearly negative
///   (`|l| ≤ r + 8ε(|f| + r)`), and exist whenever it is clearly positive;
/// - near and far roots (lines through `|l| ≤ 0.9r`, well-separated roots): from outside
///   the hit is the near root (front face); from inside, the far root (back face); with
///   both roots behind, no hit — each within `8ε(|f| + r)` of the exact root.
pub(crate) fn check_sphere_roots<F: Float>(case: &SphereCase<F>) -> Result<(), TestCaseError> {
    let (s, ray) = (&case.sphere, &case.ray);
    let ex = case.exact();
    let r = dd1(s.radius()).to_f64();
    let band = 8.0 * eps::<F>() * (ex.dist + r);
    let roots = s.roots(ray);
    if let Some((t0, t1)) = roots {
        prop_assert!(t0.is_finite() && t1.is_finite() && t0 <= t1, "roots {t0}, {t1}");
    }
    // Consistency: the hit is the smallest positive root, bit for bit.
    let smallest_positive = roots.and_then(|(t0, t1)| {
        if t0 > F::zero() {
            Some(t0)
        } else if t1 > F::zero() {
            Some(t1)
        } else {
            None
        }
    });
    let expected = smallest_positive.filter(|&t| t < case.t_max);
    let h = s.hit(ray, case.t_max);
    prop_assert_eq!(h.map(|h| h.t), expected, "hit vs roots {:?}", roots);
    prop_assert_eq!(s.occluded(ray, case.t_max), h.is_some());
    // Tangent rays: the computed decision follows the exact discriminant outside the band.
    if roots.is_some() {
        prop_assert!(
            ex.perp <= r + band,
            "roots although the line is {:e}r outside",
            ex.perp / r - 1.0
        );
    } else {
        prop_assert!(
            ex.perp >= r - band,
            "no roots although the line is {:e}r inside",
            1.0 - ex.perp / r
        );
    }
    // Near and far roots, origin inside, against the exact roots.
    if ex.perp <= 0.9 * r {
        let (x0, x1) = ex.roots.expect("|l| < r: the exact line meets the sphere");
        let h_inf = s.hit(ray, F::infinity());
        let tol = band;
        let along = |t: F| t.to_f64() * ex.dir_len;
        if x0 > band {
            prop_assert!(h_inf.is_some(), "outside, sphere ahead: no hit");
            let h = h_inf.unwrap();
            prop_assert!(
                (along(h.t) - x0).abs() <= tol,
                "near root {} vs exact {x0}",
                along(h.t)
            );
            prop_assert!(h.front_face, "outside: must hit the front face");
        } else if x0 < -band && x1 > band {
            prop_assert!(ex.dist < r, "both roots' signs differ only from inside");
            prop_assert!(h_inf.is_some(), "origin inside: no hit");
            let h = h_inf.unwrap();
            prop_assert!(
                (along(h.t) - x1).abs() <= tol,
                "far root {} vs exact {x1}",
                along(h.t)
            );
            prop_assert!(!h.front_face, "origin inside: must hit the back face");
        } else if x1 < -band {
            prop_assert!(
                h_inf.is_none(),
                "sphere behind the origin, yet hit at {:?}",
                h_inf.map(|h| h.t)
            );
        }
    }
    Ok(())
}
