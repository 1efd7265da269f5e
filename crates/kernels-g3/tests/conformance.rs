//! Every conformance check of the seam (`intersect::conformance`) on the three kernels in
//! both precisions: `ga-plucker` claims watertightness, `ga` and `ga-report` do not.

use intersect::conformance::check_all;
use intersect::{Guarantees, Intersector};

const PLUCKER: Guarantees = Guarantees { watertight: true, exact: false };
const NOT_WATERTIGHT: Guarantees = Guarantees { watertight: false, exact: false };

#[test]
fn ga_report_f32_conforms() {
    assert_eq!(
        <kernels_g3::G3Report<f32> as Intersector>::GUARANTEES,
        NOT_WATERTIGHT,
        "declared guarantees"
    );
    check_all::<kernels_g3::G3Report<f32>>();
}

#[test]
fn ga_report_f64_conforms() {
    assert_eq!(
        <kernels_g3::G3Report<f64> as Intersector>::GUARANTEES,
        NOT_WATERTIGHT,
        "declared guarantees"
    );
    check_all::<kernels_g3::G3Report<f64>>();
}

#[test]
fn ga_f32_conforms() {
    assert_eq!(
        <kernels_g3::G3Frame<f32> as Intersector>::GUARANTEES,
        NOT_WATERTIGHT,
        "declared guarantees"
    );
    check_all::<kernels_g3::G3Frame<f32>>();
}

#[test]
fn ga_f64_conforms() {
    assert_eq!(
        <kernels_g3::G3Frame<f64> as Intersector>::GUARANTEES,
        NOT_WATERTIGHT,
        "declared guarantees"
    );
    check_all::<kernels_g3::G3Frame<f64>>();
}

#[test]
fn ga_plucker_f32_conforms() {
    assert_eq!(
        <kernels_g3::G3Watertight<f32> as Intersector>::GUARANTEES,
        PLUCKER,
        "declared guarantees"
    );
    check_all::<kernels_g3::G3Watertight<f32>>();
}

#[test]
fn ga_plucker_f64_conforms() {
    assert_eq!(
        <kernels_g3::G3Watertight<f64> as Intersector>::GUARANTEES,
        PLUCKER,
        "declared guarantees"
    );
    check_all::<kernels_g3::G3Watertight<f64>>();
}
