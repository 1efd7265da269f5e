//! The product traits shared by every algebra: the products that are methods rather than
//! operators (left and right contractions, scalar product, commutator) and the sandwich.
//!
//! Each is a trait so that one method name serves every right-hand type, with the smallest
//! result type for each pair; every type of every algebra also has them as inherent methods
//! generic over the right-hand side (so a call needs no import), and generic code names the
//! trait (`A: LeftContraction<B>`). A pair on which the product is identically zero has no
//! impl.

/// The left contraction `a ⌋ b`: for an `r`-blade `a` and an `s`-blade `b`, the grade `s - r`
/// part of `a b`, zero when `r > s`.
///
/// A scalar contracts as scaling (`λ ⌋ b = λ b`), which is where it differs from the report's
/// inner product `|`. [`crate::g3::contraction`] lists the pairs of G3 and their result types.
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
/// A scalar on the right scales (`a ⌊ λ = λ a`). [`crate::g3::contraction`] lists the pairs
/// of G3 and their result types.
pub trait RightContraction<Rhs> {
    /// The smallest type that holds the result.
    type Output;
    /// `self ⌊ b`.
    #[must_use]
    fn right_contraction(self, b: Rhs) -> Self::Output;
}

/// The scalar product `a ∗ b = ⟨a b⟩₀`, the scalar part of the geometric product.
///
/// Only equal grades contribute, and `a ∗ b = b ∗ a`. [`crate::g3::contraction`] lists the
/// pairs of G3.
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
/// [`crate::g3::contraction`] lists the pairs of G3 and their result types.
pub trait Commutator<Rhs> {
    /// The smallest type that holds the result.
    type Output;
    /// `(self b - b self) / 2`.
    #[must_use]
    fn commutator(self, b: Rhs) -> Self::Output;
}

/// The sandwich `v x ṽ`: the versor `v` applied to `x` (a rotation, reflection, translation
/// or other motion when `v` is a unit versor of that kind).
///
/// Only the grades of `x` are kept: for a versor (a product of invertible vectors) the other
/// grades cancel, and the kernels leave their terms out. The result is not normalised: it is
/// scaled by `v ṽ` (1 for a unit versor). For an odd versor (a vector, a plane) this is
/// `v x ṽ` without the sign `(-1)^grade` that a reflection formula may add.
pub trait Sandwich<X> {
    /// The smallest type that holds the result.
    type Output;
    /// `self x self̃`, keeping the grades of `x`.
    #[must_use]
    fn sandwich(self, x: X) -> Self::Output;
}
