//! `results/SUMMARY.md`, generated from the CSV files: whether the report's conclusion holds
//! on this machine, with figures, and the state of every hard limit.

use std::fmt::Write as _;
use std::fs;
use std::path::Path;

use backends::Backend;
use serde::de::DeserializeOwned;

use super::rows::{AccuracyRow, StabilityRow};
use crate::distinct;

mod matrix;
mod tables;

use matrix::read_optional;
pub use matrix::{InstructionLine, InterleavedLine, KernelLine, kernel_lines, target};
use tables::{accuracy_table, aimed_table, families, limits, sweeps};

/// One row of `results/throughput.csv` (written by the throughput bench), the columns this
/// summary reads.
#[derive(Clone, Debug, PartialEq)]
pub struct ThroughputLine {
    /// Back end.
    pub backend: String,
    /// `f32` or `f64`.
    pub precision: String,
    /// Scene.
    pub scene: String,
    /// Ray set.
    pub ray_set: String,
    /// Threads.
    pub threads: String,
    /// Millions of rays per second.
    pub mrays_per_s: f64,
    /// Time over `la`'s in the same precision, scene, ray set and threads.
    pub ratio_to_la: Option<f64>,
}

/// Reads CSV rows.
///
/// # Errors
///
/// A message naming the file.
pub fn read_rows<R: DeserializeOwned>(path: &Path) -> Result<Vec<R>, String> {
    let mut reader =
        csv::Reader::from_path(path).map_err(|e| format!("{}: {e}", path.display()))?;
    reader
        .deserialize()
        .collect::<Result<Vec<R>, _>>()
        .map_err(|e| format!("{}: {e}", path.display()))
}

/// Reads `throughput.csv` by column name; `Ok(None)` when the file is absent.
///
/// # Errors
///
/// A message naming the file when it exists but lacks a column or holds a bad number.
pub fn read_throughput(path: &Path) -> Result<Option<Vec<ThroughputLine>>, String> {
    if !path.exists() {
        return Ok(None);
    }
    let err = |e: &dyn std::fmt::Display| format!("{}: {e}", path.display());
    let mut reader = csv::Reader::from_path(path).map_err(|e| err(&e))?;
    let headers = reader.headers().map_err(|e| err(&e))?.clone();
    let column = |name: &str| {
        headers.iter().position(|h| h == name).ok_or_else(|| err(&format!("no column {name}")))
    };
    let (b, p, s) = (column("backend")?, column("precision")?, column("scene")?);
    let (r, t) = (column("ray_set")?, column("threads")?);
    let (m, q) = (column("mrays_per_s")?, column("ratio_to_la")?);
    let mut out = Vec::new();
    for record in reader.records() {
        let record = record.map_err(|e| err(&e))?;
        let number = |k: usize| -> Result<Option<f64>, String> {
            let text = record.get(k).unwrap_or("");
            if text.is_empty() { Ok(None) } else { text.parse().map(Some).map_err(|e| err(&e)) }
        };
        out.push(ThroughputLine {
            backend: record[b].to_owned(),
            precision: record[p].to_owned(),
            scene: record[s].to_owned(),
            ray_set: record[r].to_owned(),
            threads: record[t].to_owned(),
            mrays_per_s: number(m)?.unwrap_or(f64::NAN),
            ratio_to_la: number(q)?,
        });
    }
    Ok(Some(out))
}

/// Reads the CSVs in `results` and writes `SUMMARY.md` there, and `matrix.svg` (the
/// like-for-like plot) when `interleaved.csv` is present.
///
/// # Errors
///
/// A message naming the file that could not be read or written.
pub fn write_summary(results: &Path) -> Result<(), String> {
    let accuracy: Vec<AccuracyRow> = read_rows(&results.join("accuracy.csv"))?;
    let stability: Vec<StabilityRow> = read_rows(&results.join("stability.csv"))?;
    let throughput = read_throughput(&results.join("throughput.csv"))?;
    let interleaved: Option<Vec<InterleavedLine>> =
        read_optional(&results.join("interleaved.csv"))?;
    let kernels: Option<Vec<KernelLine>> = read_optional(&results.join("kernels.csv"))?;
    let instructions: Option<Vec<InstructionLine>> =
        read_optional(&results.join("instructions.csv"))?;
    let measured = Measured {
        throughput: throughput.as_deref(),
        interleaved: interleaved.as_deref(),
        kernels: kernels.as_deref(),
        instructions: instructions.as_deref(),
        kernel_lines: &kernel_lines(&crate::workspace_root()),
    };
    if let Some(lines) = &interleaved {
        let svg = results.join("matrix.svg");
        matrix::draw_matrix_svg(&svg, lines).map_err(|e| format!("{}: {e}", svg.display()))?;
    }
    let text = render(&accuracy, &stability, &measured);
    let path = results.join("SUMMARY.md");
    fs::write(&path, text).map_err(|e| format!("{}: {e}", path.display()))
}

fn fmt(x: Option<f64>) -> String {
    match x {
        None => "-".to_owned(),
        Some(0.0) => "0".to_owned(),
        Some(v) if v.abs() >= 1e4 || v.abs() < 1e-2 => format!("{v:.2e}"),
        Some(v) if v.abs() >= 100.0 => format!("{v:.0}"),
        Some(v) => format!("{v:.3}").trim_end_matches('0').trim_end_matches('.').to_owned(),
    }
}

fn count(x: Option<u64>) -> String {
    x.map_or_else(|| "-".to_owned(), |v| v.to_string())
}

fn find<'a>(
    rows: &'a [AccuracyRow],
    backend: &str,
    precision: &str,
    set: &str,
) -> Option<&'a AccuracyRow> {
    rows.iter().find(|r| r.backend == backend && r.precision == precision && r.ray_set == set)
}

/// The median of the finite values, if any.
fn median(mut v: Vec<f64>) -> Option<f64> {
    v.retain(|x| x.is_finite());
    (!v.is_empty()).then(|| crate::median(&mut v))
}

/// The timing CSVs the summary reads beside the accuracy suite's, each absent when its bench
/// has not been run.
#[derive(Clone, Copy, Debug, Default)]
pub struct Measured<'a> {
    /// `throughput.csv`.
    pub throughput: Option<&'a [ThroughputLine]>,
    /// `interleaved.csv`: the like-for-like times.
    pub interleaved: Option<&'a [InterleavedLine]>,
    /// `kernels.csv`: ns per test and bytes per triangle.
    pub kernels: Option<&'a [KernelLine]>,
    /// `instructions.csv`: instructions per ray.
    pub instructions: Option<&'a [InstructionLine]>,
    /// Lines of code per back end's kernel ([`kernel_lines`]).
    pub kernel_lines: &'a [(String, usize)],
}

/// The summary's Markdown.
#[must_use]
pub fn render(accuracy: &[AccuracyRow], stability: &[StabilityRow], measured: &Measured) -> String {
    let mut s = String::new();
    let cpu = accuracy.first().map_or("unknown", |r| r.cpu.as_str());
    let _ = writeln!(s, "# Like for like, accuracy and stability: summary\n");
    let _ = writeln!(
        s,
        "Generated from `results/accuracy.csv`, `results/stability.csv` and, when present, \
         `results/interleaved.csv`, `results/kernels.csv`, `results/instructions.csv` and \
         `results/throughput.csv` by `cargo bench -p wedge-benches --bench accuracy` (or \
         `cargo run -p wedge-benches --bin summary` to regenerate from the CSVs alone). Do not \
         edit. CPU: {cpu}.\n"
    );
    matrix::verdict(&mut s, accuracy, measured);
    conclusion(&mut s, accuracy, measured.throughput);
    limits(&mut s, accuracy, stability);
    accuracy_table(&mut s, accuracy);
    aimed_table(&mut s, accuracy);
    sweeps(&mut s, stability);
    families(&mut s, stability);
    let _ = writeln!(s, "## Definitions\n");
    let _ = writeln!(
        s,
        "Every figure is judged by the exact reference (`exact`) on exactly the values \
         each back end saw (its precision's rounding of the suite's rays and triangles). \
         A **disagreement** is a hit where the reference misses or the reverse (for aimed rays: \
         any outcome other than the reference's single triangle). A **crack** is a ray aimed \
         at a point of a shared edge or at a shared vertex that hits none of the triangles \
         there; a **double hit** is one that more than one of them reports hit (any-hit \
         semantics). The reference's tie rule makes exactly one triangle count for a ray \
         exactly through an edge (an **exact tie**); a kernel with simply closed edges reports \
         both, which is counted as a double hit, while the watertight back ends ({}) break \
         ties with a rule of their own and report one (on a tie, either single triangle is \
         right). Aimed rays are kept only where every triangle at the target faces the ray the \
         same way (no fold seen along the ray). **Distance errors** are against the exact \
         rational `t`, relative and in ulps of the back end's precision. Full definitions: the \
         docs of `wedge_benches::accuracy`.\n",
        watertight_names()
    );
    s
}

/// The back ends that declare themselves watertight, as `` `la`, `ga-plucker`, ... ``.
fn watertight_names() -> String {
    let names = Backend::ALL.iter().filter(|b| b.guarantees().watertight).map(|b| b.name());
    names.map(|n| format!("`{n}`")).collect::<Vec<_>>().join(", ")
}

/// Whether `name` is a back end of the registry other than the baseline (`la`), which the
/// cost tables compare with it.
fn compared_with_baseline(name: &str) -> bool {
    Backend::from_name(name).is_some_and(|b| b != Backend::BASELINE)
}

/// Images and cost per back end, every back end against `la` (the default), whatever its
/// method: the tables the like-for-like verdict above is read beside.
fn conclusion(s: &mut String, rows: &[AccuracyRow], throughput: Option<&[ThroughputLine]>) {
    let _ = writeln!(s, "## Images and cost of every back end against `la`\n");
    let _ = writeln!(
        s,
        "Every back end against the default (`la`, LA watertight), across methods: what a \
         user choosing a back end sees. The like-for-like comparison of algebras is above.\n"
    );
    let camera: Vec<&AccuracyRow> = rows.iter().filter(|r| r.ray_set == "camera").collect();
    if camera.is_empty() {
        let _ = writeln!(s, "**Images**: no camera rows in `accuracy.csv` (the run had none).\n");
    } else {
        let pixels = camera[0].rays;
        let side = (pixels as f64).sqrt().round();
        let _ = writeln!(
            s,
            "**Images.** The bunny drawn by each back end ({side} x {side} pixels, closest hit \
             per pixel); a pixel differs when its nearest triangle (or miss) differs from \
             `la`'s in the same precision.\n"
        );
        let _ = writeln!(
            s,
            "| back end | precision | pixels differing from `la` | per million | pixels where the reference's triangle differs |"
        );
        let _ = writeln!(s, "|---|---|---|---|---|");
        for r in &camera {
            let differ = r.differs_from_la_per_million.map(|pm| (pm * r.rays as f64 / 1e6).round());
            let wrong = r.wrong_triangle.map(|w| w as f64);
            let _ = writeln!(
                s,
                "| {} | {} | {} | {} | {} (+{} hit/miss) |",
                r.backend,
                r.precision,
                fmt(differ),
                fmt(r.differs_from_la_per_million),
                fmt(wrong),
                r.disagreements
            );
        }
        let _ = writeln!(s);
    }
    let _ = writeln!(
        s,
        "**Cost.** Nanoseconds per ray from this bench (closest hit through the BVH, random \
         rays through the bunny, one thread, thread CPU time) and the ratio to `la` in the \
         same precision:\n"
    );
    let _ = writeln!(s, "| back end | f32 ns/ray | ratio to la | f64 ns/ray | ratio to la |");
    let _ = writeln!(s, "|---|---|---|---|---|");
    let backends = distinct(rows.iter().map(|r| r.backend.as_str()));
    for b in &backends {
        let mut cells = Vec::new();
        for p in ["f32", "f64"] {
            let ns = find(rows, b, p, "random").and_then(|r| r.ns_per_ray);
            let la = find(rows, Backend::BASELINE.name(), p, "random").and_then(|r| r.ns_per_ray);
            let ratio = ns.zip(la).map(|(a, l)| a / l);
            cells.push(format!("{} | {}", fmt(ns), fmt(ratio)));
        }
        let _ = writeln!(s, "| {b} | {} |", cells.join(" | "));
    }
    let _ = writeln!(s);
    match throughput {
        None => {
            let _ = writeln!(
                s,
                "`results/throughput.csv` is **absent**: the throughput bench \
                 (`cargo bench -p wedge-benches --bench throughput`) has not been run here, so \
                 the cost figures above are this bench's only.\n"
            );
        }
        Some(lines) => {
            let _ = writeln!(
                s,
                "From `results/throughput.csv` (every scene, ray set and thread count it \
                 holds), time relative to `la` in the same precision, scene, ray set and \
                 threads:\n"
            );
            let _ =
                writeln!(s, "| back end | precision | cases | median ratio to la | min | max |");
            let _ = writeln!(s, "|---|---|---|---|---|---|");
            for b in backends.iter().filter(|b| compared_with_baseline(b)) {
                for p in ["f32", "f64"] {
                    let ratios: Vec<f64> = lines
                        .iter()
                        .filter(|l| l.backend == *b && l.precision == p)
                        .filter_map(|l| l.ratio_to_la)
                        .collect();
                    if ratios.is_empty() {
                        continue;
                    }
                    let lo = ratios.iter().copied().fold(f64::INFINITY, f64::min);
                    let hi = ratios.iter().copied().fold(0.0, f64::max);
                    let m = median(ratios.clone());
                    let _ = writeln!(
                        s,
                        "| {b} | {p} | {} | {} | {} | {} |",
                        ratios.len(),
                        fmt(m),
                        fmt(Some(lo)),
                        fmt(Some(hi))
                    );
                }
            }
            let _ = writeln!(s);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use backends::{Algebra, Method};

    fn row(backend: &str, precision: &str, ray_set: &str) -> AccuracyRow {
        AccuracyRow {
            backend: backend.into(),
            precision: precision.into(),
            scene: "bunny".into(),
            ray_set: ray_set.into(),
            rays: 10_000,
            hits: 5_000,
            cpu: "test cpu".into(),
            ..AccuracyRow::default()
        }
    }

    /// Camera rows (with the given pixel differences from `la`) and timed random rows.
    fn rows(ga_differs: f64, ga_ns: f64) -> Vec<AccuracyRow> {
        let mut out = Vec::new();
        for p in ["f32", "f64"] {
            for (b, ns, differs) in [("la", 100.0, 0.0), ("ga", ga_ns, ga_differs)] {
                let mut random = row(b, p, "random");
                random.ns_per_ray = Some(ns);
                out.push(random);
                let mut camera = row(b, p, "camera");
                camera.differs_from_la_per_million = Some(differs);
                camera.wrong_triangle = Some(0);
                out.push(camera);
            }
        }
        out
    }

    /// Interleaved lines for every back end, in one column, with `rate(backend)` Mrays/s.
    fn interleaved(rate: impl Fn(Backend) -> f64) -> Vec<InterleavedLine> {
        let mut out = Vec::new();
        for b in Backend::ALL {
            for p in ["f32", "f64"] {
                out.push(InterleavedLine {
                    backend: b.name().into(),
                    precision: p.into(),
                    scene: "bunny".into(),
                    ray_set: "primary_closest".into(),
                    median_mrays_per_s: rate(b),
                });
            }
        }
        out
    }

    #[test]
    fn the_verdict_follows_the_figures() {
        let absent = render(&rows(0.0, 110.0), &[], &Measured::default());
        assert!(absent.contains("`results/interleaved.csv` is **absent**"), "{absent}");
        assert!(absent.contains("`results/throughput.csv` is **absent**"));
        // Every cell as fast as its LA cell: every row met, the report's conclusion holds.
        let level = interleaved(|_| 10.0);
        let m = Measured { interleaved: Some(&level), ..Measured::default() };
        let text = render(&rows(0.0, 110.0), &[], &m);
        assert!(!text.contains("**missed**"), "{text}");
        assert!(text.contains("the report's conclusion holds when methods are matched"), "{text}");
        assert!(text.contains("Neither reduces computation"), "{text}");
        // CGA cells at half the rate: 2x their LA cells' time, over the 1.10 target.
        let slow = interleaved(|b| if b.algebra() == Algebra::Cga { 5.0 } else { 10.0 });
        let m = Measured { interleaved: Some(&slow), ..Measured::default() };
        let text = render(&rows(0.0, 110.0), &[], &m);
        let cga_mt = Backend::cell(Method::MollerTrumbore, Algebra::Cga).unwrap().name();
        let row = format!("| mt | `{cga_mt}` | cga | f32 | 2 | 2 | 1.10 | **missed** |");
        assert!(text.contains(&row), "{text}");
        assert!(text.contains("**Why cells miss.**"), "{text}");
        assert!(text.contains("| cga | 2 (2-2) | 0 of 10 |"), "{text}");
        // G3 faster than LA for the same method: a benefit the report did not find.
        let fast = interleaved(|b| if b.algebra() == Algebra::G3 { 20.0 } else { 10.0 });
        let m = Measured { interleaved: Some(&fast), ..Measured::default() };
        let text = render(&rows(0.0, 110.0), &[], &m);
        assert!(text.contains("3D GA is faster than LA for the same method"), "{text}");
    }

    #[test]
    fn every_backend_of_the_registry_reaches_the_cost_tables() {
        // Rows and throughput lines for every back end (and the reference, which is not a
        // back end): each back end but the baseline gets a throughput row, whatever its name.
        let mut rows = Vec::new();
        let mut tp = Vec::new();
        let names = Backend::ALL.map(Backend::name);
        for b in names.into_iter().chain(["exact"]) {
            let mut random = row(b, "f32", "random");
            random.ns_per_ray = Some(100.0);
            rows.push(random);
            tp.push(ThroughputLine {
                backend: b.into(),
                precision: "f32".into(),
                scene: "bunny".into(),
                ray_set: "primary".into(),
                threads: "1".into(),
                mrays_per_s: 1.0,
                ratio_to_la: Some(1.0),
            });
        }
        let m = Measured { throughput: Some(&tp), ..Measured::default() };
        let text = render(&rows, &[], &m);
        for b in names {
            let cost_row = format!("| {b} | 100 | 1 |");
            assert!(text.contains(&cost_row), "{b} missing from the cost table:\n{text}");
            let tp_row = format!("| {b} | f32 | 1 | 1 | 1 | 1 |");
            let listed = text.contains(&tp_row);
            assert_eq!(listed, Backend::from_name(b) != Some(Backend::BASELINE), "{b}:\n{text}");
        }
        assert!(!text.contains("| exact | f32 | 1 |"), "the reference is not compared");
        assert!(!compared_with_baseline("exact"));
    }

    #[test]
    fn throughput_columns_are_read_by_name() {
        let dir = std::env::temp_dir().join(format!("wedge-summary-{}", std::process::id()));
        fs::create_dir_all(&dir).unwrap();
        let path = dir.join("throughput.csv");
        assert_eq!(read_throughput(&path), Ok(None));
        fs::write(
            &path,
            "backend,precision,scene,triangles,ray_set,threads,mrays_per_s,ratio_to_la\n\
             ga,f32,bunny,69451,primary,1,5.5,1.25\nla,f32,bunny,69451,primary,1,6.9,\n",
        )
        .unwrap();
        let lines = read_throughput(&path).unwrap().unwrap();
        assert_eq!(lines.len(), 2);
        assert_eq!((lines[0].ratio_to_la, lines[1].ratio_to_la), (Some(1.25), None));
        fs::write(&path, "backend,precision\nga,f32\n").unwrap();
        assert!(read_throughput(&path).unwrap_err().contains("no column scene"));
        fs::remove_dir_all(&dir).unwrap();
    }
}
