//! The conformance kit on every PGA cell, in both precisions, after asserting what each
//! declares: only the watertight cell promises no cracks (the kit then checks it).

use intersect::Guarantees;
use intersect::conformance::check_declared;

const NOT_WATERTIGHT: Guarantees = Guarantees { watertight: false, exact: false };
const WATERTIGHT: Guarantees = Guarantees { watertight: true, exact: false };

#[test]
fn pga_report_conforms() {
    check_declared::<kernels_pga::PgaReport<f32>>(NOT_WATERTIGHT);
    check_declared::<kernels_pga::PgaReport<f64>>(NOT_WATERTIGHT);
}

#[test]
fn pga_mt_conforms() {
    check_declared::<kernels_pga::PgaMt<f32>>(NOT_WATERTIGHT);
    check_declared::<kernels_pga::PgaMt<f64>>(NOT_WATERTIGHT);
}

#[test]
fn pga_frame_conforms() {
    check_declared::<kernels_pga::PgaFrame<f32>>(NOT_WATERTIGHT);
    check_declared::<kernels_pga::PgaFrame<f64>>(NOT_WATERTIGHT);
}

#[test]
fn pga_watertight_conforms() {
    check_declared::<kernels_pga::PgaWatertight<f32>>(WATERTIGHT);
    check_declared::<kernels_pga::PgaWatertight<f64>>(WATERTIGHT);
}

#[test]
fn pga_plucker_conforms() {
    check_declared::<kernels_pga::PgaPlucker<f32>>(NOT_WATERTIGHT);
    check_declared::<kernels_pga::PgaPlucker<f64>>(NOT_WATERTIGHT);
}
