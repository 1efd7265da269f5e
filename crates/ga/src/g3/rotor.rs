//! [`Rotor`]: the even subalgebra (scalar + bivector); unit rotors are rotations.

use crate::Scalar;
use crate::g3::linear::impl_fields;
use crate::g3::{Bivector, Vector};

/// An element of the even subalgebra, `s + e12·e12 + e23·e23 + e31·e31`; a rotation when unit.
///
/// # Rotation convention
///
/// The rotor turning by the angle `θ` in the unit plane `P` is `R = exp(-P θ/2) = cos(θ/2) -
/// P sin(θ/2)` and acts as `x' = R x R̃`. A positive angle turns the first vector of the plane
/// toward the second: with `P = e12 = e1 ∧ e2`, `+90°` takes `e1` to `e2`. That is the same
/// rotation as a right-handed quaternion about the normal `P* = e3`, so `R` and glam's `Quat`
/// correspond by `w = s`, `(x, y, z) = -(e23, e31, e12)`.
///
/// Composition reads right to left, as for matrices and quaternions: `(R2 * R1).rotate(x)` first
/// applies `R1`, then `R2`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[repr(C, align(16))]
pub struct Rotor<T> {
    /// The scalar part (`cos(θ/2)` for a unit rotor).
    pub s: T,
    /// Coefficient of `e12`.
    pub e12: T,
    /// Coefficient of `e23`.
    pub e23: T,
    /// Coefficient of `e31`.
    pub e31: T,
}

impl_fields!(Rotor { s: "", e12: "e12", e23: "e23", e31: "e31" });

impl<T: Scalar> Rotor<T> {
    /// The identity rotation, `1`.
    pub const IDENTITY: Self = Self::new(T::ONE, T::ZERO, T::ZERO, T::ZERO);
    /// Zero (not a rotation; the additive identity).
    pub const ZERO: Self = Self::new(T::ZERO, T::ZERO, T::ZERO, T::ZERO);

    /// `s + e12 e12 + e23 e23 + e31 e31`.
    #[must_use]
    #[inline]
    pub const fn new(s: T, e12: T, e23: T, e31: T) -> Self {
        Self { s, e12, e23, e31 }
    }

    /// `s + B`.
    #[must_use]
    #[inline]
    pub const fn from_scalar_bivector(s: T, b: Bivector<T>) -> Self {
        Self::new(s, b.e12, b.e23, b.e31)
    }

    /// From `[s, e12, e23, e31]`.
    #[must_use]
    #[inline]
    pub const fn from_array(a: [T; 4]) -> Self {
        Self::new(a[0], a[1], a[2], a[3])
    }

    /// As `[s, e12, e23, e31]`.
    #[must_use]
    #[inline]
    pub const fn to_array(self) -> [T; 4] {
        [self.s, self.e12, self.e23, self.e31]
    }

    /// The bivector part.
    #[must_use]
    #[inline]
    pub const fn bivector(self) -> Bivector<T> {
        Bivector::new(self.e12, self.e23, self.e31)
    }

    /// The rotation by `angle` (radians) in the plane `plane`, turning from the plane's first
    /// vector toward its second: `exp(-P angle/2)` with `P = plane / |plane|`.
    ///
    /// `plane` need not be unit; a zero plane gives NaN components.
    #[must_use]
    #[inline]
    pub fn from_angle_plane(angle: T, plane: Bivector<T>) -> Self {
        let (sin, cos) = (angle * T::HALF).sin_cos();
        Self::from_scalar_bivector(cos, plane * (-sin * plane.norm().recip()))
    }

    /// The smallest rotation taking the direction of `from` to the direction of `to`.
    ///
    /// `from` and `to` need not be unit. For opposite directions every plane containing `from`
    /// gives a half turn; one is chosen (the plane containing `from` and the basis axis least
    /// aligned with it). Zero or non-finite inputs give NaN components.
    #[must_use]
    pub fn from_vectors(from: Vector<T>, to: Vector<T>) -> Self {
        let (a, b) = (from.normalize(), to.normalize());
        // R ∝ 1 + b a = (1 + a·b) + b ∧ a, rotating by twice the angle between a and the halfway
        // vector, i.e. by the angle from a to b. 1 + a·b = |a + b|²/2 is computed from the sum
        // so that it keeps its relative accuracy when a and b are nearly opposite.
        let h = a + b;
        let raw = Self::from_scalar_bivector(h.norm_squared() * T::HALF, b ^ a);
        let n2 = raw.norm_squared();
        if n2 > T::EPSILON * T::EPSILON {
            return raw * n2.sqrt().recip();
        }
        // Opposite (to rounding): a half turn in a plane containing a. Any normal m ⟂ a will
        // do; a × (least aligned axis) is far from zero. exp(-P π/2) = -P.
        let (x, y, z) = (a.e1.abs(), a.e2.abs(), a.e3.abs());
        let axis = if x <= y && x <= z {
            Vector::E1
        } else if y <= z {
            Vector::E2
        } else {
            Vector::E3
        };
        let plane = a.cross(axis).undual().normalize();
        Self::from_scalar_bivector(T::ZERO, -plane)
    }

    /// The logarithm of a unit rotor: the bivector `L` with `L.exp() == self`, with
    /// `|L| ∈ [0, π]` (the half angle).
    ///
    /// For `R = cos φ + P sin φ`, `log R = P φ` with `φ = atan2(|B|, s)`, so the rotor
    /// [`from_angle_plane(θ, P)`](Rotor::from_angle_plane) has the logarithm `-P θ/2`. A
    /// non-unit rotor gives the logarithm of `R/|R|` (the scalar `ln|R|` is dropped). `-1`
    /// (a full turn) has no unique plane; `π e12` is returned.
    #[must_use]
    #[inline]
    pub fn log(self) -> Bivector<T> {
        let b = self.bivector();
        let sin = b.norm();
        if sin == T::ZERO {
            return if self.s < T::ZERO { Bivector::E12 * T::PI } else { Bivector::ZERO };
        }
        b * (sin.atan2(self.s) / sin)
    }

    /// Spherical interpolation from `self` (`t = 0`) to `other` (`t = 1`) at constant angular
    /// speed, along the shorter arc: `R0 (R̃0 R1)^t`. Both should be unit rotors.
    ///
    /// `R1` and `-R1` are the same rotation; the one nearer `self` is used.
    #[must_use]
    #[inline]
    pub fn slerp(self, other: Self, t: T) -> Self {
        let mut rel = self.reverse() * other;
        if rel.s < T::ZERO {
            rel = -rel;
        }
        self * (rel.log() * t).exp()
    }

    /// Rotates `v`: `R v R̃` for a unit rotor, expanded (about the cost of a quaternion
    /// rotating a vector; not two general products).
    ///
    /// The rotor is assumed unit; a non-unit rotor gives a wrong result (use
    /// [`Rotor::normalize`] first, or the general sandwich `R * v * R.reverse()`, which also
    /// scales by `|R|²`).
    #[must_use]
    #[inline]
    pub fn rotate(self, v: Vector<T>) -> Vector<T> {
        // Write B = b I with b = B* = (e23, e31, e12) (I is central, I² = -1). For vectors
        // b v = b·v + (b × v) I, so
        //   R v R̃ = (s + bI) v (s - bI) = s² v + s I (b v - v b) + b v b
        //         = (s² - |b|²) v + 2s (v × b) + 2 (b·v) b,
        // and with s² + |b|² = 1 that is v + s t + t × b where t = 2 (v × b)
        // (t × b = 2 b × (b × v) = 2 (b·v) b - 2 |b|² v). 15 multiplies, as a quaternion.
        let (bx, by, bz) = (self.e23, self.e31, self.e12);
        let tx = T::TWO * (v.e2 * bz - v.e3 * by);
        let ty = T::TWO * (v.e3 * bx - v.e1 * bz);
        let tz = T::TWO * (v.e1 * by - v.e2 * bx);
        Vector::new(
            v.e1 + self.s * tx + (ty * bz - tz * by),
            v.e2 + self.s * ty + (tz * bx - tx * bz),
            v.e3 + self.s * tz + (tx * by - ty * bx),
        )
    }

    /// Rotates the bivector `b`: `R B R̃` for a unit rotor.
    ///
    /// Rotations commute with `I`, so this rotates the normal `B*` and dualises back.
    #[must_use]
    #[inline]
    pub fn rotate_bivector(self, b: Bivector<T>) -> Bivector<T> {
        self.rotate(b.dual()).undual()
    }

    /// Rotates the point `p` about the point `center`: `c + R (p - c) R̃`.
    #[must_use]
    #[inline]
    pub fn rotate_about(self, p: Vector<T>, center: Vector<T>) -> Vector<T> {
        center + self.rotate(p - center)
    }

    /// `|R|² = R R̃ = s² + |B|²` (1 for a rotation).
    #[must_use]
    #[inline]
    pub fn norm_squared(self) -> T {
        self.s * self.s + self.e12 * self.e12 + self.e23 * self.e23 + self.e31 * self.e31
    }

    /// `|R|`.
    #[must_use]
    #[inline]
    pub fn norm(self) -> T {
        self.norm_squared().sqrt()
    }

    /// `R / |R|`. Zero gives NaN components; see [`Rotor::try_normalize`].
    #[must_use]
    #[inline]
    pub fn normalize(self) -> Self {
        self * self.norm().recip()
    }

    /// `R / |R|`, or `None` when `|R|` is zero or the result is not finite.
    #[must_use]
    #[inline]
    pub fn try_normalize(self) -> Option<Self> {
        let r = self.norm().recip();
        (r.is_finite() && r > T::ZERO).then(|| self * r)
    }

    /// The reverse `R̃ = s - B`, which is the inverse of a unit rotor.
    #[must_use]
    #[inline]
    pub fn reverse(self) -> Self {
        Self::from_array(T::rotor_reverse(self.to_array()))
    }

    /// The Clifford conjugate, equal to the reverse for even elements.
    #[must_use]
    #[inline]
    pub fn conjugate(self) -> Self {
        self.reverse()
    }

    /// The grade involution, the identity on even elements.
    #[must_use]
    #[inline]
    pub fn grade_involution(self) -> Self {
        self
    }

    /// `R⁻¹ = R̃ / (R R̃)` (`R R̃ = s² + |B|²` is a scalar for every even element of G3), or
    /// `None` when `|R|²` is zero or not finite. For a unit rotor this is the
    /// [reverse](Rotor::reverse), which is what glam's `Quat::inverse` computes (it assumes a unit
    /// quaternion); call `reverse` when the rotor is known to be unit.
    #[must_use]
    #[inline]
    pub fn inverse(self) -> Option<Self> {
        // Finite whenever 0 < |R|² < ∞, as for `Vector::inverse`.
        let n2 = self.norm_squared();
        (n2 > T::ZERO && n2 < T::INFINITY).then_some(self.reverse() / n2)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::g3::Multivector;
    use core::f64::consts::{FRAC_PI_2, PI};
    // `abs` on a value whose float type is inferred later needs the trait that has it in scope.
    use crate::Real as _;

    type V = Vector<f64>;

    /// The general sandwich `R v R̃` with two geometric products, as an independent check.
    fn sandwich(r: Rotor<f64>, v: V) -> V {
        let m = Multivector::from(r) * Multivector::from(v) * Multivector::from(r.reverse());
        // Only rounding may leave a trivector part.
        assert!(m.e123().abs() < 1e-14, "{m}");
        m.vector_part()
    }

    #[test]
    fn quarter_turns_follow_the_convention() {
        let tol = 1e-15;
        let r = Rotor::from_angle_plane(FRAC_PI_2, Bivector::E12);
        assert!(r.rotate(V::E1).abs_diff_eq(V::E2, tol));
        assert!(r.rotate(V::E2).abs_diff_eq(-V::E1, tol));
        assert!(r.rotate(V::E3).abs_diff_eq(V::E3, tol));
        let r = Rotor::from_angle_plane(FRAC_PI_2, Bivector::E23);
        assert!(r.rotate(V::E2).abs_diff_eq(V::E3, tol));
        let r = Rotor::from_angle_plane(FRAC_PI_2, Bivector::E31 * 5.0);
        assert!(r.rotate(V::E3).abs_diff_eq(V::E1, tol));
        // R = exp(-B θ/2).
        let b = Bivector::new(0.2, -0.3, 0.9).normalize();
        assert!(Rotor::from_angle_plane(0.8, b).abs_diff_eq((b * -0.4).exp(), tol));
    }

    #[test]
    fn rotate_is_the_sandwich() {
        let r = Rotor::new(0.3, -0.5, 0.2, 0.7).normalize();
        for v in [V::E1, V::E2, V::E3, V::new(1.5, -2.0, 0.25)] {
            assert!(r.rotate(v).abs_diff_eq(sandwich(r, v), 1e-14));
        }
        let b = Bivector::new(1.0, 2.0, -3.0);
        let m = Multivector::from(r) * Multivector::from(b) * Multivector::from(r.reverse());
        assert!(Multivector::from(r.rotate_bivector(b)).abs_diff_eq(m, 1e-14));
        // Rotation about a point fixes that point.
        let c = V::new(1.0, 1.0, 0.0);
        assert!(r.rotate_about(c, c).abs_diff_eq(c, 1e-15));
        let quarter = Rotor::from_angle_plane(FRAC_PI_2, Bivector::E12);
        assert!(
            quarter
                .rotate_about(V::new(2.0, 1.0, 0.0), c)
                .abs_diff_eq(V::new(1.0, 2.0, 0.0), 1e-15)
        );
    }

    #[test]
    fn composition_applies_the_right_factor_first() {
        let r1 = Rotor::from_angle_plane(FRAC_PI_2, Bivector::E12); // e1 -> e2
        let r2 = Rotor::from_angle_plane(FRAC_PI_2, Bivector::E23); // e2 -> e3
        assert!((r2 * r1).rotate(V::E1).abs_diff_eq(V::E3, 1e-15));
        let mut r = r2;
        r *= r1;
        assert_eq!(r, r2 * r1);
        assert!((r * r.inverse().unwrap()).abs_diff_eq(Rotor::IDENTITY, 1e-15));
    }

    #[test]
    fn from_vectors_handles_zero_and_straight_angles() {
        let tol = 1e-14;
        let pairs = [
            (V::new(1.0, 2.0, 3.0), V::new(-2.0, 0.5, 1.0)),
            (V::new(1.0, 2.0, 3.0), V::new(2.0, 4.0, 6.0)), // 0°
            (V::new(1.0, 2.0, 3.0), V::new(-1.0, -2.0, -3.0)), // 180°
            (V::E1, -V::E1 * 3.0),                          // 180° along an axis
            (V::new(0.0, 0.0, 2.0), V::new(0.0, 0.0, -1.0)),
            (V::E1, V::new(-1.0, 1e-9, 0.0)), // nearly opposite
        ];
        for (a, b) in pairs {
            let r = Rotor::from_vectors(a, b);
            assert!((r.norm() - 1.0).abs() < tol, "{a} -> {b}: |R| = {}", r.norm());
            let got = r.rotate(a.normalize());
            assert!(got.abs_diff_eq(b.normalize(), tol), "{a} -> {b}: got {got}");
        }
        assert_eq!(Rotor::from_vectors(V::E1, V::E1 * 2.0), Rotor::IDENTITY);
        // The smallest rotation: e1 -> e2 is the quarter turn in e12, nothing else.
        let r = Rotor::from_vectors(V::E1, V::E2);
        assert!(r.abs_diff_eq(Rotor::from_angle_plane(FRAC_PI_2, Bivector::E12), tol));
    }

    #[test]
    fn exp_and_log_are_inverse() {
        for b in [
            Bivector::new(0.1, 0.2, -0.3),
            Bivector::new(1.0, 0.0, 0.0),
            Bivector::new(0.0, -1.5, 1.0),
            Bivector::new(1e-12, 0.0, 0.0),
            Bivector::ZERO,
        ] {
            let r = b.exp();
            assert!((r.norm() - 1.0).abs() < 1e-15);
            assert!(r.log().abs_diff_eq(b, 1e-15), "{b}: {}", r.log());
        }
        // The half angle of a rotation by θ is the norm of its log.
        let r = Rotor::from_angle_plane(2.5, Bivector::new(1.0, 1.0, 0.0));
        assert!((r.log().norm() - 1.25).abs() < 1e-15);
        // A full turn: -1.
        assert!((-Rotor::<f64>::IDENTITY).log().exp().abs_diff_eq(-Rotor::IDENTITY, 1e-15));
        assert_eq!(Rotor::<f64>::IDENTITY.log(), Bivector::ZERO);
        assert!((Bivector::E12 * PI).exp().abs_diff_eq(-Rotor::IDENTITY, 1e-15));
    }

    #[test]
    fn slerp_moves_at_constant_angle_on_the_short_arc() {
        let p = Bivector::new(0.3, 0.4, -0.2).normalize();
        let r0 = Rotor::from_angle_plane(0.2, p);
        let r1 = Rotor::from_angle_plane(1.4, p);
        for (t, angle) in [(0.0, 0.2), (0.25, 0.5), (0.5, 0.8), (1.0, 1.4)] {
            let want = Rotor::from_angle_plane(angle, p);
            assert!(r0.slerp(r1, t).abs_diff_eq(want, 1e-14), "t = {t}");
        }
        // -r1 is the same rotation: the path is the same.
        assert!(r0.slerp(-r1, 0.5).abs_diff_eq(Rotor::from_angle_plane(0.8, p), 1e-14));
    }
}
