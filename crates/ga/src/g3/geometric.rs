//! The geometric product `*` between every pair of G3 types.
//!
//! Each kernel is the bilinear expansion of its two operands over the Cayley table below (row
//! times column, with `e31 = e3 e1`), keeping only the terms whose blades both types hold, so
//! no zero grade is ever multiplied. The result is the smallest type holding every grade that
//! can appear: vector times vector is a [`Rotor`] (scalar plus bivector), vector times bivector
//! is odd (vector plus trivector) and so a [`Multivector`]. The kernels are written by
//! `ga-codegen` (`g3/generated/geometric.rs`); the tests in `tests/` compare every one against
//! the generic bitmask algebra of the `ga-reference` crate.
//!
#![doc = include_str!("generated/cayley.md")]
//!
//! (Report figure 2.5 prints this table transposed: its entry in row `e1`, column `e2` is
//! `-e12`, which is `e2 e1`; see [`crate::errata`].)
//!
//! # The full product
//!
//! `Multivector * Multivector` needs all 64 terms. On x86-64 with AVX2 and FMA it uses the
//! structure of the table in the bitmask basis `1, e1, e2, e12, e3, e13, e23, e123`, where
//! `e_k e_j = ±e_(k XOR j)`: `a b = Σ_k a_k (e_k b)`, and `e_k b` is `b` with its lanes permuted
//! by `l ↦ l XOR k` (in-register shuffles) and a fixed sign pattern. With `b` in two 4-lane
//! registers that is 16 fused multiply-adds, 6 shuffles and 6 sign flips; `Multivector` stores
//! its coefficients in that order (with `e31` for `e13`) so no reordering is needed. Other
//! targets use the 64 terms written out. `Rotor * Rotor` uses the same idea on the four lanes
//! `1, e12, e23, e31` (bitmasks `0, 3, 6, 5`, closed under XOR), like a quaternion product.

// The operator traits name the product (`Mul`, `BitXor`, ...) but each kernel is a sum of
// products of coefficients, which is what clippy's heuristic flags.
#![allow(clippy::suspicious_arithmetic_impl)]

use core::ops::{Mul, MulAssign};

use crate::Scalar;
use crate::g3::{Multivector, Rotor};

// The products with SIMD kernels, and the assigning operators.

/// Geometric product `Multivector * Multivector -> Multivector`, all 64 terms of the Cayley
/// table. On x86-64 with AVX2 and FMA (this workspace builds with `-C target-cpu=x86-64-v3`)
/// it is the SIMD kernel of the module docs; elsewhere the 64 terms written out.
impl<T: Scalar> Mul<Multivector<T>> for Multivector<T> {
    type Output = Multivector<T>;
    #[inline]
    fn mul(self, b: Multivector<T>) -> Multivector<T> {
        Multivector { c: T::geometric_product(&self.c, &b.c) }
    }
}

/// The geometric product of two multivectors written out term by term (the Cayley table, as
/// `ga-codegen` expands it), for targets without a SIMD kernel and as its check.
#[inline]
pub(crate) fn geometric_portable<T: Scalar>(
    a: Multivector<T>,
    b: Multivector<T>,
) -> Multivector<T> {
    crate::g3::generated::geometric_multivector_multivector(a, b)
}

/// Geometric product `Rotor * Rotor -> Rotor`: composition of rotations (`(R2 * R1)` applies
/// `R1` first). The same 16 products as a quaternion product; for f32 on x86-64 with AVX2 and
/// FMA it is an SSE kernel, elsewhere the lane-by-lane expansion below.
impl<T: Scalar> Mul<Rotor<T>> for Rotor<T> {
    type Output = Rotor<T>;
    #[inline]
    fn mul(self, b: Rotor<T>) -> Rotor<T> {
        Rotor::from_array(T::rotor_product(self.to_array(), b.to_array()))
    }
}

/// The rotor product written lane by lane, for targets without a SIMD kernel and as its check.
#[inline]
pub(crate) fn rotor_product_portable<T: Scalar>(a: Rotor<T>, b: Rotor<T>) -> Rotor<T> {
    // a b = Σ_k a_k (e_k b) over a's blades 1, e12, e23, e31, with
    //   1 b   = [ b.s,    b.e12,  b.e23,  b.e31]
    //   e12 b = [-b.e12,  b.s,    b.e31, -b.e23]   (e12 e12 = -1, e12 e23 = -e31, e12 e31 = e23)
    //   e23 b = [-b.e23, -b.e31,  b.s,    b.e12]   (e23 e31 = -e12, e23 e12 = e31)
    //   e31 b = [-b.e31,  b.e23, -b.e12,  b.s  ]   (e31 e12 = -e23, e31 e23 = e12)
    // Lanes s, e12, e23, e31 are the blade bitmasks {0, 3, 6, 5}, a group under XOR, so row k
    // reads b's lanes in the order l XOR k and its signs can ride on the broadcast a_k. Written
    // lane by lane with one shape, the optimiser turns it into broadcasts, shuffles and FMAs.
    let (n12, n23, n31) = (-a.e12, -a.e23, -a.e31);
    let lane = |x: [T; 4], y: [T; 4]| {
        let mad = T::mul_add_if_fma;
        mad(x[3], y[3], mad(x[2], y[2], mad(x[1], y[1], x[0] * y[0])))
    };
    Rotor::new(
        lane([a.s, n12, n23, n31], [b.s, b.e12, b.e23, b.e31]),
        lane([a.s, a.e12, n23, a.e31], [b.e12, b.s, b.e31, b.e23]),
        lane([a.s, a.e12, a.e23, n31], [b.e23, b.e31, b.s, b.e12]),
        lane([a.s, n12, a.e23, a.e31], [b.e31, b.e23, b.e12, b.s]),
    )
}

impl<T: Scalar> MulAssign for Rotor<T> {
    /// `self = self * rhs`: the composite applies `rhs` first, then the old `self`.
    #[inline]
    fn mul_assign(&mut self, rhs: Self) {
        *self = *self * rhs;
    }
}

impl<T: Scalar> MulAssign for Multivector<T> {
    /// `self = self * rhs`.
    #[inline]
    fn mul_assign(&mut self, rhs: Self) {
        *self = *self * rhs;
    }
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::g3::generated::{geometric_multivector_multivector, geometric_rotor_rotor};

    /// Whether `a` equals `b` within `tol` relative to `b`'s largest coefficient (at least 1).
    pub(crate) fn close<const N: usize>(a: [f64; N], b: [f64; N], tol: f64) -> bool {
        let scale = b.iter().fold(1.0f64, |m, x| m.max(x.abs()));
        a.iter().zip(&b).all(|(x, y)| (x - y).abs() <= tol * scale)
    }

    /// A fixed sequence of coefficients in [-2, 2) (an LCG: no dependency, same every run).
    pub(crate) fn coefficients(seed: u64) -> impl Iterator<Item = f64> {
        let mut state = seed;
        core::iter::repeat_with(move || {
            state = state.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            (state >> 11) as f64 / (1u64 << 53) as f64 * 4.0 - 2.0
        })
    }

    /// The hand-written rotor kernels (the lane-by-lane FMA form, and the SIMD kernel behind
    /// `Rotor * Rotor`) against the generated expansion, and the multivector operator against
    /// its generated form.
    #[test]
    fn hand_kernels_match_the_generated_expansions() {
        let mut x = coefficients(3);
        for _ in 0..1000 {
            let a = Rotor::<f64>::from_array(core::array::from_fn(|_| x.next().unwrap()));
            let b = Rotor::<f64>::from_array(core::array::from_fn(|_| x.next().unwrap()));
            let want = geometric_rotor_rotor(a, b);
            assert!(rotor_product_portable(a, b).abs_diff_eq(want, 1e-13), "{a} {b}");
            assert!((a * b).abs_diff_eq(want, 1e-13), "{a} {b}");
            let (a32, b32) = (Rotor::from_array(a.to_array().map(|v| v as f32)), {
                Rotor::from_array(b.to_array().map(|v| v as f32))
            });
            let want32 = geometric_rotor_rotor(a32, b32);
            assert!((a32 * b32).abs_diff_eq(want32, 1e-5), "{a32} {b32}");
            assert!(rotor_product_portable(a32, b32).abs_diff_eq(want32, 1e-5));

            let m = Multivector::<f64>::from_array(core::array::from_fn(|_| x.next().unwrap()));
            let n = Multivector::<f64>::from_array(core::array::from_fn(|_| x.next().unwrap()));
            assert!((m * n).abs_diff_eq(geometric_multivector_multivector(m, n), 1e-13));
        }
    }
}
