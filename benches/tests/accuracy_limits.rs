//! The fast subset of the accuracy suite (`wedge_benches::accuracy`), holding every back end
//! to the hard limits. Every verdict comes from the exact reference
//! (`exact::Exact`), computed on exactly the values each back end saw.
//!
//! Sizes are `Sizes::test()`: the tile grid fully, a few thousand edge and vertex rays on the
//! bunny at every step of the translation sweep, 100,000 random rays through the bunny's BVH.
//! The figures are printed with `--nocapture`.

use std::sync::OnceLock;

use backends::{Backend, Precision};
use wedge_benches::accuracy::mesh::TriMesh;
use wedge_benches::accuracy::rays::random_rays;
use wedge_benches::accuracy::rows::StabilityRow;
use wedge_benches::accuracy::runner::Subject;
use wedge_benches::accuracy::suite::{
    SEED, Sizes, Sweep, degenerate_rows, ray_family_rows, run_aimed, run_scene, sweep_rows,
};

fn bunny() -> &'static TriMesh {
    static BUNNY: OnceLock<TriMesh> = OnceLock::new();
    BUNNY.get_or_init(|| TriMesh::bunny().unwrap_or_else(|e| panic!("{e}")))
}

fn meshes() -> [TriMesh; 2] {
    [bunny().clone(), TriMesh::tiles()]
}

/// The back ends that document watertightness, in both precisions.
fn watertight() -> Vec<Subject> {
    Subject::kernels().into_iter().filter(|s| s.claims_watertight()).collect()
}

/// Aimed rows of the translation sweep (edges and vertices, exact aim) and of the `f64` aim
/// on the unmoved meshes, for `subjects`.
fn aimed_rows(subjects: &[Subject]) -> Vec<StabilityRow> {
    let sizes = Sizes::test();
    let mut rows = Vec::new();
    for mesh in meshes() {
        rows.extend(sweep_rows(&sizes, &mesh, Sweep::Translate, subjects));
        let edges = wedge_benches::accuracy::rays::edge_rays(
            &mesh,
            sizes.sweep_edges,
            wedge_benches::accuracy::rays::Aim::F64,
            SEED,
        );
        for (s, c) in run_aimed(&edges, subjects, false) {
            rows.push(StabilityRow::from_aimed(s, "aim-f64", &mesh.name, "offset=0", &c));
        }
    }
    for r in &rows {
        println!(
            "{:>10} {:>6} {:<10} {:<8} {:>10} {:>4}: {:>5} rays, {:>5} ties, {} cracks, \
             {} double hits, {} wrong side",
            r.family,
            r.scene,
            r.variant,
            r.ray_set,
            r.backend,
            r.precision,
            r.rays,
            r.ties.unwrap_or(0),
            r.cracks.unwrap_or(0),
            r.double_hits.unwrap_or(0),
            r.wrong_side.unwrap_or(0)
        );
    }
    rows
}

#[test]
fn watertight_backends_have_no_cracks_at_shared_edges_and_vertices() {
    let rows = aimed_rows(&watertight());
    // Enough rays were kept at every step for the test to mean something.
    for r in &rows {
        assert!(
            r.rays >= 100,
            "{} {} {}: only {} rays kept",
            r.scene,
            r.variant,
            r.ray_set,
            r.rays
        );
    }
    let bad: Vec<String> = rows
        .iter()
        .filter(|r| r.cracks != Some(0) || r.nan != 0 || r.contract_violations != Some(0))
        .map(|r| {
            format!(
                "{} {} {} {} {}: {:?} cracks, {} NaN, {:?} contract violations",
                r.scene,
                r.variant,
                r.ray_set,
                r.backend,
                r.precision,
                r.cracks,
                r.nan,
                r.contract_violations
            )
        })
        .collect();
    assert!(bad.is_empty(), "rays slipped through:\n{}", bad.join("\n"));
}

/// No double hits either: both back ends break exact ties (a zero edge function) by a
/// symbolic perturbation, so a ray exactly through a shared edge or vertex is reported by one
/// triangle only. The rays kept are those where every triangle at the target faces the ray
/// the same way, so exactly one crossing is right under any consistent tie rule.
#[test]
fn watertight_backends_have_no_double_hits_at_shared_edges_and_vertices() {
    let rows = aimed_rows(&watertight());
    let bad: Vec<String> = rows
        .iter()
        .filter(|r| r.double_hits != Some(0))
        .map(|r| {
            format!(
                "{} {} {} {} {}: {:?} double hits of {} rays ({:?} ties)",
                r.scene,
                r.variant,
                r.ray_set,
                r.backend,
                r.precision,
                r.double_hits,
                r.rays,
                r.ties
            )
        })
        .collect();
    assert!(bad.is_empty(), "double hits:\n{}", bad.join("\n"));
}

#[test]
fn ordinary_rays_agree_with_the_reference_and_distances_are_accurate() {
    let sizes = Sizes::test();
    let mesh = bunny();
    let rays = random_rays(mesh, sizes.random_rays, SEED);
    let results = run_scene(&mesh.triangle_list(), &rays, &Subject::kernels(), sizes.judged_rays);
    let mut bad = Vec::new();
    for (s, c) in &results {
        let row =
            wedge_benches::accuracy::rows::AccuracyRow::from_scene(*s, "bunny", "random", c, "");
        let f32 = s.precision() == Precision::F32;
        let max_per_million = if f32 { 10.0 } else { 1.0 };
        println!(
            "{:>10} {}: {} rays, {} exact hits, {} disagreements ({:.1}/M), \
             wrong triangle {:?}/M, t median {:?} ulps, p99.9 {:?}, max {:?}",
            row.backend,
            row.precision,
            row.rays,
            row.exact_hits,
            row.disagreements,
            row.disagree_per_million,
            row.wrong_triangle_per_million,
            row.t_ulp_err_median,
            row.t_ulp_err_p999,
            row.t_ulp_err_max
        );
        // About half the rays hit: the comparison is not vacuous.
        assert!(c.exact_hits > c.rays / 4 && c.exact_hits < c.rays * 3 / 4);
        assert!(row.t_samples > 1000, "{}: too few distance samples", row.backend);
        if row.disagree_per_million > max_per_million {
            bad.push(format!(
                "{} {}: {:.1} disagreements per million",
                row.backend, row.precision, row.disagree_per_million
            ));
        }
        if f32 && !row.t_ulp_err_median.is_some_and(|m| m <= 1.0) {
            bad.push(format!(
                "{} f32: median distance error {:?} ulps",
                row.backend, row.t_ulp_err_median
            ));
        }
        if row.nan_or_inf != 0 {
            bad.push(format!(
                "{} {}: {} NaN or infinite hits",
                row.backend, row.precision, row.nan_or_inf
            ));
        }
    }
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}

#[test]
fn degenerate_input_never_panics_is_never_hit_and_gives_no_nan() {
    let rows = degenerate_rows(&Sizes::test(), &Subject::all());
    let describe = |r: &StabilityRow| {
        format!(
            "{} {} {}: panics {:?}, degenerate hits {:?}, NaN {} (NaN or inf {}), \
             contract violations {:?}",
            r.variant,
            r.backend,
            r.precision,
            r.panics,
            r.degenerate_hits,
            r.nan,
            r.nan_or_inf,
            r.contract_violations
        )
    };
    let bad: Vec<String> =
        rows.iter().filter(|r| r.meets_limits != Some(true)).map(describe).collect();
    assert!(rows.iter().any(|r| r.variant == "collinear" && r.rays > 100));
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}

#[test]
fn grazing_axis_aligned_and_on_surface_rays_give_no_nan_and_no_panic() {
    let sizes = Sizes::test();
    for mesh in meshes() {
        let rows = ray_family_rows(&sizes, &mesh, &Subject::all());
        for r in &rows {
            println!(
                "{:>12} {:>6} {:<24} {:>10} {}: {} tests, {} disagreements ({} false hits), \
                 NaN or inf {}",
                r.family,
                r.scene,
                r.variant,
                r.backend,
                r.precision,
                r.rays,
                r.disagreements,
                r.false_hits,
                r.nan_or_inf
            );
            assert!(r.rays > 0, "{} {}: no rays", r.family, r.variant);
            assert_eq!(r.nan, 0, "{} {} {} {}", r.family, r.variant, r.backend, r.precision);
            assert_eq!(r.panics.unwrap_or(0), 0, "{} {} {}", r.family, r.backend, r.precision);
            assert_eq!(
                r.contract_violations.unwrap_or(0),
                0,
                "{} {} {}",
                r.family,
                r.backend,
                r.precision
            );
            // The reference never hits a triangle from its own plane or from a point on it.
            if r.backend == "exact" && r.family != "axis-aligned" && r.variant != "near-plane" {
                assert_eq!(r.exact_hits, 0, "{} {}", r.family, r.variant);
            }
        }
    }
}

#[test]
fn every_backend_is_judged() {
    // The names the kernels run report, against the registry's.
    let names: Vec<&str> = Subject::kernels().iter().map(|s| s.name()).collect();
    for b in Backend::ALL.map(Backend::name) {
        assert_eq!(names.iter().filter(|n| **n == b).count(), 2, "{b}");
    }
    let watertight = watertight();
    for p in Precision::ALL {
        for b in [Backend::LaWatertight, Backend::G3Watertight] {
            assert!(watertight.contains(&Subject::Kernel(b, p)), "{b:?} {p:?}");
        }
        for b in [Backend::LaMt, Backend::G3Frame, Backend::G3Report] {
            assert!(!watertight.contains(&Subject::Kernel(b, p)), "{b:?} {p:?}");
        }
    }
}
