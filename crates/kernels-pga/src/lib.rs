//! Ray-triangle intersection in projective geometric algebra R(3,0,1): the PGA column of the
//! method x algebra matrix, built on the [`ga`] crate's [`ga::pga`] types and generated
//! products (`^` meet, `&` join, `|` inner).
//!
//! ```
//! use intersect::{Intersector, Ray, Triangle};
//! use kernels_pga::{PgaReport, PgaWatertight};
//!
//! // A triangle in the plane z = 2 and a ray looking up at it from below the origin.
//! let tri = Triangle::new([0.0, 0.0, 2.0], [4.0, 0.0, 2.0], [0.0, 4.0, 2.0]);
//! let ray = Ray::new([1.0, 2.0, -1.0], [0.0, 0.0, 1.0]);
//! let report = PgaReport::<f64>::new();
//! let hit = report.intersect(&report.prepare(&tri), &ray, &(), f64::INFINITY).unwrap();
//! assert_eq!((hit.t, hit.u, hit.v), (3.0, 0.25, 0.5));
//! let wt = PgaWatertight::<f64>::new();
//! let rd = wt.prepare_ray(&ray);
//! assert_eq!(wt.intersect(&wt.prepare(&tri), &ray, &rd, f64::INFINITY), Some(hit));
//! ```
//!
//! # The cells
//!
//! One kernel per method (see the `backends` crate's "Rules for a fair row"), each mirroring
//! its row's LA cell (the same per-triangle quantities, decisions and tie rule) with the
//! per-test code in `ga::pga` types; each module holds its derivation in the algebra, its
//! per-triangle bytes, its operations per test and its tie rule.
//!
//! | method | cell | module | mirrors | per triangle (`f32` / `f64`) | edges |
//! |---|---|---|---|---|---|
//! | report | [`PgaReport`] (`"pga-report"`) | [`report`] | `la-report` | 3 points: 48 B / 96 B | closed |
//! | mt | [`PgaMt`] (`"pga-mt"`) | [`mt`] | `la-mt` | a point, 2 ideal points: 48 B / 96 B | closed |
//! | frame | [`PgaFrame`] (`"pga-frame"`) | [`frame`] | `la-frame` | a point, 3 planes: 64 B / 128 B | closed |
//! | watertight | [`PgaWatertight`] (`"pga-watertight"`) | [`watertight`] | `la`, `g3-watertight` | 3 points, a plane: 64 B / 128 B | tie rule, no cracks |
//! | plucker | [`PgaPlucker`] (`"pga-plucker"`) | [`plucker`] | `la-plucker` | 3 lines, a point, a plane: 104 B / 208 B | closed |
//!
//! In each: the ray is the join `O & D` of its origin and the ideal point of its direction
//! where the method needs a line, `t` is read from the triangle's plane (its incidence with
//! the ray's origin over the meet's weight `π & D`, the origin taken relative to a vertex
//! where the row's LA cell does so), degenerate triangles (decided exactly at `prepare`) are
//! stored so that no ray hits them, and NaN or infinite input misses without a panic.
//! Per-triangle quantities are computed in `f64` and rounded once.

#![deny(missing_docs)]

pub mod frame;
pub mod mt;
pub mod plucker;
pub mod report;
pub mod watertight;

pub use frame::{PgaFrame, PgaFramePrim};
pub use mt::{PgaMt, PgaMtPrim};
pub use plucker::{PgaPlucker, PgaPluckerPrim, PgaPluckerRay};
pub use report::{PgaReport, PgaReportPrim};
pub use watertight::{PgaWatertight, PgaWatertightBlock, PgaWatertightPrim, PgaWatertightRay};

use ga::Scalar;
use ga::pga::{Line, Plane, Point};

/// Re-exported from the seam, where every back end finds it: whether a triangle has zero
/// area, decided exactly.
pub use intersect::is_degenerate;

/// The point `p` (weight 1).
#[inline(always)]
fn point<T: Scalar>(p: [T; 3]) -> Point<T> {
    Point::from_xyz_array(p)
}

/// The ideal point of the direction `d` (weight 0).
#[inline(always)]
fn direction<T: Scalar>(d: [T; 3]) -> Point<T> {
    Point::direction(d[0], d[1], d[2])
}

/// The point at `p - origin` (weight 1): `p` seen from `origin` (both of weight 1), so that
/// products with it lose no digits to the distance of both from the world origin.
#[inline(always)]
fn seen_from<T: Scalar>(p: Point<T>, origin: Point<T>) -> Point<T> {
    p - origin + Point::from_xyz(T::ZERO, T::ZERO, T::ZERO)
}

/// The plane through the points `a`, `b`, `c` (weight 1), the join of `a` with the ideal
/// points of the edges, `(A & (B - A)) & (C - A)`: normal `(b - a) × (c - a)`, offset
/// `-a · N`. (`A & B & C` is the same plane, but sums its normal from the moments `a × b`,
/// large terms that cancel far from the world origin.)
#[inline(always)]
fn plane_through<T: Scalar>(a: Point<T>, b: Point<T>, c: Point<T>) -> Plane<T> {
    (a & (b - a)) & (c - a)
}

/// [`plane_through`] with a unit normal.
fn unit_plane(a: Point<f64>, b: Point<f64>, c: Point<f64>) -> Plane<f64> {
    plane_through(a, b, c).normalized()
}

/// `p` rounded once to `T`.
fn round_plane<T: Scalar>(p: Plane<f64>) -> Plane<T> {
    Plane::from_array(p.to_array().map(T::from_f64))
}

/// `l` rounded once to `T`.
fn round_line<T: Scalar>(l: Line<f64>) -> Line<T> {
    Line::from_array(l.to_array().map(T::from_f64))
}
