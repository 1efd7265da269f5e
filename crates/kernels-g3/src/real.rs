//! The precisions the GA back end supports, and the one thing its kernels need beyond
//! [`ga::Scalar`]: the four-lane parts of the `ga` and `ga-plucker` kernels for each precision
//! ([`crate::lanes`]).

/// A precision the GA back end supports: `f32` or `f64`.
///
/// A [`ga::Scalar`], hence the workspace's one float trait [`ga::Real`] (which is also the
/// seam's [`intersect::Real`]), plus this crate's per-precision lane kernels. Sealed:
/// implemented for `f32` and `f64` only.
pub trait GaReal: private::Float {}

impl GaReal for f32 {}
impl GaReal for f64 {}

pub(crate) mod private {
    /// What the kernels compute in: [`ga::Scalar`] (so every float operation, `mul_add` and
    /// `mul_add_if_fma` included, is [`ga::Real`]'s) plus the vector parts of two kernels.
    ///
    /// Those are a different concern from the scalar: hand-written AVX2 code in `f32` and
    /// `f64` ([`crate::lanes`]) chosen by precision at compile time, which no generic
    /// scalar operation can express, so they live here, in a private trait, and not in
    /// `real`. The kernels are generic over this trait alone.
    pub trait Float: ga::Scalar {
        /// The `ga` kernel's undivided values `[num, den, U, V]` for a triangle stored by axis
        /// (`axes[k] = (n_k, m_b_k, m_c_k, a_k)`) and a ray: with `s = a - o`, `num = s · n`,
        /// `den = u · n`, `U = num (u · m_b) - den (s · m_b)`, `V` likewise with `m_c`. See
        /// [`crate::frame`] and [`crate::lanes`].
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
