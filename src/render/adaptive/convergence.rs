//! What an adaptive render reached: each pixel's sample count and error, and a summary.

use std::fmt;

/// Each pixel's sample count and estimated error after an adaptive render, row by row
/// from the top-left of the rendered region, as [`Image`](crate::Image)'s pixels are.
#[derive(Clone, Debug, PartialEq)]
pub struct Convergence {
    width: usize,
    height: usize,
    samples: Vec<u32>,
    error: Vec<f64>,
    target: Option<f64>,
    max_spp: u32,
    rounds: u32,
}

impl Convergence {
    /// The maps of a `width × height` region; `samples` and `error` hold one value per
    /// pixel.
    pub(super) fn new(
        (width, height): (usize, usize),
        samples: Vec<u32>,
        error: Vec<f64>,
        (target, max_spp): (Option<f64>, u32),
        rounds: u32,
    ) -> Self {
        debug_assert!(samples.len() == width * height && error.len() == samples.len());
        Self {
            width,
            height,
            samples,
            error,
            target,
            max_spp,
            rounds,
        }
    }

    /// Width in pixels.
    pub fn width(&self) -> usize {
        self.width
    }

    /// Height in pixels.
    pub fn height(&self) -> usize {
        self.height
    }

    /// The samples each pixel took.
    pub fn samples(&self) -> &[u32] {
        &self.samples
    }

    /// Each pixel's estimated relative standard error of its mean luminance, as defined in
    /// the [module docs](super).
    pub fn error(&self) -> &[f64] {
        &self.error
    }

    /// The target error, if the render had one.
    pub fn target(&self) -> Option<f64> {
        self.target
    }

    /// The rounds the render took.
    pub fn rounds(&self) -> u32 {
        self.rounds
    }

    /// The median, the 99th percentile and the samples spent.
    #[must_use]
    pub fn summary(&self) -> ConvergenceSummary {
        let mut sorted = self.error.clone();
        sorted.sort_by(f64::total_cmp);
        let total: u64 = self.samples.iter().map(|&n| u64::from(n)).sum();
        let met = self
            .target
            .map(|t| self.error.iter().filter(|&&e| e <= t).count());
        ConvergenceSummary {
            median: quantile(&sorted, 0.5),
            p99: quantile(&sorted, 0.99),
            samples: total,
            pixels: self.samples.len(),
            least: self.samples.iter().copied().min().unwrap_or(0),
            most: self.samples.iter().copied().max().unwrap_or(0),
            target: self.target,
            met: met.unwrap_or(0),
            at_cap: self.samples.iter().filter(|&&n| n >= self.max_spp).count(),
        }
    }
}

/// The value below which a share `q` of `sorted` lies: the nearest-rank quantile,
/// element `⌈q·len⌉ − 1` (NaN for no values).
pub(super) fn quantile(sorted: &[f64], q: f64) -> f64 {
    if sorted.is_empty() {
        return f64::NAN;
    }
    let rank = (q * sorted.len() as f64).ceil() as usize;
    sorted[rank.clamp(1, sorted.len()) - 1]
}

/// The median and the 99th percentile of `errors` (nearest rank), found in linear time:
/// shown after every round.
pub(super) fn median_and_p99(mut errors: Vec<f64>) -> (f64, f64) {
    if errors.is_empty() {
        return (f64::NAN, f64::NAN);
    }
    let rank = |q: f64| ((q * errors.len() as f64).ceil() as usize).clamp(1, errors.len()) - 1;
    let (m, p) = (rank(0.5), rank(0.99));
    let median = *errors.select_nth_unstable_by(m, f64::total_cmp).1;
    let p99 = *errors.select_nth_unstable_by(p, f64::total_cmp).1;
    (median, p99)
}

/// An adaptive render in a few numbers; its `Display` is the line the render ends with.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ConvergenceSummary {
    /// The median of the pixels' estimated errors.
    pub median: f64,
    /// Their 99th percentile (nearest rank).
    pub p99: f64,
    /// Samples taken in all.
    pub samples: u64,
    /// Pixels.
    pub pixels: usize,
    /// The fewest and the most samples a pixel took.
    pub least: u32,
    /// See `least`.
    pub most: u32,
    /// The target, if there was one.
    pub target: Option<f64>,
    /// Pixels whose estimate met the target.
    pub met: usize,
    /// Pixels that stopped at the most samples allowed.
    pub at_cap: usize,
}

impl fmt::Display for ConvergenceSummary {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let percent = |share: f64| 100.0 * share;
        write!(
            f,
            "error {:.3} % median, {:.3} % at the 99th percentile",
            percent(self.median),
            percent(self.p99)
        )?;
        if let Some(t) = self.target {
            write!(
                f,
                " (target {:.3} %, met by {:.1} % of pixels)",
                percent(t),
                percent(self.met as f64 / self.pixels.max(1) as f64)
            )?;
        }
        write!(
            f,
            "; {} samples, {:.1} per pixel ({} to {})",
            self.samples,
            self.samples as f64 / self.pixels.max(1) as f64,
            self.least,
            self.most
        )?;
        if self.at_cap > 0 {
            write!(
                f,
                ", {:.1} % of pixels at the most allowed",
                percent(self.at_cap as f64 / self.pixels.max(1) as f64)
            )?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quantiles_are_nearest_rank() {
        let v: Vec<f64> = (1..=100).map(f64::from).collect();
        assert_eq!(quantile(&v, 0.5), 50.0);
        assert_eq!(quantile(&v, 0.99), 99.0);
        assert_eq!(quantile(&v, 1.0), 100.0);
        assert_eq!(quantile(&v, 0.0), 1.0);
        assert_eq!(quantile(&[3.0], 0.99), 3.0);
        assert!(quantile(&[], 0.5).is_nan());
    }

    #[test]
    fn the_summary_line_says_what_was_reached_and_spent() {
        let c = Convergence::new(
            (2, 2),
            vec![32, 64, 4096, 32],
            vec![0.008, 0.01, 0.02, 0.004],
            (Some(0.01), 4096),
            5,
        );
        let s = c.summary();
        assert_eq!(
            (s.samples, s.least, s.most, s.met, s.at_cap),
            (4224, 32, 4096, 3, 1)
        );
        assert_eq!(
            s.to_string(),
            "error 0.800 % median, 2.000 % at the 99th percentile (target 1.000 %, met by \
             75.0 % of pixels); 4224 samples, 1056.0 per pixel (32 to 4096), 25.0 % of pixels \
             at the most allowed"
        );
    }
}
