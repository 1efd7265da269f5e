//! Each ray-triangle kernel alone: nanoseconds per `Intersector::intersect` call, for rays that
//! hit, rays that miss, and the two mixed in random order (which the branch predictor cannot
//! learn), `f32` and `f64`, every back end plus the exact reference (`f64` only).
//!
//! Inputs: `BATCH` random triangles (vertices within 0.3 of a random centre in the unit cube)
//! and one ray per triangle, from 1 to 3 units away, aimed at a point whose barycentric
//! weights are all at least 0.1 (hit) or one of which is at most -0.1 (miss: outside one edge,
//! chosen at random, in front of the origin). The per-triangle data (`prepare`) and per-ray
//! data (`prepare_ray`) are computed before timing, as the BVH traversal does: they are paid
//! once per triangle and once per ray, not per test. One iteration runs the kernel on every
//! pair; the figure is the mean time per iteration over `BATCH` (throughput, not latency).
//!
//! After the benchmarks, `main` writes `results/kernels.csv` (one row per back end, precision
//! and case, with the ratio to `la`). Run: `cargo bench -p wedge-benches --bench kernels`;
//! `WEDGE_BENCH_QUICK=1` for a smoke run (CSV under the criterion directory).

use std::hint::black_box;
use std::time::SystemTime;

use backends::{Backend, Job, Precision, dispatch};
use criterion::{Criterion, Throughput};
use exact::Exact;
use intersect::vec3::{cross, dot, sub};
use intersect::{Intersector, Ray, Real, Triangle};
use wedge_benches::clock::configured;
use wedge_benches::throughput::rows::{KernelRow, fill_kernel_ratios_to_la};
use wedge_benches::{
    SplitMix64, bench_times, criterion_dir, machine, mean_ns, output_path, write_csv,
};

/// Ray-triangle pairs per iteration: the largest per-triangle data (96 bytes) and rays fit in
/// L1 together.
const BATCH: usize = 256;

/// The cases, each a list of pairs in `f64`.
struct Cases {
    names: [&'static str; 3],
    pairs: [Vec<(Triangle<f64>, Ray<f64>)>; 3],
}

fn random_triangle(rng: &mut SplitMix64) -> Triangle<f64> {
    loop {
        let c: [f64; 3] = rng.array();
        let mut corner = || core::array::from_fn(|k| c[k] + 0.3 * rng.range(-1.0, 1.0));
        let t = Triangle::new(corner(), corner(), corner());
        // Not too thin: a sliver makes hit points near edges, which the cases avoid.
        let (e1, e2) = (sub(t.b, t.a), sub(t.c, t.a));
        let n = cross(e1, e2);
        if dot(n, n).sqrt() > 0.2 * dot(e1, e1).max(dot(e2, e2)) {
            return t;
        }
    }
}

/// A ray towards the point of `t` with barycentric weights `w` (summing to 1).
fn ray_towards(rng: &mut SplitMix64, t: &Triangle<f64>, w: [f64; 3]) -> Ray<f64> {
    let p: [f64; 3] = core::array::from_fn(|k| w[0] * t.a[k] + w[1] * t.b[k] + w[2] * t.c[k]);
    let d: [f64; 3] = rng.array();
    let len = dot(d, d).sqrt().max(1e-3);
    let dist = rng.range(1.0, 3.0);
    let origin = core::array::from_fn(|k| p[k] + dist * d[k] / len);
    Ray::new(origin, sub(p, origin))
}

fn hit_pair(rng: &mut SplitMix64) -> (Triangle<f64>, Ray<f64>) {
    let t = random_triangle(rng);
    // Weights >= 0.1 each: a uniform point of the inner triangle.
    let (mut u, mut v) = (rng.range(0.0, 1.0), rng.range(0.0, 1.0));
    if u + v > 1.0 {
        (u, v) = (1.0 - u, 1.0 - v);
    }
    let (b, c) = (0.1 + 0.7 * u, 0.1 + 0.7 * v);
    (t, ray_towards(rng, &t, [1.0 - b - c, b, c]))
}

fn miss_pair(rng: &mut SplitMix64) -> (Triangle<f64>, Ray<f64>) {
    let t = random_triangle(rng);
    let out = rng.range(-0.8, -0.1);
    let other = rng.range(0.0, 1.0 - out);
    let mut w = [out, other, 1.0 - out - other];
    // Which edge the point lies outside of.
    let k = (rng.next_u64() % 3) as usize;
    w.rotate_right(k);
    (t, ray_towards(rng, &t, w))
}

fn cases() -> Cases {
    let mut rng = SplitMix64::new(0x6b65_726e_656c);
    let hit: Vec<_> = (0..BATCH).map(|_| hit_pair(&mut rng)).collect();
    let miss: Vec<_> = (0..BATCH).map(|_| miss_pair(&mut rng)).collect();
    let mixed: Vec<_> = (0..BATCH)
        .map(|_| if rng.next_u64() & 1 == 0 { hit_pair(&mut rng) } else { miss_pair(&mut rng) })
        .collect();
    Cases { names: ["hit", "miss", "mixed"], pairs: [hit, miss, mixed] }
}

/// One benchmark that ran.
struct Measured {
    group: String,
    backend: String,
    precision: &'static str,
    case: &'static str,
    prim_bytes: usize,
}

struct BenchKernel<'a> {
    criterion: &'a mut Criterion,
    cases: &'a Cases,
    precision: &'static str,
}

impl Job for BenchKernel<'_> {
    type Output = Vec<Measured>;

    fn run<I: Intersector + 'static>(self, k: I) -> Vec<Measured> {
        let mut measured = Vec::new();
        for (case, pairs) in self.cases.names.into_iter().zip(&self.cases.pairs) {
            let prims: Vec<I::Prim> = pairs.iter().map(|(t, _)| k.prepare(&t.cast())).collect();
            let rays: Vec<Ray<I::Real>> = pairs.iter().map(|(_, r)| r.cast()).collect();
            let data: Vec<I::RayData> = rays.iter().map(|r| k.prepare_ray(r)).collect();
            let inf = <I::Real as Real>::INFINITY;
            let hits =
                (0..BATCH).filter(|&i| k.intersect(&prims[i], &rays[i], &data[i], inf).is_some());
            let hits = hits.count();
            let expected = match case {
                "hit" => Some(BATCH),
                "miss" => Some(0),
                _ => None,
            };
            if expected.is_some_and(|e| e != hits) {
                eprintln!(
                    "warning: {} {}: {hits} hits of {BATCH} in case {case}",
                    I::NAME,
                    self.precision
                );
            }
            let group = format!("kernel_{case}_{}", self.precision);
            let mut g = self.criterion.benchmark_group(&group);
            g.throughput(Throughput::Elements(BATCH as u64));
            g.bench_function(I::NAME, |b| {
                b.iter(|| {
                    let (prims, rays, data) = black_box((&prims, &rays, &data));
                    for i in 0..BATCH {
                        black_box(k.intersect(&prims[i], &rays[i], &data[i], inf));
                    }
                });
            });
            g.finish();
            measured.push(Measured {
                group,
                backend: I::NAME.to_owned(),
                precision: self.precision,
                case,
                prim_bytes: size_of::<I::Prim>(),
            });
        }
        measured
    }
}

fn main() {
    let started = SystemTime::now();
    let mut criterion = configured(Criterion::default(), bench_times()).configure_from_args();
    let cases = cases();
    let mut measured = Vec::new();
    for precision in Precision::ALL {
        for backend in Backend::ALL {
            let job = BenchKernel {
                criterion: &mut criterion,
                cases: &cases,
                precision: precision.name(),
            };
            measured.extend(dispatch(backend, precision, job));
        }
    }
    // The exact reference exists in f64 only.
    let job = BenchKernel { criterion: &mut criterion, cases: &cases, precision: "f64" };
    measured.extend(job.run(Exact));
    criterion.final_summary();

    let dir = criterion_dir();
    let cpu = machine();
    let benchmarks = measured.len();
    let mut rows: Vec<KernelRow> = measured
        .into_iter()
        .filter_map(|m| {
            let ns = mean_ns(&dir, &m.group, &m.backend, started)?;
            Some(KernelRow {
                backend: m.backend,
                precision: m.precision.to_owned(),
                case: m.case.to_owned(),
                ns_per_test: ns / BATCH as f64,
                ratio_to_la: None,
                prim_bytes: m.prim_bytes,
                cpu: cpu.clone(),
            })
        })
        .collect();
    if rows.is_empty() {
        return;
    }
    fill_kernel_ratios_to_la(&mut rows);
    // A benchmark filtered out of this run has no fresh estimate and no row.
    let path = output_path("kernels", "csv", rows.len() == benchmarks);
    write_csv(&path, &rows).unwrap_or_else(|e| panic!("writing {}: {e}", path.display()));
    println!(
        "\n{:<11} {:<4} {:<6} {:>9} {:>7} {:>6}",
        "backend", "prec", "case", "ns/test", "vs la", "bytes"
    );
    for r in &rows {
        let ratio = r.ratio_to_la.map_or_else(|| "-".to_owned(), |x| format!("{x:.3}"));
        println!(
            "{:<11} {:<4} {:<6} {:>9.3} {:>7} {:>6}",
            r.backend, r.precision, r.case, r.ns_per_test, ratio, r.prim_bytes
        );
    }
    println!("wrote {}", path.display());
}
