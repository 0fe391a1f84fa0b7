//! Intersections checked against exact geometry, as property tests
//! written once and run for f32 and f64 with fixed proptest seeds.
//!
//! Every reference value is computed in double-double ([`TwoFloat`], ~106 bits) from the
//! *rounded* inputs the library sees (the sphere's stored centre and radius, the plane's
//! stored point and unit normal, the triangle's vertices, the ray's `F` origin and
//! direction), so the only error left in a comparison is the library's own.
//!
//! This file complements `sphere_stability.rs` (spheres near the world origin, far small
//! spheres) and `flat_shapes.rs` (seeded re-intersection loops): here the sphere is placed
//! up to `10⁵` radii from the world origin, so the `|P|` term of the error bound matters;
//! the sphere's [`hit`](Hittable::hit) is checked for *exact* agreement with
//! [`Sphere::roots`] and random `t_max`; and a triangle's hit/miss decision is checked
//! against barycentric coordinates computed independently from the exact geometry.
//!
//! # Margins
//! - **Sphere discriminant.** With `f = O − C` (exact), the computed perpendicular distance
//!   of the line from the centre is within `~4ε(|f| + r)` of the exact one (see
//!   `sphere_stability.rs`), so the decision "the line meets the sphere" is only checked
//!   outside the band `| |l| − r | ≤ 8ε(|f| + r)`, and the root only outside `8ε(|f| + r)`
//!   of `t = 0`.
//! - **Triangle edge functions.** The watertight test computes the three edge functions
//!   `eᵢ` in a translated, permuted and sheared frame; with `M` the largest coordinate of
//!   `Vᵢ − O`, pbrt-v4's bound on their rounding is `δe ≤ 83εM²` (each sheared coordinate
//!   is at most `2M`, off by `≤ γ(5)(2 + √3)M`; two products and a difference). The exact
//!   edge functions are the triple products `Tᵢ = D·((Vⱼ − O)×(Vₖ − O))` divided by the
//!   largest component of `D` (`≤ 1`), so `|Tᵢ| > 128εM²` fixes the sign of the computed
//!   `eᵢ`. In barycentric units (`bᵢ = Tᵢ/ΣT`, `ΣT = D·N`) the margin is
//!   `mᵢ = 128εM²/|D·N|`: it widens for far origins (large `M`) and grazing rays (small
//!   `D·N`), exactly where the barycentrics are ill-conditioned. The ray's `t` must exceed
//!   pbrt's `δt`, which is below `t_m = 32εM(1 + 32M²/|D·N|)` for a clearly inside ray.

mod common;

use common::*;
use proptest::prelude::*;
use proptest::test_runner::{RngSeed, TestRunner};
use raytrace::shape::textbook_sphere_hit;
use raytrace::{Float, Hit, Hittable, Plane, Ray, Sphere, Triangle, Vec3, lit};
use std::f64::consts::TAU;
use twofloat::TwoFloat;

/// The fixed seed of the power checks (`common::harness_rejects`).
const HARNESS_SEED: u64 = 0x1DE5;

const REGRESSIONS: &str = "proptest-regressions/intersections.txt";

/// Cases per property and scalar: all checks are a few hundred flops, so 20 000 cases of the
/// five properties take about a second in the optimised test profile.
const CASES: u32 = 20_000;

/// `10^e`, `e` uniform in `[lo, hi)`: log-uniform magnitudes.
fn pow10(lo: f64, hi: f64) -> impl Strategy<Value = f64> {
    (lo..hi).prop_map(|e| 10f64.powf(e))
}

/// `a + s·b` in `f64`.
fn axpy(a: [f64; 3], s: f64, b: [f64; 3]) -> [f64; 3] {
    std::array::from_fn(|i| a[i] + s * b[i])
}

fn vec<F: Float>(a: [f64; 3]) -> Vec3<F> {
    Vec3::from_f64(a[0], a[1], a[2])
}

fn zero() -> TwoFloat {
    TwoFloat::from(0.0)
}

/// `F::gamma(n)` as an `f64`.
fn gamma<F: Float>(n: u32) -> f64 {
    F::gamma(n).to_f64()
}

// ---------------------------------------------------------------------------------------
// Spheres
// ---------------------------------------------------------------------------------------

/// A sphere, a ray and the `t_max` it is cast with.
#[derive(Clone, Copy, Debug)]
struct SphereCase<F> {
    sphere: Sphere<F>,
    ray: Ray<F>,
    t_max: F,
}

/// Spheres of radius `10^U(−3, 3)` whose centre lies `10^U(−1, 5)` radii from the world
/// origin; ray origins `10^U(−2, 2)` radii from the centre (inside when below 1). Three
/// rays in four are aimed at a point up to `1.5r` from the centre (so they hit or miss,
/// and one in two of those points away from it); one in four is tangent or nearly so
/// (its line `r(1 + s)` from the centre, `s = 0` or `±10^U(−16, −1)`). `t_max` is `∞` or
/// a random distance up to three times the origin's distance from the far side.
fn sphere_case<F: Float>() -> impl Strategy<Value = SphereCase<F>> {
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
struct SphereExact {
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
fn check_sphere_surface<F: Float>(
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
fn check_sphere_roots<F: Float>(case: &SphereCase<F>) -> Result<(), TestCaseError> {
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

// ---------------------------------------------------------------------------------------
// Planes
// ---------------------------------------------------------------------------------------

#[derive(Clone, Copy, Debug)]
struct PlaneCase<F> {
    plane: Plane<F>,
    ray: Ray<F>,
}

/// Planes through a point `10^U(−1, 5)·s` from the world origin (`s = 10^U(−3, 3)` the
/// scene's scale), normal along an axis (1 in 4) or random, given with a length
/// `10^U(−3, 3)` (the constructor normalizes it); ray origins at height `±10^U(−3, 2)·s`
/// above a point of the plane; directions aimed at a point of the plane, random, or grazing
/// (`10^U(−12, −1)` radians from the plane, or exactly in it, towards or away from it).
fn plane_case<F: Float>() -> impl Strategy<Value = PlaneCase<F>> {
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
fn check_plane<F: Float>(case: &PlaneCase<F>) -> Result<(), TestCaseError> {
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

// ---------------------------------------------------------------------------------------
// Triangles
// ---------------------------------------------------------------------------------------

#[derive(Clone, Copy, Debug)]
struct TriCase<F> {
    tri: Triangle<F>,
    ray: Ray<F>,
}

/// A coordinate of the target's barycentrics close to an edge: exactly 0, or
/// `±10^U(−8, −1)` (inside or outside by a little).
fn near_zero() -> impl Strategy<Value = f64> {
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
fn tri_case<F: Float>() -> impl Strategy<Value = TriCase<F>> {
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
struct TriExact {
    /// The triple products `Tᵢ = D·((Vⱼ − O)×(Vₖ − O))`, `(i, j, k)` cyclic: the
    /// unnormalized barycentric coordinates of the ray's line.
    tri: [TwoFloat; 3],
    /// `ΣTᵢ = D·N`, `N = (B − A)×(C − A)`.
    det: TwoFloat,
    /// The ray parameter of the plane crossing, `((A − O)·N)/(D·N)`.
    t: f64,
    /// `M`, the largest coordinate of `Vᵢ − O`.
    m: f64,
    /// `N`.
    normal: Vec3<TwoFloat>,
}

impl<F: Float> TriCase<F> {
    fn exact(&self) -> TriExact {
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
fn classify<F: Float>(ex: &TriExact) -> Option<(bool, f64, f64)> {
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
fn check_triangle_decision<F: Float>(
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
fn check_triangle_hit<F: Float>(case: &TriCase<F>) -> Result<(), TestCaseError> {
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
    let (_, b) = tri.intersect(ray, F::infinity()).expect("hit implies intersect");
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

/// A Möller–Trumbore test that closes cracks with a tolerance, accepting `u, v ≥ −10⁻³`
/// and `u + v ≤ 1 + 10⁻³` (common in hobby tracers): a wrong method the decision check
/// must catch.
fn moller_trumbore_lenient<F: Float>(tri: &Triangle<F>, ray: &Ray<F>) -> Option<F> {
    moller_trumbore(tri, ray, -1e-3)
}

/// Möller–Trumbore requiring `u, v > 10⁻³` and `u + v < 1 − 10⁻³`: too strict, so it
/// misses clearly inside rays near the edges.
fn moller_trumbore_strict<F: Float>(tri: &Triangle<F>, ray: &Ray<F>) -> Option<F> {
    moller_trumbore(tri, ray, 1e-3)
}

/// The textbook Möller–Trumbore test with the inside test shifted by `tol` in
/// barycentric units (`u ≥ tol`, `v ≥ tol`, `u + v ≤ 1 − tol`).
fn moller_trumbore<F: Float>(tri: &Triangle<F>, ray: &Ray<F>, tol: f64) -> Option<F> {
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
fn check_coverage<F: Float>() {
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

macro_rules! intersection_tests {
    ($name:ident, $F:ty, $seed:expr) => {
        mod $name {
            use super::*;

            proptest! {
                #![proptest_config(config(CASES, $seed, REGRESSIONS))]

                #[test]
                fn sphere_hits_lie_on_the_sphere_within_the_error_bound(case in sphere_case::<$F>()) {
                    check_sphere_surface(&case, |s, r, t_max| s.hit(r, t_max))?;
                }

                #[test]
                fn sphere_hit_is_the_smallest_positive_root(case in sphere_case::<$F>()) {
                    check_sphere_roots(&case)?;
                }

                #[test]
                fn plane_hits_lie_on_the_plane_and_decide_like_exact_t(case in plane_case::<$F>()) {
                    check_plane(&case)?;
                }

                #[test]
                fn triangle_hits_and_misses_follow_exact_barycentrics(case in tri_case::<$F>()) {
                    check_triangle_decision(&case, |t, r| t.intersect(r, <$F>::INFINITY).map(|x| x.0))?;
                }

                #[test]
                fn triangle_hits_lie_on_the_triangle_within_the_error_bound(case in tri_case::<$F>()) {
                    check_triangle_hit(&case)?;
                }
            }

            /// The harness has power: the textbook sphere (no reprojection, zero error
            /// bound) fails the surface check, and Möller–Trumbore with a crack-closing
            /// tolerance, or a too strict one, fails the barycentric decision check.
            #[test]
            fn the_checks_reject_wrong_methods() {
                assert!(
                    harness_rejects(sphere_case::<$F>(), CASES, HARNESS_SEED, |c| {
                        check_sphere_surface(&c, |s, r, t_max| textbook_sphere_hit(s, r, 0.0, t_max))
                    }),
                    "the textbook sphere passed the surface check"
                );
                assert!(
                    harness_rejects(tri_case::<$F>(), CASES, HARNESS_SEED, |c| {
                        check_triangle_decision(&c, moller_trumbore_lenient)
                    }),
                    "a lenient Möller–Trumbore passed the decision check"
                );
                assert!(
                    harness_rejects(tri_case::<$F>(), CASES, HARNESS_SEED, |c| {
                        check_triangle_decision(&c, moller_trumbore_strict)
                    }),
                    "a strict Möller–Trumbore passed the decision check"
                );
                // The plain Möller–Trumbore is inexact only at the edges, inside the margins:
                // the decision check accepts it, so it tests decisions, not watertightness.
                assert!(
                    !harness_rejects(tri_case::<$F>(), CASES, HARNESS_SEED, |c| {
                        check_triangle_decision(&c, |t, r| moller_trumbore(t, r, 0.0))
                    }),
                    "the plain Möller–Trumbore failed the decision check"
                );
            }

            #[test]
            fn the_strategies_reach_the_decisive_cases() {
                check_coverage::<$F>();
            }
        }
    };
}

intersection_tests!(single, f32, 0x1_5EC7_0032);
intersection_tests!(double, f64, 0x1_5EC7_0064);
