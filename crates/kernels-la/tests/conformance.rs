//! Every conformance check of the seam (`intersect::conformance`) on every kernel in both
//! precisions: the watertight kernel claims watertightness, the others do not. The watertight
//! kernel and Moller-Trumbore solve in the ray's frame, so they also claim exact barycentrics
//! on axis-aligned rays.

use intersect::Guarantees;
use intersect::conformance::check_declared;
use intersect::conformance::contract::axis_aligned_rays_are_exact_on_skewed_triangles;

const WATERTIGHT: Guarantees = Guarantees { watertight: true, exact: false };
/// What every kernel but the watertight one declares: nothing beyond the contract.
const MOLLER_TRUMBORE: Guarantees = Guarantees { watertight: false, exact: false };

#[test]
fn watertight_f32_conforms() {
    axis_aligned_rays_are_exact_on_skewed_triangles::<kernels_la::Watertight<f32>>();
    check_declared::<kernels_la::Watertight<f32>>(WATERTIGHT);
}

#[test]
fn watertight_f64_conforms() {
    axis_aligned_rays_are_exact_on_skewed_triangles::<kernels_la::Watertight<f64>>();
    check_declared::<kernels_la::Watertight<f64>>(WATERTIGHT);
}

#[test]
fn moller_trumbore_f32_conforms() {
    axis_aligned_rays_are_exact_on_skewed_triangles::<kernels_la::MollerTrumbore<f32>>();
    check_declared::<kernels_la::MollerTrumbore<f32>>(MOLLER_TRUMBORE);
}

#[test]
fn moller_trumbore_f64_conforms() {
    axis_aligned_rays_are_exact_on_skewed_triangles::<kernels_la::MollerTrumbore<f64>>();
    check_declared::<kernels_la::MollerTrumbore<f64>>(MOLLER_TRUMBORE);
}

#[test]
fn report_conforms_in_both_precisions() {
    check_declared::<kernels_la::Report<f32>>(MOLLER_TRUMBORE);
    check_declared::<kernels_la::Report<f64>>(MOLLER_TRUMBORE);
}

#[test]
fn frame_conforms_in_both_precisions() {
    check_declared::<kernels_la::Frame<f32>>(MOLLER_TRUMBORE);
    check_declared::<kernels_la::Frame<f64>>(MOLLER_TRUMBORE);
}

#[test]
fn plucker_conforms_in_both_precisions() {
    check_declared::<kernels_la::Plucker<f32>>(MOLLER_TRUMBORE);
    check_declared::<kernels_la::Plucker<f64>>(MOLLER_TRUMBORE);
}
