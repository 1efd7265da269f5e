//! The machinery of the benches that measure in alternating processes (`interleaved`,
//! `versus`): one child process per measurement, the order of the children rotated from round
//! to round, the median over rounds; and the Embree reference (`benches/embree/trace.py`),
//! which runs in a Python process of its own on triangles and rays written as `f32` files.
//!
//! Why processes: on the machine of `results/` the time of the same binary on the same rays
//! moves by up to ±10% between processes, and is steady within one (see the `interleaved`
//! bench's documentation).

use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::Path;
use std::process::Command;

use intersect::Ray;
use scene::Mesh;

/// The script that traces rays with Embree 4.
pub const EMBREE_SCRIPT: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/embree/trace.py");

/// The Python interpreter for the Embree reference: `WEDGE_PYTHON`, else `python3`.
#[must_use]
pub fn python() -> String {
    std::env::var("WEDGE_PYTHON").unwrap_or_else(|_| "python3".to_owned())
}

/// Whether the Embree reference can run: `embreex` imports.
#[must_use]
pub fn embree_available() -> bool {
    Command::new(python())
        .args(["-c", "import embreex"])
        .output()
        .is_ok_and(|out| out.status.success())
}

/// Writes `values` as little-endian `f32`.
///
/// # Errors
///
/// If the file cannot be created or written.
pub fn write_f32(path: &Path, values: impl Iterator<Item = f32>) -> std::io::Result<()> {
    let mut out = BufWriter::new(File::create(path)?);
    for x in values {
        out.write_all(&x.to_le_bytes())?;
    }
    out.flush()
}

/// Writes `mesh`'s triangles for the Embree script (`n x 3 x 3` `f32`, each triangle's
/// vertices, in mesh order).
///
/// # Errors
///
/// If the file cannot be created or written.
pub fn write_triangles(path: &Path, mesh: &Mesh) -> std::io::Result<()> {
    let triangles = mesh.triangles::<f32>();
    write_f32(path, triangles.iter().flat_map(|t| t.vertices().into_iter().flatten()))
}

/// Writes rays for the Embree script (`n x 6` `f32`: origin, then direction), each rounded
/// from `f64` once, as the `f32` back ends round them.
///
/// # Errors
///
/// If the file cannot be created or written.
pub fn write_rays(path: &Path, rays: &[Ray<f64>]) -> std::io::Result<()> {
    let values = rays.iter().flat_map(|r| r.origin.into_iter().chain(r.dir));
    write_f32(path, values.map(|x| x as f32))
}

/// Runs `command` and parses its standard output as whitespace-separated numbers (`NaN` for a
/// figure that does not apply); `spec` names it in errors.
///
/// # Errors
///
/// If it cannot start, fails, or prints something that is not a number.
pub fn figures_of(spec: &str, command: &mut Command) -> Result<Vec<f64>, String> {
    let out = command.output().map_err(|e| format!("{spec}: {e}"))?;
    if !out.status.success() {
        return Err(format!("{spec}: {}", String::from_utf8_lossy(&out.stderr).trim()));
    }
    String::from_utf8_lossy(&out.stdout)
        .split_whitespace()
        .map(|s| s.parse().map_err(|e| format!("{spec}: {e}")))
        .collect()
}

/// This bench's own binary as a child, with `env` set to `spec` (see
/// [`child_or_parent`](crate::child_or_parent)), and its figures.
///
/// # Errors
///
/// As [`figures_of`].
pub fn run_self(env: &str, spec: &str) -> Result<Vec<f64>, String> {
    let exe = std::env::current_exe().map_err(|e| e.to_string())?;
    figures_of(spec, Command::new(exe).env(env, spec))
}

/// Runs `rounds` rounds of every spec `0..specs`, each round starting one spec later than the
/// last (so that no spec always runs first, or after the same one), with `run(spec)` giving
/// that spec's figures. Returns, per spec and per figure, the figures of every round (as
/// many figures as the spec's first run gave).
///
/// # Errors
///
/// The first error of `run`, or a run that gives a different number of figures.
pub fn alternate(
    names: &[String],
    rounds: usize,
    mut run: impl FnMut(usize) -> Result<Vec<f64>, String>,
) -> Result<Vec<Vec<Vec<f64>>>, String> {
    let specs = names.len();
    let mut figures: Vec<Vec<Vec<f64>>> = vec![Vec::new(); specs];
    for round in 0..rounds {
        for k in 0..specs {
            let i = (k + round) % specs;
            let got = run(i)?;
            eprintln!("round {round} {}: {got:?}", names[i]);
            if figures[i].is_empty() {
                figures[i] = vec![Vec::new(); got.len()];
            }
            if got.len() != figures[i].len() {
                return Err(format!(
                    "{}: {} figures, then {}",
                    names[i],
                    figures[i].len(),
                    got.len()
                ));
            }
            for (series, x) in figures[i].iter_mut().zip(got) {
                series.push(x);
            }
        }
    }
    Ok(figures)
}

/// Splits the Embree script's figures over rounds (per set, Mrays/s, then per set the binding's
/// cost per ray in ns) into the measured series and the series with the binding's cost taken
/// off (`embree4-net`, a bound in Embree's favour).
#[must_use]
pub fn embree_net(figures: &[Vec<f64>]) -> (Vec<Vec<f64>>, Vec<Vec<f64>>) {
    let (raw, cost) = figures.split_at(figures.len() / 2);
    let net = raw
        .iter()
        .zip(cost)
        .map(|(x, ns)| x.iter().zip(ns).map(|(&x, &ns)| 1e3 / (1e3 / x - ns)).collect())
        .collect();
    (raw.to_vec(), net)
}

/// The median, minimum and maximum of `values` that are not NaN, or `None` if there is none.
#[must_use]
pub fn summary(values: &[f64]) -> Option<(f64, f64, f64)> {
    let mut v: Vec<f64> = values.iter().copied().filter(|x| !x.is_nan()).collect();
    if v.is_empty() {
        return None;
    }
    let m = crate::median(&mut v);
    Some((m, v[0], v[v.len() - 1]))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn alternate_rotates_and_collects() {
        let names: Vec<String> = ["a", "b", "c"].map(String::from).to_vec();
        let mut order = Vec::new();
        let figures = alternate(&names, 2, |i| {
            order.push(i);
            Ok(vec![i as f64, 10.0 * i as f64])
        })
        .unwrap();
        assert_eq!(order, [0, 1, 2, 1, 2, 0]);
        assert_eq!(figures[2], [vec![2.0, 2.0], vec![20.0, 20.0]]);
        let mut calls = 0;
        let uneven = alternate(&names, 2, |_| {
            calls += 1;
            Ok(vec![0.0; if calls > 3 { 1 } else { 2 }])
        });
        assert!(uneven.is_err());
    }

    #[test]
    fn embree_net_takes_the_binding_off() {
        // 10 Mrays/s is 100 ns per ray; without 50 ns of binding it is 20 Mrays/s.
        let (raw, net) = embree_net(&[vec![10.0], vec![50.0]]);
        assert_eq!(raw, [vec![10.0]]);
        assert!((net[0][0] - 20.0).abs() < 1e-9);
    }

    #[test]
    fn summary_skips_nan() {
        assert_eq!(summary(&[3.0, f64::NAN, 1.0, 2.0]), Some((2.0, 1.0, 3.0)));
        assert_eq!(summary(&[f64::NAN]), None);
    }
}
