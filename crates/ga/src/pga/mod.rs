//! Projective geometric algebra R(3,0,1), plane-based: planes are vectors, lines bivectors,
//! points trivectors.
//!
//! ```
//! use ga::pga::{Plane, Point};
//!
//! // The planes x = 1 (e1 - e0: x - 1 = 0) and y = 2 meet in a line ...
//! let (x1, y2) = (Plane::new(-1.0, 1.0, 0.0, 0.0), Plane::new(-2.0, 0.0, 1.0, 0.0));
//! let line = x1 ^ y2;
//! // ... that passes through the point (1, 2, 5): joined with it, it spans no plane.
//! let p = Point::new(5.0, 2.0, 1.0, 1.0); // z e021 + y e013 + x e032 + e123
//! assert_eq!(line & p, Plane::ZERO);
//! // The join of two points is the line through them; both lie on it.
//! let q = Point::new(0.0, 2.0, 1.0, 1.0);
//! let pq = p & q;
//! assert_eq!(pq & q, Plane::ZERO);
//! // A point lies on a plane exactly when their outer product vanishes; for the origin `e123`
//! // and the plane y = 2 it is `-2 e0 ^ e123 = -2 e0123` (e2 ^ e123 = 0).
//! assert_eq!((x1 ^ p).e0123, 0.0);
//! assert_eq!((y2 ^ Point::new(0.0, 0.0, 0.0, 1.0)).e0123, -2.0);
//! ```
//!
//! # Basis, metric and orientation
//!
//! Four generators: `e0` with `e0² = 0` (the degenerate, projective direction) and `e1, e2, e3`
//! with `e1² = e2² = e3² = 1`. The sixteen basis blades, in the order of
//! [`Multivector::from_array`], `to_array` and every type's fields, are those of bivector.net
//! and Klein:
//!
//! `1, e0, e1, e2, e3, e01, e02, e03, e12, e31, e23, e021, e013, e032, e123, e0123`
//!
//! where each name is the product of its generators in the order written: `e31 = e3 e1`,
//! `e021 = e0 e2 e1 = -e012`, `e013 = e0 e1 e3`, `e032 = e0 e3 e2`, `e0123 = e0 e1 e2 e3`.
//!
//! | type | blades | meaning |
//! |------|--------|---------|
//! | [`Plane`] | `e0, e1, e2, e3` | `a e1 + b e2 + c e3 + d e0`: the plane `ax + by + cz + d = 0` |
//! | [`Line`] | `e01, e02, e03, e12, e31, e23` | the meet of two planes, the join of two points |
//! | [`Point`] | `e021, e013, e032, e123` | `x e032 + y e013 + z e021 + w e123`: `(x, y, z) / w` |
//! | [`Motor`] | `1, e01, e02, e03, e12, e31, e23, e0123` | rigid motions (the even subalgebra) |
//! | [`Rotor`] | `1, e12, e31, e23` | rotations about lines through the origin |
//! | [`Translator`] | `1, e01, e02, e03` | translations |
//! | [`Pseudoscalar`] | `e0123` | |
//! | [`Multivector`] | all sixteen | |
//!
//! A point with `w = 0` is an ideal point: the direction `(x, y, z)`.
//!
//! # Operators
//!
//! As in [`crate::g3`], each operator means one thing, and every product returns the smallest
//! type holding every blade it can produce (a pair whose product is identically zero has no
//! impl):
//!
//! - `a * b` geometric product;
//! - `a ^ b` outer product, the **meet**: plane ^ plane is their line, line ^ plane their
//!   point;
//! - `a & b` regressive product, the **join**: point & point is the line through them, line &
//!   point the plane through both;
//! - `a | b` inner product, the symmetric "fat dot" of bivector.net and Klein: for an
//!   `r`-blade and an `s`-blade the grade `|r - s|` part of the geometric product, scalars
//!   included (a scalar scales);
//! - `left_contraction`, `right_contraction`, `scalar_product`, `commutator` and `sandwich`
//!   are methods (traits in [`crate::products`]); `v.sandwich(x)` is `v x ṽ`, keeping the
//!   grades of `x`.
//!
//! # Dual
//!
//! `e0` squares to zero, so the pseudoscalar has no inverse and `A I⁻¹` does not exist. The dual
//! is the metric-free Poincaré (Hodge-like) duality through the right complement: each basis
//! blade `e_A` maps to `±e_Ā`, its complementary blade, signed so that
//! `e_A ^ dual(e_A) = e0123`; `undual` is the left complement (`undual(e_A) ^ e_A = e0123`), the
//! inverse of `dual`. For example `dual(1) = e0123`, `dual(e0) = e123`, `dual(e1) = e032`,
//! `dual(e12) = e03` and `dual(e123) = -e0`. The join is defined through it:
//! `a & b = undual(dual(a) ^ dual(b))`.
//!
//! `norm_squared` is `⟨A Ã⟩₀`, so the blades containing `e0` do not count (the Euclidean norm of
//! a plane's normal, of a point's weight `w`).
//!
//! These are the types and products, written by `ga-codegen` from its table, except
//! `Multivector * Multivector` and `Motor * Motor`, in `geometric.rs` (the generated
//! lane-by-lane AVX2 kernel or three G3 products; three quaternion products), checked against
//! the generated expansions. Built on them by hand: [`geometry`] (points from coordinates and
//! back, planes from normals or three points, joins and meets, distances, angles, projections) and
//! [`motor`] (rotors, translators and motors from axes, angles and translations, `exp` of a
//! line and `log` of a motor in closed form, normalisation, the motor applied to each type,
//! its matrix).
//!
//! # Cayley table of the geometric product
//!
//! Row times column, `e_row e_col`:
//!
#![doc = include_str!("generated/cayley.md")]
//!
//! # Result types
//!
//! The type each product returns for each pair of types (`T` a scalar, `—` no impl: the
//! product is identically zero), as generated:
//!
#![doc = include_str!("generated/products.md")]

pub(crate) mod generated;
pub(crate) mod geometric;
pub mod geometry;
#[cfg(feature = "glam")]
mod glam_interop;
mod meet;
pub mod motor;
#[cfg(all(target_arch = "x86_64", target_feature = "avx2", target_feature = "fma"))]
pub(crate) mod simd;

pub use generated::{Line, Motor, Multivector, Plane, Point, Pseudoscalar, Rotor, Translator};
