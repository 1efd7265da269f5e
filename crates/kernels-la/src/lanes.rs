//! The glam vector type of each precision, behind one small trait so that each kernel is
//! written once.
//!
//! `f32` maps to [`Vec3A`] (16-byte aligned, one SSE register, so a vector operation is one
//! instruction) and `f64` to [`DVec3`] (three scalars; the compiler vectorises what it can).
//! The trait is sealed: [`Lanes`] lives in a private module, so only these two impls exist and
//! none of its methods become public API.

use core::fmt::Debug;
use core::ops::{Add, Div, Mul, Neg, Sub};

use glam::{DVec3, DVec4, Vec3A, Vec3Swizzles, Vec4};
use intersect::Real;

/// The vector operations the kernels need, for one precision: an extension of the shared
/// float trait [`Real`] by glam's vector type, a different concern from the scalar (see
/// [`crate::GlamReal`]).
///
/// Every method is `#[inline(always)]`: the kernels are a few dozen instructions long and a
/// call would cost as much as the arithmetic.
pub trait Lanes: Real {
    /// glam's 3-vector of this precision.
    type V: Copy
        + Debug
        + PartialEq
        + Send
        + Sync
        + Add<Output = Self::V>
        + Sub<Output = Self::V>
        + Mul<Output = Self::V>
        + Mul<Self, Output = Self::V>;

    /// The vector `[x, y, z]`.
    fn load(p: [Self; 3]) -> Self::V;
    /// The vector `[x, x, x]`.
    fn splat(x: Self) -> Self::V;
    /// The components as an array.
    fn lanes(v: Self::V) -> [Self; 3];
    /// Dot product.
    fn dot(a: Self::V, b: Self::V) -> Self;
    /// Cross product.
    fn cross(a: Self::V, b: Self::V) -> Self::V;
    /// `x + y + z`.
    fn sum(v: Self::V) -> Self;
    /// `[y, z, x]`: each lane takes its successor's value.
    fn rotate(v: Self::V) -> Self::V;
    /// `[z, x, y]`: each lane takes its predecessor's value.
    fn rotate_back(v: Self::V) -> Self::V;
    /// Whether some lane is `== 0` (either zero).
    fn any_zero(v: Self::V) -> bool;
    /// Whether the lanes' sign bits differ. With no lane zero or NaN: whether one lane is
    /// `< 0` and another `> 0`. One mask of the sign bits and one range check, so that the
    /// caller's test is one branch.
    fn mixed_signs(v: Self::V) -> bool;
    /// `rotate(x) * y - rotate(y) * x`, lane by lane, with an error small enough that the sign
    /// of each lane is that of the exact value: the watertight kernel's fallback when the
    /// plain computation gives a zero. See [`crate::Watertight`].
    fn edge_functions_exact_sign(x: Self::V, y: Self::V) -> Self::V;

    /// glam's 4-vector of this precision: four triangles of a leaf block, one per lane.
    type Q: Copy
        + Debug
        + PartialEq
        + Send
        + Sync
        + Add<Output = Self::Q>
        + Sub<Output = Self::Q>
        + Mul<Output = Self::Q>
        + Div<Output = Self::Q>
        + Neg<Output = Self::Q>;
    /// The four lanes `a`.
    fn q_load(a: &[Self; 4]) -> Self::Q;
    /// `[x, x, x, x]`.
    fn q_splat(x: Self) -> Self::Q;
    /// The lanes as an array.
    fn q_lanes(q: Self::Q) -> [Self; 4];
    /// Bit `l`: `a[l] < b[l]`.
    fn q_lt(a: Self::Q, b: Self::Q) -> u32;
    /// Bit `l`: `a[l] <= b[l]`.
    fn q_le(a: Self::Q, b: Self::Q) -> u32;
    /// Bit `l`: `a[l] == b[l]`.
    fn q_eq(a: Self::Q, b: Self::Q) -> u32;
    /// Bit `l`: `a[l]` is finite.
    fn q_finite(a: Self::Q) -> u32;
    /// Lane `l`: `-a[l]` where bit `l` of `mask` is set, else `a[l]`.
    fn q_negate_where(mask: u32, a: Self::Q) -> Self::Q;
}

impl Lanes for f32 {
    type V = Vec3A;
    type Q = Vec4;

    #[inline(always)]
    fn q_load(a: &[f32; 4]) -> Vec4 {
        Vec4::from_array(*a)
    }
    #[inline(always)]
    fn q_splat(x: f32) -> Vec4 {
        Vec4::splat(x)
    }
    #[inline(always)]
    fn q_lanes(q: Vec4) -> [f32; 4] {
        q.to_array()
    }
    #[inline(always)]
    fn q_lt(a: Vec4, b: Vec4) -> u32 {
        a.cmplt(b).bitmask()
    }
    #[inline(always)]
    fn q_le(a: Vec4, b: Vec4) -> u32 {
        a.cmple(b).bitmask()
    }
    #[inline(always)]
    fn q_eq(a: Vec4, b: Vec4) -> u32 {
        a.cmpeq(b).bitmask()
    }
    #[inline(always)]
    fn q_finite(a: Vec4) -> u32 {
        a.is_finite_mask().bitmask()
    }
    #[inline(always)]
    fn q_negate_where(mask: u32, a: Vec4) -> Vec4 {
        let m = glam::BVec4A::new(mask & 1 != 0, mask & 2 != 0, mask & 4 != 0, mask & 8 != 0);
        Vec4::select(m, -a, a)
    }

    #[inline(always)]
    fn load(p: [f32; 3]) -> Vec3A {
        Vec3A::from_array(p)
    }
    #[inline(always)]
    fn splat(x: f32) -> Vec3A {
        Vec3A::splat(x)
    }
    #[inline(always)]
    fn lanes(v: Vec3A) -> [f32; 3] {
        v.to_array()
    }
    #[inline(always)]
    fn dot(a: Vec3A, b: Vec3A) -> f32 {
        a.dot(b)
    }
    #[inline(always)]
    fn cross(a: Vec3A, b: Vec3A) -> Vec3A {
        a.cross(b)
    }
    #[inline(always)]
    fn sum(v: Vec3A) -> f32 {
        v.element_sum()
    }
    #[inline(always)]
    fn rotate(v: Vec3A) -> Vec3A {
        v.yzx()
    }
    #[inline(always)]
    fn rotate_back(v: Vec3A) -> Vec3A {
        v.zxy()
    }
    #[inline(always)]
    fn any_zero(v: Vec3A) -> bool {
        v.cmpeq(Vec3A::ZERO).any()
    }
    #[inline(always)]
    fn mixed_signs(v: Vec3A) -> bool {
        let m = v.is_negative_bitmask();
        m != 0 && m != 0b111
    }
    /// Products of two `f32` are exact in `f64` (24 + 24 significand bits fit in 53, and
    /// the exponent range is wide enough), so the `f64` difference is the exact value rounded
    /// once: its sign is exact. This is the paper's own fallback (Woop et al. 2013, Fig. 6).
    #[inline(always)]
    fn edge_functions_exact_sign(x: Vec3A, y: Vec3A) -> Vec3A {
        let (x, y) = (x.as_dvec3(), y.as_dvec3());
        (x.yzx() * y - y.yzx() * x).as_vec3a()
    }
}

impl Lanes for f64 {
    type V = DVec3;
    type Q = DVec4;

    #[inline(always)]
    fn q_load(a: &[f64; 4]) -> DVec4 {
        DVec4::from_array(*a)
    }
    #[inline(always)]
    fn q_splat(x: f64) -> DVec4 {
        DVec4::splat(x)
    }
    #[inline(always)]
    fn q_lanes(q: DVec4) -> [f64; 4] {
        q.to_array()
    }
    #[inline(always)]
    fn q_lt(a: DVec4, b: DVec4) -> u32 {
        a.cmplt(b).bitmask()
    }
    #[inline(always)]
    fn q_le(a: DVec4, b: DVec4) -> u32 {
        a.cmple(b).bitmask()
    }
    #[inline(always)]
    fn q_eq(a: DVec4, b: DVec4) -> u32 {
        a.cmpeq(b).bitmask()
    }
    #[inline(always)]
    fn q_finite(a: DVec4) -> u32 {
        a.is_finite_mask().bitmask()
    }
    #[inline(always)]
    fn q_negate_where(mask: u32, a: DVec4) -> DVec4 {
        let m = glam::BVec4::new(mask & 1 != 0, mask & 2 != 0, mask & 4 != 0, mask & 8 != 0);
        DVec4::select(m, -a, a)
    }

    #[inline(always)]
    fn load(p: [f64; 3]) -> DVec3 {
        DVec3::from_array(p)
    }
    #[inline(always)]
    fn splat(x: f64) -> DVec3 {
        DVec3::splat(x)
    }
    #[inline(always)]
    fn lanes(v: DVec3) -> [f64; 3] {
        v.to_array()
    }
    #[inline(always)]
    fn dot(a: DVec3, b: DVec3) -> f64 {
        a.dot(b)
    }
    #[inline(always)]
    fn cross(a: DVec3, b: DVec3) -> DVec3 {
        a.cross(b)
    }
    #[inline(always)]
    fn sum(v: DVec3) -> f64 {
        v.element_sum()
    }
    #[inline(always)]
    fn rotate(v: DVec3) -> DVec3 {
        v.yzx()
    }
    #[inline(always)]
    fn rotate_back(v: DVec3) -> DVec3 {
        v.zxy()
    }
    #[inline(always)]
    fn any_zero(v: DVec3) -> bool {
        v.cmpeq(DVec3::ZERO).any()
    }
    #[inline(always)]
    fn mixed_signs(v: DVec3) -> bool {
        let m = v.is_negative_bitmask();
        m != 0 && m != 0b111
    }
    /// There is no wider hardware type than `f64`, so each lane `a*b - c*d` is computed with
    /// Kahan's difference of products: `w = c*d` rounded, `e = w - c*d` exactly (one fused
    /// multiply-add), `f = a*b - w` rounded once (another), result `f + e`. Its relative
    /// error is at most `2u`, `u = 2^-53` (Jeannerod, Louvet, Muller, Math. Comp. 2013), so a
    /// nonzero exact value keeps its sign, and an exact zero gives `f = -e`, hence exactly 0.
    /// This holds as long as no product underflows (magnitudes above about 1e-292).
    #[cold]
    #[inline(never)]
    fn edge_functions_exact_sign(x: DVec3, y: DVec3) -> DVec3 {
        let (a, b, c, d) = (x.yzx().to_array(), y.to_array(), y.yzx().to_array(), x.to_array());
        DVec3::from_array(core::array::from_fn(|k| {
            let w = c[k] * d[k];
            let e = (-c[k]).mul_add(d[k], w);
            let f = a[k].mul_add(b[k], -w);
            f + e
        }))
    }
}

#[cfg(test)]
mod tests {
    use super::Lanes;
    use glam::{DVec3, Vec3A};

    /// One sign everywhere is not mixed, whatever the sizes; any other combination is, and
    /// only three lanes count (`Vec3A` has a fourth, unused).
    #[test]
    fn mixed_signs_reads_the_three_sign_bits() {
        for (v, mixed) in [
            ([1.0, 2.0, 3.0], false),
            ([-1.0, -2e30, -1e-30], false),
            ([1.0, -2.0, 3.0], true),
            ([-1.0, 2.0, 3.0], true),
            ([f64::INFINITY, 1.0, -1.0], true),
            ([-f64::INFINITY, -1.0, -1.0], false),
        ] {
            assert_eq!(<f64 as Lanes>::mixed_signs(DVec3::from_array(v)), mixed, "{v:?}");
            let v32 = Vec3A::from_array(v.map(|x| x as f32));
            assert_eq!(<f32 as Lanes>::mixed_signs(v32), mixed, "{v:?}");
        }
    }

    /// Fibonacci numbers: `F(n+1) F(n-1) - F(n)^2 = (-1)^n`, a difference of two huge
    /// products that is exactly 1 in size.
    fn fibonacci(n: usize) -> [i128; 3] {
        let (mut a, mut b) = (0i128, 1i128);
        for _ in 1..n {
            (a, b) = (b, a + b);
        }
        [a, b, a + b]
    }

    /// Lane 0 of `rotate(x) * y - rotate(y) * x` is `x[1] y[0] - y[1] x[0]`. Cases built from
    /// Fibonacci numbers (value +-k^2), and exact zeros; checks the sign of the fallback
    /// against integer arithmetic, and that the plain computation does get some wrong.
    fn cases(ns: core::ops::Range<usize>) -> Vec<([i128; 3], [i128; 3], i128)> {
        let mut out = Vec::new();
        for n in ns {
            let [f0, f1, f2] = fibonacci(n);
            for k in 1..4 {
                let (x, y) = ([k * f1, k * f2, 0], [k * f0, k * f1, 0]);
                out.push((x, y, x[1] * y[0] - y[1] * x[0]));
                // The same edge walked the other way.
                out.push((y, x, y[1] * x[0] - x[1] * y[0]));
                // Exactly zero: x[1] y[0] = (k f1)(k f0) = y[1] x[0].
                let (x, y) = ([k * f0, k * f1, 0], [k * f0, k * f1, 0]);
                out.push((x, y, 0));
            }
        }
        out
    }

    #[test]
    fn f64_fallback_sign_is_exact_where_plain_arithmetic_is_not() {
        let mut plain_wrong = 0;
        for (x, y, want) in cases(38..60) {
            let [xv, yv] = [x, y].map(|p| DVec3::from_array(p.map(|v| v as f64)));
            assert_eq!([xv, yv].map(|p| p.to_array().map(|v| v as i128)), [x, y], "inexact");
            let plain = (f64::rotate(xv) * yv - f64::rotate(yv) * xv).x;
            plain_wrong +=
                i32::from(plain.signum() as i128 * i128::from(plain != 0.0) != want.signum());
            let got = f64::edge_functions_exact_sign(xv, yv).x;
            assert_eq!(got.signum() as i128 * i128::from(got != 0.0), want.signum(), "{x:?} {y:?}");
        }
        assert!(plain_wrong > 10, "the cases must defeat the plain computation: {plain_wrong}");
    }

    #[test]
    fn f32_fallback_sign_is_exact_where_plain_arithmetic_is_not() {
        let mut plain_wrong = 0;
        for (x, y, want) in cases(14..24) {
            let [xv, yv] = [x, y].map(|p| Vec3A::from_array(p.map(|v| v as f32)));
            assert_eq!([xv, yv].map(|p| p.to_array().map(|v| v as i128)), [x, y], "inexact");
            let plain = (f32::rotate(xv) * yv - f32::rotate(yv) * xv).x;
            plain_wrong +=
                i32::from(plain.signum() as i128 * i128::from(plain != 0.0) != want.signum());
            let got = f32::edge_functions_exact_sign(xv, yv).x;
            assert_eq!(got.signum() as i128 * i128::from(got != 0.0), want.signum(), "{x:?} {y:?}");
        }
        assert!(plain_wrong > 10, "the cases must defeat the plain computation: {plain_wrong}");
    }
}
