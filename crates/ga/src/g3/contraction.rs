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
//! Where a method equals an operator on a pair the impl calls the operator, so each expansion
//! is written (and tested) once: for blades with `r ≤ s` (`r ≥ s`) the left (right)
//! contraction is the report's inner product `|`, and so is the scalar product of equal
//! grades; contracting onto the pseudoscalar is the geometric product (`a ⌋ I = a I`); the
//! commutator of two vectors is their outer product and that of a vector and a bivector their
//! inner product. Where only a rotor's scalar or bivector part takes part the impl scales or
//! calls the bivector kernel. The other pairs are hand-expanded kernels whose comments list
//! the blade products they keep; `tests/oracle.rs` checks every pair against
//! the generic algebra of the `ga-reference` crate.

use crate::Scalar;
use crate::g3::{Bivector, Multivector, Rotor, Trivector, Vector};

/// The left contraction `a ⌋ b`: for an `r`-blade `a` and an `s`-blade `b`, the grade `s - r`
/// part of `a b`, zero when `r > s`.
///
/// A scalar contracts as scaling (`λ ⌋ b = λ b`), which is where it differs from the report's
/// inner product `|`. The [module docs](self) list the pairs and their result types.
pub trait LeftContraction<Rhs> {
    /// The smallest type that holds the result.
    type Output;
    /// `self ⌋ b`.
    #[must_use]
    fn left_contraction(self, b: Rhs) -> Self::Output;
}

/// The right contraction `a ⌊ b`: for an `r`-blade `a` and an `s`-blade `b`, the grade `r - s`
/// part of `a b`, zero when `s > r`.
///
/// A scalar on the right scales (`a ⌊ λ = λ a`). The [module docs](self) list the pairs and
/// their result types.
pub trait RightContraction<Rhs> {
    /// The smallest type that holds the result.
    type Output;
    /// `self ⌊ b`.
    #[must_use]
    fn right_contraction(self, b: Rhs) -> Self::Output;
}

/// The scalar product `a ∗ b = ⟨a b⟩₀`, the scalar part of the geometric product.
///
/// Only equal grades contribute, and `a ∗ b = b ∗ a`. The [module docs](self) list the pairs.
pub trait ScalarProduct<Rhs> {
    /// The scalar type `T`.
    type Output;
    /// `⟨self b⟩₀`.
    #[must_use]
    fn scalar_product(self, b: Rhs) -> Self::Output;
}

/// The commutator product `a × b = (a b - b a) / 2`: the terms of `a b` whose blades
/// anticommute (the commuting ones cancel).
///
/// Antisymmetric: `a × b = -(b × a)`. For bivectors it is the bivector part of `a b`; for
/// planes `B = b I` and `C = c I` with normals `b` and `c` that is minus the plane of
/// `b.cross(c)`, as `I` is central and squares to -1:
///
/// ```
/// use ga::g3::Vector;
///
/// let (b, c) = (Vector::<f64>::new(1.0, 2.0, 3.0), Vector::new(-2.0, 0.5, 1.0));
/// assert_eq!(b.undual().commutator(c.undual()), -b.cross(c).undual());
/// ```
///
/// The [module docs](self) list the pairs and their result types.
pub trait Commutator<Rhs> {
    /// The smallest type that holds the result.
    type Output;
    /// `(self b - b self) / 2`.
    #[must_use]
    fn commutator(self, b: Rhs) -> Self::Output;
}

/// Gives each listed type `$method` as an inherent method generic over the right-hand side,
/// forwarding to `$Trait`: inherent methods come first in method lookup, so `a.method(b)`
/// works without the trait in scope, for every `b` the trait is implemented for.
macro_rules! inherent_method {
    ($Trait:ident::$method:ident, $summary:literal: $($ty:ident),+) => {$(
        impl<T: Scalar> $ty<T> {
            #[doc = $summary]
            ///
            #[doc = concat!(
                "Defined for the right-hand types that [`", stringify!($Trait), "`] lists, with ",
                "the smallest result type; this inherent form needs no import of the trait."
            )]
            #[must_use]
            #[inline]
            pub fn $method<B>(self, b: B) -> <Self as $Trait<B>>::Output
            where
                Self: $Trait<B>,
            {
                $Trait::$method(self, b)
            }
        }
    )+};
}

inherent_method!(LeftContraction::left_contraction, "The left contraction `self ⌋ b`.":
    Vector, Bivector, Trivector, Rotor, Multivector);
inherent_method!(RightContraction::right_contraction, "The right contraction `self ⌊ b`.":
    Vector, Bivector, Trivector, Rotor, Multivector);
inherent_method!(ScalarProduct::scalar_product, "The scalar product `⟨self b⟩₀`.":
    Vector, Bivector, Trivector, Rotor, Multivector);
// No trivector: it commutes with everything in 3D, so all its commutators vanish.
inherent_method!(Commutator::commutator, "The commutator product `(self b - b self) / 2`.":
    Vector, Bivector, Rotor, Multivector);

/// Implements `$Trait` for pairs on which it equals an operator (module docs, "Kernels") by
/// calling the operator, so the expansion is written once.
macro_rules! same_as_operator {
    ($Trait:ident::$method:ident, $name:literal, $sym:literal;
     $($a:ident $op:tt $b:ident -> $out:ty),+ $(,)?) => {$(
        #[doc = concat!(
            $name, " `", stringify!($a), " ", $sym, " ", stringify!($b), "`, which is `",
            stringify!($a), " ", stringify!($op), " ", stringify!($b), "` on these types."
        )]
        impl<T: Scalar> $Trait<$b<T>> for $a<T> {
            type Output = $out;
            #[inline]
            fn $method(self, b: $b<T>) -> $out {
                self $op b
            }
        }
    )+};
}

mod commutator;
mod left_contraction;
mod right_contraction;
mod scalar_product;
