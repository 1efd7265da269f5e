//! Every CGA cell against the seam's conformance kit (`intersect::conformance`), in both
//! precisions, each held to the guarantees it declares (asserted first): the watertight cell
//! to the tie rule and to no crack and no double hit on the kit's aimed rays.

use intersect::conformance::check_all;
use intersect::{Guarantees, Intersector};
use kernels_cga::{CgaFrame, CgaMt, CgaPlucker, CgaReport, CgaWatertight};

const WATERTIGHT: Guarantees = Guarantees { watertight: true, exact: false };
const NOT_WATERTIGHT: Guarantees = Guarantees { watertight: false, exact: false };

/// Asserts what `I` declares, then runs every check that applies to it.
fn conforms<I: Intersector + Default>(declared: Guarantees) {
    assert_eq!(I::GUARANTEES, declared, "{}: declared guarantees", I::NAME);
    check_all::<I>();
}

#[test]
fn mt_conforms() {
    conforms::<CgaMt<f32>>(NOT_WATERTIGHT);
    conforms::<CgaMt<f64>>(NOT_WATERTIGHT);
}

#[test]
fn frame_conforms() {
    conforms::<CgaFrame<f32>>(NOT_WATERTIGHT);
    conforms::<CgaFrame<f64>>(NOT_WATERTIGHT);
}

#[test]
fn report_conforms() {
    conforms::<CgaReport<f32>>(NOT_WATERTIGHT);
    conforms::<CgaReport<f64>>(NOT_WATERTIGHT);
}

#[test]
fn plucker_conforms() {
    conforms::<CgaPlucker<f32>>(NOT_WATERTIGHT);
    conforms::<CgaPlucker<f64>>(NOT_WATERTIGHT);
}

#[test]
fn watertight_conforms() {
    conforms::<CgaWatertight<f32>>(WATERTIGHT);
    conforms::<CgaWatertight<f64>>(WATERTIGHT);
}
