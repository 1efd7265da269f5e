//! `raycast MESH RAYS.npy HITS.npy [options]`: traces an array of rays through a mesh.
//!
//! See `--help` for the array formats.

use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::{Duration, Instant};

use anyhow::Context as _;
use backends::{Backend, Job, Precision, dispatch};
use bvh::accel::Accel;
use clap::Parser;
use intersect::{Intersector, Ray, Real};
use rayon::prelude::*;
use raytrace::args::{parse_threads, resolve_threads};
use raytrace::progress::Progress;
use raytrace::{Named, Stats, Timings, UsageError};
use render::output::{AtomicFile, npy};
use scene::Mesh;

/// Rays traced between two updates of the progress bar.
const RAYS_PER_BLOCK: usize = 4096;

/// Trace your own rays through a triangle mesh (OBJ, PLY, STL, glTF/GLB; .obj.gz, .ply.gz).
///
/// RAYS is a NumPy .npy array of float32 or float64 (little-endian, C order) with shape
/// (N, 6): origin x, y, z, direction x, y, z. Directions need not be unit length; t is
/// measured in units of the direction.
///
/// HITS is written as float64 with shape (N, 4): t, triangle index, u, v (the hit point is
/// (1 - u - v) a + u b + v c of the triangle's vertices a, b, c). A miss is
/// (+inf, -1, NaN, NaN). With --any-hit, HITS has shape (N, 1): 1 where the ray hits any
/// triangle at t > 0, 0 where it misses. A ray with a NaN or infinite component, or a zero
/// direction, is a miss. Triangle indices count the file's faces in order, each n-gon fanned
/// into n - 2 triangles from its first vertex.
#[derive(Parser, Debug)]
#[command(name = "raycast", version)]
struct Cli {
    /// The mesh: .obj, .ply, .stl, .gltf, .glb, .obj.gz or .ply.gz.
    input: PathBuf,
    /// The rays: .npy, float32 or float64, shape (N, 6).
    rays: PathBuf,
    /// Where to write the hits: .npy, float64, shape (N, 4), or (N, 1) with --any-hit
    /// (replaced if it exists; never the rays or the mesh).
    hits: PathBuf,
    /// Ray-triangle back end.
    #[arg(long, value_enum, default_value_t = Backend::LaWatertight)]
    backend: Backend,
    /// Precision of rays, triangles and kernel (float64 rays are rounded for f32).
    #[arg(long, value_enum, default_value_t = Precision::F32)]
    precision: Precision,
    /// Only ask whether each ray hits something (faster; HITS is (N, 1) of 1 or 0).
    #[arg(long)]
    any_hit: bool,
    /// Worker threads, at most 4 per core; 0 is one per core [default: one per core].
    #[arg(long, value_name = "N", value_parser = parse_threads, allow_negative_numbers = true)]
    threads: Option<usize>,
    /// Print nothing but errors (no progress, no summary).
    #[arg(long, short)]
    quiet: bool,
    /// Also write the summary's figures to this JSON file (replaces only an earlier one).
    #[arg(long, value_name = "FILE.json")]
    stats: Option<PathBuf>,
    #[command(flatten)]
    see: raytrace::see::SeeArgs,
}

fn main() -> ExitCode {
    let start = Instant::now();
    raytrace::one_line_panics();
    match Cli::try_parse() {
        Ok(cli) => raytrace::exit(run(&cli, start)),
        Err(e) => raytrace::clap_exit(&e),
    }
}

fn run(cli: &Cli, start: Instant) -> anyhow::Result<()> {
    if !has_npy_extension(&cli.hits) {
        let hits = cli.hits.display();
        let e = format!("{hits}: the hits are written as NumPy arrays: use a .npy extension");
        return Err(UsageError(e).into());
    }
    let stats_path = cli.stats.as_deref();
    let inputs =
        [Named { role: "mesh", path: &cli.input }, Named { role: "rays", path: &cli.rays }];
    let mut outputs = vec![Named { role: "hits", path: &cli.hits }];
    outputs.extend(stats_path.map(|path| Named { role: "stats", path }));
    cli.see.outputs(&mut outputs)?;
    raytrace::start_run(&inputs, &outputs, stats_path)?;
    let hits_file = AtomicFile::create(&cli.hits)?;
    let stats_file = raytrace::create_stats_file(stats_path)?;
    let see_files = cli.see.create()?;
    let threads = resolve_threads(cli.threads);
    let pool = raytrace::thread_pool(threads)?;

    let progress = Progress::new(cli.quiet);
    progress.phase(format!("reading {}", cli.rays.display()));
    let bytes = scene::input::read_file(&cli.rays)?;
    let rays = npy::read_f64_matrix(&bytes, 6).with_context(|| cli.rays.display().to_string())?;
    drop(bytes);

    progress.phase(format!("loading {}", cli.input.display()));
    let t = Instant::now();
    let mesh = raytrace::load_mesh(&cli.input, cli.precision)?;
    let load = t.elapsed();

    let samples = if cli.see.wanted() {
        view::sample_indices(rays.rows, cli.see.view_rays)
    } else {
        Vec::new()
    };
    let job = CastJob {
        mesh: &mesh,
        rays: &rays.values,
        any_hit: cli.any_hit,
        progress: &progress,
        samples: &samples,
    };
    let (name, hits, build, trace, sample_t) =
        pool.install(|| dispatch(cli.backend, cli.precision, job));

    progress.phase(format!("writing {}", cli.hits.display()));
    let t = Instant::now();
    let columns = if cli.any_hit { 1 } else { 4 };
    let hits = hits_file.write(|w| npy::write(w, &[rays.rows, columns], hits.iter().copied()))?;
    let write = t.elapsed();
    let time = Timings { load, build, trace, write, wall: start.elapsed() };
    let n = rays.rows as u64;
    let stats = Stats::new(mesh.len(), n, time, name, cli.precision, threads);
    let mut written = vec![hits];
    if let Some(file) = stats_file {
        written.push(stats.write_json(file)?);
    }
    if cli.see.wanted() {
        progress.phase("writing the viewer and scene");
        // Unit directions and distances along them (raycast's t is in units of the direction).
        let traced = samples.iter().zip(&sample_t).filter_map(|(&k, &t)| {
            let r = &rays.values[6 * k..6 * k + 6];
            let len = (r[3] * r[3] + r[4] * r[4] + r[5] * r[5]).sqrt();
            let finite = r.iter().all(|x| x.is_finite()) && len > 0.0 && len.is_finite();
            let dir = [r[3] / len, r[4] / len, r[5] / len];
            finite.then_some(([r[0], r[1], r[2]], dir, t.map(|t| t * len)))
        });
        let run = view::Run {
            mesh: &mesh,
            camera: None,
            layers: view::hit_and_miss_layers(&mesh, traced),
            figures: raytrace::see::figures(&stats, &[]),
        };
        written.extend(see_files.write(&run)?);
    }
    render::output::commit_all(written)?;
    progress.finish();
    if !cli.quiet {
        println!("{}: {} -> {}", cli.input.display(), stats.summary(), cli.hits.display());
    }
    Ok(())
}

fn has_npy_extension(path: &Path) -> bool {
    path.extension().and_then(|e| e.to_str()).is_some_and(|e| e.eq_ignore_ascii_case("npy"))
}

/// Builds the acceleration structure and traces the rays with one back end.
struct CastJob<'a> {
    mesh: &'a Mesh,
    /// Six values per ray.
    rays: &'a [f64],
    any_hit: bool,
    progress: &'a Progress,
    /// Rays to show with `--view` and `--scene`, traced again for their nearest hit (with
    /// `--any-hit` the hits hold no distance).
    samples: &'a [usize],
}

impl Job for CastJob<'_> {
    /// The back end's name, the HITS values in row order, build time, trace time, the
    /// samples' hit distances.
    type Output = (&'static str, Vec<f64>, Duration, Duration, Vec<Option<f64>>);

    fn run<I: Intersector + 'static>(self, intersector: I) -> Self::Output {
        self.progress.phase("building the BVH");
        let start = Instant::now();
        let accel = Accel::build(intersector, &self.mesh.triangles());
        let build = start.elapsed();
        self.progress.trace((self.rays.len() / 6) as u64);
        let start = Instant::now();
        let ray = |r: &[f64]| {
            let ray: Ray<I::Real> = Ray::new([r[0], r[1], r[2]], [r[3], r[4], r[5]]).cast();
            // Rounding to f32 can overflow a finite f64 to infinity: check after the cast.
            let finite = ray.origin.iter().chain(&ray.dir).all(|x| x.is_finite());
            (finite && ray.dir != [<I::Real as Real>::ZERO; 3]).then_some(ray)
        };
        let columns = if self.any_hit { 1 } else { 4 };
        let mut hits = vec![0.0; self.rays.len() / 6 * columns];
        // In blocks, each writing its own rows of the hits, so that the bar can count them.
        let blocks = self.rays.par_chunks(6 * RAYS_PER_BLOCK);
        blocks.zip(hits.par_chunks_mut(columns * RAYS_PER_BLOCK)).for_each(|(rays, out)| {
            let rays = rays.chunks_exact(6);
            if self.any_hit {
                let inf = <I::Real as Real>::INFINITY;
                for (r, h) in rays.zip(out.iter_mut()) {
                    *h = ray(r).map_or(0.0, |ray| f64::from(u8::from(accel.any_hit(&ray, inf))));
                }
            } else {
                for (r, h) in rays.zip(out.chunks_exact_mut(4)) {
                    h.copy_from_slice(&match ray(r).and_then(|ray| accel.closest_hit(&ray)) {
                        Some(h) => [h.t.to_f64(), f64::from(h.prim), h.u.to_f64(), h.v.to_f64()],
                        None => [f64::INFINITY, -1.0, f64::NAN, f64::NAN],
                    });
                }
            }
            self.progress.inc((out.len() / columns) as u64);
        });
        let trace = start.elapsed();
        let t = self
            .samples
            .iter()
            .map(|&k| {
                ray(&self.rays[6 * k..6 * k + 6])
                    .and_then(|ray| accel.closest_hit(&ray))
                    .map(|hit| hit.t.to_f64())
            })
            .collect();
        (I::NAME, hits, build, trace, t)
    }
}
