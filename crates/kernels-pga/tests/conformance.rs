//! The conformance kit on every PGA cell, in both precisions, after asserting what each
//! declares: only the watertight cell promises no cracks (the kit then checks it).

use intersect::conformance::check_all;
use intersect::{Guarantees, Intersector};

const NOT_WATERTIGHT: Guarantees = Guarantees { watertight: false, exact: false };
const WATERTIGHT: Guarantees = Guarantees { watertight: true, exact: false };

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
fn pga_report_conforms() {
    conforms::<kernels_pga::PgaReport<f32>, kernels_pga::PgaReport<f64>>(NOT_WATERTIGHT);
}

#[test]
fn pga_mt_conforms() {
    conforms::<kernels_pga::PgaMt<f32>, kernels_pga::PgaMt<f64>>(NOT_WATERTIGHT);
}

#[test]
fn pga_frame_conforms() {
    conforms::<kernels_pga::PgaFrame<f32>, kernels_pga::PgaFrame<f64>>(NOT_WATERTIGHT);
}

#[test]
fn pga_watertight_conforms() {
    conforms::<kernels_pga::PgaWatertight<f32>, kernels_pga::PgaWatertight<f64>>(WATERTIGHT);
}

#[test]
fn pga_plucker_conforms() {
    conforms::<kernels_pga::PgaPlucker<f32>, kernels_pga::PgaPlucker<f64>>(NOT_WATERTIGHT);
}
