//! Full traversal: Mrays/s of every back end and precision, through the same BVH code, on the
//! same rays, one thread (and all threads for the baseline back end, `la`).
//!
//! Scenes: the Stanford bunny (69,451 triangles), the bunny split twice (1,111,216 triangles,
//! made at run time with `scene::generators::subdivide`) and every `obj/` scene. Ray sets (see
//! `wedge_benches::throughput::rays`): 1024 x 1024 primary rays of a camera framing the mesh,
//! closest hit and any hit; 1,000,000 incoherent rays (origins uniform in the mesh's box,
//! directions uniform on the sphere, fixed seed), closest hit; and on the 1.1M mesh the
//! issue's alpha frame, 1920 x 1080 primary rays, any hit. One criterion iteration traces the
//! whole set; rays are made in `f64` and rounded once per precision.
//!
//! After the benchmarks, `main` reads criterion's estimates and writes
//! `results/throughput.csv` (one row per back end, precision, scene, ray set and thread count,
//! with the ratio of each back end's time to `la`'s) and `results/throughput.svg`.
//!
//! Run: `cargo bench -p wedge-benches --bench throughput`. Environment:
//! - `WEDGE_BENCH_QUICK=1`: 128 x 128 primary rays and 16,384 incoherent rays, a few
//!   milliseconds per benchmark; CSV and SVG go to the criterion directory (a smoke test).
//! - `WEDGE_BENCH_SCENES=bunny,torus` and `WEDGE_BENCH_BACKENDS=la,ga`: only these. Such a
//!   run, like one filtered by criterion (`-- bunny`), writes `throughput.partial.csv` and
//!   `.svg` to the criterion directory, never over `results/`.

use std::hint::black_box;
use std::thread::available_parallelism;
use std::time::{Duration, SystemTime};

use backends::{Backend, Job, Precision, dispatch};
use bvh::accel::Accel;
use criterion::{Criterion, SamplingMode, Throughput};
use intersect::{Intersector, Ray};
use wedge_benches::clock::configured;
use wedge_benches::throughput::plot::draw_throughput_svg;
use wedge_benches::throughput::rays::{INCOHERENT_SEED, RaySet, incoherent_rays, primary_rays};
use wedge_benches::throughput::rows::{ThroughputRow, fill_ratios_to_la};
use wedge_benches::throughput::scenes::{BenchScene, all_scenes};
use wedge_benches::throughput::trace::{Traced, trace, trace_parallel};
use wedge_benches::{
    bench_times, criterion_dir, machine, mean_ns, output_path, quick_mode, write_csv,
};

/// Scenes with at least this many triangles also get the 1920 x 1080 alpha frame.
const LARGE_SCENE: usize = 1_000_000;

/// Ray counts: full runs and quick (smoke) runs.
struct Sizes {
    primary: (u32, u32),
    full_hd: (u32, u32),
    incoherent: usize,
}

const FULL: Sizes = Sizes { primary: (1024, 1024), full_hd: (1920, 1080), incoherent: 1_000_000 };
const QUICK: Sizes = Sizes { primary: (128, 128), full_hd: (192, 108), incoherent: 16_384 };

/// The rays of one scene, in `f64`.
struct SceneRays {
    primary: Vec<Ray<f64>>,
    incoherent: Vec<Ray<f64>>,
    full_hd: Option<Vec<Ray<f64>>>,
}

impl SceneRays {
    fn new(scene: &BenchScene, sizes: &Sizes) -> Self {
        let (w, h) = sizes.primary;
        let large = scene.mesh.len() >= LARGE_SCENE;
        Self {
            primary: primary_rays(&scene.mesh, w, h),
            incoherent: incoherent_rays(&scene.mesh, sizes.incoherent, INCOHERENT_SEED),
            full_hd: large.then(|| primary_rays(&scene.mesh, sizes.full_hd.0, sizes.full_hd.1)),
        }
    }

    fn get(&self, set: RaySet) -> Option<&[Ray<f64>]> {
        match set {
            RaySet::PrimaryClosest | RaySet::PrimaryAny => Some(&self.primary),
            RaySet::IncoherentClosest => Some(&self.incoherent),
            RaySet::AlphaFullHd => self.full_hd.as_deref(),
        }
    }
}

/// One benchmark that ran: what the CSV row needs besides criterion's estimate.
struct Measured {
    group: String,
    function: String,
    row: ThroughputRow,
}

/// Builds one back end's accelerator for one scene and benchmarks every ray set on it.
struct BenchBackend<'a> {
    criterion: &'a mut Criterion,
    scene: &'a BenchScene,
    rays: &'a SceneRays,
    pool: Option<&'a rayon::ThreadPool>,
    precision: Precision,
    cpu: &'a str,
    quick: bool,
}

impl Job for BenchBackend<'_> {
    type Output = Vec<Measured>;

    fn run<I: Intersector + 'static>(self, intersector: I) -> Vec<Measured> {
        let accel = Accel::build(intersector, &self.scene.mesh.triangles());
        let stats = accel.stats();
        let per_triangle = |bytes: usize| bytes as f64 / stats.triangles.max(1) as f64;
        let mut measured = Vec::new();
        let sets = RaySet::ALL.into_iter().chain([RaySet::AlphaFullHd]);
        for set in sets {
            let Some(rays64) = self.rays.get(set) else { continue };
            let rays: Vec<Ray<I::Real>> = rays64.iter().map(Ray::cast).collect();
            let query = set.query();
            let group = format!("throughput_{}_{}", self.scene.name, set.name());
            let mut g = self.criterion.benchmark_group(&group);
            g.sampling_mode(SamplingMode::Flat).throughput(Throughput::Elements(rays.len() as u64));
            if !self.quick {
                // One iteration traces a million rays (tens of milliseconds): ten samples of a
                // few iterations each are plenty, and keep the full run of every back end
                // within half an hour.
                g.sample_size(10)
                    .warm_up_time(Duration::from_millis(300))
                    .measurement_time(Duration::from_secs(1));
            }
            // All threads only for the baseline back end: the parallel loop and the BVH are the
            // same for every back end, so its scaling is the BVH's; every back end is measured
            // on one thread.
            let threads_all = self.pool.map_or(1, rayon::ThreadPool::current_num_threads);
            let mut thread_counts = vec![1];
            if threads_all > 1 && I::NAME == Backend::BASELINE.name() {
                thread_counts.push(threads_all);
            }
            for threads in thread_counts {
                let function = format!("{}_{}_t{threads}", I::NAME, self.precision.name());
                // Counted once outside the timing: the figures every back end should share.
                let traced: Traced = match (threads, self.pool) {
                    (1, _) | (_, None) => trace(&accel, &rays, query),
                    (_, Some(pool)) => trace_parallel(pool, &accel, &rays, query),
                };
                g.bench_function(&function, |b| match (threads, self.pool) {
                    (1, _) | (_, None) => {
                        b.iter(|| black_box(trace(&accel, black_box(&rays), query)))
                    }
                    (_, Some(pool)) => {
                        b.iter(|| black_box(trace_parallel(pool, &accel, black_box(&rays), query)))
                    }
                });
                measured.push(Measured {
                    group: group.clone(),
                    function,
                    row: ThroughputRow {
                        backend: I::NAME.to_owned(),
                        precision: self.precision.name().to_owned(),
                        scene: self.scene.name.clone(),
                        triangles: stats.triangles,
                        ray_set: set.name().to_owned(),
                        threads,
                        rays: rays.len(),
                        hits: traced.hits,
                        mrays_per_s: f64::NAN,
                        ns_per_ray: f64::NAN,
                        ratio_to_la: None,
                        build_ms: stats.bvh_build.as_secs_f64() * 1e3,
                        prepare_ms: stats.prepare.as_secs_f64() * 1e3,
                        bytes_per_triangle: stats.bytes_per_triangle(),
                        bvh_bytes_per_triangle: per_triangle(stats.bvh_bytes),
                        prim_bytes_per_triangle: per_triangle(stats.prim_bytes),
                        cpu: self.cpu.to_owned(),
                    },
                });
            }
            g.finish();
        }
        measured
    }
}

/// The comma-separated names in environment variable `var`, if set.
fn selection(var: &str) -> Option<Vec<String>> {
    std::env::var(var).ok().map(|v| v.split(',').map(|s| s.trim().to_owned()).collect())
}

fn main() {
    let started = SystemTime::now();
    let quick = quick_mode();
    let sizes = if quick { &QUICK } else { &FULL };
    let mut criterion = configured(Criterion::default(), bench_times()).configure_from_args();

    let threads = available_parallelism().map_or(1, usize::from);
    let pool = (threads > 1).then(|| {
        rayon::ThreadPoolBuilder::new().num_threads(threads).build().expect("a thread pool")
    });
    let cpu = machine();
    let scene_filter = selection("WEDGE_BENCH_SCENES");
    let backend_filter = selection("WEDGE_BENCH_BACKENDS");
    let mut measured = Vec::new();
    for scene in all_scenes() {
        if scene_filter.as_ref().is_some_and(|f| !f.contains(&scene.name)) {
            continue;
        }
        let rays = SceneRays::new(&scene, sizes);
        for backend in Backend::ALL {
            let name = backend.name().to_owned();
            if backend_filter.as_ref().is_some_and(|f| !f.contains(&name)) {
                continue;
            }
            for precision in Precision::ALL {
                let job = BenchBackend {
                    criterion: &mut criterion,
                    scene: &scene,
                    rays: &rays,
                    pool: pool.as_ref(),
                    precision,
                    cpu: &cpu,
                    quick,
                };
                measured.extend(dispatch(backend, precision, job));
            }
        }
    }
    criterion.final_summary();

    let dir = criterion_dir();
    let benchmarks = measured.len();
    let mut rows: Vec<ThroughputRow> = measured
        .into_iter()
        .filter_map(|m| {
            // A benchmark filtered out of this run has no fresh estimate: no row for it.
            let ns = mean_ns(&dir, &m.group, &m.function, started)?;
            let mut row = m.row;
            row.ns_per_ray = ns / row.rays as f64;
            row.mrays_per_s = row.rays as f64 / ns * 1e3;
            Some(row)
        })
        .collect();
    if rows.is_empty() {
        return;
    }
    fill_ratios_to_la(&mut rows);
    let complete = rows.len() == benchmarks && scene_filter.is_none() && backend_filter.is_none();
    let csv = output_path("throughput", "csv", complete);
    write_csv(&csv, &rows).unwrap_or_else(|e| panic!("writing {}: {e}", csv.display()));
    let svg = output_path("throughput", "svg", complete);
    let title = format!("Ray throughput, same BVH for every back end ({cpu})");
    draw_throughput_svg(&svg, &rows, &title)
        .unwrap_or_else(|e| panic!("writing {}: {e}", svg.display()));
    print_table(&rows);
    println!("wrote {} and {}", csv.display(), svg.display());
}

fn print_table(rows: &[ThroughputRow]) {
    println!(
        "\n{:<11} {:<4} {:<11} {:<22} {:>3} {:>9} {:>8} {:>6} {:>9} {:>7}",
        "backend",
        "prec",
        "scene",
        "ray set",
        "thr",
        "Mrays/s",
        "ns/ray",
        "vs la",
        "build ms",
        "B/tri"
    );
    for r in rows {
        println!(
            "{:<11} {:<4} {:<11} {:<22} {:>3} {:>9.2} {:>8.1} {:>6} {:>9.1} {:>7.1}",
            r.backend,
            r.precision,
            r.scene,
            r.ray_set,
            r.threads,
            r.mrays_per_s,
            r.ns_per_ray,
            r.ratio_to_la.map_or_else(|| "-".to_owned(), |x| format!("{x:.3}")),
            r.build_ms,
            r.bytes_per_triangle
        );
    }
}
