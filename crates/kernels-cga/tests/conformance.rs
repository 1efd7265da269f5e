//! Every CGA cell against the seam's conformance kit, in both precisions, held to the
//! guarantees it declares.

use intersect::conformance::check_all;
use kernels_cga::{CgaFrame, CgaMt, CgaPlucker, CgaReport};

#[test]
fn mt_conforms() {
    check_all::<CgaMt<f32>>();
    check_all::<CgaMt<f64>>();
}

#[test]
fn frame_conforms() {
    check_all::<CgaFrame<f32>>();
    check_all::<CgaFrame<f64>>();
}

#[test]
fn report_conforms() {
    check_all::<CgaReport<f32>>();
    check_all::<CgaReport<f64>>();
}

#[test]
fn plucker_conforms() {
    check_all::<CgaPlucker<f32>>();
    check_all::<CgaPlucker<f64>>();
}
