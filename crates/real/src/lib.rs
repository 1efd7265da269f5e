//! A float the project computes in: one trait, [`Real`], implemented for `f32` and `f64` only.
//!
//! Every generic numeric code path of the workspace (the algebra in `ga`, the seam in
//! `intersect`, the kernels behind it) is generic over this trait, so that one implementation
//! serves both precisions. It holds what that code needs (constants, a few elementary
//! functions, conversions and sign operations); it is not a general numeric tower.
//!
//! ```
//! use real::Real;
//!
//! /// `|(a, b)|`, written once for both precisions.
//! fn hypot<T: Real>(a: T, b: T) -> T {
//!     a.mul_add(a, b * b).sqrt()
//! }
//!
//! assert_eq!(hypot(3.0_f64, 4.0), 5.0);
//! assert_eq!(hypot(3.0_f32, 4.0), 5.0);
//! assert_eq!(<f32 as Real>::MANTISSA_DIGITS, 24);
//!
//! // `mul_add` rounds once, like `f64::mul_add`: 1 + 2^-27 squared is 1 + 2^-26 + 2^-54,
//! // and only a fused multiply-add keeps the last term.
//! let a = 1.0 + 2f64.powi(-27);
//! assert_eq!(Real::mul_add(a, a, -(1.0 + 2f64.powi(-26))), 2f64.powi(-54));
//! ```
//!
//! # What `mul_add` means
//!
//! [`Real::mul_add`] is always fused: `self * a + b` with one rounding, exactly
//! [`f32::mul_add`] and [`f64::mul_add`]. The name has std's meaning because std's inherent
//! method wins whenever the type is concrete (`x.mul_add(y, z)` on an `f64` never reaches this
//! trait), so any other meaning would give generic and concrete code different bits for the
//! same expression. The price: on a CPU without FMA a fused multiply-add is a slow library
//! call.
//!
//! Code that wants a multiply-add only when it is cheap calls [`Real::mul_add_if_fma`]: fused
//! when the build targets a CPU with FMA (this workspace does on x86-64, `-C
//! target-cpu=x86-64-v3`), a separate multiply and add otherwise. The choice is made at compile
//! time, so the bits depend on the build's target features, never on the machine a binary
//! runs on.
//!
//! # Why not `#![no_std]`
//!
//! `sqrt`, `sin`, `mul_add` and the other elementary functions of `f32` and `f64` are defined
//! in `std` (`core` has no maths library on stable Rust), and the trait forwards to them.

#![deny(missing_docs)]

use core::fmt::{Debug, Display};
use core::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Sub, SubAssign};

/// A private supertrait, so that [`Real`] cannot be implemented outside this crate: it stays
/// `f32` and `f64`, and code generic over it may rely on IEEE 754 binary32 and binary64.
mod sealed {
    pub trait Sealed {}
    impl Sealed for f32 {}
    impl Sealed for f64 {}
}

/// A floating-point scalar: implemented for `f32` and `f64`, and only for them (sealed).
pub trait Real:
    sealed::Sealed
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
    /// -1/2 (a constant, so that `const` items can use it, e.g. `ga::cga::Vector::E_O`).
    const NEG_HALF: Self;
    /// π.
    const PI: Self;
    /// Machine epsilon (distance from 1 to the next representable number).
    const EPSILON: Self;
    /// Positive infinity.
    const INFINITY: Self;
    /// Number of bits in the significand, the implicit one included (24 or 53).
    const MANTISSA_DIGITS: u32;

    /// Converts from `f64`, rounding to nearest.
    #[must_use]
    fn from_f64(x: f64) -> Self;
    /// `x` rounded to this precision, keeping its sign when it is non-zero: a value that would
    /// round to zero becomes the smallest subnormal of the same sign (for code that needs the
    /// sign of a value computed in `f64`, not its size).
    #[must_use]
    fn from_f64_keep_sign(x: f64) -> Self;
    /// Converts to `f64` (exact).
    #[must_use]
    fn to_f64(self) -> f64;
    /// Absolute value.
    #[must_use]
    fn abs(self) -> Self;
    /// `|self|` with the sign of `sign` (its sign bit, so `-0.0` counts as negative).
    #[must_use]
    fn copy_sign(self, sign: Self) -> Self;
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
    /// `e^self - 1`, accurate near 0.
    #[must_use]
    fn exp_m1(self) -> Self;
    /// `ln(1 + self)`, accurate near 0.
    #[must_use]
    fn ln_1p(self) -> Self;
    /// The smaller of two values (the other one if one is NaN).
    #[must_use]
    fn min(self, other: Self) -> Self;
    /// The larger of two values (the other one if one is NaN).
    #[must_use]
    fn max(self, other: Self) -> Self;
    /// `self * a + b` with one rounding (fused), on every target: [`f32::mul_add`] and
    /// [`f64::mul_add`]. See [the crate docs](crate#what-mul_add-means).
    #[must_use]
    fn mul_add(self, a: Self, b: Self) -> Self;
    /// `self * a + b`, fused (one rounding) when the build targets a CPU with FMA, else a
    /// separate multiply and add (two roundings). See [the crate docs](crate#what-mul_add-means).
    #[must_use]
    fn mul_add_if_fma(self, a: Self, b: Self) -> Self;
    /// Whether the value is neither infinite nor NaN.
    #[must_use]
    fn is_finite(self) -> bool;
    /// Whether the value is NaN.
    #[must_use]
    fn is_nan(self) -> bool;
}

macro_rules! impl_real {
    ($t:ident) => {
        impl Real for $t {
            const ZERO: Self = 0.0;
            const ONE: Self = 1.0;
            const TWO: Self = 2.0;
            const HALF: Self = 0.5;
            const NEG_HALF: Self = -0.5;
            const PI: Self = core::$t::consts::PI;
            const EPSILON: Self = $t::EPSILON;
            const INFINITY: Self = $t::INFINITY;
            const MANTISSA_DIGITS: u32 = $t::MANTISSA_DIGITS;

            #[inline(always)]
            fn from_f64(x: f64) -> Self {
                x as $t
            }
            #[inline]
            fn from_f64_keep_sign(x: f64) -> Self {
                let r = x as $t;
                if r == 0.0 && x != 0.0 { $t::from_bits(1).copysign(x as $t) } else { r }
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
            fn copy_sign(self, sign: Self) -> Self {
                $t::copysign(self, sign)
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
            fn exp_m1(self) -> Self {
                $t::exp_m1(self)
            }
            #[inline(always)]
            fn ln_1p(self) -> Self {
                $t::ln_1p(self)
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
                $t::mul_add(self, a, b)
            }
            #[inline(always)]
            fn mul_add_if_fma(self, a: Self, b: Self) -> Self {
                if cfg!(target_feature = "fma") { $t::mul_add(self, a, b) } else { self * a + b }
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

impl_real!(f32);
impl_real!(f64);

#[cfg(test)]
mod tests {
    use super::Real;

    fn generic_hypot<T: Real>(a: T, b: T) -> T {
        a.mul_add(a, b * b).sqrt()
    }

    fn generic_hypot_if_fma<T: Real>(a: T, b: T) -> T {
        a.mul_add_if_fma(a, b * b).sqrt()
    }

    #[test]
    fn both_precisions_agree_with_std() {
        assert_eq!(generic_hypot(3.0_f64, 4.0), 5.0);
        assert_eq!(generic_hypot(3.0_f32, 4.0), 5.0);
        assert_eq!(generic_hypot_if_fma(3.0_f64, 4.0), 5.0);
        assert_eq!(generic_hypot_if_fma(3.0_f32, 4.0), 5.0);
        assert_eq!(<f32 as Real>::from_f64(0.1), 0.1_f32);
        assert_eq!(Real::atan2(1.0_f64, 0.0), core::f64::consts::FRAC_PI_2);
        assert_eq!(<f64 as Real>::MANTISSA_DIGITS, 53);
        assert_eq!(Real::copy_sign(2.0_f32, -0.0), -2.0);
    }

    /// `(1 + d)^2 - (1 + 2d) = d^2` exactly, with `d` half the precision: the plain product
    /// rounds `d^2` away (it is below half an ulp of 1), a fused multiply-add keeps it.
    fn fused_and_plain<T: Real>(d: T) -> (T, T, T) {
        let a = T::ONE + d;
        let c = -(T::ONE + T::TWO * d);
        (Real::mul_add(a, a, c), a.mul_add_if_fma(a, c), d * d)
    }

    #[test]
    fn mul_add_is_always_fused_and_mul_add_if_fma_follows_the_build() {
        let fma = cfg!(target_feature = "fma");
        let (fused, if_fma, d2) = fused_and_plain(2f64.powi(-27));
        assert_eq!(fused, d2);
        assert_eq!(if_fma, if fma { d2 } else { 0.0 });
        let (fused, if_fma, d2) = fused_and_plain(2f32.powi(-12));
        assert_eq!(fused, d2);
        assert_eq!(if_fma, if fma { d2 } else { 0.0 });
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
