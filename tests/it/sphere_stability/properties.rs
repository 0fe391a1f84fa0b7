//! The properties, for f32 and f64: near and far roots, origins inside, tangent rays, random rays.

use super::REGRESSIONS;
use super::cases::*;
use crate::common::Alone;
use crate::common::*;
use proptest::prelude::*;
use raytrace::{Float, Ray, lit};
use std::f64::consts::TAU;

/// Parameters of a case, drawn in `f64` (see [`build`]).
fn geometry(
    dist: impl Strategy<Value = f64>,
    side: impl Strategy<Value = f64>,
) -> impl Strategy<Value = (f64, f64, [f64; 3], [f64; 3], f64, f64)> {
    (
        (-3.0f64..3.0).prop_map(|e| 10f64.powf(e)),
        dist,
        unit_f64(),
        [-1.0f64..1.0, -1.0f64..1.0, -1.0f64..1.0],
        side,
        0.0..TAU,
    )
}

/// Distances `|C − O|/r` log-uniform in `[1.02, 10⁴]` (origin outside).
fn outside() -> impl Strategy<Value = f64> {
    (0.01f64..4.0).prop_map(|e| 10f64.powf(e) + 1.0)
}

/// Near and far roots from outside: both roots positive and within `8ε·scale` of the
/// exact ones; `hit` returns the near one, a front-face hit, and respects the open interval
/// `(0, t_max)` exactly (`t_max = t₀` misses, `t_max = next_up(t₀)` hits); a ray starting
/// between the roots (inside) hits the far side from within (`front_face == false`).
fn check_roots<F: Float>(case: Case<F>) -> Result<(), TestCaseError> {
    let exact = case.exact();
    let (t0x, t1x) = exact.roots.expect("aimed within 0.9r");
    let (t0, t1) = case.sphere.roots(&case.ray).expect("the stable roots exist");
    let tol = 8.0 * eps::<F>() * exact.scale;
    prop_assert!(t0 <= t1);
    prop_assert!((t0.to_f64() - t0x).abs() <= tol, "t₀ = {t0}, exact {t0x}");
    prop_assert!((t1.to_f64() - t1x).abs() <= tol, "t₁ = {t1}, exact {t1x}");
    let h = case.sphere.hit(&case.ray, F::infinity());
    prop_assert!(h.is_some());
    let h = h.unwrap();
    prop_assert_eq!(h.t, t0);
    prop_assert!(h.front_face);
    case.check_hit(&h, t0x, exact.scale)?;
    prop_assert!(case.sphere.hit(&case.ray, t0).is_none(), "t_max is exclusive");
    prop_assert_eq!(case.sphere.hit(&case.ray, t0.next_up()).map(|h| h.t), Some(t0));
    prop_assert_eq!(case.sphere.occluded(&case.ray, t0), false);

    // From a point between the roots, the ray leaves through the far side.
    let mid = (t0 + t1) * lit(0.5);
    let inside = Ray::new(case.ray.at(mid), case.ray.direction);
    let inner = Case {
        sphere: case.sphere,
        ray: inside,
    };
    let ix = inner.exact();
    let Some((_, t_exit)) = ix.roots else {
        return Err(TestCaseError::fail("the exact line misses from inside"));
    };
    if t_exit > 8.0 * eps::<F>() * ix.scale {
        let h = case.sphere.hit(&inside, F::infinity());
        prop_assert!(h.is_some(), "no exit hit from inside: {inner:?}");
        let h = h.unwrap();
        prop_assert!(!h.front_face);
        inner.check_hit(&h, t_exit, ix.scale)?;
    }
    Ok(())
}

/// From an origin inside the sphere (`|O − C| ≤ 0.99r`), every direction hits, from the
/// inside, at the far root.
fn check_inside<F: Float>(case: Case<F>) -> Result<(), TestCaseError> {
    let exact = case.exact();
    prop_assert!(exact.dist < dd1(case.sphere.radius()).to_f64());
    let (_, t1x) = exact.roots.expect("inside: the line meets the sphere");
    let h = case.sphere.hit(&case.ray, F::infinity());
    prop_assert!(h.is_some(), "no hit from inside: {case:?}");
    let h = h.unwrap();
    prop_assert!(!h.front_face);
    case.check_hit(&h, t1x, exact.scale)
}

/// Tangent and near-tangent rays (`|l| = r(1 + s)`, `|s|` from 10⁻¹ to 10⁻¹⁶ and 0):
/// nothing is NaN; `hit` and `occluded` agree; a hit lies on the surface within its bound;
/// and the decision matches the exact geometry outside a band `|perp − r| ≤ 8ε(|f| + r)`.
/// The stable discriminant `r² − |l|²` has an error `≤ 2|l|·3ε|f| + 2εr²` (`l = f − (f·D)D`
/// is off by `~3ε|f|`; a direction off unit by `δ` changes `|l|²` only by `δ²b²`), so its
/// sign is right when `|r − perp| > 3ε|f| + εr`: the band has twice that. Near tangency
/// the hit's *position along the ray* is ill-conditioned (`∂t/∂perp → ∞`), so only the
/// distance to the surface is checked, and the reprojection keeps it within the bound.
fn check_tangent<F: Float>(case: Case<F>) -> Result<(), TestCaseError> {
    let exact = case.exact();
    let r = dd1(case.sphere.radius()).to_f64();
    let h = case.sphere.hit(&case.ray, F::infinity());
    prop_assert_eq!(h.is_some(), case.sphere.occluded(&case.ray, F::infinity()));
    let band = 8.0 * eps::<F>() * (exact.dist + r);
    if let Some(roots) = case.sphere.roots(&case.ray) {
        prop_assert!(roots.0.is_finite() && roots.1.is_finite(), "{roots:?}");
    }
    match h {
        Some(h) => {
            prop_assert!(
                exact.perp <= r + band,
                "hit although {:e} r outside",
                exact.perp / r - 1.0
            );
            prop_assert!(h.t.is_finite() && h.point.is_finite() && h.error.is_finite());
            let off = case.off_surface(h.point);
            prop_assert!(off <= length_dd(h.error), "{off:e} off the surface");
            prop_assert!(h.normal.dot(case.ray.direction) <= F::zero());
        }
        None => {
            prop_assert!(
                exact.perp >= r - band,
                "missed although {:e} r inside",
                1.0 - exact.perp / r
            );
        }
    }
    Ok(())
}

/// Random spheres and rays — origins inside and outside, rays towards and away from the
/// sphere, passing up to 1.5r from its centre: whatever `hit` returns is finite, inside
/// `(0, ∞)`, on the surface within its bound, faces the ray; and the decision agrees with
/// the exact geometry outside the band of [`check_tangent`] (and, for the root, outside
/// `8ε·scale` of `t = 0`).
fn check_random<F: Float>(case: Case<F>) -> Result<(), TestCaseError> {
    let exact = case.exact();
    let r = dd1(case.sphere.radius()).to_f64();
    let band = 8.0 * eps::<F>() * (exact.dist + r);
    let t_band = 8.0 * eps::<F>() * exact.scale;
    let h = case.sphere.hit(&case.ray, F::infinity());
    let should_hit = match exact.roots {
        Some((t0, t1)) if exact.perp < r - band => {
            if t1 > t_band && !(t0 > -t_band && t0 < t_band) {
                Some(true)
            } else if t1 < -t_band {
                Some(false)
            } else {
                None
            }
        }
        _ if exact.perp > r + band => Some(false),
        _ => None,
    };
    if let Some(expected) = should_hit {
        prop_assert_eq!(h.is_some(), expected, "{:?}", case);
    }
    if let Some(h) = h {
        prop_assert!(h.t > F::zero() && h.t.is_finite());
        prop_assert!(h.point.is_finite() && h.error.is_finite());
        let off = case.off_surface(h.point);
        prop_assert!(
            off <= length_dd(h.error),
            "{off:e} off the surface, bound {:e}",
            length_dd(h.error)
        );
        prop_assert!(h.normal.dot(case.ray.direction) <= F::zero());
        prop_assert!((length_dd(h.normal) - 1.0).abs() <= 4.0 * eps::<F>());
    }
    Ok(())
}

macro_rules! sphere_tests {
    ($name:ident, $F:ty, $seed:expr) => {
        mod $name {
            use super::*;

            proptest! {
                #![proptest_config(config(10_000, $seed, REGRESSIONS))]

                #[test]
                fn near_and_far_roots(
                    (r, dist, axis, origin, side, psi) in geometry(outside(), 0.0f64..0.9),
                ) {
                    check_roots(build::<$F>(r, dist, axis, origin, side, psi, false, false))?;
                }

                #[test]
                fn origin_inside(
                    (r, dist, axis, origin, side, psi) in geometry(0.0f64..0.99, 0.0f64..3.0),
                    backwards in any::<bool>(),
                ) {
                    // origin within the unit cube scaled by r, centre dist·r away: the origin
                    // is inside when |O − C| = dist·r < r.
                    check_inside(build::<$F>(r, dist, axis, origin, side, psi, false, backwards))?;
                }

                #[test]
                fn tangent_rays(
                    (r, dist, axis, origin, _side, psi) in geometry(outside(), Just(1.0)),
                    s in prop_oneof![
                        Just(0.0),
                        (1.0f64..16.0, any::<bool>()).prop_map(|(k, up)| {
                            if up { 10f64.powf(-k) } else { -(10f64.powf(-k)) }
                        }),
                    ],
                ) {
                    check_tangent(build::<$F>(r, dist, axis, origin, 1.0 + s, psi, true, false))?;
                }

                #[test]
                fn random_rays_hit_on_the_surface(
                    (r, dist, axis, origin, side, psi) in geometry(
                        (-2.0f64..4.0).prop_map(|e| 10f64.powf(e)),
                        0.0f64..1.5,
                    ),
                    backwards in any::<bool>(),
                ) {
                    check_random(build::<$F>(r, dist, axis, origin, side, psi, false, backwards))?;
                }
            }
        }
    };
}

sphere_tests!(single, f32, 0x5A_E2E1);
sphere_tests!(double, f64, 0x5A_E2E2);
