//! The products that are methods rather than operators: the left and right contractions, the
//! scalar product and the commutator product, for every pair of G3 types where they are not
//! identically zero.
//!
//! They are methods so that each operator keeps one meaning (see the crate docs). Each is a
//! trait ([`LeftContraction`], [`RightContraction`], [`ScalarProduct`], [`Commutator`]) so
//! that one name serves every right-hand type, and every type also has them as inherent
//! methods generic over the right-hand side, so a call needs no import. Generic code names
//! the trait (`A: LeftContraction<B>`).
//!
//! ```
//! use ga::g3::{Bivector, Rotor, Trivector, Vector};
//!
//! // A scalar on the left of a contraction scales; a bivector contracts a vector to zero.
//! let r = Rotor::new(2.0, 1.0, 0.0, 0.0);
//! assert_eq!(r.left_contraction(Vector::E1), Vector::E1 * 2.0);
//! // A vector contracts a bivector to a vector in its plane, as the report's `|` does.
//! assert_eq!(Vector::<f64>::E1.left_contraction(Bivector::E12), Vector::E2);
//! assert_eq!(Bivector::<f64>::E12.scalar_product(Bivector::E12), -1.0);
//! // The commutator of two planes is the bivector part of their product: e12 e23 = -e31.
//! assert_eq!(Bivector::<f64>::E12.commutator(Bivector::E23), -Bivector::E31);
//! assert_eq!(Trivector::<f64>::I.right_contraction(Vector::E3), Bivector::E12);
//! ```
//!
//! For an `r`-blade `a` and an `s`-blade `b` (each extends bilinearly to sums of blades):
//!
//! | method | written | is |
//! |--------|---------|----|
//! | `a.left_contraction(b)` | `a ⌋ b` | grade `s - r` of `a b`, zero when `r > s` |
//! | `a.right_contraction(b)` | `a ⌊ b` | grade `r - s` of `a b`, zero when `s > r` |
//! | `a.scalar_product(b)` | `a ∗ b` | `⟨a b⟩₀`, the scalar part of `a b`, of type `T` |
//! | `a.commutator(b)` | `a × b` | `(a b - b a) / 2`: the blade products that anticommute |
//!
//! A scalar contracts as scaling: `λ ⌋ b = λ b` and `a ⌊ λ = λ a`.
//!
//! The contractions agree with the report's inner product `|` except where a scalar takes part
//! (`|` is zero there) or the grades are the wrong way round (`r > s` for the left one, `s > r`
//! for the right one), where the contraction is zero and `|` is not.
//!
//! # Pairs and result types
//!
//! Each pair returns the smallest type that holds every grade it can produce (`T` is the
//! scalar). A `—` marks a pair whose product is zero for all inputs in 3D; it has no impl, as
//! such pairs have no operator.
//!
//! Left contraction `a ⌋ b`; the gaps contract a higher grade onto a lower one (a rotor's
//! grades, 0 and 2, are both below a trivector's):
//!
//! | `a` \ `b` | Vector | Bivector | Trivector | Rotor | Multivector |
//! |---|---|---|---|---|---|
//! | Vector | `T` | Vector | Bivector | Vector | Multivector |
//! | Bivector | — | `T` | Vector | `T` | Multivector |
//! | Trivector | — | — | `T` | — | `T` |
//! | Rotor | Vector | Rotor | Multivector | Rotor | Multivector |
//! | Multivector | Multivector | Multivector | Multivector | Multivector | Multivector |
//!
//! Right contraction `a ⌊ b`, the mirror image:
//!
//! | `a` \ `b` | Vector | Bivector | Trivector | Rotor | Multivector |
//! |---|---|---|---|---|---|
//! | Vector | `T` | — | — | Vector | Multivector |
//! | Bivector | Vector | `T` | — | Rotor | Multivector |
//! | Trivector | Bivector | Vector | `T` | Multivector | Multivector |
//! | Rotor | Vector | `T` | — | Rotor | Multivector |
//! | Multivector | Multivector | Multivector | `T` | Multivector | Multivector |
//!
//! Scalar product `a ∗ b`; blades of different grades have no scalar part in their product,
//! and a rotor has no vector or trivector part:
//!
//! | `a` \ `b` | Vector | Bivector | Trivector | Rotor | Multivector |
//! |---|---|---|---|---|---|
//! | Vector | `T` | — | — | — | `T` |
//! | Bivector | — | `T` | — | `T` | `T` |
//! | Trivector | — | — | `T` | — | `T` |
//! | Rotor | — | `T` | — | `T` | `T` |
//! | Multivector | `T` | `T` | `T` | `T` | `T` |
//!
//! Commutator `a × b`; in 3D the pseudoscalar commutes with everything, so every commutator
//! with a trivector vanishes, and so does a rotor's scalar part:
//!
//! | `a` \ `b` | Vector | Bivector | Trivector | Rotor | Multivector |
//! |---|---|---|---|---|---|
//! | Vector | Bivector | Vector | — | Vector | Multivector |
//! | Bivector | Vector | Bivector | — | Bivector | Multivector |
//! | Trivector | — | — | — | — | — |
//! | Rotor | Vector | Bivector | — | Bivector | Multivector |
//! | Multivector | Multivector | Multivector | — | Multivector | Multivector |
//!
//! # Kernels
//!
//! Every kernel is written by `ga-codegen` (in `g3/generated/`) from the table of the
//! reference algebra, with only its non-zero terms; `tests/oracle.rs` and
//! `tests/generated_kernels.rs` check every pair against the `ga-reference` crate. The traits
//! live in [`crate::products`], shared by every algebra, and are re-exported here.

pub use crate::products::{Commutator, LeftContraction, RightContraction, ScalarProduct};
