//! The progress bar of `contact run`: simulated time against end time, accepted and rejected
//! steps, drawn on stderr only when stderr is a terminal.
//!
//! The solver reports after every accepted step ([`Progress`]); redrawing that often would cost
//! more than some steps, so the bar is updated at most once per [`REFRESH`] of wall time (one
//! clock read per step otherwise). Logs, pipes and tests see nothing: the bar is not created
//! when stderr is not a terminal, nor with `--quiet`.

use contact_solver::simulate::Progress;
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use std::io::IsTerminal;
use std::time::{Duration, Instant};

/// The least wall time between two redraws.
pub const REFRESH: Duration = Duration::from_millis(50);

/// Ticks of the bar over the simulated span (its resolution).
const TICKS: u64 = 10_000;

/// A progress display for one run; does nothing when hidden.
#[derive(Debug)]
pub struct RunProgress {
    bar: Option<ProgressBar>,
    last_draw: Instant,
}

impl RunProgress {
    /// A bar on stderr if `visible` (normally: not `--quiet` and stderr is a terminal).
    pub fn new(visible: bool) -> Self {
        let bar = visible.then(|| {
            let bar =
                ProgressBar::with_draw_target(Some(TICKS), ProgressDrawTarget::stderr_with_hz(20));
            let style = ProgressStyle::with_template("{bar:20} {percent:>3}% {msg} {elapsed}")
                .unwrap_or_else(|_| ProgressStyle::default_bar());
            bar.set_style(style);
            bar
        });
        Self {
            bar,
            last_draw: Instant::now(),
        }
    }

    /// A bar when stderr is a terminal and the user did not ask for quiet.
    pub fn for_stderr(quiet: bool) -> Self {
        Self::new(!quiet && std::io::stderr().is_terminal())
    }

    /// Whether a bar is drawn.
    pub fn is_visible(&self) -> bool {
        self.bar.is_some()
    }

    /// Records where the run is; redraws if [`REFRESH`] has passed since the last redraw.
    pub fn update(&mut self, progress: &Progress) {
        let Some(bar) = &self.bar else {
            return;
        };
        let now = Instant::now();
        if now.duration_since(self.last_draw) < REFRESH {
            return;
        }
        self.last_draw = now;
        bar.set_position(ticks(progress));
        bar.set_message(message(progress));
    }

    /// Removes the bar from the terminal (before the summary is printed).
    pub fn finish(self) {
        if let Some(bar) = self.bar {
            bar.finish_and_clear();
        }
    }
}

/// The bar position: the fraction of the simulated span done, in [0, TICKS].
fn ticks(p: &Progress) -> u64 {
    let span = p.end - p.start;
    let fraction = if span > 0.0 {
        ((p.t - p.start) / span).clamp(0.0, 1.0)
    } else {
        1.0
    };
    (fraction * TICKS as f64).round() as u64
}

/// The text beside the bar, short enough for an 80-column terminal:
/// `t=1.234e-1/1e0 812 steps 9 rejected`.
fn message(p: &Progress) -> String {
    format!(
        "t={:.3e}/{:e} {} steps {} rejected",
        p.t, p.end, p.steps, p.rejected
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    fn at(t: f64) -> Progress {
        Progress {
            t,
            start: 1.0,
            end: 3.0,
            steps: 12,
            rejected: 3,
        }
    }

    #[test]
    fn position_is_the_fraction_of_the_span_clamped() {
        assert_eq!(ticks(&at(1.0)), 0);
        assert_eq!(ticks(&at(2.0)), TICKS / 2);
        assert_eq!(ticks(&at(3.0)), TICKS);
        assert_eq!(ticks(&at(5.0)), TICKS);
    }

    #[test]
    fn message_names_time_steps_and_rejections() {
        let text = message(&at(2.0));
        assert!(text.contains("t=2.000e0/3e0"), "{text}");
        assert!(text.contains("12 steps"), "{text}");
        assert!(text.contains("3 rejected"), "{text}");
    }

    #[test]
    fn a_hidden_bar_draws_nothing_and_finishes() {
        let mut progress = RunProgress::new(false);
        assert!(!progress.is_visible());
        progress.update(&at(2.0));
        progress.finish();
    }
}
