//! Reflectance: energy, Fresnel's angle form, normal and grazing incidence, monotony, Schlick's error.

use crate::common::*;
use proptest::prelude::*;
use raytrace::optics::{fresnel, schlick, schlick_reflectance};
use raytrace::{Float, lit};

/// Every reflectance is finite and in `[0, 1]`, also for `cos θ` slightly outside `[0, 1]`.
pub(crate) fn check_reflectances<F: Float>(cos: F, eta: F) -> Result<(), TestCaseError> {
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
pub(crate) fn transmittance<F: Float>(cos1: F, eta: F) -> F {
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
pub(crate) fn check_energy<F: Float>(cos1: F, eta: F) -> Result<(), TestCaseError> {
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
pub(crate) fn check_angle_form<F: Float>(frac: f64, eta: F) -> Result<(), TestCaseError> {
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
pub(crate) fn check_normal_incidence<F: Float>(n1: F, n2: F) -> Result<(), TestCaseError> {
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
pub(crate) fn check_grazing<F: Float>(cos1: F, eta: F) -> Result<(), TestCaseError> {
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
pub(crate) fn reflectance_error_bound<F: Float>(cos1: F, eta: F) -> f64 {
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
pub(crate) fn check_monotone<F: Float>(c_lo: F, c_hi: F, eta: F) -> Result<(), TestCaseError> {
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
pub(crate) fn schlick_worst<F: Float>(eta: f64) -> (f64, f64) {
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
pub(crate) fn check_schlick_error<F: Float>() {
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
