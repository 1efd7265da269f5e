//! Shared by the integration tests: an independent `f64` reference solver, random scenes with
//! fixed seeds, and a macro that runs one generic test on every kernel and precision.

#![allow(dead_code)] // Each test file uses a different part of this module.

use intersect::{Ray, Real, Triangle};
use rand::{Rng, SeedableRng};
use rand_pcg::Pcg64;

/// Runs `$check::<K>()` for both kernels in both precisions.
#[macro_export]
macro_rules! for_each_kernel {
    ($check:ident) => {
        $check::<la_tracer::Watertight<f32>>();
        $check::<la_tracer::Watertight<f64>>();
        $check::<la_tracer::MollerTrumbore<f32>>();
        $check::<la_tracer::MollerTrumbore<f64>>();
    };
}

pub use intersect::conformance::label;

/// Relative precision the tests expect of a kernel in precision `T`: `1e-5` for `f32`,
/// `1e-12` for `f64` (about 100 and 4500 ulps: room for the conditioning of random
/// well-shaped cases, far below any real error).
pub fn tolerance<T: Real>() -> f64 {
    if T::MANTISSA_DIGITS == f32::MANTISSA_DIGITS { 1e-5 } else { 1e-12 }
}

/// A fixed-seed generator.
pub fn rng(seed: u64) -> Pcg64 {
    Pcg64::seed_from_u64(seed)
}

/// The intersection of a ray's line with a triangle's plane, solved independently of the
/// kernels: Cramer's rule on `o + t d = a + u (b - a) + v (c - a)` with explicit 3x3
/// determinants (cofactor expansion), in `f64`.
#[derive(Clone, Copy, Debug)]
pub struct PlaneHit {
    /// Ray parameter.
    pub t: f64,
    /// Weight of `b`.
    pub u: f64,
    /// Weight of `c`.
    pub v: f64,
    /// `|cos|` of the angle between the ray and the plane's normal: small means grazing.
    pub cos: f64,
}

impl PlaneHit {
    /// Signed distance, in barycentric units, to the nearest edge: positive inside.
    pub fn margin(&self) -> f64 {
        self.u.min(self.v).min(1.0 - self.u - self.v)
    }

    /// Whether the exact answer is a hit within `(0, t_max]`, closed edges.
    pub fn is_hit(&self, t_max: f64) -> bool {
        self.t > 0.0 && self.t <= t_max && self.margin() >= 0.0
    }
}

fn sub(p: [f64; 3], q: [f64; 3]) -> [f64; 3] {
    [p[0] - q[0], p[1] - q[1], p[2] - q[2]]
}

/// `det [x y z]` with `x, y, z` as columns, by cofactor expansion along the first row.
fn det3(x: [f64; 3], y: [f64; 3], z: [f64; 3]) -> f64 {
    x[0] * (y[1] * z[2] - y[2] * z[1]) - y[0] * (x[1] * z[2] - x[2] * z[1])
        + z[0] * (x[1] * y[2] - x[2] * y[1])
}

fn norm(p: [f64; 3]) -> f64 {
    (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt()
}

fn cross(p: [f64; 3], q: [f64; 3]) -> [f64; 3] {
    [p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]]
}

/// The reference for a triangle and ray of any precision (converted to `f64` exactly);
/// `None` if the ray is parallel to the plane or the triangle is degenerate.
pub fn reference<T: Real>(tri: &Triangle<T>, ray: &Ray<T>) -> Option<PlaneHit> {
    let (tri, ray): (Triangle<f64>, Ray<f64>) = (tri.cast(), ray.cast());
    let (e1, e2, s) = (sub(tri.b, tri.a), sub(tri.c, tri.a), sub(ray.origin, tri.a));
    let minus_d = ray.dir.map(|x| -x);
    let det = det3(minus_d, e1, e2);
    if det == 0.0 || !det.is_finite() {
        return None;
    }
    Some(PlaneHit {
        t: det3(s, e1, e2) / det,
        u: det3(minus_d, s, e2) / det,
        v: det3(minus_d, e1, s) / det,
        cos: det.abs() / (norm(ray.dir) * norm(cross(e1, e2))),
    })
}

/// A point uniform in the cube `[-r, r]^3`.
pub fn point(rng: &mut Pcg64, r: f64) -> [f64; 3] {
    [0; 3].map(|_| rng.random_range(-r..=r))
}

/// A random triangle in `[-1, 1]^3`.
pub fn triangle(rng: &mut Pcg64) -> Triangle<f64> {
    Triangle::new(point(rng, 1.0), point(rng, 1.0), point(rng, 1.0))
}

/// A ray from a random origin in `[-3, 3]^3` towards the point of `tri`'s plane with
/// barycentrics `(u, v)` drawn from `[-0.1, 1.0]` (about 40% hit), with a direction of
/// random length. One ray in four has an axis-aligned direction or one with a zero component
/// instead (then its aim is only approximate).
pub fn ray_towards(rng: &mut Pcg64, tri: &Triangle<f64>) -> Ray<f64> {
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

/// Next representable value towards minus infinity, for positive finite `x`.
pub fn prev_down<T: Real>(x: T) -> T {
    if T::MANTISSA_DIGITS == f32::MANTISSA_DIGITS {
        let x = x.to_f64() as f32;
        T::from_f64(f32::from_bits(x.to_bits() - 1) as f64)
    } else {
        T::from_f64(f64::from_bits(x.to_f64().to_bits() - 1))
    }
}
