//! SIMD kernels for x86-64 with AVX2 and FMA, compiled only when the build enables both (as
//! this workspace does with `-C target-cpu=x86-64-v3`); other targets use the portable
//! expansions.
//!
//! # The geometric product of two multivectors
//!
//! In the bitmask basis `1, e1, e2, e12, e3, e13, e23, e123` (blade `k` is the product of the
//! generators whose bits are set in `k`) the product of two basis blades is
//! `e_k e_j = σ(k, j) e_(k XOR j)`. So `a b = Σ_k a_k (e_k b)`, and `e_k b` is `b` with its lanes
//! permuted by `l ↦ l XOR k` and multiplied by a sign pattern `σ_k`:
//!
//! | `k` | lane permutation of `b` | signs `σ_k` of lanes 0-3 (4-7 repeat them) |
//! |-----|-------------------------|--------------------------------------------|
//! | 0 | identity | `+ + + +` |
//! | 1 | swap within pairs | `+ + + +` |
//! | 2 | swap the two pairs | `+ - + -` |
//! | 3 | reverse each half | `- + - +` |
//! | 4 | swap halves | `+ - - +` |
//! | 5 | swap halves, then within pairs | `- + + -` |
//! | 6 | swap halves, then the pairs | `- - + +` |
//! | 7 | swap halves, then reverse | `- - + +` |
//!
//! (Each row is read off the Cayley table in [`crate::g3::geometric`]; the tests check the
//! kernels against the term-by-term expansion.) The signs repeat between the halves, so each
//! row costs one broadcast of `a_k` with its signs applied (an XOR), one permutation of `b`
//! shared by two rows, and one fused multiply-add per half: 16 FMAs and 6 permutations for f64,
//! 8 FMAs and 7 permutations for f32, no gathers and no branches.
//!
//! The storage order of [`Multivector`](crate::g3::Multivector) is this bitmask order except
//! that slot 5 holds `e31 = -e13`; the kernels negate that lane of `b` on the way in, fold the
//! sign of `a`'s into `σ_5`, and negate the lane of the result on the way out.
//!
//! Not used: G3 is also the algebra of 2×2 complex matrices (`e1, e2, e3` the Pauli matrices),
//! whose product needs only 8 f64 FMAs; with the conversions in and out that kernel takes 27
//! operations where this one takes 33, but it measured 3.06-3.35 ns against 2.95-3.01 ns (its
//! chain of dependent operations is longer), and it rounds every coefficient at the scale of
//! the whole product: in `(1 + 1.1e-9 e3)(1 + 1.3e-9 e1)` its `e31` is off by 4.5e-8 relative.

use core::arch::x86_64::*;

/// `a b` for f64 multivectors in storage order.
#[inline]
pub(crate) fn geometric_f64(a: &[f64; 8], b: &[f64; 8]) -> [f64; 8] {
    // SAFETY: this module is compiled only when the build enables avx2 and fma (see the `cfg`
    // on its declaration), so the CPU running this code has them.
    unsafe { geometric_f64_avx2(a, b) }
}

/// `a b` for f32 multivectors in storage order.
#[inline]
pub(crate) fn geometric_f32(a: &[f32; 8], b: &[f32; 8]) -> [f32; 8] {
    // SAFETY: this module is compiled only when the build enables avx2 and fma, so the CPU
    // running this code has them.
    unsafe { geometric_f32_avx2(a, b) }
}

/// Sign masks: `-0.0` flips a lane's sign under XOR, `0.0` keeps it.
const N: f64 = -0.0;
const P: f64 = 0.0;

#[target_feature(enable = "avx2,fma")]
fn geometric_f64_avx2(a: &[f64; 8], b: &[f64; 8]) -> [f64; 8] {
    let signs = |m: [f64; 4]| _mm256_setr_pd(m[0], m[1], m[2], m[3]);
    let lane1 = signs([P, N, P, P]);
    // The halves of b in bitmask order: lanes 0-3 are 1, e1, e2, e12; 4-7 are e3, e13, e23, e123.
    let lo = _mm256_setr_pd(b[0], b[1], b[2], b[3]);
    let hi = _mm256_xor_pd(_mm256_setr_pd(b[4], b[5], b[6], b[7]), lane1);
    let (lo1, hi1) = (_mm256_permute_pd::<0b0101>(lo), _mm256_permute_pd::<0b0101>(hi));
    let (lo2, hi2) =
        (_mm256_permute4x64_pd::<0b01_00_11_10>(lo), _mm256_permute4x64_pd::<0b01_00_11_10>(hi));
    let (lo3, hi3) =
        (_mm256_permute4x64_pd::<0b00_01_10_11>(lo), _mm256_permute4x64_pd::<0b00_01_10_11>(hi));
    // a_k broadcast with σ_k applied; a[5] is e31 = -e13, so σ_5 is negated.
    let s = |k: usize, m: [f64; 4]| _mm256_xor_pd(_mm256_set1_pd(a[k]), signs(m));
    let s0 = _mm256_set1_pd(a[0]);
    let s1 = _mm256_set1_pd(a[1]);
    let s2 = s(2, [P, N, P, N]);
    let s3 = s(3, [N, P, N, P]);
    let s4 = s(4, [P, N, N, P]);
    let s5 = s(5, [P, N, N, P]);
    let s6 = s(6, [N, N, P, P]);
    let s7 = s(7, [N, N, P, P]);
    // Two accumulators per half halve the dependency chain.
    let c_lo0 = _mm256_fmadd_pd(
        s5,
        hi1,
        _mm256_fmadd_pd(s4, hi, _mm256_fmadd_pd(s1, lo1, _mm256_mul_pd(s0, lo))),
    );
    let c_lo1 = _mm256_fmadd_pd(
        s7,
        hi3,
        _mm256_fmadd_pd(s6, hi2, _mm256_fmadd_pd(s3, lo3, _mm256_mul_pd(s2, lo2))),
    );
    let c_hi0 = _mm256_fmadd_pd(
        s5,
        lo1,
        _mm256_fmadd_pd(s4, lo, _mm256_fmadd_pd(s1, hi1, _mm256_mul_pd(s0, hi))),
    );
    let c_hi1 = _mm256_fmadd_pd(
        s7,
        lo3,
        _mm256_fmadd_pd(s6, lo2, _mm256_fmadd_pd(s3, hi3, _mm256_mul_pd(s2, hi2))),
    );
    let c_lo = _mm256_add_pd(c_lo0, c_lo1);
    let c_hi = _mm256_xor_pd(_mm256_add_pd(c_hi0, c_hi1), lane1);
    let mut out = [0.0; 8];
    // SAFETY: `out` has 8 f64, the two unaligned stores write lanes 0-3 and 4-7.
    unsafe {
        _mm256_storeu_pd(out.as_mut_ptr(), c_lo);
        _mm256_storeu_pd(out.as_mut_ptr().add(4), c_hi);
    }
    out
}

#[target_feature(enable = "avx2,fma")]
fn geometric_f32_avx2(a: &[f32; 8], b: &[f32; 8]) -> [f32; 8] {
    const N: f32 = -0.0;
    const P: f32 = 0.0;
    let signs = |m: [f32; 4]| _mm256_setr_ps(m[0], m[1], m[2], m[3], m[0], m[1], m[2], m[3]);
    let lane5 = _mm256_setr_ps(P, P, P, P, P, N, P, P);
    let b0 = _mm256_xor_ps(_mm256_setr_ps(b[0], b[1], b[2], b[3], b[4], b[5], b[6], b[7]), lane5);
    // In-lane permutations l ↦ l XOR k for k < 4; k ≥ 4 first swaps the 128-bit halves.
    let b1 = _mm256_permute_ps::<0b10_11_00_01>(b0);
    let b2 = _mm256_permute_ps::<0b01_00_11_10>(b0);
    let b3 = _mm256_permute_ps::<0b00_01_10_11>(b0);
    let b4 = _mm256_permute2f128_ps::<0x01>(b0, b0);
    let b5 = _mm256_permute_ps::<0b10_11_00_01>(b4);
    let b6 = _mm256_permute_ps::<0b01_00_11_10>(b4);
    let b7 = _mm256_permute_ps::<0b00_01_10_11>(b4);
    let s = |k: usize, m: [f32; 4]| _mm256_xor_ps(_mm256_set1_ps(a[k]), signs(m));
    let c0 = _mm256_fmadd_ps(
        s(6, [N, N, P, P]),
        b6,
        _mm256_fmadd_ps(
            s(4, [P, N, N, P]),
            b4,
            _mm256_fmadd_ps(s(2, [P, N, P, N]), b2, _mm256_mul_ps(_mm256_set1_ps(a[0]), b0)),
        ),
    );
    let c1 = _mm256_fmadd_ps(
        s(7, [N, N, P, P]),
        b7,
        _mm256_fmadd_ps(
            s(5, [P, N, N, P]),
            b5,
            _mm256_fmadd_ps(s(3, [N, P, N, P]), b3, _mm256_mul_ps(_mm256_set1_ps(a[1]), b1)),
        ),
    );
    let c = _mm256_xor_ps(_mm256_add_ps(c0, c1), lane5);
    let mut out = [0.0; 8];
    // SAFETY: `out` has 8 f32, one unaligned store writes them all.
    unsafe { _mm256_storeu_ps(out.as_mut_ptr(), c) };
    out
}

/// `a b` for f32 rotors `[s, e12, e23, e31]`; see `rotor_product_portable` for the rows.
#[inline]
pub(crate) fn rotor_product_f32(a: [f32; 4], b: [f32; 4]) -> [f32; 4] {
    // SAFETY: this module is compiled only when the build enables avx2 and fma, so the CPU
    // running this code has them.
    unsafe { rotor_product_f32_fma(a, b) }
}

/// The reverse `[s, -e12, -e23, -e31]` of an f32 rotor, one XOR.
#[inline]
pub(crate) fn rotor_reverse_f32(a: [f32; 4]) -> [f32; 4] {
    // SAFETY: this module is compiled only when the build enables avx2 and fma (and so SSE),
    // so the CPU running this code has them.
    unsafe { rotor_reverse_f32_sse(a) }
}

#[target_feature(enable = "avx2,fma")]
fn rotor_product_f32_fma(a: [f32; 4], b: [f32; 4]) -> [f32; 4] {
    const N: f32 = -0.0;
    const P: f32 = 0.0;
    // Row k of a b is a_k times b's lanes in the order l XOR k, with the signs of
    // `rotor_product_portable` applied to the broadcast a_k.
    let b0 = _mm_setr_ps(b[0], b[1], b[2], b[3]);
    let b1 = _mm_permute_ps::<0b10_11_00_01>(b0);
    let b2 = _mm_permute_ps::<0b01_00_11_10>(b0);
    let b3 = _mm_permute_ps::<0b00_01_10_11>(b0);
    let s1 = _mm_xor_ps(_mm_set1_ps(a[1]), _mm_setr_ps(N, P, P, N));
    let s2 = _mm_xor_ps(_mm_set1_ps(a[2]), _mm_setr_ps(N, N, P, P));
    let s3 = _mm_xor_ps(_mm_set1_ps(a[3]), _mm_setr_ps(N, P, N, P));
    let c0 = _mm_fmadd_ps(s1, b1, _mm_mul_ps(_mm_set1_ps(a[0]), b0));
    let c1 = _mm_fmadd_ps(s3, b3, _mm_mul_ps(s2, b2));
    let mut out = [0.0; 4];
    // SAFETY: `out` has 4 f32, one unaligned store writes them.
    unsafe { _mm_storeu_ps(out.as_mut_ptr(), _mm_add_ps(c0, c1)) };
    out
}

#[target_feature(enable = "avx2,fma")]
fn rotor_reverse_f32_sse(a: [f32; 4]) -> [f32; 4] {
    let r = _mm_xor_ps(_mm_setr_ps(a[0], a[1], a[2], a[3]), _mm_setr_ps(0.0, -0.0, -0.0, -0.0));
    let mut out = [0.0; 4];
    // SAFETY: `out` has 4 f32, one unaligned store writes them.
    unsafe { _mm_storeu_ps(out.as_mut_ptr(), r) };
    out
}

#[cfg(test)]
mod tests {
    use crate::g3::geometric::geometric_portable;
    use crate::g3::geometric::tests::coefficients;
    use crate::g3::{Multivector, Rotor};

    /// `x + y = s + e` exactly (Knuth's two-sum).
    fn two_sum(x: f64, y: f64) -> (f64, f64) {
        let s = x + y;
        let v = s - x;
        (s, (x - (s - v)) + (y - v))
    }

    /// Adds `x` exactly to a non-overlapping expansion, smallest component first (Shewchuk's
    /// grow-expansion); the sum of the components, smallest first, is its value.
    fn grow(expansion: &mut Vec<f64>, x: f64) {
        let mut q = x;
        for c in expansion.iter_mut() {
            (q, *c) = two_sum(q, *c);
        }
        expansion.push(q);
    }

    /// Checks every coefficient of the f64 kernel's `a b` against the exact product: the
    /// error of each is at most 3ε times the sum of the magnitudes of its own 8 terms, i.e. a
    /// small coefficient is accurate next to large ones (a product of 2×2 complex matrices,
    /// with half the multiplications, is accurate only relative to the whole product). The
    /// terms and their signs come from the reference algebra in the bitmask basis, where
    /// storage lane 5 is `e31 = -e13`; each product is split exactly by an FMA.
    #[test]
    fn f64_kernel_is_accurate_coefficient_by_coefficient() {
        let g3 = ga_reference::Algebra::new(3, 0, 0);
        let flip = |l: usize| if l == 5 { -1.0 } else { 1.0 };
        let check = |a: [f64; 8], b: [f64; 8]| {
            let got = super::geometric_f64(&a, &b);
            let mut exact: [Vec<f64>; 8] = core::array::from_fn(|l| vec![-got[l]]);
            let mut magnitude = [0.0f64; 8];
            for (k, &ak) in a.iter().enumerate() {
                for (j, &bj) in b.iter().enumerate() {
                    let (sign, l) = g3.blade_product(k, j);
                    let (x, y) = (ak * flip(k), bj * flip(j) * sign * flip(l));
                    let p = x * y;
                    grow(&mut exact[l], p);
                    grow(&mut exact[l], x.mul_add(y, -p));
                    magnitude[l] += p.abs();
                }
            }
            for l in 0..8 {
                let error = exact[l].iter().sum::<f64>().abs();
                assert!(error <= 3.0 * f64::EPSILON * magnitude[l], "lane {l}: {a:?} {b:?}");
            }
        };
        let mut x = coefficients(11);
        let mut scales = coefficients(12);
        for _ in 0..2_000 {
            let (a, b) = ([(); 8].map(|_| x.next().unwrap()), [(); 8].map(|_| x.next().unwrap()));
            check(a, b);
            // Coefficients of unrelated magnitudes, 2^-40 to 2^40.
            let mut skew = || 2f64.powi((scales.next().unwrap() * 20.0) as i32);
            check(a.map(|v| v * skew()), b.map(|v| v * skew()));
            // Near 1: the other coefficients are 2^-30 times the scalar.
            let near_one = |c: [f64; 8]| {
                let mut c = c.map(|v| v * 2f64.powi(-30));
                c[0] = 1.0;
                c
            };
            check(near_one(a), near_one(b));
        }
    }

    #[test]
    fn simd_products_match_the_term_by_term_expansion() {
        let mut x = coefficients(7);
        for _ in 0..500 {
            let a: [f64; 8] = core::array::from_fn(|_| x.next().unwrap());
            let b: [f64; 8] = core::array::from_fn(|_| x.next().unwrap());
            let want = geometric_portable(Multivector { c: a }, Multivector { c: b });
            let got = super::geometric_f64(&a, &b);
            assert!(Multivector { c: got }.abs_diff_eq(want, 1e-13), "{a:?} {b:?}");

            let (a32, b32) = (a.map(|v| v as f32), b.map(|v| v as f32));
            let want = geometric_portable(Multivector { c: a32 }, Multivector { c: b32 });
            let got = super::geometric_f32(&a32, &b32);
            assert!(Multivector { c: got }.abs_diff_eq(want, 1e-5), "{a32:?} {b32:?}");
        }
        // Rotors: products and reverses.
        for _ in 0..200 {
            let a: [f32; 4] = core::array::from_fn(|_| x.next().unwrap() as f32);
            let b: [f32; 4] = core::array::from_fn(|_| x.next().unwrap() as f32);
            let (ra, rb) = (Rotor::from_array(a), Rotor::from_array(b));
            let want = crate::g3::geometric::rotor_product_portable(ra, rb);
            assert!(Rotor::from_array(super::rotor_product_f32(a, b)).abs_diff_eq(want, 1e-5));
            assert_eq!(super::rotor_reverse_f32(a), [a[0], -a[1], -a[2], -a[3]]);
        }
        // Every pair of basis blades exactly, both precisions.
        for i in 0..8 {
            for j in 0..8 {
                let (a, b) = (Multivector::<f64>::basis(i), Multivector::<f64>::basis(j));
                assert_eq!(super::geometric_f64(&a.c, &b.c), geometric_portable(a, b).c);
                let (a, b) = (Multivector::<f32>::basis(i), Multivector::<f32>::basis(j));
                assert_eq!(super::geometric_f32(&a.c, &b.c), geometric_portable(a, b).c);
            }
        }
    }
}
