//! The rows of `results/accuracy.csv` and `results/stability.csv`, and the hard limits each
//! row is held to.

use serde::{Deserialize, Serialize};

use super::metrics::{TError, per_million, quantiles};
use super::runner::{AimedCounts, PairCounts, SceneCounts, Subject};

/// One row of `results/accuracy.csv`: one back end in one precision on one ray set.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct AccuracyRow {
    /// Back end (`la`, `la-mt`, `ga`, `ga-report`, `ga-plucker`, `exact`).
    pub backend: String,
    /// `f32` or `f64`.
    pub precision: String,
    /// `bunny` or `tiles`.
    pub scene: String,
    /// `random`, `camera` (closest hit through the BVH), or `edges-exact`, `edges-f64`,
    /// `vertices-exact`, `vertices-f64` (aimed rays against the triangles at the target).
    pub ray_set: String,
    /// Rays judged.
    pub rays: u64,
    /// Mean nanoseconds per closest-hit ray through the BVH, one thread, thread CPU time
    /// (timed sets only).
    pub ns_per_ray: Option<f64>,
    /// Rays the reference says hit.
    pub exact_hits: u64,
    /// Rays the back end says hit.
    pub hits: u64,
    /// Rays whose outcome differs from the reference's: hit/miss for scene sets; any of
    /// crack, double hit or wrong side for aimed sets.
    pub disagreements: u64,
    /// `disagreements` per million rays.
    pub disagree_per_million: f64,
    /// Rays whose nearest triangle differs from the reference's (of those judged for it).
    pub wrong_triangle: Option<u64>,
    /// `wrong_triangle` per million rays judged for it.
    pub wrong_triangle_per_million: Option<f64>,
    /// Hits whose distance error was measured.
    pub t_samples: u64,
    /// Median relative error of the hit distance `t`.
    pub t_rel_err_median: Option<f64>,
    /// 99.9th percentile of the relative error of `t`.
    pub t_rel_err_p999: Option<f64>,
    /// Largest relative error of `t`.
    pub t_rel_err_max: Option<f64>,
    /// Median error of `t` in ulps of the back end's precision.
    pub t_ulp_err_median: Option<f64>,
    /// 99.9th percentile of the error of `t` in ulps.
    pub t_ulp_err_p999: Option<f64>,
    /// Largest error of `t` in ulps.
    pub t_ulp_err_max: Option<f64>,
    /// Hits with a NaN or infinite `t`, `u` or `v`.
    pub nan_or_inf: u64,
    /// Hits with a NaN `t`, `u` or `v`.
    pub nan: u64,
    /// Hits with `t <= 0`, or `occludes` disagreeing with `intersect`.
    pub contract_violations: u64,
    /// Aimed sets: rays exactly through an edge or vertex (exact ties).
    pub ties: Option<u64>,
    /// Aimed sets: rays that hit none of the triangles at their target.
    pub cracks: Option<u64>,
    /// Aimed sets: rays that hit more than one of them.
    pub double_hits: Option<u64>,
    /// Aimed sets: double hits on rays that are not exact ties.
    pub double_hits_off_tie: Option<u64>,
    /// Aimed sets: rays that hit one triangle, not the reference's (exact ties excepted).
    pub wrong_side: Option<u64>,
    /// Camera set: pixels whose nearest triangle (or miss) differs from `la`'s in the same
    /// precision, per million.
    pub differs_from_la_per_million: Option<f64>,
    /// The hard limits this row is held to, in words (empty: none).
    pub limits: String,
    /// Whether it meets them (empty when there are none).
    pub meets_limits: Option<bool>,
    /// The CPU.
    pub cpu: String,
}

/// Error quantiles of a distance sample: `(rel median, p99.9, max, ulp median, p99.9, max)`.
fn error_columns(errors: &[TError]) -> [Option<f64>; 6] {
    let mut rel: Vec<f64> = errors.iter().map(|e| e.relative).collect();
    let mut ulps: Vec<f64> = errors.iter().map(|e| e.ulps).collect();
    let (r, u) = (quantiles(&mut rel), quantiles(&mut ulps));
    [
        r.map(|q| q.median),
        r.map(|q| q.p999),
        r.map(|q| q.max),
        u.map(|q| q.median),
        u.map(|q| q.p999),
        u.map(|q| q.max),
    ]
}

impl AccuracyRow {
    fn base(subject: Subject, scene: &str, ray_set: &str, cpu: &str) -> Self {
        Self {
            backend: subject.name().to_owned(),
            precision: subject.precision().name().to_owned(),
            scene: scene.to_owned(),
            ray_set: ray_set.to_owned(),
            cpu: cpu.to_owned(),
            ..Self::default()
        }
    }

    fn set_errors(&mut self, errors: &[TError]) {
        let [a, b, c, d, e, f] = error_columns(errors);
        self.t_samples = errors.len() as u64;
        (self.t_rel_err_median, self.t_rel_err_p999, self.t_rel_err_max) = (a, b, c);
        (self.t_ulp_err_median, self.t_ulp_err_p999, self.t_ulp_err_max) = (d, e, f);
    }

    /// A row for rays through a whole scene.
    #[must_use]
    pub fn from_scene(
        subject: Subject,
        scene: &str,
        ray_set: &str,
        c: &SceneCounts,
        cpu: &str,
    ) -> Self {
        let mut row = Self::base(subject, scene, ray_set, cpu);
        row.rays = c.rays;
        row.exact_hits = c.exact_hits;
        row.hits = c.hits;
        row.disagreements = c.false_hits + c.false_misses;
        row.disagree_per_million = per_million(row.disagreements, c.rays);
        row.wrong_triangle = (c.judged_closest > 0).then_some(c.wrong_triangle);
        row.wrong_triangle_per_million =
            (c.judged_closest > 0).then(|| per_million(c.wrong_triangle, c.judged_closest));
        row.nan_or_inf = c.nan_or_inf;
        row.nan = c.nan;
        row.contract_violations = c.contract_violations;
        row.set_errors(&c.t_errors);
        row
    }

    /// A row for rays aimed at shared edges or vertices.
    #[must_use]
    pub fn from_aimed(
        subject: Subject,
        scene: &str,
        ray_set: &str,
        c: &AimedCounts,
        cpu: &str,
    ) -> Self {
        let mut row = Self::base(subject, scene, ray_set, cpu);
        row.rays = c.rays;
        row.exact_hits = c.rays;
        row.hits = c.rays - c.cracks;
        row.disagreements = c.cracks + c.double_hits + c.wrong_side;
        row.disagree_per_million = per_million(row.disagreements, c.rays);
        row.nan_or_inf = c.nan_or_inf;
        row.nan = c.nan;
        row.contract_violations = c.contract_violations;
        row.ties = Some(c.ties);
        row.cracks = Some(c.cracks);
        row.double_hits = Some(c.double_hits);
        row.double_hits_off_tie = Some(c.double_hits_off_tie);
        row.wrong_side = Some(c.wrong_side);
        row.set_errors(&c.t_errors);
        row
    }

    /// Fills `limits` and `meets_limits` from the hard limits:
    /// - `random` rays: at most 10 hit/miss disagreements per million in `f32`, 1 in `f64`;
    ///   median distance error at most 1 ulp in `f32`;
    /// - aimed rays, back ends that claim watertightness: no crack, no double hit;
    /// - every row: no NaN, no hit with `t <= 0`.
    pub fn apply_limits(&mut self, subject: Subject) {
        let f32 = self.precision == "f32";
        let mut limits = vec!["nan=0".to_owned(), "contract_violations=0".to_owned()];
        let mut ok = self.nan == 0 && self.contract_violations == 0;
        if self.ray_set == "random" {
            let max = if f32 { 10.0 } else { 1.0 };
            limits.push(format!("disagree_per_million<={max}"));
            ok &= self.disagree_per_million <= max;
            if f32 {
                limits.push("t_ulp_err_median<=1".to_owned());
                ok &= self.t_ulp_err_median.is_some_and(|m| m <= 1.0);
            }
        }
        if self.cracks.is_some() && subject.claims_watertight() {
            limits.push("cracks=0".to_owned());
            limits.push("double_hits=0".to_owned());
            ok &= self.cracks == Some(0) && self.double_hits == Some(0);
        }
        self.limits = limits.join(" ");
        self.meets_limits = Some(ok);
    }
}

/// One row of `results/stability.csv`: one back end in one precision on one stress case.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct StabilityRow {
    /// `translate`, `scale`, `grazing`, `axis-aligned`, `on-surface` or `degenerate`.
    pub family: String,
    /// `bunny`, `tiles` or `soup`.
    pub scene: String,
    /// The case within the family: `offset=1e3` (times the extent), `scale=1e-3`, the kind
    /// of grazing ray, ...
    pub variant: String,
    /// `edges`, `vertices` (aimed, against the triangles at the target), `random`,
    /// `axis-aligned` (through the whole scene), or `pairs` (ray-triangle pairs).
    pub ray_set: String,
    /// Back end.
    pub backend: String,
    /// `f32` or `f64`.
    pub precision: String,
    /// Rays (or pairs) judged.
    pub rays: u64,
    /// Rays (pairs) the reference says hit.
    pub exact_hits: u64,
    /// Rays (pairs) the back end says hit.
    pub hits: u64,
    /// `exact_hits / rays`.
    pub hit_fraction_exact: f64,
    /// `hits / rays`.
    pub hit_fraction: f64,
    /// Sweeps, `random` rays: `hit_fraction` minus that of the same back end on the
    /// unmoved, unscaled mesh.
    pub hit_fraction_change: Option<f64>,
    /// The same change for the reference (in this row's precision): the part of the change
    /// due to the moved mesh's rounding, not to the back end.
    pub hit_fraction_exact_change: Option<f64>,
    /// Outcomes different from the reference's (hit/miss; for aimed rays, any of crack,
    /// double hit or wrong side).
    pub disagreements: u64,
    /// Hits where the reference misses.
    pub false_hits: u64,
    /// Aimed rays exactly through an edge or vertex.
    pub ties: Option<u64>,
    /// Aimed rays that hit none of the triangles at their target.
    pub cracks: Option<u64>,
    /// Aimed rays that hit more than one.
    pub double_hits: Option<u64>,
    /// Double hits on aimed rays that are not exact ties.
    pub double_hits_off_tie: Option<u64>,
    /// Aimed rays that hit one, not the reference's.
    pub wrong_side: Option<u64>,
    /// Hits with NaN or infinite results.
    pub nan_or_inf: u64,
    /// Hits with NaN results.
    pub nan: u64,
    /// Pairs: hits on degenerate (zero-area or non-finite) triangles.
    pub degenerate_hits: Option<u64>,
    /// Pairs: panics.
    pub panics: Option<u64>,
    /// Hits outside `(0, t_max]`, or `occludes` disagreeing with `intersect`.
    pub contract_violations: Option<u64>,
    /// The hard limits this row is held to, in words.
    pub limits: String,
    /// Whether it meets them.
    pub meets_limits: Option<bool>,
}

fn fraction(count: u64, total: u64) -> f64 {
    if total == 0 { 0.0 } else { count as f64 / total as f64 }
}

impl StabilityRow {
    fn base(subject: Subject, family: &str, scene: &str, variant: &str, ray_set: &str) -> Self {
        Self {
            family: family.to_owned(),
            scene: scene.to_owned(),
            variant: variant.to_owned(),
            ray_set: ray_set.to_owned(),
            backend: subject.name().to_owned(),
            precision: subject.precision().name().to_owned(),
            ..Self::default()
        }
    }

    fn set_counts(&mut self, rays: u64, exact_hits: u64, hits: u64) {
        (self.rays, self.exact_hits, self.hits) = (rays, exact_hits, hits);
        self.hit_fraction_exact = fraction(exact_hits, rays);
        self.hit_fraction = fraction(hits, rays);
    }

    /// A row for aimed rays (limits: no NaN, no contract violation; no crack and no double
    /// hit for back ends that claim watertightness).
    #[must_use]
    pub fn from_aimed(
        subject: Subject,
        family: &str,
        scene: &str,
        variant: &str,
        c: &AimedCounts,
    ) -> Self {
        let mut row = Self::base(subject, family, scene, variant, "aimed");
        row.set_counts(c.rays, c.rays, c.rays - c.cracks);
        row.disagreements = c.cracks + c.double_hits + c.wrong_side;
        (row.ties, row.cracks, row.double_hits) =
            (Some(c.ties), Some(c.cracks), Some(c.double_hits));
        row.double_hits_off_tie = Some(c.double_hits_off_tie);
        row.wrong_side = Some(c.wrong_side);
        row.nan_or_inf = c.nan_or_inf;
        row.nan = c.nan;
        row.contract_violations = Some(c.contract_violations);
        let sound = c.nan == 0 && c.contract_violations == 0;
        if subject.claims_watertight() {
            row.limits = "cracks=0 double_hits=0 nan=0 contract_violations=0".to_owned();
            row.meets_limits = Some(c.cracks == 0 && c.double_hits == 0 && sound);
        } else {
            row.limits = "nan=0 contract_violations=0".to_owned();
            row.meets_limits = Some(sound);
        }
        row
    }

    /// A row for rays through a whole scene (limits: no NaN, no hit with `t <= 0`).
    #[must_use]
    pub fn from_scene(
        subject: Subject,
        family: &str,
        scene: &str,
        variant: &str,
        ray_set: &str,
        c: &SceneCounts,
    ) -> Self {
        let mut row = Self::base(subject, family, scene, variant, ray_set);
        row.set_counts(c.rays, c.exact_hits, c.hits);
        row.disagreements = c.false_hits + c.false_misses;
        row.false_hits = c.false_hits;
        row.nan_or_inf = c.nan_or_inf;
        row.nan = c.nan;
        row.contract_violations = Some(c.contract_violations);
        row.limits = "nan=0 contract_violations=0".to_owned();
        row.meets_limits = Some(c.nan == 0 && c.contract_violations == 0);
        row
    }

    /// A row for ray-triangle pairs (limits: no panic, no NaN, no hit on a degenerate
    /// triangle, no contract violation; infinite results are counted, not limited: the
    /// reference itself reports `t = inf` where the exact `t` exceeds `f64::MAX`).
    #[must_use]
    pub fn from_pairs(
        subject: Subject,
        family: &str,
        scene: &str,
        variant: &str,
        c: &PairCounts,
    ) -> Self {
        let mut row = Self::base(subject, family, scene, variant, "pairs");
        row.set_counts(c.tests, c.exact_hits, c.hits);
        row.disagreements = c.false_hits + c.false_misses;
        row.false_hits = c.false_hits;
        row.nan_or_inf = c.nan_or_inf;
        row.nan = c.nan;
        row.degenerate_hits = Some(c.degenerate_hits);
        row.panics = Some(c.panics);
        row.contract_violations = Some(c.contract_violations);
        row.limits = "panics=0 nan=0 degenerate_hits=0 contract_violations=0".to_owned();
        row.meets_limits = Some(
            c.panics == 0 && c.nan == 0 && c.degenerate_hits == 0 && c.contract_violations == 0,
        );
        row
    }
}
