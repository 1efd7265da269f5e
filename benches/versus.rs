//! `la` f32 against the reference tracers, and its user-facing paths against its core loop, in
//! alternating processes (the machinery of the `interleaved` bench, `wedge_benches::alternate`):
//! issue 18's table. Writes `results/versus.csv`.
//!
//! **Meshes, views, rays.** The Stanford bunny (69,451 triangles) and the bunny split twice
//! (`bunny-sub2`, 1,111,216 triangles, made at run time as the throughput bench makes it). Per
//! mesh three views, 1024 x 1024 primary rays each (one per pixel, row by row), closest and any
//! hit, then 1M incoherent rays (closest hit, the throughput bench's):
//!
//! - `fill`: the throughput bench's camera (`Camera::auto`, from -z, 45 degrees) moved to
//!   [`FILL`] of its distance, so that the mesh fills the frame;
//! - `small`: the same camera moved back to [`SMALL`] times its distance: the mesh is small in
//!   the frame and most rays miss;
//! - `edge-on`: looking along the longest side of the mesh's bounding box from the `fill`
//!   distance, so that a flat mesh would be seen from its edge and many rays graze the surface
//!   (for the bunny: its side view).
//!
//! **Rows** (`path` in the CSV), all `la` f32 on one thread, but for the references:
//!
//! - `core`: the bench's trace loop (`throughput::trace::trace`): `Accel::closest_hit` or
//!   `Accel::any_hit` per ray on rays already rounded to `f32`, hits counted.
//! - `packet`: `Accel::closest_hits_packet` or `Accel::any_hits_packet` on the same rays,
//!   handed over once in 8 x 8 blocks of pixels (the order `render_frame` traces them in; put
//!   in that order before timing), every answer kept in a `Vec`. Primary rays only: on the
//!   incoherent rays a packet's bounds span the mesh, and packets run hundreds of times slower
//!   than single rays (`results/README.md`), which is why those keep the single-ray path.
//! - `api`: the library API as a caller uses it: the same queries, every hit kept in a `Vec`.
//! - `render`: `render::trace::render_frame`, the loop of `raytrace`, in `depth` mode (closest)
//!   or `alpha` mode (any) on a rayon pool of one thread, on the same camera and image size:
//!   the same rays, made a tile's row at a time and traced in 16 x 16 tiles. Primary rays only.
//! - `raycast`: the release binary `raycast --threads 1 --stats` on the same rays as `.npy`
//!   (`f64`, rounded to `f32` inside), its `mrays_per_s` (trace phase only: the load, build and
//!   write phases are left out). One trace per process, after the build; the best of
//!   [`REPEATS`] processes counts, as the best of [`REPEATS`] traces does in the rows measured
//!   in this bench's own processes (a maximum of three noisy figures against one would favour
//!   those by the noise alone; the cold start of each process stays in). Left out with a note
//!   when `target/release/raycast` is not built (`cargo build --release -p raytrace`).
//! - `tinybvh`: tinybvh 1.6.8 through the `tinybvh-rs` crate (a dev-dependency of this crate
//!   only), built as its documentation says for `BVH8_CPU`: `BVH::Build` (binned SAH), leaves
//!   split to at most 4 triangles, `MBVH<8>`, `BVH8_CPU`; `BVH8_CPU::Intersect` per ray
//!   (closest hit), its C++ compiled with `-march=native` by the crate's build script. Each of
//!   its rays is made from the same `f32` origin and direction inside the timed loop
//!   (`Ray::new`, which computes its reciprocal direction), as `core` prepares its rays inside
//!   its loop. **Any hit is not measured**: the crate exposes no occlusion query for
//!   `BVH8_CPU` (`IsOccluded` is not in its bindings), so the any-hit rows have no reference.
//! - `embree4`, `embree4-net`: Embree 4 through `embreex` (`benches/embree/trace.py`, one
//!   `rtcIntersect1`/`rtcOccluded1` per ray), **warm**: every set is cast once, untimed, before
//!   the timed traces (its first casts in a process run about 2x slower); `-net` takes off the
//!   binding's cost per ray, as in `interleaved`. Left out when `embreex` does not import.
//!
//! Every row is the median over [`ROUNDS`] rounds of the best of [`REPEATS`] traces in a fresh
//! process (the first warms the caches), with the order of the rows rotated from round to round.
//! `la_core_ratio` is `core`'s median Mrays/s over the row's: for a reference the issue's
//! `la`/tinybvh or `la`/Embree (target at least 1.1 on primary rays, 1.0 incoherent), for a
//! path of ours the core loop's speed over the path's (target at most 1.05). `hits` counts the
//! rays that hit (the views' coverage, and a check that the tracers see the same scene).
//!
//! Run: `cargo build --release -p raytrace && cargo bench -p wedge-benches --bench versus`
//! (about 15 minutes). With `WEDGE_BENCH_QUICK=1`: one round on the bunny and the bunny split
//! once, 64 x 64 primary and 4,096 incoherent rays, written to the criterion directory.
//!
//! **Selections** (`WEDGE_VERSUS_ROWS`), for the measurements of issue 18 that need only some
//! rows; each writes `results/versus-<set>.csv` (a list of rows instead of a set's name writes
//! `versus.partial.csv` in the criterion directory):
//!
//! - `packet`: `core`, `packet` and `tinybvh` (the packet path against single rays and the
//!   reference);
//! - `isa`: `core` and `core-avx2`, the core loop with the default node test (AVX-512 for
//!   `f32` where the CPU has it) and with the AVX2 baseline (`WEDGE_ISA=avx2` in the child, see
//!   `bvh::Isa`), and in `f64` with the default (AVX2) and with AVX-512 (`core-f64`,
//!   `core-f64-avx512`, `WEDGE_ISA=avx512`);
//! - `render`: `core` and `render` (the render path within 5% of the core loop);
//! - `threads`: one against two threads of `render_frame` (`render`, `render-2t`), of the
//!   array path (`array`, `array-2t`: the throughput bench's `trace_parallel`, 2048 rays per
//!   task, on a pool of one or two threads) and of `raycast` (`raycast`, `raycast-2t`).
//!
//! A row name ending in `-2t` runs on two threads, in `-f64` in `f64`, in `-avx2` or
//! `-avx512` with that node test (suffixes in that order). The table printed at the end adds,
//! per pair, the ratio of the two (`-2t` over one thread, the default node test over `-avx2`,
//! `-avx512` over the default). `WEDGE_VERSUS_SCENES=bunny` (or `bunny-sub2`) keeps one
//! mesh.

use std::fmt::Write as _;
use std::fs::File;
use std::hint::black_box;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};
use std::process::{Command, ExitCode};
use std::time::Instant;

use backends::{Backend, Job, Precision, dispatch};
use bvh::accel::Accel;
use intersect::vec3::sub;
use intersect::{Intersector, Ray, Real};
use render::camera::{Camera, DEFAULT_FOV_DEG};
use render::frame::{Frame, FrameData, Mode};
use render::trace::render_frame;
use scene::Mesh;
use serde::Serialize;
use wedge_benches::alternate::{
    EMBREE_SCRIPT, alternate, embree_available, embree_net, figures_of, python, summary,
    write_rays, write_triangles,
};
use wedge_benches::throughput::rays::{INCOHERENT_SEED, Query, camera_rays, incoherent_rays};
use wedge_benches::throughput::scenes::{bunny, subdivided};
use wedge_benches::throughput::trace::{trace, trace_parallel};
use wedge_benches::{criterion_dir, machine, quick_mode, results_dir, write_csv};

/// Rounds of a full run.
const ROUNDS: usize = 5;
/// Traces of each ray set per process; the best one counts.
const REPEATS: usize = 3;
/// Set in a child process: the path to measure (`core`, `packet`, `api`, `render`,
/// `tinybvh`).
const CHILD: &str = "WEDGE_VERSUS_CHILD";
/// The `fill` view's distance, as a fraction of `Camera::auto`'s.
const FILL: f64 = 0.7;
/// The `small` view's distance, as a multiple of `Camera::auto`'s.
const SMALL: f64 = 3.0;
/// The rows measured in processes of this bench (and their `-2t` and `-avx2` forms).
const IN_PROCESS: [&str; 6] = ["core", "packet", "api", "render", "tinybvh", "array"];
/// The rows of a full run, in order.
const FULL: [&str; 5] = ["core", "packet", "api", "render", "tinybvh"];
/// The selections of [`ROWS_ENV`]: a name, its rows.
const SETS: [(&str, &[&str]); 4] = [
    ("packet", &["core", "packet", "tinybvh"]),
    ("isa", &["core", "core-avx2", "core-f64", "core-f64-avx512"]),
    ("render", &["core", "render"]),
    ("threads", &["render", "render-2t", "array", "array-2t", "raycast", "raycast-2t"]),
];
/// Selects rows (see the module documentation).
const ROWS_ENV: &str = "WEDGE_VERSUS_ROWS";
/// Keeps one mesh.
const SCENES_ENV: &str = "WEDGE_VERSUS_SCENES";
/// Suffix of a row on two threads.
const TWO_THREADS: &str = "-2t";
/// Suffix of a row with the AVX2 node test (after every other suffix).
const AVX2: &str = "-avx2";
/// Suffix of a row with the AVX-512 node test for both precisions (after every other suffix).
const AVX512: &str = "-avx512";
/// Suffix of a row with `la` in `f64` (before `-avx2`).
const F64: &str = "-f64";
/// The row of the `raycast` binary.
const RAYCAST: &str = "raycast";
/// The Embree rows: as measured, and with the binding's cost taken off.
const EMBREE: [&str; 2] = ["embree4", "embree4-net"];

/// A camera placement.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum View {
    Fill,
    Small,
    EdgeOn,
}

impl View {
    const ALL: [View; 3] = [View::Fill, View::Small, View::EdgeOn];

    const fn name(self) -> &'static str {
        match self {
            View::Fill => "fill",
            View::Small => "small",
            View::EdgeOn => "edge-on",
        }
    }

    /// The camera of this view of `mesh` (square image).
    fn camera(self, mesh: &Mesh) -> Camera {
        let (center, radius) = mesh.bounding_sphere();
        let auto = Camera::auto(center, radius, DEFAULT_FOV_DEG, 1.0)
            .expect("a loaded mesh has finite bounds");
        let back = sub(auto.eye(), center);
        let at = |scale: f64, dir: [f64; 3], up: [f64; 3]| {
            let eye = core::array::from_fn(|k| center[k] + scale * dir[k]);
            Camera::look_at(eye, center, up, DEFAULT_FOV_DEG).expect("a valid camera")
        };
        match self {
            View::Fill => at(FILL, back, [0.0, 1.0, 0.0]),
            View::Small => at(SMALL, back, [0.0, 1.0, 0.0]),
            View::EdgeOn => {
                let b = mesh.bounds();
                let extent: [f64; 3] = core::array::from_fn(|k| b.max[k] - b.min[k]);
                let long = (0..3).max_by(|&i, &j| extent[i].total_cmp(&extent[j])).unwrap_or(0);
                let dist = back.iter().map(|x| x * x).sum::<f64>().sqrt();
                let mut dir = [0.0; 3];
                dir[long] = -dist;
                let up = if long == 1 { [0.0, 0.0, 1.0] } else { [0.0, 1.0, 0.0] };
                at(FILL, dir, up)
            }
        }
    }
}

/// One ray set of a mesh: a view's primary rays with a query, or the incoherent rays.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Series {
    view: Option<View>,
    query: Query,
}

impl Series {
    /// Per mesh, in the order of every child's figures.
    fn all() -> Vec<Series> {
        let primary = View::ALL.into_iter().flat_map(|v| {
            [Query::Closest, Query::Any].map(|query| Series { view: Some(v), query })
        });
        primary.chain([Series { view: None, query: Query::Closest }]).collect()
    }

    fn view_name(self) -> &'static str {
        self.view.map_or("random", View::name)
    }

    fn set_name(self) -> &'static str {
        match (self.view, self.query) {
            (Some(_), Query::Closest) => "primary_closest",
            (Some(_), Query::Any) => "primary_any",
            (None, _) => "incoherent_closest",
        }
    }

    /// The file stem of the rays (views' rays are shared by both queries).
    fn rays_stem(self, scene: &str) -> String {
        format!("{scene}-{}", self.view_name())
    }
}

/// Image side and incoherent ray count.
fn sizes() -> (u32, usize) {
    if quick_mode() { (64, 4096) } else { (1024, 1_000_000) }
}

/// The meshes, with their names in the CSV.
fn meshes() -> Vec<(&'static str, Mesh)> {
    let bunny = bunny();
    let only = std::env::var(SCENES_ENV).ok();
    let keep = |name: &str| only.as_deref().is_none_or(|o| o == name);
    let (big, splits) = if quick_mode() { ("bunny-sub1", 1) } else { ("bunny-sub2", 2) };
    let mut out = Vec::new();
    if keep(big) {
        out.push((big, subdivided(&bunny, splits)));
    }
    if keep("bunny") {
        out.insert(0, ("bunny", bunny));
    }
    out
}

/// The rays of `series` on `mesh`, in `f64`.
fn rays_of(mesh: &Mesh, series: Series) -> Vec<Ray<f64>> {
    let (side, incoherent) = sizes();
    match series.view {
        Some(view) => camera_rays(&view.camera(mesh), side, side),
        None => incoherent_rays(mesh, incoherent, INCOHERENT_SEED),
    }
}

/// Best Mrays/s of [`REPEATS`] runs of `f` over `n` rays, and what the last run returned.
fn best_of(n: usize, mut f: impl FnMut() -> u64) -> (f64, u64) {
    best_of_into(n, &mut 0, |hits| *hits = black_box(f()), |hits| *hits)
}

/// [`best_of`] for a path that fills `out`: only `run` is timed, and `count` reads the hits
/// from what it left (a pass over the buffer that is not the path's work, and serial, so it
/// would also understate what a second thread gains).
fn best_of_into<O: ?Sized>(
    n: usize,
    out: &mut O,
    mut run: impl FnMut(&mut O),
    count: impl Fn(&mut O) -> u64,
) -> (f64, u64) {
    let (mut best, mut hits) = (0.0_f64, 0);
    for _ in 0..REPEATS {
        let start = Instant::now();
        run(black_box(&mut *out));
        best = best.max(n as f64 / start.elapsed().as_secs_f64() / 1e6);
        hits = count(out);
    }
    (best, hits)
}

/// A child's work with `la`: one path on every series of one mesh; per series Mrays/s and hits
/// (NaN where the path does not apply).
struct LaPath<'a> {
    path: &'a str,
    mesh: &'a Mesh,
    /// The pool the child runs on (one or two threads), for the `array` path.
    pool: &'a rayon::ThreadPool,
}

impl Job for LaPath<'_> {
    type Output = Vec<(f64, f64)>;

    fn run<I: Intersector + 'static>(self, intersector: I) -> Self::Output {
        let accel = Accel::build(intersector, &self.mesh.triangles());
        let inf = <I::Real as Real>::INFINITY;
        let (side, _) = sizes();
        Series::all()
            .into_iter()
            .map(|series| {
                let rays: Vec<Ray<I::Real>> =
                    rays_of(self.mesh, series).iter().map(Ray::cast).collect();
                let n = rays.len();
                let (mrays, hits) = match (self.path, series.query) {
                    ("core", q) => best_of(n, || trace(&accel, black_box(&rays), q).hits),
                    ("array", q) => {
                        best_of(n, || trace_parallel(self.pool, &accel, black_box(&rays), q).hits)
                    }
                    ("packet", q) => match series.view {
                        Some(_) => packet(&accel, &in_blocks(&rays, side), q),
                        // Incoherent rays take the single-ray path (see the module docs).
                        None => (f64::NAN, 0),
                    },
                    ("api", Query::Closest) => best_of(n, || {
                        let hits: Vec<_> = rays.iter().map(|r| accel.closest_hit(r)).collect();
                        hits.iter().filter(|h| h.is_some()).count() as u64
                    }),
                    ("api", Query::Any) => best_of(n, || {
                        let hits: Vec<bool> = rays.iter().map(|r| accel.any_hit(r, inf)).collect();
                        hits.iter().filter(|&&h| h).count() as u64
                    }),
                    ("render", q) => match series.view {
                        None => (f64::NAN, 0),
                        Some(view) => render(&accel, self.mesh, &view.camera(self.mesh), side, q),
                    },
                    _ => unreachable!("checked by the caller"),
                };
                (mrays, if mrays.is_nan() { f64::NAN } else { hits as f64 })
            })
            .collect()
    }
}

/// The rays of a `side x side` frame, given row by row, in 8 x 8 blocks of pixels.
fn in_blocks<T: Copy>(rays: &[T], side: u32) -> Vec<T> {
    let side = side as usize;
    let mut out = Vec::with_capacity(rays.len());
    for bj in (0..side).step_by(8) {
        for bi in (0..side).step_by(8) {
            for j in bj..(bj + 8).min(side) {
                out.extend_from_slice(&rays[j * side + bi..j * side + (bi + 8).min(side)]);
            }
        }
    }
    out
}

/// The packet queries on `rays` with no limit, every answer kept: best Mrays/s and hits.
fn packet<I: Intersector>(accel: &Accel<I>, rays: &[Ray<I::Real>], query: Query) -> (f64, u64) {
    let inf = <I::Real as Real>::INFINITY;
    match query {
        Query::Closest => best_of_into(
            rays.len(),
            &mut vec![None; rays.len()][..],
            |out| accel.closest_hits_packet(black_box(rays), inf, out),
            |out| out.iter().filter(|h| h.is_some()).count() as u64,
        ),
        Query::Any => best_of_into(
            rays.len(),
            &mut vec![false; rays.len()][..],
            |out| accel.any_hits_packet(black_box(rays), inf, out),
            |out| out.iter().filter(|&&h| h).count() as u64,
        ),
    }
}

/// `render_frame` of a `side x side` frame in `depth` (closest) or `alpha` (any) mode, on the
/// current (one-thread) pool: best Mrays/s and pixels hit.
fn render<I: Intersector>(
    accel: &Accel<I>,
    mesh: &Mesh,
    camera: &Camera,
    side: u32,
    query: Query,
) -> (f64, u64) {
    let mode = match query {
        Query::Closest => Mode::Depth,
        Query::Any => Mode::Alpha,
    };
    let mut frame = Frame::new(mode, side, side).expect("a small frame");
    let n = side as usize * side as usize;
    best_of_into(
        n,
        &mut frame,
        |frame| render_frame(accel, mesh, camera, frame, &|_| {}),
        |frame| {
            let hits = match frame.data_mut() {
                FrameData::Depth(px) => px.iter().filter(|t| t.is_finite()).count(),
                FrameData::Alpha(px) => px.iter().filter(|&&a| a != 0).count(),
                _ => 0,
            };
            hits as u64
        },
    )
}

/// tinybvh's `BVH8_CPU` on every series of `mesh`: closest hit only (see the module docs).
fn tinybvh(mesh: &Mesh) -> Vec<(f64, f64)> {
    use tinybvh_rs::{Intersector as _, bvh, bvh8_cpu, mbvh};
    let positions: Vec<[f32; 4]> = mesh
        .triangles::<f32>()
        .iter()
        .flat_map(|t| t.vertices().map(|[x, y, z]| [x, y, z, 0.0]))
        .collect();
    let mut wald = bvh::BVH::new(positions.as_slice().into()).expect("whole triangles");
    wald.split_leaves(4);
    let wide = mbvh::BVH::new(&wald);
    let bvh8 = bvh8_cpu::BVH::new(&wide).expect("leaves of at most 4 triangles");
    Series::all()
        .into_iter()
        .map(|series| {
            if series.query == Query::Any {
                return (f64::NAN, f64::NAN);
            }
            // Each ray is made (`Ray::new`: its reciprocal direction, the empty hit) inside
            // the timed loop, as ours are prepared inside ours: the same input, origin and
            // direction, on both sides.
            let rays: Vec<Ray<f32>> = rays_of(mesh, series).iter().map(Ray::cast).collect();
            let (mut best, mut hits) = (0.0_f64, 0);
            for _ in 0..REPEATS {
                let start = Instant::now();
                let mut found = 0usize;
                for r in black_box(&rays) {
                    let mut ray = tinybvh_rs::Ray::new(r.origin, r.dir);
                    bvh8.intersect(&mut ray);
                    found += usize::from(ray.hit.t < tinybvh_rs::INFINITE);
                }
                best = best.max(rays.len() as f64 / start.elapsed().as_secs_f64() / 1e6);
                hits = black_box(found);
            }
            (best, hits as f64)
        })
        .collect()
}

/// A row's path, thread count and `WEDGE_ISA` (`bvh::ISA_ENV`) value: `render-2t` is
/// `("render", 2, None)`, `core-f64-avx2` is `("core", 1, Some("avx2"))` (and
/// [`precision_of`] F64).
fn parse_row(row: &str) -> (&str, usize, Option<&'static str>) {
    let (row, isa) = without_isa(row);
    let row = row.strip_suffix(F64).unwrap_or(row);
    let (row, threads) = row.strip_suffix(TWO_THREADS).map_or((row, 1), |r| (r, 2));
    (row, threads, isa)
}

/// `row` without its `-avx2` or `-avx512` suffix, and the `WEDGE_ISA` value it asks for.
fn without_isa(row: &str) -> (&str, Option<&'static str>) {
    if let Some(r) = row.strip_suffix(AVX2) {
        (r, Some("avx2"))
    } else if let Some(r) = row.strip_suffix(AVX512) {
        (r, Some("avx512"))
    } else {
        (row, None)
    }
}

/// The precision of a row: `f64` for a name with [`F64`] before any `-avx2` or `-avx512`.
fn precision_of(row: &str) -> Precision {
    if without_isa(row).0.ends_with(F64) { Precision::F64 } else { Precision::F32 }
}

/// Child mode: measures `row` on every mesh and prints every series' Mrays/s, then every
/// series' hits.
fn child(row: &str) -> Result<(), String> {
    let (path, threads, _) = parse_row(row);
    if !IN_PROCESS.contains(&path) || (path == "tinybvh" && row != path) {
        return Err(format!("unknown path {row}"));
    }
    let pool =
        rayon::ThreadPoolBuilder::new().num_threads(threads).build().map_err(|e| e.to_string())?;
    let mut figures = Vec::new();
    for (_, mesh) in meshes() {
        figures.extend(if path == "tinybvh" {
            tinybvh(&mesh)
        } else {
            pool.install(|| {
                let job = LaPath { path, mesh: &mesh, pool: &pool };
                dispatch(Backend::BASELINE, precision_of(row), job)
            })
        });
    }
    let (mrays, hits): (Vec<f64>, Vec<f64>) = figures.into_iter().unzip();
    let text: Vec<String> = mrays.iter().chain(&hits).map(f64::to_string).collect();
    println!("{}", text.join(" "));
    Ok(())
}

/// What the parent wrote for the processes it runs: per mesh its file for `raycast`, its `.tri`
/// for Embree, and per series the rays in both forms (`dir/<scene>-<view>.npy`, `.ray`).
struct Inputs {
    dir: PathBuf,
    scenes: Vec<(&'static str, usize, PathBuf)>,
}

/// Writes the [`Inputs`] into `dir` (the `raycast` and Embree files only when they are used).
fn write_inputs(dir: &Path, raycast: bool, embree: bool) -> std::io::Result<Inputs> {
    std::fs::create_dir_all(dir)?;
    let mut scenes = Vec::new();
    for (name, mesh) in meshes() {
        let obj = if name == "bunny" {
            wedge_benches::throughput::scenes::shared_meshes_dir().join("stanford-bunny.obj")
        } else {
            let path = dir.join(format!("{name}.obj"));
            if raycast {
                write_obj(&path, &mesh)?;
            }
            path
        };
        if embree {
            write_triangles(&dir.join(format!("{name}.tri")), &mesh)?;
        }
        for series in Series::all().into_iter().filter(|s| s.query == Query::Closest) {
            let rays = rays_of(&mesh, series);
            let stem = dir.join(series.rays_stem(name));
            if embree {
                write_rays(&stem.with_extension("ray"), &rays)?;
            }
            if raycast {
                let mut out = BufWriter::new(File::create(stem.with_extension("npy"))?);
                let values = rays.iter().flat_map(|r| r.origin.into_iter().chain(r.dir));
                render::output::npy::write(&mut out, &[rays.len(), 6], values)?;
                out.flush()?;
            }
        }
        scenes.push((name, mesh.len(), obj));
    }
    Ok(Inputs { dir: dir.to_path_buf(), scenes })
}

/// `mesh` as OBJ text (vertices, then faces in mesh order), for `raycast`.
fn write_obj(path: &Path, mesh: &Mesh) -> std::io::Result<()> {
    let mut out = BufWriter::new(File::create(path)?);
    let mut line = String::new();
    for p in &mesh.positions {
        line.clear();
        // Shortest round-trip formatting: the file holds the very same `f64` positions.
        let _ = writeln!(line, "v {} {} {}", p[0], p[1], p[2]);
        out.write_all(line.as_bytes())?;
    }
    for t in &mesh.triangles {
        line.clear();
        let _ = writeln!(line, "f {} {} {}", t[0] + 1, t[1] + 1, t[2] + 1);
        out.write_all(line.as_bytes())?;
    }
    out.flush()
}

/// The `raycast` binary beside this bench's (`target/release/raycast` in the bench profile), if
/// it is built.
fn raycast_binary() -> Option<PathBuf> {
    let exe = std::env::current_exe().ok()?;
    let path = exe.parent()?.parent()?.join("raycast");
    path.is_file().then_some(path)
}

/// Runs `raycast` [`REPEATS`] times per series of every mesh: per series the best Mrays/s of
/// its trace phase, then NaN hits (it writes its hits, which are not counted here).
fn run_raycast(binary: &Path, inputs: &Inputs, threads: usize) -> Result<Vec<f64>, String> {
    let mut mrays = Vec::new();
    let stats = inputs.dir.join("raycast-stats.json");
    let hits = inputs.dir.join("raycast-hits.npy");
    for (name, _, obj) in &inputs.scenes {
        for series in Series::all() {
            let rays = inputs.dir.join(series.rays_stem(name)).with_extension("npy");
            let mut command = Command::new(binary);
            command.arg(obj).arg(&rays).arg(&hits).arg("--threads").arg(threads.to_string());
            command.args(["--quiet", "--stats"]);
            command.arg(&stats);
            if series.query == Query::Any {
                command.arg("--any-hit");
            }
            let mut best = 0.0_f64;
            for _ in 0..REPEATS {
                figures_of(RAYCAST, &mut command)?;
                let text =
                    std::fs::read_to_string(&stats).map_err(|e| format!("{RAYCAST}: {e}"))?;
                let json: serde_json::Value =
                    serde_json::from_str(&text).map_err(|e| format!("{RAYCAST}: {e}"))?;
                best = best.max(json["mrays_per_s"].as_f64().ok_or("raycast: no mrays_per_s")?);
            }
            mrays.push(best);
        }
    }
    let _ = std::fs::remove_file(&hits);
    let n = mrays.len();
    mrays.extend(std::iter::repeat_n(f64::NAN, n));
    Ok(mrays)
}

/// Runs the Embree script once per mesh: per series Mrays/s of every mesh, then per series the
/// binding's cost per ray (see [`embree_net`]).
fn run_embree(inputs: &Inputs) -> Result<Vec<f64>, String> {
    let (mut raw, mut cost) = (Vec::new(), Vec::new());
    for (name, _, _) in &inputs.scenes {
        let series = Series::all();
        let mut command = Command::new(python());
        command.arg(EMBREE_SCRIPT).arg(&inputs.dir).arg(format!("{name}.tri"));
        for s in &series {
            let query = if s.query == Query::Any { "any" } else { "closest" };
            command.arg(format!("{}:{query}", s.rays_stem(name)));
        }
        let got = figures_of(EMBREE[0], &mut command)?;
        let (r, c) = got.split_at(series.len());
        raw.extend_from_slice(r);
        cost.extend_from_slice(c);
    }
    raw.extend(cost);
    Ok(raw)
}

/// One row of `versus.csv`.
#[derive(Serialize)]
struct Row {
    path: String,
    scene: &'static str,
    triangles: usize,
    view: &'static str,
    ray_set: &'static str,
    rays: usize,
    hits: Option<u64>,
    rounds: usize,
    median_mrays_per_s: f64,
    min_mrays_per_s: f64,
    max_mrays_per_s: f64,
    /// `core`'s median Mrays/s over this row's.
    la_core_ratio: f64,
    cpu: String,
}

/// The rows [`ROWS_ENV`] selects (`None` for a full run) and the file stem of the results.
fn selection() -> Result<Option<(Vec<String>, String)>, String> {
    let Ok(value) = std::env::var(ROWS_ENV) else { return Ok(None) };
    if let Some((set, rows)) = SETS.iter().find(|(set, _)| *set == value) {
        return Ok(Some((rows.iter().map(|r| (*r).to_owned()).collect(), format!("versus-{set}"))));
    }
    let rows: Vec<String> = value.split(',').map(|r| r.trim().to_owned()).collect();
    for row in &rows {
        let (path, _, _) = parse_row(row);
        if !(IN_PROCESS.contains(&path) || path == RAYCAST || row == EMBREE[0]) {
            return Err(format!("{ROWS_ENV}: unknown row {row}"));
        }
    }
    Ok(Some((rows, "versus.partial".to_owned())))
}

/// This bench's binary as the child measuring `row`, with the AVX2 node test for a `-avx2` row.
fn run_row(row: &str) -> Result<Vec<f64>, String> {
    let exe = std::env::current_exe().map_err(|e| e.to_string())?;
    let mut command = Command::new(exe);
    command.env(CHILD, row);
    if let Some(isa) = parse_row(row).2 {
        command.env(bvh::ISA_ENV, isa);
    }
    figures_of(row, &mut command)
}

fn parent() -> Result<(), String> {
    let quick = quick_mode();
    let rounds = if quick { 1 } else { ROUNDS };
    let selected = selection()?;
    let mut names: Vec<String> = match &selected {
        Some((rows, _)) => rows.clone(),
        None => FULL.map(String::from).to_vec(),
    };
    let raycast = raycast_binary();
    match &raycast {
        Some(_) if selected.is_none() => names.push(RAYCAST.to_owned()),
        Some(_) => {}
        None => {
            eprintln!(
                "note: no raycast rows (target/release/raycast is not built: \
                 `cargo build --release -p raytrace`)"
            );
            names.retain(|n| parse_row(n).0 != RAYCAST);
        }
    }
    // tinybvh-rs 0.1.0-beta.3 calls a null function pointer (SIGSEGV) when this bench is built
    // in the test profile, as CI's smoke run builds it (`cargo bench --profile test`, which
    // reuses the test build); which of that profile's settings sets it off is not known. Debug
    // assertions tell that profile from the bench profile, where the row works.
    if cfg!(debug_assertions) && names.iter().any(|n| n == "tinybvh") {
        eprintln!("note: no tinybvh row (it crashes in a build with debug assertions)");
        names.retain(|n| n != "tinybvh");
    }
    if selected.is_none() {
        if embree_available() {
            names.push(EMBREE[0].to_owned());
        } else {
            eprintln!(
                "note: no Embree reference rows (`{} -c \"import embreex\"` failed)",
                python()
            );
        }
    }
    let embree = names.iter().any(|n| n == EMBREE[0]);
    let wants_raycast = names.iter().any(|n| parse_row(n).0 == RAYCAST);
    let dir = criterion_dir().join("versus-input");
    let inputs =
        write_inputs(&dir, wants_raycast, embree).map_err(|e| format!("{}: {e}", dir.display()))?;
    let mut figures = alternate(&names, rounds, |i| match parse_row(&names[i]) {
        (RAYCAST, threads, _) => {
            run_raycast(raycast.as_deref().expect("listed when built"), &inputs, threads)
        }
        _ if names[i] == EMBREE[0] => run_embree(&inputs),
        _ => run_row(&names[i]),
    })?;
    if embree {
        let (raw, net) = embree_net(&figures[names.len() - 1]);
        figures[names.len() - 1] = raw;
        figures.push(net);
        names.push(EMBREE[1].to_owned());
    }
    // Per row the series' Mrays/s over the rounds, and where known the hits (the same every
    // round: the first round's).
    let series = Series::all();
    let count = inputs.scenes.len() * series.len();
    let core: Vec<f64> = match names.iter().position(|n| n == "core") {
        Some(c) => {
            figures[c][..count].iter().map(|v| summary(v).map_or(f64::NAN, |s| s.0)).collect()
        }
        None => vec![f64::NAN; count],
    };
    let (side, incoherent) = sizes();
    let cpu = machine();
    let mut rows = Vec::new();
    for (i, name) in names.iter().enumerate() {
        for k in 0..count {
            let (scene, triangles, _) = inputs.scenes[k / series.len()];
            let s = series[k % series.len()];
            let Some((median, min, max)) = summary(&figures[i][k]) else { continue };
            let hits = figures[i].get(count + k).and_then(|v| v.first()).filter(|h| !h.is_nan());
            rows.push(Row {
                path: name.clone(),
                scene,
                triangles,
                view: s.view_name(),
                ray_set: s.set_name(),
                rays: if s.view.is_some() { side as usize * side as usize } else { incoherent },
                hits: hits.map(|&h| h as u64),
                rounds,
                median_mrays_per_s: median,
                min_mrays_per_s: min,
                max_mrays_per_s: max,
                la_core_ratio: core[k] / median,
                cpu: cpu.clone(),
            });
        }
    }
    check_hits(&rows)?;
    print_table(&names, &rows);
    print_pairs(&names, &rows);
    let out = match &selected {
        _ if quick => criterion_dir().join("versus.csv"),
        Some((_, stem)) if stem.ends_with(".partial") => {
            criterion_dir().join(format!("{stem}.csv"))
        }
        Some((_, stem)) => results_dir().join(format!("{stem}.csv")),
        None => results_dir().join("versus.csv"),
    };
    write_csv(&out, &rows).map_err(|e| format!("{}: {e}", out.display()))?;
    println!("wrote {}", out.display());
    Ok(())
}

/// Every row that counts its hits against `core`'s on the same rays: they must agree up to
/// rays through edges and vertices (at most one ray in a thousand), or the tracers did not see
/// the same scene and rays, and no ratio between them means anything.
fn check_hits(rows: &[Row]) -> Result<(), String> {
    for r in rows {
        let core = rows.iter().find(|c| {
            c.path == "core" && c.scene == r.scene && c.view == r.view && c.ray_set == r.ray_set
        });
        if let (Some(h), Some(c)) = (r.hits, core.and_then(|c| c.hits))
            && h.abs_diff(c) * 1000 > r.rays as u64
        {
            return Err(format!(
                "{} hits {h} of the {} rays of {} {} {}, core {c}",
                r.path, r.rays, r.scene, r.view, r.ray_set
            ));
        }
    }
    Ok(())
}

/// The median Mrays/s of row `path` on `r`'s mesh, view and ray set, if measured.
fn median_of(rows: &[Row], path: &str, r: &Row) -> Option<f64> {
    rows.iter()
        .find(|x| {
            x.path == path && x.scene == r.scene && x.view == r.view && x.ray_set == r.ray_set
        })
        .map(|x| x.median_mrays_per_s)
}

/// Prints the table in Markdown: per mesh, view and ray set, every row's median
/// Mrays/s, then `la`/tinybvh, `la`/Embree (warm, as measured) and each path over the core.
fn print_table(names: &[String], rows: &[Row]) {
    let figure = |path: &str, r: &Row| median_of(rows, path, r);
    let cell =
        |x: Option<f64>, digits: usize| x.map_or("-".to_owned(), |x| format!("{x:.digits$}"));
    let mut header = "| mesh | view | rays |".to_owned();
    for n in names {
        let _ = write!(header, " {n} |");
    }
    header.push_str(
        " la/tinybvh | la/Embree | core/packet | core/api | core/render | core/raycast |",
    );
    println!("{header}");
    println!("|{}", "---|".repeat(3 + names.len() + 6));
    // One line per series of the first row (`core` in a full run).
    let first = names.first().map_or("core", String::as_str);
    for r in rows.iter().filter(|r| r.path == first) {
        let mut line = format!("| {} | {} | {} |", r.scene, r.view, r.ray_set);
        for n in names {
            let _ = write!(line, " {} |", cell(figure(n, r), 2));
        }
        // Over the core loop, where it was measured.
        let core = figure("core", r);
        for other in ["tinybvh", EMBREE[0], "packet", "api", "render", RAYCAST] {
            let ratio = core.zip(figure(other, r)).map(|(c, x)| c / x);
            let _ = write!(line, " {} |", cell(ratio, 2));
        }
        println!("{line}");
    }
}

/// Prints, for each pair of rows that differ by a suffix (`X` and `X-2t`, `X` and `X-avx2`),
/// the ratio of their medians per mesh, view and ray set: the speed-up of two threads over
/// one, of the default node test over the AVX2 one, of AVX-512 over the default.
fn print_pairs(names: &[String], rows: &[Row]) {
    let median = |path: &str, r: &Row| median_of(rows, path, r);
    for name in names {
        for (suffix, what, two_over_one) in [
            (TWO_THREADS, "two threads over one", true),
            (AVX2, "the default node test over AVX2", false),
            (AVX512, "AVX-512 over the default node test", true),
        ] {
            let Some(base) = name.strip_suffix(suffix) else { continue };
            if !names.iter().any(|n| n == base) {
                continue;
            }
            println!(
                "\n{base} vs {name}: {what}\n\n| mesh | view | rays | ratio |\n|---|---|---|---|"
            );
            for r in rows.iter().filter(|r| r.path == *base) {
                if let Some(other) = median(name, r) {
                    let ratio = if two_over_one {
                        other / r.median_mrays_per_s
                    } else {
                        r.median_mrays_per_s / other
                    };
                    println!("| {} | {} | {} | {ratio:.3} |", r.scene, r.view, r.ray_set);
                }
            }
        }
    }
}

fn main() -> ExitCode {
    wedge_benches::child_or_parent(CHILD, child, parent)
}
