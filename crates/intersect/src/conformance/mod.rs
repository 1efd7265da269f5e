//! Everything a back end's tests need to show that it keeps the seam's contract and the
//! guarantees it claims, in one call per kernel and precision:
//!
//! ```ignore
//! use intersect::conformance::check_all;
//!
//! #[test]
//! fn la_conforms() {
//!     // Held to what the kernel declares in `Intersector::GUARANTEES`.
//!     check_all::<kernels_la::Watertight<f32>>();
//!     check_all::<kernels_la::Watertight<f64>>();
//! }
//! ```
//!
//! - [`contract`]: `t_max` inclusive, `t > 0`, nothing behind the origin or in the triangle's
//!   plane, both faces, degenerate triangles never hit, NaN and infinity a miss, `occludes`
//!   agrees with `intersect` (on every call: [`contract::run`]).
//! - [`group`]: `intersect_group` gives each ray of a group the hits of `intersect`, bit for
//!   bit.
//! - [`leaf`]: `intersect_leaf` and `occludes_leaf` answer as the loop over a leaf's triangles,
//!   bit for bit, from the kernel's blocks laid out as a BVH lays them out.
//! - [`reference`](mod@reference): the independent `f64` solver (Cramer's rule) and the fixed-seed
//!   generators of triangles and rays, for the back ends' own accuracy tests too.
//! - [`sweeps`]: agreement with the reference on random rays, then after scaling the scene
//!   by powers of two (the answer keeps its bits) and translating it far from the origin.
//! - [`ties`] and [`cracks`]: for watertight kernels, the tie rule on a shared edge and a
//!   fan, and no crack and no double hit on meshes whose edges and vertices are hit exactly.
//! - Extreme coordinates ([`ties::huge_coordinates_give_no_nan`]): never a NaN.
//!
//! Each check panics with a message that names the kernel ([`label`]) when the kernel fails
//! it. Enabled by the `conformance` feature:
//!
//! ```toml
//! [dev-dependencies]
//! intersect = { workspace = true, features = ["conformance"] }
//! ```

pub mod contract;
pub mod cracks;
pub mod group;
pub mod leaf;
pub mod reference;
pub mod sweeps;
pub mod ties;

use crate::Intersector;

pub use crate::Guarantees;

/// `"la f32"`, `"ga-plucker f64"`, ...: names a kernel in assertion messages.
#[must_use]
pub fn label<I: Intersector>() -> String {
    format!("{} {}", I::NAME, core::any::type_name::<I::Real>())
}

/// Asserts that `I` declares exactly `declared` (what its tests expect of it, written
/// independently of the kernel, so that a kernel cannot leave the watertight checks by
/// declaring less), then runs [`check_all`].
///
/// # Panics
///
/// If the declaration differs, or at the first check the kernel fails.
pub fn check_declared<I: Intersector + Default>(declared: Guarantees) {
    assert_eq!(I::GUARANTEES, declared, "{}: declared guarantees", I::NAME);
    check_all::<I>();
}

/// Every check of this module that applies to a kernel with the guarantees it declares
/// ([`Intersector::GUARANTEES`]): a kernel that claims watertightness is held to it.
///
/// # Panics
///
/// At the first check the kernel fails, with a message naming the kernel and the case.
pub fn check_all<I: Intersector + Default>() {
    let g = &I::GUARANTEES;
    contract::t_max_is_inclusive::<I>();
    contract::t_max_and_behind_on_random_rays::<I>(g);
    contract::degenerate_triangles_never_hit::<I>();
    contract::non_finite_input_misses::<I>();
    contract::occludes_agrees_with_intersect::<I>();
    contract::both_windings_hit::<I>();
    contract::axis_aligned_rays::<I>();
    contract::planes_on_both_sides_of_the_origin::<I>();
    group::group_agrees_with_single_rays::<I>();
    leaf::leaf_agrees_with_one_by_one::<I>();
    sweeps::agrees_with_reference::<I>(g);
    sweeps::scale_sweep::<I>();
    sweeps::translation_sweep::<I>();
    ties::huge_coordinates_give_no_nan::<I>();
    if g.watertight {
        ties::shared_edge_has_one_owner::<I>();
        ties::fan_vertex_has_one_owner::<I>();
        cracks::no_cracks_and_no_double_hits::<I>();
    }
}
