//! The instruction sets: [`Isa`], the node test's, chosen once per process at run time; and
//! [`F4`], four `f32` lanes for the build, one SSE register on x86-64 (where SSE2 is always
//! present), a plain array elsewhere (lanes 0 to 2 are x, y, z; lane 3 is carried along and
//! ignored).

#[cfg(target_arch = "x86_64")]
use core::arch::x86_64::*;
#[cfg(target_arch = "x86_64")]
use std::sync::atomic::{AtomicU8, Ordering};

/// The environment variable that overrides the run-time choice of [`Isa`], so that a bench can
/// pair the paths on one machine: `avx2` (or `baseline`) keeps the build's baseline node test
/// for both precisions; `avx512` takes AVX-512 for both where the CPU has it; `auto` (or unset)
/// takes it for `f32` rays only ([`Isa::current`], [`Isa::current_f64`]). Read once, at the
/// first traversal.
pub const ISA_ENV: &str = "WEDGE_ISA";

/// The instruction set of the BVH's node test (and of the traversal loop around it).
///
/// Both give the same answers bit for bit: the same operations on the same values in the same
/// order, only in wider registers. The choice is made once per process ([`Isa::current`]),
/// from the CPU (`is_x86_feature_detected!`), not from the build's target features, so one
/// binary built for the x86-64-v3 baseline uses AVX-512 where the machine has it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Isa {
    /// The build's own: AVX2 on the workspace's x86-64-v3 baseline, lane by lane without it.
    Baseline,
    /// AVX-512 (F and VL): the traversal loop compiled with it, the node test comparing into
    /// a mask register.
    Avx512,
}

/// [`Isa::current`]'s cache: 0 until chosen, then 1 + the `f32` choice + 2 x the `f64` one.
#[cfg(target_arch = "x86_64")]
static CHOSEN: AtomicU8 = AtomicU8::new(0);

impl Isa {
    /// The name used in records and by [`ISA_ENV`]: `avx2`, `scalar` (a build without AVX2)
    /// or `avx512`.
    #[must_use]
    pub const fn name(self) -> &'static str {
        match self {
            Isa::Baseline if cfg!(all(target_arch = "x86_64", target_feature = "avx2")) => "avx2",
            Isa::Baseline => "scalar",
            Isa::Avx512 => "avx512",
        }
    }

    /// The best node test this CPU runs, ignoring [`ISA_ENV`].
    #[must_use]
    pub fn detected() -> Isa {
        #[cfg(target_arch = "x86_64")]
        if std::arch::is_x86_feature_detected!("avx512f")
            && std::arch::is_x86_feature_detected!("avx512vl")
        {
            return Isa::Avx512;
        }
        Isa::Baseline
    }

    /// The node test of `f32` rays: [`Isa::detected`], unless [`ISA_ENV`] asks for the
    /// baseline. Chosen at the first call and the same for the rest of the process.
    #[must_use]
    #[inline]
    pub fn current() -> Isa {
        Self::chosen().0
    }

    /// The node test of `f64` rays: the baseline, unless [`ISA_ENV`] is `avx512` and the CPU
    /// has it. With AVX-512 the `f64` traversal measured slower on the machine of
    /// `results/README.md` ("AVX-512"), so it is not chosen by default.
    #[must_use]
    #[inline]
    pub fn current_f64() -> Isa {
        Self::chosen().1
    }

    /// The node tests of both precisions, as `(f32, f64)`.
    #[inline]
    fn chosen() -> (Isa, Isa) {
        #[cfg(target_arch = "x86_64")]
        {
            let code = match CHOSEN.load(Ordering::Relaxed) {
                0 => Self::choose(),
                code => code,
            } - 1;
            let isa = |bit: u8| if code & bit != 0 { Isa::Avx512 } else { Isa::Baseline };
            (isa(1), isa(2))
        }
        #[cfg(not(target_arch = "x86_64"))]
        {
            (Isa::Baseline, Isa::Baseline)
        }
    }

    #[cfg(target_arch = "x86_64")]
    #[cold]
    fn choose() -> u8 {
        let wanted = std::env::var(ISA_ENV).unwrap_or_default();
        let has = Self::detected() == Isa::Avx512;
        let (f32_wide, f64_wide) = match wanted.trim().to_ascii_lowercase().as_str() {
            "avx2" | "baseline" | "scalar" => (false, false),
            "avx512" => (has, has),
            _ => (has, false),
        };
        let code = 1 + u8::from(f32_wide) + 2 * u8::from(f64_wide);
        // Threads racing here all store the same value.
        CHOSEN.store(code, Ordering::Relaxed);
        code
    }
}

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
    fn the_isa_is_chosen_once_and_named() {
        let (isa, isa64) = (Isa::current(), Isa::current_f64());
        assert_eq!((Isa::current(), Isa::current_f64()), (isa, isa64));
        // The override can never raise the choice above the CPU's.
        for i in [isa, isa64] {
            assert!(i == Isa::Baseline || Isa::detected() == Isa::Avx512);
            assert!(["avx2", "scalar", "avx512"].contains(&i.name()));
        }
        println!("node test in use: f32 {}, f64 {}", isa.name(), isa64.name());
    }

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
