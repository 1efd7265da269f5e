//! BVH build time: triangle boxes and `bvh::Bvh::build` (what
//! `bvh::accel::AccelStats::bvh_build` measures), `f32` and `f64`, on the Stanford bunny
//! (69,451 triangles) and the bunny split twice (1,111,216), one thread and all threads.
//!
//! The targets, single thread: 30 ms for the bunny, 0.5 s for the 1.1M mesh.
//! After the benchmarks, `main` writes `results/build.csv`. Run:
//! `cargo bench -p wedge-benches --bench build`; `WEDGE_BENCH_QUICK=1` for a smoke run.

use std::hint::black_box;
use std::thread::available_parallelism;
use std::time::{Duration, SystemTime};

use bvh::{Aabb, Bvh};
use criterion::{Criterion, SamplingMode};
use intersect::{Real, Triangle};
use wedge_benches::clock::configured;
use wedge_benches::throughput::rows::BuildRow;
use wedge_benches::throughput::scenes::{BenchScene, bunny, subdivided};
use wedge_benches::{
    bench_times, criterion_dir, machine, mean_ns, output_path, quick_mode, write_csv,
};

/// What `Accel::build` times as the BVH build: the boxes, then the tree.
fn build<T: Real>(triangles: &[Triangle<T>]) -> Bvh<T> {
    let boxes: Vec<Aabb<T>> = triangles.iter().map(Aabb::of_triangle).collect();
    Bvh::build(&boxes)
}

struct Measured {
    group: String,
    function: String,
    row: BuildRow,
}

fn bench_scene<T: Real>(
    c: &mut Criterion,
    scene: &BenchScene,
    precision: &str,
    pools: &[rayon::ThreadPool],
    target_ms: Option<f64>,
) -> Vec<Measured> {
    let triangles: Vec<Triangle<T>> = scene.mesh.triangles();
    let group = format!("build_{}", scene.name);
    let mut g = c.benchmark_group(&group);
    g.sampling_mode(SamplingMode::Flat);
    if !quick_mode() {
        g.sample_size(10).measurement_time(Duration::from_secs(5));
    }
    let mut out = Vec::new();
    for pool in pools {
        let threads = pool.current_num_threads();
        let function = format!("{precision}_t{threads}");
        let bvh = pool.install(|| build(&triangles));
        g.bench_function(&function, |b| {
            b.iter(|| pool.install(|| black_box(build(black_box(&triangles)))));
        });
        out.push(Measured {
            group: group.clone(),
            function,
            row: BuildRow {
                scene: scene.name.clone(),
                triangles: triangles.len(),
                precision: precision.to_owned(),
                threads,
                build_ms: f64::NAN,
                target_ms: if threads == 1 { target_ms } else { None },
                meets_target: None,
                bvh_bytes_per_triangle: bvh.bytes() as f64 / triangles.len() as f64,
                cpu: String::new(),
            },
        });
    }
    g.finish();
    out
}

fn main() {
    let started = SystemTime::now();
    let mut criterion = configured(Criterion::default(), bench_times()).configure_from_args();
    let threads = available_parallelism().map_or(1, usize::from);
    let mut counts = vec![1];
    if threads > 1 {
        counts.push(threads);
    }
    let pools: Vec<rayon::ThreadPool> = counts
        .into_iter()
        .map(|n| rayon::ThreadPoolBuilder::new().num_threads(n).build().expect("a thread pool"))
        .collect();
    let small = bunny();
    let large = subdivided(&small, 2);
    let scenes = [
        (BenchScene { name: "bunny".into(), mesh: small }, 30.0),
        (BenchScene { name: "bunny-sub2".into(), mesh: large }, 500.0),
    ];
    let mut measured = Vec::new();
    for (scene, target) in &scenes {
        measured.extend(bench_scene::<f32>(&mut criterion, scene, "f32", &pools, Some(*target)));
        measured.extend(bench_scene::<f64>(&mut criterion, scene, "f64", &pools, Some(*target)));
    }
    criterion.final_summary();

    let dir = criterion_dir();
    let cpu = machine();
    let benchmarks = measured.len();
    let rows: Vec<BuildRow> = measured
        .into_iter()
        .filter_map(|m| {
            let ns = mean_ns(&dir, &m.group, &m.function, started)?;
            let mut row = m.row;
            row.build_ms = ns / 1e6;
            row.meets_target = row.target_ms.map(|t| row.build_ms <= t);
            row.cpu.clone_from(&cpu);
            Some(row)
        })
        .collect();
    if rows.is_empty() {
        return;
    }
    let path = output_path("build", "csv", rows.len() == benchmarks);
    write_csv(&path, &rows).unwrap_or_else(|e| panic!("writing {}: {e}", path.display()));
    println!(
        "\n{:<11} {:>9} {:<4} {:>3} {:>9} {:>7} {:>6}",
        "scene", "triangles", "prec", "thr", "build ms", "target", "B/tri"
    );
    for r in &rows {
        let target = r.target_ms.map_or_else(String::new, |t| {
            format!("{t}{}", if r.meets_target == Some(true) { " met" } else { " MISSED" })
        });
        println!(
            "{:<11} {:>9} {:<4} {:>3} {:>9.2} {:>7} {:>6.1}",
            r.scene,
            r.triangles,
            r.precision,
            r.threads,
            r.build_ms,
            target,
            r.bvh_bytes_per_triangle
        );
    }
    println!("wrote {}", path.display());
}
