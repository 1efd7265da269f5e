//! Glue for the command-line programs `raytrace` (render a mesh to an image) and `raycast`
//! (trace an array of rays): timing figures and the few parsers the programs share. The work
//! itself is in `render` and the back ends, which the programs choose through `backends`.

#![deny(missing_docs)]

pub mod args;
pub mod paths;
pub mod progress;
pub mod record;
pub mod see;
pub mod signals;

use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Duration;

use anyhow::Context as _;
use backends::Precision;
use render::output::{AtomicFile, Written};
use scene::Mesh;

use record::{CameraRecord, Record};

pub use args::{clap_exit, parse_vec3};
pub use paths::{Named, UsageError};

/// How long each part of a run took.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Timings {
    /// Reading and parsing the mesh.
    pub load: Duration,
    /// Building the BVH and preparing the triangles for the back end.
    pub build: Duration,
    /// Tracing every ray.
    pub trace: Duration,
    /// Encoding and writing the image or hits (into the temporary file).
    pub write: Duration,
    /// The whole run, from the program's start to the stats being written: the phases
    /// above, and also the checks, the thread pool's start, reading the rays.
    pub wall: Duration,
}

/// The figures both programs print and write with `--stats` (the JSON keys are the field
/// names; the run record's keys sit beside them).
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
    /// Time to encode and write the image or hits.
    pub write_ms: f64,
    /// Wall time of the whole run (see [`Timings::wall`]).
    pub wall_ms: f64,
    /// Rays per second during tracing, in millions.
    pub mrays_per_s: f64,
    /// The back end's name (`la`, `la-mt`, ...).
    pub backend: String,
    /// `f32` or `f64`.
    pub precision: String,
    /// Threads used for tracing.
    pub threads: usize,
    /// The process's peak resident memory so far, in bytes ([`peak_memory_bytes`]).
    pub peak_memory_bytes: Option<u64>,
    /// The camera of a rendered frame (`raytrace`), however it was placed.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub camera: Option<CameraRecord>,
    /// The run record (with `--stats`): program, commit, command, inputs, output, machine.
    #[serde(flatten)]
    pub record: Option<Record>,
    /// With `--compare`: the comparison's figures (absent otherwise).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub compare: Option<CompareStats>,
}

/// The `compare` object of the `--stats` JSON (the keys are the field names).
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct CompareStats {
    /// Each back end's own figures, in the order asked for.
    pub backends: Vec<BackendTimes>,
    /// Pixels on which some two back ends disagree (hit against miss, or triangles).
    pub disagreeing_pixels: usize,
    /// One entry per pair, as in the table.
    pub pairs: Vec<PairEntry>,
}

/// One back end's times in a comparison.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct BackendTimes {
    /// The back end's name.
    pub name: String,
    /// Time to build its BVH.
    pub build_ms: f64,
    /// Time to trace its rays (for the first, the image's render and the hits).
    pub trace_ms: f64,
}

/// A pair's figures and the diff image written for it.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct PairEntry {
    /// The figures.
    #[serde(flatten)]
    pub stats: render::compare::PairStats,
    /// The diff image's path, as written.
    pub diff_image: String,
}

impl CompareStats {
    /// The figures of `comparison`, with each back end's `(build, trace)` times and each
    /// pair's diff image path (in the order of `comparison.pairs`).
    #[must_use]
    pub fn new(
        comparison: &render::compare::Comparison,
        times: &[(Duration, Duration)],
        diff_images: &[PathBuf],
    ) -> Self {
        let backends = comparison
            .backends
            .iter()
            .zip(times)
            .map(|(name, &(build, trace))| BackendTimes {
                name: name.clone(),
                build_ms: ms(build),
                trace_ms: ms(trace),
            })
            .collect();
        let pairs = comparison
            .pairs
            .iter()
            .zip(diff_images)
            .map(|(p, path)| PairEntry { stats: p.clone(), diff_image: path.display().to_string() })
            .collect();
        Self { backends, disagreeing_pixels: comparison.disagreements.len(), pairs }
    }
}

/// The longest file name written (most file systems' limit, in bytes).
pub const MAX_NAME_BYTES: usize = 255;

/// The diff image of back ends `a` and `b` for the image `output`: beside it, named
/// `STEM.diff.A.B.png` (`out.png` gives `out.diff.la.ga.png`), whatever `output`'s format.
///
/// # Errors
///
/// [`UsageError`] when the name would be longer than [`MAX_NAME_BYTES`] (found before the
/// work rather than when the finished file is renamed into place).
pub fn diff_path(output: &Path, a: &str, b: &str) -> anyhow::Result<PathBuf> {
    let mut name = output.file_stem().unwrap_or_default().to_os_string();
    name.push(format!(".diff.{a}.{b}.png"));
    if name.len() > MAX_NAME_BYTES {
        return Err(UsageError(format!(
            "{}: the name of the diff image for {a} and {b} would be longer than \
             {MAX_NAME_BYTES} bytes: choose a shorter output name",
            output.display()
        ))
        .into());
    }
    Ok(output.with_file_name(name))
}

/// The peak resident memory of this process, in bytes: Linux's `VmHWM` of
/// `/proc/self/status`, which counts this program's memory only (`getrusage`'s `ru_maxrss`
/// would also count the memory of the process that started it, from before the exec).
/// `None` where the file does not exist.
#[must_use]
pub fn peak_memory_bytes() -> Option<u64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find_map(|l| l.strip_prefix("VmHWM:"))?;
    let kib: u64 = line.trim().strip_suffix("kB")?.trim().parse().ok()?;
    kib.checked_mul(1024)
}

impl Stats {
    /// Figures from the measured durations; `mrays_per_s` is `rays / trace`, with the trace
    /// time counted as at least a nanosecond so that it stays finite.
    #[must_use]
    pub fn new(
        triangles: usize,
        rays: u64,
        time: Timings,
        backend: &str,
        precision: Precision,
        threads: usize,
    ) -> Self {
        let secs = time.trace.as_secs_f64().max(1e-9);
        Self {
            triangles,
            rays,
            load_ms: ms(time.load),
            build_ms: ms(time.build),
            trace_ms: ms(time.trace),
            write_ms: ms(time.write),
            wall_ms: ms(time.wall),
            mrays_per_s: rays as f64 / secs / 1e6,
            backend: backend.to_owned(),
            precision: precision.name().to_owned(),
            threads,
            peak_memory_bytes: peak_memory_bytes(),
            camera: None,
            record: None,
            compare: None,
        }
    }

    /// The one-line summary the programs print; with a camera, the options that repeat its
    /// view (so that the view `--camera auto` chose can be given again).
    #[must_use]
    pub fn summary(&self) -> String {
        let camera = self.camera.map(|c| format!(", camera {}", c.options()));
        let figures = format!(
            "{} triangles, load {:.1} ms, BVH build {:.1} ms, trace {:.1} ms, write {:.1} ms, \
             total {:.1} ms, {} rays, {:.2} Mrays/s ({} {}, {} threads)",
            self.triangles,
            self.load_ms,
            self.build_ms,
            self.trace_ms,
            self.write_ms,
            self.wall_ms,
            self.rays,
            self.mrays_per_s,
            self.backend,
            self.precision,
            self.threads
        );
        figures + &camera.unwrap_or_default()
    }

    /// Writes the figures as pretty-printed JSON into `file` (created earlier, so that an
    /// unwritable path fails before the work), to be committed with the run's other outputs.
    ///
    /// # Errors
    ///
    /// If writing fails.
    pub fn write_json(&self, file: AtomicFile) -> anyhow::Result<Written> {
        Ok(file.write(|w| {
            serde_json::to_writer_pretty(&mut *w, self).map_err(std::io::Error::other)?;
            std::io::Write::write_all(w, b"\n")
        })?)
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

/// Checks the files a run names before any work (see [`paths`]): the `--stats` path, then
/// every output against the inputs and the other outputs; then starts removing the outputs'
/// temporary files on SIGINT and SIGTERM ([`signals`]). `outputs` includes the stats file.
///
/// # Errors
///
/// [`UsageError`] or a data error from [`paths`]; an error if the signals cannot be handled.
pub fn start_run(
    inputs: &[Named<'_>],
    outputs: &[Named<'_>],
    stats: Option<&Path>,
) -> anyhow::Result<()> {
    paths::check_output_names(outputs)?;
    if let Some(stats) = stats {
        paths::check_stats_path(stats)?;
    }
    paths::check_outputs(inputs, outputs)?;
    signals::remove_outputs_on_interrupt(outputs.first().map_or(Path::new("output"), |o| o.path))
}

/// Loads the mesh for a run in `precision`.
///
/// # Errors
///
/// The loader's errors; and, for `f32`, a vertex coordinate beyond f32's range (it would
/// round to infinity and the triangles through it would vanish without a word).
pub fn load_mesh(path: &Path, precision: Precision) -> anyhow::Result<Mesh> {
    let mesh = Mesh::load(path)?;
    if precision == Precision::F32
        && let Some((_, value)) = mesh.first_coordinate_beyond(f64::from(f32::MAX))
    {
        anyhow::bail!(
            "{}: vertex coordinate {value:e} is beyond f32's range (about 3.4e38): \
             use --precision f64",
            path.display()
        );
    }
    Ok(mesh)
}

/// Creates the `--stats` file early if one was asked for, with the file named in the error.
///
/// # Errors
///
/// If the file's directory is missing or not writable.
pub fn create_stats_file(path: Option<&Path>) -> anyhow::Result<Option<AtomicFile>> {
    Ok(path.map(AtomicFile::create).transpose()?)
}

/// Builds the thread pool for `threads` threads (see [`args::resolve_threads`]).
///
/// # Errors
///
/// If the operating system refuses the threads.
pub fn thread_pool(threads: usize) -> anyhow::Result<rayon::ThreadPool> {
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .context("cannot start the worker threads")
}

/// The program's exit for the result of its run: success, or one `error:` line and status 2
/// for a [`UsageError`], 1 for anything else.
#[must_use]
pub fn exit(result: anyhow::Result<()>) -> ExitCode {
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {}", error_line(&e));
            if e.downcast_ref::<UsageError>().is_some() {
                ExitCode::from(2)
            } else {
                ExitCode::FAILURE
            }
        }
    }
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
    fn stats_figures_and_keys() {
        let ms = Duration::from_millis;
        let time =
            Timings { load: ms(3), build: ms(4), trace: ms(500), write: ms(6), wall: ms(520) };
        let s = Stats::new(10, 2_000_000, time, "la", Precision::F64, 2);
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
                "peak_memory_bytes",
                "precision",
                "rays",
                "threads",
                "trace_ms",
                "triangles",
                "wall_ms",
                "write_ms"
            ]
        );
        assert!(s.summary().starts_with("10 triangles, load 3.0 ms, BVH build 4.0 ms"));
        assert!(s.summary().contains("write 6.0 ms, total 520.0 ms"), "{}", s.summary());
        let z = Stats::new(1, 1, Timings::default(), "la", Precision::F32, 1);
        assert!(z.mrays_per_s.is_finite());
    }
}
