//! Pearson's χ² test: the statistic, its p-value by the regularised incomplete gamma
//! function, and the suite's significance levels.

use std::f64::consts::TAU;

/// The significance level of every χ² test in the suite: a correct sampler is rejected
/// with probability 10⁻⁶ per test (the seeds are fixed, so a run is reproducible anyway;
/// the level says how unlucky a fixed seed would have to be).
pub const CHI2_ALPHA: f64 = 1e-6;

/// Pearson's statistic `X² = Σ (Oᵢ − Eᵢ)²/Eᵢ` for counts `observed` against equal
/// expected counts (equal-probability bins).
pub fn chi2_equiprobable(observed: &[u64]) -> f64 {
    let total: u64 = observed.iter().sum();
    let expected = total as f64 / observed.len() as f64;
    observed
        .iter()
        .map(|&o| {
            let d = o as f64 - expected;
            d * d / expected
        })
        .sum()
}

/// Pearson's statistic `X² = Σ (Oᵢ − Eᵢ)²/Eᵢ` for counts `observed` against the expected
/// shares `probabilities` (summing to 1) of their total.
pub fn chi2_against(observed: &[u64], probabilities: &[f64]) -> f64 {
    let total: u64 = observed.iter().sum();
    observed
        .iter()
        .zip(probabilities)
        .map(|(&o, &p)| {
            let e = total as f64 * p;
            let d = o as f64 - e;
            d * d / e
        })
        .sum()
}

/// The upper-tail probability `P(χ²_k ≥ x)` of the χ² distribution with `k` degrees of
/// freedom: the regularized upper incomplete gamma function `Q(k/2, x/2)`.
pub fn chi2_sf(x: f64, k: u32) -> f64 {
    gamma_q(f64::from(k) / 2.0, x / 2.0)
}

/// Equal-probability bins of `[0, 1)` for a value `u` (clamped into range, so `u = 1`
/// lands in the last bin).
pub fn bin_of(u: f64, bins: usize) -> usize {
    ((u * bins as f64) as usize).min(bins - 1)
}

/// `ln Γ(a)` for `a > 0`, by Lanczos' approximation (g = 7, 9 terms; relative error
/// ~10⁻¹⁵), with the reflection formula below `a = ½`.
pub fn ln_gamma(a: f64) -> f64 {
    const G: f64 = 7.0;
    const C: [f64; 9] = [
        0.999_999_999_999_809_9,
        676.520_368_121_885_1,
        -1_259.139_216_722_402_8,
        771.323_428_777_653_1,
        -176.615_029_162_140_6,
        12.507_343_278_686_905,
        -0.138_571_095_265_720_12,
        9.984_369_578_019_572e-6,
        1.505_632_735_149_311_6e-7,
    ];
    if a < 0.5 {
        // Γ(a)Γ(1 − a) = π / sin(πa).
        let pi = std::f64::consts::PI;
        return (pi / (pi * a).sin()).ln() - ln_gamma(1.0 - a);
    }
    let a = a - 1.0;
    let mut s = C[0];
    for (i, c) in C.iter().enumerate().skip(1) {
        s += c / (a + i as f64);
    }
    let t = a + G + 0.5;
    0.5 * TAU.ln() + (a + 0.5) * t.ln() - t + s.ln()
}

/// The regularized upper incomplete gamma function `Q(a, x) = Γ(a, x)/Γ(a)`, `a > 0`,
/// `x ≥ 0` (Numerical Recipes §6.2): the series of `P = 1 − Q` below `x = a + 1`, where
/// `Q` is not small, and the continued fraction of `Q` (modified Lentz) above, which keeps
/// full relative accuracy in the far tail.
pub fn gamma_q(a: f64, x: f64) -> f64 {
    assert!(a > 0.0 && x >= 0.0, "gamma_q({a}, {x})");
    if x == 0.0 {
        return 1.0;
    }
    let log_prefactor = a * x.ln() - x - ln_gamma(a);
    if x < a + 1.0 {
        // P(a, x) = e⁻ˣ xᵃ / Γ(a) · Σₙ xⁿ / (a(a+1)…(a+n)).
        let (mut term, mut sum, mut ap) = (1.0 / a, 1.0 / a, a);
        for _ in 0..10_000 {
            ap += 1.0;
            term *= x / ap;
            sum += term;
            if term.abs() < sum.abs() * 1e-17 {
                break;
            }
        }
        1.0 - sum * log_prefactor.exp()
    } else {
        // Q(a, x) = e⁻ˣ xᵃ / Γ(a) · 1/(x + 1 − a − 1·(1 − a)/(x + 3 − a − 2(2 − a)/(x + 5 − a − …))).
        let tiny = 1e-300;
        let mut b = x + 1.0 - a;
        let mut c = 1.0 / tiny;
        let mut d = 1.0 / b;
        let mut h = d;
        for i in 1..10_000 {
            let an = -(i as f64) * (i as f64 - a);
            b += 2.0;
            d = an * d + b;
            if d.abs() < tiny {
                d = tiny;
            }
            c = b + an / c;
            if c.abs() < tiny {
                c = tiny;
            }
            d = 1.0 / d;
            let delta = d * c;
            h *= delta;
            if (delta - 1.0).abs() < 1e-16 {
                break;
            }
        }
        h * log_prefactor.exp()
    }
}

/// The two-sided standard-normal quantile for the suite's significance level
/// [`CHI2_ALPHA`] = 10⁻⁶: `P(|Z| > 4.8916) = 10⁻⁶`.
pub const Z_ALPHA: f64 = 4.891_638_475_698_85;
