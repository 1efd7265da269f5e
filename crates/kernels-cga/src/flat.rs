//! The conformal objects every cell builds on: Euclidean vectors, points and flat lines in
//! `ga::cga` types.
//!
//! A flat object through a point `x` always carries a factor `e∞`, and
//! `up(x) ∧ e∞ = (eₒ + x + ½x² e∞) ∧ e∞ = (eₒ + x) ∧ e∞`: the `½x²` term of the embedding is
//! killed by the outer product. So the cells write a point of a flat as `eₒ + x` ([`point`]),
//! whose `e4`, `e5` coefficients are the exact constants `-½`, `½`. That is the same
//! multivector after `∧ e∞`, exactly, and it avoids the precision loss of the stored
//! `½x² ± ½` (see `ga::cga::geometry`, "Precision"): the products then only multiply
//! coordinates by `±½` and `±1`, which is exact, so every coefficient of a flat is one
//! rounding of the Euclidean expression (the moment `x ∧ d`, the direction `d`) and scaling
//! the scene by a power of two scales every value exactly.

use ga::Scalar;
use ga::cga::{Trivector, Vector};

/// The Euclidean vector `x` (no `e4`, `e5` part).
#[inline(always)]
pub(crate) fn vector<T: Scalar>(x: [T; 3]) -> Vector<T> {
    Vector::new(x[0], x[1], x[2], T::ZERO, T::ZERO)
}

/// The point `x` as a factor of a flat: `eₒ + x`, equal to `up(x)` after `∧ e∞`.
#[inline(always)]
pub(crate) fn point<T: Scalar>(x: Vector<T>) -> Vector<T> {
    Vector::E_O + x
}

/// The flat line through `x` with direction `d`: `up(x) ∧ d ∧ e∞ = (eₒ + x) ∧ d ∧ e∞`, whose
/// coefficients are the moment `x ∧ d` (on `e_ij4` and `e_ij5`, equal) and the direction (on
/// `e_i45`).
#[inline(always)]
pub(crate) fn line<T: Scalar>(x: Vector<T>, d: Vector<T>) -> Trivector<T> {
    point(x) ^ d ^ Vector::E_INF
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn flat_points_equal_the_embedding_after_the_outer_product_with_infinity() {
        let x = vector([3.0, -2.0, 0.5]);
        let d = vector([0.25, 1.0, -4.0]);
        let up = Vector::up(ga::g3::Vector::new(3.0, -2.0, 0.5));
        assert_eq!(point(x) ^ Vector::E_INF, up ^ Vector::E_INF);
        assert_eq!(line(x, d), up ^ d ^ Vector::E_INF);
        // The flat line of two points is the line through them.
        let y = vector([3.25, -1.0, -3.5]);
        assert_eq!(point(x) ^ point(y) ^ Vector::E_INF, line(x, d));
    }
}
