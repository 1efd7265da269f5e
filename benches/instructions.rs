//! Instructions per ray of every back end and precision, counted by callgrind: the one figure
//! of cost that the host's load cannot move. Writes `results/instructions.csv`.
//!
//! Each measurement is a child process of this binary run under `valgrind --tool=callgrind`
//! with collection off except inside [`measured_trace`] (`--toggle-collect`): the child loads
//! the bunny, builds one back end's BVH, makes one ray set and traces it once inside that
//! function, so the count is the traversal and the ray-triangle tests alone (no loading,
//! building or ray making), divided by the number of rays. Ray sets: 128 x 128 primary rays of
//! the same camera as the other benches (closest and any hit) and 16,384 incoherent rays
//! (closest hit); fewer rays than the timed benches, since callgrind runs about 50 times
//! slower, but the same kind of ray: the count per ray depends on the rays' geometry, not on
//! how many there are.
//!
//! valgrind cannot decode AVX-512, so this bench needs a build without it: the workspace's
//! `x86-64-v3` flags (`.cargo/config.toml`) are such a build. The CSV gives each back end's
//! count and its ratio to its row's LA cell (the same method in glam), the like-for-like
//! figure of `SUMMARY.md`.
//!
//! Run: `cargo bench -p wedge-benches --bench instructions` (about 10 minutes). Without
//! valgrind on the `PATH` it prints a note and writes nothing. `WEDGE_BENCH_QUICK=1`: two back
//! ends, 16 x 16 and 256 rays, the CSV under the criterion directory (a smoke test).

use std::hint::black_box;
use std::process::{Command, ExitCode};

use backends::{Algebra, Backend, Job, Precision, dispatch};
use bvh::accel::Accel;
use intersect::{Intersector, Ray};
use scene::Mesh;
use serde::Serialize;
use wedge_benches::throughput::rays::{INCOHERENT_SEED, RaySet, incoherent_rays, primary_rays};
use wedge_benches::throughput::scenes::bunny;
use wedge_benches::throughput::trace::{Traced, trace};
use wedge_benches::{criterion_dir, machine, quick_mode, results_dir, write_csv};

/// Set in a child process: `backend:precision:ray_set` to count.
const CHILD: &str = "WEDGE_INSTRUCTIONS_CHILD";

/// One row of `instructions.csv`.
#[derive(Serialize)]
struct Row {
    backend: String,
    precision: String,
    scene: &'static str,
    ray_set: &'static str,
    rays: usize,
    instructions_per_ray: f64,
    /// Over the row's LA cell's count in the same precision and ray set.
    ratio_to_la_cell: f64,
    cpu: String,
}

/// The only code callgrind counts: one trace of the rays.
#[inline(never)]
fn measured_trace<I: Intersector>(accel: &Accel<I>, rays: &[Ray<I::Real>], set: RaySet) -> Traced {
    trace(accel, black_box(rays), set.query())
}

/// A child's work: build, make the rays, trace them once.
struct Count {
    mesh: Mesh,
    rays: Vec<Ray<f64>>,
    set: RaySet,
}

impl Job for Count {
    type Output = Traced;

    fn run<I: Intersector + 'static>(self, intersector: I) -> Traced {
        let accel = Accel::build(intersector, &self.mesh.triangles());
        let rays: Vec<Ray<I::Real>> = self.rays.iter().map(Ray::cast).collect();
        black_box(measured_trace(&accel, &rays, self.set))
    }
}

/// Primary rays per image side and incoherent rays.
const fn sizes(quick: bool) -> (u32, usize) {
    if quick { (16, 256) } else { (128, 16_384) }
}

/// How many rays `set` has.
fn ray_count(set: RaySet, quick: bool) -> usize {
    let (side, incoherent) = sizes(quick);
    if set.is_primary() { (side * side) as usize } else { incoherent }
}

/// The rays of `set` on `mesh`, in `f64`.
fn rays(mesh: &Mesh, set: RaySet, quick: bool) -> Vec<Ray<f64>> {
    let (side, incoherent) = sizes(quick);
    if set.is_primary() {
        primary_rays(mesh, side, side)
    } else {
        incoherent_rays(mesh, incoherent, INCOHERENT_SEED)
    }
}

fn child(spec: &str) -> Result<(), String> {
    let mut parts = spec.split(':');
    let mut next = || parts.next().ok_or_else(|| format!("bad spec {spec}"));
    let backend = next()?;
    let backend = Backend::from_name(backend).ok_or(format!("no back end {backend}"))?;
    let precision = next()?;
    let precision = Precision::from_name(precision).ok_or(format!("no precision {precision}"))?;
    let set = next()?;
    let set = RaySet::ALL.into_iter().find(|s| s.name() == set).ok_or(format!("no set {set}"))?;
    let mesh = bunny();
    let rays = rays(&mesh, set, quick_mode());
    let traced = dispatch(backend, precision, Count { mesh, rays, set });
    println!("{}", traced.hits);
    Ok(())
}

/// Runs one child under callgrind and returns the instructions counted in [`measured_trace`].
fn count(spec: &str) -> Result<f64, String> {
    let exe = std::env::current_exe().map_err(|e| e.to_string())?;
    let out = Command::new("valgrind")
        .args([
            "--tool=callgrind",
            "--collect-atstart=no",
            "--toggle-collect=*measured_trace*",
            "--callgrind-out-file=/dev/null",
        ])
        .arg(exe)
        .env(CHILD, spec)
        .output()
        .map_err(|e| format!("valgrind: {e}"))?;
    let stderr = String::from_utf8_lossy(&out.stderr);
    if !out.status.success() {
        return Err(format!("{spec}: {}", stderr.trim()));
    }
    stderr
        .lines()
        .find_map(|l| l.split_once("Collected :").map(|(_, n)| n.trim().to_owned()))
        .ok_or_else(|| format!("{spec}: no count in callgrind's output"))?
        .parse()
        .map_err(|e| format!("{spec}: {e}"))
}

fn parent() -> Result<(), String> {
    let available = Command::new("valgrind").arg("--version").output();
    if !available.is_ok_and(|o| o.status.success()) {
        eprintln!("note: valgrind is not on the PATH: no instruction counts (nothing written)");
        return Ok(());
    }
    let quick = quick_mode();
    let backends: Vec<Backend> =
        if quick { vec![Backend::BASELINE, Backend::ALL[1]] } else { Backend::ALL.to_vec() };
    let mut rows = Vec::new();
    let cpu = machine();
    for precision in Precision::ALL {
        for set in RaySet::ALL {
            let n = ray_count(set, quick);
            let mut counts = Vec::new();
            for &b in &backends {
                let spec = format!("{}:{}:{}", b.name(), precision.name(), set.name());
                let per_ray = count(&spec)? / n as f64;
                eprintln!("{spec}: {per_ray:.0} instructions per ray");
                counts.push((b, per_ray));
            }
            for &(b, per_ray) in &counts {
                let la = Backend::cell(b.method(), Algebra::La)
                    .and_then(|c| counts.iter().find(|(x, _)| *x == c))
                    .map_or(f64::NAN, |x| x.1);
                rows.push(Row {
                    backend: b.name().to_owned(),
                    precision: precision.name().to_owned(),
                    scene: "bunny",
                    ray_set: set.name(),
                    rays: n,
                    instructions_per_ray: per_ray,
                    ratio_to_la_cell: per_ray / la,
                    cpu: cpu.clone(),
                });
            }
        }
    }
    let path = if quick { criterion_dir() } else { results_dir() }.join("instructions.csv");
    write_csv(&path, &rows).map_err(|e| format!("{}: {e}", path.display()))?;
    println!("wrote {}", path.display());
    Ok(())
}

fn main() -> ExitCode {
    wedge_benches::child_or_parent(CHILD, child, parent)
}
