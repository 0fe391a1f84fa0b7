//! Property tests of mirror reflection `r = d − 2(d·n)n` ([`raytrace::optics::reflect`]),
//! each written once and run for f32 and f64 with a fixed proptest seed.
//!
//! # Tolerances
//! Inputs are unit vectors rounded to the scalar and normalized in it, so `|n|² = 1 + δ`
//! with `|δ| ≤ 3.5ε` (the squared length is rounded to `γ(3)`, the square root and the
//! division add `ε/2` each, per component, doubled by squaring; 2ε is the largest seen).
//! `reflect` itself rounds `d·n` (error `≤ γ(3)|d||n| ≈ 1.5ε`, so `s = 2d·n` is off by
//! `≤ 3ε`, *along `n`*), then `n·s` and `d − n·s` once per component (a vector of length
//! `≤ ε/2·|s| + ε/2·|r| ≤ 1.5ε`). Each tolerance below adds the terms that reach its
//! property; the checks are evaluated in double-double, so their own rounding is
//! negligible. The largest errors seen over 2·10⁶ random pairs are quoted with each bound:
//! every bound is within a factor 3 of what is reached, so a method that is a few ulps
//! worse (say, one computed in a lower precision, or a normal renormalized badly) fails.

use crate::common;

use common::*;
use proptest::prelude::*;
use raytrace::optics::reflect;
use raytrace::{Float, Vec3};

const REGRESSIONS: &str = "proptest-regressions/reflection.txt";

/// `| |r| − |d| | ≤ 12ε`: exact arithmetic with `|n|² = 1 + δ` gives
/// `|r|² = |d|² + 4(d·n)²δ`, so `|r| − |d| ≤ 2|δ| ≤ 7ε`; the rounding of `r` adds
/// `≤ 3ε + 1.5ε`. (Largest seen: 4.6ε in f32, 4.9ε in f64.)
fn check_length<F: Float>(d: Vec3<F>, n: Vec3<F>) -> Result<(), TestCaseError> {
    let r = reflect(d, n);
    let err = (dd(r).length() - dd(d).length()).to_f64().abs();
    prop_assert!(
        err <= 12.0 * eps::<F>(),
        "| |r| − |d| | = {:.2}ε",
        err / eps::<F>()
    );
    Ok(())
}

/// `|r·n + d·n| ≤ 12ε`: exactly, `r·n = d·n − 2(d·n)|n|² = −d·n(1 + 2δ)`, so the sum is
/// `≤ 2|δ| ≤ 7ε`; the rounding of `r` adds `≤ 4.5ε`. (Largest seen: 4.6ε, 5.0ε.)
fn check_normal_component_flips<F: Float>(d: Vec3<F>, n: Vec3<F>) -> Result<(), TestCaseError> {
    let r = reflect(d, n);
    let err = (dd(r).dot(dd(n)) + dd(d).dot(dd(n))).to_f64().abs();
    prop_assert!(err <= 12.0 * eps::<F>(), "|r·n + d·n| = {:.2}ε", err / eps::<F>());
    Ok(())
}

/// `|reflect(reflect(d, n), n) − d| ≤ 24ε`: exactly, `(I − 2nnᵀ)²d = d + 4δ(n·d)n`, at most
/// `4|δ| ≤ 14ε`; each reflection rounds by `≤ 4.5ε` (the first one's error passes through
/// the second unchanged in length). (Largest seen: 8.4ε, 9.3ε.)
fn check_involution<F: Float>(d: Vec3<F>, n: Vec3<F>) -> Result<(), TestCaseError> {
    let rr = reflect(reflect(d, n), n);
    let err = (dd(rr) - dd(d)).length().to_f64();
    prop_assert!(err <= 24.0 * eps::<F>(), "|rr − d| = {:.2}ε", err / eps::<F>());
    Ok(())
}

/// `|(d − r)×n| ≤ 1.55ε`: exactly `d − r = s·n` for *any* rounded `s`, so the error of
/// `d·n` (along `n`) cancels in the cross product and only the per-component rounding of
/// `n·s` and `d − n·s` is left, `≤ (ε/2)|s| + (ε/2)|r| ≤ 1.5ε(1 + O(ε))`. (Largest seen:
/// 1.00ε, 1.02ε: a `d − r` with any component not along `n` shows up here.)
fn check_difference_along_normal<F: Float>(d: Vec3<F>, n: Vec3<F>) -> Result<(), TestCaseError> {
    let r = reflect(d, n);
    let err = (dd(d) - dd(r)).cross(dd(n)).length().to_f64();
    prop_assert!(err <= 1.55 * eps::<F>(), "|(d − r)×n| = {:.2}ε", err / eps::<F>());
    Ok(())
}

/// `|(d×n)·r| ≤ 1.55ε`: `d`, `n` and `r` are coplanar because `r = d − s·n` lies in the plane
/// of `d` and `n` for any `s`; only the per-component rounding (`≤ 1.5ε`, times
/// `|d×n| ≤ 1`) leaves it. (Largest seen: 0.62ε, 0.65ε.)
fn check_coplanar<F: Float>(d: Vec3<F>, n: Vec3<F>) -> Result<(), TestCaseError> {
    let r = reflect(d, n);
    let err = dd(d).cross(dd(n)).dot(dd(r)).to_f64().abs();
    prop_assert!(err <= 1.55 * eps::<F>(), "|(d×n)·r| = {:.2}ε", err / eps::<F>());
    Ok(())
}

/// `reflect(d, −n) == reflect(d, n)` bit for bit: negating `n` negates `d·n` exactly and the
/// two negations cancel exactly in `n·(2d·n)`, with no rounding difference anywhere.
fn check_sign_symmetry<F: Float>(d: Vec3<F>, n: Vec3<F>) -> Result<(), TestCaseError> {
    prop_assert_eq!(reflect(d, -n), reflect(d, n));
    Ok(())
}

/// Whether `x` is zero or a normal number: scaling by a power of two is exact on it and
/// commutes with rounding.
fn normal_or_zero<F: Float>(x: F) -> bool {
    x == F::zero() || (x.abs() >= F::min_positive_value() && x.is_finite())
}

/// `reflect(2ᵏd, n) == 2ᵏ·reflect(d, n)` bit for bit: every operation of `reflect` is linear
/// in `d`, and a product, sum or difference of scaled operands is the scaled rounded
/// result, as long as nothing underflows into the subnormals or overflows. The test
/// checks that precondition on every intermediate and on both results, and proptest
/// redraws the (rare) inputs that break it, so the claim is tested exactly where it holds.
fn check_power_of_two_scaling<F: Float>(d: Vec3<F>, n: Vec3<F>, k: i32) -> Result<(), TestCaseError> {
    let scale = F::from_f64(2f64.powi(k));
    let scaled = d * scale;
    let s = F::from_f64(2.0) * scaled.dot(n);
    let intermediates = [
        scaled.x * n.x,
        scaled.y * n.y,
        scaled.z * n.z,
        scaled.x * n.x + scaled.y * n.y,
        s,
        n.x * s,
        n.y * s,
        n.z * s,
    ];
    prop_assume!(intermediates.into_iter().all(normal_or_zero::<F>));
    let r = reflect(d, n);
    let ends = [
        scaled.x,
        scaled.y,
        scaled.z,
        r.x * scale,
        r.y * scale,
        r.z * scale,
    ];
    prop_assume!(ends.into_iter().all(normal_or_zero::<F>));
    let lhs = reflect(scaled, n);
    let rhs = r * scale;
    prop_assert_eq!(lhs, rhs, "k = {}", k);
    Ok(())
}

/// Powers of two `k` that keep unit-sized values far from overflow: `|k| ≤ max_exp/4`
/// (32 for f32, 256 for f64).
fn exponent<F: Float>() -> impl Strategy<Value = i32> {
    let max = (F::max_value().to_f64().log2() / 4.0) as i32;
    -max..=max
}

macro_rules! reflection_tests {
    ($name:ident, $F:ty, $seed:expr) => {
        mod $name {
            use super::*;

            proptest! {
                #![proptest_config(config(10_000, $seed, REGRESSIONS))]

                #[test]
                fn preserves_length(d in unit::<$F>(), n in unit::<$F>()) {
                    check_length(d, n)?;
                }

                #[test]
                fn flips_the_normal_component(d in unit::<$F>(), n in unit::<$F>()) {
                    check_normal_component_flips(d, n)?;
                }

                #[test]
                fn is_an_involution(d in unit::<$F>(), n in unit::<$F>()) {
                    check_involution(d, n)?;
                }

                #[test]
                fn changes_only_the_normal_component(d in unit::<$F>(), n in unit::<$F>()) {
                    check_difference_along_normal(d, n)?;
                }

                #[test]
                fn stays_in_the_plane_of_incidence(d in unit::<$F>(), n in unit::<$F>()) {
                    check_coplanar(d, n)?;
                }

                #[test]
                fn ignores_the_sign_of_the_normal(
                    d in unit::<$F>(),
                    n in prop_oneof![unit::<$F>(), inflated_unit::<$F>()],
                ) {
                    check_sign_symmetry(d, n)?;
                }

                #[test]
                fn commutes_with_powers_of_two(d in unit::<$F>(), n in unit::<$F>(), k in exponent::<$F>()) {
                    check_power_of_two_scaling(d, n, k)?;
                }
            }
        }
    };
}

reflection_tests!(single, f32, 0x5EF1_EC71);
reflection_tests!(double, f64, 0x5EF1_EC72);
