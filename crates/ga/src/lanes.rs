//! Multivectors of four lanes: the same types and products on [`Lanes4`] coefficients, one
//! independent multivector per lane (structure of arrays).
//!
//! The products, the sums and the negation of every type are written for any
//! [`Coefficient`]: a type with `+`, `-`, `*`, negation and a zero. The floats are
//! coefficients, and so is [`Lanes4`], four of them side by side, whose operations act lane
//! by lane. So `Vector<Lanes4<f32>>` is four G3 vectors, and `a ^ b` on two of them computes
//! the four outer products at once, each lane with exactly the operations, in exactly the
//! order, of `Vector<f32>`'s: the same bits (IEEE 754 rounds each operation on its own, and
//! the generated products never fuse a multiply and an add).
//!
//! This is how a ray-triangle kernel written in the algebra tests four triangles at a time
//! with the code that tests one, and why its hits are the same.
//!
//! ```
//! use ga::Lanes4;
//! use ga::g3::Vector;
//!
//! let lanes = |v: [Vector<f32>; 4]| Vector {
//!     e1: Lanes4(v.map(|v| v.e1)),
//!     e2: Lanes4(v.map(|v| v.e2)),
//!     e3: Lanes4(v.map(|v| v.e3)),
//! };
//! let a = [1.0, 2.0, 3.0, 4.0].map(|x| Vector::new(x, 1.0, 0.5));
//! let b = [0.1, -2.0, 7.0, 1e-3].map(|x| Vector::new(0.3, x, 2.0));
//! let (wide_inner, wide_outer) = (lanes(a) | lanes(b), lanes(a) ^ lanes(b));
//! for l in 0..4 {
//!     assert_eq!(wide_inner.0[l], a[l] | b[l]);
//!     assert_eq!(wide_outer.e12.0[l], (a[l] ^ b[l]).e12);
//! }
//! ```

use core::ops::{Add, Div, Mul, Neg, Sub};

use crate::Real;

/// What the products and the linear operations of the algebras need of a coefficient: the
/// floats ([`Real`], every one of which is a coefficient) and [`Lanes4`].
pub trait Coefficient:
    Copy + Add<Output = Self> + Sub<Output = Self> + Mul<Output = Self> + Neg<Output = Self>
{
    /// Zero.
    const ZERO: Self;
}

impl<T: Real> Coefficient for T {
    const ZERO: Self = <T as Real>::ZERO;
}

/// Four floats side by side, operated on lane by lane: the coefficient of four multivectors
/// at once (see the [module documentation](self)).
///
/// Aligned to 16 bytes: one SSE register in `f32`; in `f64`, 32 bytes that AVX loads
/// unaligned at no cost.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[repr(C, align(16))]
pub struct Lanes4<T>(pub [T; 4]);

/// A lane mask: bit `l` for lane `l`.
pub type Mask = u32;

impl<T: Real> Lanes4<T> {
    /// `x` in every lane.
    #[must_use]
    #[inline(always)]
    pub fn splat(x: T) -> Self {
        Self([x; 4])
    }

    /// `f` lane by lane.
    #[inline(always)]
    fn map(self, f: impl Fn(T) -> T) -> Self {
        // Lane by lane rather than `[T; 4]::map`, which the compiler left out of line.
        Self([f(self.0[0]), f(self.0[1]), f(self.0[2]), f(self.0[3])])
    }

    /// `f` on the lanes of `self` and `b`, lane by lane.
    #[inline(always)]
    fn zip(self, b: Self, f: impl Fn(T, T) -> T) -> Self {
        Self([
            f(self.0[0], b.0[0]),
            f(self.0[1], b.0[1]),
            f(self.0[2], b.0[2]),
            f(self.0[3], b.0[3]),
        ])
    }

    /// The lanes where `f` holds.
    #[inline(always)]
    fn mask(self, b: Self, f: impl Fn(T, T) -> bool) -> Mask {
        (0..4).fold(0, |m, l| m | Mask::from(f(self.0[l], b.0[l])) << l)
    }

    /// The lanes where `self < b`.
    #[must_use]
    #[inline(always)]
    pub fn lt(self, b: Self) -> Mask {
        self.mask(b, |x, y| x < y)
    }

    /// The lanes where `self <= b`.
    #[must_use]
    #[inline(always)]
    pub fn le(self, b: Self) -> Mask {
        self.mask(b, |x, y| x <= y)
    }

    /// The lanes where `self == b`.
    #[must_use]
    #[inline(always)]
    pub fn eq(self, b: Self) -> Mask {
        self.mask(b, |x, y| x == y)
    }

    /// The lanes that are finite.
    #[must_use]
    #[inline(always)]
    pub fn finite(self) -> Mask {
        // `|x| < ∞`, false for NaN: one vector comparison, where `is_finite` lane by lane
        // was compiled as four scalar ones.
        self.abs().lt(Self::splat(T::INFINITY))
    }

    /// [`Real::abs`] lane by lane.
    #[must_use]
    #[inline(always)]
    pub fn abs(self) -> Self {
        self.map(Real::abs)
    }

    /// [`Real::copy_sign`] lane by lane: the magnitudes of `self`, the signs of `sign`.
    #[must_use]
    #[inline(always)]
    pub fn copy_sign(self, sign: Self) -> Self {
        self.zip(sign, Real::copy_sign)
    }
}

impl<T: Real> Coefficient for Lanes4<T> {
    const ZERO: Self = Self([<T as Real>::ZERO; 4]);
}

impl<T: Real> Add for Lanes4<T> {
    type Output = Self;
    #[inline(always)]
    fn add(self, b: Self) -> Self {
        self.zip(b, |x, y| x + y)
    }
}

impl<T: Real> Sub for Lanes4<T> {
    type Output = Self;
    #[inline(always)]
    fn sub(self, b: Self) -> Self {
        self.zip(b, |x, y| x - y)
    }
}

impl<T: Real> Mul for Lanes4<T> {
    type Output = Self;
    #[inline(always)]
    fn mul(self, b: Self) -> Self {
        self.zip(b, |x, y| x * y)
    }
}

impl<T: Real> Div for Lanes4<T> {
    type Output = Self;
    #[inline(always)]
    fn div(self, b: Self) -> Self {
        self.zip(b, |x, y| x / y)
    }
}

impl<T: Real> Neg for Lanes4<T> {
    type Output = Self;
    #[inline(always)]
    fn neg(self) -> Self {
        self.map(|x| -x)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{cga, g3, pga};

    /// Four random-ish lanes from a seed (no dependency needed for this).
    fn lanes(seed: u32) -> Lanes4<f64> {
        Lanes4(core::array::from_fn(|l| {
            let x = seed.wrapping_mul(2_654_435_761).wrapping_add(l as u32 * 40_503) as f64;
            (x / f64::from(u32::MAX) - 0.5) * 8.0
        }))
    }

    fn lane(x: Lanes4<f64>, l: usize) -> f64 {
        x.0[l]
    }

    /// Products of four-lane multivectors are the products of each lane's, bit for bit, in
    /// the three algebras.
    #[test]
    fn products_act_lane_by_lane() {
        let v = |s| g3::Vector { e1: lanes(s), e2: lanes(s + 1), e3: lanes(s + 2) };
        let (a, b) = (v(1), v(7));
        let one = |x: g3::Vector<Lanes4<f64>>, l| {
            g3::Vector::new(lane(x.e1, l), lane(x.e2, l), lane(x.e3, l))
        };
        let plane = pga::Plane { e0: lanes(3), e1: lanes(4), e2: lanes(5), e3: lanes(6) };
        let point = pga::Point { e021: lanes(8), e013: lanes(9), e032: lanes(10), e123: lanes(11) };
        let cv = |s| cga::Vector {
            e1: lanes(s),
            e2: lanes(s + 1),
            e3: lanes(s + 2),
            e4: lanes(s + 3),
            e5: lanes(s + 4),
        };
        let (p, q) = (cv(12), cv(20));
        for l in 0..4 {
            let (al, bl) = (one(a, l), one(b, l));
            assert_eq!(lane(a | b, l), al | bl);
            let w = a ^ b;
            assert_eq!(
                [lane(w.e12, l), lane(w.e23, l), lane(w.e31, l)],
                [(al ^ bl).e12, (al ^ bl).e23, (al ^ bl).e31]
            );
            let pl = pga::Plane::new(
                lane(plane.e0, l),
                lane(plane.e1, l),
                lane(plane.e2, l),
                lane(plane.e3, l),
            );
            let pt = pga::Point::new(
                lane(point.e021, l),
                lane(point.e013, l),
                lane(point.e032, l),
                lane(point.e123, l),
            );
            assert_eq!(lane(plane & (point - point * Lanes4::splat(0.5)), l), pl & (pt - pt * 0.5));
            let c = |x: cga::Vector<Lanes4<f64>>| {
                cga::Vector::new(
                    lane(x.e1, l),
                    lane(x.e2, l),
                    lane(x.e3, l),
                    lane(x.e4, l),
                    lane(x.e5, l),
                )
            };
            let wide = p ^ q;
            let narrow = c(p) ^ c(q);
            assert_eq!(lane(wide.e12, l), narrow.e12);
            assert_eq!(lane(wide.e45, l), narrow.e45);
        }
    }

    #[test]
    fn masks_and_signs() {
        let x = Lanes4([1.0f32, -0.0, f32::NAN, f32::INFINITY]);
        let zero = Lanes4::splat(0.0);
        assert_eq!(x.lt(zero), 0);
        assert_eq!(zero.lt(x), 0b1001);
        assert_eq!(x.eq(zero), 0b0010);
        assert_eq!(x.le(zero), 0b0010);
        assert_eq!(x.finite(), 0b0011);
        assert_eq!(Lanes4::splat(1.0f32).copy_sign(x).0[1], -1.0);
        assert_eq!(x.abs().0[1].to_bits(), 0);
    }
}
