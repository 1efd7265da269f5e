//! Every conformance check of the seam (`intersect::conformance`) on every kernel in both
//! precisions, each held to the guarantees it declares (asserted first).

use intersect::Guarantees;
use intersect::conformance::check_declared;

const PLUCKER: Guarantees = Guarantees { watertight: true, exact: false };
const NOT_WATERTIGHT: Guarantees = Guarantees { watertight: false, exact: false };

#[test]
fn ga_report_f32_conforms() {
    check_declared::<kernels_g3::G3Report<f32>>(NOT_WATERTIGHT);
}

#[test]
fn ga_report_f64_conforms() {
    check_declared::<kernels_g3::G3Report<f64>>(NOT_WATERTIGHT);
}

#[test]
fn ga_f32_conforms() {
    check_declared::<kernels_g3::G3Frame<f32>>(NOT_WATERTIGHT);
}

#[test]
fn ga_f64_conforms() {
    check_declared::<kernels_g3::G3Frame<f64>>(NOT_WATERTIGHT);
}

#[test]
fn ga_plucker_f32_conforms() {
    check_declared::<kernels_g3::G3Watertight<f32>>(PLUCKER);
}

#[test]
fn ga_plucker_f64_conforms() {
    check_declared::<kernels_g3::G3Watertight<f64>>(PLUCKER);
}

#[test]
fn g3_mt_conforms() {
    check_declared::<kernels_g3::G3Mt<f32>>(NOT_WATERTIGHT);
    check_declared::<kernels_g3::G3Mt<f64>>(NOT_WATERTIGHT);
}

#[test]
fn g3_frame_conforms() {
    check_declared::<kernels_g3::G3FrameCell<f32>>(NOT_WATERTIGHT);
    check_declared::<kernels_g3::G3FrameCell<f64>>(NOT_WATERTIGHT);
}

#[test]
fn g3_watertight_conforms() {
    check_declared::<kernels_g3::G3WatertightCell<f32>>(PLUCKER);
    check_declared::<kernels_g3::G3WatertightCell<f64>>(PLUCKER);
}

#[test]
fn g3_plucker_conforms() {
    check_declared::<kernels_g3::G3Plucker<f32>>(NOT_WATERTIGHT);
    check_declared::<kernels_g3::G3Plucker<f64>>(NOT_WATERTIGHT);
}
