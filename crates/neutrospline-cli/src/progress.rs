//! A progress bar on standard error for long jobs (indicatif).
//!
//! The bar is drawn only where someone can see it and it cannot get in the way: standard error
//! is a terminal, the table is not being printed on that same terminal, the job has at least
//! [`MIN_ROWS`] rows, and it has been running for [`DELAY`]. It is cleared when the job ends,
//! whether it succeeded or not, so the terminal is left as it was.

use std::io::IsTerminal as _;
use std::time::{Duration, Instant};

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressState, ProgressStyle};

/// Jobs with fewer rows never show a bar.
pub const MIN_ROWS: u64 = 100_000;
/// A bar appears once a job has run this long: a quick job prints nothing extra.
pub const DELAY: Duration = Duration::from_millis(400);
/// Rows counted between updates of the shared counter (an update costs an atomic operation).
const STRIDE: u32 = 4096;

/// Whether a job of `rows` rows gets a bar, given whether standard error is a terminal and
/// whether the table goes to a terminal on standard output.
pub fn wanted(rows: u64, stderr_is_terminal: bool, table_on_terminal: bool) -> bool {
    rows >= MIN_ROWS && stderr_is_terminal && !table_on_terminal
}

/// Counts rows and, for a long job on a terminal, shows them as a bar.
pub struct Progress {
    bar: Option<ProgressBar>,
    start: Instant,
    shown: bool,
    pending: u32,
}

impl Progress {
    /// A counter for a job of `rows` rows; `to_stdout` says whether the table is written to
    /// standard output.
    pub fn new(rows: u64, to_stdout: bool) -> Self {
        let table_on_terminal = to_stdout && std::io::stdout().is_terminal();
        let bar =
            wanted(rows, std::io::stderr().is_terminal(), table_on_terminal).then(|| {
                let style = ProgressStyle::with_template(
                "{elapsed_precise} [{wide_bar}] {human_pos}/{human_len} rows, {rate}, {eta} left",
            )
            .unwrap_or_else(|_| ProgressStyle::default_bar())
            .with_key("rate", |state: &ProgressState, w: &mut dyn std::fmt::Write| {
                let _ = write!(w, "{:.2} M rows/s", state.per_sec() / 1e6);
            })
            .progress_chars("=> ");
                // Hidden until `DELAY` has passed.
                ProgressBar::with_draw_target(Some(rows), ProgressDrawTarget::hidden())
                    .with_style(style)
            });
        Progress {
            bar,
            start: Instant::now(),
            shown: false,
            pending: 0,
        }
    }

    /// Counts one row.
    #[inline]
    pub fn tick(&mut self) {
        if self.bar.is_some() {
            self.pending += 1;
            if self.pending == STRIDE {
                self.update();
            }
        }
    }

    fn update(&mut self) {
        if let Some(bar) = &self.bar {
            bar.inc(u64::from(self.pending));
            self.pending = 0;
            if !self.shown && self.start.elapsed() >= DELAY {
                bar.set_draw_target(ProgressDrawTarget::stderr());
                self.shown = true;
            }
        }
    }
}

impl Drop for Progress {
    fn drop(&mut self) {
        if let Some(bar) = self.bar.take() {
            bar.finish_and_clear();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bar_only_for_long_jobs_on_a_terminal() {
        assert!(wanted(MIN_ROWS, true, false));
        assert!(wanted(10_000_000, true, false));
        assert!(!wanted(MIN_ROWS - 1, true, false));
        assert!(!wanted(10_000_000, false, false));
        assert!(!wanted(10_000_000, true, true));
    }

    #[test]
    fn counts_in_strides() {
        let mut progress = Progress {
            bar: Some(ProgressBar::hidden()),
            start: Instant::now(),
            shown: false,
            pending: 0,
        };
        for _ in 0..(2 * STRIDE + 5) {
            progress.tick();
        }
        let bar = progress.bar.as_ref().map(ProgressBar::position);
        assert_eq!(bar, Some(2 * u64::from(STRIDE)));
        assert_eq!(progress.pending, 5);
    }
}
