//! Every CGA cell against the seam's conformance kit (`intersect::conformance`), in both
//! precisions, each held to the guarantees it declares (asserted first): the watertight cell
//! to the tie rule and to no crack and no double hit on the kit's aimed rays.

use intersect::Guarantees;
use intersect::conformance::check_declared;
use kernels_cga::{CgaFrame, CgaMt, CgaPlucker, CgaReport, CgaWatertight};

const WATERTIGHT: Guarantees = Guarantees { watertight: true, exact: false };
const NOT_WATERTIGHT: Guarantees = Guarantees { watertight: false, exact: false };

#[test]
fn mt_conforms() {
    check_declared::<CgaMt<f32>>(NOT_WATERTIGHT);
    check_declared::<CgaMt<f64>>(NOT_WATERTIGHT);
}

#[test]
fn frame_conforms() {
    check_declared::<CgaFrame<f32>>(NOT_WATERTIGHT);
    check_declared::<CgaFrame<f64>>(NOT_WATERTIGHT);
}

#[test]
fn report_conforms() {
    check_declared::<CgaReport<f32>>(NOT_WATERTIGHT);
    check_declared::<CgaReport<f64>>(NOT_WATERTIGHT);
}

#[test]
fn plucker_conforms() {
    check_declared::<CgaPlucker<f32>>(NOT_WATERTIGHT);
    check_declared::<CgaPlucker<f64>>(NOT_WATERTIGHT);
}

#[test]
fn watertight_conforms() {
    check_declared::<CgaWatertight<f32>>(WATERTIGHT);
    check_declared::<CgaWatertight<f64>>(WATERTIGHT);
}
