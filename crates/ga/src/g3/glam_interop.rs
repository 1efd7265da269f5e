//! Conversions to and from glam (feature `glam`).
//!
//! Vectors map component-wise (`e1, e2, e3` ↔ `x, y, z`). A rotor and a quaternion describing
//! the same rotation correspond by
//!
//! ```text
//! w = s,   x = -e23,   y = -e31,   z = -e12
//! ```
//!
//! because the quaternion units are `i = -e23`, `j = -e31`, `k = -e12` (check: `i j =
//! e23 e31 = -e12 = k`), and the rotor about the unit axis `n` by `θ` is `cos(θ/2) - (n I)
//! sin(θ/2)` with `n I = n1 e23 + n2 e31 + n3 e12`, while glam's quaternion is `cos(θ/2) +
//! (n1 i + n2 j + n3 k) sin(θ/2)`. Both rotate right-handedly about `n` (`e1` toward `e2` about
//! `e3`), so `Rotor::rotate` and `Quat * Vec3` agree.

use glam::{DQuat, DVec3, Quat, Vec3, Vec3A};

use crate::g3::{Rotor, Vector};

impl From<Vec3> for Vector<f32> {
    #[inline]
    fn from(v: Vec3) -> Self {
        Self::new(v.x, v.y, v.z)
    }
}

impl From<Vector<f32>> for Vec3 {
    #[inline]
    fn from(v: Vector<f32>) -> Self {
        Vec3::new(v.e1, v.e2, v.e3)
    }
}

impl From<Vec3A> for Vector<f32> {
    #[inline]
    fn from(v: Vec3A) -> Self {
        Self::new(v.x, v.y, v.z)
    }
}

impl From<Vector<f32>> for Vec3A {
    #[inline]
    fn from(v: Vector<f32>) -> Self {
        Vec3A::new(v.e1, v.e2, v.e3)
    }
}

impl From<DVec3> for Vector<f64> {
    #[inline]
    fn from(v: DVec3) -> Self {
        Self::new(v.x, v.y, v.z)
    }
}

impl From<Vector<f64>> for DVec3 {
    #[inline]
    fn from(v: Vector<f64>) -> Self {
        DVec3::new(v.e1, v.e2, v.e3)
    }
}

/// The same rotation: `s = w`, `(e23, e31, e12) = -(x, y, z)` (see the crate docs).
impl From<Quat> for Rotor<f32> {
    #[inline]
    fn from(q: Quat) -> Self {
        Self::new(q.w, -q.z, -q.x, -q.y)
    }
}

/// The same rotation: `w = s`, `(x, y, z) = -(e23, e31, e12)` (see the crate docs).
impl From<Rotor<f32>> for Quat {
    #[inline]
    fn from(r: Rotor<f32>) -> Self {
        Quat::from_xyzw(-r.e23, -r.e31, -r.e12, r.s)
    }
}

/// The same rotation: `s = w`, `(e23, e31, e12) = -(x, y, z)` (see the crate docs).
impl From<DQuat> for Rotor<f64> {
    #[inline]
    fn from(q: DQuat) -> Self {
        Self::new(q.w, -q.z, -q.x, -q.y)
    }
}

/// The same rotation: `w = s`, `(x, y, z) = -(e23, e31, e12)` (see the crate docs).
impl From<Rotor<f64>> for DQuat {
    #[inline]
    fn from(r: Rotor<f64>) -> Self {
        DQuat::from_xyzw(-r.e23, -r.e31, -r.e12, r.s)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::g3::Bivector;

    #[test]
    fn rotating_agrees_with_glam_f64() {
        let axis = DVec3::new(0.3, -0.5, 0.8).normalize();
        let angle = 1.1;
        let q = DQuat::from_axis_angle(axis, angle);
        // The rotor in the plane whose normal is the axis: B = n I.
        let r = Rotor::from_angle_plane(angle, Vector::from(axis).undual());
        assert!(Rotor::from(q).abs_diff_eq(r, 1e-15));
        assert!(DQuat::from(r).abs_diff_eq(q, 1e-15));
        for v in [DVec3::X, DVec3::Y, DVec3::Z, DVec3::new(1.5, -2.0, 0.25)] {
            let expected = q * v;
            let got = DVec3::from(r.rotate(Vector::from(v)));
            assert!(got.abs_diff_eq(expected, 1e-14), "{got} vs {expected}");
        }
        // Composition agrees too: quaternion product and rotor product in the same order.
        let q2 = DQuat::from_axis_angle(DVec3::new(1.0, 2.0, 2.0).normalize(), -0.4);
        assert!(Rotor::from(q2 * q).abs_diff_eq(Rotor::from(q2) * r, 1e-15));
    }

    #[test]
    fn rotating_agrees_with_glam_f32() {
        let q = Quat::from_rotation_z(0.7);
        let r = Rotor::from_angle_plane(0.7_f32, Bivector::E12);
        assert!(Rotor::from(q).abs_diff_eq(r, 1e-7));
        let v = Vec3::new(0.2, 1.0, -3.0);
        assert!(Vec3::from(r.rotate(v.into())).abs_diff_eq(q * v, 1e-6));
        assert_eq!(
            Vector::from(Vec3A::from(Vector::new(1.0, 2.0, 3.0))),
            Vector::new(1.0, 2.0, 3.0)
        );
    }
}
