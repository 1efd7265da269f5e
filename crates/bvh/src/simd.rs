//! Four `f32` lanes for the build: one SSE register on x86-64 (where SSE2 is always present),
//! a plain array elsewhere. Lanes 0 to 2 are x, y, z; lane 3 is carried along and ignored.

#[cfg(target_arch = "x86_64")]
use core::arch::x86_64::*;

/// Four `f32` lanes.
#[derive(Clone, Copy, Debug)]
#[repr(transparent)]
pub struct F4(#[cfg(target_arch = "x86_64")] __m128, #[cfg(not(target_arch = "x86_64"))] [f32; 4]);

impl F4 {
    /// Every lane `+inf`.
    pub const INFINITY: F4 = F4::from_array_const([f32::INFINITY; 4]);
    /// Every lane `-inf`.
    pub const NEG_INFINITY: F4 = F4::from_array_const([f32::NEG_INFINITY; 4]);

    /// Half the surface area of the box from `self` to `hi` (lanes 0 to 2), for a box that
    /// is not empty.
    #[inline(always)]
    pub fn half_area(self, hi: Self) -> f32 {
        let [x, y, z, _] = hi.sub(self).to_array();
        x * y + y * z + z * x
    }
}

#[cfg(target_arch = "x86_64")]
impl F4 {
    const fn from_array_const(a: [f32; 4]) -> Self {
        // SAFETY: `__m128` is 16 bytes of four f32 lanes, as is `[f32; 4]`.
        Self(unsafe { core::mem::transmute::<[f32; 4], __m128>(a) })
    }

    #[inline(always)]
    pub fn new(a: [f32; 4]) -> Self {
        // SAFETY: SSE is part of every x86-64 target, so the CPU has the instruction.
        Self(unsafe { _mm_setr_ps(a[0], a[1], a[2], a[3]) })
    }
    #[inline(always)]
    pub fn splat(x: f32) -> Self {
        // SAFETY: SSE is part of every x86-64 target; no memory is touched.
        Self(unsafe { _mm_set1_ps(x) })
    }
    #[inline(always)]
    pub fn to_array(self) -> [f32; 4] {
        let mut out = [0.0f32; 4];
        // SAFETY: `out` has room for four f32; the store is unaligned.
        unsafe { _mm_storeu_ps(out.as_mut_ptr(), self.0) };
        out
    }
    /// `min(self, other)` per lane; a NaN lane of `other` keeps `self` (MINPS returns its
    /// second operand when either is NaN).
    #[inline(always)]
    pub fn min(self, other: Self) -> Self {
        // SAFETY: SSE is part of every x86-64 target; no memory is touched.
        Self(unsafe { _mm_min_ps(other.0, self.0) })
    }
    /// `max(self, other)` per lane; a NaN lane of `other` keeps `self`.
    #[inline(always)]
    pub fn max(self, other: Self) -> Self {
        // SAFETY: SSE is part of every x86-64 target; no memory is touched.
        Self(unsafe { _mm_max_ps(other.0, self.0) })
    }
    #[inline(always)]
    pub fn add(self, other: Self) -> Self {
        // SAFETY: SSE is part of every x86-64 target; no memory is touched.
        Self(unsafe { _mm_add_ps(self.0, other.0) })
    }
    #[inline(always)]
    pub fn sub(self, other: Self) -> Self {
        // SAFETY: SSE is part of every x86-64 target; no memory is touched.
        Self(unsafe { _mm_sub_ps(self.0, other.0) })
    }
    #[inline(always)]
    pub fn mul(self, other: Self) -> Self {
        // SAFETY: SSE is part of every x86-64 target; no memory is touched.
        Self(unsafe { _mm_mul_ps(self.0, other.0) })
    }
    #[inline(always)]
    pub fn div(self, other: Self) -> Self {
        // SAFETY: SSE is part of every x86-64 target; no memory is touched.
        Self(unsafe { _mm_div_ps(self.0, other.0) })
    }
    /// Truncation towards zero, clamped to `0..=max` (NaN gives 0).
    #[inline(always)]
    pub fn bins(self, max: i32) -> [u32; 4] {
        // Clamped as floats first (MAXPS returns its second operand, 0, for a NaN lane), so
        // the truncation never sees a value out of range.
        let mut out = [0u32; 4];
        // SAFETY: SSE2 is part of every x86-64 target; `out` has room for the 16 bytes of the
        // unaligned store.
        unsafe {
            let x = _mm_max_ps(self.0, _mm_setzero_ps());
            let x = _mm_min_ps(x, _mm_set1_ps(max as f32));
            _mm_storeu_si128(out.as_mut_ptr().cast(), _mm_cvttps_epi32(x));
        }
        out
    }
}

#[cfg(not(target_arch = "x86_64"))]
impl F4 {
    const fn from_array_const(a: [f32; 4]) -> Self {
        Self(a)
    }

    #[inline(always)]
    pub fn new(a: [f32; 4]) -> Self {
        Self(a)
    }
    #[inline(always)]
    pub fn splat(x: f32) -> Self {
        Self([x; 4])
    }
    #[inline(always)]
    pub fn to_array(self) -> [f32; 4] {
        self.0
    }
    #[inline(always)]
    pub fn min(self, other: Self) -> Self {
        Self(core::array::from_fn(|i| if other.0[i] < self.0[i] { other.0[i] } else { self.0[i] }))
    }
    #[inline(always)]
    pub fn max(self, other: Self) -> Self {
        Self(core::array::from_fn(|i| if other.0[i] > self.0[i] { other.0[i] } else { self.0[i] }))
    }
    #[inline(always)]
    pub fn add(self, other: Self) -> Self {
        Self(core::array::from_fn(|i| self.0[i] + other.0[i]))
    }
    #[inline(always)]
    pub fn sub(self, other: Self) -> Self {
        Self(core::array::from_fn(|i| self.0[i] - other.0[i]))
    }
    #[inline(always)]
    pub fn mul(self, other: Self) -> Self {
        Self(core::array::from_fn(|i| self.0[i] * other.0[i]))
    }
    #[inline(always)]
    pub fn div(self, other: Self) -> Self {
        Self(core::array::from_fn(|i| self.0[i] / other.0[i]))
    }
    #[inline(always)]
    pub fn bins(self, max: i32) -> [u32; 4] {
        // `as i32` saturates and maps NaN to 0, like the clamp of the x86-64 version.
        self.0.map(|x| (x as i32).clamp(0, max) as u32)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lanes_and_nan_handling() {
        let a = F4::new([1.0, -2.0, 3.0, 0.0]);
        let b = F4::new([0.5, f32::NAN, 4.0, 0.0]);
        assert_eq!(a.min(b).to_array()[..3], [0.5, -2.0, 3.0]);
        assert_eq!(a.max(b).to_array()[..3], [1.0, -2.0, 4.0]);
        assert_eq!(a.add(b).to_array()[0], 1.5);
        assert_eq!(a.sub(F4::splat(1.0)).mul(F4::splat(2.0)).to_array()[..3], [0.0, -6.0, 4.0]);
        let bins = F4::new([-3.5, 2.9, 100.0, f32::NAN]).bins(15);
        assert_eq!(bins, [0, 2, 15, 0]);
    }
}
