//! What a run shows on stderr while it works, when stderr is a terminal and `--quiet` is not
//! given: one line naming the phase (`loading NAME`, `building the BVH`) with the time spent
//! so far, then a bar while tracing. Nothing at all on a file or a pipe.
//!
//! The bar's ETA is shown only once it means something: after [`ETA_AFTER`] and
//! [`ETA_AFTER_FRACTION`] of the work, extrapolated linearly from the elapsed time (the rays
//! of one image cost about the same on average; the first few percent, spent while threads
//! start and caches fill, do not).

use std::borrow::Cow;
use std::io::IsTerminal as _;
use std::time::Duration;

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressState, ProgressStyle};

/// No ETA before this much time has passed.
pub const ETA_AFTER: Duration = Duration::from_secs(1);

/// No ETA before this fraction of the work is done.
pub const ETA_AFTER_FRACTION: f64 = 0.05;

/// The remaining time after `elapsed` for `fraction` (0 to 1) of the work, when it is worth
/// showing (see the [module documentation](self)).
#[must_use]
pub fn eta(elapsed: Duration, fraction: f64) -> Option<Duration> {
    if elapsed < ETA_AFTER || !(ETA_AFTER_FRACTION..=1.0).contains(&fraction) {
        return None;
    }
    Some(elapsed.mul_f64((1.0 - fraction) / fraction))
}

/// `m:ss` for a minute or more, else `Ns`.
#[must_use]
pub fn clock(d: Duration) -> String {
    let s = d.as_secs();
    if s >= 60 { format!("{}:{:02}", s / 60, s % 60) } else { format!("{s}s") }
}

/// The line on stderr (hidden when it is not a terminal or the run is quiet).
#[derive(Debug)]
pub struct Progress {
    bar: ProgressBar,
}

impl Progress {
    /// A progress line on stderr, drawn only if stderr is a terminal and not `quiet`.
    #[must_use]
    pub fn new(quiet: bool) -> Self {
        let bar = ProgressBar::with_draw_target(None, ProgressDrawTarget::hidden());
        if !quiet && std::io::stderr().is_terminal() {
            bar.set_draw_target(ProgressDrawTarget::stderr());
            bar.enable_steady_tick(Duration::from_millis(100));
        }
        Self { bar }
    }

    /// Shows `what` as the current phase, with the time it has taken so far.
    pub fn phase(&self, what: impl Into<Cow<'static, str>>) {
        let style = ProgressStyle::with_template("{spinner} {msg} ({elapsed})")
            .expect("the template is valid");
        self.bar.set_style(style);
        self.bar.reset();
        self.bar.set_message(what);
    }

    /// Switches to a bar over `total` units of tracing work (pixels, rays).
    pub fn trace(&self, total: u64) {
        self.trace_labelled("tracing", total);
    }

    /// Switches to a bar over `total` units of tracing work, headed `label` instead of
    /// `tracing` (`--compare` names the back end: `tracing la-mt (2/5)`).
    pub fn trace_labelled(&self, label: impl Into<Cow<'static, str>>, total: u64) {
        let style = ProgressStyle::with_template("{msg} {bar:40} {percent:>3}% {elapsed}{eta}")
            .expect("the template is valid")
            .with_key("eta", |s: &ProgressState, w: &mut dyn std::fmt::Write| {
                if let Some(left) = eta(s.elapsed(), f64::from(s.fraction())) {
                    let _ = write!(w, " (eta {})", clock(left));
                }
            });
        self.bar.set_style(style);
        self.bar.reset();
        self.bar.set_message(label);
        self.bar.set_length(total);
    }

    /// Counts `n` units of the tracing work as done.
    pub fn inc(&self, n: u64) {
        self.bar.inc(n);
    }

    /// Removes the line.
    pub fn finish(&self) {
        self.bar.finish_and_clear();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn eta_only_once_it_means_something() {
        let ms = Duration::from_millis;
        assert_eq!(eta(ms(150), 0.5), None, "a 0.3 s trace shows no ETA");
        assert_eq!(eta(ms(5000), 0.01), None, "1 % done says little");
        assert_eq!(eta(ms(2000), 0.25), Some(ms(6000)));
        assert_eq!(eta(ms(2000), 1.0), Some(Duration::ZERO));
        assert_eq!(eta(ms(2000), f64::NAN), None);
        assert_eq!(clock(ms(6500)), "6s");
        assert_eq!(clock(Duration::from_secs(125)), "2:05");
    }
}
