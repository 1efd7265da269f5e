//! `results/SUMMARY.md`, generated from the CSV files: whether the report's conclusion holds
//! on this machine, with figures, and the state of every hard limit.

use std::fmt::Write as _;
use std::fs;
use std::path::Path;

use serde::de::DeserializeOwned;

use super::rows::{AccuracyRow, StabilityRow};

mod tables;

use tables::{accuracy_table, aimed_table, families, limits, sweeps};

/// Ratios of GA to `la` time within this band count as "no significant difference".
pub const SAME_COST_BAND: (f64, f64) = (0.8, 1.25);

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

/// Reads the CSVs in `results` and writes `SUMMARY.md` there.
///
/// # Errors
///
/// A message naming the file that could not be read or written.
pub fn write_summary(results: &Path) -> Result<(), String> {
    let accuracy: Vec<AccuracyRow> = read_rows(&results.join("accuracy.csv"))?;
    let stability: Vec<StabilityRow> = read_rows(&results.join("stability.csv"))?;
    let throughput = read_throughput(&results.join("throughput.csv"))?;
    let text = render(&accuracy, &stability, throughput.as_deref());
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

fn median(mut v: Vec<f64>) -> Option<f64> {
    v.retain(|x| x.is_finite());
    v.sort_by(f64::total_cmp);
    (!v.is_empty()).then(|| v[v.len() / 2])
}

/// The summary's Markdown.
#[must_use]
pub fn render(
    accuracy: &[AccuracyRow],
    stability: &[StabilityRow],
    throughput: Option<&[ThroughputLine]>,
) -> String {
    let mut s = String::new();
    let cpu = accuracy.first().map_or("unknown", |r| r.cpu.as_str());
    let _ = writeln!(s, "# Accuracy and stability: summary\n");
    let _ = writeln!(
        s,
        "Generated from `results/accuracy.csv`, `results/stability.csv` and, when present, \
         `results/throughput.csv` by `cargo bench -p wedge-benches --bench accuracy` (or \
         `cargo run -p wedge-benches --bin summary` to regenerate from the CSVs alone). Do not \
         edit. CPU: {cpu}.\n"
    );
    conclusion(&mut s, accuracy, throughput);
    limits(&mut s, accuracy, stability);
    accuracy_table(&mut s, accuracy);
    aimed_table(&mut s, accuracy);
    sweeps(&mut s, stability);
    families(&mut s, stability);
    let _ = writeln!(s, "## Definitions\n");
    let _ = writeln!(
        s,
        "Every figure is judged by the exact reference (`exact-tracer`) on exactly the values \
         each back end saw (its precision's rounding of the suite's rays and triangles). \
         A **disagreement** is a hit where the reference misses or the reverse (for aimed rays: \
         any outcome other than the reference's single triangle). A **crack** is a ray aimed \
         at a point of a shared edge or at a shared vertex that hits none of the triangles \
         there; a **double hit** is one that more than one of them reports hit (any-hit \
         semantics). The reference's tie rule makes exactly one triangle count for a ray \
         exactly through an edge (an **exact tie**); a kernel with closed edges reports both, \
         which is counted as a double hit. **Distance errors** are against the exact rational \
         `t`, relative and in ulps of the back end's precision. Full definitions: the docs of \
         `wedge_benches::accuracy`.\n"
    );
    s
}

fn conclusion(s: &mut String, rows: &[AccuracyRow], throughput: Option<&[ThroughputLine]>) {
    let _ = writeln!(s, "## Does the report's conclusion hold on this machine?\n");
    let _ = writeln!(
        s,
        "The report concludes that \"geometric algebra in 3-dimensions has no significant \
         benefits or disadvantages over linear algebra\" for a ray tracer. Two checks: do the \
         GA back ends draw the same images as the linear-algebra one, and at what cost?\n"
    );
    let camera: Vec<&AccuracyRow> = rows.iter().filter(|r| r.ray_set == "camera").collect();
    let mut images_equal = true;
    if camera.is_empty() {
        images_equal = false;
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
            if r.backend.starts_with("ga") && differ.is_some_and(|d| d > 0.0) {
                images_equal = false;
            }
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
         rays through the bunny, one thread) and the ratio to `la` in the same precision:\n"
    );
    let _ = writeln!(s, "| back end | f32 ns/ray | ratio to la | f64 ns/ray | ratio to la |");
    let _ = writeln!(s, "|---|---|---|---|---|");
    let mut ga_ratios = Vec::new();
    let mut backends: Vec<&str> = Vec::new();
    for r in rows {
        if !backends.contains(&r.backend.as_str()) {
            backends.push(&r.backend);
        }
    }
    for b in &backends {
        let mut cells = Vec::new();
        for p in ["f32", "f64"] {
            let ns = find(rows, b, p, "random").and_then(|r| r.ns_per_ray);
            let la = find(rows, "la", p, "random").and_then(|r| r.ns_per_ray);
            let ratio = ns.zip(la).map(|(a, l)| a / l);
            if b.starts_with("ga")
                && let Some(x) = ratio
            {
                ga_ratios.push((b.to_string(), p, x));
            }
            cells.push(format!("{} | {}", fmt(ns), fmt(ratio)));
        }
        let _ = writeln!(s, "| {b} | {} |", cells.join(" | "));
    }
    let _ = writeln!(s);
    let mut tp_ratios: Vec<(String, f64)> = Vec::new();
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
            for b in backends.iter().filter(|b| b.starts_with("ga") || **b == "la-mt") {
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
                    if b.starts_with("ga")
                        && let Some(m) = m
                    {
                        tp_ratios.push((format!("{b} {p}"), m));
                    }
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
    // The verdict, from the figures above.
    let cheapest = ga_ratios.iter().min_by(|a, b| a.2.total_cmp(&b.2));
    let in_band = |x: f64| x >= SAME_COST_BAND.0 && x <= SAME_COST_BAND.1;
    let same_cost = cheapest.is_some_and(|(_, _, x)| in_band(*x));
    let _ = write!(s, "**Verdict.** ");
    if images_equal {
        let _ = write!(
            s,
            "The GA back ends draw exactly the same images as `la` (same nearest triangle in every pixel). "
        );
    } else if !camera.is_empty() {
        let _ = write!(
            s,
            "The GA back ends do **not** draw exactly the same images as `la`: see the pixel counts above (differences are pixels whose ray passes within rounding of an edge, where the nearest triangle is decided by the last bits). "
        );
    }
    match cheapest {
        Some((b, p, x)) => {
            let _ = write!(
                s,
                "The cheapest GA back end, `{b}` in {p}, takes {x:.2} times `la`'s time per ray{}",
                if same_cost {
                    format!(
                        ", within the band {:.2} to {:.2} counted here as no significant difference",
                        SAME_COST_BAND.0, SAME_COST_BAND.1
                    )
                } else {
                    format!(
                        ", outside the band {:.2} to {:.2} counted here as no significant difference",
                        SAME_COST_BAND.0, SAME_COST_BAND.1
                    )
                }
            );
            if let Some((name, m)) = tp_ratios.iter().min_by(|a, b| a.1.total_cmp(&b.1)) {
                let _ = write!(s, " (throughput bench: best GA median ratio {m:.2}, `{name}`)");
            }
            let _ = write!(s, ". ");
        }
        None => {
            let _ = write!(
                s,
                "No timings in `accuracy.csv` (a run without criterion timings): cost unknown. "
            );
        }
    }
    let holds = images_equal && same_cost;
    let _ = writeln!(
        s,
        "So on this machine the report's conclusion **{}**.\n",
        if holds {
            "holds: equal images at no significant cost difference"
        } else if images_equal {
            "holds for the images but not for the cost"
        } else if same_cost {
            "holds for the cost, and for the images up to the pixels counted above"
        } else {
            "does not hold as stated; see the figures above"
        }
    );
}
