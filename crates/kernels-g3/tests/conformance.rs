//! Every conformance check of the seam (`intersect::conformance`) on every kernel in both
//! precisions, each held to the guarantees it declares (asserted first).

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

/// `check_all` in both precisions, after asserting the declared guarantees.
fn conforms<F32, F64>(guarantees: Guarantees)
where
    F32: Intersector + Default,
    F64: Intersector + Default,
{
    assert_eq!(F32::GUARANTEES, guarantees, "declared guarantees");
    assert_eq!(F64::GUARANTEES, guarantees, "declared guarantees");
    check_all::<F32>();
    check_all::<F64>();
}

#[test]
fn g3_mt_conforms() {
    conforms::<kernels_g3::G3Mt<f32>, kernels_g3::G3Mt<f64>>(NOT_WATERTIGHT);
}

#[test]
fn g3_frame_conforms() {
    conforms::<kernels_g3::G3FrameCell<f32>, kernels_g3::G3FrameCell<f64>>(NOT_WATERTIGHT);
}

#[test]
fn g3_watertight_conforms() {
    conforms::<kernels_g3::G3WatertightCell<f32>, kernels_g3::G3WatertightCell<f64>>(PLUCKER);
}

#[test]
fn g3_plucker_conforms() {
    conforms::<kernels_g3::G3Plucker<f32>, kernels_g3::G3Plucker<f64>>(NOT_WATERTIGHT);
}
