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
