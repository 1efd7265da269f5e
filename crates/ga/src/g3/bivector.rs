//! [`Bivector`]: grade 2, `e12 e12 + e23 e23 + e31 e31`.

use crate::Scalar;
use crate::g3::linear::impl_fields;
use crate::g3::{Rotor, Vector};

/// A bivector (grade 2), an oriented plane element: `e12·e12 + e23·e23 + e31·e31`.
///
/// The third basis bivector is `e31 = e3 e1` (the report's orientation), not `e13`. With this
/// choice the dual maps `e23, e31, e12` to `e1, e2, e3` without signs.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[repr(C)]
pub struct Bivector<T> {
    /// Coefficient of `e12 = e1 e2`.
    pub e12: T,
    /// Coefficient of `e23 = e2 e3`.
    pub e23: T,
    /// Coefficient of `e31 = e3 e1`.
    pub e31: T,
}

impl_fields!(Bivector { e12: "e12", e23: "e23", e31: "e31" });

impl<T: Scalar> Bivector<T> {
    /// The zero bivector.
    pub const ZERO: Self = Self::new(T::ZERO, T::ZERO, T::ZERO);
    /// The basis bivector `e12 = e1 e2` (the xy-plane, oriented from `e1` toward `e2`).
    pub const E12: Self = Self::new(T::ONE, T::ZERO, T::ZERO);
    /// The basis bivector `e23 = e2 e3`.
    pub const E23: Self = Self::new(T::ZERO, T::ONE, T::ZERO);
    /// The basis bivector `e31 = e3 e1`.
    pub const E31: Self = Self::new(T::ZERO, T::ZERO, T::ONE);

    /// `e12 e12 + e23 e23 + e31 e31` (note the argument order: the report's basis order).
    #[must_use]
    #[inline]
    pub const fn new(e12: T, e23: T, e31: T) -> Self {
        Self { e12, e23, e31 }
    }

    /// From `[e12, e23, e31]`.
    #[must_use]
    #[inline]
    pub const fn from_array(a: [T; 3]) -> Self {
        Self::new(a[0], a[1], a[2])
    }

    /// As `[e12, e23, e31]`.
    #[must_use]
    #[inline]
    pub const fn to_array(self) -> [T; 3] {
        [self.e12, self.e23, self.e31]
    }

    /// `|B|² = B B̃ = -B²`, the squared area.
    #[must_use]
    #[inline]
    pub fn norm_squared(self) -> T {
        self.e12 * self.e12 + self.e23 * self.e23 + self.e31 * self.e31
    }

    /// `|B|`, the area of the oriented plane element.
    #[must_use]
    #[inline]
    pub fn norm(self) -> T {
        self.norm_squared().sqrt()
    }

    /// `B / |B|`. The zero bivector gives NaN components; see [`Bivector::try_normalize`].
    #[must_use]
    #[inline]
    pub fn normalize(self) -> Self {
        self * self.norm().recip()
    }

    /// `B / |B|`, or `None` when `|B|` is zero or the result is not finite.
    #[must_use]
    #[inline]
    pub fn try_normalize(self) -> Option<Self> {
        let r = self.norm().recip();
        (r.is_finite() && r > T::ZERO).then(|| self * r)
    }

    /// `B⁻¹ = -B / |B|²` (a bivector squares to `-|B|²`), or `None` when `|B|²` is zero or
    /// not finite.
    #[must_use]
    #[inline]
    pub fn inverse(self) -> Option<Self> {
        // Finite whenever 0 < |B|² < ∞, as for `Vector::inverse`.
        let n2 = self.norm_squared();
        (n2 > T::ZERO && n2 < T::INFINITY).then_some(-self / n2)
    }

    /// The reverse `B̃ = -B` (`e2 e1 = -e1 e2`).
    #[must_use]
    #[inline]
    pub fn reverse(self) -> Self {
        -self
    }

    /// The grade involution `B̂ = B` (even grade).
    #[must_use]
    #[inline]
    pub fn grade_involution(self) -> Self {
        self
    }

    /// The Clifford conjugate `B̄ = -B`.
    #[must_use]
    #[inline]
    pub fn conjugate(self) -> Self {
        -self
    }

    /// The dual `B* = B I⁻¹`: the plane's normal vector, right-handed
    /// (`e12* = e3`, `e23* = e1`, `e31* = e2`; `(e1 ∧ e2)* = e1 × e2`).
    #[must_use]
    #[inline]
    pub fn dual(self) -> Vector<T> {
        // B I⁻¹ = -B e123, with e12 e123 = -e3, e23 e123 = -e1, e31 e123 = -e2.
        Vector::new(self.e23, self.e31, self.e12)
    }

    /// The inverse of [`Vector::dual`]: `B I`, so that `v.dual().undual() == v`.
    #[must_use]
    #[inline]
    pub fn undual(self) -> Vector<T> {
        Vector::new(-self.e23, -self.e31, -self.e12)
    }

    /// The exponential `e^B = cos|B| + (B/|B|) sin|B|`, a unit rotor (`B² = -|B|²`, so the
    /// series splits like Euler's formula).
    ///
    /// The rotor rotating by `θ` in the unit plane `P` is `(P * (-θ / 2)).exp()`; see
    /// [`Rotor::from_angle_plane`].
    #[must_use]
    #[inline]
    pub fn exp(self) -> Rotor<T> {
        let angle = self.norm();
        let (sin, cos) = angle.sin_cos();
        // sin(x)/x → 1 as x → 0; below EPSILON the two agree to rounding.
        let k = if angle > T::EPSILON { sin / angle } else { T::ONE };
        Rotor::new(cos, self.e12 * k, self.e23 * k, self.e31 * k)
    }
}
