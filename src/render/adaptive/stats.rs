//! A pixel's running statistics and the error estimate made from them.

use super::ErrorEstimate;
use crate::float::Float;
use crate::vec3::Color;

/// The luminance of a linear Rec. 709 (sRGB primaries) colour, `Y = 0.2126 R + 0.7152 G +
/// 0.0722 B`: the one number a pixel's error is measured in.
#[inline]
#[must_use]
pub fn luminance(rgb: [f64; 3]) -> f64 {
    0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2]
}

/// What an adaptive render keeps of one pixel: the sum of its sample colours in their
/// order (the uniform renderer's sum, so the mean is its bits) and the power sums of
/// their luminances about the first one, `Σ (Y − Y₀)^k` for `k = 1..4`, in `f64`.
///
/// Power sums about a shift `K` give the central moments with no division per sample
/// and four independent sums (a one-pass update of the central moments, Welford's or
/// Pébay's, chains a division through every sample of a pixel). They lose nothing to cancellation when `K`
/// is one of the samples. With `d = Ȳ − K`, sample `K` alone gives `M₂ ≥ d²`, so the sum
/// `S₂ = Σ(Y−K)² = M₂ + n·d²` is at most `(n+1)·M₂`, and summing it rounds by at most
/// `n·ε·S₂`: the relative error of `M₂` is below about `n²·ε` (4·10⁻⁹ at 4096 samples),
/// and of `M₄`, by `M₄ ≥ d⁴` and `(a+b)⁴ ≤ 8(a⁴+b⁴)`, below about `8n²·ε`.
#[derive(Clone, Copy, Debug)]
pub(super) struct PixelStats<F> {
    /// The sum of the sample colours, sample 0 first.
    pub sum: Color<F>,
    /// Samples taken.
    pub n: u32,
    /// `K`: the first sample's luminance.
    shift: f64,
    /// `Σ (Y − K)^k` for `k = 1, 2, 3, 4`.
    powers: [f64; 4],
    /// The bounces all its paths took: what its samples cost.
    bounces: u64,
}

/// A pixel's luminances summarised: their mean and central moment sums `Σ (Y − Ȳ)^k`.
#[derive(Clone, Copy, Debug)]
struct Moments {
    mean: f64,
    m2: f64,
    m4: f64,
}

impl<F: Float> PixelStats<F> {
    /// No samples yet.
    pub fn new() -> Self {
        Self {
            sum: Color::zero(),
            n: 0,
            shift: 0.0,
            powers: [0.0; 4],
            bounces: 0,
        }
    }

    /// Adds the next sample: its colour and the bounces its path took.
    #[inline]
    pub fn add(&mut self, colour: Color<F>, bounces: u32) {
        self.sum = self.sum + colour;
        self.bounces += u64::from(bounces);
        let y = luminance(colour.to_f64());
        if self.n == 0 {
            self.shift = y;
        }
        self.n += 1;
        let t = y - self.shift;
        let t2 = t * t;
        self.powers[0] += t;
        self.powers[1] += t2;
        self.powers[2] += t2 * t;
        self.powers[3] += t2 * t2;
    }

    /// The mean and central moments from the power sums: with `d = S₁/n`,
    /// `M₂ = S₂ − n·d²` and `M₄ = S₄ − 4d·S₃ + 6d²·S₂ − 3n·d⁴` (the binomial expansion of
    /// `Σ((Y−K) − d)⁴`, its `S₁` term folded in by `S₁ = n·d`).
    fn moments(&self) -> Moments {
        let n = f64::from(self.n.max(1));
        let [s1, s2, s3, s4] = self.powers;
        let d = s1 / n;
        let d2 = d * d;
        Moments {
            mean: self.shift + d,
            m2: (s2 - n * d2).max(0.0),
            m4: (s4 - 4.0 * d * s3 + 6.0 * d2 * s2 - 3.0 * n * d2 * d2).max(0.0),
        }
    }

    /// The rays a sample of this pixel has cost on average, counted as its camera ray and
    /// one per bounce (the shadow rays go with the bounces).
    pub fn cost(&self) -> f64 {
        1.0 + self.bounces as f64 / f64::from(self.n.max(1))
    }

    /// The error estimate for the samples so far.
    pub fn estimate(&self, floor: f64, kind: ErrorEstimate) -> Estimate {
        let m = self.moments();
        match kind {
            ErrorEstimate::Guarded => estimate(self.n, m.mean, m.m2, m.m4, floor),
            ErrorEstimate::SampleVariance => sample_variance(self.n, m.mean, m.m2, floor),
        }
    }
}

/// A pixel's error, as estimated from its samples.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Estimate {
    /// The relative standard error of the mean luminance, `σ̂/(√n·max(Ȳ, floor))`.
    pub error: f64,
    /// The per-sample relative deviation, `σ̂/max(Ȳ, floor)` (so `error·√n`): what the time
    /// budget's allocation shares samples by. It keeps the pseudo-sample: a pixel whose
    /// first samples all agree has seen none of its rarer paths yet, and without it would
    /// show no deviation and never be sampled again (on `point_lights`, adaptive sampling
    /// then fell behind uniform sampling as the budget grew; bench/results/equal_time.md).
    pub deviation: f64,
}

/// The error of a mean of `n` luminances with mean `mean` and central moment sums
/// `m2 = Σ(Y−Ȳ)²` and `m4 = Σ(Y−Ȳ)⁴`, relative to `s = max(mean, floor)`:
/// `e = σ̂/(√n·s)` with
///
/// `σ̂² = s² + √Var̂(s²) + s²_floor/n`, where `s² = m2/(n−1)`,
/// `Var̂(s²) = (m4/n − s⁴·(n−3)/(n−1))/n` and `s_floor = max(mean, floor)`.
///
/// The plain sample variance `s²` is too small exactly when it is used, two ways:
///
/// - **Stopping when it is low.** A pixel stops at the first round its estimate meets
///   the target, so among pixels that stop, `s²` is low by chance more often than not.
///   The second term is one standard error of `s²` (its large-sample variance for any
///   distribution with a fourth moment; `2σ⁴/(n−1)` for a normal one), so the estimate
///   is an upper confidence bound. It grows with the sample kurtosis: a pixel that has
///   found a rare bright path once or twice (a caustic seen through a diffuse bounce)
///   keeps sampling until that path's share of its mean is itself known.
/// - **Paths not yet found.** Until a pixel has met a path its samples find with
///   probability `p`, nothing in them shows it; a path of probability `1/n` that takes
///   the value 0 or `2Ȳ` (a rare occlusion, a rare bright path) moves the mean by about
///   `Ȳ/n`. The third term is that one pseudo-sample: the estimate never claims a
///   relative error below `1/n`. With `n ≥ 100` it no longer matters at a 1 % target.
///
/// Measured on the Cornell box, a mesh scene and a glass caustic (tests/it/
/// adaptive_calibration.rs), the plain `s²` put 91–94 % of pixels within twice their
/// stated error, this estimate at least 95 %.
pub(super) fn estimate(n: u32, mean: f64, m2: f64, m4: f64, floor: f64) -> Estimate {
    if n < 2 {
        return Estimate {
            error: f64::INFINITY,
            deviation: f64::INFINITY,
        };
    }
    let nf = f64::from(n);
    let s2 = m2 / (nf - 1.0);
    let var_s2 = (m4 / nf - s2 * s2 * (nf - 3.0) / (nf - 1.0)) / nf;
    let scale = mean.max(floor);
    let shown = s2 + var_s2.max(0.0).sqrt();
    let sigma2 = shown + scale * scale / nf;
    Estimate {
        error: (sigma2 / nf).max(0.0).sqrt() / scale,
        deviation: sigma2.max(0.0).sqrt() / scale,
    }
}

/// [`ErrorEstimate::SampleVariance`]: `σ̂² = s² = m2/(n−1)`, nothing more.
fn sample_variance(n: u32, mean: f64, m2: f64, floor: f64) -> Estimate {
    if n < 2 {
        return Estimate {
            error: f64::INFINITY,
            deviation: f64::INFINITY,
        };
    }
    let nf = f64::from(n);
    let deviation = (m2 / (nf - 1.0)).max(0.0).sqrt() / mean.max(floor);
    Estimate {
        error: deviation / nf.sqrt(),
        deviation,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The moments equal those computed in two passes, for values spread about their
    /// mean and for values far from zero with a small spread, where power sums about zero
    /// would lose every digit of the variance.
    #[test]
    fn power_sums_give_the_two_pass_moments() {
        let spread = [0.3, 0.1, 4.0, 0.2, 0.25, 0.0, 0.7, 0.15];
        for offset in [0.0, 1e6] {
            let ys = spread.map(|y| y + offset);
            let mut stats = PixelStats::<f64>::new();
            for &y in &ys {
                stats.add(Color::new(y, y, y), 1);
            }
            // Far from zero the weights' rounding moves the luminances: compare with them,
            // and in two passes over their differences from the first (exact near 10⁶,
            // where the values are within a factor of 2), as a mean near 10⁶ would round
            // the deviations from it.
            let ys = ys.map(|y| luminance([y; 3]));
            let xs = ys.map(|y| y - ys[0]);
            let n = ys.len() as f64;
            let mean = xs.iter().sum::<f64>() / n;
            let m = |k: i32| xs.iter().map(|x| (x - mean).powi(k)).sum::<f64>();
            let got = stats.moments();
            assert!(
                (got.mean - (ys[0] + mean)).abs() <= 1e-15 * got.mean.max(1.0),
                "{got:?}"
            );
            let bound = 8.0 * n * n * f64::EPSILON;
            assert!((got.m2 - m(2)).abs() < bound * m(2), "{got:?} {}", m(2));
            assert!((got.m4 - m(4)).abs() < bound * m(4), "{got:?} {}", m(4));
            assert_eq!(stats.n, 8);
            assert_eq!(stats.cost(), 2.0);
        }
    }

    /// The worst case for the shift: the first sample a firefly, far from all the others.
    /// The moments still hold, as the firefly itself bounds them.
    #[test]
    fn a_firefly_loses_no_digits() {
        let ys: Vec<f64> = (0..4096)
            .map(|k| {
                if k == 0 {
                    1e7
                } else {
                    0.5 + 1e-3 * f64::from(k % 7)
                }
            })
            .collect();
        let mut stats = PixelStats::<f64>::new();
        for &y in &ys {
            stats.add(Color::splat(y), 0);
        }
        let n = ys.len() as f64;
        let mean = ys.iter().sum::<f64>() / n;
        let m = |k: i32| ys.iter().map(|y| (y - mean).powi(k)).sum::<f64>();
        let got = stats.moments();
        // The bounds of the type's docs.
        assert!(
            (got.m2 - m(2)).abs() < n * n * f64::EPSILON * m(2),
            "{got:?} {}",
            m(2)
        );
        assert!(
            (got.m4 - m(4)).abs() < 8.0 * n * n * f64::EPSILON * m(4),
            "{got:?} {}",
            m(4)
        );
    }

    /// The pseudo-sample alone: a pixel whose samples all agree claims `1/n`.
    #[test]
    fn a_constant_pixel_claims_one_over_n() {
        let mut stats = PixelStats::<f64>::new();
        for _ in 0..20 {
            stats.add(Color::splat(0.5), 3);
        }
        let e = stats.estimate(0.01, ErrorEstimate::Guarded);
        assert_eq!(stats.estimate(0.01, ErrorEstimate::SampleVariance).error, 0.0);
        assert_eq!(stats.cost(), 4.0);
        assert!((e.error - 1.0 / 20.0).abs() < 1e-15, "{e:?}");
        // It is not written off: its deviation is the pseudo-sample's, 1/√n.
        assert!((e.deviation - 1.0 / 20f64.sqrt()).abs() < 1e-15, "{e:?}");
        assert_eq!(estimate(1, 0.5, 0.0, 0.0, 0.01).error, f64::INFINITY);
    }

    /// The three terms, each computed by hand for a two-valued pixel, and the kurtosis term
    /// large once a rare bright value is among the samples.
    #[test]
    fn the_terms_add_up_and_grow_with_a_rare_value() {
        let floor = 0.01;
        let (mut calm, mut spiky) = (PixelStats::<f64>::new(), PixelStats::<f64>::new());
        for k in 0..64 {
            let y = if k % 2 == 0 { 0.4 } else { 0.6 };
            calm.add(Color::splat(y), 0);
            // The same values but one replaced by a rare bright one.
            spiky.add(Color::splat(if k == 40 { 20.0 } else { y }), 0);
        }
        let by_hand = |s: &PixelStats<f64>| {
            let s = s.moments();
            let s2 = s.m2 / 63.0;
            let var_s2 = (s.m4 / 64.0 - s2 * s2 * 61.0 / 63.0) / 64.0;
            let sigma2 = s2 + var_s2.max(0.0).sqrt() + s.mean * s.mean / 64.0;
            (sigma2 / 64.0).sqrt() / s.mean
        };
        let (c, p) = (
            calm.estimate(floor, ErrorEstimate::Guarded),
            spiky.estimate(floor, ErrorEstimate::Guarded),
        );
        assert!((c.error - by_hand(&calm)).abs() < 1e-12, "{c:?}");
        assert!((p.error - by_hand(&spiky)).abs() < 1e-12, "{p:?}");
        // The deviation the allocation shares by is the error times √n.
        assert!((c.deviation - c.error * 8.0).abs() < 1e-12, "{c:?}");
        // Two values: s⁴·(n−3)/(n−1) is nearly m₄, so the bound adds almost nothing...
        let plain = |s: &PixelStats<f64>| {
            let s = s.moments();
            (s.m2 / 63.0 / 64.0 + s.mean * s.mean / 4096.0).sqrt() / s.mean
        };
        assert!(c.error < 1.01 * plain(&calm), "{c:?}");
        // ...but with one value 40 times the others, the kurtosis makes it count.
        assert!(p.error > 1.3 * plain(&spiky), "{p:?} vs {}", plain(&spiky));
    }

    #[test]
    fn dark_pixels_are_measured_against_the_floor() {
        // Mean 0.001, deviation 0.001: 100 % of the value, 10 % of the floor.
        let (dark, n) = (0.001, 100);
        let m2 = 99.0 * dark * dark;
        let at = |floor: f64| estimate(n, dark, m2, 0.0, floor).error;
        assert!(at(0.01) < 0.2 * at(0.0001), "{} {}", at(0.01), at(0.0001));
        assert!(
            (at(0.0001) - at(0.001)).abs() < 1e-15,
            "below the mean the floor does nothing"
        );
    }
}
