//! The CSV rows of `results/throughput.csv`, `results/kernels.csv` and `results/build.csv`.

use backends::Backend;
use serde::Serialize;

/// One row of `results/throughput.csv`: one back end, precision, scene, ray set and thread
/// count.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ThroughputRow {
    /// The back end's name (`la`, `ga`, ...).
    pub backend: String,
    /// `f32` or `f64`.
    pub precision: String,
    /// The scene (`bunny`, `bunny-sub2`, `torus`, ...).
    pub scene: String,
    /// Triangles in the scene.
    pub triangles: usize,
    /// `primary_closest`, `primary_any` or `incoherent_closest`.
    pub ray_set: String,
    /// Threads tracing.
    pub threads: usize,
    /// Rays in the set.
    pub rays: usize,
    /// Rays that hit something (the same for every back end, up to rounding at edges).
    pub hits: u64,
    /// Millions of rays per second.
    pub mrays_per_s: f64,
    /// Nanoseconds per ray (wall time divided by rays, all threads together).
    pub ns_per_ray: f64,
    /// This back end's time over the `la` back end's, same precision, scene, rays and threads.
    pub ratio_to_la: Option<f64>,
    /// Time to compute the boxes and build the BVH (one build, single thread unless the build
    /// is parallel).
    pub build_ms: f64,
    /// Time to prepare the per-triangle data of this back end.
    pub prepare_ms: f64,
    /// BVH nodes, slot map and per-triangle data, per triangle.
    pub bytes_per_triangle: f64,
    /// Of which BVH nodes and slot map.
    pub bvh_bytes_per_triangle: f64,
    /// Of which the back end's per-triangle data.
    pub prim_bytes_per_triangle: f64,
    /// The CPU.
    pub cpu: String,
}

/// Fills [`ThroughputRow::ratio_to_la`] from the `la` row of the same precision, scene, ray set
/// and threads (left empty where there is none).
pub fn fill_ratios_to_la(rows: &mut [ThroughputRow]) {
    let la: Vec<ThroughputRow> =
        rows.iter().filter(|r| r.backend == Backend::BASELINE.name()).cloned().collect();
    for row in rows.iter_mut() {
        row.ratio_to_la = la
            .iter()
            .find(|l| {
                l.precision == row.precision
                    && l.scene == row.scene
                    && l.ray_set == row.ray_set
                    && l.threads == row.threads
            })
            .map(|l| row.ns_per_ray / l.ns_per_ray);
    }
}

/// One row of `results/kernels.csv`: one kernel alone on one case.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct KernelRow {
    /// The back end's name.
    pub backend: String,
    /// `f32` or `f64`.
    pub precision: String,
    /// `hit`, `miss` or `mixed` (half and half, in random order).
    pub case: String,
    /// Nanoseconds per ray-triangle test (`Intersector::intersect`), throughput.
    pub ns_per_test: f64,
    /// This kernel's time over the `la` kernel's, same precision and case.
    pub ratio_to_la: Option<f64>,
    /// Bytes of per-triangle data.
    pub prim_bytes: usize,
    /// The CPU.
    pub cpu: String,
}

/// Fills [`KernelRow::ratio_to_la`] from the `la` row of the same precision and case.
pub fn fill_kernel_ratios_to_la(rows: &mut [KernelRow]) {
    let la: Vec<KernelRow> =
        rows.iter().filter(|r| r.backend == Backend::BASELINE.name()).cloned().collect();
    for row in rows.iter_mut() {
        row.ratio_to_la = la
            .iter()
            .find(|l| l.precision == row.precision && l.case == row.case)
            .map(|l| row.ns_per_test / l.ns_per_test);
    }
}

/// One row of `results/build.csv`: one BVH build.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct BuildRow {
    /// The scene.
    pub scene: String,
    /// Triangles in the scene.
    pub triangles: usize,
    /// The precision of the boxes the build starts from.
    pub precision: String,
    /// Threads available to the build.
    pub threads: usize,
    /// Milliseconds for the triangle boxes and the BVH (criterion's mean).
    pub build_ms: f64,
    /// The target for single-threaded builds, where there is one.
    pub target_ms: Option<f64>,
    /// Whether the target is met.
    pub meets_target: Option<bool>,
    /// BVH bytes per triangle (nodes and slot map).
    pub bvh_bytes_per_triangle: f64,
    /// The CPU.
    pub cpu: String,
}
