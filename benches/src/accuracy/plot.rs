//! `results/runtime_vs_error.svg`: every back end and precision as a point, nanoseconds per
//! ray against error, with the Pareto front marked.

use std::path::Path;

use plotters::prelude::*;

use super::rows::AccuracyRow;
use crate::distinct;

/// One point of the plot.
#[derive(Clone, Debug, PartialEq)]
pub struct Point {
    /// `backend precision`.
    pub label: String,
    /// Back end (picks the colour).
    pub backend: String,
    /// Nanoseconds per ray.
    pub x: f64,
    /// Error (0 allowed: drawn on the floor of the axis).
    pub y: f64,
}

/// The points of one panel: for each back end and precision with a timing on the random
/// rays, its `x` and the error `error(rows of that back end and precision)`.
#[must_use]
pub fn points(rows: &[AccuracyRow], error: impl Fn(&[&AccuracyRow]) -> Option<f64>) -> Vec<Point> {
    let mut out = Vec::new();
    for timed in rows.iter().filter(|r| r.ray_set == "random") {
        let Some(x) = timed.ns_per_ray.filter(|x| *x > 0.0) else { continue };
        let own: Vec<&AccuracyRow> = rows
            .iter()
            .filter(|r| r.backend == timed.backend && r.precision == timed.precision)
            .collect();
        if let Some(y) = error(&own) {
            out.push(Point {
                label: format!("{} {}", timed.backend, timed.precision),
                backend: timed.backend.clone(),
                x,
                y,
            });
        }
    }
    out
}

/// The Pareto front (no other point is both faster and more accurate), by increasing `x`.
#[must_use]
pub fn pareto_front(points: &[Point]) -> Vec<Point> {
    let mut sorted: Vec<&Point> = points.iter().collect();
    sorted.sort_by(|a, b| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)));
    let mut front: Vec<Point> = Vec::new();
    for p in sorted {
        if front.last().is_none_or(|best| p.y < best.y) {
            front.push(p.clone());
        }
    }
    front
}

/// The relative distance error at the 99.9th percentile on the random rays.
#[must_use]
pub fn distance_error(rows: &[&AccuracyRow]) -> Option<f64> {
    rows.iter().find(|r| r.ray_set == "random").and_then(|r| r.t_rel_err_p999)
}

/// Cracks, double hits and wrong sides per million aimed rays, over every aimed set.
#[must_use]
pub fn aimed_failures(rows: &[&AccuracyRow]) -> Option<f64> {
    let aimed: Vec<&&AccuracyRow> = rows.iter().filter(|r| r.cracks.is_some()).collect();
    let rays: u64 = aimed.iter().map(|r| r.rays).sum();
    let bad: u64 = aimed.iter().map(|r| r.disagreements).sum();
    (rays > 0).then(|| super::metrics::per_million(bad, rays))
}

/// Draws two panels: distance error (p99.9, relative) and aimed-ray failures per million,
/// each against nanoseconds per ray on log scales, the Pareto front as a dashed step line.
///
/// # Errors
///
/// If the file cannot be written.
pub fn draw_runtime_vs_error(
    path: &Path,
    rows: &[AccuracyRow],
    title: &str,
) -> Result<(), Box<dyn std::error::Error>> {
    let panels = [
        ("relative distance error, p99.9 (random rays)", points(rows, distance_error)),
        (
            "cracks + double hits + wrong side per million (edge and vertex rays)",
            points(rows, aimed_failures),
        ),
    ];
    let backends: Vec<String> = distinct(rows.iter().map(|r| r.backend.clone()));
    let root = SVGBackend::new(path, (1200, 560)).into_drawing_area();
    root.fill(&WHITE)?;
    let (header, body) = root.split_vertically(40);
    header.draw(&Text::new(title.to_owned(), (10, 10), ("sans-serif", 16).into_font()))?;
    let areas = body.split_evenly((1, 2));
    for ((caption, pts), area) in panels.iter().zip(&areas) {
        if pts.is_empty() {
            continue;
        }
        let (x_lo, x_hi) = range(pts.iter().map(|p| p.x));
        let positive = pts.iter().map(|p| p.y).filter(|y| *y > 0.0);
        let (y_lo, y_hi) = range(positive);
        let (y_lo, y_hi) = if y_lo.is_finite() { (y_lo, y_hi) } else { (1e-3, 1.0) };
        // Zero errors sit on the floor, a decade below the smallest non-zero one.
        let floor = y_lo / 10.0;
        let y_of = |y: f64| if y > 0.0 { y } else { floor };
        let mut chart = ChartBuilder::on(area)
            .caption(*caption, ("sans-serif", 13))
            .margin(12)
            .x_label_area_size(36)
            .y_label_area_size(64)
            .build_cartesian_2d(
                (x_lo / 1.5..x_hi * 1.5).log_scale(),
                (floor / 3.0..y_hi * 5.0).log_scale(),
            )?;
        chart
            .configure_mesh()
            .x_labels(6)
            .y_labels(8)
            .x_label_formatter(&|x| format!("{x:.0}"))
            .y_label_formatter(&|y| format!("{y:.0e}"))
            .x_desc("ns per ray (closest hit, BVH, one thread, CPU time)")
            .y_desc("error (floor line: 0)")
            .label_style(("sans-serif", 11))
            .draw()?;
        chart.draw_series(std::iter::once(PathElement::new(
            vec![(x_lo / 1.5, floor), (x_hi * 1.5, floor)],
            BLACK.mix(0.3),
        )))?;
        let front = pareto_front(pts);
        let mut steps = Vec::new();
        for (i, p) in front.iter().enumerate() {
            if i > 0 {
                steps.push((p.x, y_of(front[i - 1].y)));
            }
            steps.push((p.x, y_of(p.y)));
        }
        if let Some(last) = front.last() {
            steps.push((x_hi * 1.5, y_of(last.y)));
        }
        chart.draw_series(dashed(&steps, BLACK.mix(0.6)))?;
        for p in pts {
            let b = backends.iter().position(|n| *n == p.backend).unwrap_or(0);
            let colour = Palette99::pick(b).to_rgba();
            let at = (p.x, y_of(p.y));
            if p.label.ends_with("f32") {
                chart.draw_series(std::iter::once(Circle::new(at, 5, colour.filled())))?;
            } else {
                chart.draw_series(std::iter::once(TriangleMarker::new(at, 6, colour.filled())))?;
            }
            if front.iter().any(|f| f.label == p.label) {
                chart.draw_series(std::iter::once(Circle::new(at, 9, BLACK.stroke_width(1))))?;
            }
            chart.draw_series(std::iter::once(Text::new(
                p.label.clone(),
                (p.x * 1.04, y_of(p.y) * 1.15),
                ("sans-serif", 11),
            )))?;
        }
    }
    header.draw(&Text::new(
        "circle: f32, triangle: f64; ringed points and dashed line: Pareto front".to_owned(),
        (700, 12),
        ("sans-serif", 12),
    ))?;
    root.present()?;
    Ok(())
}

/// The smallest and largest of positive finite values (`(inf, 0)` if none).
fn range(values: impl Iterator<Item = f64>) -> (f64, f64) {
    values
        .filter(|v| v.is_finite() && *v > 0.0)
        .fold((f64::INFINITY, 0.0f64), |(lo, hi), v| (lo.min(v), hi.max(v)))
}

/// A dashed polyline, as short segments (plotters' SVG backend has no dash style).
fn dashed(points: &[(f64, f64)], colour: RGBAColor) -> Vec<PathElement<(f64, f64)>> {
    let mut out = Vec::new();
    for w in points.windows(2) {
        let ((x0, y0), (x1, y1)) = (w[0], w[1]);
        // Interpolate in log space: both axes are logarithmic.
        let n = 12;
        for k in (0..n).step_by(2) {
            let at = |s: f64| {
                let lerp = |a: f64, b: f64| (a.ln() + (b.ln() - a.ln()) * s).exp();
                (lerp(x0, x1), lerp(y0, y1))
            };
            let (s0, s1) = (k as f64 / n as f64, (k + 1) as f64 / n as f64);
            out.push(PathElement::new(vec![at(s0), at(s1)], colour));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(label: &str, x: f64, y: f64) -> Point {
        Point { label: label.into(), backend: label.into(), x, y }
    }

    #[test]
    fn pareto_front_keeps_the_undominated() {
        let pts = [
            p("a", 1.0, 5.0),
            p("b", 2.0, 1.0),
            p("c", 3.0, 2.0),
            p("d", 4.0, 0.0),
            p("e", 0.5, 9.0),
        ];
        let front: Vec<String> = pareto_front(&pts).into_iter().map(|p| p.label).collect();
        assert_eq!(front, ["e", "a", "b", "d"]);
    }
}
