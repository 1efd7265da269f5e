//! `raytrace INPUT.obj OUTPUT WIDTH HEIGHT [options]`: renders a mesh, one ray per pixel.
//!
//! The report's four arguments are kept; everything else is an option. See `--help`.

use std::io::IsTerminal as _;
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;

use anyhow::Context as _;
use backends::{Backend, Job, Precision, dispatch};
use clap::{Parser, ValueEnum};
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use intersect::Intersector;
use raytrace::Stats;
use render::accel::Accel;
use render::camera::{Camera, DEFAULT_FOV_DEG};
use render::frame::{Frame, Mode};
use render::output::ImageOutput;
use render::scene::Mesh;

/// Render a triangle mesh (Wavefront OBJ) to an image, one ray per pixel.
///
/// The output format follows OUTPUT's extension: .png, .jpg/.jpeg (8-bit), .exr (32-bit
/// float) or .npy (the mode's raw values).
#[derive(Parser, Debug)]
#[command(version, about)]
struct Cli {
    /// The mesh to render (.obj).
    input: PathBuf,
    /// The image to write: .png, .jpg, .jpeg, .exr or .npy.
    output: PathBuf,
    /// Image width in pixels.
    width: u32,
    /// Image height in pixels.
    height: u32,
    /// Ray-triangle back end.
    #[arg(long, value_enum, default_value_t = Backend::La)]
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
    #[arg(long, value_name = "X,Y,Z", value_parser = raytrace::parse_vec3, allow_hyphen_values = true)]
    eye: Option<[f64; 3]>,
    /// Point looked at X,Y,Z (overrides the --camera placement's).
    #[arg(long, value_name = "X,Y,Z", value_parser = raytrace::parse_vec3, allow_hyphen_values = true)]
    look_at: Option<[f64; 3]>,
    /// Up direction X,Y,Z [default: 0,1,0].
    #[arg(long, value_name = "X,Y,Z", value_parser = raytrace::parse_vec3, allow_hyphen_values = true)]
    up: Option<[f64; 3]>,
    /// Vertical field of view in degrees.
    #[arg(long, value_name = "DEG", default_value_t = DEFAULT_FOV_DEG)]
    fov: f64,
    /// Worker threads [default: one per core].
    #[arg(long, value_name = "N")]
    threads: Option<usize>,
    /// Print nothing but errors (no progress bar, no summary).
    #[arg(long, short)]
    quiet: bool,
    /// Also write the summary's figures to this JSON file.
    #[arg(long, value_name = "FILE.json")]
    stats: Option<PathBuf>,
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
    // Everything that can be checked without the mesh is checked before loading it, and the
    // output files are created (empty, temporary) before the work, so that a bad path fails
    // in a moment rather than after the render.
    let output = ImageOutput::create(&cli.output)?;
    let stats_file = raytrace::create_stats_file(cli.stats.as_deref())?;
    let mut frame = Frame::new(cli.mode.into(), cli.width, cli.height)?;
    let pool = raytrace::thread_pool(cli.threads)?;

    let start = Instant::now();
    let mesh = Mesh::load(&cli.input)?;
    let load = start.elapsed();
    let camera = camera(cli, &mesh)?;

    let bar = progress_bar(cli, u64::from(cli.width) * u64::from(cli.height));
    let job = RenderJob { mesh: &mesh, camera: &camera, frame: &mut frame, bar: &bar };
    let (name, build, trace) = pool.install(|| dispatch(cli.backend, cli.precision, job));
    bar.finish_and_clear();

    output.write(&frame)?;
    let rays = u64::from(cli.width) * u64::from(cli.height);
    let threads = pool.current_num_threads();
    let stats = Stats::new(mesh.len(), rays, load, build, trace, name, cli.precision, threads);
    if let Some(file) = stats_file {
        stats.write_json(file)?;
    }
    if !cli.quiet {
        println!("{}: {} -> {}", cli.input.display(), stats.summary(), cli.output.display());
    }
    Ok(())
}

/// The camera from `--camera`, then `--eye`, `--look-at`, `--up` and `--fov` on top.
fn camera(cli: &Cli, mesh: &Mesh) -> anyhow::Result<Camera> {
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
    Camera::look_at(eye, look_at, up, cli.fov).context("bad camera")
}

fn progress_bar(cli: &Cli, pixels: u64) -> ProgressBar {
    let bar = ProgressBar::with_draw_target(Some(pixels), ProgressDrawTarget::hidden());
    if !cli.quiet && std::io::stderr().is_terminal() {
        let style = ProgressStyle::with_template("{bar:40} {percent:>3}% {elapsed} (eta {eta})")
            .expect("the template is valid");
        bar.set_style(style);
        bar.set_draw_target(ProgressDrawTarget::stderr());
    }
    bar
}

/// Builds the acceleration structure and renders: the part compiled once per back end.
struct RenderJob<'a> {
    mesh: &'a Mesh,
    camera: &'a Camera,
    frame: &'a mut Frame,
    bar: &'a ProgressBar,
}

impl Job for RenderJob<'_> {
    /// The back end's name, build time, trace time.
    type Output = (&'static str, std::time::Duration, std::time::Duration);

    fn run<I: Intersector + 'static>(self, intersector: I) -> Self::Output {
        let start = Instant::now();
        let accel = Accel::from_mesh(intersector, self.mesh);
        let build = start.elapsed();
        let start = Instant::now();
        render::render::render(&accel, self.mesh, self.camera, self.frame, &|n| {
            self.bar.inc(n as u64);
        });
        (I::NAME, build, start.elapsed())
    }
}
