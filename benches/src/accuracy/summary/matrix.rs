//! The like-for-like verdict of `SUMMARY.md`: each cell of the method x algebra matrix against
//! its row's LA cell (the same method, data and decisions in glam), in time (from
//! `interleaved.csv`: one process per measurement, rounds in rotation, medians) and in error
//! (from `accuracy.csv`), held to the targets of issue 16, then the report's two questions
//! answered with those figures beside Fontijne and Dorst's.

use std::fmt::Write as _;
use std::path::Path;

use backends::{Algebra, Backend, Method};

use super::{AccuracyRow, Measured, fmt, median};
use crate::distinct;

/// Time over the row's LA cell that each algebra's cells are held to, in every column.
#[must_use]
pub const fn target(algebra: Algebra) -> f64 {
    match algebra {
        Algebra::La => 1.0,
        Algebra::G3 => 1.02,
        Algebra::Pga => 1.05,
        Algebra::Cga => 1.10,
    }
}

/// Fontijne and Dorst (2003), their ray tracer's time relative to 3D linear algebra: the
/// algebra and the figure as they state it.
const FONTIJNE_DORST: [(Algebra, &str); 3] =
    [(Algebra::G3, "2.56-3.94x"), (Algebra::Pga, "2.97x"), (Algebra::Cga, "5.71x")];

/// One row of `interleaved.csv`, the columns the verdict reads.
#[derive(Clone, Debug, PartialEq, serde::Deserialize)]
pub struct InterleavedLine {
    /// Back end (or an Embree row, which the verdict skips).
    pub backend: String,
    /// `f32` or `f64`.
    pub precision: String,
    /// Mesh and view.
    pub scene: String,
    /// Ray set.
    pub ray_set: String,
    /// Median over the rounds.
    pub median_mrays_per_s: f64,
}

/// One row of `kernels.csv`, the columns the verdict reads.
#[derive(Clone, Debug, PartialEq, serde::Deserialize)]
pub struct KernelLine {
    /// Back end.
    pub backend: String,
    /// `f32` or `f64`.
    pub precision: String,
    /// `hit`, `miss` or `mixed`.
    pub case: String,
    /// Nanoseconds per ray-triangle test on cached data.
    pub ns_per_test: f64,
    /// Bytes of the back end's prepared triangle.
    pub prim_bytes: u64,
}

/// One row of `instructions.csv`, the columns the verdict reads.
#[derive(Clone, Debug, PartialEq, serde::Deserialize)]
pub struct InstructionLine {
    /// Back end.
    pub backend: String,
    /// `f32` or `f64`.
    pub precision: String,
    /// Ray set.
    pub ray_set: String,
    /// Instructions per ray counted by callgrind (traversal and tests).
    pub instructions_per_ray: f64,
}

/// The lines of code of every back end's kernel: the file under `crates/kernels-*/src/` that
/// declares its `NAME` (one kernel per file), counting neither blank lines, comments nor the
/// tests after `#[cfg(test)]`. Decision code shared along a row counts once, in the file
/// that holds it (`kernels-g3`'s `frame.rs` and `watertight.rs`).
#[must_use]
pub fn kernel_lines(workspace: &Path) -> Vec<(String, usize)> {
    let mut files = Vec::new();
    let crates = std::fs::read_dir(workspace.join("crates")).into_iter().flatten().flatten();
    for krate in crates.filter(|c| c.file_name().to_string_lossy().starts_with("kernels-")) {
        let sources = std::fs::read_dir(krate.path().join("src")).into_iter().flatten().flatten();
        files.extend(sources.filter_map(|f| std::fs::read_to_string(f.path()).ok()));
    }
    let mut out = Vec::new();
    for b in Backend::ALL {
        let declared = format!("const NAME: &'static str = \"{}\";", b.name());
        if let Some(text) = files.iter().find(|t| t.contains(&declared)) {
            let code = text
                .lines()
                .map(str::trim)
                .take_while(|l| *l != "#[cfg(test)]")
                .filter(|l| !l.is_empty() && !l.starts_with("//"))
                .count();
            out.push((b.name().to_owned(), code));
        }
    }
    out
}

/// Reads a CSV if it exists; `Ok(None)` when it is absent.
///
/// # Errors
///
/// A message naming the file when it exists but does not parse.
pub fn read_optional<R: serde::de::DeserializeOwned>(
    path: &Path,
) -> Result<Option<Vec<R>>, String> {
    if path.exists() { super::read_rows(path).map(Some) } else { Ok(None) }
}

/// The time columns of the verdict: every (scene, ray set) of `interleaved.csv`, in order.
fn columns(lines: &[InterleavedLine]) -> Vec<(String, String)> {
    distinct(lines.iter().map(|l| (l.scene.clone(), l.ray_set.clone())))
}

/// `backend`'s time over `base`'s in one precision and column (median Mrays/s inverted).
fn time_ratio(
    lines: &[InterleavedLine],
    backend: Backend,
    base: Backend,
    precision: &str,
    (scene, set): &(String, String),
) -> Option<f64> {
    let rate = |b: Backend| {
        lines
            .iter()
            .find(|l| {
                l.backend == b.name()
                    && l.precision == precision
                    && l.scene == *scene
                    && l.ray_set == *set
            })
            .map(|l| l.median_mrays_per_s)
    };
    rate(base).zip(rate(backend)).map(|(b, x)| b / x).filter(|r| r.is_finite())
}

/// The geometric mean of positive values.
fn geomean(v: &[f64]) -> Option<f64> {
    (!v.is_empty()).then(|| (v.iter().map(|x| x.ln()).sum::<f64>() / v.len() as f64).exp())
}

fn accuracy<'a>(
    rows: &'a [AccuracyRow],
    b: Backend,
    p: &str,
    set: &str,
) -> Option<&'a AccuracyRow> {
    rows.iter().find(|r| r.backend == b.name() && r.precision == p && r.ray_set == set)
}

/// Cracks and double hits (off exact ties) over every aimed set of `b` in `p`, as
/// `"cracks / double hits"`, or `-` without aimed rows.
fn cracks(rows: &[AccuracyRow], b: Backend, p: &str) -> String {
    let aimed: Vec<&AccuracyRow> = rows
        .iter()
        .filter(|r| r.backend == b.name() && r.precision == p && r.cracks.is_some())
        .collect();
    if aimed.is_empty() {
        return "-".to_owned();
    }
    let c: u64 = aimed.iter().filter_map(|r| r.cracks).sum();
    let d: u64 = aimed.iter().filter_map(|r| r.double_hits_off_tie).sum();
    format!("{c} / {d}")
}

/// The back ends of `algebra` for `method`: the cell first, then its variants.
fn members(method: Method, algebra: Algebra) -> Vec<Backend> {
    let mut out: Vec<Backend> = Backend::cell(method, algebra).into_iter().collect();
    out.extend(
        Backend::ALL
            .into_iter()
            .filter(|b| b.variant().is_some() && (b.method(), b.algebra()) == (method, algebra)),
    );
    out
}

/// Writes the verdict's sections.
pub(super) fn verdict(out: &mut String, accuracy_rows: &[AccuracyRow], measured: &Measured) {
    let Measured { interleaved, kernels, instructions, kernel_lines, .. } = *measured;
    // The tables go into `tables`, written after the verdict drawn from them.
    let mut tables = String::new();
    let s = &mut tables;
    let _ = writeln!(s, "## Like for like: every method in every algebra\n");
    let _ = writeln!(
        s,
        "Each cell of the matrix is one ray-triangle method written in one algebra's own types; \
         along a row the method, the per-triangle data, the decision order and the tie rule are \
         the same (the rules are in the `backends` crate's documentation), so a row's ratios \
         measure the algebra. Time is from `results/interleaved.csv`: one thread, each back end \
         in its own process per round, rounds in rotation, the median over the rounds; a ratio \
         is the cell's time over its row's LA cell's time on the same rays. Targets: G3 within \
         {:.2}x, PGA within {:.2}x, CGA within {:.2}x, in every column. Labelled variants \
         (hand SIMD over arrays) are shown beside their cells and do not stand for them.\n",
        target(Algebra::G3),
        target(Algebra::Pga),
        target(Algebra::Cga)
    );
    let Some(lines) = interleaved else {
        let _ = writeln!(
            s,
            "`results/interleaved.csv` is **absent** (`cargo bench -p wedge-benches --bench \
             interleaved`): no like-for-like times.\n"
        );
        out.push_str(&tables);
        return;
    };
    let cols = columns(lines);
    let head: Vec<String> = cols.iter().map(|(sc, set)| format!("{sc} {set}")).collect();
    let _ = writeln!(
        s,
        "| method | back end | algebra | precision | {} | worst | target | |",
        head.join(" | ")
    );
    let _ = writeln!(s, "|---|---|---|---|{}---|---|---|", "---|".repeat(cols.len()));
    // Per algebra: every cell ratio (for the geometric mean) and the rows meeting the target.
    let mut per_algebra: Vec<(Algebra, Vec<f64>, usize, usize)> = Vec::new();
    let mut misses: Vec<(Backend, Backend, String, f64)> = Vec::new();
    for algebra in [Algebra::G3, Algebra::Pga, Algebra::Cga] {
        let mut all = Vec::new();
        let (mut met, mut rows) = (0, 0);
        for method in Method::ALL {
            let Some(base) = Backend::cell(method, Algebra::La) else { continue };
            for b in members(method, algebra) {
                for p in ["f32", "f64"] {
                    let ratios: Vec<Option<f64>> =
                        cols.iter().map(|c| time_ratio(lines, b, base, p, c)).collect();
                    let worst = ratios.iter().flatten().copied().fold(f64::NAN, f64::max);
                    let cell = b.variant().is_none();
                    let ok = worst <= target(algebra);
                    if cell && worst.is_finite() {
                        all.extend(ratios.iter().flatten().copied());
                        rows += 1;
                        met += usize::from(ok);
                        if !ok {
                            misses.push((b, base, p.to_owned(), worst));
                        }
                    }
                    let cells: Vec<String> = ratios.iter().map(|r| fmt(*r)).collect();
                    let _ = writeln!(
                        s,
                        "| {} | `{}`{} | {} | {p} | {} | {} | {:.2} | {} |",
                        method.name(),
                        b.name(),
                        if cell { "" } else { " (variant)" },
                        algebra.name(),
                        cells.join(" | "),
                        fmt(worst.is_finite().then_some(worst)),
                        target(algebra),
                        if !worst.is_finite() {
                            "no figure"
                        } else if ok {
                            "met"
                        } else {
                            "**missed**"
                        }
                    );
                }
            }
        }
        per_algebra.push((algebra, all, met, rows));
    }
    let _ = writeln!(s);

    // Error against the same method's LA cell.
    let _ = writeln!(
        s,
        "**Error, cell against its row's LA cell** (`accuracy.csv`): pixels of the bunny image \
         whose nearest triangle differs from `la`'s, hit/miss disagreements with the exact \
         reference per million random rays, the 99.9th percentile of the distance error in \
         ulps, and cracks / double hits (off exact ties) over every aimed set.\n"
    );
    let _ = writeln!(
        s,
        "| method | back end | precision | differing pixels | disagreements per M (LA cell) | t error p99.9, ulps (LA cell) | cracks / double hits (LA cell) |"
    );
    let _ = writeln!(s, "|---|---|---|---|---|---|---|");
    let mut differing_pixels = 0.0;
    for method in Method::ALL {
        let Some(base) = Backend::cell(method, Algebra::La) else { continue };
        for algebra in [Algebra::G3, Algebra::Pga, Algebra::Cga] {
            for b in members(method, algebra) {
                for p in ["f32", "f64"] {
                    let camera = accuracy(accuracy_rows, b, p, "camera");
                    let pixels = camera.and_then(|r| {
                        r.differs_from_la_per_million.map(|pm| (pm * r.rays as f64 / 1e6).round())
                    });
                    if b.variant().is_none() {
                        differing_pixels += pixels.unwrap_or(0.0);
                    }
                    let random = |k: Backend| accuracy(accuracy_rows, k, p, "random");
                    let dis = |k: Backend| random(k).map(|r| r.disagree_per_million);
                    let ulp = |k: Backend| random(k).and_then(|r| r.t_ulp_err_p999);
                    let _ = writeln!(
                        s,
                        "| {} | `{}` | {p} | {} | {} ({}) | {} ({}) | {} ({}) |",
                        method.name(),
                        b.name(),
                        fmt(pixels),
                        fmt(dis(b)),
                        fmt(dis(base)),
                        fmt(ulp(b)),
                        fmt(ulp(base)),
                        cracks(accuracy_rows, b, p),
                        cracks(accuracy_rows, base, p)
                    );
                }
            }
        }
    }
    let _ = writeln!(s);

    // Why the misses: the kernel's own cost per test and its data, against the LA cell's.
    if !misses.is_empty() {
        let _ = writeln!(
            s,
            "**Why cells miss.** For each cell over its target: its worst ratio, the time of one \
             ray-triangle test on cached data (`kernels.csv`, the mixed case: no traversal, so \
             this is the algebra's arithmetic alone) and the bytes of its prepared triangle, \
             against its row's LA cell, and the instructions per ray that callgrind counts \
             (`instructions.csv`, traversal and tests, each ray set) over the LA cell's. A \
             test-time ratio near the traversal ratio says the \
             algebra's extra terms are the cost; more bytes say the cell also pays in memory. \
             What each algebra computes that LA does not is written in each kernel's \
             documentation (PGA: the homogeneous weight of every join and meet; CGA: the `e4`, \
             `e5` coefficients of its flats and the outer products with `e∞`).\n"
        );
        let _ = writeln!(
            s,
            "| back end | precision | worst time ratio | ns per test (LA cell) | test ratio | bytes per triangle (LA cell) | instructions per ray over LA cell |"
        );
        let _ = writeln!(s, "|---|---|---|---|---|---|---|");
        for (b, base, p, worst) in &misses {
            let k = |x: Backend| {
                kernels.and_then(|ks| {
                    ks.iter()
                        .find(|l| l.backend == x.name() && l.precision == *p && l.case == "mixed")
                })
            };
            let ns = |x: Backend| k(x).map(|l| l.ns_per_test);
            let bytes = |x: Backend| k(x).map_or("-".to_owned(), |l| l.prim_bytes.to_string());
            let test_ratio = ns(*b).zip(ns(*base)).map(|(a, l)| a / l);
            let ir = |x: Backend, set: &str| {
                instructions.and_then(|is| {
                    is.iter()
                        .find(|l| l.backend == x.name() && l.precision == *p && l.ray_set == set)
                        .map(|l| l.instructions_per_ray)
                })
            };
            let sets: Vec<String> = ["primary_closest", "primary_any", "incoherent_closest"]
                .iter()
                .map(|set| fmt(ir(*b, set).zip(ir(*base, set)).map(|(a, l)| a / l)))
                .collect();
            let _ = writeln!(
                s,
                "| `{}` | {p} | {} | {} ({}) | {} | {} ({}) | {} |",
                b.name(),
                fmt(Some(*worst)),
                fmt(ns(*b)),
                fmt(ns(*base)),
                fmt(test_ratio),
                bytes(*b),
                bytes(*base),
                sets.join(" / ")
            );
        }
        let _ = writeln!(s);
    }

    // The fastest method of each algebra: the geometric mean of its cell's time over `la`'s.
    let _ = writeln!(
        s,
        "**Fastest method per algebra.** The geometric mean, over both precisions and every \
         column, of each cell's time over `la`'s (the LA watertight cell, the default back \
         end):\n"
    );
    let _ = writeln!(s, "| algebra | {} | fastest |", Method::ALL.map(Method::name).join(" | "));
    let _ = writeln!(s, "|---|{}---|", "---|".repeat(Method::ALL.len()));
    let mut best_of: Vec<(Algebra, Method, f64)> = Vec::new();
    for algebra in [Algebra::La, Algebra::G3, Algebra::Pga, Algebra::Cga] {
        let means: Vec<Option<f64>> = Method::ALL
            .iter()
            .map(|&m| {
                let b = Backend::cell(m, algebra)?;
                let r: Vec<f64> = ["f32", "f64"]
                    .iter()
                    .flat_map(|p| {
                        cols.iter().filter_map(|c| time_ratio(lines, b, Backend::BASELINE, p, c))
                    })
                    .collect();
                geomean(&r)
            })
            .collect();
        let best = Method::ALL
            .iter()
            .zip(&means)
            .filter_map(|(m, x)| x.map(|x| (*m, x)))
            .min_by(|a, b| a.1.total_cmp(&b.1));
        if let Some((m, x)) = best {
            best_of.push((algebra, m, x));
        }
        let cells: Vec<String> = means.iter().map(|x| fmt(*x)).collect();
        let _ = writeln!(
            s,
            "| {} | {} | {} |",
            algebra.name(),
            cells.join(" | "),
            best.map_or("-".to_owned(), |(m, x)| format!("{} ({})", m.name(), fmt(Some(x))))
        );
    }
    let _ = writeln!(s);

    if !kernel_lines.is_empty() {
        let _ = writeln!(
            s,
            "**Writing it.** Lines of code of each cell's kernel (its file, without comments, \
             blank lines and tests; decision code shared along a row counts once, in \
             `kernels-g3`), the report having found GA harder to write:\n"
        );
        let algebras = [Algebra::La, Algebra::G3, Algebra::Pga, Algebra::Cga];
        let _ = writeln!(s, "| method | {} |", algebras.map(Algebra::name).join(" | "));
        let _ = writeln!(s, "|---|{}", "---|".repeat(algebras.len()));
        for m in Method::ALL {
            let cells = algebras.map(|a| {
                Backend::cell(m, a)
                    .and_then(|b| kernel_lines.iter().find(|(n, _)| n == b.name()))
                    .map_or("-".to_owned(), |(_, n)| n.to_string())
            });
            let _ = writeln!(s, "| {} | {} |", m.name(), cells.join(" | "));
        }
        let _ = writeln!(s);
    }

    // The verdict, before the tables drawn from it.
    let s = out;
    let _ = writeln!(s, "## Verdict\n");
    let la_best = best_of.iter().find(|(a, ..)| *a == Algebra::La).map(|x| x.2);
    let _ = writeln!(
        s,
        "| algebra | cells' time over LA, same method: geometric mean (range) | rows within target | best cell over best LA cell | Fontijne and Dorst (2003) |"
    );
    let _ = writeln!(s, "|---|---|---|---|---|");
    // Per algebra with figures: (algebra, geometric mean, best cell over best LA cell, rows
    // within target, rows).
    let mut standing: Vec<(Algebra, f64, Option<f64>, usize, usize)> = Vec::new();
    for (algebra, all, met, rows) in &per_algebra {
        let g = geomean(all);
        let lo = all.iter().copied().reduce(f64::min);
        let hi = all.iter().copied().reduce(f64::max);
        let best = best_of.iter().find(|(a, ..)| a == algebra);
        let best_ratio = best.zip(la_best).map(|(b, l)| b.2 / l);
        let fd = FONTIJNE_DORST.iter().find(|(a, _)| a == algebra).map_or("-", |x| x.1);
        let _ = writeln!(
            s,
            "| {} | {} ({}-{}) | {met} of {rows} | {} ({}) | {fd} |",
            algebra.name(),
            fmt(g),
            fmt(lo),
            fmt(hi),
            fmt(best_ratio),
            best.map_or("-", |b| b.1.name())
        );
        if let Some(g) = g {
            standing.push((*algebra, g, best_ratio, *met, *rows));
        }
    }
    let _ = writeln!(s);
    let g3 = standing.iter().find(|x| x.0 == Algebra::G3);
    let images = if differing_pixels == 0.0 {
        "the same images (0 differing pixels in every cell, both precisions)".to_owned()
    } else {
        format!(
            "the same images but for {differing_pixels} pixels over all cells (rays within \
             rounding of an edge, counted above)"
        )
    };
    let _ = write!(
        s,
        "**3D GA (the report's question).** Written in G3 types, every method gives {images}"
    );
    if let Some((_, g, best, met, rows)) = g3 {
        let _ = write!(
            s,
            " at {}x LA's time for the same method (geometric mean over methods, precisions and \
             columns; the tables below have each row), and its fastest cell takes {}x the \
             fastest LA cell's time. Held to the target of issue 16 (within {:.2}x of LA in \
             every column), {met} of {rows} rows (method x precision) meet it. ",
            fmt(Some(*g)),
            fmt(*best),
            target(Algebra::G3)
        );
        let band = (0.95..=1.05).contains(g);
        let _ = write!(
            s,
            "{} Fontijne and Dorst measured 2.56-3.94x for 3D GA in 2003; with generated, \
             grade-typed products the gap they saw is {}.\n\n",
            if band {
                "So the report's conclusion holds when methods are matched: no significant \
                 benefit or disadvantage."
            } else if *g < 0.95 {
                "So 3D GA is faster than LA for the same method here, a benefit the report \
                 did not find."
            } else {
                "So 3D GA costs more than LA for the same method here, a disadvantage the \
                 report did not find."
            },
            if *g < 1.5 { "gone" } else { "smaller but still there" }
        );
    } else {
        let _ = writeln!(s, ".\n");
    }
    let higher: Vec<String> = standing
        .iter()
        .filter(|x| x.0 != Algebra::G3)
        .map(|(a, g, best, met, rows)| {
            format!(
                "{} takes {}x LA's time for the same method (its best cell {}x the best LA \
                 cell; {met} of {rows} rows within {:.2}x)",
                a.name(),
                fmt(Some(*g)),
                fmt(*best),
                target(*a)
            )
        })
        .collect();
    if !higher.is_empty() {
        let reduce = standing
            .iter()
            .filter(|x| x.0 != Algebra::G3)
            .any(|(_, g, best, ..)| *g < 1.0 || best.is_some_and(|b| b < 1.0));
        let _ = writeln!(
            s,
            "**4D and 5D GA (the report's future work).** {}. {} Fontijne and Dorst found 2.97x \
             (4D) and 5.71x (5D).\n",
            higher.join("; "),
            if reduce {
                "A higher algebra reduces computation for at least one method here."
            } else {
                "Neither reduces computation against LA: the extra coefficients (the \
                 homogeneous weight in PGA, `e4` and `e5` in CGA) are work LA does not do."
            }
        );
    }
    if let Some(median_ratio) = median(per_algebra.iter().flat_map(|x| x.1.clone()).collect()) {
        let _ = writeln!(
            s,
            "Median of every GA cell's time over its LA cell's: {}.\n",
            fmt(Some(median_ratio))
        );
    }
    s.push_str(&tables);
}

/// Draws `results/matrix.svg`: one panel per precision, one group of bars per method, one bar
/// per algebra (G3, PGA, CGA) and variant, each the geometric mean over the columns of
/// `interleaved.csv` of the back end's time over its row's LA cell's, with a line from the
/// lowest to the highest column; the line at 1 is LA, and a tick on each bar marks its target.
///
/// # Errors
///
/// If the file cannot be written.
pub fn draw_matrix_svg(
    path: &Path,
    lines: &[InterleavedLine],
) -> Result<(), Box<dyn std::error::Error>> {
    use plotters::prelude::*;
    let cols = columns(lines);
    let bars: Vec<(Algebra, Option<&'static str>)> =
        distinct([Algebra::G3, Algebra::Pga, Algebra::Cga].into_iter().flat_map(|a| {
            let variants = Backend::ALL
                .into_iter()
                .filter(move |b| b.algebra() == a)
                .filter_map(Backend::variant)
                .map(Some);
            std::iter::once(None).chain(variants).map(move |v| (a, v))
        }));
    // The back end of a bar in a method's group.
    let backend = |m: Method, (a, v): (Algebra, Option<&'static str>)| {
        Backend::ALL.into_iter().find(|b| b.method() == m && b.algebra() == a && b.variant() == v)
    };
    let stats = |b: Backend, p: &str| -> Option<(f64, f64, f64)> {
        let base = Backend::cell(b.method(), Algebra::La)?;
        let r: Vec<f64> = cols.iter().filter_map(|c| time_ratio(lines, b, base, p, c)).collect();
        let lo = r.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = r.iter().copied().fold(0.0, f64::max);
        geomean(&r).map(|g| (g, lo, hi))
    };
    let hi = Backend::ALL
        .iter()
        .flat_map(|&b| ["f32", "f64"].map(|p| stats(b, p).map_or(0.0, |s| s.2)))
        .fold(1.2, f64::max)
        * 1.05;
    let size = (1100, 760);
    let root = SVGBackend::new(path, size).into_drawing_area();
    root.fill(&WHITE)?;
    let (header, body) = root.split_vertically(60);
    header.draw(&Text::new(
        "Time over the row's LA cell (interleaved.csv; geometric mean over scenes and ray sets, \
         line: lowest to highest)",
        (10, 8),
        ("sans-serif", 15).into_font().color(&BLACK),
    ))?;
    for (k, (a, v)) in bars.iter().enumerate() {
        let x = 10 + 200 * k as i32;
        let label = v.map_or(a.name().to_owned(), |_| format!("{} variant", a.name()));
        let color = Palette99::pick(k).to_rgba();
        header.draw(&Rectangle::new([(x, 34), (x + 14, 48)], color.filled()))?;
        header.draw(&Text::new(label, (x + 18, 34), ("sans-serif", 13)))?;
    }
    let panels = body.split_evenly((2, 1));
    let group = 0.8;
    let width = group / bars.len() as f64;
    for (panel, p) in panels.iter().zip(["f32", "f64"]) {
        let mut chart = ChartBuilder::on(panel)
            .caption(p, ("sans-serif", 14))
            .margin(8)
            .x_label_area_size(24)
            .y_label_area_size(50)
            .build_cartesian_2d(-0.5..Method::ALL.len() as f64 - 0.5, 0.0..hi)?;
        chart
            .configure_mesh()
            .disable_x_mesh()
            .x_labels(0)
            .y_desc("time / LA cell")
            .label_style(("sans-serif", 11))
            .draw()?;
        let one = [(-0.5, 1.0), (Method::ALL.len() as f64 - 0.5, 1.0)];
        chart.draw_series(std::iter::once(PathElement::new(one, BLACK.stroke_width(1))))?;
        for (m, method) in Method::ALL.into_iter().enumerate() {
            chart.draw_series(std::iter::once(Text::new(
                method.name(),
                (m as f64 - 0.1, hi * 0.97),
                ("sans-serif", 12),
            )))?;
            for (k, &bar) in bars.iter().enumerate() {
                let Some((g, lo, top)) = backend(method, bar).and_then(|b| stats(b, p)) else {
                    continue;
                };
                let x0 = m as f64 - group / 2.0 + width * k as f64;
                let color = Palette99::pick(k).to_rgba();
                let rect = [(x0, 0.0), (x0 + width * 0.85, g)];
                chart.draw_series(std::iter::once(Rectangle::new(rect, color.filled())))?;
                let mid = x0 + width * 0.425;
                let range = [(mid, lo), (mid, top)];
                chart
                    .draw_series(std::iter::once(PathElement::new(range, BLACK.stroke_width(1))))?;
                let t = target(bar.0);
                let tick = [(x0, t), (x0 + width * 0.85, t)];
                chart.draw_series(std::iter::once(PathElement::new(tick, RED.stroke_width(2))))?;
            }
        }
    }
    root.present()?;
    Ok(())
}
