//! The precisions the GA back end supports, the bit-level operations its kernels need beyond
//! [`ga::Scalar`], and the inner products of the `ga` kernel, on four lanes where the machine
//! has them.

/// A precision the GA back end supports: `f32` or `f64`.
///
/// The algebra ([`ga::Scalar`]) and the seam ([`intersect::Real`]) each define their own
/// scalar trait; this one joins them. Sealed: implemented for `f32` and `f64` only.
pub trait GaReal: private::Float + intersect::Real {}

impl GaReal for f32 {}
impl GaReal for f64 {}

pub(crate) mod private {
    /// What the kernels use: [`ga::Scalar`] plus sign manipulation. The kernels are generic
    /// over this trait alone, so `T::ZERO` and friends name [`ga::Scalar`]'s items without
    /// ambiguity (`intersect::Real` has items of the same names).
    pub trait Float: ga::Scalar {
        /// `1` or `-1` times `|self|`, with the sign of `sign` (its sign bit, so `-0.0`
        /// counts as negative).
        fn copy_sign(self, sign: Self) -> Self;

        /// `self`, negated when `sign_of` has its sign bit set: `x * sign(s)` without a
        /// multiply or a branch (one AND and one XOR of the bit patterns).
        fn xor_sign(self, sign_of: Self) -> Self;

        /// `x` rounded to this precision, keeping its sign when it is non-zero: a value that
        /// would round to zero becomes the smallest subnormal of the same sign. The
        /// watertight kernel's exact fallback needs the sign, not the size.
        fn from_f64_keep_sign(x: f64) -> Self;

        /// The `ga` kernel's undivided values `[num, den, U, V]` for a triangle stored by axis
        /// (`axes[k] = (n_k, m_b_k, m_c_k, a_k)`) and a ray: with `s = a - o`, `num = s · n`,
        /// `den = u · n`, `U = num (u · m_b) - den (s · m_b)`, `V` likewise with `m_c`. See
        /// [`crate::precomputed`]. [`frame_products`] gives the rounding of every
        /// implementation.
        fn frame_products(axes: &[[Self; 4]; 3], origin: &[Self; 3], dir: &[Self; 3]) -> [Self; 4];
    }

    /// [`Float::frame_products`] lane by lane. Each inner product is `x_1 row_1[j]`, plus
    /// `x_2 row_2[j]`, plus `x_3 row_3[j]`, in that order, with fused multiply-adds where the
    /// build has them; `U` is `num (u · m_b) - fl(den (s · m_b))` with one rounding. The
    /// four-lane form rounds every operation the same way.
    #[inline(always)]
    pub fn frame_products<T: ga::Scalar>(
        axes: &[[T; 4]; 3],
        origin: &[T; 3],
        dir: &[T; 3],
    ) -> [T; 4] {
        let [x, y, z] = axes;
        let s = [x[3] - origin[0], y[3] - origin[1], z[3] - origin[2]];
        let inner = |v: &[T; 3], j: usize| v[2].mul_add(z[j], v[1].mul_add(y[j], v[0] * x[j]));
        let (num, den) = (inner(&s, 0), inner(dir, 0));
        let edge = |j| num.mul_add(inner(dir, j), -(den * inner(&s, j)));
        [num, den, edge(1), edge(2)]
    }

    /// [`Float::frame_products`] for `f32` on four lanes: the three rows are three SSE
    /// registers, so each set of three inner products is one multiply and two fused
    /// multiply-adds.
    #[cfg(all(target_arch = "x86_64", target_feature = "fma"))]
    #[inline(always)]
    fn frame_products_f32(axes: &[[f32; 4]; 3], origin: &[f32; 3], dir: &[f32; 3]) -> [f32; 4] {
        use core::arch::x86_64::*;
        // SAFETY: this function is compiled only when the build enables FMA (which implies
        // AVX, for the lane permutations); each row is four f32 (unaligned loads).
        unsafe {
            let [x, y, z] = axes.each_ref().map(|row| _mm_loadu_ps(row.as_ptr()));
            let inner =
                |v: [__m128; 3]| _mm_fmadd_ps(v[2], z, _mm_fmadd_ps(v[1], y, _mm_mul_ps(v[0], x)));
            // s_k = a_k - o_k in every lane: the fourth lane of each row, broadcast.
            let s = [x, y, z].map(|row| _mm_permute_ps::<0xff>(row));
            let s = core::array::from_fn(|k| _mm_sub_ps(s[k], _mm_set1_ps(origin[k])));
            let along_s = inner(s);
            let along_u = inner(dir.map(|d| _mm_set1_ps(d)));
            let num = _mm_permute_ps::<0>(along_s);
            let den = _mm_permute_ps::<0>(along_u);
            // Lanes 1 and 2: U and V.
            let edges = _mm_fmsub_ps(num, along_u, _mm_mul_ps(den, along_s));
            [
                _mm_cvtss_f32(num),
                _mm_cvtss_f32(den),
                _mm_cvtss_f32(_mm_permute_ps::<1>(edges)),
                _mm_cvtss_f32(_mm_permute_ps::<2>(edges)),
            ]
        }
    }

    #[cfg(not(all(target_arch = "x86_64", target_feature = "fma")))]
    #[inline(always)]
    fn frame_products_f32(axes: &[[f32; 4]; 3], origin: &[f32; 3], dir: &[f32; 3]) -> [f32; 4] {
        frame_products(axes, origin, dir)
    }

    macro_rules! impl_float {
        ($t:ident, $bits:ident, $frame:path) => {
            impl Float for $t {
                #[inline(always)]
                fn copy_sign(self, sign: Self) -> Self {
                    self.copysign(sign)
                }

                #[inline(always)]
                fn xor_sign(self, sign_of: Self) -> Self {
                    const SIGN: $bits = 1 << ($bits::BITS - 1);
                    $t::from_bits(self.to_bits() ^ (sign_of.to_bits() & SIGN))
                }

                #[inline]
                fn from_f64_keep_sign(x: f64) -> Self {
                    let r = x as $t;
                    if r == 0.0 && x != 0.0 { $t::from_bits(1).copysign(x as $t) } else { r }
                }

                #[inline(always)]
                fn frame_products(axes: &[[$t; 4]; 3], origin: &[$t; 3], dir: &[$t; 3]) -> [$t; 4] {
                    $frame(axes, origin, dir)
                }
            }
        };
    }

    impl_float!(f32, u32, frame_products_f32);
    impl_float!(f64, u64, frame_products::<f64>);
}

#[cfg(test)]
mod tests {
    use super::private::{Float, frame_products};
    use rand::{Rng, SeedableRng};
    use rand_pcg::Pcg64;

    /// The four-lane `f32` form (where the build has FMA) gives the same bits as the
    /// lane-by-lane reference, including NaN and infinities where they arise.
    #[test]
    fn four_lane_frame_products_match_lane_by_lane() {
        let mut rng = Pcg64::seed_from_u64(0x6a_4002);
        let value = |rng: &mut Pcg64| match rng.random_range(0..40) {
            0 => f32::NAN,
            1 => f32::INFINITY,
            2 => 0.0,
            _ => rng.random_range(-100.0f32..100.0) * 10f32.powi(rng.random_range(-3..3)),
        };
        for _ in 0..100_000 {
            let axes: [[f32; 4]; 3] =
                core::array::from_fn(|_| core::array::from_fn(|_| value(&mut rng)));
            let origin = core::array::from_fn(|_| value(&mut rng));
            let dir = core::array::from_fn(|_| value(&mut rng));
            let got = f32::frame_products(&axes, &origin, &dir);
            let want = frame_products(&axes, &origin, &dir);
            // NaN payloads may differ; NaN-ness may not.
            for (g, w) in got.into_iter().zip(want) {
                assert!(
                    g.to_bits() == w.to_bits() || (g.is_nan() && w.is_nan()),
                    "{axes:?} {origin:?} {dir:?}"
                );
            }
        }
    }

    #[test]
    fn xor_sign_flips_only_for_negative_signs() {
        assert_eq!(3.0f32.xor_sign(-2.0), -3.0);
        assert_eq!(3.0f32.xor_sign(2.0), 3.0);
        assert_eq!((-3.0f64).xor_sign(-0.5), 3.0);
        assert_eq!(1.0f64.xor_sign(-0.0), -1.0);
        assert!(f64::NAN.xor_sign(-1.0).is_nan());
    }

    #[test]
    fn keep_sign_never_rounds_a_nonzero_to_zero() {
        assert_eq!(f32::from_f64_keep_sign(1e-300), f32::from_bits(1));
        assert_eq!(f32::from_f64_keep_sign(-1e-300), -f32::from_bits(1));
        assert_eq!(f32::from_f64_keep_sign(0.0), 0.0);
        assert_eq!(f32::from_f64_keep_sign(0.5), 0.5);
        assert_eq!(f64::from_f64_keep_sign(-1e-300), -1e-300);
    }
}
