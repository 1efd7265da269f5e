//! `raytrace MESH OUTPUT WIDTH HEIGHT [options]`: renders a mesh, one ray per pixel.
//!
//! The report's four arguments are kept; everything else is an option. See `--help`.

use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;

use anyhow::Context as _;
use backends::{Backend, Job, Precision, dispatch};
use bvh::accel::Accel;
use clap::{Parser, ValueEnum};
use intersect::Intersector;
use intersect::Real as _;
use raytrace::args::{parse_fov, parse_threads, resolve_threads};
use raytrace::progress::Progress;
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
    #[command(flatten)]
    see: raytrace::see::SeeArgs,
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
    let start = Instant::now();
    raytrace::one_line_panics();
    match Cli::try_parse() {
        Ok(cli) => raytrace::exit(run(&cli, start)),
        Err(e) => raytrace::clap_exit(&e),
    }
}

fn run(cli: &Cli, start: Instant) -> anyhow::Result<()> {
    // Everything that can be checked without the mesh is checked before loading it, and the
    // output files are created (empty, temporary) before the work, so that a bad path fails
    // in a moment rather than after the render.
    Format::from_path(&cli.output).map_err(|e| UsageError(e.to_string()))?;
    let stats_path = cli.stats.as_deref();
    let mut outputs = vec![Named { role: "image", path: &cli.output }];
    outputs.extend(stats_path.map(|path| Named { role: "stats", path }));
    cli.see.outputs(&mut outputs)?;
    raytrace::start_run(&[Named { role: "mesh", path: &cli.input }], &outputs, stats_path)?;
    let output = ImageOutput::create(&cli.output)?;
    let stats_file = raytrace::create_stats_file(stats_path)?;
    let see_files = cli.see.create()?;
    let mut frame = Frame::new(cli.mode.into(), cli.width, cli.height)?;
    let threads = resolve_threads(cli.threads);
    let pool = raytrace::thread_pool(threads)?;

    let progress = Progress::new(cli.quiet);
    progress.phase(format!("loading {}", cli.input.display()));
    let t = Instant::now();
    let mesh = raytrace::load_mesh(&cli.input, cli.precision)?;
    let load = t.elapsed();
    let camera = camera(cli, &mesh)?;

    let samples = if cli.see.wanted() {
        view::sample_pixels(cli.width, cli.height, cli.see.view_rays)
    } else {
        Vec::new()
    };
    let job = RenderJob {
        mesh: &mesh,
        camera: &camera,
        frame: &mut frame,
        progress: &progress,
        samples: &samples,
    };
    let (name, build, trace, sample_t) = pool.install(|| dispatch(cli.backend, cli.precision, job));

    progress.phase(format!("writing {}", cli.output.display()));
    let t = Instant::now();
    let image = output.encode(&frame)?;
    let write = t.elapsed();
    let rays = u64::from(cli.width) * u64::from(cli.height);
    let time = Timings { load, build, trace, write, wall: start.elapsed() };
    let stats = Stats::new(mesh.len(), rays, time, name, cli.precision, threads);
    let mut written = vec![image];
    if let Some(file) = stats_file {
        written.push(stats.write_json(file)?);
    }
    if cli.see.wanted() {
        progress.phase("writing the viewer and scene");
        let (w, h) = (cli.width, cli.height);
        let rays = samples
            .iter()
            .zip(&sample_t)
            .map(|(&(i, j), &t)| (camera.eye(), camera.direction(i, j, w, h), t));
        let look_at = look_at(cli, &mesh);
        let extra = [(
            "mode",
            cli.mode.to_possible_value().map_or_else(String::new, |v| v.get_name().to_owned()),
        )];
        let run = view::Run {
            mesh: &mesh,
            camera: Some(view::RunCamera {
                camera,
                look_at,
                width: w,
                height: h,
                png: view::png_of(&frame).context("--view: the image")?,
            }),
            layers: view::hit_and_miss_layers(&mesh, rays),
            figures: raytrace::see::figures(&stats, &extra),
        };
        written.extend(see_files.write(&run)?);
    }
    render::output::commit_all(written)?;
    progress.finish();
    if !cli.quiet {
        println!("{}: {} -> {}", cli.input.display(), stats.summary(), cli.output.display());
    }
    Ok(())
}

/// The camera from `--camera`, then `--eye`, `--look-at`, `--up` and `--fov` on top.
fn camera(cli: &Cli, mesh: &Mesh) -> anyhow::Result<Camera> {
    let aspect = f64::from(cli.width) / f64::from(cli.height);
    let base_eye = match cli.camera {
        CameraArg::Auto => {
            let (center, radius) = mesh.bounding_sphere();
            Camera::auto(center, radius, cli.fov, aspect).context("--camera auto")?.eye()
        }
        CameraArg::Origin => [0.0; 3],
    };
    let eye = cli.eye.unwrap_or(base_eye);
    let up = cli.up.unwrap_or([0.0, 1.0, 0.0]);
    Camera::look_at(eye, look_at(cli, mesh), up, cli.fov).context("bad camera")
}

/// The point looked at: `--look-at`, else the `--camera` placement's.
fn look_at(cli: &Cli, mesh: &Mesh) -> [f64; 3] {
    cli.look_at.unwrap_or_else(|| match cli.camera {
        CameraArg::Auto => mesh.bounding_sphere().0,
        CameraArg::Origin => [0.0, 0.0, 1.0],
    })
}

/// Builds the acceleration structure and renders: the part compiled once per back end.
struct RenderJob<'a> {
    mesh: &'a Mesh,
    camera: &'a Camera,
    frame: &'a mut Frame,
    progress: &'a Progress,
    /// Pixels to trace again for `--view` and `--scene`, with the same camera and back end:
    /// the frame keeps no hit distance in every mode (alpha asks only "any hit?").
    samples: &'a [(u32, u32)],
}

impl Job for RenderJob<'_> {
    /// The back end's name, build time, trace time, the samples' hit distances.
    type Output = (&'static str, std::time::Duration, std::time::Duration, Vec<Option<f64>>);

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
        let trace = start.elapsed();
        let (w, h) = (self.frame.width(), self.frame.height());
        let t = self
            .samples
            .iter()
            .map(|&(i, j)| {
                let ray = self.camera.ray::<I::Real>(i, j, w, h);
                accel.closest_hit(&ray).map(|hit| hit.t.to_f64())
            })
            .collect();
        (I::NAME, build, trace, t)
    }
}
