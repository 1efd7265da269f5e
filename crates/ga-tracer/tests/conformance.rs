//! Every conformance check of the seam (`intersect::conformance`) on the three kernels in
//! both precisions: `ga-plucker` claims watertightness, `ga` and `ga-report` do not.

use intersect::conformance::{Guarantees, check_all};

const PLUCKER: Guarantees = Guarantees { watertight: true, exact: false };
const NOT_WATERTIGHT: Guarantees = Guarantees { watertight: false, exact: false };

#[test]
fn ga_report_f32_conforms() {
    check_all::<ga_tracer::GaReport<f32>>(&NOT_WATERTIGHT);
}

#[test]
fn ga_report_f64_conforms() {
    check_all::<ga_tracer::GaReport<f64>>(&NOT_WATERTIGHT);
}

#[test]
fn ga_f32_conforms() {
    check_all::<ga_tracer::Ga<f32>>(&NOT_WATERTIGHT);
}

#[test]
fn ga_f64_conforms() {
    check_all::<ga_tracer::Ga<f64>>(&NOT_WATERTIGHT);
}

#[test]
fn ga_plucker_f32_conforms() {
    check_all::<ga_tracer::GaPlucker<f32>>(&PLUCKER);
}

#[test]
fn ga_plucker_f64_conforms() {
    check_all::<ga_tracer::GaPlucker<f64>>(&PLUCKER);
}
