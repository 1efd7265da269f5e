//! The point map of a motor applied lane-wise, for x86-64 with AVX2 and FMA (compiled only when
//! the build enables both, as this workspace does with `-C target-cpu=x86-64-v3`; other targets
//! use the portable form in `scalar.rs`).
//!
//! [`Motor::transform_points`](crate::pga::Motor::transform_points) works out the sandwich's
//! 4×4 matrix once; each point `p` (its four coefficients in storage order) then becomes
//! `Σ_k c_k p_k` with `c_k` the matrix column that multiplies storage lane `k`: four broadcasts,
//! one multiply and three fused multiply-adds on one 4-lane register (SSE for f32, AVX for
//! f64), the same instructions as `glam::Affine3A::transform_point3a`. Left to itself the
//! compiler vectorises the loop across eight points instead, transposing them through the
//! stack, which measured slower on short arrays.

use core::arch::x86_64::*;

/// `Σ_k columns[k] p[k]` for an f32 point `p`.
#[inline]
pub(crate) fn map_point_f32(columns: &[[f32; 4]; 4], p: [f32; 4]) -> [f32; 4] {
    // SAFETY: this module is compiled only when the build enables avx2 and fma (see the `cfg`
    // on its declaration), so the CPU running this code has them.
    unsafe { map_point_f32_fma(columns, p) }
}

/// `Σ_k columns[k] p[k]` for an f64 point `p`.
#[inline]
pub(crate) fn map_point_f64(columns: &[[f64; 4]; 4], p: [f64; 4]) -> [f64; 4] {
    // SAFETY: this module is compiled only when the build enables avx2 and fma, so the CPU
    // running this code has them.
    unsafe { map_point_f64_fma(columns, p) }
}

#[inline]
#[target_feature(enable = "avx2,fma")]
fn map_point_f32_fma(c: &[[f32; 4]; 4], p: [f32; 4]) -> [f32; 4] {
    // SAFETY: each column is 4 f32, read by one unaligned load.
    let col = |k: usize| unsafe { _mm_loadu_ps(c[k].as_ptr()) };
    let mut v = _mm_mul_ps(col(0), _mm_set1_ps(p[0]));
    v = _mm_fmadd_ps(col(1), _mm_set1_ps(p[1]), v);
    v = _mm_fmadd_ps(col(2), _mm_set1_ps(p[2]), v);
    v = _mm_fmadd_ps(col(3), _mm_set1_ps(p[3]), v);
    let mut out = [0.0; 4];
    // SAFETY: `out` has 4 f32, one unaligned store writes them.
    unsafe { _mm_storeu_ps(out.as_mut_ptr(), v) };
    out
}

#[inline]
#[target_feature(enable = "avx2,fma")]
fn map_point_f64_fma(c: &[[f64; 4]; 4], p: [f64; 4]) -> [f64; 4] {
    // SAFETY: each column is 4 f64, read by one unaligned load.
    let col = |k: usize| unsafe { _mm256_loadu_pd(c[k].as_ptr()) };
    let mut v = _mm256_mul_pd(col(0), _mm256_set1_pd(p[0]));
    v = _mm256_fmadd_pd(col(1), _mm256_set1_pd(p[1]), v);
    v = _mm256_fmadd_pd(col(2), _mm256_set1_pd(p[2]), v);
    v = _mm256_fmadd_pd(col(3), _mm256_set1_pd(p[3]), v);
    let mut out = [0.0; 4];
    // SAFETY: `out` has 4 f64, one unaligned store writes them.
    unsafe { _mm256_storeu_pd(out.as_mut_ptr(), v) };
    out
}

/// `Motor`'s blades in storage order as bitmasks of `e0, e1, e2, e3` (bit 0 is `e0`), each
/// with its orientation against the ascending product of its factors (`e31 = -e13`).
const MOTOR_BLADES: [(u8, i8); 8] = [
    (0b0000, 1),
    (0b0011, 1),
    (0b0101, 1),
    (0b1001, 1),
    (0b0110, 1),
    (0b1010, -1),
    (0b1100, 1),
    (0b1111, 1),
];

/// `e_A e_B = f(A, B) e_(A XOR B)` for ascending blades: each generator of `B` moves past the
/// generators of `A` above it, one sign each; `e1, e2, e3` square to 1 and `e0` to 0.
const fn blade_sign(a: u8, b: u8) -> i8 {
    if a & b & 1 != 0 {
        return 0;
    }
    let (mut swaps, mut g) = (0, 0);
    while g < 4 {
        if b >> g & 1 == 1 {
            swaps += (a >> (g + 1)).count_ones();
        }
        g += 1;
    }
    if swaps % 2 == 0 { 1 } else { -1 }
}

/// The motor product `c = a b` as eight terms, one per blade `x` of `a` (storage order): in a
/// lane order `order` (lane `i` holds `flip[i]` times storage coefficient `order[i]`), output
/// lane `i` gains `a_x sign[x][i] b[lane[x][i]]`, `b` in that lane order too. `e_x e_j = ±e_i`
/// for exactly one `j` per `i`, so each term is a broadcast times a signed lane permutation of
/// `b`; the sign is 0 where `e_x` and `e_j` both hold `e0`.
struct MotorTerms {
    lane: [[i32; 8]; 8],
    sign: [[f64; 8]; 8],
}

const fn motor_terms(order: [usize; 8], flip: [i8; 8]) -> MotorTerms {
    let mut t = MotorTerms { lane: [[0; 8]; 8], sign: [[0.0; 8]; 8] };
    let mut x = 0;
    while x < 8 {
        let mut i = 0;
        while i < 8 {
            let (bx, bi) = (MOTOR_BLADES[x], MOTOR_BLADES[order[i]]);
            let mut j = 0;
            while MOTOR_BLADES[order[j]].0 != bi.0 ^ bx.0 {
                j += 1;
            }
            let bj = MOTOR_BLADES[order[j]];
            // (o_x ê_x)(o_j ê_j) = o_x o_j f(x, j) ê_i = o_x o_j o_i f(x, j) e_i (o = ±1), and
            // the lane order's flips on both sides of the term.
            let sign = bx.1 * bj.1 * bi.1 * blade_sign(bx.0, bj.0) * flip[i] * flip[j];
            t.lane[x][i] = j as i32;
            t.sign[x][i] = sign as f64;
            i += 1;
        }
        x += 1;
    }
    t
}

/// The terms in storage order: one 8-lane register holds an f32 motor.
const STORAGE_TERMS: MotorTerms = motor_terms([0, 1, 2, 3, 4, 5, 6, 7], [1; 8]);

/// The product of two f32 motors in storage order: the eight terms of [`MotorTerms`], each a
/// broadcast, a lane permutation of `b`, a multiplication by the signs and a fused
/// multiply-add (`x = 0`, the scalar, needs neither permutation nor signs).
#[inline(always)]
pub(crate) fn motor_product_f32(a: &[f32; 8], b: &[f32; 8]) -> [f32; 8] {
    const SIGNS: [[f32; 8]; 8] = {
        let mut s = [[0.0; 8]; 8];
        let mut k = 0;
        while k < 64 {
            s[k / 8][k % 8] = STORAGE_TERMS.sign[k / 8][k % 8] as f32;
            k += 1;
        }
        s
    };
    // SAFETY: the intrinsics need AVX2 and FMA, which the build enables wherever this module is
    // compiled; every load and store reads or writes 8 lanes of an 8-element array.
    unsafe {
        let b = _mm256_loadu_ps(b.as_ptr());
        let term = |x: usize| {
            let lanes = _mm256_loadu_si256(STORAGE_TERMS.lane[x].as_ptr().cast());
            let signs = _mm256_loadu_ps(SIGNS[x].as_ptr());
            (_mm256_set1_ps(a[x]), _mm256_mul_ps(_mm256_permutevar8x32_ps(b, lanes), signs))
        };
        let mut c0 = _mm256_mul_ps(_mm256_set1_ps(a[0]), b);
        let (a1, b1) = term(1);
        let mut c1 = _mm256_mul_ps(a1, b1);
        for x in (2..8).step_by(2) {
            let (ax, bx) = term(x);
            c0 = _mm256_fmadd_ps(ax, bx, c0);
            let (ay, by) = term(x + 1);
            c1 = _mm256_fmadd_ps(ay, by, c1);
        }
        let mut out = [0.0; 8];
        _mm256_storeu_ps(out.as_mut_ptr(), _mm256_add_ps(c0, c1));
        out
    }
}

/// The dual-quaternion lane order for f64, two 4-lane registers: `G = [1, e12, e23, e31]` and
/// `E = [e0123, -e03, -e01, -e02]` (`E = e0123 G` lane by lane). A blade `x` without `e0` maps
/// `G` to `G` and `E` to `E` by one permutation; a blade with `e0` maps `G` to `E` and kills `E`
/// (a test checks this on the table), so each term is one 4-lane permutation of one register.
const DUAL_ORDER: [usize; 8] = [0, 4, 6, 5, 7, 3, 1, 2];
const DUAL_FLIP: [i8; 8] = [1, 1, 1, 1, 1, -1, -1, -1];
const DUAL_TERMS: MotorTerms = motor_terms(DUAL_ORDER, DUAL_FLIP);

/// The product of two f64 motors in storage order: `b` gathered into `G` and `E` (storage
/// `[1, e01, e02, e03]`, `[e12, e31, e23, e0123]`), the twelve non-zero 4-lane terms of
/// [`DUAL_TERMS`], and the gather back.
#[inline(always)]
pub(crate) fn motor_product_f64(a: &[f64; 8], b: &[f64; 8]) -> [f64; 8] {
    /// `[f64; 4]` lane `l` is f32 lanes `2l, 2l + 1`: the permutations as 8 f32 lanes.
    const PAIRS: [[i32; 8]; 8] = {
        let mut p = [[0; 8]; 8];
        let mut x = 0;
        while x < 8 {
            let mut k = 0;
            while k < 8 {
                p[x][k] = 2 * (DUAL_TERMS.lane[x][4 + k / 2] % 4) + (k % 2) as i32;
                k += 1;
            }
            x += 1;
        }
        p
    };
    // SAFETY: the intrinsics need AVX2 and FMA, which the build enables wherever this module is
    // compiled; every load and store reads or writes 4 lanes of an 8-element array.
    unsafe {
        let lo = _mm256_loadu_pd(b.as_ptr());
        let hi = _mm256_loadu_pd(b.as_ptr().add(4));
        // G = [lo0, hi0, hi2, hi1]; E = [hi3, lo3, lo1, lo2] with the flips [+, -, -, -].
        let g = _mm256_blend_pd::<0b0001>(_mm256_permute4x64_pd::<0b01_10_00_00>(hi), lo);
        let e = _mm256_blend_pd::<0b0001>(
            _mm256_permute4x64_pd::<0b10_01_11_00>(lo),
            _mm256_permute4x64_pd::<0b00_00_00_11>(hi),
        );
        let flip = _mm256_setr_pd(1.0, -1.0, -1.0, -1.0);
        let e = _mm256_mul_pd(e, flip);
        let perm = |v: __m256d, x: usize| {
            let lanes = _mm256_loadu_si256(PAIRS[x].as_ptr().cast());
            _mm256_castps_pd(_mm256_permutevar8x32_ps(_mm256_castpd_ps(v), lanes))
        };
        let signs =
            |x: usize, half: usize| _mm256_loadu_pd(DUAL_TERMS.sign[x][4 * half..].as_ptr());
        let (mut cg, mut ce) = (_mm256_setzero_pd(), _mm256_setzero_pd());
        for (x, &ax) in a.iter().enumerate() {
            let ax = _mm256_set1_pd(ax);
            if DUAL_TERMS.sign[x][0] != 0.0 {
                // No e0 in x: G to G and E to E.
                cg = _mm256_fmadd_pd(ax, _mm256_mul_pd(perm(g, x), signs(x, 0)), cg);
                ce = _mm256_fmadd_pd(ax, _mm256_mul_pd(perm(e, x), signs(x, 1)), ce);
            } else {
                ce = _mm256_fmadd_pd(ax, _mm256_mul_pd(perm(g, x), signs(x, 1)), ce);
            }
        }
        let ce = _mm256_mul_pd(ce, flip);
        // Storage [1, e01, e02, e03] = [G0, E2, E3, E1]; [e12, e31, e23, e0123] = [G1, G3, G2, E0].
        let lo = _mm256_blend_pd::<0b0001>(_mm256_permute4x64_pd::<0b01_11_10_00>(ce), cg);
        let hi = _mm256_blend_pd::<0b1000>(
            _mm256_permute4x64_pd::<0b00_10_11_01>(cg),
            _mm256_permute4x64_pd::<0b00_00_00_00>(ce),
        );
        let mut out = [0.0; 8];
        _mm256_storeu_pd(out.as_mut_ptr(), lo);
        _mm256_storeu_pd(out.as_mut_ptr().add(4), hi);
        out
    }
}

/// `Line ^ Plane` for f32 in storage order, `P = X1 Y1 + s (X2 Y2 + X3 Y3)` (derivation in
/// `pga/meet.rs`).
///
/// The line is read as its first four coefficients and its last two, the pieces a caller's
/// copy of it is stored in: a load that straddles two stores waits for them to reach the cache
/// (store forwarding fails), which cost 14 ns a call where the line was passed by value.
#[inline(always)]
pub(crate) fn meet_line_plane_f32(a: &[f32; 6], b: &[f32; 4]) -> [f32; 4] {
    // SAFETY: the intrinsics need AVX2 and FMA, which the build enables wherever this module is
    // compiled; the loads read lanes 0..4 and 4..6 of `a` and the 4 of `b`.
    unsafe {
        let l0 = _mm_loadu_ps(a.as_ptr()); // e01 e02 e03 e12
        let l1 = _mm_castpd_ps(_mm_load_sd(a.as_ptr().add(4).cast())); // e31 e23 0 0
        let b = _mm_loadu_ps(b.as_ptr()); // e0 e1 e2 e3
        let x1 = _mm_permute_ps::<0b11_10_00_01>(l0); // e02 e01 e03 e12
        let y1 = _mm_permute_ps::<0b11_10_11_01>(b); // b1 b3 b2 b3
        let x2 = _mm_shuffle_ps::<0b00_01_10_00>(l0, l1); // e01 e03 e23 e31
        let y2 = _mm_permute_ps::<0b10_00_01_10>(b); // b2 b1 b0 b2
        let x3 = _mm_unpacklo_ps(_mm_permute_ps::<0b00_00_01_11>(l0), l1); // e12 e31 e02 e23
        let y3 = _mm_permute_ps::<0b01_11_00_00>(b); // b0 b0 b3 b1
        let u = _mm_fmadd_ps(x2, y2, _mm_mul_ps(x3, y3));
        let p = _mm_fmadd_ps(u, _mm_setr_ps(-1.0, -1.0, -1.0, 1.0), _mm_mul_ps(x1, y1));
        let mut out = [0.0; 4];
        _mm_storeu_ps(out.as_mut_ptr(), p);
        out
    }
}

/// `p / p[3]` lane by lane for f32: one vector division (the three scalar ones it replaces
/// occupy the divider three times as long).
#[inline(always)]
pub(crate) fn divide_by_last_f32(p: [f32; 4]) -> [f32; 4] {
    // SAFETY: the intrinsics need AVX2 and FMA, which the build enables wherever this module is
    // compiled; the load and the store access the 4 lanes of 4-element arrays.
    unsafe {
        let v = _mm_loadu_ps(p.as_ptr());
        let mut out = [0.0; 4];
        _mm_storeu_ps(out.as_mut_ptr(), _mm_div_ps(v, _mm_permute_ps::<0xFF>(v)));
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The layout `motor_product_f64` assumes: a blade without `e0` permutes `G` and `E` alike,
    /// one with `e0` takes `G` to `E` and `E` to zero; and every term has a sign.
    #[test]
    fn dual_terms_keep_their_halves() {
        for (x, (blade, _)) in MOTOR_BLADES.into_iter().enumerate() {
            let (lane, sign) = (DUAL_TERMS.lane[x], DUAL_TERMS.sign[x]);
            if blade & 1 == 0 {
                for i in 0..4 {
                    assert!(lane[i] < 4 && lane[i + 4] == lane[i] + 4, "{x}");
                    assert!(sign[i] != 0.0 && sign[i + 4] != 0.0, "{x}");
                }
            } else {
                assert_eq!(sign[..4], [0.0; 4], "{x}");
                assert!((4..8).all(|i| lane[i] < 4 && sign[i] != 0.0), "{x}");
            }
        }
        // In storage order, the zero terms are exactly the products of two e0 blades.
        for (x, (blade, _)) in MOTOR_BLADES.into_iter().enumerate() {
            for i in 0..8 {
                let j = STORAGE_TERMS.lane[x][i] as usize;
                let both = blade & MOTOR_BLADES[j].0 & 1 == 1;
                assert_eq!(STORAGE_TERMS.sign[x][i] == 0.0, both, "{x} {i}");
            }
        }
    }
}
