//! `raycast MESH RAYS.npy HITS.npy [options]`: traces an array of rays through a mesh.
//!
//! See `--help` for the array formats.

use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::{Duration, Instant, SystemTime};

use anyhow::Context as _;
use backends::{Backend, Job, Precision, dispatch};
use bvh::accel::Accel;
use clap::Parser;
use intersect::{Intersector, Real};
use raytrace::args::{parse_threads, resolve_threads};
use raytrace::progress::Progress;
use raytrace::record::{OutputRecord, Record};
use raytrace::{Named, Stats, Timings, UsageError};
use render::cast::{self, Columns};
use render::output::{AtomicFile, npy};
use scene::Mesh;

/// Trace your own rays through a triangle mesh (OBJ, PLY, STL, glTF/GLB; .obj.gz, .ply.gz).
///
/// RAYS is a NumPy .npy array of float32 or float64 (little-endian, C order) with shape
/// (N, 6): origin x, y, z, direction x, y, z; or (N, 8), adding t_min and t_max: only hits
/// with t_min <= t <= t_max count (a segment, e.g. a shadow ray). Directions need not be unit
/// length; t is measured in units of the direction, and a hit always has t > 0.
///
/// HITS is written as float64 with shape (N, 4): t, triangle index, u, v (the hit point is
/// (1 - u - v) a + u b + v c of the triangle's vertices a, b, c). A miss is
/// (+inf, -1, NaN, NaN). --with point,normal adds the hit point's x, y, z and the triangle's
/// unit normal (b - a) x (c - a), normalised (NaN on a miss), in that order. With --any-hit,
/// HITS has shape (N, 1): 1 where the ray hits any triangle, 0 where it misses; --with prim
/// adds the index of a triangle it hits (the first found, not the nearest; -1 on a miss). A
/// ray with a NaN or infinite origin or direction component, a zero direction, or a NaN
/// t_min or t_max, is a miss. Triangle indices count the file's faces in order, each n-gon
/// fanned into n - 2 triangles from its first vertex.
#[derive(Parser, Debug)]
#[command(name = "raycast", version)]
struct Cli {
    /// The mesh: .obj, .ply, .stl, .gltf, .glb, .obj.gz or .ply.gz.
    input: PathBuf,
    /// The rays: .npy, float32 or float64, shape (N, 6), or (N, 8) with t_min, t_max.
    rays: PathBuf,
    /// Where to write the hits: .npy, float64, shape (N, 4), or (N, 1) with --any-hit, plus
    /// the --with columns (replaced if it exists; never the rays or the mesh).
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
    /// Extra columns of HITS, written in the order listed here whatever the order given:
    /// point, normal (closest hit); prim (--any-hit).
    #[arg(long, value_enum, value_delimiter = ',', value_name = "COLUMN,...")]
    with: Vec<Extra>,
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

/// An optional column group of HITS.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, clap::ValueEnum)]
enum Extra {
    /// The hit point x, y, z (from the triangle's vertices in f64 and the hit's u, v).
    Point,
    /// The triangle's unit geometric normal x, y, z, in its winding.
    Normal,
    /// With --any-hit: the index of a triangle hit.
    Prim,
}

/// The columns `cli` asks for, or a usage error for an extra that does not go with the query.
fn columns(cli: &Cli) -> Result<Columns, UsageError> {
    let has = |e| cli.with.contains(&e);
    let c = Columns {
        any_hit: cli.any_hit,
        point: has(Extra::Point),
        normal: has(Extra::Normal),
        prim: has(Extra::Prim),
    };
    if c.any_hit && (c.point || c.normal) {
        return Err(UsageError(
            "--with point and normal need a closest hit: not with --any-hit".into(),
        ));
    }
    if !c.any_hit && c.prim {
        return Err(UsageError(
            "--with prim is for --any-hit (the closest hit always has its triangle)".into(),
        ));
    }
    Ok(c)
}

fn main() -> ExitCode {
    let start = (Instant::now(), SystemTime::now());
    raytrace::one_line_panics();
    match Cli::try_parse() {
        Ok(cli) => raytrace::exit(run(&cli, start)),
        Err(e) => raytrace::clap_exit(&e),
    }
}

fn run(cli: &Cli, (start, started): (Instant, SystemTime)) -> anyhow::Result<()> {
    if !has_npy_extension(&cli.hits) {
        let hits = cli.hits.display();
        let e = format!("{hits}: the hits are written as NumPy arrays: use a .npy extension");
        return Err(UsageError(e).into());
    }
    let columns = columns(cli)?;
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
    let rays =
        npy::read_f64_matrix_of(&bytes, &[6, 8]).with_context(|| cli.rays.display().to_string())?;
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
        stride: rays.columns,
        columns,
        progress: &progress,
        samples: &samples,
    };
    let (name, hits, build, trace, sample_t) =
        pool.install(|| dispatch(cli.backend, cli.precision, job));

    progress.phase(format!("writing {}", cli.hits.display()));
    let t = Instant::now();
    let shape = [rays.rows, columns.count()];
    let hits = hits_file.write(|w| npy::write(w, &shape, hits.iter().copied()))?;
    let write = t.elapsed();
    let time = Timings { load, build, trace, write, wall: start.elapsed() };
    let n = rays.rows as u64;
    let mut stats = Stats::new(mesh.len(), n, time, name, cli.precision, threads);
    let mut written = vec![hits];
    if let Some(file) = stats_file {
        let output = OutputRecord {
            path: cli.hits.display().to_string(),
            shape: Some(shape),
            ..OutputRecord::default()
        };
        let inputs = [("mesh", cli.input.as_path()), ("rays", cli.rays.as_path())];
        stats.record = Some(Record::new("raycast", started, &inputs, output)?);
        written.push(stats.write_json(file)?);
    }
    if cli.see.wanted() {
        progress.phase("writing the viewer and scene");
        // Unit directions and distances along them (raycast's t is in units of the direction).
        let traced = samples.iter().zip(&sample_t).filter_map(|(&k, &t)| {
            let r = &rays.values[rays.columns * k..rays.columns * k + 6];
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
    /// `stride` values per ray: origin, direction, and t_min, t_max when `stride` is 8.
    rays: &'a [f64],
    stride: usize,
    columns: Columns,
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
        let (stride, columns) = (self.stride, self.columns);
        let n = self.rays.len() / stride;
        self.progress.trace(n as u64);
        let start = Instant::now();
        let mut hits = vec![0.0; n * columns.count()];
        let inc = |rays: usize| self.progress.inc(rays as u64);
        cast::trace_rays(&accel, self.mesh, self.rays, stride, columns, &mut hits, &inc);
        let trace = start.elapsed();
        let t = self
            .samples
            .iter()
            .map(|&k| {
                cast::kernel_ray::<I::Real>(&self.rays[stride * k..stride * (k + 1)], stride)
                    .and_then(|(ray, t_min, t_max)| accel.closest_hit_between(&ray, t_min, t_max))
                    .map(|hit| hit.t.to_f64())
            })
            .collect();
        (I::NAME, hits, build, trace, t)
    }
}
