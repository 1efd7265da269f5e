//! The point map of an even versor applied lane-wise, for x86-64 with AVX2 and FMA (compiled
//! only when the build enables both, as this workspace does with `-C target-cpu=x86-64-v3`;
//! other targets use the portable form in `scalar.rs`).
//!
//! [`Motor::transform_points`](crate::cga::Motor::transform_points) reduces the sandwich to
//! four columns and an offset, each four numbers (the Euclidean part and the weight of the
//! image). A point `q = (x₁, x₂, x₃, h)` then becomes `y = o + Σ_k c_k q_k`: four broadcasts
//! and four fused multiply-adds on one 4-lane register, the chain starting from the offset (SSE
//! for f32, AVX for f64). `down` divides the Euclidean lanes by the weight in lane 3: one
//! broadcast of that lane and one 4-lane division, which rounds each lane as the scalar
//! division `yᵢ / w` does, where three scalar divisions would wait on each other in the
//! divider.

use core::arch::x86_64::*;

/// `(o + Σ_k c[k] q[k])` with its first three lanes divided by its last, for f32.
#[inline]
pub(crate) fn map_down_f32(c: &[[f32; 4]; 4], o: [f32; 4], q: [f32; 4]) -> [f32; 3] {
    // SAFETY: this module is compiled only when the build enables avx2 and fma (see the `cfg`
    // on its declaration), so the CPU running this code has them.
    unsafe { map_down_f32_fma(c, o, q) }
}

/// `(o + Σ_k c[k] q[k])` with its first three lanes divided by its last, for f64.
#[inline]
pub(crate) fn map_down_f64(c: &[[f64; 4]; 4], o: [f64; 4], q: [f64; 4]) -> [f64; 3] {
    // SAFETY: this module is compiled only when the build enables avx2 and fma, so the CPU
    // running this code has them.
    unsafe { map_down_f64_fma(c, o, q) }
}

#[inline]
#[target_feature(enable = "avx2,fma")]
fn map_down_f32_fma(c: &[[f32; 4]; 4], o: [f32; 4], q: [f32; 4]) -> [f32; 3] {
    // SAFETY: each column and the offset are 4 f32, read by one unaligned load each.
    let load = |x: &[f32; 4]| unsafe { _mm_loadu_ps(x.as_ptr()) };
    let mut v = _mm_fmadd_ps(load(&c[0]), _mm_set1_ps(q[0]), load(&o));
    v = _mm_fmadd_ps(load(&c[1]), _mm_set1_ps(q[1]), v);
    v = _mm_fmadd_ps(load(&c[2]), _mm_set1_ps(q[2]), v);
    v = _mm_fmadd_ps(load(&c[3]), _mm_set1_ps(q[3]), v);
    let v = _mm_div_ps(v, _mm_permute_ps::<0xFF>(v));
    let mut out = [0.0; 4];
    // SAFETY: `out` has 4 f32, one unaligned store writes them.
    unsafe { _mm_storeu_ps(out.as_mut_ptr(), v) };
    [out[0], out[1], out[2]]
}

#[inline]
#[target_feature(enable = "avx2,fma")]
fn map_down_f64_fma(c: &[[f64; 4]; 4], o: [f64; 4], q: [f64; 4]) -> [f64; 3] {
    // SAFETY: each column and the offset are 4 f64, read by one unaligned load each.
    let load = |x: &[f64; 4]| unsafe { _mm256_loadu_pd(x.as_ptr()) };
    let mut v = _mm256_fmadd_pd(load(&c[0]), _mm256_set1_pd(q[0]), load(&o));
    v = _mm256_fmadd_pd(load(&c[1]), _mm256_set1_pd(q[1]), v);
    v = _mm256_fmadd_pd(load(&c[2]), _mm256_set1_pd(q[2]), v);
    v = _mm256_fmadd_pd(load(&c[3]), _mm256_set1_pd(q[3]), v);
    let v = _mm256_div_pd(v, _mm256_permute4x64_pd::<0xFF>(v));
    let mut out = [0.0; 4];
    // SAFETY: `out` has 4 f64, one unaligned store writes them.
    unsafe { _mm256_storeu_pd(out.as_mut_ptr(), v) };
    [out[0], out[1], out[2]]
}
