//! The refracted direction: unit, Snell's law, coplanar, reversible, critical angle, long normals.

use super::incidences::Incidence;
use super::reflectance::check_reflectances;
use crate::common::*;
use proptest::prelude::*;
use raytrace::optics::{fresnel, refract, schlick_reflectance};
use raytrace::{Float, Vec3};
use twofloat::TwoFloat;

/// The refracted direction has unit length: `| |t| − 1 | ≤ 4(1 + η²)ε`.
///
/// With `t = ηd + (η cos θ₁ − cos θ₂)n`, `|t|² = 1` holds exactly when `cos θ₁ = −d·n`
/// exactly; the rounding of `d·n` (`≤ 1.5ε`) costs only through
/// `∂|t|²/∂cos θ₁ = 2η(η cos θ₁ − cos θ₂)`, at most `2η(1 + η)`, and the error of `sin²θ₂`
/// (a few `η²ε`) passes to `|t|²` one to one (`∂|t|²/∂ sin²θ₂ = 1`, even near the critical
/// angle where `cos θ₂` itself is ill-conditioned). Adding `|d|, |n| ≠ 1` and the rounding
/// of `t`'s components, `|t|² − 1` is a few `(1 + η²)ε`. (Largest seen: `1.4(1 + η²)ε` in
/// f32, `1.5(1 + η²)ε` in f64.)
pub(crate) fn check_unit_length<F: Float>(i: Incidence<F>) -> Result<(), TestCaseError> {
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
pub(crate) fn check_snell<F: Float>(i: Incidence<F>) -> Result<(), TestCaseError> {
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
pub(crate) fn check_coplanar<F: Float>(i: Incidence<F>) -> Result<(), TestCaseError> {
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
pub(crate) fn check_reversal<F: Float>(i: Incidence<F>) -> Result<(), TestCaseError> {
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

/// Total internal reflection happens exactly when `η sin θ₁ ≥ 1`, decided on the actual
/// (rounded) `d`, `n`, `η` in double-double: `q = η²|d×n|²/(|d|²|n|²) − 1`. The library
/// evaluates `η²(1 − cos²θ₁)` in `F` with `cos θ₁` off by `≤ 1.5ε` and `|d||n| = 1 ± 3.5ε`,
/// so its `q` is off by `≤ η²(2·1.5ε + 7ε + 2ε) < 16η²ε`: outside that band the decision must
/// match the exact one, inside it either is right. (Largest seen: transmitted at
/// `q = +2.7η²ε`, totally reflected at `q = −1.7η²ε`; `| |t| − 1 |` up to `1.7(1 + η²)ε`.)
/// Whatever the decision, nothing is NaN or infinite: a transmitted direction is unit
/// length (bound of [`check_unit_length`]) and obeys Snell's law, and under total internal
/// reflection `fresnel` and `schlick_reflectance` both report exactly 1.
pub(crate) fn check_critical_angle<F: Float>(i: Incidence<F>) -> Result<(), TestCaseError> {
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
pub(crate) fn check_inflated_normal<F: Float>(n: Vec3<F>, d: Vec3<F>, eta: F) -> Result<(), TestCaseError> {
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
