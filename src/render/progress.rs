//! The progress bar: rows done, rate and time left on stderr, with the default `progress`
//! feature and only when stderr is a terminal. Without the feature it is a no-op and the
//! library does not depend on `indicatif`.
//!
//! An adaptive render shows its rounds instead: the pixels that have met the target (or
//! the time spent, with a time budget) as the bar, and after each round the error the
//! pixels have reached, falling.

use super::adaptive::Adaptive;
use std::time::Duration;

/// What an adaptive render's bar shows after a round.
#[cfg_attr(not(feature = "progress"), allow(dead_code))]
pub(super) struct Round {
    /// Rounds done.
    pub number: u32,
    /// The pixels' median error and its 99th percentile.
    pub median: f64,
    /// See `median`.
    pub p99: f64,
    /// Pixels still sampling.
    pub active: usize,
    /// Time since the start.
    pub elapsed: Duration,
}

/// Rows done so far, drawn as a bar.
pub(super) struct Progress {
    #[cfg(feature = "progress")]
    bar: indicatif::ProgressBar,
    /// Whether the bar counts milliseconds of a time budget (else rows or pixels).
    #[cfg(feature = "progress")]
    timed: bool,
}

#[cfg(feature = "progress")]
impl Progress {
    /// A bar for `rows` rows, hidden unless `wanted` and stderr is a terminal.
    pub(super) fn new(wanted: bool, rows: u64) -> Self {
        use indicatif::{ProgressBar, ProgressDrawTarget};
        use std::io::IsTerminal;
        if !wanted || !std::io::stderr().is_terminal() {
            return Self {
                bar: ProgressBar::hidden(),
                timed: false,
            };
        }
        Self::drawn(rows, ProgressDrawTarget::stderr())
    }

    /// A bar for `rows` rows on `target`, drawn at once: a band of rows can take minutes,
    /// and a bar that appears only after it looks like a hang.
    fn drawn(rows: u64, target: indicatif::ProgressDrawTarget) -> Self {
        use indicatif::{ProgressBar, ProgressStyle};
        let bar = ProgressBar::with_draw_target(Some(rows), target);
        if let Ok(style) = ProgressStyle::with_template("{bar:40} {pos}/{len} rows  {per_sec}  eta {eta}") {
            bar.set_style(style);
        }
        bar.tick();
        Self { bar, timed: false }
    }

    /// `rows` more rows done.
    pub(super) fn inc(&self, rows: u64) {
        self.bar.inc(rows);
    }

    /// A bar for the rounds of an adaptive render of `pixels` pixels: the pixels done,
    /// or with a time budget the seconds spent, with the error reached beside it.
    pub(super) fn rounds(wanted: bool, adaptive: &Adaptive, pixels: u64) -> Self {
        use indicatif::{ProgressBar, ProgressDrawTarget};
        use std::io::IsTerminal;
        if !wanted || !std::io::stderr().is_terminal() {
            return Self {
                bar: ProgressBar::hidden(),
                timed: false,
            };
        }
        Self::rounds_on(adaptive, pixels, ProgressDrawTarget::stderr())
    }

    fn rounds_on(adaptive: &Adaptive, pixels: u64, target: indicatif::ProgressDrawTarget) -> Self {
        use indicatif::{ProgressBar, ProgressStyle};
        let (len, template) = match adaptive.time_budget {
            Some(budget) => (
                budget.as_millis().max(1) as u64,
                "{bar:30} {elapsed} of the time  {msg}",
            ),
            None => (pixels, "{bar:30} {pos}/{len} pixels done  {msg}"),
        };
        let bar = ProgressBar::with_draw_target(Some(len), target);
        if let Ok(style) = ProgressStyle::with_template(template) {
            bar.set_style(style);
        }
        bar.set_message(match adaptive.target_error {
            Some(t) => format!(
                "first round: {} samples per pixel, target {:.2} %",
                adaptive.min_spp,
                100.0 * t
            ),
            None => format!("first round: {} samples per pixel", adaptive.min_spp),
        });
        bar.tick();
        Self {
            bar,
            timed: adaptive.time_budget.is_some(),
        }
    }

    /// Shows the state after a round.
    pub(super) fn round(&self, round: &Round) {
        let len = self.bar.length().unwrap_or(0);
        self.bar.set_position(if self.timed {
            (round.elapsed.as_millis() as u64).min(len)
        } else {
            len.saturating_sub(round.active as u64)
        });
        self.bar.set_message(format!(
            "round {}: error {:.2} % median, {:.2} % 99th pct; {} pixels sampling",
            round.number,
            100.0 * round.median,
            100.0 * round.p99,
            round.active
        ));
    }

    /// Removes the bar.
    pub(super) fn finish(&self) {
        self.bar.finish_and_clear();
    }
}

#[cfg(not(feature = "progress"))]
impl Progress {
    pub(super) fn new(_wanted: bool, _rows: u64) -> Self {
        Self {}
    }
    pub(super) fn rounds(_wanted: bool, _adaptive: &Adaptive, _pixels: u64) -> Self {
        Self {}
    }
    pub(super) fn inc(&self, _rows: u64) {}
    pub(super) fn round(&self, _round: &Round) {}
    pub(super) fn finish(&self) {}
}

#[cfg(all(test, feature = "progress"))]
mod tests {
    use super::*;
    use std::sync::{Arc, Mutex};

    /// A terminal that keeps what is written to it.
    #[derive(Clone, Debug, Default)]
    struct Screen(Arc<Mutex<String>>);

    impl indicatif::TermLike for Screen {
        fn width(&self) -> u16 {
            100
        }
        fn move_cursor_up(&self, _: usize) -> std::io::Result<()> {
            Ok(())
        }
        fn move_cursor_down(&self, _: usize) -> std::io::Result<()> {
            Ok(())
        }
        fn move_cursor_right(&self, _: usize) -> std::io::Result<()> {
            Ok(())
        }
        fn move_cursor_left(&self, _: usize) -> std::io::Result<()> {
            Ok(())
        }
        fn write_line(&self, s: &str) -> std::io::Result<()> {
            self.write_str(&format!("{s}\n"))
        }
        fn write_str(&self, s: &str) -> std::io::Result<()> {
            self.0.lock().unwrap().push_str(s);
            Ok(())
        }
        fn clear_line(&self) -> std::io::Result<()> {
            Ok(())
        }
        fn flush(&self) -> std::io::Result<()> {
            Ok(())
        }
    }

    #[test]
    fn an_adaptive_render_shows_the_error_falling_round_by_round() {
        let screen = Screen::default();
        let target = indicatif::ProgressDrawTarget::term_like(Box::new(screen.clone()));
        let progress = Progress::rounds_on(&Adaptive::target(0.01), 100, target);
        let shown = || screen.0.lock().unwrap().clone();
        assert!(shown().contains("0/100 pixels done"), "{:?}", shown());
        assert!(
            shown().contains("first round: 32 samples per pixel, target 1.00 %"),
            "{:?}",
            shown()
        );
        for (number, median, active) in [(1, 0.031, 80), (2, 0.012, 30)] {
            progress.round(&Round {
                number,
                median,
                p99: 2.0 * median,
                active,
                elapsed: Duration::from_millis(100),
            });
            // indicatif draws at most every few milliseconds: make it draw now.
            progress.bar.tick();
        }
        let text = shown();
        assert!(text.contains("20/100 pixels done"), "{text:?}");
        assert!(
            text.contains("round 1: error 3.10 % median, 6.20 % 99th pct; 80 pixels sampling"),
            "{text:?}"
        );
        assert!(text.contains("70/100 pixels done"), "{text:?}");
        assert!(
            text.contains("round 2: error 1.20 % median, 2.40 % 99th pct; 30 pixels sampling"),
            "{text:?}"
        );
        progress.finish();
    }

    #[test]
    fn the_bar_is_drawn_before_the_first_row_is_done() {
        let screen = Screen::default();
        let progress = Progress::drawn(
            8,
            indicatif::ProgressDrawTarget::term_like(Box::new(screen.clone())),
        );
        let shown = screen.0.lock().unwrap().clone();
        assert!(shown.contains("0/8 rows"), "nothing drawn yet: {shown:?}");
        progress.finish();
    }
}
