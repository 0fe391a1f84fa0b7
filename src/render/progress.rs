//! The progress bar: rows done, rate and time left on stderr, with the default `progress`
//! feature and only when stderr is a terminal. Without the feature it is a no-op and the
//! library does not depend on `indicatif`.

/// Rows done so far, drawn as a bar.
pub(super) struct Progress {
    #[cfg(feature = "progress")]
    bar: indicatif::ProgressBar,
}

#[cfg(feature = "progress")]
impl Progress {
    /// A bar for `rows` rows, hidden unless `wanted` and stderr is a terminal.
    pub(super) fn new(wanted: bool, rows: u64) -> Self {
        use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
        use std::io::IsTerminal;
        if !wanted || !std::io::stderr().is_terminal() {
            return Self {
                bar: ProgressBar::hidden(),
            };
        }
        let bar = ProgressBar::with_draw_target(Some(rows), ProgressDrawTarget::stderr());
        if let Ok(style) = ProgressStyle::with_template("{bar:40} {pos}/{len} rows  {per_sec}  eta {eta}") {
            bar.set_style(style);
        }
        Self { bar }
    }

    /// `rows` more rows done.
    pub(super) fn inc(&self, rows: u64) {
        self.bar.inc(rows);
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
    pub(super) fn inc(&self, _rows: u64) {}
    pub(super) fn finish(&self) {}
}
