//! Run time against error: every back end and precision (and the exact reference) timed with
//! criterion on closest-hit rays through the bunny's BVH, then judged by the exact reference on
//! ordinary, edge-aimed and vertex-aimed rays and on the stability suite
//! (`wedge_benches::accuracy`).
//!
//! Writes `results/accuracy.csv`, `results/stability.csv`, `results/runtime_vs_error.svg` and
//! `results/SUMMARY.md` (which also reads `results/throughput.csv` when present).
//!
//! ```text
//! cargo bench -p wedge-benches --bench accuracy          # full run, a few minutes
//! WEDGE_BENCH_QUICK=1 cargo bench -p wedge-benches --bench accuracy   # smoke run
//! ```
//!
//! The smoke run uses tiny sizes and writes under the criterion directory
//! (`<criterion dir>/accuracy-quick/`), never over `results/`.
//!
//! **Clock.** Timings are the benchmark thread's CPU time (`CLOCK_THREAD_CPUTIME_ID`), one
//! thread: the machine is shared, and a thread's CPU time stops while it is descheduled, so
//! the ratios between back ends stay meaningful under load (measured here: wall-clock ratios
//! of the same build moved by up to 2x between runs on a busy machine). `WEDGE_BENCH_WALL=1`
//! measures wall time instead.

use std::path::Path;
use std::time::{Duration, SystemTime};

use backends::Job;
use bvh::accel::Accel;
use criterion::{BenchmarkGroup, Criterion, Throughput};
use intersect::{Intersector, Ray, Triangle};
use wedge_benches::accuracy::mesh::TriMesh;
use wedge_benches::accuracy::plot::draw_runtime_vs_error;
use wedge_benches::accuracy::rays::random_rays;
use wedge_benches::accuracy::runner::Subject;
use wedge_benches::accuracy::suite::{SEED, Sizes, accuracy_rows, stability_rows};
use wedge_benches::accuracy::summary::write_summary;
use wedge_benches::clock::{ThreadClock, configured};
use wedge_benches::{criterion_dir, machine, mean_ns, quick_mode, results_dir, write_csv};

/// Rays per timed iteration: the first rays of the suite's random set.
const TIMED_RAYS: usize = 2048;

/// Criterion's group name.
const GROUP: &str = "accuracy_ns_per_ray";

/// Registers the closest-hit timing of one back end.
struct TimeJob<'a, 'g> {
    group: &'a mut BenchmarkGroup<'g, ThreadClock>,
    triangles: &'a [Triangle<f64>],
    rays: &'a [Ray<f64>],
    id: String,
}

impl Job for TimeJob<'_, '_> {
    type Output = ();
    fn run<I: Intersector + 'static>(self, k: I) {
        let tris: Vec<Triangle<I::Real>> = self.triangles.iter().map(Triangle::cast).collect();
        let accel = Accel::build(k, &tris);
        let rays: Vec<Ray<I::Real>> = self.rays.iter().map(Ray::cast).collect();
        self.group.bench_function(&self.id, |b| {
            b.iter(|| {
                let mut hits = 0u32;
                for ray in &rays {
                    hits += u32::from(accel.closest_hit(std::hint::black_box(ray)).is_some());
                }
                hits
            });
        });
    }
}

fn id(subject: Subject) -> String {
    format!("{}-{}", subject.name(), subject.precision().name())
}

fn main() {
    let started = SystemTime::now();
    let quick = quick_mode();
    let sizes = if quick { Sizes::quick() } else { Sizes::full() };
    let out_dir = if quick { criterion_dir().join("accuracy-quick") } else { results_dir() };
    let bunny = TriMesh::bunny().unwrap_or_else(|e| {
        eprintln!("error: {e}");
        std::process::exit(1);
    });
    let tiles = TriMesh::tiles();
    let cpu = machine();

    // 1. Time every subject on the same rays.
    let triangles = bunny.triangle_list();
    let timed = random_rays(&bunny, TIMED_RAYS, SEED);
    let full = (Duration::from_secs(1), Duration::from_secs(3));
    let criterion = Criterion::default().with_measurement(ThreadClock::from_env());
    let mut criterion = configured(criterion, full).sample_size(10).configure_from_args();
    {
        let mut group = criterion.benchmark_group(GROUP);
        group.throughput(Throughput::Elements(TIMED_RAYS as u64));
        for subject in Subject::all() {
            let job =
                TimeJob { group: &mut group, triangles: &triangles, rays: &timed, id: id(subject) };
            subject.run(job);
        }
        group.finish();
    }
    criterion.final_summary();

    // 2. Judge everything.
    let clock = std::time::Instant::now();
    let mut accuracy = accuracy_rows(&sizes, &bunny, &tiles, &cpu);
    let dir = criterion_dir();
    for row in accuracy.iter_mut().filter(|r| r.ray_set == "random") {
        let subject = Subject::all()
            .into_iter()
            .find(|s| s.name() == row.backend && s.precision().name() == row.precision)
            .expect("every row comes from a subject");
        row.ns_per_ray =
            mean_ns(&dir, GROUP, &id(subject), started).map(|ns| ns / TIMED_RAYS as f64);
    }
    eprintln!("accuracy rows: {:.1} s", clock.elapsed().as_secs_f64());
    let clock = std::time::Instant::now();
    let stability = stability_rows(&sizes, &bunny, &tiles);
    eprintln!("stability rows: {:.1} s", clock.elapsed().as_secs_f64());

    // 3. Write the CSVs, then the plot and the summary from them.
    let write = |name: &str, result: std::io::Result<()>| {
        let path = out_dir.join(name);
        result.unwrap_or_else(|e| panic!("writing {}: {e}", path.display()));
        println!("wrote {}", path.display());
    };
    write("accuracy.csv", write_csv(&out_dir.join("accuracy.csv"), &accuracy));
    write("stability.csv", write_csv(&out_dir.join("stability.csv"), &stability));
    let title = format!("Run time against error, every back end and precision ({cpu})");
    let svg = out_dir.join("runtime_vs_error.svg");
    draw_runtime_vs_error(&svg, &accuracy, &title)
        .unwrap_or_else(|e| panic!("drawing {}: {e}", svg.display()));
    println!("wrote {}", svg.display());
    if quick {
        // The smoke run's summary reads the real throughput figures if there are any.
        copy_if_present(&results_dir().join("throughput.csv"), &out_dir.join("throughput.csv"));
    }
    write_summary(&out_dir).unwrap_or_else(|e| panic!("writing the summary: {e}"));
    println!("wrote {}", out_dir.join("SUMMARY.md").display());
    let failing = accuracy.iter().filter(|r| r.meets_limits == Some(false)).count()
        + stability.iter().filter(|r| r.meets_limits == Some(false)).count();
    println!("{failing} rows miss their hard limits (see SUMMARY.md)");
}

fn copy_if_present(from: &Path, to: &Path) {
    if from.exists() {
        let _ = std::fs::copy(from, to);
    } else {
        let _ = std::fs::remove_file(to);
    }
}
