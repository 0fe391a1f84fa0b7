//! Adaptive sampling: samples go where a pixel's own estimate says its error is, and the
//! render reports the error each pixel reached.
//!
//! # The error
//! A pixel's error is the **relative standard error of the mean luminance** of its
//! samples, `Y = 0.2126 R + 0.7152 G + 0.0722 B` (linear Rec. 709, [`luminance`]), with an
//! absolute floor for dark pixels:
//!
//! `e = σ̂ / (√n · max(Ȳ, floor))`,
//!
//! `Ȳ` the mean of the `n` sample luminances and `σ̂` their standard deviation, made
//! conservative against the two ways a pixel's own samples understate it
//! ([`ErrorEstimate::Guarded`]). So a pixel brighter than the floor
//! reaches `e ≤ E` when its standard error is a share `E` of its value, and a pixel darker
//! than the floor when its standard error is below `E · floor` in absolute terms: a
//! near-black pixel does not need millions of samples to be known to 1 % of almost
//! nothing. The default floor, [`Adaptive::DEFAULT_FLOOR`] = 0.01, is a hundredth of
//! display white; at `E = 1 %` a pixel at the floor is then known to `10⁻⁴` absolute,
//! a third of an 8-bit step of its sRGB code.
//!
//! # Rounds
//! Every pixel first takes [`Adaptive::min_spp`] samples. After each round a pixel whose
//! estimate meets the target stops; one that does not takes more, in the next round:
//! with a target alone, as many as its estimate says it still needs, at least a quarter
//! and at most all of what it has (a pixel never commits to more samples than it has
//! already judged), up to [`Adaptive::max_spp`]. A pixel's samples are always the
//! streams `0..n` of the uniform render ([`sample_seed`](super::sample_seed)), each
//! jittered in the pixel, summed in their order: a pixel that stops at `n` samples has
//! the value the uniform render with `n` samples per pixel gives it, bit for bit.
//!
//! Each pixel's decisions depend on its own samples only, so the image is the same bytes
//! on any number of threads and in any tiling, and tiles merge to the whole render.
//!
//! # A time budget
//! With [`Adaptive::time_budget`] the render goes on until the time is spent (or every
//! pixel meets the target, if there is one, or reaches `max_spp`), and each round goes
//! where it lowers the error most: the round's samples are shared out so that a pixel's
//! total grows in proportion to its per-sample relative deviation `σ̂/max(Ȳ, floor)` (the
//! pseudo-sample included: a pixel whose samples all agree so far is not written off)
//! over the square root of what its samples cost, the allocation that minimises the summed
//! squared relative error for the time spent. **Such an image depends on the time**: on the machine, its load and the
//! threads, and each tile of a tiled render spends the whole budget on its own pixels.
//! It is not reproducible, only its first round (`min_spp` samples everywhere, which is
//! always completed) is.

mod convergence;
mod engine;
mod schedule;
mod stats;

pub use convergence::{Convergence, ConvergenceSummary};
pub(super) use engine::render_adaptive;
pub use stats::luminance;

use crate::error::{Error, Result};
use std::time::Duration;

/// How an adaptive render spends its samples: a target error, a time budget, or both,
/// between a least and a greatest number of samples per pixel. See the
/// [module docs](self) for the error's definition.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Adaptive {
    /// The relative standard error each pixel should reach ([module docs](self)); `None`
    /// renders until the time budget is spent.
    pub target_error: Option<f64>,
    /// Wall time to spend at most; `None` renders until every pixel meets the target.
    pub time_budget: Option<Duration>,
    /// Samples every pixel takes before its error is first judged, at least
    /// [`Adaptive::MIN_SPP`]: the guard against paths too rare to have been seen yet.
    pub min_spp: u32,
    /// Samples no pixel goes beyond, whatever its error.
    pub max_spp: u32,
    /// The luminance below which a pixel's error is measured in absolute terms.
    pub error_floor: f64,
    /// How a pixel's error is estimated from its samples.
    pub estimate: ErrorEstimate,
}

/// How a pixel's standard error is estimated from its samples.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum ErrorEstimate {
    /// The sample variance made an upper confidence bound (one standard error of it above,
    /// from the sample kurtosis) with one pseudo-sample against paths not yet found: a
    /// pixel never claims a relative error below `1/n`. The default; the formula and the
    /// reasons are at `stats::estimate` (src/render/adaptive/stats.rs), the measurements
    /// in tests/it/adaptive_calibration.rs.
    #[default]
    Guarded,
    /// The plain sample variance, `s²/n`: too small exactly when a pixel stops (when it
    /// happens to be low, or before a rare path has been found). Kept to be measured
    /// against: the calibration test shows it stating too small an error.
    SampleVariance,
}

impl Adaptive {
    /// The fewest samples a pixel's error is judged on. Below it the estimate of a
    /// deviation is itself too uncertain (and a path found once in 16 samples may not
    /// yet have been found at all).
    pub const MIN_SPP: u32 = 16;
    /// The default [`Adaptive::min_spp`].
    pub const DEFAULT_MIN_SPP: u32 = 32;
    /// The default [`Adaptive::max_spp`].
    pub const DEFAULT_MAX_SPP: u32 = 4096;
    /// The default [`Adaptive::error_floor`]: a hundredth of display white.
    pub const DEFAULT_FLOOR: f64 = 0.01;

    /// Render until every pixel's relative error is at most `target_error`.
    #[must_use]
    pub fn target(target_error: f64) -> Self {
        Self {
            target_error: Some(target_error),
            ..Self::empty()
        }
    }

    /// Render for `budget` of wall time.
    #[must_use]
    pub fn time(budget: Duration) -> Self {
        Self {
            time_budget: Some(budget),
            ..Self::empty()
        }
    }

    /// Neither a target nor a budget yet (not valid as it is), and the default limits.
    pub(super) fn empty() -> Self {
        Self {
            target_error: None,
            time_budget: None,
            min_spp: Self::DEFAULT_MIN_SPP,
            max_spp: Self::DEFAULT_MAX_SPP,
            error_floor: Self::DEFAULT_FLOOR,
            estimate: ErrorEstimate::Guarded,
        }
    }

    /// Checks the settings, naming the one at fault.
    ///
    /// # Errors
    /// [`Error::InvalidSettings`] if there is neither a target nor a budget, the target or
    /// the floor is not a finite number `> 0`, the budget is zero, `min_spp` is below
    /// [`Adaptive::MIN_SPP`], or `max_spp < min_spp`.
    pub fn validate(&self) -> Result<()> {
        let bad = |m: String| Err(Error::InvalidSettings(m));
        if self.target_error.is_none() && self.time_budget.is_none() {
            return bad("adaptive sampling needs a target error or a time budget".into());
        }
        if let Some(e) = self.target_error
            && !(e.is_finite() && e > 0.0)
        {
            return bad(format!("target error must be a finite number > 0 (got {e})"));
        }
        if self.time_budget == Some(Duration::ZERO) {
            return bad("time budget must be longer than 0 s".into());
        }
        if !(self.error_floor.is_finite() && self.error_floor > 0.0) {
            return bad(format!(
                "error floor must be a finite number > 0 (got {})",
                self.error_floor
            ));
        }
        if self.min_spp < Self::MIN_SPP {
            return bad(format!(
                "min spp must be at least {} (got {}): a pixel's error is judged on that many samples",
                Self::MIN_SPP,
                self.min_spp
            ));
        }
        if self.max_spp < self.min_spp {
            return bad(format!(
                "max spp ({}) must be at least min spp ({})",
                self.max_spp, self.min_spp
            ));
        }
        Ok(())
    }
}
