//! The independent `f64` reference solver, the tolerances the checks hold kernels to, and the
//! fixed-seed generators of triangles and rays.

use rand::{Rng, SeedableRng};
use rand_pcg::Pcg64;

use crate::vec3::{cross, length, sub};
use crate::{Ray, Real, Triangle};

/// The intersection of a ray's line with a triangle's plane, solved independently of every
/// kernel: Cramer's rule on `o + t d = a + u (b - a) + v (c - a)`, i.e.
/// `[-d, b - a, c - a] (t, u, v) = o - a`, with 3x3 determinants by cofactor expansion, in
/// `f64`.
#[derive(Clone, Copy, Debug)]
pub struct Reference {
    /// Ray parameter.
    pub t: f64,
    /// Weight of `b`.
    pub u: f64,
    /// Weight of `c`.
    pub v: f64,
    /// `|cos|` of the angle between the ray and the plane's normal: small means grazing.
    pub cos: f64,
}

impl Reference {
    /// The smallest barycentric weight: negative outside, its magnitude the distance to the
    /// nearest edge line in barycentric units.
    #[must_use]
    pub fn margin(&self) -> f64 {
        self.u.min(self.v).min(1.0 - self.u - self.v)
    }

    /// Whether the exact answer is a hit within `(0, t_max]` (closed edges).
    #[must_use]
    pub fn is_hit(&self, t_max: f64) -> bool {
        self.t > 0.0 && self.t <= t_max && self.margin() >= 0.0
    }
}

/// `det [x y z]` (columns), by cofactor expansion along the first row.
fn det3(x: [f64; 3], y: [f64; 3], z: [f64; 3]) -> f64 {
    x[0] * (y[1] * z[2] - y[2] * z[1]) - y[0] * (x[1] * z[2] - x[2] * z[1])
        + z[0] * (x[1] * y[2] - x[2] * y[1])
}

/// The reference for a triangle and ray of either precision (converted to `f64` exactly);
/// `None` if the ray is parallel to the plane or the triangle is degenerate.
#[must_use]
pub fn reference<T: Real>(tri: &Triangle<T>, ray: &Ray<T>) -> Option<Reference> {
    let (tri, ray): (Triangle<f64>, Ray<f64>) = (tri.cast(), ray.cast());
    let (e1, e2, s) = (sub(tri.b, tri.a), sub(tri.c, tri.a), sub(ray.origin, tri.a));
    let minus_d = ray.dir.map(|x| -x);
    let det = det3(minus_d, e1, e2);
    if det == 0.0 || !det.is_finite() {
        return None;
    }
    Some(Reference {
        t: det3(s, e1, e2) / det,
        u: det3(minus_d, s, e2) / det,
        v: det3(minus_d, e1, s) / det,
        cos: det.abs() / (length(ray.dir) * length(cross(e1, e2))),
    })
}

/// Whether `T` is `f32`.
#[must_use]
pub fn is_f32<T: Real>() -> bool {
    T::MANTISSA_DIGITS == f32::MANTISSA_DIGITS
}

/// Relative precision expected of `t` in precision `T` for well-conditioned cases: `1e-5`
/// for `f32`, `1e-12` for `f64` (about 80 and 4500 ulps: room for the conditioning of random
/// well-shaped cases, far below any real error).
#[must_use]
pub fn tolerance<T: Real>() -> f64 {
    if is_f32::<T>() { 1e-5 } else { 1e-12 }
}

/// A fixed-seed generator.
#[must_use]
pub fn rng(seed: u64) -> Pcg64 {
    Pcg64::seed_from_u64(seed)
}

/// A point uniform in the cube `[-r, r]^3` around `centre`.
pub fn point_near(rng: &mut Pcg64, centre: [f64; 3], r: f64) -> [f64; 3] {
    centre.map(|c| c + rng.random_range(-r..=r))
}

/// A point uniform in the cube `[-r, r]^3`.
pub fn point(rng: &mut Pcg64, r: f64) -> [f64; 3] {
    point_near(rng, [0.0; 3], r)
}

/// A random triangle in `[-1, 1]^3`.
pub fn triangle(rng: &mut Pcg64) -> Triangle<f64> {
    Triangle::new(point(rng, 1.0), point(rng, 1.0), point(rng, 1.0))
}

/// A ray from a random origin in `[-3, 3]^3` towards a point of `tri`'s plane, with a
/// direction of random length (a power of two from 1/16 to 16, so the aim is kept exactly).
/// Half of the targets have barycentrics drawn from `[-0.2, 1.0]` (about half of those hit);
/// the other half lie within `10^-k` (`k` uniform in `[2, 15)`) of a random edge, on either
/// side.
pub fn ray_towards(rng: &mut Pcg64, tri: &Triangle<f64>) -> Ray<f64> {
    let (u, v) = if rng.random_bool(0.5) {
        (rng.random_range(-0.2..1.0), rng.random_range(-0.2..1.0))
    } else {
        let along = rng.random_range(0.0..=1.0);
        let off = 10f64.powf(-rng.random_range(2.0..15.0))
            * if rng.random_bool(0.5) { 1.0 } else { -1.0 };
        match rng.random_range(0..3) {
            0 => (off, along), // near the edge u = 0 (from a to c)
            1 => (along, off), // near v = 0 (from a to b)
            _ => (along - off / 2.0, 1.0 - along - off / 2.0), // near u + v = 1
        }
    };
    let target = tri.point(u, v);
    let origin = point(rng, 3.0);
    let scale = 2f64.powi(rng.random_range(-4..=4));
    Ray::new(origin, sub(target, origin).map(|x| x * scale))
}

/// A ray from a random origin in `[-3, 3]^3` towards the point of `tri`'s plane with
/// barycentrics `(u, v)` drawn from `[-0.1, 1.0]` (about 40% hit), with a direction of
/// random length. One ray in four has an axis-aligned direction or one with a zero component
/// instead (then its aim is only approximate): the zeros kernels divide by or pick an axis by.
pub fn ray_with_zero_components(rng: &mut Pcg64, tri: &Triangle<f64>) -> Ray<f64> {
    let (u, v) = (rng.random_range(-0.1..1.0), rng.random_range(-0.1..1.0));
    let target = tri.point(u, v);
    let origin = point(rng, 3.0);
    let scale = 2f64.powi(rng.random_range(-4..=4));
    let mut dir = sub(target, origin).map(|x| x * scale);
    if rng.random_bool(0.25) {
        // Zero one or two components (keep the largest so the ray still goes somewhere).
        let big = (0..3).max_by(|&i, &j| dir[i].abs().total_cmp(&dir[j].abs())).unwrap_or(0);
        for (k, x) in dir.iter_mut().enumerate() {
            if k != big && rng.random_bool(0.6) {
                *x = 0.0;
            }
        }
    }
    Ray::new(origin, dir)
}

/// The next representable value below a positive finite `x`.
#[must_use]
pub fn prev_down<T: Real>(x: T) -> T {
    if is_f32::<T>() {
        T::from_f64(f64::from((x.to_f64() as f32).next_down()))
    } else {
        T::from_f64(x.to_f64().next_down())
    }
}

/// The triangle with each vertex converted to `T`.
#[must_use]
pub fn cast_tri<T: Real>(a: [f64; 3], b: [f64; 3], c: [f64; 3]) -> Triangle<T> {
    Triangle::new(a, b, c).cast()
}

/// The ray with origin and direction converted to `T`.
#[must_use]
pub fn cast_ray<T: Real>(origin: [f64; 3], dir: [f64; 3]) -> Ray<T> {
    Ray::new(origin, dir).cast()
}
