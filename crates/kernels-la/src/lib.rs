//! Ray-triangle intersection with glam linear algebra: the `la` back end of the
//! [`intersect::Intersector`] seam.
//!
//! ```
//! use intersect::{Intersector, Ray, Triangle};
//! use kernels_la::{MollerTrumbore, Watertight};
//!
//! // Two triangles sharing the edge from (1, 0, 0) to (0, 1, 0).
//! let left = Triangle::new([0.0f32, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
//! let right = Triangle::new([1.0f32, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]);
//! // A ray aimed exactly at a point of the shared edge.
//! let ray = Ray::new([0.25f32, 0.75, 1.0], [0.0, 0.0, -1.0]);
//!
//! let wt = Watertight::<f32>::new();
//! let rd = wt.prepare_ray(&ray);
//! let hits = [left, right].map(|tri| wt.intersect(&wt.prepare(&tri), &ray, &rd, f32::INFINITY));
//! // A tie rule gives the shared edge to exactly one of them: one hit, at t = 1.
//! assert_eq!(hits.iter().flatten().count(), 1);
//! assert!(hits.iter().flatten().all(|h| h.t == 1.0));
//!
//! let mt = MollerTrumbore::<f32>::new();
//! let hit = mt.intersect(&mt.prepare(&left), &ray, &(), f32::INFINITY).unwrap();
//! assert_eq!((hit.t, hit.u, hit.v), (1.0, 0.25, 0.75));
//! assert_eq!(<Watertight<f32> as Intersector>::NAME, "la");
//! ```
//!
//! # The cells of the method x algebra matrix
//!
//! One kernel per method in the LA column (see the `backends` crate's "Rules for a fair
//! row"), each written with glam vectors (no hand intrinsics): [`Report`] (`"la-report"`),
//! [`MollerTrumbore`] (`"la-mt"`), [`Frame`] (`"la-frame"`), [`Watertight`] (`"la"`) and
//! [`Plucker`] (`"la-plucker"`). Each module holds its derivation, its per-triangle bytes, its
//! operations per test and its tie rule.
//!
//! # What each kernel guarantees
//!
//! All are generic over the precision: `f32` works on glam's [`glam::Vec3A`] (one SSE
//! register per vector), `f64` on [`glam::DVec3`] (see [`GlamReal`]).
//!
//! The two kernels that came first, in detail:
//!
//! | | [`Watertight`] (`"la"`, default) | [`MollerTrumbore`] (`"la-mt"`) |
//! |---|---|---|
//! | Source, derivation | Woop, Benthin, Wald, JCGT 2013; [`watertight`] | Moller, Trumbore, JGT 1997; [`moller_trumbore`] |
//! | Shared edges and vertices | **no cracks**: a ray through a shared edge or vertex hits exactly one of the triangles there (a tie rule decides exact zeros), given that neighbours use the same vertex values | not watertight: in `f32` rays through shared edges can miss both triangles, or hit both; rarer in `f64`, not excluded |
//! | Edges | tie rule: an edge function `== 0` takes the sign it has for the ray moved by `(ε, ε²)` in the sheared plane ([`watertight`](crate::watertight#ties-a-ray-exactly-through-an-edge-or-a-vertex)) | closed (`u, v >= 0`, `u + v <= 1` as rounded) |
//! | Scale | no epsilon: only `det == 0` is rejected | no epsilon: only `det == 0` (or non-finite) is rejected |
//! | Faces | both | both |
//! | Degenerate triangles | never hit (zero area decided exactly at [`Intersector::prepare`](intersect::Intersector::prepare)) | never hit (same) |
//! | NaN or infinite input | miss, no panic | miss, no panic |
//! | Per triangle | 3 vertices, transposed: 48 B (`f32`), 72 B (`f64`); and again axis by axis in blocks of four for single rays ([`WatertightBlock`]): 36 B, 72 B, plus the padding of leaves to whole blocks | `a`, `e1`, `e2`: 48 B (`f32`), 72 B (`f64`) |
//! | Per ray | axis permutation, permuted origin, shear, the last two also broadcast ([`WatertightRay`]) | nothing |
//! | Per test, until the first branch | one triangle (packets, fallbacks): 3 vector subtractions, 2 vector multiply-subtracts (translate + shear), 2 shuffles, 2 multiplies, 1 subtraction (edge functions); single rays test four triangles of a leaf at once in glam's 4-vectors: 9 subtractions, 6 multiplies and 6 subtractions (translate + shear), 6 multiplies and 3 subtractions (edge functions), 6 compares | 1 cross, 1 dot, then a division on every non-parallel test |
//! | Division | only when the edge and distance tests pass | one reciprocal per non-parallel test |
//! | Rare slow path | exact-sign recomputation when an edge function is exactly 0 (`f64` arithmetic for `f32`, fused multiply-adds for `f64`) | none |
//!
//! [`Report`] (`"la-report"`) is the report's method step by step (plane, line-plane
//! intersection, cross-product edge tests, everything per ray), the glam twin of
//! `ga-report`: not watertight, closed edges, 3 vertices per triangle; see [`report`].
//! [`Frame`] (`"la-frame"`) is the frame method (precomputed unit normal and reciprocal frame,
//! one dot product per edge), the glam twin of `g3-frame` and `ga`: not watertight, closed
//! edges; see [`frame`].
//! [`Plucker`] (`"la-plucker"`) tests the ray's line against the edges' lines in Plücker
//! coordinates (the six-vector form, edge lines precomputed), the glam twin of `g3-plucker`:
//! not watertight, closed edges; see [`plucker`].
//!
//! Measured by `tests/watertight.rs` (random height fields with `f32` vertices; 12,676 rays
//! aimed exactly at points of shared edges and at shared vertices, per placement): the
//! watertight kernel lets no ray through and hits exactly one triangle with every ray (each
//! is tested against the whole mesh), in `f32` and `f64`, near the origin and 16,384
//! units (1,024 mesh extents) away. Moller-Trumbore in `f32` lets 1,119 through near the
//! origin (8.8%) and 7 far away (where the vertices are quantised to `2^-9` and its
//! arithmetic becomes nearly exact); in `f64`, 1 and 0.
//!
//! Speeds are measured by the criterion benches in `benches/`, not here.
//!
//! # Accuracy
//!
//! Against an independent `f64` solver on random rays and triangles, the worst relative error
//! of `t` (times the cosine of incidence, since a grazing ray magnifies every rounding error)
//! is about `5e-6` in `f32` and `2e-14` in `f64`, for both kernels; the tests assert `1e-5`
//! and `1e-12`. Every reported hit has `0 < t <= t_max` and finite `t`, `u`, `v`,
//! with `u >= 0` and `v >= 0` exactly. `u + v <= 1` holds exactly for Moller-Trumbore (it is
//! its test) and up to the rounding of one multiplication for the watertight kernel, whose
//! inside test is made on the undivided edge functions.

#![deny(missing_docs)]

pub mod frame;
mod lanes;
pub mod moller_trumbore;
pub mod plucker;
pub mod report;
pub mod watertight;

pub use frame::{Frame, FramePrim};
pub use moller_trumbore::{MollerTrumbore, MtPrim};
pub use plucker::{Plucker, PluckerPrim, PluckerRay};
pub use report::{Report, ReportPrim};
pub use watertight::{Watertight, WatertightBlock, WatertightPrim, WatertightRay};

/// A precision the glam back end supports: `f32` (computed with [`glam::Vec3A`]) and `f64`
/// (with [`glam::DVec3`]).
///
/// Every scalar operation is the workspace's one float trait, [`intersect::Real`] (its
/// `mul_add` always fused); what this adds is glam's vector type of each precision and the
/// operations the kernels do on it, a concern of this crate alone (no other crate computes
/// with glam). Sealed: the vector operations behind it are private, so no other type can
/// implement it.
pub trait GlamReal: lanes::Lanes {}

impl GlamReal for f32 {}
impl GlamReal for f64 {}

/// Re-exported from the seam, where every back end finds it: whether a triangle has zero
/// area, decided exactly.
pub use intersect::is_degenerate;
