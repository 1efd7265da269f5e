//! `results/throughput.svg`: Mrays/s of every back end on every scene, one panel per
//! precision and ray set, drawn with plotters' SVG backend.

use std::path::Path;

use plotters::prelude::*;

use super::rows::ThroughputRow;
use crate::distinct;

/// Panel size in pixels.
const PANEL: (u32, u32) = (560, 330);

/// Draws the rows into an SVG at `path`: panels for `f32`/`f64` (rows) by ray set (columns);
/// in each, one group of bars per scene and one bar per back end, log scale. Filled bars are
/// one thread, outlined bars all threads.
///
/// # Errors
///
/// If the file cannot be written.
pub fn draw_throughput_svg(
    path: &Path,
    rows: &[ThroughputRow],
    title: &str,
) -> Result<(), Box<dyn std::error::Error>> {
    let precisions = distinct(rows.iter().map(|r| r.precision.as_str()));
    let ray_sets = distinct(rows.iter().map(|r| r.ray_set.as_str()));
    let scenes = distinct(rows.iter().map(|r| r.scene.as_str()));
    let backends = distinct(rows.iter().map(|r| r.backend.as_str()));
    let max_threads = rows.iter().map(|r| r.threads).max().unwrap_or(1);
    if rows.is_empty() {
        return Ok(());
    }
    let size = (PANEL.0 * ray_sets.len() as u32, PANEL.1 * precisions.len() as u32 + 60);
    let root = SVGBackend::new(path, size).into_drawing_area();
    root.fill(&WHITE)?;
    let (header, body) = root.split_vertically(60);
    header.draw(&Text::new(
        title.to_owned(),
        (10, 8),
        ("sans-serif", 16).into_font().color(&BLACK),
    ))?;
    // The legend: one swatch per back end.
    for (b, name) in backends.iter().enumerate() {
        let x = 10 + 130 * b as i32;
        let color = Palette99::pick(b).to_rgba();
        header.draw(&Rectangle::new([(x, 34), (x + 14, 48)], color.filled()))?;
        header.draw(&Text::new(name.to_string(), (x + 18, 34), ("sans-serif", 13)))?;
    }
    let note = format!("filled: 1 thread, outline: {max_threads} threads; log scale");
    let x = 10 + 130 * backends.len() as i32;
    header.draw(&Text::new(note, (x, 34), ("sans-serif", 13)))?;

    let (lo, hi) = rows
        .iter()
        .map(|r| r.mrays_per_s)
        .filter(|v| *v > 0.0 && v.is_finite())
        .fold((f64::INFINITY, 0.0f64), |(lo, hi), v| (lo.min(v), hi.max(v)));
    let (lo, hi) = (lo / 1.5, hi * 1.5);
    let panels = body.split_evenly((precisions.len(), ray_sets.len()));
    let group = 0.8;
    let width = group / backends.len() as f64;
    for (p, precision) in precisions.iter().enumerate() {
        for (s, ray_set) in ray_sets.iter().enumerate() {
            let area = &panels[p * ray_sets.len() + s];
            let mut chart = ChartBuilder::on(area)
                .caption(format!("{ray_set}, {precision}"), ("sans-serif", 14))
                .margin(6)
                .x_label_area_size(22)
                .y_label_area_size(46)
                .build_cartesian_2d(-0.5..scenes.len() as f64 - 0.5, (lo..hi).log_scale())?;
            chart
                .configure_mesh()
                .disable_x_mesh()
                .x_labels(0)
                .y_desc("Mrays/s")
                .label_style(("sans-serif", 11))
                .draw()?;
            for (k, scene) in scenes.iter().enumerate() {
                chart.draw_series(std::iter::once(Text::new(
                    scene.to_string(),
                    (k as f64 - 0.45, lo * 1.02),
                    ("sans-serif", 10),
                )))?;
                for (b, backend) in backends.iter().enumerate() {
                    let x0 = k as f64 - group / 2.0 + width * b as f64;
                    let color = Palette99::pick(b).to_rgba();
                    let find = |one: bool| {
                        rows.iter().find(|r| {
                            r.precision == *precision
                                && r.ray_set == *ray_set
                                && r.scene == *scene
                                && r.backend == *backend
                                && (r.threads == 1) == one
                        })
                    };
                    if let Some(r) = find(true) {
                        let bar = [(x0, lo), (x0 + width * 0.9, r.mrays_per_s.max(lo))];
                        chart.draw_series(std::iter::once(Rectangle::new(bar, color.filled())))?;
                    }
                    if let Some(r) = find(false).filter(|_| max_threads > 1) {
                        let bar = [(x0, lo), (x0 + width * 0.9, r.mrays_per_s.max(lo))];
                        let style = ShapeStyle::from(color).stroke_width(1);
                        chart.draw_series(std::iter::once(Rectangle::new(bar, style)))?;
                    }
                }
            }
        }
    }
    root.present()?;
    Ok(())
}
