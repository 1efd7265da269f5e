//! `raytrace MESH OUTPUT WIDTH HEIGHT [options]`: renders a mesh, one ray per pixel.
//!
//! The report's four arguments are kept; everything else is an option. See `--help`.

use std::path::PathBuf;
use std::process::ExitCode;
use std::time::{Duration, Instant, SystemTime};

use anyhow::Context as _;
use backends::{Backend, Job, Precision, dispatch};
use bvh::accel::Accel;
use clap::{Parser, ValueEnum};
use intersect::Intersector;
use intersect::Real as _;
use raytrace::args::{parse_fov, parse_threads, resolve_threads};
use raytrace::progress::Progress;
use raytrace::record::{CameraRecord, OutputRecord, Record};
use raytrace::{CompareStats, Named, Stats, Timings, UsageError};
use render::camera::{Camera, DEFAULT_FOV_DEG, Placement, PlacementError};
use render::compare::Hits;
use render::frame::{Frame, FrameError, MAX_SIDE, Mode};
use render::output::{AtomicFile, Format, ImageOutput};
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
    /// Render the same rays with each listed back end (comma-separated, each once; alone:
    /// every back end) and compare them pixel by pixel: a table per pair on stdout, a diff
    /// image per pair beside OUTPUT named STEM.diff.A.B.png (black: equal, red: only A hits,
    /// green: only B hits, yellow: different triangles, blue: same triangle, different
    /// distance, brighter for more), and a "compare" object in --stats. OUTPUT holds the first
    /// listed back end's image. Put it after the four arguments, or write --compare=LIST.
    #[arg(
        long,
        value_enum,
        value_name = "BACKENDS",
        num_args = 0..=1,
        value_delimiter = ',',
        conflicts_with = "backend",
        hide_possible_values = true
    )]
    compare: Option<Vec<Backend>>,
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
    let backends = backends_to_run(cli)?;
    let pairs = pairs(&backends);
    let diff_paths = pairs
        .iter()
        .map(|&(a, b)| raytrace::diff_path(&cli.output, a.name(), b.name()))
        .collect::<anyhow::Result<Vec<_>>>()?;
    let stats_path = cli.stats.as_deref();
    let mut outputs = vec![Named { role: "image", path: &cli.output }];
    outputs.extend(diff_paths.iter().map(|path| Named { role: "diff image", path }));
    outputs.extend(stats_path.map(|path| Named { role: "stats", path }));
    cli.see.outputs(&mut outputs)?;
    raytrace::start_run(&[Named { role: "mesh", path: &cli.input }], &outputs, stats_path)?;
    let output = ImageOutput::create(&cli.output)?;
    let diff_files =
        diff_paths.iter().map(|p| AtomicFile::create(p)).collect::<Result<Vec<_>, _>>()?;
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
    let (camera, placed) = camera(cli, &mesh)?;

    let samples = if cli.see.wanted() {
        view::sample_pixels(cli.width, cli.height, cli.see.view_rays)
    } else {
        Vec::new()
    };
    let comparing = cli.compare.is_some();
    let mut runs = Vec::with_capacity(backends.len());
    for (k, &backend) in backends.iter().enumerate() {
        let label = if comparing {
            format!(" {} ({}/{})", backend.name(), k + 1, backends.len())
        } else {
            String::new()
        };
        let job = RenderJob {
            mesh: &mesh,
            camera: &camera,
            // The image (and the viewer's sample) is the first back end's; the others only
            // trace the hits.
            frame: (k == 0).then_some(&mut frame),
            size: (cli.width, cli.height),
            hits: comparing,
            progress: &progress,
            label,
            samples: if k == 0 { &samples } else { &[] },
        };
        runs.push(pool.install(|| dispatch(backend, cli.precision, job))?);
    }

    progress.phase(format!("writing {}", cli.output.display()));
    let t = Instant::now();
    let mut written = vec![output.encode(&frame)?];
    let comparison = if comparing {
        let named: Vec<(&str, &Hits)> = runs
            .iter()
            .map(|r| (r.name, r.hits.as_ref().expect("compared runs trace hits")))
            .collect();
        let comparison = render::compare::compare(&named, &camera);
        for (file, &(a, b)) in diff_files.into_iter().zip(&pairs) {
            let (a, b) = (named[index(&backends, a)].1, named[index(&backends, b)].1);
            written.push(file.write_png(&render::compare::diff_image(a, b)?)?);
        }
        Some(comparison)
    } else {
        None
    };
    let write = t.elapsed();
    let traces = u64::try_from(runs.len()).unwrap_or(u64::MAX) + u64::from(comparing);
    let rays = u64::from(cli.width) * u64::from(cli.height) * traces;
    let build = runs.iter().map(|r| r.build).sum();
    let trace = runs.iter().map(|r| r.trace).sum();
    let time = Timings { load, build, trace, write, wall: start.elapsed() };
    let mut stats = Stats::new(mesh.len(), rays, time, runs[0].name, cli.precision, threads);
    stats.camera = Some(placed);
    if let Some(comparison) = &comparison {
        let times: Vec<_> = runs.iter().map(|r| (r.build, r.trace)).collect();
        stats.compare = Some(CompareStats::new(comparison, &times, &diff_paths));
    }
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
    if cli.see.wanted() {
        progress.phase("writing the viewer and scene");
        let (w, h) = (cli.width, cli.height);
        let rays = samples
            .iter()
            .zip(&runs[0].sample_t)
            .map(|(&(i, j), &t)| (camera.eye(), camera.direction(i, j, w, h), t));
        let look_at = placed.look_at;
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
            layers: see_layers(&mesh, rays, comparison.as_ref(), cli.see.view_rays),
            figures: raytrace::see::figures(&stats, &extra),
        };
        written.extend(see_files.write(&run)?);
    }
    render::output::commit_all(written)?;
    progress.finish();
    if !cli.quiet {
        if let Some(comparison) = &comparison {
            println!(
                "compare: {} back ends, {} of {} pixels where some disagree; diff images {}",
                comparison.backends.len(),
                comparison.disagreements.len(),
                u64::from(cli.width) * u64::from(cli.height),
                raytrace::diff_path(&cli.output, "A", "B")?.display()
            );
            print!("{}", render::compare::table(comparison));
        }
        println!("{}: {} -> {}", cli.input.display(), stats.summary(), cli.output.display());
    }
    Ok(())
}

/// The viewer's ray layers: the sample's hits and misses, and with `--compare` the rays where
/// the back ends disagree, which the page then shows alone at first (the sample's layers start
/// hidden: a crack is one ray among thousands).
fn see_layers(
    mesh: &scene::Mesh,
    rays: impl IntoIterator<Item = ([f64; 3], [f64; 3], Option<f64>)>,
    comparison: Option<&render::compare::Comparison>,
    n: usize,
) -> Vec<view::RayLayer> {
    let mut layers = view::hit_and_miss_layers(mesh, rays);
    if let Some(comparison) = comparison {
        let disagree = view::disagreement_layers(comparison, n);
        if !disagree.is_empty() {
            layers.iter_mut().for_each(|l| l.shown = false);
        }
        layers.extend(disagree);
    }
    layers
}

/// The back ends to render with: `--backend`'s, or `--compare`'s list (every back end when
/// it is empty).
///
/// # Errors
///
/// [`UsageError`] for a back end listed twice or a list of one.
fn backends_to_run(cli: &Cli) -> anyhow::Result<Vec<Backend>> {
    let Some(list) = &cli.compare else { return Ok(vec![cli.backend]) };
    if list.is_empty() {
        return Ok(Backend::ALL.to_vec());
    }
    for (k, b) in list.iter().enumerate() {
        if list[..k].contains(b) {
            return Err(UsageError(format!(
                "--compare: {} is listed twice (each back end once)",
                b.name()
            ))
            .into());
        }
    }
    if list.len() < 2 {
        return Err(UsageError(format!(
            "--compare: {} alone has nothing to be compared with: list two or more back ends",
            list[0].name()
        ))
        .into());
    }
    Ok(list.clone())
}

/// Every pair `(a, b)` of `backends` with `a` listed before `b`, in the order of
/// [`render::compare::Comparison::pairs`].
fn pairs(backends: &[Backend]) -> Vec<(Backend, Backend)> {
    let mut v = Vec::new();
    for (k, &a) in backends.iter().enumerate() {
        v.extend(backends[k + 1..].iter().map(|&b| (a, b)));
    }
    v
}

fn index(backends: &[Backend], b: Backend) -> usize {
    backends.iter().position(|&x| x == b).expect("pairs are made of the listed back ends")
}

/// The camera from `--camera`, then `--eye`, `--look-at`, `--up` and `--fov` on top, and the
/// options that place it again.
fn camera(cli: &Cli, mesh: &Mesh) -> anyhow::Result<(Camera, CameraRecord)> {
    let aspect = f64::from(cli.width) / f64::from(cli.height);
    let placement = Placement {
        auto: cli.camera == CameraArg::Auto,
        eye: cli.eye,
        look_at: cli.look_at,
        up: cli.up,
        fov_deg: cli.fov,
    };
    let (camera, look_at, up) =
        placement.camera(mesh.bounding_sphere(), aspect).map_err(|e| match e {
            PlacementError::Auto(e) => anyhow::Error::new(e).context("--camera auto"),
            PlacementError::Camera(e) => anyhow::Error::new(e).context("bad camera"),
        })?;
    let placed = CameraRecord::new(&camera, look_at, up);
    Ok((camera, placed))
}

/// Builds the acceleration structure and renders the image and/or traces the hits for
/// `--compare`: the part compiled once per back end.
struct RenderJob<'a> {
    mesh: &'a Mesh,
    camera: &'a Camera,
    frame: Option<&'a mut Frame>,
    size: (u32, u32),
    hits: bool,
    progress: &'a Progress,
    /// Appended to the progress lines (` la-mt (2/5)`), empty for a single back end.
    label: String,
    /// Pixels to trace again for `--view` and `--scene`, with the same camera and back end:
    /// the frame keeps no hit distance in every mode (alpha asks only "any hit?").
    samples: &'a [(u32, u32)],
}

/// What one back end's [`RenderJob`] gives.
struct Run {
    name: &'static str,
    build: Duration,
    trace: Duration,
    hits: Option<Hits>,
    /// The closest hit's distance of each of the job's `samples`.
    sample_t: Vec<Option<f64>>,
}

impl Job for RenderJob<'_> {
    type Output = Result<Run, FrameError>;

    fn run<I: Intersector + 'static>(self, intersector: I) -> Self::Output {
        let label = &self.label;
        self.progress.phase(format!("building the BVH{label}"));
        let start = Instant::now();
        let accel = Accel::build(intersector, &self.mesh.triangles());
        let build = start.elapsed();
        let (w, h) = self.size;
        let traces = u64::from(self.frame.is_some()) + u64::from(self.hits);
        self.progress
            .trace_labelled(format!("tracing{label}"), u64::from(w) * u64::from(h) * traces);
        let inc = |n: usize| self.progress.inc(n as u64);
        let start = Instant::now();
        if let Some(frame) = self.frame {
            render::trace::render_frame(&accel, self.mesh, self.camera, frame, &inc);
        }
        let hits = if self.hits {
            Some(render::compare::trace_hits(&accel, self.camera, w, h, &inc)?)
        } else {
            None
        };
        let trace = start.elapsed();
        let sample_t = self
            .samples
            .iter()
            .map(|&(i, j)| {
                let ray = self.camera.ray::<I::Real>(i, j, w, h);
                accel.closest_hit(&ray).map(|hit| hit.t.to_f64())
            })
            .collect();
        Ok(Run { name: I::NAME, build, trace, hits, sample_t })
    }
}
