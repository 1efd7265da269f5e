//! What the benches time with, and how long: [`ThreadClock`], a criterion measurement of the
//! benchmark thread's CPU time, and [`configured`], the run lengths every bench shares.
//!
//! **Why CPU time.** The machine the figures come from is shared (two cores, other jobs
//! compiling); a thread's CPU time stops while it is descheduled, so nanosecond figures stay
//! meaningful under load. `WEDGE_BENCH_WALL=1` switches to wall time for a quiet machine.
//! Both sides of a comparison always use the same clock.

use std::time::{Duration, Instant};

use criterion::Criterion;
use criterion::measurement::{Measurement, ValueFormatter, WallTime};

use crate::{bench_times, quick_mode};

/// Criterion measurement: the calling thread's CPU time (`CLOCK_THREAD_CPUTIME_ID`), or wall
/// time when `WEDGE_BENCH_WALL=1`.
pub struct ThreadClock {
    /// The origin of wall-clock readings, when measuring wall time.
    wall: Option<Instant>,
}

impl ThreadClock {
    /// CPU time, or wall time if `WEDGE_BENCH_WALL=1`.
    #[must_use]
    pub fn from_env() -> Self {
        let wall = std::env::var("WEDGE_BENCH_WALL").is_ok_and(|v| v == "1");
        Self { wall: wall.then(Instant::now) }
    }

    /// The clock's reading: the thread's CPU time, or wall time since the clock was made.
    #[must_use]
    pub fn now(&self) -> Duration {
        if let Some(epoch) = self.wall {
            return epoch.elapsed();
        }
        let mut ts = libc::timespec { tv_sec: 0, tv_nsec: 0 };
        // SAFETY: `ts` is a valid, writable timespec, and CLOCK_THREAD_CPUTIME_ID is a clock
        // every Linux kernel provides for the calling thread.
        let rc = unsafe { libc::clock_gettime(libc::CLOCK_THREAD_CPUTIME_ID, &raw mut ts) };
        assert_eq!(rc, 0, "clock_gettime(CLOCK_THREAD_CPUTIME_ID) failed");
        let secs = u64::try_from(ts.tv_sec).expect("a thread's CPU time is not negative");
        let nanos = u32::try_from(ts.tv_nsec).expect("nanoseconds below one second");
        Duration::new(secs, nanos)
    }
}

impl Measurement for ThreadClock {
    type Intermediate = Duration;
    type Value = Duration;

    fn start(&self) -> Duration {
        self.now()
    }
    fn end(&self, start: Duration) -> Duration {
        self.now().saturating_sub(start)
    }
    fn add(&self, a: &Duration, b: &Duration) -> Duration {
        *a + *b
    }
    fn zero(&self) -> Duration {
        Duration::ZERO
    }
    fn to_f64(&self, value: &Duration) -> f64 {
        value.as_nanos() as f64
    }
    fn formatter(&self) -> &dyn ValueFormatter {
        // Values are durations in nanoseconds, as criterion's wall clock reports them.
        WallTime.formatter()
    }
}

/// `criterion` with the warm-up and measurement times `full` (a full run) or those of
/// [`bench_times`] with 10 samples and 1,000 resamples (`WEDGE_BENCH_QUICK=1`). The caller
/// adds its own settings and then `configure_from_args`.
#[must_use]
pub fn configured<M: Measurement>(
    criterion: Criterion<M>,
    full: (Duration, Duration),
) -> Criterion<M> {
    let (warm_up, measurement) = if quick_mode() { bench_times() } else { full };
    let criterion = criterion.warm_up_time(warm_up).measurement_time(measurement);
    if quick_mode() { criterion.sample_size(10).nresamples(1000) } else { criterion }
}
