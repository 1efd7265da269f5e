//! Cost of the exact reference per ray-triangle test: the filtered common case, the exact
//! fallback (rays exactly through an edge), and hits (exact t, u, v), with a plain f64
//! Moller-Trumbore loop as the yardstick.
//!
//! `cargo bench -p exact`; criterion reports time per batch and, with the throughput
//! set to the batch size, tests per second (ns per test = 1e9 / that). With
//! `WEDGE_BENCH_QUICK=1` (as CI runs it, like the benches in `benches/`) each benchmark runs
//! for a few milliseconds: a smoke test, not a measurement.

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use exact::{Exact, ExactTriangle};
use intersect::{Intersector, Ray, Triangle};
use rand::{Rng, SeedableRng};
use rand_pcg::Pcg64;
use std::hint::black_box;
use std::time::Duration;

const BATCH: usize = 1024;

fn point(rng: &mut Pcg64, scale: f64) -> [f64; 3] {
    core::array::from_fn(|_| rng.random_range(-scale..scale))
}

/// Random triangles in the unit cube and rays from a shell around it towards random points
/// of it: about a fifth hit, the rest miss, almost none near an edge.
fn random_pairs(rng: &mut Pcg64) -> Vec<(Triangle<f64>, Ray<f64>)> {
    (0..BATCH)
        .map(|_| {
            let tri = Triangle::new(point(rng, 1.0), point(rng, 1.0), point(rng, 1.0));
            let origin = point(rng, 4.0);
            let target = tri.point(rng.random_range(-0.2..0.8), rng.random_range(-0.2..0.6));
            let dir = core::array::from_fn(|k| target[k] - origin[k]);
            (tri, Ray::new(origin, dir))
        })
        .collect()
}

/// Rays through the exact midpoint of an edge (dyadic coordinates, so `target - origin` is
/// exact and the edge test is exactly zero): the filter cannot decide that edge.
fn edge_pairs(rng: &mut Pcg64) -> Vec<(Triangle<f64>, Ray<f64>)> {
    let dyadic = |rng: &mut Pcg64| f64::from(rng.random_range(-4096..4096)) / 1024.0;
    (0..BATCH)
        .map(|_| {
            let v: [[f64; 3]; 3] = core::array::from_fn(|_| core::array::from_fn(|_| dyadic(rng)));
            let tri = Triangle::new(v[0], v[1], v[2]);
            let target: [f64; 3] = core::array::from_fn(|k| 0.5 * (v[0][k] + v[1][k]));
            let origin: [f64; 3] = core::array::from_fn(|_| dyadic(rng) * 4.0);
            let dir = core::array::from_fn(|k| target[k] - origin[k]);
            (tri, Ray::new(origin, dir))
        })
        .collect()
}

/// Plain f64 Moller-Trumbore, the yardstick (no exactness, no tie rule).
fn moller_trumbore(tri: &Triangle<f64>, ray: &Ray<f64>) -> Option<f64> {
    let sub = |p: [f64; 3], q: [f64; 3]| [p[0] - q[0], p[1] - q[1], p[2] - q[2]];
    let cross = |p: [f64; 3], q: [f64; 3]| {
        [p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]]
    };
    let dot = |p: [f64; 3], q: [f64; 3]| p[0] * q[0] + p[1] * q[1] + p[2] * q[2];
    let (e1, e2) = (sub(tri.b, tri.a), sub(tri.c, tri.a));
    let p = cross(ray.dir, e2);
    let det = dot(e1, p);
    let inv = 1.0 / det;
    let s = sub(ray.origin, tri.a);
    let u = dot(s, p) * inv;
    let q = cross(s, e1);
    let v = dot(ray.dir, q) * inv;
    let t = dot(e2, q) * inv;
    (det != 0.0 && u >= 0.0 && v >= 0.0 && u + v <= 1.0 && t > 0.0).then_some(t)
}

fn prepared(pairs: &[(Triangle<f64>, Ray<f64>)]) -> Vec<(ExactTriangle, Ray<f64>)> {
    pairs.iter().map(|(tri, ray)| (Exact.prepare(tri), *ray)).collect()
}

fn bench(c: &mut Criterion) {
    let mut rng = Pcg64::seed_from_u64(7);
    let random = random_pairs(&mut rng);
    let edges = edge_pairs(&mut rng);
    let (random_prims, edge_prims) = (prepared(&random), prepared(&edges));
    let hits: Vec<_> = random_prims
        .iter()
        .filter(|(p, r)| Exact.occludes(p, r, &(), f64::INFINITY))
        .copied()
        .collect();

    let mut group = c.benchmark_group("exact");
    group.throughput(Throughput::Elements(BATCH as u64));
    group.bench_function("moller_trumbore_f64_random", |b| {
        b.iter(|| random.iter().filter(|(t, r)| moller_trumbore(t, r).is_some()).count());
    });
    group.bench_function("occludes_random", |b| {
        b.iter(|| random_prims.iter().filter(|(p, r)| Exact.occludes(p, r, &(), 1e30)).count());
    });
    group.bench_function("intersect_random", |b| {
        b.iter(|| {
            random_prims.iter().filter_map(|(p, r)| Exact.intersect(p, r, &(), 1e30)).count()
        });
    });
    group.bench_function("occludes_exact_edge", |b| {
        b.iter(|| edge_prims.iter().filter(|(p, r)| Exact.occludes(p, r, &(), 1e30)).count());
    });
    group.finish();

    let mut group = c.benchmark_group("exact_hits");
    group.throughput(Throughput::Elements(hits.len() as u64));
    group.bench_function("occludes_hits", |b| {
        b.iter(|| hits.iter().filter(|(p, r)| Exact.occludes(p, r, &(), 1e30)).count());
    });
    group.bench_function("intersect_hits", |b| {
        b.iter(|| hits.iter().filter_map(|(p, r)| Exact.intersect(p, r, &(), 1e30)).count());
    });
    group.finish();
    black_box(());
}

/// Criterion's defaults, or a few milliseconds per benchmark with `WEDGE_BENCH_QUICK=1`.
fn config() -> Criterion {
    let quick = std::env::var("WEDGE_BENCH_QUICK").is_ok_and(|v| v == "1");
    if quick {
        Criterion::default()
            .sample_size(10)
            .warm_up_time(Duration::from_millis(10))
            .measurement_time(Duration::from_millis(20))
    } else {
        Criterion::default()
    }
}

criterion_group! {
    name = benches;
    config = config();
    targets = bench
}
criterion_main!(benches);
