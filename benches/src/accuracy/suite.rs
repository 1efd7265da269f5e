//! The suite: which rays, how many, and the rows they give for every back end.

use backends::{Backend, Job, Precision};
use bvh::accel::Accel;
use intersect::{Intersector, Ray, Triangle};

use super::degenerate::soup;
use super::mesh::TriMesh;
use super::rays::{
    Aim, AimedSet, axis_aligned_rays, camera_rays, edge_rays, grazing_rays, random_rays,
    surface_rays, vertex_rays,
};
use super::rows::{AccuracyRow, StabilityRow};
use super::runner::{
    AimedCounts, AimedVerdict, Pair, PairCounts, PairVerdict, SceneCounts, SceneVerdict, Subject,
    check_aimed, check_pairs, check_scene, judge_aimed, judge_pairs, judge_scene,
};

/// The seed of every generator (each family derives its own from it).
pub const SEED: u64 = 0x00ac_c0ac_0001;

/// How many rays of each family.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Sizes {
    /// Ordinary random rays through the bunny.
    pub random_rays: usize,
    /// Of those, how many (the first ones) are judged for the nearest triangle and the
    /// distance error (microseconds each for the reference).
    pub judged_rays: usize,
    /// Side in pixels of the bunny images compared between back ends (0: none).
    pub camera_side: u32,
    /// Rays at shared edges of the bunny, per aim.
    pub bunny_edges: usize,
    /// Rays at shared vertices of the bunny, per aim.
    pub bunny_vertices: usize,
    /// Rays per shared edge of the tile grid, per aim.
    pub tiles_per_edge: usize,
    /// Rays per interior vertex of the tile grid, per aim.
    pub tiles_per_vertex: usize,
    /// Sweeps: rays at shared edges of each moved or scaled mesh (the tile grid gets at
    /// least one per edge).
    pub sweep_edges: usize,
    /// Sweeps: rays at shared vertices of each moved or scaled mesh.
    pub sweep_vertices: usize,
    /// Sweeps: random rays through each moved or scaled mesh (0: none).
    pub sweep_random: usize,
    /// Grazing rays per mesh.
    pub grazing: usize,
    /// Axis-aligned rays per mesh.
    pub axis_aligned: usize,
    /// Rays starting on the surface, per mesh.
    pub on_surface: usize,
    /// Copies of each degenerate triangle kind.
    pub soup_copies: usize,
    /// Rays aimed at each soup triangle.
    pub soup_rays: usize,
}

impl Sizes {
    /// The bench's full run (about five minutes on two busy cores): a million random rays,
    /// every shared edge and closed vertex of the bunny (about 104,000 and 35,000).
    #[must_use]
    pub const fn full() -> Self {
        Self {
            random_rays: 1_000_000,
            judged_rays: 200_000,
            camera_side: 384,
            bunny_edges: 110_000,
            bunny_vertices: 36_000,
            tiles_per_edge: 8,
            tiles_per_vertex: 8,
            sweep_edges: 10_000,
            sweep_vertices: 4_000,
            sweep_random: 20_000,
            grazing: 6_000,
            axis_aligned: 20_000,
            on_surface: 6_000,
            soup_copies: 12,
            soup_rays: 3,
        }
    }

    /// The fast subset run by `cargo test` (seconds).
    #[must_use]
    pub const fn test() -> Self {
        Self {
            random_rays: 100_000,
            judged_rays: 10_000,
            camera_side: 0,
            bunny_edges: 3_000,
            bunny_vertices: 1_000,
            tiles_per_edge: 2,
            tiles_per_vertex: 2,
            sweep_edges: 1_500,
            sweep_vertices: 500,
            sweep_random: 0,
            grazing: 600,
            axis_aligned: 2_000,
            on_surface: 600,
            soup_copies: 3,
            soup_rays: 2,
        }
    }

    /// The bench's smoke run (`WEDGE_BENCH_QUICK=1`): every family, tiny sizes.
    #[must_use]
    pub const fn quick() -> Self {
        Self {
            random_rays: 4_000,
            judged_rays: 4_000,
            camera_side: 32,
            bunny_edges: 500,
            bunny_vertices: 200,
            tiles_per_edge: 1,
            tiles_per_vertex: 1,
            sweep_edges: 300,
            sweep_vertices: 100,
            sweep_random: 500,
            grazing: 150,
            axis_aligned: 500,
            on_surface: 150,
            soup_copies: 1,
            soup_rays: 1,
        }
    }
}

/// The reference's verdicts for both precisions, `[f32, f64]`.
fn both<V>(judge: impl Fn(Precision) -> V) -> [V; 2] {
    [judge(Precision::F32), judge(Precision::F64)]
}

fn index(p: Precision) -> usize {
    usize::from(p == Precision::F64)
}

struct AimedJob<'a> {
    set: &'a AimedSet,
    verdicts: &'a [Option<AimedVerdict>],
    with_t: bool,
}

impl Job for AimedJob<'_> {
    type Output = AimedCounts;
    fn run<I: Intersector + 'static>(self, k: I) -> AimedCounts {
        check_aimed(&k, self.set, self.verdicts, self.with_t)
    }
}

struct SceneJob<'a> {
    triangles: &'a [Triangle<f64>],
    rays: &'a [Ray<f64>],
    verdicts: &'a [SceneVerdict],
    t_rays: usize,
}

impl Job for SceneJob<'_> {
    type Output = SceneCounts;
    fn run<I: Intersector + 'static>(self, k: I) -> SceneCounts {
        let tris: Vec<Triangle<I::Real>> = self.triangles.iter().map(Triangle::cast).collect();
        let accel = Accel::build(k, &tris);
        check_scene(&accel, self.triangles, self.rays, self.verdicts, self.t_rays)
    }
}

struct PairJob<'a> {
    pairs: &'a [Pair],
    verdicts: &'a [PairVerdict],
}

impl Job for PairJob<'_> {
    type Output = PairCounts;
    fn run<I: Intersector + 'static>(self, k: I) -> PairCounts {
        check_pairs(&k, self.pairs, self.verdicts)
    }
}

/// Every subject's counts on an aimed set.
#[must_use]
pub fn run_aimed(
    set: &AimedSet,
    subjects: &[Subject],
    with_t: bool,
) -> Vec<(Subject, AimedCounts)> {
    let verdicts = both(|p| judge_aimed(set, p));
    subjects
        .iter()
        .map(|&s| {
            let verdicts = &verdicts[index(s.precision())];
            (s, s.run(AimedJob { set, verdicts, with_t }))
        })
        .collect()
}

/// Every subject's counts on rays through a whole scene; the first `judged` rays are judged
/// for the nearest triangle and the distance error.
#[must_use]
pub fn run_scene(
    triangles: &[Triangle<f64>],
    rays: &[Ray<f64>],
    subjects: &[Subject],
    judged: usize,
) -> Vec<(Subject, SceneCounts)> {
    let verdicts = both(|p| judge_scene(triangles, rays, p, judged));
    subjects
        .iter()
        .map(|&s| {
            let verdicts = &verdicts[index(s.precision())];
            (s, s.run(SceneJob { triangles, rays, verdicts, t_rays: judged }))
        })
        .collect()
}

/// Every subject's counts on ray-triangle pairs.
#[must_use]
pub fn run_pairs(pairs: &[Pair], subjects: &[Subject]) -> Vec<(Subject, PairCounts)> {
    let verdicts = both(|p| judge_pairs(pairs, p));
    subjects
        .iter()
        .map(|&s| (s, s.run(PairJob { pairs, verdicts: &verdicts[index(s.precision())] })))
        .collect()
}

/// The aimed sets of a mesh: edges and vertices, each aimed exactly and in `f64` only.
fn aimed_sets(mesh: &TriMesh, edges: usize, vertices: usize, seed: u64) -> Vec<(String, AimedSet)> {
    let mut out = Vec::new();
    for aim in [Aim::Exact, Aim::F64] {
        let e = edge_rays(mesh, edges, aim, seed ^ 0xed6e);
        out.push((format!("edges-{}", aim.name()), e));
        let v = vertex_rays(mesh, vertices, aim, seed ^ 0x0e27);
        out.push((format!("vertices-{}", aim.name()), v));
    }
    out
}

/// The rows of `results/accuracy.csv` (without timings): ordinary random rays and camera
/// rays through the bunny, and rays aimed at shared edges and vertices of the bunny and the
/// tile grid, for every back end, precision and the reference.
#[must_use]
pub fn accuracy_rows(
    sizes: &Sizes,
    bunny: &TriMesh,
    tiles: &TriMesh,
    cpu: &str,
) -> Vec<AccuracyRow> {
    let subjects = Subject::all();
    let mut rows = Vec::new();
    let triangles = bunny.triangle_list();
    let rays = random_rays(bunny, sizes.random_rays, SEED);
    for (s, c) in run_scene(&triangles, &rays, &subjects, sizes.judged_rays) {
        rows.push(AccuracyRow::from_scene(s, &bunny.name, "random", &c, cpu));
    }
    if sizes.camera_side > 0 {
        let rays = camera_rays(bunny, sizes.camera_side, sizes.camera_side);
        let results = run_scene(&triangles, &rays, &subjects, rays.len());
        let la = |p: Precision| {
            results
                .iter()
                .find(|(s, _)| s.name() == Backend::BASELINE.name() && s.precision() == p)
                .map(|(_, c)| c)
        };
        for (s, c) in &results {
            let mut row = AccuracyRow::from_scene(*s, &bunny.name, "camera", c, cpu);
            row.differs_from_la_per_million = la(s.precision()).map(|la| {
                let differ = la.prims.iter().zip(&c.prims).filter(|(a, b)| a != b).count();
                super::metrics::per_million(differ as u64, c.rays)
            });
            rows.push(row);
        }
    }
    let tiles_edges = tiles.shared_edges().len() * sizes.tiles_per_edge;
    let tiles_vertices = tiles.fans().len() * sizes.tiles_per_vertex;
    for (mesh, edges, vertices) in
        [(bunny, sizes.bunny_edges, sizes.bunny_vertices), (tiles, tiles_edges, tiles_vertices)]
    {
        for (name, set) in aimed_sets(mesh, edges, vertices, SEED) {
            for (s, c) in run_aimed(&set, &subjects, true) {
                rows.push(AccuracyRow::from_aimed(s, &mesh.name, &name, &c, cpu));
            }
        }
    }
    for row in &mut rows {
        let subject = subjects
            .iter()
            .copied()
            .find(|s| s.name() == row.backend && s.precision().name() == row.precision)
            .expect("every row comes from a subject");
        row.apply_limits(subject);
    }
    rows
}

/// A sweep: moved or scaled copies of a mesh.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Sweep {
    /// Every coordinate moved by 0, 10^2, 10^3 and 10^4 times the mesh's extent.
    Translate,
    /// Scaled about the origin by 10^-3 to 10^3.
    Scale,
}

impl Sweep {
    /// `(variant name, scale factor, offset in extents)` for each step.
    #[must_use]
    pub fn steps(self) -> Vec<(String, f64, f64)> {
        match self {
            Sweep::Translate => [(0, 0.0), (2, 1e2), (3, 1e3), (4, 1e4)]
                .into_iter()
                .map(|(k, f)| {
                    (if k == 0 { "offset=0".into() } else { format!("offset=1e{k}") }, 1.0, f)
                })
                .collect(),
            Sweep::Scale => {
                (-3..=3).map(|k: i32| (format!("scale=1e{k}"), 10f64.powi(k), 0.0)).collect()
            }
        }
    }

    /// `translate` or `scale`.
    #[must_use]
    pub const fn name(self) -> &'static str {
        match self {
            Sweep::Translate => "translate",
            Sweep::Scale => "scale",
        }
    }
}

/// The rows of one sweep over one mesh: at each step, rays aimed exactly at shared edges and
/// vertices of the moved mesh (built there, so they still pass exactly through its edges and
/// vertices), and the same random rays moved or scaled with the mesh.
#[must_use]
pub fn sweep_rows(
    sizes: &Sizes,
    mesh: &TriMesh,
    sweep: Sweep,
    subjects: &[Subject],
) -> Vec<StabilityRow> {
    let extent = mesh.extent();
    let base_rays = random_rays(mesh, sizes.sweep_random, SEED ^ 0x5eeb);
    let mut rows: Vec<StabilityRow> = Vec::new();
    let family = sweep.name();
    for (variant, factor, offset) in sweep.steps() {
        let shift = [offset * extent; 3];
        let moved = mesh.transformed(factor, shift);
        let edges =
            sizes.sweep_edges.max(if mesh.len() < 2048 { mesh.shared_edges().len() } else { 0 });
        for set in [
            edge_rays(&moved, edges, Aim::Exact, SEED ^ 0x5eed),
            vertex_rays(&moved, sizes.sweep_vertices, Aim::Exact, SEED ^ 0x5eef),
        ] {
            for (s, c) in run_aimed(&set, subjects, false) {
                let mut row = StabilityRow::from_aimed(s, family, &mesh.name, &variant, &c);
                row.ray_set = set.target.to_owned();
                rows.push(row);
            }
        }
        if !base_rays.is_empty() {
            let rays: Vec<Ray<f64>> = base_rays
                .iter()
                .map(|r| Ray::new(core::array::from_fn(|k| r.origin[k] * factor + shift[k]), r.dir))
                .collect();
            for (s, c) in run_scene(&moved.triangle_list(), &rays, subjects, 0) {
                rows.push(StabilityRow::from_scene(s, family, &mesh.name, &variant, "random", &c));
            }
        }
    }
    let base_variant = sweep.steps()[match sweep {
        Sweep::Translate => 0,
        Sweep::Scale => 3,
    }]
    .0
    .clone();
    let baseline: Vec<StabilityRow> = rows
        .iter()
        .filter(|r| r.variant == base_variant && r.ray_set == "random")
        .cloned()
        .collect();
    for row in rows.iter_mut().filter(|r| r.ray_set == "random") {
        if let Some(base) =
            baseline.iter().find(|b| b.backend == row.backend && b.precision == row.precision)
        {
            row.hit_fraction_change = Some(row.hit_fraction - base.hit_fraction);
            row.hit_fraction_exact_change = Some(row.hit_fraction_exact - base.hit_fraction_exact);
        }
    }
    rows
}

/// Grazing, axis-aligned and on-surface rays of one mesh.
#[must_use]
pub fn ray_family_rows(sizes: &Sizes, mesh: &TriMesh, subjects: &[Subject]) -> Vec<StabilityRow> {
    let mut rows = Vec::new();
    let grazing = grazing_rays(mesh, sizes.grazing, SEED ^ 0x6a2e);
    for kind in ["along-edge", "in-plane", "near-plane"] {
        let pairs: Vec<Pair> =
            grazing.iter().filter(|(k, _)| *k == kind).map(|(_, p)| *p).collect();
        for (s, c) in run_pairs(&pairs, subjects) {
            rows.push(StabilityRow::from_pairs(s, "grazing", &mesh.name, kind, &c));
        }
    }
    let rays = axis_aligned_rays(mesh, sizes.axis_aligned, SEED ^ 0xa715);
    for (s, c) in run_scene(&mesh.triangle_list(), &rays, subjects, 0) {
        rows.push(StabilityRow::from_scene(
            s,
            "axis-aligned",
            &mesh.name,
            "zero-components",
            "axis-aligned",
            &c,
        ));
    }
    let pairs = surface_rays(mesh, sizes.on_surface, SEED ^ 0x5a2f);
    for (s, c) in run_pairs(&pairs, subjects) {
        rows.push(StabilityRow::from_pairs(
            s,
            "on-surface",
            &mesh.name,
            "edge-and-vertex-origins",
            &c,
        ));
    }
    rows
}

/// The degenerate soup, one row per triangle kind.
#[must_use]
pub fn degenerate_rows(sizes: &Sizes, subjects: &[Subject]) -> Vec<StabilityRow> {
    let soup = soup(sizes.soup_copies, sizes.soup_rays, SEED ^ 0xde9e);
    let pairs = soup.pairs();
    let mut kinds: Vec<&str> = Vec::new();
    for (kind, _) in &pairs {
        if !kinds.contains(kind) {
            kinds.push(kind);
        }
    }
    let mut rows = Vec::new();
    for kind in kinds {
        let of_kind: Vec<Pair> =
            pairs.iter().filter(|(k, _)| *k == kind).map(|(_, p)| *p).collect();
        for (s, c) in run_pairs(&of_kind, subjects) {
            rows.push(StabilityRow::from_pairs(s, "degenerate", "soup", kind, &c));
        }
    }
    rows
}

/// Every row of `results/stability.csv`.
#[must_use]
pub fn stability_rows(sizes: &Sizes, bunny: &TriMesh, tiles: &TriMesh) -> Vec<StabilityRow> {
    let subjects = Subject::all();
    let mut rows = Vec::new();
    for mesh in [bunny, tiles] {
        for sweep in [Sweep::Translate, Sweep::Scale] {
            rows.extend(sweep_rows(sizes, mesh, sweep, &subjects));
        }
        rows.extend(ray_family_rows(sizes, mesh, &subjects));
    }
    rows.extend(degenerate_rows(sizes, &subjects));
    rows
}
