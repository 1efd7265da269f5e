//! The tables of `SUMMARY.md` after the conclusion: hard limits, ordinary rays, aimed rays,
//! sweeps and the other stress families.

use std::fmt::Write as _;

use super::{count, fmt};
use crate::accuracy::rows::{AccuracyRow, StabilityRow};
use crate::distinct;

/// One hard limit missed by one back end, summed over the rows it applies to.
struct Miss {
    subject: String,
    limit: &'static str,
    detail: String,
}

fn subjects_of(accuracy: &[AccuracyRow]) -> Vec<(String, String)> {
    distinct(accuracy.iter().map(|r| (r.backend.clone(), r.precision.clone())))
}

fn misses(accuracy: &[AccuracyRow], stability: &[StabilityRow]) -> Vec<Miss> {
    let mut out = Vec::new();
    for (b, p) in subjects_of(accuracy) {
        let subject = format!("{b} {p}");
        let acc: Vec<&AccuracyRow> =
            accuracy.iter().filter(|r| r.backend == b && r.precision == p).collect();
        let stab: Vec<&StabilityRow> =
            stability.iter().filter(|r| r.backend == b && r.precision == p).collect();
        // Aimed rows held to watertightness: (rays, cracks, double hits, rows, rows failing).
        let aimed: Vec<(u64, u64, u64)> = acc
            .iter()
            .filter(|r| r.limits.contains("cracks=0"))
            .map(|r| (r.rays, r.cracks.unwrap_or(0), r.double_hits.unwrap_or(0)))
            .chain(
                stab.iter()
                    .filter(|r| r.limits.contains("cracks=0"))
                    .map(|r| (r.rays, r.cracks.unwrap_or(0), r.double_hits.unwrap_or(0))),
            )
            .collect();
        let rays: u64 = aimed.iter().map(|a| a.0).sum();
        for (limit, pick) in [("cracks=0", 1), ("double_hits=0", 2)] {
            let value = |a: &(u64, u64, u64)| if pick == 1 { a.1 } else { a.2 };
            let total: u64 = aimed.iter().map(value).sum();
            if total > 0 {
                let cases = aimed.iter().filter(|a| value(a) > 0).count();
                out.push(Miss {
                    subject: subject.clone(),
                    limit,
                    detail: format!(
                        "{total} of {rays} aimed rays ({} per million), in {cases} of {} cases",
                        fmt(Some(crate::accuracy::metrics::per_million(total, rays))),
                        aimed.len()
                    ),
                });
            }
        }
        if let Some(r) = acc.iter().find(|r| r.ray_set == "random") {
            let max = if p == "f32" { 10.0 } else { 1.0 };
            if r.disagree_per_million > max {
                out.push(Miss {
                    subject: subject.clone(),
                    limit: "random rays: disagreements per million",
                    detail: format!(
                        "{} per million (limit {max})",
                        fmt(Some(r.disagree_per_million))
                    ),
                });
            }
            if p == "f32" && !r.t_ulp_err_median.is_some_and(|m| m <= 1.0) {
                out.push(Miss {
                    subject: subject.clone(),
                    limit: "random rays: median distance error <= 1 ulp",
                    detail: format!("{} ulps", fmt(r.t_ulp_err_median)),
                });
            }
        }
        let sum_cases = |f: &dyn Fn(&StabilityRow) -> u64, g: &dyn Fn(&AccuracyRow) -> u64| {
            let cases: Vec<String> = stab
                .iter()
                .filter(|r| f(r) > 0)
                .map(|r| format!("{} {} {}", r.family, r.scene, r.variant))
                .chain(
                    acc.iter().filter(|r| g(r) > 0).map(|r| format!("{} {}", r.scene, r.ray_set)),
                )
                .collect();
            let total =
                stab.iter().map(|r| f(r)).sum::<u64>() + acc.iter().map(|r| g(r)).sum::<u64>();
            (total, cases)
        };
        let checks: [(&'static str, (u64, Vec<String>)); 4] = [
            ("nan=0", sum_cases(&|r| r.nan, &|r| r.nan)),
            (
                "contract_violations=0",
                sum_cases(&|r| r.contract_violations.unwrap_or(0), &|r| r.contract_violations),
            ),
            ("panics=0", sum_cases(&|r| r.panics.unwrap_or(0), &|_| 0)),
            ("degenerate_hits=0", sum_cases(&|r| r.degenerate_hits.unwrap_or(0), &|_| 0)),
        ];
        for (limit, (total, cases)) in checks {
            if total > 0 {
                out.push(Miss {
                    subject: subject.clone(),
                    limit,
                    detail: format!("{total}, in: {}", cases.join(", ")),
                });
            }
        }
    }
    out
}

pub(super) fn limits(s: &mut String, accuracy: &[AccuracyRow], stability: &[StabilityRow]) {
    let _ = writeln!(s, "## Hard limits\n");
    let _ = writeln!(
        s,
        "Watertight back ends ({}): no crack and no double hit on rays aimed at shared edges \
         and vertices, in both precisions and at every step of the sweeps. Random rays: at \
         most 10 hit/miss disagreements per million in `f32`, 1 in `f64`; median distance \
         error at most 1 ulp in `f32`. Everywhere: no NaN, no hit outside `0 < t <= t_max`; \
         degenerate input never panics and is never hit.\n",
        super::watertight_names()
    );
    let judged = accuracy.iter().filter(|r| r.meets_limits.is_some()).count()
        + stability.iter().filter(|r| r.meets_limits.is_some()).count();
    let failing = accuracy.iter().filter(|r| r.meets_limits == Some(false)).count()
        + stability.iter().filter(|r| r.meets_limits == Some(false)).count();
    let _ = writeln!(s, "{} of {judged} rows with limits meet them.\n", judged - failing);
    let misses = misses(accuracy, stability);
    if misses.is_empty() {
        return;
    }
    let _ = writeln!(s, "Limits missed, per back end (summed over every row they apply to):\n");
    let _ = writeln!(s, "| back end | limit | measured |");
    let _ = writeln!(s, "|---|---|---|");
    for m in &misses {
        let _ = writeln!(s, "| {} | {} | {} |", m.subject, m.limit, m.detail);
    }
    let _ = writeln!(s);
}

fn signed(x: f64) -> String {
    if x == 0.0 { "0".to_owned() } else { format!("{x:+.1e}") }
}

pub(super) fn accuracy_table(s: &mut String, rows: &[AccuracyRow]) {
    let _ = writeln!(s, "## Ordinary rays (random rays through the bunny)\n");
    let _ = writeln!(
        s,
        "| back end | precision | rays | ns/ray | disagree/M | wrong triangle/M | t median (ulps) | t p99.9 (ulps) | t max (ulps) | t p99.9 (rel.) | NaN |"
    );
    let _ = writeln!(s, "|---|---|---|---|---|---|---|---|---|---|---|");
    for r in rows.iter().filter(|r| r.ray_set == "random") {
        let _ = writeln!(
            s,
            "| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |",
            r.backend,
            r.precision,
            r.rays,
            fmt(r.ns_per_ray),
            fmt(Some(r.disagree_per_million)),
            fmt(r.wrong_triangle_per_million),
            fmt(r.t_ulp_err_median),
            fmt(r.t_ulp_err_p999),
            fmt(r.t_ulp_err_max),
            fmt(r.t_rel_err_p999),
            r.nan_or_inf
        );
    }
    let _ = writeln!(s);
}

pub(super) fn aimed_table(s: &mut String, rows: &[AccuracyRow]) {
    let _ = writeln!(s, "## Rays aimed at shared edges and vertices\n");
    let _ = writeln!(
        s,
        "Per million rays. `exact` sets: rays exactly through the edge or vertex in both \
         precisions; `f64` sets: exactly in `f64`, rounded for `f32`.\n"
    );
    let _ = writeln!(
        s,
        "| back end | precision | scene | set | rays | exact ties | cracks/M | double hits/M | off-tie double hits/M | wrong side/M |"
    );
    let _ = writeln!(s, "|---|---|---|---|---|---|---|---|---|---|");
    for r in rows.iter().filter(|r| r.cracks.is_some()) {
        let pm = |x: Option<u64>| fmt(x.map(|x| crate::accuracy::metrics::per_million(x, r.rays)));
        let _ = writeln!(
            s,
            "| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |",
            r.backend,
            r.precision,
            r.scene,
            r.ray_set,
            r.rays,
            count(r.ties),
            pm(r.cracks),
            pm(r.double_hits),
            pm(r.double_hits_off_tie),
            pm(r.wrong_side)
        );
    }
    let _ = writeln!(s);
}

pub(super) fn sweeps(s: &mut String, rows: &[StabilityRow]) {
    let _ = writeln!(s, "## Translation and scale sweeps\n");
    let _ = writeln!(
        s,
        "Each cell: cracks / double hits on the aimed rays (edges and vertices together), then \
         the change of the hit fraction of the random rays against the unmoved, unscaled mesh, \
         and in brackets the reference's change in the same precision (the part due to the \
         moved mesh's rounding to `f32`).\n"
    );
    let variants = distinct(
        rows.iter()
            .filter(|r| r.family == "translate" || r.family == "scale")
            .map(|r| (r.family.as_str(), r.scene.as_str(), r.variant.as_str())),
    );
    let subjects = distinct(rows.iter().map(|r| (r.backend.as_str(), r.precision.as_str())));
    let header: Vec<String> = subjects.iter().map(|(b, p)| format!("{b} {p}")).collect();
    let _ = writeln!(s, "| sweep | scene | step | {} |", header.join(" | "));
    let _ = writeln!(s, "|---|---|---|{}", "---|".repeat(subjects.len()));
    for (family, scene, variant) in variants {
        let mut cells = Vec::new();
        for (b, p) in &subjects {
            let of = |r: &&StabilityRow| {
                r.family == family
                    && r.scene == scene
                    && r.variant == variant
                    && r.backend == *b
                    && r.precision == *p
            };
            let aimed: Vec<&StabilityRow> =
                rows.iter().filter(of).filter(|r| r.cracks.is_some()).collect();
            let cracks: u64 = aimed.iter().filter_map(|r| r.cracks).sum();
            let doubles: u64 = aimed.iter().filter_map(|r| r.double_hits).sum();
            let random = rows.iter().filter(of).find(|r| r.ray_set == "random");
            let change =
                random.and_then(|r| r.hit_fraction_change.zip(r.hit_fraction_exact_change));
            let change = change
                .map_or_else(String::new, |(c, e)| format!(", {} (ref. {})", signed(c), signed(e)));
            cells.push(format!("{cracks}/{doubles}{change}"));
        }
        let _ = writeln!(s, "| {family} | {scene} | {variant} | {} |", cells.join(" | "));
    }
    let _ = writeln!(s);
}

pub(super) fn families(s: &mut String, rows: &[StabilityRow]) {
    let _ = writeln!(s, "## Grazing, axis-aligned, on-surface and degenerate input\n");
    let _ = writeln!(
        s,
        "Summed over the cases of each family: disagreements with the reference, hits where \
         the reference has none (grazing: hits from a ray in the triangle's plane, which the \
         reference never reports; on-surface: self-hits at `t` near 0), NaN (and infinite) \
         results, panics, hits on degenerate triangles. The reference's infinite results are \
         distances beyond `f64::MAX` (a subnormal direction), as its docs state.\n"
    );
    let _ = writeln!(
        s,
        "| family | back end | precision | tests | disagreements | false hits | NaN (infinite) | panics | degenerate hits | contract violations |"
    );
    let _ = writeln!(s, "|---|---|---|---|---|---|---|---|---|---|");
    for family in ["grazing", "axis-aligned", "on-surface", "degenerate"] {
        let subjects = distinct(
            rows.iter()
                .filter(|r| r.family == family)
                .map(|r| (r.backend.as_str(), r.precision.as_str())),
        );
        for (b, p) in subjects {
            let of: Vec<&StabilityRow> = rows
                .iter()
                .filter(|r| r.family == family && r.backend == b && r.precision == p)
                .collect();
            let sum = |f: &dyn Fn(&StabilityRow) -> u64| of.iter().map(|r| f(r)).sum::<u64>();
            let tests = sum(&|r| r.rays);
            let false_hits = sum(&|r| r.false_hits);
            let _ = writeln!(
                s,
                "| {family} | {b} | {p} | {tests} | {} | {} | {} ({}) | {} | {} | {} |",
                sum(&|r| r.disagreements),
                if family == "axis-aligned" { "-".to_owned() } else { false_hits.to_string() },
                sum(&|r| r.nan),
                sum(&|r| r.nan_or_inf - r.nan),
                sum(&|r| r.panics.unwrap_or(0)),
                sum(&|r| r.degenerate_hits.unwrap_or(0)),
                sum(&|r| r.contract_violations.unwrap_or(0)),
            );
        }
    }
    let _ = writeln!(s);
}
