//! `raytrace MESH OUTPUT WIDTH HEIGHT [options]`: renders a mesh, one ray per pixel.
//!
//! The report's four arguments are kept; everything else is an option. See `--help`.

use std::path::PathBuf;
use std::process::ExitCode;
use std::time::{Instant, SystemTime};

use anyhow::Context as _;
use backends::{Backend, Job, Precision, dispatch};
use bvh::accel::Accel;
use clap::{Parser, ValueEnum};
use intersect::Intersector;
use raytrace::args::{parse_fov, parse_threads, resolve_threads};
use raytrace::progress::Progress;
use raytrace::record::{CameraRecord, OutputRecord, Record};
use raytrace::{Named, Stats, Timings, UsageError};
use render::camera::{Camera, DEFAULT_FOV_DEG};
use render::frame::{Frame, MAX_SIDE, Mode};
use render::output::{Format, ImageOutput};
use scene::Mesh;

/// Render a triangle mesh (OBJ, PLY, STL, glTF/GLB; .obj.gz, .ply.gz) to an image, one ray per
/// pixel.
///
/// The output format follows OUTPUT's extension: .png, .jpg/.jpeg (8-bit), .exr (32-bit
/// float) or .npy (the mode's raw values).
#[derive(Parser, Debug)]
#[command(name = "raytrace", version)]
struct Cli {
    /// The mesh to render: .obj, .ply, .stl, .gltf, .glb, .obj.gz or .ply.gz.
    input: PathBuf,
    /// The image to write: .png, .jpg, .jpeg, .exr or .npy (replaced if it exists).
    output: PathBuf,
    /// Image width in pixels (1 to 65535).
    #[arg(value_parser = side(), allow_negative_numbers = true)]
    width: u32,
    /// Image height in pixels (1 to 65535).
    #[arg(value_parser = side(), allow_negative_numbers = true)]
    height: u32,
    /// Ray-triangle back end.
    #[arg(long, value_enum, default_value_t = Backend::LaWatertight)]
    backend: Backend,
    /// Precision of rays, triangles and kernel.
    #[arg(long, value_enum, default_value_t = Precision::F32)]
    precision: Precision,
    /// What each pixel shows. alpha: white where a ray hits (the report's image); depth:
    /// distance, near white; normal: geometric normal as 0.5 n + 0.5; shade: Lambert, one
    /// light; prim: false colour per triangle.
    #[arg(long, value_enum, default_value_t = ModeArg::Alpha)]
    mode: ModeArg,
    /// Camera placement: auto frames the mesh's bounding sphere from the -z side; origin is
    /// the report's camera (eye at the origin, looking along +z, +y up).
    #[arg(long, value_enum, default_value_t = CameraArg::Auto)]
    camera: CameraArg,
    /// Eye position X,Y,Z (overrides the --camera placement's).
    #[arg(
        long,
        value_name = "X,Y,Z",
        value_parser = raytrace::parse_vec3,
        allow_hyphen_values = true
    )]
    eye: Option<[f64; 3]>,
    /// Point looked at X,Y,Z (overrides the --camera placement's).
    #[arg(
        long,
        value_name = "X,Y,Z",
        value_parser = raytrace::parse_vec3,
        allow_hyphen_values = true
    )]
    look_at: Option<[f64; 3]>,
    /// Up direction X,Y,Z [default: 0,1,0].
    #[arg(
        long,
        value_name = "X,Y,Z",
        value_parser = raytrace::parse_vec3,
        allow_hyphen_values = true
    )]
    up: Option<[f64; 3]>,
    /// Vertical field of view in degrees, between 0 and 180.
    #[arg(long, value_name = "DEG", default_value_t = DEFAULT_FOV_DEG, value_parser = parse_fov,
        allow_negative_numbers = true)]
    fov: f64,
    /// Worker threads, at most 4 per core; 0 is one per core [default: one per core].
    #[arg(long, value_name = "N", value_parser = parse_threads, allow_negative_numbers = true)]
    threads: Option<usize>,
    /// Print nothing but errors (no progress, no summary).
    #[arg(long, short)]
    quiet: bool,
    /// Also write the summary's figures to this JSON file (replaces only an earlier one).
    #[arg(long, value_name = "FILE.json")]
    stats: Option<PathBuf>,
}

/// The parser for a side of the image: 1 to [`MAX_SIDE`] pixels.
fn side() -> clap::builder::RangedI64ValueParser<u32> {
    clap::value_parser!(u32).range(1..=i64::from(MAX_SIDE))
}

#[derive(Clone, Copy, Debug, ValueEnum)]
enum ModeArg {
    Alpha,
    Depth,
    Normal,
    Shade,
    Prim,
}

impl From<ModeArg> for Mode {
    fn from(m: ModeArg) -> Mode {
        match m {
            ModeArg::Alpha => Mode::Alpha,
            ModeArg::Depth => Mode::Depth,
            ModeArg::Normal => Mode::Normal,
            ModeArg::Shade => Mode::Shade,
            ModeArg::Prim => Mode::Prim,
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
enum CameraArg {
    Auto,
    Origin,
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
    // Everything that can be checked without the mesh is checked before loading it, and the
    // output files are created (empty, temporary) before the work, so that a bad path fails
    // in a moment rather than after the render.
    Format::from_path(&cli.output).map_err(|e| UsageError(e.to_string()))?;
    let stats_path = cli.stats.as_deref();
    let mut outputs = vec![Named { role: "image", path: &cli.output }];
    outputs.extend(stats_path.map(|path| Named { role: "stats", path }));
    raytrace::start_run(&[Named { role: "mesh", path: &cli.input }], &outputs, stats_path)?;
    let output = ImageOutput::create(&cli.output)?;
    let stats_file = raytrace::create_stats_file(stats_path)?;
    let mut frame = Frame::new(cli.mode.into(), cli.width, cli.height)?;
    let threads = resolve_threads(cli.threads);
    let pool = raytrace::thread_pool(threads)?;

    let progress = Progress::new(cli.quiet);
    progress.phase(format!("loading {}", cli.input.display()));
    let t = Instant::now();
    let mesh = raytrace::load_mesh(&cli.input, cli.precision)?;
    let load = t.elapsed();
    let (camera, placed) = camera(cli, &mesh)?;

    let job = RenderJob { mesh: &mesh, camera: &camera, frame: &mut frame, progress: &progress };
    let (name, build, trace) = pool.install(|| dispatch(cli.backend, cli.precision, job));

    progress.phase(format!("writing {}", cli.output.display()));
    let t = Instant::now();
    let image = output.encode(&frame)?;
    let write = t.elapsed();
    let rays = u64::from(cli.width) * u64::from(cli.height);
    let time = Timings { load, build, trace, write, wall: start.elapsed() };
    let mut stats = Stats::new(mesh.len(), rays, time, name, cli.precision, threads);
    stats.camera = Some(placed);
    let mut written = vec![image];
    if let Some(file) = stats_file {
        let output = OutputRecord {
            path: cli.output.display().to_string(),
            width: Some(cli.width),
            height: Some(cli.height),
            mode: cli.mode.to_possible_value().map(|v| v.get_name().to_owned()),
            shape: None,
        };
        let inputs = [("mesh", cli.input.as_path())];
        stats.record = Some(Record::new("raytrace", started, &inputs, output)?);
        written.push(stats.write_json(file)?);
    }
    render::output::commit_all(written)?;
    progress.finish();
    if !cli.quiet {
        println!("{}: {} -> {}", cli.input.display(), stats.summary(), cli.output.display());
    }
    Ok(())
}

/// The camera from `--camera`, then `--eye`, `--look-at`, `--up` and `--fov` on top, and the
/// options that place it again.
fn camera(cli: &Cli, mesh: &Mesh) -> anyhow::Result<(Camera, CameraRecord)> {
    let aspect = f64::from(cli.width) / f64::from(cli.height);
    let base = match cli.camera {
        CameraArg::Auto => {
            let (center, radius) = mesh.bounding_sphere();
            let auto = Camera::auto(center, radius, cli.fov, aspect).context("--camera auto")?;
            (auto.eye(), center)
        }
        CameraArg::Origin => ([0.0; 3], [0.0, 0.0, 1.0]),
    };
    let eye = cli.eye.unwrap_or(base.0);
    let look_at = cli.look_at.unwrap_or(base.1);
    let up = cli.up.unwrap_or([0.0, 1.0, 0.0]);
    let camera = Camera::look_at(eye, look_at, up, cli.fov).context("bad camera")?;
    let placed = CameraRecord::new(&camera, look_at, up);
    Ok((camera, placed))
}

/// Builds the acceleration structure and renders: the part compiled once per back end.
struct RenderJob<'a> {
    mesh: &'a Mesh,
    camera: &'a Camera,
    frame: &'a mut Frame,
    progress: &'a Progress,
}

impl Job for RenderJob<'_> {
    /// The back end's name, build time, trace time.
    type Output = (&'static str, std::time::Duration, std::time::Duration);

    fn run<I: Intersector + 'static>(self, intersector: I) -> Self::Output {
        self.progress.phase("building the BVH");
        let start = Instant::now();
        let accel = Accel::build(intersector, &self.mesh.triangles());
        let build = start.elapsed();
        self.progress.trace(u64::from(self.frame.width()) * u64::from(self.frame.height()));
        let start = Instant::now();
        render::trace::render_frame(&accel, self.mesh, self.camera, self.frame, &|n| {
            self.progress.inc(n as u64);
        });
        (I::NAME, build, start.elapsed())
    }
}
