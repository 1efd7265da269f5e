//! `raycast INPUT.obj RAYS.npy HITS.npy [options]`: traces an array of rays through a mesh.
//!
//! See `--help` for the array formats.

use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::{Duration, Instant};

use anyhow::{Context as _, bail};
use backends::{Backend, Job, Precision, dispatch};
use clap::Parser;
use intersect::{Intersector, Ray, Real};
use rayon::prelude::*;
use raytrace::Stats;
use render::accel::Accel;
use render::output::{AtomicFile, npy};
use render::scene::Mesh;

/// Trace your own rays through a triangle mesh (Wavefront OBJ).
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
#[command(version, about, long_about)]
struct Cli {
    /// The mesh (.obj).
    input: PathBuf,
    /// The rays: .npy, float32 or float64, shape (N, 6).
    rays: PathBuf,
    /// Where to write the hits: .npy, float64, shape (N, 4), or (N, 1) with --any-hit.
    hits: PathBuf,
    /// Ray-triangle back end.
    #[arg(long, value_enum, default_value_t = Backend::La)]
    backend: Backend,
    /// Precision of rays, triangles and kernel (float64 rays are rounded for f32).
    #[arg(long, value_enum, default_value_t = Precision::F32)]
    precision: Precision,
    /// Only ask whether each ray hits something (faster; HITS is (N, 1) of 1 or 0).
    #[arg(long)]
    any_hit: bool,
    /// Worker threads [default: one per core].
    #[arg(long, value_name = "N")]
    threads: Option<usize>,
    /// Print nothing but errors.
    #[arg(long, short)]
    quiet: bool,
    /// Also write the summary's figures to this JSON file.
    #[arg(long, value_name = "FILE.json")]
    stats: Option<PathBuf>,
}

fn main() -> ExitCode {
    raytrace::one_line_panics();
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => return raytrace::clap_exit(&e),
    };
    match run(&cli) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {}", raytrace::error_line(&e));
            ExitCode::FAILURE
        }
    }
}

fn run(cli: &Cli) -> anyhow::Result<()> {
    if !has_npy_extension(&cli.hits) {
        bail!("{}: the hits are written as NumPy arrays: use a .npy extension", cli.hits.display());
    }
    let hits_file = AtomicFile::create(&cli.hits)?;
    let stats_file = raytrace::create_stats_file(cli.stats.as_deref())?;
    let pool = raytrace::thread_pool(cli.threads)?;

    let bytes = render::input::read_file(&cli.rays)?;
    let rays = npy::read_f64_matrix(&bytes, 6).with_context(|| cli.rays.display().to_string())?;
    drop(bytes);

    let start = Instant::now();
    let mesh = Mesh::load(&cli.input)?;
    let load = start.elapsed();

    let job = CastJob { mesh: &mesh, rays: &rays.values, any_hit: cli.any_hit };
    let (name, hits, build, trace) = pool.install(|| dispatch(cli.backend, cli.precision, job));

    let columns = if cli.any_hit { 1 } else { 4 };
    hits_file.commit(|w| npy::write(w, &[rays.rows, columns], hits.iter().copied()))?;
    let threads = pool.current_num_threads();
    let n = rays.rows as u64;
    let stats = Stats::new(mesh.len(), n, load, build, trace, name, cli.precision, threads);
    if let Some(file) = stats_file {
        stats.write_json(file)?;
    }
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
}

impl Job for CastJob<'_> {
    /// The back end's name, the HITS values in row order, build time, trace time.
    type Output = (&'static str, Vec<f64>, Duration, Duration);

    fn run<I: Intersector + 'static>(self, intersector: I) -> Self::Output {
        let start = Instant::now();
        let accel = Accel::from_mesh(intersector, self.mesh);
        let build = start.elapsed();
        let start = Instant::now();
        let ray = |r: &[f64]| {
            let ray: Ray<I::Real> = Ray::new([r[0], r[1], r[2]], [r[3], r[4], r[5]]).cast();
            // Rounding to f32 can overflow a finite f64 to infinity: check after the cast.
            let finite = ray.origin.iter().chain(&ray.dir).all(|x| x.is_finite());
            (finite && ray.dir != [<I::Real as Real>::ZERO; 3]).then_some(ray)
        };
        let hits: Vec<f64> = if self.any_hit {
            let inf = <I::Real as Real>::INFINITY;
            self.rays
                .par_chunks_exact(6)
                .map(|r| ray(r).map_or(0.0, |ray| f64::from(u8::from(accel.any_hit(&ray, inf)))))
                .collect()
        } else {
            self.rays
                .par_chunks_exact(6)
                .flat_map_iter(|r| match ray(r).and_then(|ray| accel.closest_hit(&ray)) {
                    Some(h) => [h.t.to_f64(), f64::from(h.prim), h.u.to_f64(), h.v.to_f64()],
                    None => [f64::INFINITY, -1.0, f64::NAN, f64::NAN],
                })
                .collect()
        };
        (I::NAME, hits, build, start.elapsed())
    }
}
