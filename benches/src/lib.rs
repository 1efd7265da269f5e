//! Helpers shared by the benches: where criterion keeps its estimates, where results go, and
//! the CSV rows the benches write.
//!
//! The benches measure with criterion and then turn its estimates into `results/*.csv`: after
//! the groups have run, [`mean_ns`] (or [`median_ns`]) reads
//! `<criterion dir>/<group>/<function>/new/estimates.json` (the mean's or the median's point
//! estimate) for each measurement and the bench writes one CSV row per comparison. Reading
//! criterion's own files keeps one source of truth for every figure.
//!
//! ```
//! use wedge_benches::{GaOpsFigures, GaOpsRow, Target};
//!
//! let figures = GaOpsFigures { ga_ns: Some(2.2), glam_ns: Some(2.0), paired_ratio: Some(1.08) };
//! let row = GaOpsRow::new("rotor_rotate", "f32", figures, Target::RatioToGlam(1.1), "cpu");
//! assert_eq!(row.ratio_ga_over_glam, Some(1.08));
//! assert_eq!(row.meets_target, Some(true));
//! ```

#![deny(missing_docs)]

pub mod accuracy;
pub mod alternate;
pub mod clock;
pub mod throughput;

use std::fs;
use std::io;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, SystemTime};

use serde::Serialize;

/// The workspace root (the parent of this crate's manifest directory).
#[must_use]
pub fn workspace_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).parent().expect("benches/ has a parent").to_path_buf()
}

/// `results/` at the workspace root.
#[must_use]
pub fn results_dir() -> PathBuf {
    workspace_root().join("results")
}

/// True when `WEDGE_BENCH_QUICK=1`: benches then run for a few milliseconds each, enough for
/// CI to check that they build and run, and write their CSV under the criterion directory
/// instead of `results/` so that smoke runs never overwrite real measurements.
#[must_use]
pub fn quick_mode() -> bool {
    std::env::var("WEDGE_BENCH_QUICK").is_ok_and(|v| v == "1")
}

/// Where a bench writes its output `stem.ext` (`"kernels", "csv"`): `results/` only after a
/// complete, non-quick run. A quick run writes `stem.quick.ext` and an incomplete one (a
/// criterion filter after `--`, or a selection by environment variable) `stem.partial.ext`,
/// both in the criterion directory, so that neither replaces a table in `results/` with
/// part of it.
#[must_use]
pub fn output_path(stem: &str, ext: &str, complete: bool) -> PathBuf {
    if quick_mode() {
        criterion_dir().join(format!("{stem}.quick.{ext}"))
    } else if !complete {
        criterion_dir().join(format!("{stem}.partial.{ext}"))
    } else {
        results_dir().join(format!("{stem}.{ext}"))
    }
}

/// Warm-up and measurement time for one benchmark: about 20 ms each in quick mode, criterion's
/// usual 3 s and 5 s otherwise.
#[must_use]
pub fn bench_times() -> (Duration, Duration) {
    if quick_mode() {
        (Duration::from_millis(20), Duration::from_millis(20))
    } else {
        (Duration::from_secs(3), Duration::from_secs(5))
    }
}

/// The directory criterion writes to, found the way criterion finds it: `$CRITERION_HOME`,
/// else `$CARGO_TARGET_DIR/criterion`, else the target directory reported by `cargo metadata`
/// (cargo sets `$CARGO` for the benches it runs), else `target/criterion`.
#[must_use]
pub fn criterion_dir() -> PathBuf {
    if let Some(home) = std::env::var_os("CRITERION_HOME") {
        return PathBuf::from(home);
    }
    if let Some(target) = std::env::var_os("CARGO_TARGET_DIR") {
        return PathBuf::from(target).join("criterion");
    }
    let from_metadata = std::env::var_os("CARGO").and_then(|cargo| {
        let output = Command::new(cargo)
            .args(["metadata", "--format-version", "1", "--no-deps"])
            .output()
            .ok()?;
        let metadata: serde_json::Value = serde_json::from_slice(&output.stdout).ok()?;
        Some(PathBuf::from(metadata.get("target_directory")?.as_str()?))
    });
    from_metadata.unwrap_or_else(|| PathBuf::from("target")).join("criterion")
}

/// The mean time per iteration in nanoseconds that criterion estimated for `group/function`,
/// or `None` when there is no estimate written at or after `since` (the benchmark was filtered
/// out of this run, or failed).
#[must_use]
pub fn mean_ns(
    criterion_dir: &Path,
    group: &str,
    function: &str,
    since: SystemTime,
) -> Option<f64> {
    estimate_ns(criterion_dir, group, function, since, "mean")
}

/// As [`mean_ns`], the median of the samples' times per iteration: unmoved by a few samples
/// that an interrupt or a descheduling made slow.
#[must_use]
pub fn median_ns(
    criterion_dir: &Path,
    group: &str,
    function: &str,
    since: SystemTime,
) -> Option<f64> {
    estimate_ns(criterion_dir, group, function, since, "median")
}

/// The point estimate of `statistic` in criterion's `estimates.json` for `group/function`, if
/// written at or after `since`.
fn estimate_ns(
    criterion_dir: &Path,
    group: &str,
    function: &str,
    since: SystemTime,
    statistic: &str,
) -> Option<f64> {
    let path = criterion_dir.join(group).join(function).join("new").join("estimates.json");
    let fresh = fs::metadata(&path).and_then(|m| m.modified()).is_ok_and(|t| t >= since);
    if !fresh {
        return None;
    }
    let text = fs::read_to_string(&path).ok()?;
    let estimates: serde_json::Value = serde_json::from_str(&text).ok()?;
    estimates.get(statistic)?.get("point_estimate")?.as_f64()
}

/// The median of `values` (the upper one of the two middle values for an even count),
/// sorting them in place; NaN sorts last, as `f64::total_cmp` orders it.
///
/// # Panics
///
/// If `values` is empty.
pub fn median(values: &mut [f64]) -> f64 {
    values.sort_by(f64::total_cmp);
    values[values.len() / 2]
}

pub use backends::machine::{cpu_model, node_test, target_features};

/// The machine description the benches write into their results: the CPU model and, in
/// brackets, the target features the build used ([`target_features`]) and the BVH's node test
/// chosen at run time ([`node_test`]), so that a figure measured with `-C target-cpu=native`
/// or with AVX-512 is told apart from one of the stated baseline.
#[must_use]
pub fn machine() -> String {
    format!("{} [{}; node test {}]", cpu_model(), target_features(), node_test())
}

/// What a GA operation is held to.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Target {
    /// At most this many times glam's time for the same operation.
    RatioToGlam(f64),
    /// At most this many nanoseconds per operation (no glam counterpart).
    MaxNs(f64),
    /// Measured for information only.
    None,
}

/// What was measured of one GA operation (see the `ga_ops` bench).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct GaOpsFigures {
    /// Median nanoseconds per operation with `ga` (criterion).
    pub ga_ns: Option<f64>,
    /// Median nanoseconds per operation with glam (criterion), where glam has the operation.
    pub glam_ns: Option<f64>,
    /// The median over rounds of `ga`'s time over glam's, the two timed back to back in each
    /// round.
    pub paired_ratio: Option<f64>,
}

/// One row of `results/ga_ops.csv`: a GA operation beside its glam counterpart.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct GaOpsRow {
    /// The operation, e.g. `rotor_rotate_vs_quat_mul_vec3`.
    pub op: String,
    /// `f32` or `f64`.
    pub precision: String,
    /// Median nanoseconds per operation with `ga` (criterion).
    pub ga_ns: Option<f64>,
    /// Median nanoseconds per operation with glam (criterion), where glam has the operation.
    pub glam_ns: Option<f64>,
    /// `ga`'s time over glam's: the median of the paired rounds' ratios.
    pub ratio_ga_over_glam: Option<f64>,
    /// The target in words, e.g. `ratio<=1.1` (on `ratio_ga_over_glam`) or `ga_ns<3`.
    pub target: String,
    /// Whether the target is met (empty when there is no target or no measurement).
    pub meets_target: Option<bool>,
    /// The CPU the figures were measured on.
    pub cpu: String,
}

impl GaOpsRow {
    /// A row from the figures of one operation (any may be missing) and its target.
    #[must_use]
    pub fn new(
        op: &str,
        precision: &str,
        figures: GaOpsFigures,
        target: Target,
        cpu: &str,
    ) -> Self {
        let ratio = figures.paired_ratio;
        let (target_text, meets) = match target {
            Target::RatioToGlam(max) => (format!("ratio<={max}"), ratio.map(|r| r <= max)),
            Target::MaxNs(max) => (format!("ga_ns<{max}"), figures.ga_ns.map(|ns| ns < max)),
            Target::None => (String::new(), None),
        };
        Self {
            op: op.to_owned(),
            precision: precision.to_owned(),
            ga_ns: figures.ga_ns,
            glam_ns: figures.glam_ns,
            ratio_ga_over_glam: ratio,
            target: target_text,
            meets_target: meets,
            cpu: cpu.to_owned(),
        }
    }
}

/// Writes rows as CSV with a header row, creating the parent directory.
///
/// # Errors
///
/// If the directory or file cannot be created or written.
pub fn write_csv<R: Serialize>(path: &Path, rows: &[R]) -> io::Result<()> {
    if let Some(parent) = path.parent() {
        fs::create_dir_all(parent)?;
    }
    let mut writer = csv::Writer::from_path(path)?;
    for row in rows {
        writer.serialize(row)?;
    }
    writer.flush()
}

/// A tiny deterministic generator (SplitMix64) for bench inputs, so that the benches need no
/// random-number crate and every run measures the same values.
#[derive(Clone, Debug)]
pub struct SplitMix64(u64);

impl SplitMix64 {
    /// A generator from a seed.
    #[must_use]
    pub fn new(seed: u64) -> Self {
        Self(seed)
    }

    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// A uniform value in `[low, high)`.
    pub fn range(&mut self, low: f64, high: f64) -> f64 {
        // The top 53 bits give every double in [0, 1) with equal spacing.
        let unit = (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64;
        low + (high - low) * unit
    }

    /// `N` values uniform in `[-1, 1)`.
    pub fn array<const N: usize>(&mut self) -> [f64; N] {
        std::array::from_fn(|_| self.range(-1.0, 1.0))
    }
}

/// The distinct values in first-seen order (the row order of a CSV, kept for its tables).
#[must_use]
pub fn distinct<T: PartialEq>(values: impl IntoIterator<Item = T>) -> Vec<T> {
    let mut out = Vec::new();
    for v in values {
        if !out.contains(&v) {
            out.push(v);
        }
    }
    out
}

/// The `main` of a bench that measures in child processes of its own binary: with the
/// environment variable `child_env` set, runs `child` on its value, else `parent`; an error
/// is printed as one `error:` line and fails the process.
#[must_use]
pub fn child_or_parent(
    child_env: &str,
    child: fn(&str) -> Result<(), String>,
    parent: fn() -> Result<(), String>,
) -> std::process::ExitCode {
    let result = match std::env::var(child_env) {
        Ok(spec) => child(&spec),
        Err(_) => parent(),
    };
    match result {
        Ok(()) => std::process::ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            std::process::ExitCode::FAILURE
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_a_complete_full_run_writes_to_results() {
        let (complete, part) =
            (output_path("kernels", "csv", true), output_path("kernels", "csv", false));
        if quick_mode() {
            assert_eq!(complete, criterion_dir().join("kernels.quick.csv"));
            assert_eq!(part, complete);
        } else {
            assert_eq!(complete, results_dir().join("kernels.csv"));
            assert_eq!(part, criterion_dir().join("kernels.partial.csv"));
        }
        assert!(output_path("throughput", "svg", false).ends_with(if quick_mode() {
            "throughput.quick.svg"
        } else {
            "throughput.partial.svg"
        }));
    }
}
