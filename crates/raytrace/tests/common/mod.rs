//! Shared by `backends_agree.rs` and `golden.rs`: scenes with their cameras, every back end and
//! precision, a job that renders a scene through whichever back end [`backends::dispatch`]
//! picks at run time (so each test is written once and run for all of them), `f64` geometry
//! to judge the pixels where results differ, and diff images.

// Each test file uses a different part of this module.
#![allow(dead_code)]

use std::path::{Path, PathBuf};

use backends::{Backend, Job, Precision};
use bvh::accel::Accel;
use intersect::{Hit, Intersector, Ray, Real, Triangle};
use rayon::prelude::*;
use render::camera::{Camera, DEFAULT_FOV_DEG};
use render::frame::{Frame, FrameData, Mode};
use render::trace::render_frame;
use scene::Mesh;

/// Every back end of the registry in every precision, in `--backend` order per precision.
#[must_use]
pub fn configs() -> Vec<Config> {
    Precision::ALL
        .into_iter()
        .flat_map(|precision| Backend::ALL.map(|backend| Config { backend, precision }))
        .collect()
}

/// One back end in one precision.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Config {
    /// The back end.
    pub backend: Backend,
    /// Its precision.
    pub precision: Precision,
}

impl Config {
    /// `la-f32`, `ga-plucker-f64`, ... (the `--backend` name and the precision).
    #[must_use]
    pub fn name(self) -> String {
        format!("{}-{}", self.backend.name(), self.precision.name())
    }

    /// The relative tolerance on a hit distance `t` for results of this precision: the
    /// issue's figures, `1e-5` in `f32` and `1e-12` in `f64`.
    #[must_use]
    pub fn depth_tolerance(self) -> f64 {
        match self.precision {
            Precision::F32 => 1e-5,
            Precision::F64 => 1e-12,
        }
    }

    /// Triangle `k` of `mesh` exactly as this configuration's kernel sees it, in `f64`.
    #[must_use]
    pub fn kernel_triangle(self, mesh: &Mesh, k: usize) -> Triangle<f64> {
        match self.precision {
            Precision::F32 => mesh.triangle::<f32>(k).cast(),
            Precision::F64 => mesh.triangle::<f64>(k),
        }
    }

    /// `ray` exactly as this configuration's kernel sees it, in `f64`.
    #[must_use]
    pub fn kernel_ray(self, ray: &Ray<f64>) -> Ray<f64> {
        match self.precision {
            Precision::F32 => ray.cast::<f32>().cast(),
            Precision::F64 => *ray,
        }
    }
}

/// A mesh, a camera and an image size.
pub struct Scene {
    /// For messages and file names.
    pub name: String,
    /// The triangles.
    pub mesh: Mesh,
    /// Where the rays come from.
    pub camera: Camera,
    /// Image width in pixels.
    pub width: u32,
    /// Image height in pixels.
    pub height: u32,
    /// Radius of the mesh's bounding sphere: the length that distance tolerances are
    /// relative to.
    pub radius: f64,
}

impl Scene {
    /// A scene from a mesh, a camera and a size.
    #[must_use]
    pub fn new(name: &str, mesh: Mesh, camera: Camera, width: u32, height: u32) -> Self {
        let radius = mesh.bounding_sphere().1;
        Self { name: name.to_owned(), mesh, camera, width, height, radius }
    }

    /// One of the generated scenes in `obj/`, seen by `camera`.
    ///
    /// # Panics
    ///
    /// If the file cannot be loaded.
    #[must_use]
    pub fn obj(file: &str, camera: Camera, width: u32, height: u32) -> Self {
        let path = repo_root().join("obj").join(file);
        let mesh = Mesh::load(&path).unwrap_or_else(|e| panic!("{e}"));
        Self::new(file.trim_end_matches(".obj"), mesh, camera, width, height)
    }

    /// One of the real meshes in the shared folder beside the repository, framed by
    /// [`Camera::auto`].
    ///
    /// # Panics
    ///
    /// If the folder or the file is missing (with a message saying where it was looked for)
    /// or the file cannot be loaded.
    #[must_use]
    pub fn shared(file: &str, width: u32, height: u32) -> Self {
        let path = shared_mesh(file);
        let mesh = Mesh::load(&path).unwrap_or_else(|e| panic!("{e}"));
        let (center, radius) = mesh.bounding_sphere();
        let aspect = f64::from(width) / f64::from(height);
        let camera = Camera::auto(center, radius, DEFAULT_FOV_DEG, aspect).expect("a valid camera");
        Self::new(file.trim_end_matches(".obj"), mesh, camera, width, height)
    }

    /// Number of pixels.
    #[must_use]
    pub fn pixels(&self) -> usize {
        self.width as usize * self.height as usize
    }

    /// Column and row of pixel `p` (row-major from the top left, as in [`Frame`]).
    #[must_use]
    pub fn ij(&self, p: usize) -> (u32, u32) {
        ((p % self.width as usize) as u32, (p / self.width as usize) as u32)
    }

    /// The `f64` ray through the centre of pixel `p`.
    #[must_use]
    pub fn ray(&self, p: usize) -> Ray<f64> {
        let (i, j) = self.ij(p);
        self.camera.ray(i, j, self.width, self.height)
    }
}

/// The workspace root.
#[must_use]
pub fn repo_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// A real mesh from the shared folder beside the repository (`../shared/meshes/`).
///
/// # Panics
///
/// If it is not there: these tests need it, and must not pass silently without it.
#[must_use]
pub fn shared_mesh(file: &str) -> PathBuf {
    let dir = repo_root().join("../shared/meshes");
    let path = dir.join(file);
    assert!(
        path.is_file(),
        "{} not found: this test renders the real meshes kept beside the repository in \
         ../shared/meshes/ (stanford-bunny.obj, teapot.obj); put them there to run it",
        path.display()
    );
    path
}

/// A camera at `eye` looking at `target`, +y up, the default field of view.
///
/// # Panics
///
/// If the eye is the target.
#[must_use]
pub fn camera(eye: [f64; 3], target: [f64; 3]) -> Camera {
    Camera::look_at(eye, target, [0.0, 1.0, 0.0], DEFAULT_FOV_DEG).expect("a valid camera")
}

/// What one configuration made of a scene.
pub struct Traced {
    /// Which back end and precision.
    pub config: Config,
    /// The `alpha` frame of [`render_frame`] (any-hit queries): whether each pixel's ray hit.
    pub alpha: Vec<bool>,
    /// The `depth` frame of [`render_frame`].
    pub depth_frame: Vec<f32>,
    /// The `prim` frame of [`render_frame`].
    pub prim_frame: Vec<u32>,
    /// [`Accel::closest_hit`] of each pixel's ray, in the back end's precision, then
    /// converted (exactly) to `f64`, so that `f64` depths keep all their digits.
    pub hits: Vec<Option<Hit<f64>>>,
    /// Pixels where the BVH queries differ from the brute-force ones, one line each.
    pub bvh_mismatches: Vec<String>,
    /// Pixels where the packet queries ([`Accel::closest_hits_packet`],
    /// [`Accel::any_hits_packet`], on the frame's rays in 8 x 8 blocks) differ in any bit from
    /// the single-ray ones, one line each.
    pub packet_mismatches: Vec<String>,
}

/// Renders a scene through one back end: the `alpha`, `depth` and `prim` frames, the closest
/// hit of every pixel, and a comparison of the BVH with brute force on `bvh_check` pixels.
pub struct Trace<'a> {
    /// What to render.
    pub scene: &'a Scene,
    /// Pixels whose rays are also traced by brute force.
    pub bvh_check: &'a [usize],
    /// Which back end and precision `dispatch` was asked for (for names in messages).
    pub config: Config,
}

impl Job for Trace<'_> {
    type Output = Traced;

    fn run<I: Intersector + 'static>(self, intersector: I) -> Traced {
        let s = self.scene;
        let (w, h) = (s.width, s.height);
        let accel = Accel::build(intersector, &s.mesh.triangles());
        let frame = |mode| {
            let mut frame = Frame::new(mode, w, h).expect("a small frame");
            render_frame(&accel, &s.mesh, &s.camera, &mut frame, &|_| {});
            frame.data().clone()
        };
        let FrameData::Alpha(alpha) = frame(Mode::Alpha) else { unreachable!() };
        let FrameData::Depth(depth_frame) = frame(Mode::Depth) else { unreachable!() };
        let FrameData::Prim(prim_frame) = frame(Mode::Prim) else { unreachable!() };
        let ray = |p: usize| {
            let (i, j) = s.ij(p);
            s.camera.ray::<I::Real>(i, j, w, h)
        };
        let hits = (0..s.pixels())
            .into_par_iter()
            .map(|p| accel.closest_hit(&ray(p)).map(hit_f64))
            .collect();
        let name = self.config.name();
        let bvh_mismatches = self
            .bvh_check
            .par_iter()
            .filter_map(|&p| {
                bvh_vs_brute_force(&accel, &ray(p)).map(|e| format!("{name} {p}: {e}"))
            })
            .collect();
        let packet_mismatches =
            packets_vs_single_rays(&accel, &(0..s.pixels()).map(ray).collect::<Vec<_>>(), w)
                .into_iter()
                .map(|e| format!("{name} {e}"))
                .collect();
        Traced {
            config: self.config,
            alpha: alpha.into_iter().map(|a| a != 0).collect(),
            depth_frame,
            prim_frame,
            hits,
            bvh_mismatches,
            packet_mismatches,
        }
    }
}

/// Where the packet queries on a `w x h` frame's rays (row-major) differ from the single-ray
/// queries, exactly: closest hits (distance, barycentrics, triangle) and any hits. The rays are
/// handed over in 8 x 8 blocks, as `render_frame` does.
fn packets_vs_single_rays<I: Intersector>(
    accel: &Accel<I>,
    rays: &[Ray<I::Real>],
    w: u32,
) -> Vec<String> {
    let (w, h) = (w as usize, rays.len() / w as usize);
    let order: Vec<usize> = (0..h.div_ceil(8) * w.div_ceil(8))
        .flat_map(|b| {
            let (bi, bj) = (b % w.div_ceil(8) * 8, b / w.div_ceil(8) * 8);
            (bj..(bj + 8).min(h)).flat_map(move |j| (bi..(bi + 8).min(w)).map(move |i| j * w + i))
        })
        .collect();
    let blocked: Vec<Ray<I::Real>> = order.iter().map(|&p| rays[p]).collect();
    let inf = <I::Real as Real>::INFINITY;
    let mut closest = vec![None; rays.len()];
    let mut any = vec![false; rays.len()];
    accel.closest_hits_packet(&blocked, inf, &mut closest);
    accel.any_hits_packet(&blocked, inf, &mut any);
    let mut bad = Vec::new();
    for (k, &p) in order.iter().enumerate() {
        let single = accel.closest_hit(&rays[p]);
        if closest[k] != single || any[k] != accel.any_hit(&rays[p], inf) {
            bad.push(format!(
                "pixel {p}: packet {:?} / any {}, single ray {single:?}",
                closest[k], any[k]
            ));
        }
    }
    bad
}

/// Renders `scene` through every configuration.
#[must_use]
pub fn trace_all(scene: &Scene, bvh_check: &[usize]) -> Vec<Traced> {
    configs()
        .into_iter()
        .map(|config| {
            backends::dispatch(config.backend, config.precision, Trace { scene, bvh_check, config })
        })
        .collect()
}

/// Where the BVH queries for `ray` differ from brute force, if anywhere: the closest hit
/// (distance, barycentrics and triangle, exactly), and any-hit queries with `t_max` infinite
/// and equal to the closest hit's distance (a hit at exactly `t_max` counts), both against
/// brute force and against what the closest hit implies; and just below that distance, where
/// nothing can be hit or the closest hit would be nearer (that one only through the BVH: brute
/// force would scan every triangle again for an answer already known).
fn bvh_vs_brute_force<I: Intersector>(accel: &Accel<I>, ray: &Ray<I::Real>) -> Option<String> {
    let inf = <I::Real as Real>::INFINITY;
    let closest = accel.closest_hit(ray);
    let brute = accel.closest_hit_brute_force(ray);
    if closest != brute {
        return Some(format!("closest_hit {closest:?} but brute force {brute:?}"));
    }
    let mut queries = vec![(inf, closest.is_some(), true)];
    if let Some(hit) = closest {
        let below = I::Real::from_f64(hit.t.to_f64() * (1.0 - 1e-6));
        queries.extend([(hit.t, true, true), (below, false, false)]);
    }
    for (t_max, expected, with_brute_force) in queries {
        let bvh = accel.any_hit(ray, t_max);
        let brute = if with_brute_force { accel.any_hit_brute_force(ray, t_max) } else { expected };
        if bvh != expected || brute != expected {
            return Some(format!(
                "any_hit(t_max {t_max}) {bvh}, brute force {brute}, expected {expected} \
                 (closest hit {closest:?})"
            ));
        }
    }
    None
}

/// A hit converted exactly to `f64`.
#[must_use]
pub fn hit_f64<T: Real>(h: Hit<T>) -> Hit<f64> {
    Hit { t: h.t.to_f64(), prim: h.prim, u: h.u.to_f64(), v: h.v.to_f64() }
}

/// Every triangle that one back end's kernel reports hit along each ray (brute force, no
/// BVH), with the distances: what a back end that reports a hit where another reports none
/// actually saw.
pub struct AllHits<'a> {
    /// The triangles.
    pub mesh: &'a Mesh,
    /// The `f64` rays, rounded to the kernel's precision as the camera rounds them.
    pub rays: &'a [Ray<f64>],
}

impl Job for AllHits<'_> {
    type Output = Vec<Vec<(u32, f64)>>;

    fn run<I: Intersector + 'static>(self, intersector: I) -> Self::Output {
        if self.rays.is_empty() {
            return Vec::new();
        }
        let prims: Vec<I::Prim> =
            self.mesh.triangles::<I::Real>().iter().map(|t| intersector.prepare(t)).collect();
        let inf = <I::Real as Real>::INFINITY;
        self.rays
            .iter()
            .map(|ray| {
                let ray = ray.cast::<I::Real>();
                let data = intersector.prepare_ray(&ray);
                let hits = prims.iter().enumerate().filter_map(|(k, prim)| {
                    let hit = intersector.intersect(prim, &ray, &data, inf)?;
                    Some((k as u32, hit.t.to_f64()))
                });
                hits.collect()
            })
            .collect()
    }
}

// ---- f64 geometry ----

pub use intersect::vec3::{cross, dot, length as norm, sub};

/// The distance between the line through `ray` and the segment `p q`.
///
/// Everything is projected onto the plane perpendicular to the ray's direction, where the
/// line is the point `0` and the segment stays a segment: the distance is that of `0` to the
/// projected segment.
#[must_use]
pub fn line_segment_distance(ray: &Ray<f64>, p: [f64; 3], q: [f64; 3]) -> f64 {
    let d = ray.dir.map(|x| x / norm(ray.dir));
    let perp = |v: [f64; 3]| {
        let along = dot(v, d);
        [v[0] - along * d[0], v[1] - along * d[1], v[2] - along * d[2]]
    };
    let w0 = perp(sub(p, ray.origin));
    let e = perp(sub(q, p));
    let ee = dot(e, e);
    let s = if ee > 0.0 { (-dot(w0, e) / ee).clamp(0.0, 1.0) } else { 0.0 };
    norm([w0[0] + s * e[0], w0[1] + s * e[1], w0[2] + s * e[2]])
}

/// The distance between the line through `ray` and the nearest edge of `tri`.
#[must_use]
pub fn edge_distance(ray: &Ray<f64>, tri: &Triangle<f64>) -> f64 {
    let [a, b, c] = tri.vertices();
    line_segment_distance(ray, a, b)
        .min(line_segment_distance(ray, b, c))
        .min(line_segment_distance(ray, c, a))
}

/// Whether the line through `ray` passes through the closed triangle (the three edge
/// functions `det[v_i - o, v_j - o, d]` have no two opposite signs; all zero means the ray
/// lies in the triangle's plane, which counts as not passing through).
#[must_use]
pub fn passes_through(ray: &Ray<f64>, tri: &Triangle<f64>) -> bool {
    let [a, b, c] = tri.vertices().map(|v| sub(v, ray.origin));
    let e = [dot(cross(a, b), ray.dir), dot(cross(b, c), ray.dir), dot(cross(c, a), ray.dir)];
    let (neg, pos) = (e.iter().any(|&x| x < 0.0), e.iter().any(|&x| x > 0.0));
    !(neg && pos) && (neg || pos)
}

/// The ray parameter where `ray` meets the plane of `tri`, and the cosine of the angle
/// between the ray and the plane's normal (how well conditioned that `t` is), if the ray is
/// not parallel to the plane.
#[must_use]
pub fn plane_hit(ray: &Ray<f64>, tri: &Triangle<f64>) -> Option<(f64, f64)> {
    let n = cross(sub(tri.b, tri.a), sub(tri.c, tri.a));
    let denom = dot(n, ray.dir);
    (denom != 0.0).then(|| {
        let t = dot(n, sub(tri.a, ray.origin)) / denom;
        (t, denom.abs() / (norm(n) * norm(ray.dir)))
    })
}

/// `|a - b| / max(|a|, |b|)` (0 when both are 0).
#[must_use]
pub fn relative_difference(a: f64, b: f64) -> f64 {
    let scale = a.abs().max(b.abs());
    if scale == 0.0 { 0.0 } else { (a - b).abs() / scale }
}

// ---- diff images ----

/// Both hit (or as expected).
pub const WHITE: [u8; 3] = [255, 255, 255];
/// Both missed.
pub const BLACK: [u8; 3] = [0, 0, 0];
/// Expected (or the first result) hit, got a miss.
pub const RED: [u8; 3] = [255, 0, 0];
/// Expected (or the first result) miss, got a hit.
pub const BLUE: [u8; 3] = [0, 64, 255];
/// Both hit, but the triangle or the distance is wrong.
pub const YELLOW: [u8; 3] = [255, 220, 0];
/// Not judged (too near an edge to call), hit.
pub const GREY: [u8; 3] = [128, 128, 128];
/// Not judged, missed.
pub const DARK_GREY: [u8; 3] = [48, 48, 48];

/// What the colours of a diff image mean, for panic messages.
pub const LEGEND: &str = "white: hit in both, black: missed in both, red: expected (or first) \
     hit but missed, blue: expected (or first) miss but hit, yellow: wrong triangle or depth, \
     grey / dark grey: not judged (near an edge), hit / missed";

/// The folder diff images go to: `test-output` in the target directory.
#[must_use]
pub fn output_dir() -> PathBuf {
    let tmp = Path::new(env!("CARGO_TARGET_TMPDIR"));
    tmp.parent().unwrap_or(tmp).join("test-output")
}

/// Writes an RGB image `name`-diff.png (`colours` row by row from the top) into
/// [`output_dir`] and returns its path, or a note saying why it could not be written.
#[must_use]
pub fn write_diff_image(name: &str, width: u32, height: u32, colours: &[[u8; 3]]) -> String {
    let dir = output_dir();
    let path = dir.join(format!("{name}-diff.png"));
    let buf: Vec<u8> = colours.iter().flatten().copied().collect();
    let image = image::RgbImage::from_raw(width, height, buf).expect("one colour per pixel");
    match std::fs::create_dir_all(&dir)
        .map_err(|e| e.to_string())
        .and_then(|()| image.save(&path).map_err(|e| e.to_string()))
    {
        Ok(()) => path.display().to_string(),
        Err(e) => format!("(diff image {} not written: {e})", path.display()),
    }
}
