//! Running one back end on one family of rays and comparing with the exact reference.
//!
//! Every check is a generic function over [`Intersector`], so each back end and precision is
//! compiled and run with static dispatch; [`Subject::run`] picks one at run time (through
//! [`backends::dispatch`] for the back ends, directly for the reference). The reference's
//! verdicts ([`judge_aimed`], [`judge_scene`], [`judge_pairs`]) are computed once per precision
//! from exactly the values a kernel of that precision sees: the suite's `f64` rays and
//! triangles rounded to the kernel's precision, then converted back to `f64` (exact).

use std::panic::{AssertUnwindSafe, catch_unwind};

use backends::{Backend, Guarantees, Job, Precision, dispatch};
use bvh::accel::Accel;
use exact::predicates::edge_sign;
use exact::{Exact, Sign};
use intersect::{Intersector, Ray, Real, Triangle, TriangleHit};

use super::metrics::{TError, facing_sign, t_error};
use super::rays::AimedSet;

/// One row subject: a back end in one precision, or the exact reference (`f64` only).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Subject {
    /// `exact::Exact`.
    Exact,
    /// A back end of the registry (`backends`), in one precision.
    Kernel(Backend, Precision),
}

impl Subject {
    /// Every back end in both precisions, then the reference.
    #[must_use]
    pub fn all() -> Vec<Subject> {
        let mut all = Self::kernels();
        all.push(Subject::Exact);
        all
    }

    /// Every back end of the registry ([`Backend::ALL`], the order of the tables) in both
    /// precisions (f32 first).
    #[must_use]
    pub fn kernels() -> Vec<Subject> {
        Precision::ALL
            .into_iter()
            .flat_map(|p| Backend::ALL.map(|b| Subject::Kernel(b, p)))
            .collect()
    }

    /// The back end's name (`la`, `ga-plucker`, ..., `exact`).
    #[must_use]
    pub fn name(self) -> &'static str {
        struct Name;
        impl Job for Name {
            type Output = &'static str;
            fn run<I: Intersector + 'static>(self, _: I) -> &'static str {
                I::NAME
            }
        }
        self.run(Name)
    }

    /// The precision of its rays, triangles and arithmetic.
    #[must_use]
    pub fn precision(self) -> Precision {
        match self {
            Subject::Exact => Precision::F64,
            Subject::Kernel(_, p) => p,
        }
    }

    /// What the kernel declares it guarantees ([`Intersector::GUARANTEES`]).
    #[must_use]
    pub const fn guarantees(self) -> Guarantees {
        match self {
            Subject::Exact => <Exact as Intersector>::GUARANTEES,
            Subject::Kernel(backend, _) => backend.guarantees(),
        }
    }

    /// Whether the back end declares that rays through shared edges and vertices never slip
    /// through (`la` and `ga-plucker`; the reference too, by its tie rule).
    #[must_use]
    pub const fn claims_watertight(self) -> bool {
        self.guarantees().watertight
    }

    /// Runs `job` with this subject's intersector.
    pub fn run<J: Job>(self, job: J) -> J::Output {
        match self {
            Subject::Exact => job.run(Exact),
            Subject::Kernel(backend, precision) => dispatch(backend, precision, job),
        }
    }
}

/// A ray as a kernel of `precision` sees it, in `f64`.
#[must_use]
pub fn seen_ray(ray: &Ray<f64>, precision: Precision) -> Ray<f64> {
    match precision {
        Precision::F32 => ray.cast::<f32>().cast(),
        Precision::F64 => *ray,
    }
}

/// A triangle as a kernel of `precision` sees it, in `f64`.
#[must_use]
pub fn seen_triangle(tri: &Triangle<f64>, precision: Precision) -> Triangle<f64> {
    match precision {
        Precision::F32 => tri.cast::<f32>().cast(),
        Precision::F64 => *tri,
    }
}

fn finite_hit<T: Real>(h: &TriangleHit<T>) -> bool {
    h.t.is_finite() && h.u.is_finite() && h.v.is_finite()
}

/// `t > 0` (false for NaN).
fn positive<T: Real>(t: T) -> bool {
    t > T::ZERO
}

fn nan_hit<T: Real>(h: &TriangleHit<T>) -> bool {
    h.t.is_nan() || h.u.is_nan() || h.v.is_nan()
}

/// The reference's verdict on one aimed ray.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct AimedVerdict {
    /// Which of the ray's triangles it hits (it hits exactly one of them).
    pub side: usize,
    /// Whether the ray passes exactly through an edge of one of its triangles (an exact tie,
    /// decided by the tie rule), rather than near it.
    pub tie: bool,
}

/// The reference's verdict for each aimed ray in `precision`, or `None` for a ray left out
/// because it does not really cross the surface there: the triangles at its target do not
/// all face it the same way (a fold seen along the ray, or a triangle collapsed to zero area
/// by rounding), or, as a check, the reference does not find exactly one of them hit.
#[must_use]
pub fn judge_aimed(set: &AimedSet, precision: Precision) -> Vec<Option<AimedVerdict>> {
    set.rays
        .iter()
        .map(|aimed| {
            let ray = seen_ray(&aimed.ray, precision);
            let tris: Vec<Triangle<f64>> = aimed
                .around
                .iter()
                .map(|&t| seen_triangle(&set.mesh.triangle(t), precision))
                .collect();
            // No fold seen along the ray: every triangle there faces it the same way, so the
            // ray crosses the surface exactly once whatever the tie rule (a fold seen edge-on
            // is crossed once or three times depending on which side a perturbation takes).
            let facing: Vec<Option<i32>> = tris.iter().map(|t| facing_sign(t, ray.dir)).collect();
            if facing[0].is_none_or(|f| f == 0) || facing.iter().any(|f| *f != facing[0]) {
                return None;
            }
            let mut hit = tris
                .iter()
                .enumerate()
                .filter(|(_, tri)| Exact.crossing(tri, &ray, f64::INFINITY).is_some());
            let (side, _) = hit.next()?;
            if hit.next().is_some() {
                return None;
            }
            let tie = tris.iter().any(|tri| {
                let [a, b, c] = tri.vertices();
                [(a, b), (b, c), (c, a)]
                    .into_iter()
                    .any(|(p, q)| edge_sign(ray.origin, ray.dir, p, q) == Some(Sign::Zero))
            });
            Some(AimedVerdict { side, tie })
        })
        .collect()
}

/// What a back end did with the aimed rays that the reference kept.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct AimedCounts {
    /// Rays judged (those the reference kept).
    pub rays: u64,
    /// Of those, rays exactly through an edge or vertex (exact ties).
    pub ties: u64,
    /// Rays that hit none of the triangles at their edge or vertex.
    pub cracks: u64,
    /// Rays that hit more than one of them (any-hit reports both sides).
    pub double_hits: u64,
    /// Double hits on rays that are not exact ties.
    pub double_hits_off_tie: u64,
    /// Rays that hit exactly one, not the one the reference hits, and are not exact ties
    /// (on a tie either single triangle is right: the reference's choice is a convention).
    pub wrong_side: u64,
    /// Hits with a NaN or infinite `t`, `u` or `v`.
    pub nan_or_inf: u64,
    /// Hits with a NaN `t`, `u` or `v`.
    pub nan: u64,
    /// Hits with `t <= 0`, or `occludes` disagreeing with `intersect`.
    pub contract_violations: u64,
    /// Distance errors of every hit (when asked for).
    pub t_errors: Vec<TError>,
}

/// Runs `k` on every kept aimed ray against the triangles at its edge or vertex.
pub fn check_aimed<I: Intersector>(
    k: &I,
    set: &AimedSet,
    verdicts: &[Option<AimedVerdict>],
    with_t: bool,
) -> AimedCounts {
    let mut out = AimedCounts::default();
    let inf = I::Real::INFINITY;
    for (aimed, verdict) in set.rays.iter().zip(verdicts) {
        let Some(verdict) = verdict else { continue };
        let ray: Ray<I::Real> = aimed.ray.cast();
        let rd = k.prepare_ray(&ray);
        let (mut hits, mut first) = (0, None);
        for (j, &t) in aimed.around.iter().enumerate() {
            let tri: Triangle<I::Real> = set.mesh.triangle(t).cast();
            let prim = k.prepare(&tri);
            let hit = k.intersect(&prim, &ray, &rd, inf);
            out.contract_violations +=
                u64::from(hit.is_some() != k.occludes(&prim, &ray, &rd, inf));
            if let Some(h) = hit {
                hits += 1;
                first.get_or_insert(j);
                out.nan += u64::from(nan_hit(&h));
                out.contract_violations += u64::from(!positive(h.t));
                if !finite_hit(&h) {
                    out.nan_or_inf += 1;
                } else if with_t
                    && let Some(e) =
                        t_error(&tri.cast(), &ray.cast(), h.t.to_f64(), I::Real::MANTISSA_DIGITS)
                {
                    out.t_errors.push(e);
                }
            }
        }
        out.rays += 1;
        out.ties += u64::from(verdict.tie);
        out.cracks += u64::from(hits == 0);
        out.double_hits += u64::from(hits > 1);
        out.double_hits_off_tie += u64::from(hits > 1 && !verdict.tie);
        out.wrong_side += u64::from(hits == 1 && first != Some(verdict.side) && !verdict.tie);
    }
    out
}

/// The reference's verdict on one ray through a whole scene.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SceneVerdict {
    /// Whether the ray hits any triangle.
    pub hit: bool,
    /// The nearest triangle hit, when this ray was judged for it.
    pub closest: Option<u32>,
}

/// The reference's verdicts on `rays` through the scene `triangles` in `precision`: hit or
/// miss for every ray (cheap: no distance is computed), and the nearest triangle for the first
/// `closest_rays` rays (microseconds per hit: distances are computed exactly).
#[must_use]
pub fn judge_scene(
    triangles: &[Triangle<f64>],
    rays: &[Ray<f64>],
    precision: Precision,
    closest_rays: usize,
) -> Vec<SceneVerdict> {
    let tris: Vec<Triangle<f64>> = triangles.iter().map(|t| seen_triangle(t, precision)).collect();
    let accel = Accel::build(Exact, &tris);
    rays.iter()
        .enumerate()
        .map(|(i, ray)| {
            let ray = seen_ray(ray, precision);
            let hit = accel.any_hit(&ray, f64::INFINITY);
            let closest = if hit && i < closest_rays {
                accel.closest_hit(&ray).map(|h| h.prim)
            } else {
                None
            };
            SceneVerdict { hit, closest }
        })
        .collect()
}

/// What a back end did with rays through a whole scene (closest hit, through its BVH).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SceneCounts {
    /// Rays traced.
    pub rays: u64,
    /// Rays the reference says hit.
    pub exact_hits: u64,
    /// Rays the back end says hit.
    pub hits: u64,
    /// Hits where the reference says miss.
    pub false_hits: u64,
    /// Misses where the reference says hit.
    pub false_misses: u64,
    /// Rays both say hit and whose nearest triangle the reference computed.
    pub judged_closest: u64,
    /// Of those, rays where the back end's nearest triangle is another one.
    pub wrong_triangle: u64,
    /// Hits with a NaN or infinite `t`, `u` or `v`.
    pub nan_or_inf: u64,
    /// Hits with a NaN `t`, `u` or `v`.
    pub nan: u64,
    /// Hits with `t <= 0`.
    pub contract_violations: u64,
    /// Distance errors of the hits of the first `t_rays` rays.
    pub t_errors: Vec<TError>,
    /// The triangle each ray hit (for comparing images between back ends).
    pub prims: Vec<Option<u32>>,
}

/// Traces `rays` through `accel` (closest hit) and compares with the reference's verdicts;
/// distance errors for the hits among the first `t_rays` rays.
pub fn check_scene<I: Intersector>(
    accel: &Accel<I>,
    triangles: &[Triangle<f64>],
    rays: &[Ray<f64>],
    verdicts: &[SceneVerdict],
    t_rays: usize,
) -> SceneCounts {
    let mut out = SceneCounts { prims: Vec::with_capacity(rays.len()), ..SceneCounts::default() };
    for (i, (ray, verdict)) in rays.iter().zip(verdicts).enumerate() {
        let ray: Ray<I::Real> = ray.cast();
        let hit = accel.closest_hit(&ray);
        out.rays += 1;
        out.exact_hits += u64::from(verdict.hit);
        out.hits += u64::from(hit.is_some());
        out.false_hits += u64::from(hit.is_some() && !verdict.hit);
        out.false_misses += u64::from(hit.is_none() && verdict.hit);
        out.prims.push(hit.map(|h| h.prim));
        let Some(h) = hit else { continue };
        let as_triangle_hit = TriangleHit { t: h.t, u: h.u, v: h.v };
        out.nan += u64::from(nan_hit(&as_triangle_hit));
        out.contract_violations += u64::from(!positive(h.t));
        if !finite_hit(&as_triangle_hit) {
            out.nan_or_inf += 1;
            continue;
        }
        if let Some(exact) = verdict.closest {
            out.judged_closest += 1;
            out.wrong_triangle += u64::from(exact != h.prim);
        }
        if i < t_rays {
            let tri: Triangle<I::Real> = triangles[h.prim as usize].cast();
            let e = t_error(&tri.cast(), &ray.cast(), h.t.to_f64(), I::Real::MANTISSA_DIGITS);
            out.t_errors.extend(e);
        }
    }
    out
}

/// One ray against one triangle, with its `t_max`: the unit of the grazing, on-surface and
/// degenerate families, tested without a BVH (a BVH may rightly skip a triangle with NaN
/// coordinates, and here every kernel must see every pair).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pair {
    /// The ray.
    pub ray: Ray<f64>,
    /// The triangle.
    pub tri: Triangle<f64>,
    /// Hits count within `0 < t <= t_max`.
    pub t_max: f64,
}

/// The reference's verdict on a pair.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PairVerdict {
    /// Whether the ray hits the triangle.
    pub hit: bool,
    /// Whether the triangle can be hit at all (finite, non-zero area).
    pub hittable: bool,
}

/// The reference's verdict on each pair in `precision`.
#[must_use]
pub fn judge_pairs(pairs: &[Pair], precision: Precision) -> Vec<PairVerdict> {
    pairs
        .iter()
        .map(|pair| {
            let prim = Exact.prepare(&seen_triangle(&pair.tri, precision));
            let t_max = match precision {
                Precision::F32 => f64::from(pair.t_max as f32),
                Precision::F64 => pair.t_max,
            };
            let hit = Exact.occludes(&prim, &seen_ray(&pair.ray, precision), &(), t_max);
            PairVerdict { hit, hittable: prim.is_hittable() }
        })
        .collect()
}

/// What a back end did with a list of pairs.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct PairCounts {
    /// Pairs tested.
    pub tests: u64,
    /// Pairs the reference says hit.
    pub exact_hits: u64,
    /// Pairs the back end says hit.
    pub hits: u64,
    /// Hits where the reference says miss.
    pub false_hits: u64,
    /// Misses where the reference says hit.
    pub false_misses: u64,
    /// Hits on triangles the reference finds degenerate (zero area or non-finite).
    pub degenerate_hits: u64,
    /// Hits with a NaN or infinite `t`, `u` or `v`.
    pub nan_or_inf: u64,
    /// Hits with a NaN `t`, `u` or `v`.
    pub nan: u64,
    /// Hits outside `0 < t <= t_max`, or `occludes` disagreeing with `intersect`.
    pub contract_violations: u64,
    /// Pairs where a call panicked (`prepare`, `prepare_ray`, `intersect` or `occludes`).
    pub panics: u64,
}

/// Runs `k` on every pair, catching panics.
pub fn check_pairs<I: Intersector>(k: &I, pairs: &[Pair], verdicts: &[PairVerdict]) -> PairCounts {
    let mut out = PairCounts::default();
    for (pair, verdict) in pairs.iter().zip(verdicts) {
        out.tests += 1;
        out.exact_hits += u64::from(verdict.hit);
        let (tri, ray): (Triangle<I::Real>, Ray<I::Real>) = (pair.tri.cast(), pair.ray.cast());
        let t_max = I::Real::from_f64(pair.t_max);
        let calls = catch_unwind(AssertUnwindSafe(|| {
            let (prim, rd) = (k.prepare(&tri), k.prepare_ray(&ray));
            (k.intersect(&prim, &ray, &rd, t_max), k.occludes(&prim, &ray, &rd, t_max))
        }));
        let Ok((hit, occludes)) = calls else {
            out.panics += 1;
            continue;
        };
        out.contract_violations += u64::from(hit.is_some() != occludes);
        out.hits += u64::from(hit.is_some());
        out.false_hits += u64::from(hit.is_some() && !verdict.hit);
        out.false_misses += u64::from(hit.is_none() && verdict.hit);
        if let Some(h) = hit {
            out.degenerate_hits += u64::from(!verdict.hittable);
            out.nan_or_inf += u64::from(!finite_hit(&h));
            out.nan += u64::from(nan_hit(&h));
            out.contract_violations += u64::from(!(h.t > I::Real::ZERO && h.t <= t_max));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn subjects_cover_every_backend() {
        // Each back end of the registry once per precision, named by its kernel, then the
        // reference: checked against the registry and against what the kernels run say.
        let all = Subject::all();
        assert_eq!(all.len(), 2 * Backend::ALL.len() + 1);
        for (i, p) in Precision::ALL.into_iter().enumerate() {
            let chunk = &all[i * Backend::ALL.len()..(i + 1) * Backend::ALL.len()];
            for (s, b) in chunk.iter().zip(Backend::ALL) {
                assert_eq!(*s, Subject::Kernel(b, p));
                assert_eq!((s.name(), s.precision()), (b.name(), p));
            }
        }
        let names: Vec<&str> = all.iter().map(|s| s.name()).collect();
        assert_eq!(&names[..3], ["la", "la-mt", "la-report"]);
        assert_eq!(&names[5..8], ["ga", "ga-report", "ga-plucker"]);
        assert_eq!(*names.last().unwrap(), "exact");
        assert!(Subject::Exact.claims_watertight() && Subject::Exact.guarantees().exact);
        assert!(Subject::Kernel(Backend::G3Watertight, Precision::F32).claims_watertight());
        assert!(!Subject::Kernel(Backend::LaMt, Precision::F64).claims_watertight());
    }
}
