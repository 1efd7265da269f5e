//! Every back end, in both precisions, renders the same images: written once, run for every
//! back end through [`backends::dispatch`] (ripgrep's `SearcherTester` habit).
//!
//! Each scene is rendered by every configuration (5 back ends x 2 precisions) in `alpha` mode
//! (any-hit queries), `depth` and `prim` mode, and traced pixel by pixel with
//! [`Accel::closest_hit`](bvh::accel::Accel::closest_hit) to keep `f64` distances whole.
//! Then:
//!
//! - **Each configuration on its own**: the BVH queries equal brute force on a sample of
//!   pixels (every pixel of the small scenes), the packet queries equal the single-ray ones in
//!   every bit on every pixel, any-hit and closest-hit agree on every pixel,
//!   the render loop's frames equal the per-pixel queries, and every reported hit is checked
//!   against an independent `f64` computation: its distance against the plane of the
//!   triangle the kernel was given (to the tolerance, `common::Config::depth_tolerance`),
//!   and the ray must pass through that triangle or within [`EDGE_TOLERANCE`] of its edges.
//! - **Pairs of configurations** (every pair of back ends in the same precision, and each back
//!   end's `f32` against its `f64`): a pixel differs when one hits and the other misses, or
//!   both hit different triangles. At most [`MAX_DIFFERING_FRACTION`] of the pixels (the
//!   issue's 0.01 %, rounded down: 0 below 10,000 pixels, 1 up to 19,999) may differ, and
//!   only where the ray passes within [`EDGE_TOLERANCE`] of the radius of an edge of the
//!   triangles concerned (all triangles the hitting back end's kernel reports along the ray,
//!   for a hit against a miss; the nearer of the two, for different triangles). Where both
//!   hit the same triangle, the distances agree to the looser of the two precisions'
//!   tolerances.
//! - **`la` and `ga` alpha masks are identical** (0 differing pixels) in each precision.
//!
//! These are the rules for views in general position. Views along an axis of symmetry of a
//! mesh put whole rows of rays exactly through edges, where back ends legitimately break the
//! tie differently and the non-watertight ones may crack; they are checked under rules of
//! their own in [`on_axis_views_put_rays_exactly_through_edges`].
//!
//! A failure names every offending pixel with its ray, triangles and edge distances, and
//! writes a diff image (see [`common::LEGEND`]) to `target/test-output/`.

mod common;

use backends::{Backend, Precision};
use common::{
    AllHits, BLACK, BLUE, Config, LEGEND, RED, Scene, Traced, WHITE, YELLOW, camera, edge_distance,
    passes_through, plane_hit, relative_difference, trace_all, write_diff_image,
};
use intersect::{Hit, Ray};
use render::camera::Camera;

/// How near an edge a ray must pass for two back ends to be allowed to disagree about it,
/// relative to the scene's bounding-sphere radius.
const EDGE_TOLERANCE: f64 = 1e-4;

/// The largest fraction of pixels on which two configurations may disagree (0.01 %).
const MAX_DIFFERING_FRACTION: f64 = 1e-4;

/// At most this many pixels are described per failed check (the count is always given).
const SHOWN: usize = 6;

#[test]
fn star() {
    agree(&Scene::obj("star.obj", Camera::origin(), 128, 96), 1, &GENERIC_VIEW);
}

#[test]
fn cube_seen_from_a_corner() {
    // Three faces, every edge slanted: more to disagree about than the face-on view.
    agree(&Scene::obj("cube.obj", camera([1.6, 1.2, -2.4], [0.0; 3]), 128, 96), 1, &GENERIC_VIEW);
}

#[test]
fn icosphere() {
    let scene = Scene::obj("icosphere.obj", camera([0.0, 0.0, -4.0], [0.0; 3]), 128, 96);
    agree(&scene, 3, &GENERIC_VIEW);
}

#[test]
fn torus_in_perspective() {
    // Off the axis, so that no ray lies in a symmetry plane of the mesh (see
    // `on_axis_views_put_rays_exactly_through_edges` for the on-axis view).
    let scene = Scene::obj("torus.obj", camera([0.31, 1.13, -3.8], [0.02, -0.03, 0.0]), 160, 120);
    agree(&scene, 5, &GENERIC_VIEW);
}

#[test]
fn tiles_in_perspective() {
    let scene = Scene::obj("tiles.obj", camera([0.47, 0.83, -2.9], [0.01, 0.02, 0.0]), 128, 96);
    agree(&scene, 2, &GENERIC_VIEW);
}

#[test]
fn polygons() {
    let scene = Scene::obj("polygons.obj", camera([0.0, 0.0, -5.0], [0.0; 3]), 160, 120);
    agree(&scene, 1, &GENERIC_VIEW);
}

#[test]
fn stanford_bunny() {
    agree(&Scene::shared("stanford-bunny.obj", 128, 128), 211, &GENERIC_VIEW);
}

#[test]
fn teapot() {
    agree(&Scene::shared("teapot.obj", 160, 120), 23, &GENERIC_VIEW);
}

/// The torus and the tiles from the cameras `obj/README.md` suggests, on their axis of
/// symmetry: every pixel whose `x = +-y` (a whole diagonal of pixels) casts its ray in a
/// diagonal plane of the mesh, exactly through the edges lying in that plane (the torus's
/// 45 degree meridian, the tiles' diagonals). Such rays hit the shared edge exactly; each back
/// end breaks the tie by its own rule, and the non-watertight ones (`la-mt`, `ga`,
/// `ga-report`) may miss both triangles (a crack). So here ties are excused, except that
/// the watertight back ends (`la`, `ga-plucker`) must have identical alpha masks, cracks and
/// all; everything else is as for views in general position.
#[test]
fn on_axis_views_put_rays_exactly_through_edges() {
    for scene in [
        Scene::obj("torus.obj", camera([0.0, 0.0, -4.0], [0.0; 3]), 160, 120),
        Scene::obj("tiles.obj", camera([0.0, 0.0, -3.0], [0.0; 3]), 128, 96),
    ] {
        let traced = agree(&scene, 11, &SYMMETRIC_VIEW);
        // The premise: many rays pass exactly through an edge of the triangle they hit.
        let la64 = traced
            .iter()
            .find(|t| {
                t.config == Config { backend: Backend::LaWatertight, precision: Precision::F64 }
            })
            .expect("la-f64 is among the configurations");
        let exact = (0..scene.pixels())
            .filter(|&p| {
                la64.hits[p].is_some_and(|hit| {
                    let tri = scene.mesh.triangle::<f64>(hit.prim as usize);
                    edge_distance(&scene.ray(p), &tri) / scene.radius < SYMMETRIC_VIEW.tie_band
                })
            })
            .count();
        assert!(exact >= 20, "{}: only {exact} rays exactly through an edge", scene.name);
    }
}

/// Renders `scene` through every configuration and checks everything in the module
/// documentation under `rules`; BVH against brute force on every `bvh_stride`-th pixel.
/// Returns the renders, in [`common::configs`] order.
fn agree(scene: &Scene, bvh_stride: usize, rules: &Rules) -> Vec<Traced> {
    let sample: Vec<usize> = (0..scene.pixels()).step_by(bvh_stride).collect();
    let traced = trace_all(scene, &sample);
    let mut failures = Vec::new();
    for t in &traced {
        check_alone(scene, t, &mut failures);
    }

    let pairs = compared_pairs(&traced);
    // The kernels' own view of every pixel where some pair differs: all the triangles each
    // one hits along the ray, by brute force without the BVH.
    let mut pixels: Vec<usize> = pairs
        .iter()
        .flat_map(|&(a, b)| {
            let (a, b) = (&traced[a], &traced[b]);
            (0..scene.pixels()).filter(move |&p| {
                a.alpha[p] != b.alpha[p] || a.hits[p].map(|h| h.prim) != b.hits[p].map(|h| h.prim)
            })
        })
        .collect();
    pixels.sort_unstable();
    pixels.dedup();
    let rays: Vec<Ray<f64>> = pixels.iter().map(|&p| scene.ray(p)).collect();
    let all_hits: Vec<Vec<Vec<(u32, f64)>>> = traced
        .iter()
        .map(|t| {
            let job = AllHits { mesh: &scene.mesh, rays: &rays };
            backends::dispatch(t.config.backend, t.config.precision, job)
        })
        .collect();
    let kernel_hits = |config: usize, p: usize| -> &[(u32, f64)] {
        &all_hits[config][pixels.binary_search(&p).expect("a differing pixel")]
    };
    // On these pixels, near edges by construction, the BVH must agree with brute force too.
    for (c, t) in traced.iter().enumerate() {
        for &p in &pixels {
            let brute = nearest(kernel_hits(c, p));
            let got = t.hits[p].map(|h| (h.prim, h.t));
            if got != brute {
                failures.push(format!(
                    "{} pixel {:?}: closest hit {got:?} through the BVH, {brute:?} by brute force",
                    t.config.name(),
                    scene.ij(p)
                ));
            }
        }
    }

    let mut summary = Vec::new();
    for &(a, b) in &pairs {
        let kernel_hits = |first: bool, p: usize| kernel_hits(if first { a } else { b }, p);
        let judge = Judge { scene, rules, a: &traced[a], b: &traced[b], kernel_hits: &kernel_hits };
        let (alpha, closest) = (judge.alpha(&mut failures), judge.closest(&mut failures));
        if alpha.counted + alpha.ties + closest.counted + closest.ties > 0 {
            let (na, nb) = judge.names();
            summary.push(format!(
                "{na} vs {nb}: alpha {} differ + {} ties, closest {} differ + {} ties",
                alpha.counted, alpha.ties, closest.counted, closest.ties
            ));
        }
    }
    // Seen with `--nocapture`: what the scene's comparisons found.
    println!(
        "{} ({} pixels, at most {} may differ per pair): {}",
        scene.name,
        scene.pixels(),
        (MAX_DIFFERING_FRACTION * scene.pixels() as f64).floor(),
        if summary.is_empty() { "all identical".to_owned() } else { summary.join("; ") }
    );
    assert!(
        failures.is_empty(),
        "{}: {} failed checks (diff images: {LEGEND}):\n{}",
        scene.name,
        failures.len(),
        failures.join("\n")
    );
    traced
}

/// Pairs of configurations compared: every two back ends in the same precision, and each back
/// end's `f32` against its `f64`.
fn compared_pairs(traced: &[Traced]) -> Vec<(usize, usize)> {
    let mut pairs = Vec::new();
    for (a, ta) in traced.iter().enumerate() {
        for (b, tb) in traced.iter().enumerate().skip(a + 1) {
            let same_precision = ta.config.precision == tb.config.precision;
            let same_backend = ta.config.backend == tb.config.backend;
            if same_precision || same_backend {
                pairs.push((a, b));
            }
        }
    }
    pairs
}

/// The nearest of a kernel's hits, ties to the lower triangle index (as
/// [`Hit::nearer_than`]).
fn nearest(hits: &[(u32, f64)]) -> Option<(u32, f64)> {
    hits.iter().copied().min_by(|x, y| x.1.total_cmp(&y.1).then(x.0.cmp(&y.0)))
}

/// Checks of one configuration against itself and against `f64` geometry.
fn check_alone(scene: &Scene, t: &Traced, failures: &mut Vec<String>) {
    let name = t.config.name();
    failures.extend(t.bvh_mismatches.iter().take(SHOWN).map(|m| format!("BVH: {m}")));
    failures.extend(t.packet_mismatches.iter().take(SHOWN).map(|m| format!("packets: {m}")));
    let mut bad = Vec::new();
    for p in 0..scene.pixels() {
        let hit = t.hits[p];
        let (i, j) = scene.ij(p);
        if t.alpha[p] != hit.is_some() {
            bad.push(format!("({i}, {j}): any-hit says {}, closest hit {hit:?}", t.alpha[p]));
        }
        if t.prim_frame[p] != hit.map_or(u32::MAX, |h| h.prim)
            || t.depth_frame[p] != hit.map_or(f32::INFINITY, |h| h.t as f32)
        {
            bad.push(format!(
                "({i}, {j}): frames say triangle {} at {}, closest hit {hit:?}",
                t.prim_frame[p], t.depth_frame[p]
            ));
        }
        let Some(hit) = hit else { continue };
        // The kernel's exact inputs, judged in f64.
        let ray = t.config.kernel_ray(&scene.ray(p));
        let tri = t.config.kernel_triangle(&scene.mesh, hit.prim as usize);
        let edge = edge_distance(&ray, &tri) / scene.radius;
        if !passes_through(&ray, &tri) && edge > EDGE_TOLERANCE {
            bad.push(format!(
                "({i}, {j}): triangle {} reported hit, but the ray passes outside it, \
                 {edge:.3e} radii from its nearest edge",
                hit.prim
            ));
        }
        let plane = plane_hit(&ray, &tri);
        let off = plane.map_or(f64::INFINITY, |(tp, _)| relative_difference(hit.t, tp));
        if off > t.config.depth_tolerance() {
            bad.push(format!(
                "({i}, {j}): triangle {} hit at t = {}, its plane at (t, cos(ray, normal)) = \
                 {plane:?}: relative difference {off:.3e} > {:e}",
                hit.prim,
                hit.t,
                t.config.depth_tolerance()
            ));
        }
    }
    if !bad.is_empty() {
        failures.push(format!(
            "{name}: {} pixels inconsistent:\n    {}",
            bad.len(),
            bad.iter().take(SHOWN).cloned().collect::<Vec<_>>().join("\n    ")
        ));
    }
}

/// Which differences a comparison allows.
struct Rules {
    /// A differing pixel whose ray passes nearer than this many radii to the edges concerned
    /// (measured as for [`EDGE_TOLERANCE`]) is a tie: a ray exactly through an edge, resolved
    /// by each back end's own rule. Ties are not counted against [`MAX_DIFFERING_FRACTION`] nor
    /// against [`Rules::identical`]. 0 for generic views, where exact ties do not happen.
    tie_band: f64,
    /// Pairs whose alpha masks must be identical apart from ties.
    identical: fn(Config, Config) -> bool,
    /// Pairs whose alpha masks must be identical, ties included.
    identical_with_ties: fn(Config, Config) -> bool,
}

/// The rules for a view in general position: `la` and `ga` alpha masks identical,
/// nothing excused as a tie.
const GENERIC_VIEW: Rules =
    Rules { tie_band: 0.0, identical: la_and_ga, identical_with_ties: never };

/// For a view whose rays pass exactly through edges by symmetry: ties are excused, except
/// between the watertight back ends, which must leave no crack there.
const SYMMETRIC_VIEW: Rules =
    Rules { tie_band: 1e-9, identical: la_and_ga, identical_with_ties: both_watertight };

/// `la` against `ga` in the same precision.
fn la_and_ga(a: Config, b: Config) -> bool {
    a.precision == b.precision
        && matches!(
            (a.backend, b.backend),
            (Backend::LaWatertight, Backend::G3Frame) | (Backend::G3Frame, Backend::LaWatertight)
        )
}

/// Both back ends watertight (`la`, `ga-plucker`: their kernels' guarantees).
fn both_watertight(a: Config, b: Config) -> bool {
    let watertight = |c: Config| c.backend.guarantees().watertight;
    watertight(a) && watertight(b)
}

fn never(_: Config, _: Config) -> bool {
    false
}

/// How a differing pixel is judged.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Verdict {
    /// Within the tie band of an edge.
    Tie,
    /// Within the edge tolerance.
    AtEdge,
    /// Farther: a real disagreement.
    NotAtEdge,
}

/// Compares two configurations' images of one scene.
struct Judge<'a> {
    scene: &'a Scene,
    rules: &'a Rules,
    a: &'a Traced,
    b: &'a Traced,
    /// All the hits of a configuration's kernel along a differing pixel's ray: `(a or b, pixel)`.
    kernel_hits: &'a dyn Fn(bool, usize) -> &'a [(u32, f64)],
}

/// What a comparison found.
#[derive(Default)]
struct Tally {
    /// Differing pixels, ties left out.
    counted: usize,
    ties: usize,
    not_at_edge: usize,
    notes: Vec<String>,
}

impl Tally {
    fn add(&mut self, (verdict, note): (Verdict, String)) {
        match verdict {
            Verdict::Tie => self.ties += 1,
            Verdict::AtEdge => self.counted += 1,
            Verdict::NotAtEdge => {
                self.counted += 1;
                self.not_at_edge += 1;
            }
        }
        // Real disagreements first in the message.
        if verdict == Verdict::NotAtEdge {
            self.notes.insert(0, note);
        } else {
            self.notes.push(note);
        }
    }

    fn shown(&self, extra: &[String]) -> String {
        let all: Vec<&String> = self.notes.iter().chain(extra).take(SHOWN).collect();
        all.iter().map(|s| format!("\n    {s}")).collect()
    }
}

impl Judge<'_> {
    fn names(&self) -> (String, String) {
        (self.a.config.name(), self.b.config.name())
    }

    /// How many differing pixels are allowed: the 0.01 %, rounded down.
    fn allowed(&self) -> usize {
        (MAX_DIFFERING_FRACTION * self.scene.pixels() as f64).floor() as usize
    }

    fn verdict(&self, distance: f64) -> Verdict {
        if distance < self.rules.tie_band {
            Verdict::Tie
        } else if distance <= EDGE_TOLERANCE {
            Verdict::AtEdge
        } else {
            Verdict::NotAtEdge
        }
    }

    /// Alpha masks: a pixel where one hits and the other misses is allowed only where every
    /// triangle the hitting kernel reports passes within the edge tolerance of the ray.
    fn alpha(&self, failures: &mut Vec<String>) -> Tally {
        let (na, nb) = self.names();
        let mut tally = Tally::default();
        for p in 0..self.scene.pixels() {
            if self.a.alpha[p] != self.b.alpha[p] {
                tally.add(self.one_sided(p, self.a.alpha[p]));
            }
        }
        let (ca, cb) = (self.a.config, self.b.config);
        let (allowed, ties_allowed) = if (self.rules.identical_with_ties)(ca, cb) {
            (0, false)
        } else if (self.rules.identical)(ca, cb) {
            (0, true)
        } else {
            (self.allowed(), true)
        };
        if tally.counted > allowed || tally.not_at_edge > 0 || (tally.ties > 0 && !ties_allowed) {
            let image = self.diff_image("alpha", |p| match (self.a.alpha[p], self.b.alpha[p]) {
                (true, true) => WHITE,
                (false, false) => BLACK,
                (true, false) => RED,
                (false, true) => BLUE,
            });
            failures.push(format!(
                "{na} vs {nb}, alpha: {} pixels differ (allowed {allowed}), {} of them not at an \
                 edge, and {} ties (rays exactly through an edge, {}); diff image {image}{}",
                tally.counted,
                tally.not_at_edge,
                tally.ties,
                if ties_allowed { "allowed" } else { "not allowed: no cracks" },
                tally.shown(&[])
            ));
        }
        tally
    }

    /// Closest hits: hit against miss as for alpha; different triangles only where the ray
    /// passes within the edge tolerance of the nearer one's edges; the same triangle at the
    /// same distance to the looser precision's tolerance.
    fn closest(&self, failures: &mut Vec<String>) -> Tally {
        let (na, nb) = self.names();
        let tolerance = self.a.config.depth_tolerance().max(self.b.config.depth_tolerance());
        let mut tally = Tally::default();
        let mut depth = Vec::new();
        let mut colours = Vec::with_capacity(self.scene.pixels());
        for p in 0..self.scene.pixels() {
            let (i, j) = self.scene.ij(p);
            let colour = match (self.a.hits[p], self.b.hits[p]) {
                (None, None) => BLACK,
                (Some(x), Some(y)) if x.prim == y.prim => {
                    let rel = relative_difference(x.t, y.t);
                    if rel <= tolerance {
                        WHITE
                    } else {
                        let cos = plane_hit(&self.scene.ray(p), &self.tri(x.prim)).map(|(_, c)| c);
                        depth.push(format!(
                            "({i}, {j}) triangle {}: t = {} ({na}) and {} ({nb}), relative \
                             difference {rel:.3e} > {tolerance:e}; cos(ray, normal) {cos:?}",
                            x.prim, x.t, y.t
                        ));
                        YELLOW
                    }
                }
                (Some(x), Some(y)) => {
                    tally.add(self.different_triangles(p, x, y));
                    YELLOW
                }
                (Some(_), None) => {
                    tally.add(self.one_sided(p, true));
                    RED
                }
                (None, Some(_)) => {
                    tally.add(self.one_sided(p, false));
                    BLUE
                }
            };
            colours.push(colour);
        }
        let allowed = self.allowed();
        if tally.counted > allowed || tally.not_at_edge > 0 || !depth.is_empty() {
            let image = self.diff_image("closest", |p| colours[p]);
            failures.push(format!(
                "{na} vs {nb}, closest hit: {} pixels differ (allowed {allowed}), {} of them not \
                 at an edge, {} ties (allowed), {} depths differ; diff image {image}{}",
                tally.counted,
                tally.not_at_edge,
                tally.ties,
                depth.len(),
                tally.shown(&depth)
            ));
        }
        tally
    }

    /// Triangle `k` in `f64`.
    fn tri(&self, k: u32) -> intersect::Triangle<f64> {
        self.scene.mesh.triangle::<f64>(k as usize)
    }

    /// One side hit pixel `p` (`a` if `a_hits`), the other missed: judged by the farthest
    /// of the edges of all the triangles the hitting kernel reports (the other missed every
    /// one of them).
    fn one_sided(&self, p: usize, a_hits: bool) -> (Verdict, String) {
        let ray = self.scene.ray(p);
        let (i, j) = self.scene.ij(p);
        let (na, nb) = self.names();
        let hitter = if a_hits { na } else { nb };
        let hits = (self.kernel_hits)(a_hits, p);
        // No hit by brute force where the BVH found one is inconsistent: never excused.
        let mut distance = if hits.is_empty() { f64::INFINITY } else { 0.0f64 };
        let mut parts = Vec::new();
        for &(k, t) in hits {
            let tri = self.tri(k);
            let edge = edge_distance(&ray, &tri) / self.scene.radius;
            distance = distance.max(edge);
            parts.push(format!(
                "triangle {k} {:?} at t = {t}, nearest edge {edge:.3e} radii",
                tri.vertices()
            ));
        }
        let verdict = self.verdict(distance);
        let note = format!(
            "({i}, {j}) only {hitter} hits, {}: ray {:?} + t {:?}; its kernel hits: {}",
            describe(verdict),
            ray.origin,
            ray.dir,
            if parts.is_empty() { "nothing (inconsistent)".to_owned() } else { parts.join("; ") }
        );
        (verdict, note)
    }

    /// Both hit, different triangles: judged by the edges of the nearer one (the other side
    /// must have missed it, or found the two at the same distance, which happens only at a
    /// shared edge).
    fn different_triangles(&self, p: usize, x: Hit<f64>, y: Hit<f64>) -> (Verdict, String) {
        let ray = self.scene.ray(p);
        let (i, j) = self.scene.ij(p);
        let (na, nb) = self.names();
        let nearer = if x.nearer_than(&y) { x.prim } else { y.prim };
        let edge = |k| edge_distance(&ray, &self.tri(k)) / self.scene.radius;
        let verdict = self.verdict(edge(nearer));
        let note = format!(
            "({i}, {j}) different triangles, {}: {na} triangle {} at t = {} (nearest edge \
             {:.3e} radii), {nb} triangle {} at t = {} ({:.3e} radii); ray {:?} + t {:?}",
            describe(verdict),
            x.prim,
            x.t,
            edge(x.prim),
            y.prim,
            y.t,
            edge(y.prim),
            ray.origin,
            ray.dir
        );
        (verdict, note)
    }

    fn diff_image(&self, what: &str, colour: impl Fn(usize) -> [u8; 3]) -> String {
        let (na, nb) = self.names();
        let colours: Vec<[u8; 3]> = (0..self.scene.pixels()).map(colour).collect();
        let name = format!("agree-{}-{na}-vs-{nb}-{what}", self.scene.name);
        write_diff_image(&name, self.scene.width, self.scene.height, &colours)
    }
}

fn describe(verdict: Verdict) -> &'static str {
    match verdict {
        Verdict::Tie => "a tie (ray exactly through an edge)",
        Verdict::AtEdge => "at an edge",
        Verdict::NotAtEdge => "NOT at an edge",
    }
}
