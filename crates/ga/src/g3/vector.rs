//! [`Vector`]: grade 1, `e1 e1 + e2 e2 + e3 e3`.

use crate::Scalar;
use crate::g3::linear::impl_fields;
use crate::g3::{Bivector, Rotor};

/// A vector (grade 1): `e1·e1 + e2·e2 + e3·e3`. Also used for points (position vectors).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[repr(C)]
pub struct Vector<T> {
    /// Coefficient of `e1`.
    pub e1: T,
    /// Coefficient of `e2`.
    pub e2: T,
    /// Coefficient of `e3`.
    pub e3: T,
}

impl_fields!(Vector { e1: "e1", e2: "e2", e3: "e3" });

impl<T: Scalar> Vector<T> {
    /// The zero vector.
    pub const ZERO: Self = Self::new(T::ZERO, T::ZERO, T::ZERO);
    /// The basis vector `e1`.
    pub const E1: Self = Self::new(T::ONE, T::ZERO, T::ZERO);
    /// The basis vector `e2`.
    pub const E2: Self = Self::new(T::ZERO, T::ONE, T::ZERO);
    /// The basis vector `e3`.
    pub const E3: Self = Self::new(T::ZERO, T::ZERO, T::ONE);

    /// `e1 e1 + e2 e2 + e3 e3`.
    #[must_use]
    #[inline]
    pub const fn new(e1: T, e2: T, e3: T) -> Self {
        Self { e1, e2, e3 }
    }

    /// From `[e1, e2, e3]`.
    #[must_use]
    #[inline]
    pub const fn from_array(a: [T; 3]) -> Self {
        Self::new(a[0], a[1], a[2])
    }

    /// As `[e1, e2, e3]`.
    #[must_use]
    #[inline]
    pub const fn to_array(self) -> [T; 3] {
        [self.e1, self.e2, self.e3]
    }

    /// `|v|² = v·v = v ṽ`.
    #[must_use]
    #[inline]
    pub fn norm_squared(self) -> T {
        self.e1 * self.e1 + self.e2 * self.e2 + self.e3 * self.e3
    }

    /// `|v|`.
    #[must_use]
    #[inline]
    pub fn norm(self) -> T {
        self.norm_squared().sqrt()
    }

    /// `v / |v|`. The zero vector gives NaN components; see [`Vector::try_normalize`].
    #[must_use]
    #[inline]
    pub fn normalize(self) -> Self {
        self * self.norm().recip()
    }

    /// `v / |v|`, or `None` when `|v|` is zero or the result is not finite.
    #[must_use]
    #[inline]
    pub fn try_normalize(self) -> Option<Self> {
        let r = self.norm().recip();
        (r.is_finite() && r > T::ZERO).then(|| self * r)
    }

    /// `v⁻¹ = v / |v|²` (a vector squares to the scalar `|v|²`), or `None` when `|v|²` is zero
    /// or not finite.
    #[must_use]
    #[inline]
    pub fn inverse(self) -> Option<Self> {
        // With 0 < |v|² < ∞ the result is finite: |v⁻¹| = 1/|v| and |v|² ≥ the smallest
        // subnormal bounds 1/|v| far below the largest float.
        let n2 = self.norm_squared();
        (n2 > T::ZERO && n2 < T::INFINITY).then_some(self / n2)
    }

    /// The reverse `ṽ = v` (a single vector has nothing to reverse).
    #[must_use]
    #[inline]
    pub fn reverse(self) -> Self {
        self
    }

    /// The grade involution `v̂ = -v` (odd grade).
    #[must_use]
    #[inline]
    pub fn grade_involution(self) -> Self {
        -self
    }

    /// The Clifford conjugate `v̄ = -v`.
    #[must_use]
    #[inline]
    pub fn conjugate(self) -> Self {
        -self
    }

    /// The dual `v* = v I⁻¹ = -v I`: the plane orthogonal to `v`.
    ///
    /// `e1* = -e23`, `e2* = -e31`, `e3* = -e12`. Dualising twice negates (`I⁻² = -1`);
    /// [`Bivector::undual`] is the inverse.
    #[must_use]
    #[inline]
    pub fn dual(self) -> Bivector<T> {
        // v I⁻¹ = -(v1 e1 + v2 e2 + v3 e3) e123, with e1 e123 = e23, e2 e123 = e31, e3 e123 = e12.
        Bivector::new(-self.e3, -self.e1, -self.e2)
    }

    /// The inverse of [`Bivector::dual`]: `v I`, so that `B.dual().undual() == B`.
    ///
    /// `e1 I = e23`, `e2 I = e31`, `e3 I = e12`.
    #[must_use]
    #[inline]
    pub fn undual(self) -> Bivector<T> {
        Bivector::new(self.e3, self.e1, self.e2)
    }

    /// The cross product `a × b = (a ∧ b)*`, for interoperating with linear-algebra code.
    #[must_use]
    #[inline]
    pub fn cross(self, b: Self) -> Self {
        (self ^ b).dual()
    }

    /// The projection of `self` onto the plane `plane` (report 2.3.4): `(a · B) B⁻¹`.
    ///
    /// `plane` need not be unit; a zero bivector gives NaN.
    #[must_use]
    #[inline]
    pub fn project(self, plane: Bivector<T>) -> Self {
        // a·B lies in B, so (a·B) B⁻¹ has no trivector part: (a·B) ∧ B⁻¹ = 0. B⁻¹ = -B/|B|², and
        // for the in-plane vector c = a·B, c B = c·B (the vector part of the geometric product).
        let c = self | plane;
        (c | plane) * (-plane.norm_squared().recip())
    }

    /// The rejection of `self` from the plane `plane` (report 2.3.4): `(a ∧ B) B⁻¹`, the
    /// component of `self` orthogonal to the plane.
    ///
    /// `plane` need not be unit; a zero bivector gives NaN.
    #[must_use]
    #[inline]
    pub fn reject(self, plane: Bivector<T>) -> Self {
        // a ∧ B = t I (a trivector), B⁻¹ = -B/|B|², and I B = -B* (B* = B I⁻¹ = -B I), so
        // (a ∧ B) B⁻¹ = -t I B / |B|² = t B* / |B|².
        let t = (self ^ plane).e123;
        plane.dual() * (t * plane.norm_squared().recip())
    }

    /// The reflection of `self` in the plane through the origin spanned by `plane`, computed
    /// as `a - 2 a⊥` with `a⊥` the [rejection](Vector::reject).
    ///
    /// In versor form this is `-B a B⁻¹`: with `B = n I`, `B a B⁻¹ = n a n⁻¹` (`I` is central),
    /// which keeps the normal component and negates the in-plane part.
    #[must_use]
    #[inline]
    pub fn reflect_in_plane(self, plane: Bivector<T>) -> Self {
        self - self.reject(plane) * T::TWO
    }

    /// The reflection of `self` in the plane through the origin with normal `normal`:
    /// `-n a n⁻¹`. `normal` need not be unit.
    #[must_use]
    #[inline]
    pub fn reflect_in_normal(self, normal: Self) -> Self {
        // -n a n⁻¹ = a - 2 (a·n) n / |n|².
        self - normal * (T::TWO * (self | normal) / normal.norm_squared())
    }

    /// Linear interpolation `self + (other - self) t`.
    #[must_use]
    #[inline]
    pub fn lerp(self, other: Self, t: T) -> Self {
        self + (other - self) * t
    }

    /// The rotor taking the direction of `self` to that of `to`; see [`Rotor::from_vectors`].
    #[must_use]
    #[inline]
    pub fn rotor_to(self, to: Self) -> Rotor<T> {
        Rotor::from_vectors(self, to)
    }
}
