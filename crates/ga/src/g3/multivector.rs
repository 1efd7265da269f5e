//! [`Multivector`]: the general element of G3, eight coefficients.

use crate::Scalar;
use crate::g3::linear::impl_linear;
use crate::g3::{Bivector, Rotor, Trivector, Vector};

/// A general multivector of G3: `s + e1·e1 + e2·e2 + e3·e3 + e12·e12 + e23·e23 + e31·e31 +
/// e123·e123`, in the report's basis order.
///
/// Every product is defined for it, so it is the type to fall back on (and the one tests compare
/// against). The grade types ([`Vector`], [`Bivector`], [`Trivector`], [`Rotor`]) are smaller
/// and faster where the grades are known.
///
/// The coefficients are reached through [`from_array`](Multivector::from_array),
/// [`to_array`](Multivector::to_array) and the accessors ([`s`](Multivector::s),
/// [`e1`](Multivector::e1), ...), all in the report's order. The storage order is private: it
/// is `1, e1, e2, e12, e3, e31, e23, e123`, which puts the even and odd halves of the geometric
/// product's permutations in matching SIMD lanes (see [`crate::g3::geometric`]), and the type
/// is 32-byte aligned so that a vector load never straddles a cache line.
#[derive(Clone, Copy, Default, PartialEq)]
#[repr(C, align(32))]
pub struct Multivector<T> {
    /// Coefficients in storage order ([`SLOT`] maps report order to it).
    pub(crate) c: [T; 8],
}

/// The storage slot of each coefficient of the report's order.
pub(crate) const SLOT: [usize; 8] = [0, 1, 2, 4, 3, 6, 5, 7];

impl<T: Scalar> Multivector<T> {
    /// [`is_finite`](Multivector::is_finite) without branches: `x - x` is 0 for finite `x`
    /// and NaN otherwise, and a sum with a NaN is NaN.
    #[inline(always)]
    pub(crate) fn all_finite(self) -> bool {
        // `x * 0` would do too; clippy's eq_op does not know that `x - x` is not always zero.
        #[allow(clippy::eq_op)]
        let z = self.c.map(|x| x - x);
        ((z[0] + z[4]) + (z[1] + z[5])) + ((z[2] + z[6]) + (z[3] + z[7])) == T::ZERO
    }
    /// The components with their blade names, in the report's order.
    #[inline(always)]
    pub(crate) fn terms(self) -> impl IntoIterator<Item = (T, &'static str)> {
        let a = self.to_array();
        core::array::from_fn::<_, 8, _>(|k| (a[k], DISPLAY[k]))
    }
}

impl_linear!(Multivector);

impl<T: Scalar> core::fmt::Debug for Multivector<T> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        let a = self.to_array();
        let mut d = f.debug_struct("Multivector");
        for (name, x) in ["s", "e1", "e2", "e3", "e12", "e23", "e31", "e123"].into_iter().zip(a) {
            d.field(name, &x);
        }
        d.finish()
    }
}

/// The basis blade names in the report's order.
pub const BASIS: [&str; 8] = ["1", "e1", "e2", "e3", "e12", "e23", "e31", "e123"];

/// The suffix `Display` writes after each coefficient (none for the scalar).
const DISPLAY: [&str; 8] = ["", "e1", "e2", "e3", "e12", "e23", "e31", "e123"];

/// The grade of each basis blade, in the report's order.
pub const GRADES: [usize; 8] = [0, 1, 1, 1, 2, 2, 2, 3];

impl<T: Scalar> Multivector<T> {
    /// Zero.
    pub const ZERO: Self = Self { c: [T::ZERO; 8] };
    /// The scalar 1.
    pub const ONE: Self = Self::basis(0);
    /// The basis vector `e1`.
    pub const E1: Self = Self::basis(1);
    /// The basis vector `e2`.
    pub const E2: Self = Self::basis(2);
    /// The basis vector `e3`.
    pub const E3: Self = Self::basis(3);
    /// The basis bivector `e12 = e1 e2`.
    pub const E12: Self = Self::basis(4);
    /// The basis bivector `e23 = e2 e3`.
    pub const E23: Self = Self::basis(5);
    /// The basis bivector `e31 = e3 e1`.
    pub const E31: Self = Self::basis(6);
    /// The unit pseudoscalar `I = e123 = e1 e2 e3`.
    pub const E123: Self = Self::basis(7);

    /// The `k`-th basis blade of the report's order `1, e1, e2, e3, e12, e23, e31, e123`.
    ///
    /// # Panics
    ///
    /// If `k >= 8`.
    #[must_use]
    pub const fn basis(k: usize) -> Self {
        assert!(k < 8, "G3 has 8 basis blades");
        let mut c = [T::ZERO; 8];
        c[SLOT[k]] = T::ONE;
        Self { c }
    }

    /// From all eight coefficients, in the report's order.
    #[allow(clippy::too_many_arguments)]
    #[must_use]
    #[inline]
    pub const fn new(s: T, e1: T, e2: T, e3: T, e12: T, e23: T, e31: T, e123: T) -> Self {
        Self { c: [s, e1, e2, e12, e3, e31, e23, e123] }
    }

    /// From `[s, e1, e2, e3, e12, e23, e31, e123]` (the report's basis order).
    #[must_use]
    #[inline]
    pub const fn from_array(a: [T; 8]) -> Self {
        Self::new(a[0], a[1], a[2], a[3], a[4], a[5], a[6], a[7])
    }

    /// As `[s, e1, e2, e3, e12, e23, e31, e123]` (the report's basis order).
    #[must_use]
    #[inline]
    pub const fn to_array(self) -> [T; 8] {
        let c = self.c;
        [c[0], c[1], c[2], c[4], c[3], c[6], c[5], c[7]]
    }

    /// The scalar `x` as a multivector.
    #[must_use]
    #[inline]
    pub const fn scalar(x: T) -> Self {
        let mut c = [T::ZERO; 8];
        c[0] = x;
        Self { c }
    }

    /// The scalar coefficient.
    #[must_use]
    #[inline]
    pub const fn s(self) -> T {
        self.c[0]
    }
    /// The `e1` coefficient.
    #[must_use]
    #[inline]
    pub const fn e1(self) -> T {
        self.c[1]
    }
    /// The `e2` coefficient.
    #[must_use]
    #[inline]
    pub const fn e2(self) -> T {
        self.c[2]
    }
    /// The `e3` coefficient.
    #[must_use]
    #[inline]
    pub const fn e3(self) -> T {
        self.c[4]
    }
    /// The `e12` coefficient.
    #[must_use]
    #[inline]
    pub const fn e12(self) -> T {
        self.c[3]
    }
    /// The `e23` coefficient.
    #[must_use]
    #[inline]
    pub const fn e23(self) -> T {
        self.c[6]
    }
    /// The `e31` coefficient.
    #[must_use]
    #[inline]
    pub const fn e31(self) -> T {
        self.c[5]
    }
    /// The `e123` coefficient.
    #[must_use]
    #[inline]
    pub const fn e123(self) -> T {
        self.c[7]
    }

    /// The grade-1 part.
    #[must_use]
    #[inline]
    pub const fn vector_part(self) -> Vector<T> {
        Vector::new(self.e1(), self.e2(), self.e3())
    }
    /// The grade-2 part.
    #[must_use]
    #[inline]
    pub const fn bivector_part(self) -> Bivector<T> {
        Bivector::new(self.e12(), self.e23(), self.e31())
    }
    /// The grade-3 part.
    #[must_use]
    #[inline]
    pub const fn trivector_part(self) -> Trivector<T> {
        Trivector::new(self.e123())
    }
    /// The even part (grades 0 and 2).
    #[must_use]
    #[inline]
    pub const fn even_part(self) -> Rotor<T> {
        Rotor::new(self.s(), self.e12(), self.e23(), self.e31())
    }
    /// The odd part (grades 1 and 3).
    #[must_use]
    #[inline]
    pub fn odd_part(self) -> Self {
        Self::new(T::ZERO, self.e1(), self.e2(), self.e3(), T::ZERO, T::ZERO, T::ZERO, self.e123())
    }

    /// The grade-`k` part `⟨A⟩_k` (zero for `k > 3`).
    #[must_use]
    #[inline]
    pub fn grade(self, k: usize) -> Self {
        let mut a = self.to_array();
        for (c, g) in a.iter_mut().zip(GRADES) {
            if g != k {
                *c = T::ZERO;
            }
        }
        Self::from_array(a)
    }

    /// The reverse `Ã`: the order of the vector factors of each blade reversed, which negates
    /// grades 2 and 3 (report 2.3.1).
    #[must_use]
    #[inline]
    pub fn reverse(self) -> Self {
        self.signed(1, 1, -1, -1)
    }

    /// The grade involution `Â`: every vector negated, which negates grades 1 and 3.
    #[must_use]
    #[inline]
    pub fn grade_involution(self) -> Self {
        self.signed(1, -1, 1, -1)
    }

    /// The Clifford conjugate `Ā`, the reverse of the grade involution: negates grades 1 and 2.
    #[must_use]
    #[inline]
    pub fn conjugate(self) -> Self {
        self.signed(1, -1, -1, 1)
    }

    /// Multiplies grade `k` by the `k`-th sign.
    #[inline]
    fn signed(self, g0: i8, g1: i8, g2: i8, g3: i8) -> Self {
        let f = |x: T, g: i8| if g < 0 { -x } else { x };
        Self::new(
            f(self.s(), g0),
            f(self.e1(), g1),
            f(self.e2(), g1),
            f(self.e3(), g1),
            f(self.e12(), g2),
            f(self.e23(), g2),
            f(self.e31(), g2),
            f(self.e123(), g3),
        )
    }

    /// The dual `A* = A I⁻¹ = -A I` (report 2.3.3).
    ///
    /// Blade by blade: `1* = -e123`, `e1* = -e23`, `e2* = -e31`, `e3* = -e12`, `e12* = e3`,
    /// `e23* = e1`, `e31* = e2`, `e123* = 1`.
    #[must_use]
    #[inline]
    pub fn dual(self) -> Self {
        Self::new(
            self.e123(),
            self.e23(),
            self.e31(),
            self.e12(),
            -self.e3(),
            -self.e1(),
            -self.e2(),
            -self.s(),
        )
    }

    /// The inverse of [`dual`](Multivector::dual): `A I`, so `a.dual().undual() == a`.
    #[must_use]
    #[inline]
    pub fn undual(self) -> Self {
        Self::new(
            -self.e123(),
            -self.e23(),
            -self.e31(),
            -self.e12(),
            self.e3(),
            self.e1(),
            self.e2(),
            self.s(),
        )
    }

    /// `|A|² = ⟨A Ã⟩₀`, the sum of the squares of the eight coefficients (the metric is
    /// Euclidean and the basis orthonormal).
    #[must_use]
    #[inline]
    pub fn norm_squared(self) -> T {
        let a = self.to_array();
        let mut sum = T::ZERO;
        for x in a {
            sum = x.mul_add_if_fma(x, sum);
        }
        sum
    }

    /// `|A|`.
    #[must_use]
    #[inline]
    pub fn norm(self) -> T {
        self.norm_squared().sqrt()
    }

    /// `A / |A|`. Zero gives NaN components; see [`Multivector::try_normalize`].
    #[must_use]
    #[inline]
    pub fn normalize(self) -> Self {
        self * self.norm().recip()
    }

    /// `A / |A|`, or `None` when `|A|` is zero or the result is not finite.
    #[must_use]
    #[inline]
    pub fn try_normalize(self) -> Option<Self> {
        let r = self.norm().recip();
        (r.is_finite() && r > T::ZERO).then(|| self * r)
    }

    /// The inverse `A⁻¹` of any invertible multivector (closed form for G3), or `None` when `A`
    /// has no inverse or the result would not be finite.
    ///
    /// `A Ā` (with `Ā` the [Clifford conjugate](Multivector::conjugate)) always lies in the
    /// centre `{1, I}` of G3, which behaves as the complex numbers (`I² = -1`). So
    /// `z = A Ā = α + β I`, and `A⁻¹ = Ā z⁻¹` with `z⁻¹ = (α - β I) / (α² + β²)`. `A` is
    /// invertible exactly when `z ≠ 0`. Unlike [`versor_inverse`](Multivector::versor_inverse)
    /// this is valid for every multivector, e.g. `1 + e1` (`z = 0`: not invertible) or
    /// `1 + e12 + e123`.
    #[must_use]
    pub fn inverse(self) -> Option<Self> {
        // Lane by lane on the storage order 1, e1, e2, e12, e3, e31, e23, e123 (the bitmask
        // order, see `geometric`), where multiplying by I pairs slot l with slot 7 - l: written
        // this way the whole inverse vectorises.
        let a = self.c;
        let signed = |x: T, negate: bool| if negate { -x } else { x };
        // α = ⟨A Ā⟩₀ = s² - |v|² + |B|² - t²: minus on the vectors and on I.
        const ALPHA_NEG: [bool; 8] = [false, true, true, false, true, false, false, true];
        // β = ⟨A Ā⟩₃ = 2 (s t - v·B*) with B* = (e23, e31, e12): twice the sum over l < 4 of
        // ±a_l a_(7-l).
        const BETA_NEG: [bool; 8] = [false, true, true, true, true, true, true, false];
        // Summed as trees (lanes, then halves) so the optimiser can keep them in vector registers
        // instead of one long chain of dependent adds.
        let p: [T; 8] = core::array::from_fn(|l| signed(a[l], ALPHA_NEG[l]) * a[l]);
        let q: [T; 4] = core::array::from_fn(|l| signed(a[l], BETA_NEG[l]) * a[7 - l]);
        let alpha = ((p[0] + p[4]) + (p[1] + p[5])) + ((p[2] + p[6]) + (p[3] + p[7]));
        let beta = T::TWO * ((q[0] + q[2]) + (q[1] + q[3]));
        let n = alpha * alpha + beta * beta;
        // A⁻¹ = Ā (c + d I) with c = α/|z|², d = -β/|z|². Ā negates grades 1 and 2; X I maps
        // 1 → e123, e1 → e23, e2 → e31, e3 → e12, e12 → -e3, e23 → -e1, e31 → -e2, e123 → -1,
        // so lane l of Ā I is ±a_(7-l): CROSS_NEG is the sign of both steps together.
        const CONJ_NEG: [bool; 8] = [false, true, true, true, true, true, true, false];
        const CROSS_NEG: [bool; 8] = [true, false, false, true, false, true, true, false];
        let r = n.recip();
        let (c, d) = (alpha * r, -beta * r);
        let inv = Self {
            c: core::array::from_fn(|l| {
                signed(a[l], CONJ_NEG[l]).mul_add_if_fma(c, signed(a[7 - l], CROSS_NEG[l]) * d)
            }),
        };
        (n > T::ZERO && n < T::INFINITY && inv.all_finite()).then_some(inv)
    }

    /// The versor inverse `Ã / (A Ã)`, valid only when `A` is a versor (a product of
    /// invertible vectors), for which `A Ã = |A|²` is a scalar (report 2.3.2). Cheaper than
    /// [`inverse`](Multivector::inverse); for a non-versor the result is simply wrong.
    ///
    /// Returns `None` when `|A|` is zero or the result is not finite.
    #[must_use]
    #[inline]
    pub fn versor_inverse(self) -> Option<Self> {
        let r = self.norm_squared().recip();
        (r.is_finite() && r > T::ZERO).then(|| self.reverse() * r)
    }

    /// The scalar part, or an error naming the first non-zero blade of another grade.
    ///
    /// # Errors
    ///
    /// [`NarrowError`](crate::g3::NarrowError) when any non-scalar coefficient is non-zero.
    pub fn try_scalar(self) -> Result<T, crate::g3::NarrowError> {
        crate::g3::convert::check_zero(&self, "scalar", &[0])?;
        Ok(self.s())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::g3::NarrowError;

    type M = Multivector<f64>;

    #[test]
    fn basis_products_follow_the_defining_rules() {
        // e_i e_i = 1, e_i e_j = -e_j e_i, and the bivector names: e12 = e1 e2, e31 = e3 e1.
        for e in [M::E1, M::E2, M::E3] {
            assert_eq!(e * e, M::ONE);
        }
        assert_eq!(M::E1 * M::E2, M::E12);
        assert_eq!(M::E2 * M::E1, -M::E12);
        assert_eq!(M::E2 * M::E3, M::E23);
        assert_eq!(M::E3 * M::E1, M::E31);
        assert_eq!(M::E1 * M::E3, -M::E31);
        assert_eq!(M::E1 * M::E2 * M::E3, M::E123);
        // The report's worked example (section 2.2.2): (e1 ∧ e2)(e1 ∧ e2 ∧ e3) = -e3.
        assert_eq!(M::E12 * M::E123, -M::E3);
        for b in [M::E12, M::E23, M::E31, M::E123] {
            assert_eq!(b * b, -M::ONE);
        }
    }

    #[test]
    fn array_order_is_the_reports() {
        let a = [1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0];
        let m = M::from_array(a);
        assert_eq!(m.to_array(), a);
        let got = [m.s(), m.e1(), m.e2(), m.e3(), m.e12(), m.e23(), m.e31(), m.e123()];
        assert_eq!(got, a);
        for (k, b) in
            [M::ONE, M::E1, M::E2, M::E3, M::E12, M::E23, M::E31, M::E123].into_iter().enumerate()
        {
            assert_eq!(b, M::basis(k));
            assert_eq!(b.to_string(), if k == 0 { "1" } else { BASIS[k] }.replace('e', "1e"));
        }
    }

    #[test]
    fn display_matches_the_report_style() {
        assert_eq!(
            M::from_array([1.0, 2.0, 0.0, 0.0, 0.0, -0.5, 0.0, 0.0]).to_string(),
            "1 + 2e1 - 0.5e23"
        );
        assert_eq!(M::ZERO.to_string(), "0");
        assert_eq!((-M::E31).to_string(), "-1e31");
        assert_eq!(format!("{:.2}", M::E1 * 0.125 - M::E123), "0.12e1 - 1.00e123");
        assert_eq!(crate::g3::Rotor::new(0.5, 0.0, -0.5, 0.0).to_string(), "0.5 - 0.5e23");
        assert_eq!(crate::g3::Vector::<f32>::ZERO.to_string(), "0");
        // Terms that round to zero at the requested precision are left out.
        assert_eq!(format!("{:.3}", M::ONE + M::E1 * 1e-17), "1.000");
        assert_eq!(format!("{:.3}", M::E1 * 1e-17), "0");
        assert_eq!((M::ONE + M::E1 * 1e-17).to_string(), "1 + 0.00000000000000001e1");
    }

    #[test]
    fn narrowing_refuses_to_drop_components() {
        let v = crate::g3::Vector::new(1.0, 2.0, 3.0);
        assert_eq!(crate::g3::Vector::try_from(M::from(v)), Ok(v));
        let err = crate::g3::Vector::try_from(M::from(v) + M::E31 * 1e-300).unwrap_err();
        assert_eq!(err, NarrowError { target: "Vector", blade: "e31" });
        assert_eq!(
            err.to_string(),
            "cannot convert multivector to Vector: its e31 component is non-zero"
        );
        assert!(crate::g3::Bivector::try_from(M::E12 + M::ONE).is_err());
        assert!(crate::g3::Trivector::try_from(M::E123 + M::E3).is_err());
        assert!(crate::g3::Rotor::try_from(M::E12 + M::ONE).is_ok());
        assert!(crate::g3::Rotor::try_from(M::E12 + M::E1 * f64::NAN).is_err());
        assert_eq!((M::ONE * 2.0).try_scalar(), Ok(2.0));
        assert!((M::ONE + M::E123).try_scalar().is_err());
    }

    #[test]
    fn involutions_and_duals() {
        let m = M::from_array([1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0]);
        assert_eq!(m.reverse().to_array(), [1.0, 2.0, 3.0, 4.0, -5.0, -6.0, -7.0, -8.0]);
        assert_eq!(m.grade_involution().to_array(), [1.0, -2.0, -3.0, -4.0, 5.0, 6.0, 7.0, -8.0]);
        assert_eq!(m.conjugate(), m.grade_involution().reverse());
        // A* = A I⁻¹ with I⁻¹ = -I, checked against the geometric product.
        assert_eq!(m.dual(), m * -M::E123);
        assert_eq!(m.undual(), m * M::E123);
        assert_eq!(m.dual().undual(), m);
        assert_eq!(M::E12.dual(), M::E3);
        assert_eq!(m.grade(2).to_array(), [0.0, 0.0, 0.0, 0.0, 5.0, 6.0, 7.0, 0.0]);
        assert_eq!(m.grade(4), M::ZERO);
        assert_eq!(m.norm_squared(), (m * m.reverse()).s());
    }

    #[test]
    fn closed_form_inverse() {
        let cases = [
            [1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0],
            [0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 1.0],
            [0.3, -0.2, 0.0, 0.9, 0.0, 0.1, -4.0, 0.0],
        ];
        for a in cases {
            let m = M::from_array(a);
            let inv = m.inverse().unwrap();
            assert!((m * inv).abs_diff_eq(M::ONE, 1e-14), "{m}: {}", m * inv);
            assert!((inv * m).abs_diff_eq(M::ONE, 1e-14), "{m}: {}", inv * m);
        }
        // 1 + e1 is a zero divisor: (1 + e1)(1 - e1) = 0.
        assert_eq!((M::ONE + M::E1).inverse(), None);
        assert_eq!(M::ZERO.inverse(), None);
        assert_eq!((M::ONE * f64::NAN).inverse(), None);
        // The versor inverse agrees on a versor (a product of vectors) ...
        let v = (M::E1 + M::E2 * 2.0) * (M::E3 - M::E1 * 0.5) * (M::E2 + M::E3);
        assert!(v.versor_inverse().unwrap().abs_diff_eq(v.inverse().unwrap(), 1e-14));
        // ... and is wrong on a non-versor, as documented.
        let n = M::ONE + M::E123 * 2.0 + M::E1;
        assert!(!(n * n.versor_inverse().unwrap()).abs_diff_eq(M::ONE, 1e-3));
    }
}
