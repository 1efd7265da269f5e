//! `Multivector * Multivector`: lane by lane, or R(4,1) as four copies of G3.
//!
//! Where the build has AVX2 and FMA, the product is the kernel `ga-codegen` writes to
//! `generated/lanes.rs`: blades by bitmask, `e1, e2, e3` the lane bits and `e4, e5` the block
//! bits (f32; f64 makes `e3` a block bit too), so output block `B` is a sum of broadcast
//! coefficients of `a` times signed lane permutations of the blocks of `b`: 128 eight-lane
//! fused multiply-adds for the 1,024 terms (the derivation is in
//! `crates/ga-codegen/src/lanes.rs`). Elsewhere it is `blockwise`:
//!
//! Every blade of R(4,1) is a G3 blade followed by one of `1, e4, e5, e45` (the basis is in
//! increasing generator order, so `e_S e4 = e_S4` with no sign), and so
//! `a = Σ_p A_p E_p` with `E_p = e4^i e5^j` (`p = i + 2j`) and four G3 parts `A_p`.
//! `e4` and `e5` anticommute with `e1, e2, e3`, so `E_p X = X^(i+j) E_p` (the grade involution
//! applied `i + j` times), and `e5 e4 = -e4 e5`, `e4² = 1`, `e5² = -1` give
//! `E_p E_q = (-1)^(j (k + l)) E_(p XOR q)` for `q = k + 2l`. Hence
//!
//! `a b = Σ_p Σ_q (-1)^(j (k + l)) (A_p B_q^(i+j)) E_(p XOR q)`:
//!
//! sixteen G3 geometric products, 1,024 terms, exactly the Cayley table's (none is zero in a
//! non-degenerate algebra). Each is G3's kernel behind `T::geometric_product` (the AVX2 kernel
//! of `g3::simd` where the build has it) instead of a 1,024-term scalar expansion; each output
//! coefficient is the same sum of the same products as the expansion's, in another order. G3's
//! storage holds `e31 = -e13`, so the `e13` lanes change sign on the way in and out.
//!
//! The tests check it against the generated expansion.

use core::ops::{Mul, MulAssign};

use crate::Scalar;
use crate::cga::Multivector;

/// For each part `p` (`1, e4, e5, e45`), the index in `Multivector::to_array` of each G3
/// storage lane (`1, e1, e2, e12, e3, e31, e23, e123`) times `E_p`; lane 5 is `-e13 E_p`.
const LANES: [[usize; 8]; 4] = [
    [0, 1, 2, 6, 3, 7, 10, 16],
    [4, 8, 11, 17, 13, 19, 22, 26],
    [5, 9, 12, 18, 14, 20, 23, 27],
    [15, 21, 24, 28, 25, 29, 30, 31],
];

/// The grade involution of a G3 multivector in storage order (G3's `grade_involution`).
#[inline]
fn involution<T: Scalar>(c: [T; 8]) -> [T; 8] {
    crate::g3::Multivector { c }.grade_involution().c
}

/// `a` as its four G3 parts.
#[inline]
fn split<T: Scalar>(a: Multivector<T>) -> [[T; 8]; 4] {
    let c = a.to_array();
    LANES.map(|lanes| {
        let mut part = lanes.map(|i| c[i]);
        part[5] = -part[5];
        part
    })
}

/// Geometric product `Multivector * Multivector -> Multivector`: the generated lane-by-lane
/// kernel of `generated/lanes.rs` where the build has AVX2 and FMA, else `blockwise` (the
/// portable kernel below).
impl<T: Scalar> Mul<Multivector<T>> for Multivector<T> {
    type Output = Multivector<T>;
    #[inline]
    fn mul(self, b: Multivector<T>) -> Multivector<T> {
        // In place: through copies (`to_array`), the kernel's vector loads would wait on the
        // copies' narrower stores (store forwarding fails).
        Multivector::from_array(T::cga_geometric(self.as_array(), b.as_array()))
    }
}

/// `a b` as the sixteen G3 products of the module docs (coefficients in basis order): the
/// portable kernel.
#[cfg_attr(
    all(target_arch = "x86_64", target_feature = "avx2", target_feature = "fma", not(test)),
    allow(dead_code)
)]
#[inline]
pub(crate) fn blockwise<T: Scalar>(a: &[T; 32], b: &[T; 32]) -> [T; 32] {
    let (a, b) = (split(Multivector::from_array(*a)), split(Multivector::from_array(*b)));
    let flipped = b.map(involution);
    let mut parts = [[T::ZERO; 8]; 4];
    for p in 0..4 {
        let (i, j) = (p & 1, p >> 1);
        for q in 0..4 {
            let (k, l) = (q & 1, q >> 1);
            let right = if (i + j) % 2 == 1 { &flipped[q] } else { &b[q] };
            let product = T::geometric_product(&a[p], right);
            let out = &mut parts[p ^ q];
            if j * (k + l) % 2 == 1 {
                for (o, x) in out.iter_mut().zip(product) {
                    *o -= x;
                }
            } else {
                for (o, x) in out.iter_mut().zip(product) {
                    *o += x;
                }
            }
        }
    }
    let mut c = [T::ZERO; 32];
    for (lanes, mut part) in LANES.iter().zip(parts) {
        part[5] = -part[5];
        for (&i, x) in lanes.iter().zip(part) {
            c[i] = x;
        }
    }
    c
}

impl<T: Scalar> MulAssign for Multivector<T> {
    /// `self = self * rhs`.
    #[inline]
    fn mul_assign(&mut self, rhs: Self) {
        *self = *self * rhs;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cga::generated::geometric_multivector_multivector;
    use crate::g3::geometric::tests::{close, coefficients};

    /// The kernel against the generated 1,024-term expansion, in both precisions.
    #[test]
    fn hand_kernel_matches_the_generated_expansion() {
        let mut x = coefficients(13);
        for _ in 0..500 {
            let a = Multivector::<f64>::from_array(core::array::from_fn(|_| x.next().unwrap()));
            let b = Multivector::<f64>::from_array(core::array::from_fn(|_| x.next().unwrap()));
            let want = geometric_multivector_multivector(a, b).to_array();
            assert!(close((a * b).to_array(), want, 1e-14), "{a:?} {b:?}");
            assert!(close(blockwise(&a.to_array(), &b.to_array()), want, 1e-14), "{a:?} {b:?}");
            let f = |m: Multivector<f64>| Multivector::from_array(m.to_array().map(|v| v as f32));
            let want32 = geometric_multivector_multivector(f(a), f(b)).to_array().map(f64::from);
            let got32 = (f(a) * f(b)).to_array().map(f64::from);
            assert!(close(got32, want32, 1e-5), "{a:?} {b:?}");
            let got32 = blockwise(&f(a).to_array(), &f(b).to_array()).map(f64::from);
            assert!(close(got32, want32, 1e-5), "{a:?} {b:?}");
        }
    }

    /// Each basis blade times each is the Cayley table's entry, exactly.
    #[test]
    fn basis_products_are_the_cayley_table() {
        let e = |k: usize| {
            Multivector::<f64>::from_array(core::array::from_fn(|n| f64::from(u8::from(n == k))))
        };
        for i in 0..32 {
            for j in 0..32 {
                let want = geometric_multivector_multivector(e(i), e(j)).to_array();
                assert_eq!((e(i) * e(j)).to_array(), want, "{i} {j}");
                assert_eq!(blockwise(&e(i).to_array(), &e(j).to_array()), want, "{i} {j}");
            }
        }
    }
}
