//! The scalar type of the algebra: one small trait, implemented for `f32` and `f64` only.

use core::fmt::{Debug, Display};
use core::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Sub, SubAssign};

/// Per-precision kernels, in a private module so that [`Scalar`] cannot be implemented outside
/// this crate (it stays `f32` and `f64`) and the hooks stay out of its public docs.
mod sealed {
    pub trait Kernels: Sized {
        /// The geometric product of two multivectors, coefficients in storage order.
        fn geometric_product(a: &[Self; 8], b: &[Self; 8]) -> [Self; 8];
        /// The product of two rotors `[s, e12, e23, e31]`.
        fn rotor_product(a: [Self; 4], b: [Self; 4]) -> [Self; 4];
        /// The reverse `[s, -e12, -e23, -e31]` of a rotor.
        fn rotor_reverse(a: [Self; 4]) -> [Self; 4];
    }
}

/// A floating-point scalar: implemented for `f32` and `f64`, and only for them.
///
/// Every type in [`crate::g3`] is generic over this trait so that one implementation serves both
/// precisions. It holds only what the algebra needs (constants, a few elementary functions and
/// conversions); it is not a general numeric tower.
pub trait Scalar:
    sealed::Kernels
    + Copy
    + Default
    + PartialEq
    + PartialOrd
    + Debug
    + Display
    + Send
    + Sync
    + 'static
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
    + AddAssign
    + SubAssign
    + MulAssign
    + DivAssign
{
    /// 0.
    const ZERO: Self;
    /// 1.
    const ONE: Self;
    /// 2.
    const TWO: Self;
    /// 1/2.
    const HALF: Self;
    /// -1/2 (a constant so that `const` items such as `cga::Vector::E_O` can use it).
    const NEG_HALF: Self;
    /// π.
    const PI: Self;
    /// Machine epsilon (distance from 1 to the next representable number).
    const EPSILON: Self;
    /// Positive infinity.
    const INFINITY: Self;

    /// Converts from `f64`, rounding to nearest.
    #[must_use]
    fn from_f64(x: f64) -> Self;
    /// Converts to `f64` (exact).
    #[must_use]
    fn to_f64(self) -> f64;
    /// Absolute value.
    #[must_use]
    fn abs(self) -> Self;
    /// Square root (NaN for negative input).
    #[must_use]
    fn sqrt(self) -> Self;
    /// `1 / self`.
    #[must_use]
    fn recip(self) -> Self;
    /// Sine (radians).
    #[must_use]
    fn sin(self) -> Self;
    /// Cosine (radians).
    #[must_use]
    fn cos(self) -> Self;
    /// Sine and cosine together (radians).
    #[must_use]
    fn sin_cos(self) -> (Self, Self);
    /// Four-quadrant arctangent of `self / x`, in `[-π, π]`.
    #[must_use]
    fn atan2(self, x: Self) -> Self;
    /// Arccosine, in `[0, π]` (NaN outside `[-1, 1]`).
    #[must_use]
    fn acos(self) -> Self;
    /// The smaller of two values (the other one if one is NaN).
    #[must_use]
    fn min(self, other: Self) -> Self;
    /// The larger of two values (the other one if one is NaN).
    #[must_use]
    fn max(self, other: Self) -> Self;
    /// `self * a + b`.
    ///
    /// Fused (one rounding) when the build targets a CPU with FMA, as this workspace does on
    /// x86-64 (`-C target-cpu=x86-64-v3`); otherwise a separate multiply and add. A fused
    /// multiply-add without hardware support is a slow library call, and the kernels use this
    /// in their inner loops, so the choice is made at compile time rather than paying that
    /// price.
    #[must_use]
    fn mul_add(self, a: Self, b: Self) -> Self;
    /// `e^self - 1`, accurate also when `self` is near zero (`sinh` of small arguments).
    #[must_use]
    fn exp_m1(self) -> Self;
    /// `ln(1 + self)`, accurate also when `self` is near zero (`atanh` of small arguments).
    #[must_use]
    fn ln_1p(self) -> Self;
    /// Whether the value is neither infinite nor NaN.
    #[must_use]
    fn is_finite(self) -> bool;
    /// Whether the value is NaN.
    #[must_use]
    fn is_nan(self) -> bool;
}

macro_rules! impl_scalar {
    ($t:ident) => {
        impl Scalar for $t {
            const ZERO: Self = 0.0;
            const ONE: Self = 1.0;
            const TWO: Self = 2.0;
            const HALF: Self = 0.5;
            const NEG_HALF: Self = -0.5;
            const PI: Self = core::$t::consts::PI;
            const EPSILON: Self = $t::EPSILON;
            const INFINITY: Self = $t::INFINITY;

            #[inline(always)]
            fn from_f64(x: f64) -> Self {
                x as $t
            }
            #[inline(always)]
            fn to_f64(self) -> f64 {
                self as f64
            }
            #[inline(always)]
            fn abs(self) -> Self {
                $t::abs(self)
            }
            #[inline(always)]
            fn sqrt(self) -> Self {
                $t::sqrt(self)
            }
            #[inline(always)]
            fn recip(self) -> Self {
                1.0 / self
            }
            #[inline(always)]
            fn sin(self) -> Self {
                $t::sin(self)
            }
            #[inline(always)]
            fn cos(self) -> Self {
                $t::cos(self)
            }
            #[inline(always)]
            fn sin_cos(self) -> (Self, Self) {
                $t::sin_cos(self)
            }
            #[inline(always)]
            fn atan2(self, x: Self) -> Self {
                $t::atan2(self, x)
            }
            #[inline(always)]
            fn acos(self) -> Self {
                $t::acos(self)
            }
            #[inline(always)]
            fn min(self, other: Self) -> Self {
                $t::min(self, other)
            }
            #[inline(always)]
            fn max(self, other: Self) -> Self {
                $t::max(self, other)
            }
            #[inline(always)]
            fn mul_add(self, a: Self, b: Self) -> Self {
                if cfg!(target_feature = "fma") { $t::mul_add(self, a, b) } else { self * a + b }
            }
            #[inline(always)]
            fn exp_m1(self) -> Self {
                $t::exp_m1(self)
            }
            #[inline(always)]
            fn ln_1p(self) -> Self {
                $t::ln_1p(self)
            }
            #[inline(always)]
            fn is_finite(self) -> bool {
                $t::is_finite(self)
            }
            #[inline(always)]
            fn is_nan(self) -> bool {
                $t::is_nan(self)
            }
        }
    };
}

impl_scalar!(f32);
impl_scalar!(f64);

/// Whether the SIMD kernels of `g3::simd` are compiled in.
macro_rules! with_simd {
    ($simd:expr, $portable:expr) => {{
        #[cfg(all(target_arch = "x86_64", target_feature = "avx2", target_feature = "fma"))]
        {
            $simd
        }
        #[cfg(not(all(target_arch = "x86_64", target_feature = "avx2", target_feature = "fma")))]
        {
            $portable
        }
    }};
}

impl sealed::Kernels for f32 {
    #[inline]
    fn geometric_product(a: &[f32; 8], b: &[f32; 8]) -> [f32; 8] {
        with_simd!(crate::g3::simd::geometric_f32(a, b), portable_geometric(a, b))
    }
    #[inline]
    fn rotor_product(a: [f32; 4], b: [f32; 4]) -> [f32; 4] {
        with_simd!(crate::g3::simd::rotor_product_f32(a, b), portable_rotor_product(a, b))
    }
    #[inline]
    fn rotor_reverse(a: [f32; 4]) -> [f32; 4] {
        with_simd!(crate::g3::simd::rotor_reverse_f32(a), [a[0], -a[1], -a[2], -a[3]])
    }
}

impl sealed::Kernels for f64 {
    #[inline]
    fn geometric_product(a: &[f64; 8], b: &[f64; 8]) -> [f64; 8] {
        with_simd!(crate::g3::simd::geometric_f64(a, b), portable_geometric(a, b))
    }
    #[inline]
    fn rotor_product(a: [f64; 4], b: [f64; 4]) -> [f64; 4] {
        // The portable form already vectorises well for f64 (glam's DQuat is scalar code).
        portable_rotor_product(a, b)
    }
    #[inline]
    fn rotor_reverse(a: [f64; 4]) -> [f64; 4] {
        [a[0], -a[1], -a[2], -a[3]]
    }
}

#[inline]
fn portable_rotor_product<T: Scalar>(a: [T; 4], b: [T; 4]) -> [T; 4] {
    use crate::g3::Rotor;
    crate::g3::geometric::rotor_product_portable(Rotor::from_array(a), Rotor::from_array(b))
        .to_array()
}

#[allow(dead_code)] // unused when every precision has a SIMD kernel
#[inline]
fn portable_geometric<T: Scalar>(a: &[T; 8], b: &[T; 8]) -> [T; 8] {
    use crate::g3::Multivector;
    crate::g3::geometric::geometric_portable(Multivector { c: *a }, Multivector { c: *b }).c
}

#[cfg(test)]
mod tests {
    use super::Scalar;

    fn generic_hypot<T: Scalar>(a: T, b: T) -> T {
        a.mul_add(a, b * b).sqrt()
    }

    #[test]
    fn both_precisions_agree_with_std() {
        assert_eq!(generic_hypot(3.0_f64, 4.0), 5.0);
        assert_eq!(generic_hypot(3.0_f32, 4.0), 5.0);
        assert_eq!(<f32 as Scalar>::from_f64(0.1), 0.1_f32);
        assert_eq!(Scalar::atan2(1.0_f64, 0.0), core::f64::consts::FRAC_PI_2);
    }
}
