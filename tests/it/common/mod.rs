//! Shared helpers of the optics, sampling and stability tests: proptest configuration and
//! strategies (unit vectors, normals whose squared length rounds above 1), scalar-generic
//! helpers, a double-double reference, a counting RNG, and Pearson's χ² with its p-value.
//!
//! Every strategy draws in `f64` and rounds to the scalar under test, so the f32 and f64
//! instances of a test see the same geometry (as the library's own sampling does).

// Each test binary includes this module and uses only part of it.
#![allow(dead_code)]

pub mod bsdf;
pub mod draws;
pub mod sphere_chi2;

use proptest::prelude::*;
use proptest::test_runner::{FileFailurePersistence, RngSeed, TestRunner};
use rand::TryRng;
use raytrace::{Float, Vec3};
use std::convert::Infallible;
use std::f64::consts::TAU;
use twofloat::TwoFloat;

/// A proptest configuration with a fixed seed, so every run tests the same cases, and with
/// failures persisted under `proptest-regressions/` (`file` is the path from the package
/// root, e.g. `"proptest-regressions/reflection.txt"`; integration tests run there).
pub fn config(cases: u32, seed: u64, file: &'static str) -> ProptestConfig {
    ProptestConfig {
        cases,
        rng_seed: RngSeed::Fixed(seed),
        failure_persistence: Some(Box::new(FileFailurePersistence::Direct(file))),
        ..ProptestConfig::default()
    }
}

/// Whether a property run fails: the power checks run a test against a deliberately
/// wrong method and require this. Fixed `seed`, no shrinking, no regression file.
pub fn harness_rejects<S: Strategy>(
    strategy: S,
    cases: u32,
    seed: u64,
    test: impl Fn(S::Value) -> Result<(), TestCaseError>,
) -> bool {
    let mut runner = TestRunner::new(ProptestConfig {
        cases,
        rng_seed: RngSeed::Fixed(seed),
        failure_persistence: None,
        max_shrink_iters: 0,
        ..ProptestConfig::default()
    });
    runner.run(&strategy, test).is_err()
}

/// The scalar's machine epsilon (`2⁻²³` for f32, `2⁻⁵²` for f64) as an `f64`.
pub fn eps<F: Float>() -> f64 {
    F::epsilon().to_f64()
}

/// A vector converted exactly to double-double (exact for f32 and f64 components).
pub fn dd<F: Float>(v: Vec3<F>) -> Vec3<TwoFloat> {
    v.cast()
}

/// A scalar converted exactly to double-double.
pub fn dd1<F: Float>(x: F) -> TwoFloat {
    TwoFloat::from(x.to_f64())
}

/// `|v|` evaluated in double-double, as an `f64`: a reference length whose own rounding
/// (~10⁻³²) is negligible against the f64 errors under test.
pub fn length_dd<F: Float>(v: Vec3<F>) -> f64 {
    dd(v).length().to_f64()
}

/// A uniformly distributed unit vector in `f64` (Archimedes: `z` uniform in `[−1, 1]`).
pub fn unit_f64() -> impl Strategy<Value = [f64; 3]> {
    (-1.0f64..=1.0, 0.0f64..TAU).prop_map(|(z, phi)| {
        let s = (1.0 - z * z).max(0.0).sqrt();
        [s * phi.cos(), s * phi.sin(), z]
    })
}

/// The six axis directions `±x, ±y, ±z`, where components are exactly 0 and 1.
pub fn axis<F: Float>() -> impl Strategy<Value = Vec3<F>> {
    (0usize..3, any::<bool>()).prop_map(|(i, neg)| {
        let mut v = [0.0; 3];
        v[i] = if neg { -1.0 } else { 1.0 };
        Vec3::from_f64(v[0], v[1], v[2])
    })
}

/// A unit vector of `F`: one of the axes (1 case in 8) or a uniformly random direction
/// rounded to `F` and normalized in `F` (so `| |v| − 1 |` is a few `ε`, as for the
/// normals a renderer computes).
pub fn unit<F: Float>() -> impl Strategy<Value = Vec3<F>> {
    prop_oneof![
        1 => axis::<F>(),
        7 => unit_f64().prop_map(|[x, y, z]| Vec3::<F>::from_f64(x, y, z).normalize()),
    ]
}

/// `n` with its largest component moved away from zero one representable value at a time
/// until `|n|²`, *as computed in `F`*, is above 1: a "unit" normal whose squared length
/// rounds above 1, the input that makes `1 − cos²θ` negative in unclamped code.
pub fn inflate<F: Float>(mut n: Vec3<F>) -> Vec3<F> {
    while n.length_squared() <= F::one() {
        let (ax, ay, az) = (n.x.abs(), n.y.abs(), n.z.abs());
        let away = |c: F| {
            if c >= F::zero() {
                c.next_up()
            } else {
                c.next_down()
            }
        };
        if ax >= ay && ax >= az {
            n.x = away(n.x);
        } else if ay >= az {
            n.y = away(n.y);
        } else {
            n.z = away(n.z);
        }
    }
    n
}

/// A unit normal of `F` whose squared length, computed in `F`, exceeds 1 (see [`inflate`]).
pub fn inflated_unit<F: Float>() -> impl Strategy<Value = Vec3<F>> {
    unit::<F>().prop_map(inflate)
}

/// An orthonormal frame `(t, b)` completing the unit `n` (computed here, in `f64`, by
/// Gram–Schmidt against the axis least aligned with `n`, independently of the library's
/// `orthonormal_basis`).
pub fn frame(n: [f64; 3]) -> ([f64; 3], [f64; 3]) {
    let a = if n[0].abs() <= n[1].abs() && n[0].abs() <= n[2].abs() {
        [1.0, 0.0, 0.0]
    } else if n[1].abs() <= n[2].abs() {
        [0.0, 1.0, 0.0]
    } else {
        [0.0, 0.0, 1.0]
    };
    let an = dot(a, n);
    let t = normalize([a[0] - an * n[0], a[1] - an * n[1], a[2] - an * n[2]]);
    let b = cross(n, t);
    (t, b)
}

/// `a·b` in `f64`.
pub fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// `a×b` in `f64`.
pub fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// `a/|a|` in `f64`.
pub fn normalize(a: [f64; 3]) -> [f64; 3] {
    let l = dot(a, a).sqrt();
    [a[0] / l, a[1] / l, a[2] / l]
}

/// The unit direction at polar angle `theta` from the unit `n` and azimuth `phi` in the
/// frame of [`frame`], in `f64`: `cos θ·n + sin θ (cos φ·t + sin φ·b)`.
pub fn direction_at(n: [f64; 3], theta: f64, phi: f64) -> [f64; 3] {
    let (t, b) = frame(n);
    let (s, c) = theta.sin_cos();
    let (sp, cp) = phi.sin_cos();
    std::array::from_fn(|i| c * n[i] + s * (cp * t[i] + sp * b[i]))
}

/// A vector of `F` from `f64` components, normalized in `F`.
pub fn unit_from<F: Float>(v: [f64; 3]) -> Vec3<F> {
    Vec3::<F>::from_f64(v[0], v[1], v[2]).normalize()
}

/// A random number generator that counts the words it hands out, to measure how many
/// draws a sampler consumes (e.g. the acceptance rate of a rejection loop).
pub struct CountingRng<R> {
    /// The wrapped generator.
    pub inner: R,
    /// `next_u64` calls (one per `f64` draw with rand's `StandardUniform`).
    pub u64s: u64,
    /// `next_u32` and `fill_bytes` calls: expected to stay 0 for the samplers tested.
    pub others: u64,
}

impl<R> CountingRng<R> {
    /// Wraps `inner` with zeroed counters.
    pub fn new(inner: R) -> Self {
        Self {
            inner,
            u64s: 0,
            others: 0,
        }
    }
}

impl<R: rand::Rng> TryRng for CountingRng<R> {
    type Error = Infallible;
    fn try_next_u32(&mut self) -> Result<u32, Infallible> {
        self.others += 1;
        Ok(self.inner.next_u32())
    }
    fn try_next_u64(&mut self) -> Result<u64, Infallible> {
        self.u64s += 1;
        Ok(self.inner.next_u64())
    }
    fn try_fill_bytes(&mut self, dst: &mut [u8]) -> Result<(), Infallible> {
        self.others += 1;
        self.inner.fill_bytes(dst);
        Ok(())
    }
}

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

#[test]
fn chi2_sf_matches_tables_and_closed_forms() {
    // Even k: Q(m, y) = e^{−y} Σ_{i<m} yⁱ/i! exactly; checked deep into the tail, where
    // the χ² tests decide (relative error, so a tail of 10⁻⁵⁰ is checked as well as 0.5).
    for k in [2u32, 4, 10, 20, 50, 120] {
        for x in [0.5, 3.0, 10.0, 30.0, 100.0, 300.0] {
            let (m, y) = (k / 2, x / 2.0);
            let mut term = 1.0;
            let mut sum = 0.0;
            for i in 0..m {
                if i > 0 {
                    term *= y / f64::from(i);
                }
                sum += term;
            }
            let exact = (-y).exp() * sum;
            let got = chi2_sf(x, k);
            assert!(
                (got - exact).abs() <= 1e-12 * exact,
                "k={k} x={x}: {got:e} vs {exact:e}"
            );
        }
    }
    // Published critical values (odd and even k; NIST/SEMATECH e-Handbook table 1.3.6.7.4,
    // given to 3–4 decimals, hence the 10⁻³ relative tolerance).
    let table = [
        (1, 3.841, 0.05),
        (1, 10.828, 0.001),
        (5, 11.070, 0.05),
        (5, 0.554, 0.99),
        (9, 21.666, 0.01),
        (19, 30.144, 0.05),
        (99, 123.225, 0.05),
        (99, 148.230, 0.001),
    ];
    for (k, x, p) in table {
        let got = chi2_sf(x, k);
        assert!((got - p).abs() <= 1e-3 * p, "k={k} x={x}: {got} vs {p}");
    }
    // k = 1: Q(½, x/2) = erfc(√(x/2)); erfc(√(23.928/2)) ≈ 1.0·10⁻⁶ at the critical value
    // of the suite's significance level.
    let p = chi2_sf(23.928_127, 1);
    assert!((p - 1e-6).abs() < 1e-9, "{p:e}");
    assert_eq!(chi2_sf(0.0, 3), 1.0);
}

/// The nearest `t` and its record at once, and the any-hit query, on a shape alone (the
/// trait asks the scene's questions only). No surface coordinates: the record a scene makes
/// for a material that reads none.
pub trait Alone<F: Float>: raytrace::Hittable<F> {
    fn hit(&self, ray: &raytrace::Ray<F>, t_max: F) -> Option<raytrace::Hit<F>> {
        let i = self.intersect(ray, t_max)?;
        Some(self.finish(ray, &i))
    }
    fn occluded(&self, ray: &raytrace::Ray<F>, t_max: F) -> bool {
        self.intersect(ray, t_max).is_some()
    }
}

impl<F: Float, S: raytrace::Hittable<F> + ?Sized> Alone<F> for S {}
