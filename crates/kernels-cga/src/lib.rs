//! Ray-triangle intersection in conformal geometric algebra R(4,1): the CGA column of the
//! method x algebra matrix, one kernel per method, each written in `ga::cga` types and its
//! generated products (`^` outer, `|` inner, `&` regressive), with no hand intrinsics and no
//! per-test code on raw arrays (see the `backends` crate's "Rules for a fair row").
//!
//! ```
//! use intersect::{Intersector, Ray, Triangle};
//! use kernels_cga::{CgaFrame, CgaMt};
//!
//! let tri = Triangle::new([0.0, 0.0, 2.0], [4.0, 0.0, 2.0], [0.0, 4.0, 2.0]);
//! let ray = Ray::new([1.0, 2.0, -1.0], [0.0, 0.0, 1.0]);
//! let mt = CgaMt::<f64>::new();
//! let hit = mt.intersect(&mt.prepare(&tri), &ray, &(), f64::INFINITY).unwrap();
//! assert_eq!((hit.t, hit.u, hit.v), (3.0, 0.25, 0.5));
//! let frame = CgaFrame::<f64>::new();
//! assert_eq!(frame.intersect(&frame.prepare(&tri), &ray, &(), f64::INFINITY), Some(hit));
//! ```
//!
//! # The cells
//!
//! Each module holds the method's derivation in the algebra, the operations per test, the
//! bytes per triangle and the tie rule, and names the LA cell it mirrors.
//!
//! | method | cell | module | the algebra's objects |
//! |---|---|---|---|
//! | report | [`CgaReport`] (`"cga-report"`) | [`report`] | plane `A ∧ B ∧ C ∧ e∞`, ray line, their meet (a flat point), edge tests as inner products of planes through the edge |
//! | mt | [`CgaMt`] (`"cga-mt"`) | [`mt`] | determinants as outer products of directions |
//! | frame | [`CgaFrame`] (`"cga-frame"`) | [`frame`] | the plane and the reciprocal frame as dual planes `m + δ e∞` evaluated at the ray's point |
//! | watertight | [`CgaWatertight`] (`"cga-watertight"`) | [`watertight`] | edge tests as the outer products `P ∧ Q ∧ L` of the edge's points with the ray's flat line, in the ray's frame; `g3-watertight`'s exact fallback and tie rule |
//! | plucker | [`CgaPlucker`] (`"cga-plucker"`) | [`plucker`] | the ray's and the edges' flat lines, sides from their regressive product |
//!
//! # Precision
//!
//! The generated types store a conformal point `up(x) = eₒ + x + ½x² e∞` in the orthonormal
//! `e4`, `e5` basis, as `½x² - ½` and `½x² + ½`; every product mixing points then cancels
//! terms of size `x²`, and in `f32` a point 100 units from the origin keeps about 3 digits.
//! The kernels never store `½x²`: every object they use is a flat (it has a factor `e∞`) or
//! a dual plane, and for those `up(x)` can be replaced by `eₒ + x` exactly (see the private
//! `flat` module), whose `e4`, `e5` coefficients are `∓½`; and they measure from a vertex or
//! from the ray's origin, as the other cells do, so coordinates are as small as the
//! triangle's distance from the ray. The agreement test of the matrix (`backends`'
//! `tests/rows.rs`: each cell against its row's LA cell on 20,000 random rays) finds the
//! same worst relative error of `t` as the LA cell of the row, within a factor 1.6, in both
//! precisions, and the conformance kit's translation sweep (scenes moved `2e3` scene sizes
//! from the origin) holds every cell to its `t` tolerance.

#![deny(missing_docs)]

mod flat;
pub mod frame;
pub mod mt;
pub mod plucker;
pub mod report;
pub mod watertight;

pub use frame::{CgaFrame, CgaFramePrim};
pub use mt::{CgaMt, CgaMtPrim};
pub use plucker::{CgaPlucker, CgaPluckerPrim, CgaPluckerRay};
pub use report::{CgaReport, CgaReportPrim};
pub use watertight::{CgaWatertight, CgaWatertightBlock, CgaWatertightPrim, CgaWatertightRay};

/// Re-exported from the seam: whether a triangle has zero area, decided exactly.
pub use intersect::is_degenerate;

/// The cross product of two `f64` vectors (per-triangle precomputation, at `prepare`).
fn cross64(x: [f64; 3], y: [f64; 3]) -> [f64; 3] {
    [x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]]
}

/// `x` rounded once to the kernel's precision.
fn round64<T: intersect::Real>(x: [f64; 3]) -> [T; 3] {
    x.map(T::from_f64)
}
