//! The geometric algebra G(3,0,0) of Euclidean 3D space, with a type per grade.
//!
//! | type | grades | fields |
//! |------|--------|--------|
//! | scalar `T` (`f32`/`f64`) | 0 | |
//! | [`Vector`] | 1 | `e1, e2, e3` |
//! | [`Bivector`] | 2 | `e12, e23, e31` |
//! | [`Trivector`] | 3 | `e123` |
//! | [`Rotor`] | 0, 2 | `s, e12, e23, e31` |
//! | [`Multivector`] | 0-3 | all eight, report order |
//!
//! See the crate docs for the conventions and the operator table, [`outer`], [`inner`] and
//! [`regressive`] for which pairs of types each operator joins, [`contraction`] for the
//! products that are methods (contractions, scalar product, commutator), and [`geometry`] for
//! lines, planes and triangles.

mod bivector;
pub mod contraction;
mod convert;
mod generated;
pub mod geometric;
pub mod geometry;
#[cfg(feature = "glam")]
mod glam_interop;
pub mod inner;
pub(crate) mod linear;
mod multivector;
pub mod outer;
pub mod regressive;
mod rotor;
#[cfg(all(target_arch = "x86_64", target_feature = "avx2", target_feature = "fma"))]
pub(crate) mod simd;
mod trivector;
mod vector;

pub use bivector::Bivector;
pub use contraction::{Commutator, LeftContraction, RightContraction, ScalarProduct};
pub use convert::NarrowError;
pub use multivector::{BASIS, GRADES, Multivector};
pub use rotor::Rotor;
pub use trivector::Trivector;
pub use vector::Vector;
