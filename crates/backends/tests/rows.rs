//! Every row of the method x algebra matrix is one method: each cell gives the answers of its
//! row's LA cell (the same decision away from the edges, `t` to the tolerance) on the same
//! random rays, in both precisions. A row without an LA cell has nothing to compare yet.

use backends::{Algebra, Backend, Job, Precision, dispatch};
use intersect::conformance::contract::run;
use intersect::conformance::reference::{Reference, ray_towards, reference, rng, tolerance};
use intersect::{Intersector, Ray, Real, Triangle};

const CASES: usize = 20_000;

/// One kernel's answers on the fixed rays, with the reference for each (computed from the
/// rays and triangles as rounded to the kernel's precision).
struct Answers;

impl Job for Answers {
    type Output = Vec<(Option<Reference>, Option<f64>)>;
    fn run<I: Intersector + 'static>(self, k: I) -> Self::Output {
        let mut rng = rng(0x6a_1602);
        (0..CASES)
            .map(|_| {
                let tri: Triangle<I::Real> =
                    intersect::conformance::reference::triangle(&mut rng).cast();
                let ray: Ray<I::Real> = ray_towards(&mut rng, &tri.cast()).cast();
                let hit = run(&k, &tri, &ray, I::Real::INFINITY);
                (reference(&tri, &ray), hit.map(|h| h.t.to_f64()))
            })
            .collect()
    }
}

/// The largest relative error of `t` against the reference over `answers`, divided by the
/// conditioning `max(1, 0.1 / cos)` as `intersect::conformance::sweeps::deviation` does.
fn worst_t(answers: &[(Option<Reference>, Option<f64>)]) -> f64 {
    let err = |(r, t): &(Option<Reference>, Option<f64>)| {
        let (r, t) = (r.as_ref()?, (*t)?);
        (r.cos >= 0.01).then(|| (t - r.t).abs() / r.t.abs() / (0.1 / r.cos).max(1.0))
    };
    answers.iter().filter_map(err).fold(0.0, f64::max)
}

#[test]
fn every_cell_agrees_with_its_rows_la_cell() {
    let mut compared_rows = 0;
    for b in Backend::ALL {
        let Some(la) = Backend::cell(b.method(), Algebra::La) else { continue };
        if la == b {
            continue;
        }
        compared_rows += 1;
        for p in Precision::ALL {
            let tol = if p == Precision::F32 { tolerance::<f32>() } else { tolerance::<f64>() };
            let (mine, theirs) = (dispatch(b, p, Answers), dispatch(la, p, Answers));
            let mut hits = 0;
            for ((r, x), (_, y)) in mine.iter().zip(&theirs) {
                let Some(r) = r else { continue };
                if r.cos < 0.1 || r.margin().abs() <= 1e-3 || r.t.abs() < 1e-3 {
                    continue;
                }
                let what = || format!("{} vs {} {}: {r:?}", b.name(), la.name(), p.name());
                assert_eq!(x.is_some(), y.is_some(), "{}", what());
                if let (Some(x), Some(y)) = (x, y) {
                    assert!((x - y).abs() <= 2.0 * tol * y.abs(), "{}: {x} {y}", what());
                    hits += 1;
                }
            }
            assert!(hits > 3_000, "{} {}: only {hits} hits compared", b.name(), p.name());
            let (name, la_name) = (b.name(), la.name());
            let (t_mine, t_la) = (worst_t(&mine), worst_t(&theirs));
            eprintln!("{name} {}: worst t error {t_mine:.1e}; {la_name}: {t_la:.1e}", p.name());
        }
    }
    assert!(compared_rows > 0, "no row has a cell beside its LA cell");
}
