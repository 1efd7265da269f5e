//! The precisions the GA back end supports, and what its kernels need beyond [`ga::Scalar`]:
//! sign operations, and the four-lane parts of the `ga` and `ga-plucker` kernels
//! for each precision ([`crate::lanes`]).

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

        /// `x` rounded to this precision, keeping its sign when it is non-zero: a value that
        /// would round to zero becomes the smallest subnormal of the same sign. The
        /// watertight kernel's exact fallback needs the sign, not the size.
        fn from_f64_keep_sign(x: f64) -> Self;

        /// The `ga` kernel's undivided values `[num, den, U, V]` for a triangle stored by axis
        /// (`axes[k] = (n_k, m_b_k, m_c_k, a_k)`) and a ray: with `s = a - o`, `num = s · n`,
        /// `den = u · n`, `U = num (u · m_b) - den (s · m_b)`, `V` likewise with `m_c`. See
        /// [`crate::precomputed`] and [`crate::lanes`].
        fn frame_products(axes: &[[Self; 4]; 3], origin: &[Self; 3], dir: &[Self; 3]) -> [Self; 4];

        /// The `ga-plucker` kernel's projections for a triangle stored by axis
        /// (`axes[k] = (a_k, b_k, c_k, n_k)`) and a ray's basis `ex`, `ey`: `[x, y, w]`, where
        /// lane `j < 3` of `x` and `y` holds vertex `j`'s coordinates `(v_j - o) · ex`,
        /// `(v_j - o) · ey`, and of `w` the edge value opposite it,
        /// `x_p y_q - y_p x_q` with `p = j + 1`, `q = j + 2` (mod 3). Lane 3 is unspecified.
        /// See [`crate::lanes`].
        fn edge_trivectors(
            axes: &[[Self; 4]; 3],
            origin: &[Self; 3],
            ex: &[Self; 3],
            ey: &[Self; 3],
        ) -> [[Self; 4]; 3];
    }

    macro_rules! impl_float {
        ($t:ident, $frame:path, $edges:path) => {
            impl Float for $t {
                #[inline(always)]
                fn copy_sign(self, sign: Self) -> Self {
                    self.copysign(sign)
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

                #[inline(always)]
                fn edge_trivectors(
                    axes: &[[$t; 4]; 3],
                    origin: &[$t; 3],
                    ex: &[$t; 3],
                    ey: &[$t; 3],
                ) -> [[$t; 4]; 3] {
                    $edges(axes, origin, ex, ey)
                }
            }
        };
    }

    use crate::lanes;
    impl_float!(f32, lanes::frame_products_f32, lanes::edge_trivectors_f32);
    impl_float!(f64, lanes::frame_products_f64, lanes::edge_trivectors_f64);
}

#[cfg(test)]
mod tests {
    use super::private::Float;

    #[test]
    fn keep_sign_never_rounds_a_nonzero_to_zero() {
        assert_eq!(f32::from_f64_keep_sign(1e-300), f32::from_bits(1));
        assert_eq!(f32::from_f64_keep_sign(-1e-300), -f32::from_bits(1));
        assert_eq!(f32::from_f64_keep_sign(0.0), 0.0);
        assert_eq!(f32::from_f64_keep_sign(0.5), 0.5);
        assert_eq!(f64::from_f64_keep_sign(-1e-300), -1e-300);
    }
}
