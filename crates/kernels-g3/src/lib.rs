//! Ray-triangle intersection with geometric algebra: the `ga` back ends of the
//! [`intersect::Intersector`] seam, built on the [`ga`] crate's G(3,0,0).
//!
//! ```
//! use intersect::{Intersector, Ray, Triangle};
//! use kernels_g3::{G3Frame, G3Watertight, G3Report};
//!
//! // A triangle in the plane z = 2 and a ray looking up at it from below the origin.
//! let tri = Triangle::new([0.0, 0.0, 2.0], [4.0, 0.0, 2.0], [0.0, 4.0, 2.0]);
//! let ray = Ray::new([1.0, 2.0, -1.0], [0.0, 0.0, 1.0]);
//!
//! // The report's method as written (errata fixed), everything per ray.
//! let report = G3Report::<f64>::new();
//! let hit = report.intersect(&report.prepare(&tri), &ray, &(), f64::INFINITY).unwrap();
//! assert_eq!((hit.t, hit.u, hit.v), (3.0, 0.25, 0.5));
//!
//! // The same mathematics with the per-triangle part precomputed: the same answer.
//! let ga = G3Frame::<f64>::new();
//! let prim = ga.prepare(&tri);
//! assert_eq!(ga.intersect(&prim, &ray, &(), f64::INFINITY), Some(hit));
//! // Hits count only within (0, t_max], and a hit exactly at t_max counts.
//! assert!(ga.occludes(&prim, &ray, &(), 3.0));
//! assert!(!ga.occludes(&prim, &ray, &(), 2.9));
//!
//! // The watertight variant has per-ray data.
//! let wt = G3Watertight::<f32>::new();
//! let (tri32, ray32) = (tri.cast::<f32>(), ray.cast::<f32>());
//! let rd = wt.prepare_ray(&ray32);
//! let hit = wt.intersect(&wt.prepare(&tri32), &ray32, &rd, f32::INFINITY).unwrap();
//! assert_eq!((hit.t, hit.u, hit.v), (3.0, 0.25, 0.5));
//! assert_eq!(<G3Watertight<f32> as Intersector>::NAME, "ga-plucker");
//! ```
//!
//! # The cells of the method x algebra matrix, and two variants
//!
//! One kernel per method in the G3 column (see the `backends` crate's "Rules for a fair
//! row"), each written in `ga::g3` types and operators, with no hand intrinsics and no
//! per-test code on raw arrays; each module holds its derivation, its per-triangle bytes, its
//! operations per test and its tie rule:
//!
//! | method | cell | module | beside it |
//! |---|---|---|---|
//! | report | [`G3Report`] (`"ga-report"`) | [`report`] | |
//! | mt | [`G3Mt`] (`"g3-mt"`) | [`mt`] | |
//! | frame | [`G3FrameCell`] (`"g3-frame"`) | [`frame_cell`] | [`G3Frame`] (`"ga"`, variant: hand four-lane SIMD over arrays) |
//! | watertight | [`G3WatertightCell`] (`"g3-watertight"`) | [`watertight_cell`] | [`G3Watertight`] (`"ga-plucker"`, variant: the same) |
//! | plucker | [`G3Plucker`] (`"g3-plucker"`) | [`plucker`] | |
//!
//! The variants share their cell's per-triangle numbers and decisions (the cells call the
//! variants' modules for them) and differ only in how the per-test values are computed.
//!
//! # The report's three kernels
//!
//! All three are generic over the precision ([`GaReal`]: `f32` or `f64`) and implement the
//! report (T. Chauncey, *An Investigation into Geometric Algebra & its Implementation in a Ray
//! Tracer*, sections 3.1 to 3.3) with its errata corrected (see [`ga::errata`]: E2, E3, E4,
//! E7). Each module holds its derivation.
//!
//! | | [`G3Report`] (`"ga-report"`) | [`G3Frame`] (`"ga"`) | [`G3Watertight`] (`"ga-plucker"`) |
//! |---|---|---|---|
//! | What it is | the report's steps as written, with [`ga::g3::geometry`]'s `Plane`, `Line` and the report's three edge tests | the same mathematics, per-triangle part precomputed | edge tests as the trivectors `((vi - o) ∧ (vj - o)) ∧ u` |
//! | Shared edges and vertices | not watertight | not watertight | **watertight**: a ray through a shared edge or vertex hits exactly one of the triangles (a tie rule decides exact zeros), given identical vertex values in both |
//! | Edges | closed | closed | tie rule: an exact zero takes the sign it has for the ray moved by `ε ex + ε² ey` ([`watertight`](crate::watertight#why-it-is-watertight)) |
//! | Faces | both | both | both |
//! | Degenerate triangles | never hit (zero area decided exactly at `prepare`, see [`is_degenerate`]) | never hit (same) | never hit (same) |
//! | NaN or infinite input | miss, no panic | miss, no panic | miss, no panic |
//! | Per triangle | 3 vertices: 36 B (`f32`), 72 B (`f64`) | `a`, unit normal `n`, reciprocal frame `m_b`, `m_c`, stored by axis: 48 B, 96 B | 3 vertices and the unit normal, stored by axis: 48 B, 96 B |
//! | Per ray | nothing | nothing | an orthonormal basis of the plane orthogonal to the ray (a square root, 2 divisions) |
//! | Per test | a plane (square root, division), the intersection (division), 3 pairs of edge bivectors and their inner products, 2 divisions for `u`, `v` | the inner products of `a - o` and of `u` with `n`, `m_b`, `m_c` (the triangle stored by axis: two four-lane expressions), `U` and `V` from them, then one branch on the edges (rarely passed, so well predicted) before the distance test: about 25 operations, 13 on four lanes (a fused multiply-add counted once); one division, for hits only | 3 translated vertices, their coordinates in the plane orthogonal to the ray, 3 edge values (one vertex per lane), then one branch on their signs: about 25 operations before the distance test, 45 written out on scalars; one division, for hits only |
//! | Rare slow path | none | none | exact signs (`orient2d`) when an edge value is exactly 0 |
//! | `t` measured from | the world origin (loses about 3 digits at `1e3` scene sizes from it) | vertex `a` (one rounded subtraction `a - o`) | vertex `a`, as [`G3Frame`] |
//!
//! Speeds are measured by the criterion benches in `benches/`, not here.
//!
//! # Accuracy
//!
//! Every reported hit has `0 < t <= t_max` and finite `t`, `u`, `v`. [`G3Frame`] and
//! [`G3Watertight`] decide on undivided values and divide once; their barycentrics satisfy `u, v >=
//! 0` and `u + v <= 1` up to the rounding of that division.
//!
//! `tests/accuracy.rs` compares every kernel with an independent `f64` solver on 40,000 random
//! triangles and rays (half of them aimed within `1e-2` to `1e-15` of an edge), for rays at
//! least 10% off grazing (errors grow as `1 / cos` below that). Measured maxima:
//!
//! | | `ga-report` | `ga` | `ga-plucker` |
//! |---|---|---|---|
//! | hit/miss disagrees only within, of an edge (barycentric units), `f32` | `5e-5` | `6e-6` | `3e-5` |
//! | the same, `f64` | `4e-15` | `2e-14` | `3e-14` |
//! | relative error of `t`, `f32` / `f64` | `9e-6` / `2e-14` | `1e-6` / `2e-14` | `1e-6` / `2e-14` |
//! | relative error of `t` at `1e3` scene sizes from the origin, `f32` / `f64` | `3e-3` / `4e-12` | `8e-7` / `7e-15` | `8e-7` / `7e-15` |
//!
//! `ga-plucker` computes its edge values from the raw vertices seen along the ray, so a thin
//! triangle widens its band in `f32`; `ga` has that conditioning folded into its precomputed
//! reciprocal frame.

#![deny(missing_docs)]

pub mod blocks;
pub mod frame;
pub mod frame_cell;
mod lanes;
pub mod mt;
pub mod plucker;
mod real;
pub mod report;
pub mod watertight;
pub mod watertight_cell;

pub use frame::{G3Frame, G3FramePrim};
pub use frame_cell::{G3FrameCell, G3FrameCellPrim};
pub use mt::{G3Mt, G3MtPrim};
pub use plucker::{G3Plucker, G3PluckerPrim, G3PluckerRay};
pub use real::GaReal;
pub use report::{G3Report, G3ReportPrim};
pub use watertight::{G3Watertight, G3WatertightPrim, G3WatertightRay};
pub use watertight_cell::{G3WatertightCell, G3WatertightCellBlock, G3WatertightCellPrim};

/// Re-exported from the seam, where every back end finds it: whether a triangle has zero
/// area (its bivector `(b - a) ∧ (c - a)` is exactly zero), decided exactly.
pub use intersect::is_degenerate;
