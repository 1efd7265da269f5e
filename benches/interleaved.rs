//! Back ends timed in alternating processes: primary rays (closest and any hit) and
//! incoherent rays on two meshes and views (the Stanford bunny, and the Utah teapot from
//! `../shared/meshes/` framed by its own camera), one thread, every back end and precision, each
//! measured in a fresh process per round, with the order of the back ends rotated from round to
//! round, and Embree 4 beside them when it is installed. Writes `results/interleaved.csv`.
//!
//! **Why.** On the machine of `results/` the time of the same binary on the same rays moves by
//! up to ±10% between processes (seen: 4.9 to 6.0 Mrays/s for `la` f32 incoherent rays in ten
//! runs), and by ±20-30% between runs of the throughput bench (`la-mt` f32 incoherent went
//! from 1.60x to 1.19x `la`'s time with no change to either kernel). Within one process the
//! figure is steady, so the spread comes with the process: where the BVH and the triangles
//! land in memory, and what else the host is doing at the time. One process per
//! measurement, alternated, and the median over rounds make the comparison of back ends fair
//! to each of them. The throughput bench remains the table of every scene and thread count.
//!
//! Each child process loads both meshes, builds one back end's BVH of each, traces each ray set
//! three times and prints the best Mrays/s of the three (the first trace warms the caches). The
//! parent runs `ROUNDS` rounds and writes, per back end, precision and ray set, the median,
//! minimum and maximum over the rounds, and the ratio of `la`'s median Mrays/s to the back
//! end's (time relative to `la`, as in `throughput.csv`).
//!
//! **Embree 4 as the reference.** When `python3 -c "import embreex"` works (`pip install
//! embreex`; another interpreter with `WEDGE_PYTHON`), each round also runs
//! `benches/embree/trace.py` in its own process, on the same triangles and the same rays
//! rounded to `f32` (written to `embree-input/` under the criterion directory): Embree 4, one
//! `rtcIntersect1`/`rtcOccluded1` call per ray, one thread, on the bunny, warm (each set cast
//! once, untimed, before the timed traces: Embree's first casts in a process run about 2x
//! slower). It gives two rows:
//! `embree4`, as measured, and `embree4-net`, with the binding's own cost per ray taken off (the
//! Cython loop and the call, timed on an empty scene with the same rays: 10 to 13 ns on the machine
//! of `results/`), a bound in Embree's favour. The targets were measured on another
//! machine; these rows are the same-machine comparison. The project does not depend on Embree:
//! without `embreex` the rows are left out, with a note.
//!
//! Run: `cargo bench -p wedge-benches --bench interleaved` (about 25 minutes for 22 back ends).
//! The views, meshes, references (tinybvh) and user-facing paths of issue 18 are the sibling
//! bench `versus`, on the same machinery (`wedge_benches::alternate`).
//!
//! With `WEDGE_BENCH_QUICK=1`: one round of 64 x 64 primary and 4,096 incoherent rays, written to
//! the criterion directory (a smoke test).

use std::hint::black_box;
use std::path::{Path, PathBuf};
use std::process::{Command, ExitCode};
use std::time::Instant;

use backends::{Backend, Job, Precision, dispatch};
use bvh::accel::Accel;
use intersect::{Intersector, Ray};
use scene::Mesh;
use serde::Serialize;
use wedge_benches::alternate::{
    EMBREE_SCRIPT, alternate, embree_available, embree_net, figures_of, python, run_self,
    write_rays, write_triangles,
};
use wedge_benches::throughput::rays::{
    INCOHERENT_SEED, Query, RaySet, incoherent_rays, primary_rays,
};
use wedge_benches::throughput::scenes::{bunny, shared_mesh};
use wedge_benches::throughput::trace::trace;
use wedge_benches::{criterion_dir, machine, median, quick_mode, results_dir, write_csv};

/// Rounds of a full run; each round runs every back end and precision once.
const ROUNDS: usize = 7;
/// The scenes, by the name the CSV rows use: the first is also Embree's.
const SCENES: [&str; 2] = ["bunny", "teapot"];
/// Traces of each ray set per process; the best one counts.
const REPEATS: usize = 3;
/// The ray sets compared: the three columns of the table.
const SETS: [RaySet; 3] = RaySet::ALL;
/// Set in a child process: `backend:precision` to measure.
const CHILD: &str = "WEDGE_INTERLEAVED_CHILD";
/// The back end name of the Embree reference, and of its row with the binding's cost removed.
const EMBREE: &str = "embree4";
/// See [`EMBREE`].
const EMBREE_NET: &str = "embree4-net";

/// One row of `interleaved.csv`.
#[derive(Serialize)]
struct Row {
    backend: String,
    precision: String,
    scene: &'static str,
    ray_set: &'static str,
    rounds: usize,
    median_mrays_per_s: f64,
    min_mrays_per_s: f64,
    max_mrays_per_s: f64,
    /// `la`'s median Mrays/s over this back end's (time relative to `la`).
    ratio_to_la: f64,
    cpu: String,
}

/// The meshes of [`SCENES`], in that order.
fn meshes() -> Vec<Mesh> {
    vec![bunny(), shared_mesh("teapot.obj")]
}

/// The rays of the comparison, in `f64`.
fn ray_sets(mesh: &Mesh, quick: bool) -> Vec<(RaySet, Vec<Ray<f64>>)> {
    let (side, incoherent) = if quick { (64, 4096) } else { (1024, 1_000_000) };
    // Both primary sets are the same rays: made once.
    let primary = primary_rays(mesh, side, side);
    SETS.iter()
        .map(|&set| {
            let rays = if set.is_primary() {
                primary.clone()
            } else {
                incoherent_rays(mesh, incoherent, INCOHERENT_SEED)
            };
            (set, rays)
        })
        .collect()
}

/// A child's work: best Mrays/s of each ray set with one back end.
struct Measure<'a> {
    mesh: &'a Mesh,
    sets: &'a [(RaySet, Vec<Ray<f64>>)],
}

impl Job for Measure<'_> {
    type Output = Vec<f64>;

    fn run<I: Intersector + 'static>(self, intersector: I) -> Vec<f64> {
        let accel = Accel::build(intersector, &self.mesh.triangles());
        self.sets
            .iter()
            .map(|(set, rays64)| {
                let rays: Vec<Ray<I::Real>> = rays64.iter().map(Ray::cast).collect();
                (0..REPEATS)
                    .map(|_| {
                        let start = Instant::now();
                        black_box(trace(&accel, black_box(&rays), set.query()));
                        rays.len() as f64 / start.elapsed().as_secs_f64() / 1e6
                    })
                    .fold(0.0, f64::max)
            })
            .collect()
    }
}

/// Child mode: measures `spec` (`backend:precision`) and prints one figure per ray set.
fn child(spec: &str) -> Result<(), String> {
    let (backend, precision) = spec.split_once(':').ok_or("expected backend:precision")?;
    let backend = Backend::from_name(backend).ok_or(format!("invalid variant: {backend}"))?;
    let precision =
        Precision::from_name(precision).ok_or(format!("invalid variant: {precision}"))?;
    let mut figures = Vec::new();
    for mesh in meshes() {
        let sets = ray_sets(&mesh, quick_mode());
        figures.extend(dispatch(backend, precision, Measure { mesh: &mesh, sets: &sets }));
    }
    println!("{}", figures.iter().map(f64::to_string).collect::<Vec<_>>().join(" "));
    Ok(())
}

/// Writes the bunny and the rays for the Embree script: `bunny.tri` (each triangle's
/// vertices) and `primary.ray`, `incoherent.ray` (origin and direction per ray; each written
/// once, though two sets share the primary rays), little-endian `f32`, the rays rounded from
/// `f64` once, as the `f32` back ends round them. Returns the script's arguments, one
/// `rays:query` per set.
fn export_for_embree(
    mesh: &Mesh,
    sets: &[(RaySet, Vec<Ray<f64>>)],
    dir: &Path,
) -> std::io::Result<Vec<String>> {
    std::fs::create_dir_all(dir)?;
    write_triangles(&dir.join("bunny.tri"), mesh)?;
    let mut args = vec![dir.display().to_string(), "bunny.tri".to_owned()];
    let mut written = Vec::new();
    for (set, rays) in sets {
        let file = if set.is_primary() { "primary" } else { "incoherent" };
        if !written.contains(&file) {
            write_rays(&dir.join(format!("{file}.ray")), rays)?;
            written.push(file);
        }
        let query = match set.query() {
            Query::Closest => "closest",
            Query::Any => "any",
        };
        args.push(format!("{file}:{query}"));
    }
    Ok(args)
}

/// Runs one child (a back end of ours, or with `embree` the Embree script with those
/// arguments) and parses its figures.
fn run_child(spec: &str, embree: &[String]) -> Result<Vec<f64>, String> {
    if spec.starts_with(EMBREE) {
        figures_of(spec, Command::new(python()).arg(EMBREE_SCRIPT).args(embree))
    } else {
        run_self(CHILD, spec)
    }
}

fn parent() -> Result<(), String> {
    let quick = quick_mode();
    let rounds = if quick { 1 } else { ROUNDS };
    let specs: Vec<(Backend, Precision)> =
        Precision::ALL.into_iter().flat_map(|p| Backend::ALL.map(|b| (b, p))).collect();
    let mut spec_names: Vec<(String, String)> =
        specs.iter().map(|(b, p)| (b.name().to_owned(), p.name().to_owned())).collect();
    let mut embree_args = Vec::new();
    if embree_available() {
        let mesh = bunny();
        let dir: PathBuf = criterion_dir().join("embree-input");
        embree_args = export_for_embree(&mesh, &ray_sets(&mesh, quick), &dir)
            .map_err(|e| format!("{}: {e}", dir.display()))?;
        spec_names.push((EMBREE.to_owned(), "f32".to_owned()));
    } else {
        eprintln!("note: no Embree reference rows (`{} -c \"import embreex\"` failed)", python());
    }
    let measured = spec_names.len();
    if !embree_args.is_empty() {
        spec_names.push((EMBREE_NET.to_owned(), "f32".to_owned()));
    }
    // figures[spec][scene * SETS.len() + set] over the rounds (Embree's: the first scene's).
    let names: Vec<String> =
        spec_names[..measured].iter().map(|(b, p)| format!("{b}:{p}")).collect();
    let mut figures = alternate(&names, rounds, |i| run_child(&names[i], &embree_args))?;
    if !embree_args.is_empty() {
        let (raw, net) = embree_net(&figures[measured - 1]);
        figures[measured - 1] = raw;
        figures.push(net);
    }
    let series = SCENES.len() * SETS.len();
    for f in &mut figures {
        f.resize(series, Vec::new());
    }
    let cpu = machine();
    // Each series sorted (by `median`): its minimum first and its maximum last.
    let medians: Vec<Vec<f64>> = figures
        .iter_mut()
        .map(|sets| {
            sets.iter_mut().map(|v| if v.is_empty() { f64::NAN } else { median(v) }).collect()
        })
        .collect();
    let mut rows = Vec::new();
    for (i, (b, p)) in spec_names.iter().enumerate() {
        let la = spec_names
            .iter()
            .position(|(lb, lp)| lb == Backend::BASELINE.name() && lp == p)
            .unwrap_or(i);
        for s in 0..series {
            let (scene, set) = (SCENES[s / SETS.len()], SETS[s % SETS.len()]);
            let sorted = &figures[i][s];
            if sorted.is_empty() {
                continue;
            }
            rows.push(Row {
                backend: b.clone(),
                precision: p.clone(),
                scene,
                ray_set: set.name(),
                rounds,
                median_mrays_per_s: medians[i][s],
                min_mrays_per_s: sorted[0],
                max_mrays_per_s: sorted[sorted.len() - 1],
                ratio_to_la: medians[la][s] / medians[i][s],
                cpu: cpu.clone(),
            });
        }
    }
    println!(
        "{:<14} {:<4} {:<7} {:<19} {:>7} {:>7} {:>7} {:>6}",
        "back end", "prec", "scene", "rays", "median", "min", "max", "ratio"
    );
    for r in &rows {
        println!(
            "{:<14} {:<4} {:<7} {:<19} {:>7.2} {:>7.2} {:>7.2} {:>6.3}",
            r.backend,
            r.precision,
            r.scene,
            r.ray_set,
            r.median_mrays_per_s,
            r.min_mrays_per_s,
            r.max_mrays_per_s,
            r.ratio_to_la
        );
    }
    let dir = if quick { criterion_dir() } else { results_dir() };
    let path = dir.join("interleaved.csv");
    write_csv(&path, &rows).map_err(|e| format!("{}: {e}", path.display()))?;
    println!("wrote {}", path.display());
    Ok(())
}

fn main() -> ExitCode {
    wedge_benches::child_or_parent(CHILD, child, parent)
}
