//! Every conformance check of the seam (`intersect::conformance`) on both kernels in both
//! precisions: the watertight kernel claims watertightness, Moller-Trumbore does not. Both
//! solve in the ray's frame, so they also claim exact barycentrics on axis-aligned rays.

use intersect::conformance::check_all;
use intersect::conformance::contract::axis_aligned_rays_are_exact_on_skewed_triangles;
use intersect::{Guarantees, Intersector};

const WATERTIGHT: Guarantees = Guarantees { watertight: true, exact: false };
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
