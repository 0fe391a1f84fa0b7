//! Property tests of refraction and reflectance ([`raytrace::optics`]: `refract`, `schlick`,
//! `schlick_reflectance`, `fresnel`), each written once and run for f32 and f64 with a
//! fixed proptest seed.
//!
//! Conventions as in the library: `d` is the incident unit direction, `n` the unit normal
//! on the side `d` comes from (`d·n ≤ 0`), `η = η₁/η₂` the ratio of the refractive indices
//! on the incident and the far side. Indices range over `[1, 2.5]` (air to diamond), so
//! `η ∈ [0.4, 2.5]`.
//!
//! # Tolerances
//! Inputs are rounded to the scalar and normalized in it: `|d|², |n|² = 1 ± 3.5ε`, and the
//! library's `cos θ₁ = −d·n` is off by `≤ γ(3) ≈ 1.5ε`. Each bound below is a first-order
//! error analysis in units of `ε`, scaled by the powers of `η` that multiply the rounded
//! terms; the largest error seen in 2·10⁶ random cases is quoted beside it. Checks are
//! evaluated in double-double, whose own rounding is negligible.

mod common;

use common::*;
use proptest::prelude::*;
use raytrace::optics::{fresnel, refract, schlick, schlick_reflectance};
use raytrace::{Float, Vec3, lit};
use std::f64::consts::{FRAC_PI_2, TAU};
use twofloat::TwoFloat;

const REGRESSIONS: &str = "proptest-regressions/refraction.txt";

/// An incident direction, a normal and a ratio of indices, rounded to `F`.
#[derive(Clone, Copy, Debug)]
struct Incidence<F> {
    d: Vec3<F>,
    n: Vec3<F>,
    eta: F,
}

/// The angle of incidence beyond which no light is transmitted: the critical angle
/// `asin(1/η)` for `η > 1`, grazing (`π/2`) otherwise.
fn max_angle(eta: f64) -> f64 {
    if eta > 1.0 { (1.0 / eta).asin() } else { FRAC_PI_2 }
}

/// Incidences with `θ₁` uniform in `[0, max_frac·θ_max)`, `θ_max` from [`max_angle`], at a
/// random azimuth about a random normal. With `max_frac < 1` the angle stays below the
/// critical one by a margin far above rounding; the critical angle itself is tested apart.
fn incidence<F: Float>(max_frac: f64) -> impl Strategy<Value = Incidence<F>> {
    (unit::<F>(), 0.4f64..2.5, 0.0..max_frac, 0.0..TAU).prop_map(|(n, eta, frac, phi)| {
        let nf = n.to_f64();
        let back = [-nf[0], -nf[1], -nf[2]];
        let d = unit_from::<F>(direction_at(back, frac * max_angle(eta), phi));
        Incidence { d, n, eta: lit(eta) }
    })
}

/// The refracted direction has unit length: `| |t| − 1 | ≤ 4(1 + η²)ε`.
///
/// With `t = ηd + (η cos θ₁ − cos θ₂)n`, `|t|² = 1` holds exactly when `cos θ₁ = −d·n`
/// exactly; the rounding of `d·n` (`≤ 1.5ε`) costs only through
/// `∂|t|²/∂cos θ₁ = 2η(η cos θ₁ − cos θ₂)`, at most `2η(1 + η)`, and the error of `sin²θ₂`
/// (a few `η²ε`) passes to `|t|²` one to one (`∂|t|²/∂ sin²θ₂ = 1`, even near the critical
/// angle where `cos θ₂` itself is ill-conditioned). Adding `|d|, |n| ≠ 1` and the rounding
/// of `t`'s components, `|t|² − 1` is a few `(1 + η²)ε`. (Largest seen: `1.4(1 + η²)ε` in
/// f32, `1.5(1 + η²)ε` in f64.)
fn check_unit_length<F: Float>(i: Incidence<F>) -> Result<(), TestCaseError> {
    let Incidence { d, n, eta } = i;
    let t = refract(d, n, eta);
    if eta <= F::one() {
        prop_assert!(t.is_some(), "no total internal reflection from a rarer medium");
    }
    let Some(t) = t else {
        return Err(TestCaseError::fail("refract failed below the critical angle"));
    };
    let e = eta.to_f64();
    let err = (length_dd(t) - 1.0).abs();
    prop_assert!(
        err <= 4.0 * (1.0 + e * e) * eps::<F>(),
        "| |t| − 1 | = {:.2}(1 + η²)ε",
        err / (1.0 + e * e) / eps::<F>()
    );
    Ok(())
}

/// Snell's law `η₁ sin θ₁ = η₂ sin θ₂`, i.e. `η|d×n| = |t×n|`, within `2.5(1 + η)ε`.
///
/// The tangential part of `t` is `η` times that of `d` (`n×n = 0`), so only rounding enters:
/// `ε/2` each for `ηd`, `n·(η cos θ₁ − cos θ₂)` and the sum (`≤ ε/2·(η + |g| + |t|)`, `|g| ≤ 1 + η`),
/// plus `|n|` and `|d|` off unit by `≤ 1.75ε`, relative. The form with cross products is
/// well conditioned at every angle, unlike `sin θ = √(1 − cos²θ)` near normal incidence.
/// (Largest seen: `0.46(1 + η)ε`, `0.48(1 + η)ε`.)
fn check_snell<F: Float>(i: Incidence<F>) -> Result<(), TestCaseError> {
    let Incidence { d, n, eta } = i;
    let t = refract(d, n, eta).expect("below the critical angle");
    let (dd_, nd, td) = (dd(d), dd(n), dd(t));
    let lhs = dd1(eta) * dd_.cross(nd).length();
    let rhs = td.cross(nd).length();
    let e = eta.to_f64();
    let err = (lhs - rhs).to_f64().abs();
    prop_assert!(
        err <= 2.5 * (1.0 + e) * eps::<F>(),
        "|η sin θ₁ − sin θ₂| = {:.2}(1 + η)ε",
        err / (1.0 + e) / eps::<F>()
    );
    // And the refracted ray goes through the surface, to the far side.
    prop_assert!(td.dot(nd) < TwoFloat::from(0.0));
    Ok(())
}

/// `d`, `n` and `t` are coplanar: `|(d×n)·t| ≤ (1 + η)ε`. `t = ηd + g·n` lies in their plane
/// for any rounded `g`; only the rounding of the components is left,
/// `≤ ε/2·(η + |g| + |t|) ≤ (1 + η)ε`. (Largest seen: `0.48(1 + η)ε`, `0.42(1 + η)ε`.)
fn check_coplanar<F: Float>(i: Incidence<F>) -> Result<(), TestCaseError> {
    let Incidence { d, n, eta } = i;
    let t = refract(d, n, eta).expect("below the critical angle");
    let err = dd(d).cross(dd(n)).dot(dd(t)).to_f64().abs();
    let e = eta.to_f64();
    prop_assert!(
        err <= (1.0 + e) * eps::<F>(),
        "|(d×n)·t| = {:.2}(1 + η)ε",
        err / (1.0 + e) / eps::<F>()
    );
    Ok(())
}

/// Light paths reverse: refracting `−t` back through the same surface (normal `−n`, ratio
/// `1/η`) gives `−d`, within `16(1 + η²)ε / cos θ₁`.
///
/// The tangential part comes back within a few `ε`; the normal part is recovered as
/// `cos θ₁ = √(1 − sin²θ₁)` from a `sin²θ₁` known to a few `(1 + η²)ε`, so its error is that
/// over `2 cos θ₁`: the reversal is ill-conditioned towards grazing incidence, as it is in
/// exact arithmetic, and the bound says by how much. (Largest seen, times `cos θ₁`:
/// `9.9(1 + η²)ε`, `10.2(1 + η²)ε`; without the `1/cos θ₁` factor the error reaches
/// `2700(1 + η²)ε` at `θ₁ = 0.999·90°`, so a constant tolerance would be either too tight or
/// far too weak near normal incidence.)
fn check_reversal<F: Float>(i: Incidence<F>) -> Result<(), TestCaseError> {
    let Incidence { d, n, eta } = i;
    let t = refract(d, n, eta).expect("below the critical angle");
    let back = refract(-t, -n, F::one() / eta);
    prop_assert!(back.is_some(), "the reverse path is totally reflected");
    let back = back.unwrap();
    let cos1 = -d.dot(n).to_f64();
    let e = eta.to_f64();
    let err = (dd(back) + dd(d)).length().to_f64();
    prop_assert!(
        err * cos1 <= 16.0 * (1.0 + e * e) * eps::<F>(),
        "|back + d|·cos θ₁ = {:.2}(1 + η²)ε",
        err * cos1 / (1.0 + e * e) / eps::<F>()
    );
    Ok(())
}

/// Incidences within a relative distance `10⁻¹..10⁻¹⁶` of the critical angle `θ_c`, on both
/// sides (`θ_c(1 − rel)` below, `θ_c + rel·(π/2 − θ_c)` above, so the ray never passes
/// grazing), `η ∈ (1, 2.5]` (light leaving the denser medium); in f32 the closest cases
/// fall on either side by rounding alone.
fn near_critical<F: Float>() -> impl Strategy<Value = Incidence<F>> {
    (unit::<F>(), 1.0001f64..2.5, 1.0f64..16.0, any::<bool>(), 0.0..TAU).prop_map(
        |(n, eta, k, above, phi)| {
            let nf = n.to_f64();
            let back = [-nf[0], -nf[1], -nf[2]];
            let crit = (1.0 / eta).asin();
            let rel = 10f64.powf(-k);
            let theta = if above {
                crit + rel * (FRAC_PI_2 - crit)
            } else {
                crit * (1.0 - rel)
            };
            let d = unit_from::<F>(direction_at(back, theta, phi));
            Incidence { d, n, eta: lit(eta) }
        },
    )
}

/// Total internal reflection happens exactly when `η sin θ₁ ≥ 1`, decided on the actual
/// (rounded) `d`, `n`, `η` in double-double: `q = η²|d×n|²/(|d|²|n|²) − 1`. The library
/// evaluates `η²(1 − cos²θ₁)` in `F` with `cos θ₁` off by `≤ 1.5ε` and `|d||n| = 1 ± 3.5ε`,
/// so its `q` is off by `≤ η²(2·1.5ε + 7ε + 2ε) < 16η²ε`: outside that band the decision must
/// match the exact one, inside it either is right. (Largest seen: transmitted at
/// `q = +2.7η²ε`, totally reflected at `q = −1.7η²ε`; `| |t| − 1 |` up to `1.7(1 + η²)ε`.)
/// Whatever the decision, nothing is NaN or infinite: a transmitted direction is unit
/// length (bound of [`check_unit_length`]) and obeys Snell's law, and under total internal
/// reflection `fresnel` and `schlick_reflectance` both report exactly 1.
fn check_critical_angle<F: Float>(i: Incidence<F>) -> Result<(), TestCaseError> {
    let Incidence { d, n, eta } = i;
    let (dd_, nd) = (dd(d), dd(n));
    let e = eta.to_f64();
    let q = (dd1(eta) * dd1(eta) * dd_.cross(nd).length_squared()
        / (dd_.length_squared() * nd.length_squared())
        - TwoFloat::from(1.0))
    .to_f64();
    let band = 16.0 * e * e * eps::<F>();
    let t = refract(d, n, eta);
    let cos1 = -d.dot(n);
    let (rf, rs) = (fresnel(cos1, eta), schlick_reflectance(cos1, eta));
    prop_assert!(rf.is_finite() && rs.is_finite());
    prop_assert!((F::zero()..=F::one()).contains(&rf) && (F::zero()..=F::one()).contains(&rs));
    match t {
        None => {
            prop_assert!(q > -band, "TIR below the critical angle: η sin θ − 1 ≈ {q:e}");
            prop_assert!(rf == F::one() && rs == F::one(), "R = {rf}, {rs} under TIR");
        }
        Some(t) => {
            prop_assert!(
                q < band,
                "transmitted past the critical angle: η sin θ − 1 ≈ {q:e}"
            );
            prop_assert!(t.is_finite());
            let err = (length_dd(t) - 1.0).abs();
            prop_assert!(err <= 4.0 * (1.0 + e * e) * eps::<F>(), "| |t| − 1 | = {err:e}");
            let snell = (dd1(eta) * dd_.cross(nd).length() - dd(t).cross(nd).length()).to_f64();
            prop_assert!(
                snell.abs() <= 2.5 * (1.0 + e) * eps::<F>(),
                "Snell off by {snell:e}"
            );
        }
    }
    Ok(())
}

/// Normals whose squared length rounds above 1 (and exact normal incidence) produce no NaN
/// or infinity: `cos θ₁ = −d·n` may exceed 1, where unclamped code would take
/// `√(1 − cos²θ₁)` of a negative number. At normal incidence, `d = −n/|n|` passes straight
/// through, and every reflectance is finite and in `[0, 1]`. With `cos θ₁` clamped to exactly
/// 1, `t = ηd + (η − 1)n`, so `|t − d| ≤ |η − 1|·| |n| − 1 | + ε/2·(η + |η − 1| + 1)
/// ≤ 1.5·2ε + 2.5ε < 8ε` (largest seen: 3.8ε in f32, 3.7ε in f64). At other incidences `t` is
/// unit within twice the bound of [`check_unit_length`], `|n|` being off by up to twice as
/// much.
fn check_inflated_normal<F: Float>(n: Vec3<F>, d: Vec3<F>, eta: F) -> Result<(), TestCaseError> {
    prop_assert!(n.length_squared() > F::one());
    // Normal incidence, with the incident direction unit (d₀) or as inflated as n (−n).
    let d0 = -n / n.length();
    for dir in [d0, -n] {
        let t = refract(dir, n, eta);
        prop_assert!(t.is_some(), "TIR at normal incidence");
        let t = t.unwrap();
        prop_assert!(t.is_finite());
        prop_assert!(
            (dd(t) - dd(dir)).length().to_f64() <= 8.0 * eps::<F>(),
            "{t:?} vs {dir:?}"
        );
        check_reflectances(-dir.dot(n), eta)?;
    }
    // Any other incidence on the same normal.
    let d = if d.dot(n) > F::zero() { -d } else { d };
    if let Some(t) = refract(d, n, eta) {
        prop_assert!(t.is_finite());
        let e = eta.to_f64();
        let err = (length_dd(t) - 1.0).abs();
        prop_assert!(err <= 8.0 * (1.0 + e * e) * eps::<F>(), "| |t| − 1 | = {err:e}");
    }
    check_reflectances(-d.dot(n), eta)
}

/// Every reflectance is finite and in `[0, 1]`, also for `cos θ` slightly outside `[0, 1]`.
fn check_reflectances<F: Float>(cos: F, eta: F) -> Result<(), TestCaseError> {
    for (name, r) in [
        ("fresnel", fresnel(cos, eta)),
        ("schlick_reflectance", schlick_reflectance(cos, eta)),
        ("schlick", schlick(cos, eta)),
    ] {
        prop_assert!(
            r.is_finite() && r >= F::zero() && r <= F::one(),
            "{name}({cos}, {eta}) = {r}"
        );
    }
    Ok(())
}

/// The transmittance of power, computed the physical way from Fresnel's amplitude
/// transmission coefficients (the test's own formula, not `1 − R`):
///
/// `t_s = 2η cos θ₁/(η cos θ₁ + cos θ₂)`, `t_p = 2η cos θ₁/(cos θ₁ + η cos θ₂)`,
/// `T = (η₂ cos θ₂)/(η₁ cos θ₁)·(t_s² + t_p²)/2 = cos θ₂/(η cos θ₁)·(t_s² + t_p²)/2`
///
/// (the factor is the ratio of beam cross-sections times the ratio of impedances; with it
/// `r_s² + T_s = 1` and `r_p² + T_p = 1` hold identically, for any `cos θ₂`). `cos θ₂` is the
/// library's own `√(1 − η²(1 − cos²θ₁))`, evaluated in `F` the same way, so the check is
/// about the Fresnel algebra and not about the conditioning of `cos θ₂` at the critical
/// angle (tested above). Returns 0 under total internal reflection and at grazing.
fn transmittance<F: Float>(cos1: F, eta: F) -> F {
    // The library's contract: cos θ₁ outside [0, 1] is clamped.
    let cos1 = cos1.max(F::zero()).min(F::one());
    let sin2_t = eta * eta * (F::one() - cos1 * cos1);
    if sin2_t >= F::one() || cos1 == F::zero() {
        return F::zero();
    }
    let cos2 = (F::one() - sin2_t).sqrt();
    let two = lit::<F>(2.0);
    let ts = two * eta * cos1 / (eta * cos1 + cos2);
    let tp = two * eta * cos1 / (cos1 + eta * cos2);
    cos2 / (eta * cos1) * (ts * ts + tp * tp) / two
}

/// Energy is conserved: `R + T = 1` within `16ε`, for every angle and `η`, including total
/// internal reflection (`R = 1`, `T = 0`). `R` and `T` each carry a relative error of a
/// few `ε` (about six roundings each, the largest terms of size 1), so their sum is within
/// `16ε` of 1. (Largest seen: 3.3ε in f32, 3.0ε in f64.)
fn check_energy<F: Float>(cos1: F, eta: F) -> Result<(), TestCaseError> {
    let r = fresnel(cos1, eta);
    let t = transmittance(cos1, eta);
    prop_assert!(r >= F::zero() && t >= F::zero());
    let err = (r.to_f64() + t.to_f64() - 1.0).abs();
    prop_assert!(
        err <= 16.0 * eps::<F>(),
        "|R + T − 1| = {:.2}ε (R = {r}, T = {t})",
        err / eps::<F>()
    );
    check_reflectances(cos1, eta)
}

/// `fresnel` agrees with the angle form of Fresnel's equations, an independent formula:
/// `R_s = sin²(θ₁ − θ₂)/sin²(θ₁ + θ₂)`, `R_p = tan²(θ₁ − θ₂)/tan²(θ₁ + θ₂)`, evaluated in
/// f64 from the same (rounded) `cos θ₁` and `η`, away from normal incidence (where it is
/// 0/0) and from the critical angle (where `R` has an infinite derivative): `θ₁` is the
/// fraction `frac` of the way from 0.5° to the smaller of 89.5° and `asin(0.99/η)`.
/// Tolerance `64ε`: with `cos θ₂ ≥ 0.14` there, `R`'s sensitivity to the rounding of
/// `cos θ₂` is below ~30, so the library's `R` is within a few dozen `ε`; the f64 reference
/// is exact for f32's purposes and within ~10ε of its own for f64. (Largest seen over
/// 2·10⁶ cases: 12ε in f32, 20ε in f64, the reference's error included.)
fn check_angle_form<F: Float>(frac: f64, eta: F) -> Result<(), TestCaseError> {
    let e = eta.to_f64();
    let (lo, hi) = (0.5f64.to_radians(), 89.5f64.to_radians().min((0.99 / e).asin()));
    let c = lit::<F>((lo + frac * (hi - lo)).cos());
    let t1 = c.to_f64().acos();
    prop_assert!(e * t1.sin() <= 0.99 + 4.0 * eps::<F>());
    let t2 = (e * t1.sin()).asin();
    let rs = ((t1 - t2).sin() / (t1 + t2).sin()).powi(2);
    let rp = ((t1 - t2).tan() / (t1 + t2).tan()).powi(2);
    let reference = (rs + rp) / 2.0;
    let r = fresnel(c, eta).to_f64();
    prop_assert!(
        (r - reference).abs() <= 64.0 * eps::<F>(),
        "fresnel = {r}, angle form = {reference}"
    );
    Ok(())
}

/// At normal incidence every reflectance is `R₀ = ((n₁ − n₂)/(n₁ + n₂))²`, within `2ε`
/// absolute. `η = n₁/n₂` is rounded once (relative `ε/2`), which moves `R₀` by
/// `≤ η|∂R₀/∂η|·ε/2 = 4η|1 − η|/(1 + η)³·ε/2 ≤ 0.3ε`; at `cos θ₁ = 1` all three functions
/// reduce to `r² `, `r = (1 − η)/(1 + η)` (Fresnel's `sin²θ₂` is exactly 0), whose roundings
/// cost `≤ 3.5ε` relative, `≤ 0.65ε` absolute for `R₀ ≤ 0.18`: about `1ε` in all, doubled.
/// (The check is absolute because near `n₁ = n₂` the relative error of `R₀ ≈ 0` is
/// unbounded.) `R₀` is computed from `n₁` and `n₂` in double-double. (Largest seen: 0.44ε
/// in f32, 0.5ε in f64.)
fn check_normal_incidence<F: Float>(n1: F, n2: F) -> Result<(), TestCaseError> {
    let eta = n1 / n2;
    let r0 = ((dd1(n1) - dd1(n2)) / (dd1(n1) + dd1(n2))).powi(2).to_f64();
    for (name, r) in [
        ("fresnel", fresnel(F::one(), eta)),
        ("schlick_reflectance", schlick_reflectance(F::one(), eta)),
        ("schlick", schlick(F::one(), eta)),
    ] {
        let err = (r.to_f64() - r0).abs();
        prop_assert!(
            err <= 2.0 * eps::<F>(),
            "{name}: {r} vs R₀ = {r0} ({:.2}ε)",
            err / eps::<F>()
        );
    }
    Ok(())
}

/// `R → 1` at grazing incidence: exactly 1 at `cos θ₁ = 0`, and linearly near it.
///
/// From a rarer medium (`η < 1`): with `x = η cos θ₁/cos θ₂` and `y = cos θ₁/(η cos θ₂)`,
/// `1 − r_s² = 4x/(1 + x)² ≤ 4x` and `1 − r_p² ≤ 4y`, and `cos θ₂ ≥ cos θ₂⁰ = √(1 − η²)`, so
/// `1 − R ≤ 2(η + 1/η)·cos θ₁/cos θ₂⁰` holds exactly, at every angle (its first-order term
/// is the same, so the bound is tight as `cos θ₁ → 0`). Schlick's
/// `1 − R = (1 − R₀)(1 − (1 − cos θ₁)⁵) ≤ 5(1 − R₀)cos θ₁` (Bernoulli). Both plus `4ε` for
/// rounding. From a denser medium (`η > 1`) grazing is past the critical angle, and there
/// (outside the rounding band of [`check_critical_angle`]) `R = 1` exactly.
fn check_grazing<F: Float>(cos1: F, eta: F) -> Result<(), TestCaseError> {
    prop_assert_eq!(fresnel(F::zero(), eta), F::one());
    prop_assert_eq!(schlick_reflectance(F::zero(), eta), F::one());
    let (c, e, u) = (cos1.to_f64(), eta.to_f64(), eps::<F>());
    let (rf, rs) = (
        fresnel(cos1, eta).to_f64(),
        schlick_reflectance(cos1, eta).to_f64(),
    );
    if e * e * (1.0 - c * c) - 1.0 > 16.0 * e * e * u {
        prop_assert!(rf == 1.0 && rs == 1.0, "R = {rf}, {rs} past the critical angle");
    } else if e < 1.0 {
        let slope = 2.0 * (e + 1.0 / e) / (1.0 - e * e).sqrt();
        prop_assert!(
            1.0 - rf <= slope * c + 4.0 * u,
            "1 − R = {} > {}",
            1.0 - rf,
            slope * c
        );
        let r0 = ((1.0 - e) / (1.0 + e)).powi(2);
        prop_assert!(1.0 - rs <= 5.0 * (1.0 - r0) * c + 4.0 * u, "1 − R = {}", 1.0 - rs);
    }
    Ok(())
}

/// A first-order bound on the rounding error of `fresnel(cos θ₁, η)` (and of
/// `schlick_reflectance`, which has the same structure): `4ε` for the final arithmetic, plus
/// the error of `cos θ₂` times the sensitivity of `R` to it.
///
/// `sin²θ₂ = η²(1 − cos²θ₁)` is computed with an absolute error `≤ 1.5η²ε`, so
/// `cos θ₂ = √(1 − sin²θ₂)` is off by `≤ 0.75η²ε/cos θ₂ + ε` (and never by more than
/// `√(1.5η²ε)`): near the critical angle `cos θ₂ → 0` and this grows without bound, as the
/// conditioning of Snell's law says it must. `|∂R/∂cos θ₂| ≤ 2η cos θ₁/(η cos θ₁ + cos θ₂)²
/// + 2η cos θ₁/(cos θ₁ + η cos θ₂)²` (from `R = (r_s² + r_p²)/2`, `|r| ≤ 1`). The bound is
/// doubled for safety (and at least 5, the slope of Schlick's `(1 − cos θ₂)⁵`, for
/// `schlick_reflectance`); under total internal reflection `R = 1` exactly.
fn reflectance_error_bound<F: Float>(cos1: F, eta: F) -> f64 {
    let (c, e, u) = (cos1.to_f64(), eta.to_f64(), eps::<F>());
    let sin2 = e * e * (1.0 - c * c);
    if sin2 >= 1.0 {
        return 4.0 * u;
    }
    let ct = (1.0 - sin2).sqrt();
    let dct = (0.75 * e * e * u / ct).min((1.5 * e * e * u).sqrt()) + u;
    let sens = 2.0 * e * c / (e * c + ct).powi(2) + 2.0 * e * c / (c + e * ct).powi(2);
    // Schlick's polynomial (1 − cos θ₂)⁵ has slope ≤ 5 in cos θ₂.
    4.0 * u + 2.0 * sens.max(5.0) * dct
}

/// `R` grows with the angle of incidence: for `cos θ ≤ cos θ'`, `R(θ) ≥ R(θ')` up to the
/// rounding error of the two values ([`reflectance_error_bound`]), for `fresnel` and
/// `schlick_reflectance`, from either side (`η < 1` and `η > 1`). The unpolarized Fresnel
/// reflectance is monotone although `R_p` alone dips to 0 at Brewster's angle (a dip of
/// `R₀ ≈ 0.04` that no rounding allowance hides). Two cosines a few ulps apart near the
/// critical angle are where rounding matters: proptest found `R` decreasing by `4.8ε` in
/// f32 at `η = 1.00087`, `cos θ₁ = 0.0579` (`cos θ₂ = 0.04`), where the bound is `~900ε`;
/// away from it the allowance is a few `ε`.
fn check_monotone<F: Float>(c_lo: F, c_hi: F, eta: F) -> Result<(), TestCaseError> {
    prop_assert!(c_lo <= c_hi);
    let slack = reflectance_error_bound(c_lo, eta) + reflectance_error_bound(c_hi, eta);
    for (name, f) in [
        ("fresnel", fresnel::<F> as fn(F, F) -> F),
        ("schlick_reflectance", schlick_reflectance::<F>),
    ] {
        let (r_lo, r_hi) = (f(c_lo, eta).to_f64(), f(c_hi, eta).to_f64());
        prop_assert!(
            r_lo >= r_hi - slack,
            "{name}: R(cos {c_lo}) = {r_lo} < R(cos {c_hi}) = {r_hi} by {:.2}ε",
            (r_hi - r_lo) / eps::<F>()
        );
    }
    Ok(())
}

/// The largest absolute error of `schlick_reflectance` against `fresnel` for `n = 1.5`,
/// over 10⁵ + 1 cosines evenly spaced in `[0, 1]`: `(error, cos θ₁)`.
fn schlick_worst<F: Float>(eta: f64) -> (f64, f64) {
    let eta = lit::<F>(eta);
    let steps = 100_000;
    (0..=steps)
        .map(|i| {
            let c = lit::<F>(f64::from(i) / f64::from(steps));
            let err = (schlick_reflectance(c, eta) - fresnel(c, eta)).abs().to_f64();
            (err, c.to_f64())
        })
        .fold((0.0, 0.0), |a, b| if b.0 > a.0 { b } else { a })
}

/// Schlick's approximation against exact Fresnel for glass, `n = 1.5`, entering (`η = 1/1.5`)
/// and leaving (`η = 1.5`). Measured: the largest error is 0.03569 both ways — at
/// `θ₁ ≈ 85°` entering and at `θ₁ ≈ 41.6°` leaving (the same ray reversed: 41.6° inside is
/// 85° outside), because `schlick_reflectance` evaluates Schlick at the angle in the rarer
/// medium and Fresnel is reciprocal. Asserted as `0.035 ≤ error ≤ 0.0357`, so both a worse
/// approximation and a silently "exact" one are caught. The raw formula [`schlick`] at the
/// *incident* angle is no approximation at all when leaving: its error exceeds 0.5 near the
/// critical angle (R jumps to 1 there, Schlick's polynomial does not).
fn check_schlick_error<F: Float>() {
    for (eta, at) in [(1.0 / 1.5, 85.0f64), (1.5, 41.6)] {
        let (err, c) = schlick_worst::<F>(eta);
        assert!(
            (0.035..=0.0357).contains(&err),
            "{}: η = {eta}: max |Schlick − Fresnel| = {err} at cos θ = {c}",
            F::NAME
        );
        let deg = c.acos().to_degrees();
        assert!((deg - at).abs() < 0.5, "worst at {deg}°, expected ~{at}°");
    }
    let eta = lit::<F>(1.5);
    let raw = (0..=10_000)
        .map(|i| {
            let c = lit::<F>(f64::from(i) / 1e4);
            (schlick(c, eta) - fresnel(c, eta)).abs().to_f64()
        })
        .fold(0.0, f64::max);
    assert!(
        raw > 0.5,
        "{}: raw Schlick leaving glass errs by only {raw}",
        F::NAME
    );
}

macro_rules! refraction_tests {
    ($name:ident, $F:ty, $seed:expr) => {
        mod $name {
            use super::*;

            proptest! {
                #![proptest_config(config(10_000, $seed, REGRESSIONS))]

                #[test]
                fn refracted_direction_is_unit(i in incidence::<$F>(0.999)) {
                    check_unit_length(i)?;
                }

                #[test]
                fn obeys_snells_law(i in incidence::<$F>(0.999)) {
                    check_snell(i)?;
                }

                #[test]
                fn stays_in_the_plane_of_incidence(i in incidence::<$F>(0.999)) {
                    check_coplanar(i)?;
                }

                #[test]
                fn reverses(i in incidence::<$F>(0.99)) {
                    check_reversal(i)?;
                }

                #[test]
                fn total_internal_reflection_exactly_past_the_critical_angle(i in near_critical::<$F>()) {
                    check_critical_angle(i)?;
                }

                #[test]
                fn no_nan_with_normals_longer_than_one(
                    n in inflated_unit::<$F>(),
                    d in unit::<$F>(),
                    eta in 0.4f64..2.5,
                ) {
                    check_inflated_normal(n, d, lit::<$F>(eta))?;
                }

                #[test]
                fn reflectance_plus_transmittance_is_one(c in -0.01f64..=1.01, eta in 0.4f64..2.5) {
                    check_energy(lit::<$F>(c), lit::<$F>(eta))?;
                }

                #[test]
                fn fresnel_matches_the_angle_form(frac in 0.0f64..=1.0, eta in 0.4f64..2.5) {
                    check_angle_form(frac, lit::<$F>(eta))?;
                }

                #[test]
                fn normal_incidence_reflectance(n1 in 1.0f64..2.5, n2 in 1.0f64..2.5) {
                    check_normal_incidence(lit::<$F>(n1), lit::<$F>(n2))?;
                }

                #[test]
                fn reflectance_tends_to_one_at_grazing(k in 0.0f64..12.0, eta in 0.4f64..2.5) {
                    check_grazing(lit::<$F>(10f64.powf(-k)), lit::<$F>(eta))?;
                }

                #[test]
                fn reflectance_grows_with_the_angle(
                    a in 0.0f64..=1.0,
                    gap in prop_oneof![0.0f64..1.0, (1.0f64..12.0).prop_map(|k| 10f64.powf(-k))],
                    eta in 0.4f64..2.5,
                ) {
                    let (lo, hi) = (a, (a + gap).min(1.0));
                    check_monotone(lit::<$F>(lo), lit::<$F>(hi), lit::<$F>(eta))?;
                }
            }

            #[test]
            fn schlick_error_against_fresnel_is_bounded() {
                check_schlick_error::<$F>();
            }
        }
    };
}

refraction_tests!(single, f32, 0x5EF2_AC71);
refraction_tests!(double, f64, 0x5EF2_AC72);
