//! Every conformance check of the seam (`intersect::conformance`) on the three kernels in
//! both precisions: `ga-plucker` claims watertightness, `ga` and `ga-report` do not.

use intersect::conformance::check_all;
use intersect::{Guarantees, Intersector};

const PLUCKER: Guarantees = Guarantees { watertight: true, exact: false };
const NOT_WATERTIGHT: Guarantees = Guarantees { watertight: false, exact: false };

#[test]
fn ga_report_f32_conforms() {
    assert_eq!(
        <ga_tracer::GaReport<f32> as Intersector>::GUARANTEES,
        NOT_WATERTIGHT,
        "declared guarantees"
    );
    check_all::<ga_tracer::GaReport<f32>>();
}

#[test]
fn ga_report_f64_conforms() {
    assert_eq!(
        <ga_tracer::GaReport<f64> as Intersector>::GUARANTEES,
        NOT_WATERTIGHT,
        "declared guarantees"
    );
    check_all::<ga_tracer::GaReport<f64>>();
}

#[test]
fn ga_f32_conforms() {
    assert_eq!(
        <ga_tracer::Ga<f32> as Intersector>::GUARANTEES,
        NOT_WATERTIGHT,
        "declared guarantees"
    );
    check_all::<ga_tracer::Ga<f32>>();
}

#[test]
fn ga_f64_conforms() {
    assert_eq!(
        <ga_tracer::Ga<f64> as Intersector>::GUARANTEES,
        NOT_WATERTIGHT,
        "declared guarantees"
    );
    check_all::<ga_tracer::Ga<f64>>();
}

#[test]
fn ga_plucker_f32_conforms() {
    assert_eq!(
        <ga_tracer::GaPlucker<f32> as Intersector>::GUARANTEES,
        PLUCKER,
        "declared guarantees"
    );
    check_all::<ga_tracer::GaPlucker<f32>>();
}

#[test]
fn ga_plucker_f64_conforms() {
    assert_eq!(
        <ga_tracer::GaPlucker<f64> as Intersector>::GUARANTEES,
        PLUCKER,
        "declared guarantees"
    );
    check_all::<ga_tracer::GaPlucker<f64>>();
}
