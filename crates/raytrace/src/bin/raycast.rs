//! `raycast MESH RAYS.npy HITS.npy [options]`: traces an array of rays through a mesh.
//!
//! See `--help` for the array formats. The rays are read, traced and their hits written a
//! chunk at a time ([`render::cast::files`]), so arrays larger than memory trace in bounded
//! memory.

use std::path::PathBuf;
use std::process::ExitCode;
use std::time::{Duration, Instant, SystemTime};

use backends::{Backend, Job, Precision, dispatch};
use bvh::accel::Accel;
use clap::Parser;
use clap::builder::{PossibleValuesParser, TypedValueParser as _};
use intersect::{Intersector, Real};
use raytrace::args::{parse_threads, resolve_threads};
use raytrace::progress::Progress;
use raytrace::record::{OutputRecord, Record};
use raytrace::{Named, Stats, Timings, UsageError};
use render::cast::files::{HitsLayout, HitsWriter, RAYS_PER_CHUNK, RaysError, RaysFile};
use render::cast::{self, Columns};
use render::output::{AtomicFile, Written};
use scene::Mesh;

/// Trace your own rays through a triangle mesh (OBJ, PLY, STL, glTF/GLB; .obj.gz, .ply.gz).
///
/// RAYS is a NumPy .npy array of float32 or float64 (little-endian, C order) with shape
/// (N, 6): origin x, y, z, direction x, y, z; or (N, 8), adding t_min and t_max: only hits
/// with t_min <= t <= t_max count (a segment, e.g. a shadow ray). Directions need not be unit
/// length; t is measured in units of the direction, and a hit always has t > 0. RAYS may also
/// be a .npz archive (np.savez or np.savez_compressed) holding one such array, or one named
/// 'rays', or raw little-endian values with no header, .f32 or .f64, 6 values per ray or
/// --ray-columns 8.
///
/// HITS is written as float64, as .npy, as .npz (the array 'hits', deflated) or as raw .f64
/// rows, with shape (N, 4): t, triangle index, u, v (the hit point is
/// (1 - u - v) a + u b + v c of the triangle's vertices a, b, c). A miss is
/// (+inf, -1, NaN, NaN). --with point,normal adds the hit point's x, y, z and the triangle's
/// unit normal (b - a) x (c - a), normalised (NaN on a miss), in that order. With --any-hit,
/// HITS has shape (N, 1): 1 where the ray hits any triangle, 0 where it misses; --with prim
/// adds the index of a triangle it hits (the first found, not the nearest; -1 on a miss). A
/// ray with a NaN or infinite origin or direction component, a zero direction, or a NaN
/// t_min or t_max, is a miss. Triangle indices count the file's faces in order, each n-gon
/// fanned into n - 2 triangles from its first vertex. Rays are read, traced and written a
/// chunk at a time, so arrays larger than memory can be traced.
#[derive(Parser, Debug)]
#[command(name = "raycast", version)]
struct Cli {
    /// The mesh: .obj, .ply, .stl, .gltf, .glb, .obj.gz or .ply.gz.
    input: PathBuf,
    /// The rays: .npy or .npz, float32 or float64, shape (N, 6), or (N, 8) with t_min, t_max;
    /// or raw .f32 or .f64 values.
    rays: PathBuf,
    /// Where to write the hits: .npy, .npz or raw .f64, float64, shape (N, 4), or (N, 1) with
    /// --any-hit, plus the --with columns (replaced if it exists; never the rays or the mesh).
    hits: PathBuf,
    /// Values per ray in raw .f32 or .f64 RAYS: 6, or 8 with t_min, t_max [default: 6]. With
    /// .npy or .npz RAYS, checked against the array's shape.
    #[arg(
        long,
        value_name = "6|8",
        value_parser = PossibleValuesParser::new(["6", "8"]).map(|s| s.parse::<usize>().unwrap())
    )]
    ray_columns: Option<usize>,
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
    let Some(layout) = HitsLayout::from_path(&cli.hits) else {
        let hits = cli.hits.display();
        let e = format!("{hits}: the hits are float64 arrays: use a .npy, .npz or .f64 extension");
        return Err(UsageError(e).into());
    };
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
    progress.phase(format!("opening {}", cli.rays.display()));
    let mut rays = RaysFile::open(&cli.rays, cli.ray_columns).map_err(|e| rays_error(cli, e))?;

    progress.phase(format!("loading {}", cli.input.display()));
    let t = Instant::now();
    let mesh = raytrace::load_mesh(&cli.input, cli.precision)?;
    let load = t.elapsed();

    let n = rays.rows();
    let samples =
        if cli.see.wanted() { view::sample_indices(n, cli.see.view_rays) } else { Vec::new() };
    let job = CastJob {
        cli,
        mesh: &mesh,
        rays: &mut rays,
        hits: hits_file,
        layout,
        columns,
        progress: &progress,
        samples: &samples,
    };
    let cast = pool.install(|| dispatch(cli.backend, cli.precision, job))?;

    let time = Timings {
        load,
        build: cast.build,
        trace: cast.trace,
        write: cast.write,
        wall: start.elapsed(),
    };
    let shape = [n, columns.count()];
    let mut stats = Stats::new(mesh.len(), n as u64, time, cast.name, cli.precision, threads);
    let mut written = vec![cast.hits];
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
        let traced = cast.samples.iter().filter_map(|(r, t)| {
            let len = (r[3] * r[3] + r[4] * r[4] + r[5] * r[5]).sqrt();
            let finite = r[..6].iter().all(|x| x.is_finite()) && len > 0.0 && len.is_finite();
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

/// A RAYS error as one line naming the file (an input error names it already).
fn rays_error(cli: &Cli, e: RaysError) -> anyhow::Error {
    match e {
        RaysError::Input(e) => e.into(),
        e => anyhow::Error::new(e).context(cli.rays.display().to_string()),
    }
}

/// Builds the acceleration structure and traces the rays with one back end, a chunk at a
/// time, writing the hits as it goes.
struct CastJob<'a> {
    cli: &'a Cli,
    mesh: &'a Mesh,
    rays: &'a mut RaysFile,
    hits: AtomicFile,
    layout: HitsLayout,
    columns: Columns,
    progress: &'a Progress,
    /// Rays to show with `--view` and `--scene` (ascending), traced again for their nearest
    /// hit (with `--any-hit` the hits hold no distance).
    samples: &'a [usize],
}

/// What a [`CastJob`] did.
struct Cast {
    name: &'static str,
    hits: Written,
    build: Duration,
    trace: Duration,
    write: Duration,
    /// The sampled rays' values and nearest hit distances.
    samples: Vec<(Vec<f64>, Option<f64>)>,
}

impl Job for CastJob<'_> {
    type Output = anyhow::Result<Cast>;

    fn run<I: Intersector + 'static>(self, intersector: I) -> Self::Output {
        self.progress.phase("building the BVH");
        let start = Instant::now();
        let accel = Accel::build(intersector, &self.mesh.triangles());
        let build = start.elapsed();
        let (n, stride, width) = (self.rays.rows(), self.rays.columns(), self.columns.count());
        let mut reader = self.rays.rows_reader().map_err(|e| rays_error(self.cli, e))?;
        self.progress.trace(n as u64);
        let inc = |rays: usize| self.progress.inc(rays as u64);
        let (mut trace, mut write) = (Duration::ZERO, Duration::ZERO);
        let mut sampled = Vec::new();
        let hits = self.hits.write_streamed(|w, fail| -> anyhow::Result<()> {
            let mut sink = HitsWriter::new(w, self.layout, n, width).map_err(fail)?;
            // The rays in the kernel's precision, as `kernel_ray` would round them: the
            // trace then reads no more bytes per ray than the kernel takes.
            let (mut rays, mut hits) = (Vec::<I::Real>::new(), Vec::new());
            let mut samples = self.samples.iter().copied().peekable();
            let mut first = 0;
            loop {
                let got = reader
                    .next_rows(RAYS_PER_CHUNK, &mut rays)
                    .map_err(|e| rays_error(self.cli, RaysError::Read(e)))?;
                if got == 0 {
                    break;
                }
                while let Some(k) = samples.next_if(|&k| k < first + got) {
                    let ray = &rays[stride * (k - first)..stride * (k - first + 1)];
                    sampled.push(ray.iter().map(|x| x.to_f64()).collect::<Vec<_>>());
                }
                hits.resize(got * width, 0.0);
                let t = Instant::now();
                cast::trace_rays(&accel, self.mesh, &rays, stride, self.columns, &mut hits, &inc);
                trace += t.elapsed();
                let t = Instant::now();
                sink.write_rows(&hits).map_err(fail)?;
                write += t.elapsed();
                first += got;
            }
            let t = Instant::now();
            sink.finish().map_err(fail)?;
            write += t.elapsed();
            Ok(())
        })?;
        let samples = sampled
            .into_iter()
            .map(|r| {
                let t = cast::kernel_ray::<I::Real, f64>(&r, stride)
                    .and_then(|(ray, t_min, t_max)| accel.closest_hit_between(&ray, t_min, t_max))
                    .map(|hit| hit.t.to_f64());
                (r, t)
            })
            .collect();
        Ok(Cast { name: I::NAME, hits, build, trace, write, samples })
    }
}
