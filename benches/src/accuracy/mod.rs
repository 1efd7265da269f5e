//! Accuracy and numerical stability of every back end, judged by the exact reference
//! (`exact::Exact`).
//!
//! The `accuracy` bench runs the suite and writes `results/accuracy.csv`,
//! `results/stability.csv`, `results/runtime_vs_error.svg` and `results/SUMMARY.md`; the
//! tests in `benches/tests/` run a fast subset and hold the back ends to the issue's hard
//! limits.
//!
//! ```
//! use backends::{Backend, Precision};
//! use wedge_benches::accuracy::mesh::TriMesh;
//! use wedge_benches::accuracy::rays::{Aim, edge_rays};
//! use wedge_benches::accuracy::runner::Subject;
//! use wedge_benches::accuracy::suite::run_aimed;
//!
//! // Rays aimed exactly at points of the tile grid's shared edges.
//! let set = edge_rays(&TriMesh::tiles(), 200, Aim::Exact, 7);
//! let la = Subject::Kernel(Backend::LaWatertight, Precision::F32);
//! let (_, counts) = &run_aimed(&set, &[la, Subject::Exact], false)[0];
//! assert_eq!(counts.rays, 200);
//! assert_eq!(counts.cracks, 0); // watertight: nothing slips through
//! ```
//!
//! # How every figure is judged
//!
//! The reference decides hit or miss exactly for the values it is given, so each back end is
//! judged on exactly the values it saw: the suite's `f64` rays and triangles rounded to the
//! back end's precision, converted back to `f64` (an exact conversion). Its tie rule (see
//! the `exact` crate docs) makes a ray exactly through a shared edge or vertex hit
//! exactly one of the triangles there. Distances are judged against the exact rational
//! `t* = N / D` ([`metrics::t_error`]), not a rounded value, so an error in ulps is exact
//! for `f64` back ends too.
//!
//! # Definitions
//!
//! - **Disagreement**: for rays through a whole scene (closest hit through the back end's
//!   BVH), the back end hits something where the reference hits nothing, or the reverse. For
//!   aimed rays, any outcome other than a single triangle: a crack, a double hit, or, on a
//!   ray that is not an exact tie, one hit on another triangle than the reference's (wrong
//!   side). On an exact tie either single triangle is right: the reference's choice is a
//!   convention (its tie rule), not geometry.
//! - **Wrong triangle**: both hit, but the nearest triangle differs (judged on the rays for
//!   which the reference computed its nearest hit).
//! - **Distance error**: `|t - t*| / t*` for every reported hit, and the same in units of the
//!   last place of `t*` in the back end's precision (ulps). Median, 99.9th percentile
//!   (nearest rank) and maximum.
//! - **NaN or infinite**: a reported hit whose `t`, `u` or `v` is NaN or infinite (the hard
//!   limit is on NaN: the reference itself reports `t = inf` where the exact distance exceeds
//!   `f64::MAX`). A hit with `t <= 0` or beyond `t_max`, or `occludes` disagreeing with
//!   `intersect`, is a **contract violation**.
//! - **Aimed rays** ([`rays::edge_rays`], [`rays::vertex_rays`]): each ray is aimed at a
//!   point exactly on a shared edge (`p + k/16 (q - p)`, exact in `f64`) or at a shared vertex,
//!   and is tested against the triangles there (the two at the edge, the ring at the vertex)
//!   with any-hit semantics (each triangle's kernel asked separately). Only rays that really
//!   cross the surface there are kept: all those triangles face the ray the same way (the
//!   exact sign of `n . d`; no fold seen along the ray, no triangle collapsed by rounding in
//!   a far-moved mesh), so that any consistent tie rule crosses exactly one of them; and, as
//!   a check, the reference in the back end's precision hits exactly one. (At a fold seen
//!   along the ray the number of triangles crossed, one or three, depends on the direction of
//!   the perturbation a tie rule applies; such rays would make "double hit" depend on the
//!   rule rather than on the kernel.) The mesh's coordinates are rounded to `f32` first, so
//!   both precisions see the same triangles.
//!   - `exact` aim: origin and direction are `f32` values and `origin + dir` is exactly the
//!     target, so the `f32` and `f64` back ends both see a ray exactly through the edge or
//!     vertex: an **exact tie**.
//!   - `f64` aim: the ray passes exactly through the target in `f64`; the `f32` back ends see
//!     its rounding, which generally passes near the edge, not through it. The reference then
//!     says which single triangle that rounded ray crosses.
//! - **Crack**: an aimed ray that hits none of the triangles at its edge or vertex.
//! - **Double hit**: an aimed ray that more than one of them reports hit (any-hit
//!   semantics, as the issue defines it). The reference's tie rule makes exactly one count.
//!   A kernel whose edges are simply closed (an edge function of exactly 0 counts as inside:
//!   `la-mt`, `ga`, `ga-report`) reports both triangles of an exact tie; `la` and
//!   `ga-plucker` break exact zeros with a tie rule of their own (a symbolic perturbation of
//!   the ray), so they report one. Which one may differ from the reference's choice, and
//!   that is not an error. The column `double_hits_off_tie` counts the double hits on rays
//!   that are not exact ties.
//! - **Hit fraction** (sweeps): the fraction of the random rays that hit the moved or scaled
//!   mesh; `hit_fraction_change` is its difference from the unmoved, unscaled mesh's.
//!
//! # Families of the stability suite
//!
//! 1. Aimed rays at shared edges and vertices of the bunny and the tile grid (in
//!    `accuracy.csv`, and at every step of the sweeps in `stability.csv`).
//! 2. Sweeps ([`suite::Sweep`]): the mesh moved by 0, 10^2, 10^3, 10^4 times its extent
//!    (every coordinate), and scaled by 10^-3 to 10^3; aimed rays are rebuilt on each moved
//!    mesh, the random rays are moved with it.
//! 3. Grazing rays (along an edge's line, in a triangle's plane, tilted `2^-20` out of it),
//!    axis-aligned rays (zero direction components, infinite inverses in the BVH), rays
//!    starting exactly on the surface (never to hit the triangles containing their origin).
//! 4. Degenerate input ([`degenerate::soup`]): zero-area, collinear and needle triangles,
//!    repeated vertices, huge triangles beside tiny ones, NaN and infinite vertices and rays,
//!    `t_max` of 0, negative or NaN. Never a panic, never a hit on a degenerate triangle,
//!    never a NaN in an output.

pub mod degenerate;
pub mod fp;
pub mod mesh;
pub mod metrics;
pub mod plot;
pub mod rays;
pub mod rows;
pub mod runner;
pub mod suite;
pub mod summary;
