//! Every conformance check of the seam (`intersect::conformance`) on every kernel in both
//! precisions: the watertight kernel claims watertightness, the others do not. The watertight
//! kernel and Moller-Trumbore solve in the ray's frame, so they also claim exact barycentrics
//! on axis-aligned rays.

use intersect::conformance::check_all;
use intersect::conformance::contract::axis_aligned_rays_are_exact_on_skewed_triangles;
use intersect::{Guarantees, Intersector};

const WATERTIGHT: Guarantees = Guarantees { watertight: true, exact: false };
/// What every kernel but the watertight one declares: nothing beyond the contract.
const MOLLER_TRUMBORE: Guarantees = Guarantees { watertight: false, exact: false };

#[test]
fn watertight_f32_conforms() {
    axis_aligned_rays_are_exact_on_skewed_triangles::<kernels_la::Watertight<f32>>();
    assert_eq!(
        <kernels_la::Watertight<f32> as Intersector>::GUARANTEES,
        WATERTIGHT,
        "declared guarantees"
    );
    check_all::<kernels_la::Watertight<f32>>();
}

#[test]
fn watertight_f64_conforms() {
    axis_aligned_rays_are_exact_on_skewed_triangles::<kernels_la::Watertight<f64>>();
    assert_eq!(
        <kernels_la::Watertight<f64> as Intersector>::GUARANTEES,
        WATERTIGHT,
        "declared guarantees"
    );
    check_all::<kernels_la::Watertight<f64>>();
}

#[test]
fn moller_trumbore_f32_conforms() {
    axis_aligned_rays_are_exact_on_skewed_triangles::<kernels_la::MollerTrumbore<f32>>();
    assert_eq!(
        <kernels_la::MollerTrumbore<f32> as Intersector>::GUARANTEES,
        MOLLER_TRUMBORE,
        "declared guarantees"
    );
    check_all::<kernels_la::MollerTrumbore<f32>>();
}

#[test]
fn moller_trumbore_f64_conforms() {
    axis_aligned_rays_are_exact_on_skewed_triangles::<kernels_la::MollerTrumbore<f64>>();
    assert_eq!(
        <kernels_la::MollerTrumbore<f64> as Intersector>::GUARANTEES,
        MOLLER_TRUMBORE,
        "declared guarantees"
    );
    check_all::<kernels_la::MollerTrumbore<f64>>();
}

#[test]
fn report_conforms_in_both_precisions() {
    assert_eq!(<kernels_la::Report<f32> as Intersector>::GUARANTEES, MOLLER_TRUMBORE);
    assert_eq!(<kernels_la::Report<f64> as Intersector>::GUARANTEES, MOLLER_TRUMBORE);
    check_all::<kernels_la::Report<f32>>();
    check_all::<kernels_la::Report<f64>>();
}

#[test]
fn frame_conforms_in_both_precisions() {
    assert_eq!(<kernels_la::Frame<f32> as Intersector>::GUARANTEES, MOLLER_TRUMBORE);
    assert_eq!(<kernels_la::Frame<f64> as Intersector>::GUARANTEES, MOLLER_TRUMBORE);
    check_all::<kernels_la::Frame<f32>>();
    check_all::<kernels_la::Frame<f64>>();
}

#[test]
fn plucker_conforms_in_both_precisions() {
    assert_eq!(<kernels_la::Plucker<f32> as Intersector>::GUARANTEES, MOLLER_TRUMBORE);
    assert_eq!(<kernels_la::Plucker<f64> as Intersector>::GUARANTEES, MOLLER_TRUMBORE);
    check_all::<kernels_la::Plucker<f32>>();
    check_all::<kernels_la::Plucker<f64>>();
}
