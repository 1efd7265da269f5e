//! Conversions to glam (feature `glam`).
//!
//! - A motor becomes the affine map it applies to points ([`Motor::to_matrix`]):
//!   `Motor<f32>` an `Affine3A`, `Motor<f64>` a `DAffine3`.
//! - A rotor and a quaternion of the same rotation correspond by `w = s`, `x = -e23`,
//!   `y = -e31`, `z = -e12`: the rotor about the unit axis `n` is
//!   `cos(θ/2) - sin(θ/2) (n1 e23 + n2 e31 + n3 e12)` (see [`Rotor::from_axis_angle`]) and
//!   glam's quaternion `cos(θ/2) + sin(θ/2) (n1 i + n2 j + n3 k)`, both right-handed.
//! - Glam vectors become Euclidean points of weight 1 ([`Point::from_xyz`]).

use glam::{Affine3A, DAffine3, DMat3, DQuat, DVec3, Mat3A, Quat, Vec3, Vec3A};

use crate::pga::{Motor, Point, Rotor};

impl From<Motor<f64>> for DAffine3 {
    fn from(m: Motor<f64>) -> Self {
        let r = m.to_matrix();
        let col = |j: usize| DVec3::new(r[0][j], r[1][j], r[2][j]);
        DAffine3 { matrix3: DMat3::from_cols(col(0), col(1), col(2)), translation: col(3) }
    }
}

impl From<Motor<f32>> for Affine3A {
    fn from(m: Motor<f32>) -> Self {
        let r = m.to_matrix();
        let col = |j: usize| Vec3A::new(r[0][j], r[1][j], r[2][j]);
        Affine3A { matrix3: Mat3A::from_cols(col(0), col(1), col(2)), translation: col(3) }
    }
}

impl From<DQuat> for Rotor<f64> {
    #[inline]
    fn from(q: DQuat) -> Self {
        Self::new(q.w, -q.z, -q.y, -q.x)
    }
}

impl From<Rotor<f64>> for DQuat {
    #[inline]
    fn from(r: Rotor<f64>) -> Self {
        DQuat::from_xyzw(-r.e23, -r.e31, -r.e12, r.s)
    }
}

impl From<Quat> for Rotor<f32> {
    #[inline]
    fn from(q: Quat) -> Self {
        Self::new(q.w, -q.z, -q.y, -q.x)
    }
}

impl From<Rotor<f32>> for Quat {
    #[inline]
    fn from(r: Rotor<f32>) -> Self {
        Quat::from_xyzw(-r.e23, -r.e31, -r.e12, r.s)
    }
}

impl From<DVec3> for Point<f64> {
    #[inline]
    fn from(v: DVec3) -> Self {
        Self::from_xyz(v.x, v.y, v.z)
    }
}

impl From<Vec3> for Point<f32> {
    #[inline]
    fn from(v: Vec3) -> Self {
        Self::from_xyz(v.x, v.y, v.z)
    }
}
