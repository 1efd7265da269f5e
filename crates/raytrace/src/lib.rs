//! Glue for the command-line programs `raytrace` (render a mesh to an image) and `raycast`
//! (trace an array of rays): timing figures and the few parsers the programs share. The work
//! itself is in `render` and the back ends, which the programs choose through `backends`.

#![deny(missing_docs)]

pub mod scenes;

use std::path::Path;
use std::time::Duration;

use anyhow::Context as _;
use backends::Precision;
use render::output::AtomicFile;

/// The figures both programs print and write with `--stats` (the JSON keys are the field
/// names).
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Stats {
    /// Triangles in the mesh.
    pub triangles: usize,
    /// Rays traced.
    pub rays: u64,
    /// Time to read and parse the mesh.
    pub load_ms: f64,
    /// Time to build the BVH and prepare the triangles for the back end.
    pub build_ms: f64,
    /// Time to trace every ray.
    pub trace_ms: f64,
    /// Rays per second during tracing, in millions.
    pub mrays_per_s: f64,
    /// The back end's name (`la`, `la-mt`, ...).
    pub backend: String,
    /// `f32` or `f64`.
    pub precision: String,
    /// Threads used for tracing.
    pub threads: usize,
}

impl Stats {
    /// Figures from the measured durations; `mrays_per_s` is `rays / trace`, with the trace
    /// time counted as at least a nanosecond so that it stays finite.
    #[must_use]
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        triangles: usize,
        rays: u64,
        load: Duration,
        build: Duration,
        trace: Duration,
        backend: &str,
        precision: Precision,
        threads: usize,
    ) -> Self {
        let secs = trace.as_secs_f64().max(1e-9);
        Self {
            triangles,
            rays,
            load_ms: ms(load),
            build_ms: ms(build),
            trace_ms: ms(trace),
            mrays_per_s: rays as f64 / secs / 1e6,
            backend: backend.to_owned(),
            precision: precision.name().to_owned(),
            threads,
        }
    }

    /// The one-line summary the programs print.
    #[must_use]
    pub fn summary(&self) -> String {
        format!(
            "{} triangles, load {:.1} ms, BVH build {:.1} ms, trace {:.1} ms, {} rays, \
             {:.2} Mrays/s ({} {}, {} threads)",
            self.triangles,
            self.load_ms,
            self.build_ms,
            self.trace_ms,
            self.rays,
            self.mrays_per_s,
            self.backend,
            self.precision,
            self.threads
        )
    }

    /// Writes the figures as pretty-printed JSON into `file` (created earlier, so that an
    /// unwritable path fails before the work).
    ///
    /// # Errors
    ///
    /// If writing fails.
    pub fn write_json(&self, file: AtomicFile) -> anyhow::Result<()> {
        file.commit(|w| {
            serde_json::to_writer_pretty(&mut *w, self).map_err(std::io::Error::other)?;
            std::io::Write::write_all(w, b"\n")
        })?;
        Ok(())
    }
}

fn ms(d: Duration) -> f64 {
    d.as_secs_f64() * 1e3
}

/// The one line a program prints for an error: the error and its causes joined by `": "`,
/// each cause left out when the line already says it (many errors repeat their source's
/// message in their own), newlines replaced by spaces.
#[must_use]
pub fn error_line(e: &anyhow::Error) -> String {
    let mut line = String::new();
    for cause in e.chain() {
        let text = cause.to_string();
        if line.contains(&text) {
            continue;
        }
        if !line.is_empty() {
            line.push_str(": ");
        }
        line.push_str(&text);
    }
    line.replace(['\n', '\r'], " ")
}

/// Parses `X,Y,Z` into three finite numbers (for `--eye`, `--look-at`, `--up`).
///
/// # Errors
///
/// A message naming what is wrong.
pub fn parse_vec3(text: &str) -> Result<[f64; 3], String> {
    let parts: Vec<&str> = text.split(',').map(str::trim).collect();
    let [x, y, z] = parts[..] else {
        return Err(format!("expected three comma-separated numbers X,Y,Z, got '{text}'"));
    };
    let num = |s: &str| match s.parse::<f64>() {
        Ok(v) if v.is_finite() => Ok(v),
        _ => Err(format!("'{s}' is not a finite number")),
    };
    Ok([num(x)?, num(y)?, num(z)?])
}

/// Creates the `--stats` file early if one was asked for, with the file named in the error.
///
/// # Errors
///
/// If the file's directory is missing or not writable.
pub fn create_stats_file(path: Option<&Path>) -> anyhow::Result<Option<AtomicFile>> {
    Ok(path.map(AtomicFile::create).transpose()?)
}

/// Builds the thread pool for `--threads` (0 or absent: one thread per core).
///
/// # Errors
///
/// If the operating system refuses the threads.
pub fn thread_pool(threads: Option<usize>) -> anyhow::Result<rayon::ThreadPool> {
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads.unwrap_or(0))
        .build()
        .context("cannot start the worker threads")
}

/// Installs a panic hook that prints one `error:` line instead of a message and backtrace:
/// a panic is a bug, but the user should still see a single line.
pub fn one_line_panics() {
    std::panic::set_hook(Box::new(|info| {
        let msg = info
            .payload()
            .downcast_ref::<&str>()
            .map(|s| (*s).to_owned())
            .or_else(|| info.payload().downcast_ref::<String>().cloned())
            .unwrap_or_else(|| "unknown panic".to_owned());
        let place = info.location().map(|l| format!(" at {}:{}", l.file(), l.line()));
        eprintln!("error: internal error: {}{}", msg.replace('\n', " "), place.unwrap_or_default());
    }));
}

/// Turns a clap error into the programs' exit: help and version go to stdout with status 0;
/// usage errors print one `error:` line and give status 2.
#[must_use]
pub fn clap_exit(e: &clap::Error) -> std::process::ExitCode {
    use clap::error::ErrorKind;
    if matches!(e.kind(), ErrorKind::DisplayHelp | ErrorKind::DisplayVersion) {
        print!("{e}");
        return std::process::ExitCode::SUCCESS;
    }
    let text = e.to_string();
    let first = text.lines().next().unwrap_or("invalid arguments");
    let first = first.strip_prefix("error: ").unwrap_or(first);
    eprintln!("error: {first} (see --help)");
    std::process::ExitCode::from(2)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn error_lines_skip_repeated_causes() {
        let io = std::io::Error::other("disk on fire");
        let e = anyhow::Error::new(io).context("out.png: write failed: disk on fire");
        assert_eq!(error_line(&e), "out.png: write failed: disk on fire");
        let e = anyhow::anyhow!("inner\nsecond").context("outer");
        assert_eq!(error_line(&e), "outer: inner second");
    }

    #[test]
    fn vec3_parsing() {
        assert_eq!(parse_vec3("1,-2.5, 3e1"), Ok([1.0, -2.5, 30.0]));
        assert!(parse_vec3("1,2").unwrap_err().contains("three"));
        assert!(parse_vec3("1,2,nan").unwrap_err().contains("'nan'"));
        assert!(parse_vec3("1,2,x").is_err());
    }

    #[test]
    fn stats_figures_and_keys() {
        let s = Stats::new(
            10,
            2_000_000,
            Duration::from_millis(3),
            Duration::from_millis(4),
            Duration::from_millis(500),
            "la",
            Precision::F64,
            2,
        );
        assert!((s.mrays_per_s - 4.0).abs() < 1e-12);
        let v = serde_json::to_value(&s).unwrap();
        let mut keys: Vec<&str> = v.as_object().unwrap().keys().map(String::as_str).collect();
        keys.sort_unstable();
        assert_eq!(
            keys,
            [
                "backend",
                "build_ms",
                "load_ms",
                "mrays_per_s",
                "precision",
                "rays",
                "threads",
                "trace_ms",
                "triangles"
            ]
        );
        assert!(s.summary().starts_with("10 triangles, load 3.0 ms, BVH build 4.0 ms"));
        let z = Stats::new(
            1,
            1,
            Duration::ZERO,
            Duration::ZERO,
            Duration::ZERO,
            "la",
            Precision::F32,
            1,
        );
        assert!(z.mrays_per_s.is_finite());
    }
}
