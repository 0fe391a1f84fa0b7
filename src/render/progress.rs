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
        use indicatif::{ProgressBar, ProgressDrawTarget};
        use std::io::IsTerminal;
        if !wanted || !std::io::stderr().is_terminal() {
            return Self {
                bar: ProgressBar::hidden(),
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
