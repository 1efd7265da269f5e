//! Shared by the integration tests: an independent `f64` reference solver, random scenes with
//! fixed seeds, and a macro that runs one generic test on every kernel and precision.

#![allow(dead_code)] // Each test file uses a different part of this module.

use intersect::{Intersector, Ray, Real, Triangle, TriangleHit};
use rand::{Rng, SeedableRng};
use rand_pcg::Pcg64;

/// Runs `$check::<K>()` for every kernel of the crate in both precisions.
#[macro_export]
macro_rules! for_each_kernel {
    ($check:ident) => {
        $check::<ga_tracer::GaReport<f32>>();
        $check::<ga_tracer::GaReport<f64>>();
        $check::<ga_tracer::Ga<f32>>();
        $check::<ga_tracer::Ga<f64>>();
        $check::<ga_tracer::GaPlucker<f32>>();
        $check::<ga_tracer::GaPlucker<f64>>();
    };
}

pub use intersect::conformance::label;

/// Whether `T` is `f32`.
pub fn is_f32<T: Real>() -> bool {
    T::MANTISSA_DIGITS == f32::MANTISSA_DIGITS
}

/// Relative precision expected of `t` in precision `T` for well-conditioned cases: `1e-5`
/// for `f32`, `1e-12` for `f64` (about 80 and 4500 ulps).
pub fn tolerance<T: Real>() -> f64 {
    if is_f32::<T>() { 1e-5 } else { 1e-12 }
}

/// A fixed-seed generator.
pub fn rng(seed: u64) -> Pcg64 {
    Pcg64::seed_from_u64(seed)
}

/// The kernel's whole pipeline for one ray and triangle: `prepare`, `prepare_ray`,
/// `intersect`, checking on the way that `occludes` agrees and that a hit is in range and
/// finite.
pub fn run<I: Intersector>(
    k: &I,
    tri: &Triangle<I::Real>,
    ray: &Ray<I::Real>,
    t_max: I::Real,
) -> Option<TriangleHit<I::Real>> {
    let prim = k.prepare(tri);
    let rd = k.prepare_ray(ray);
    let got = k.intersect(&prim, ray, &rd, t_max);
    assert_eq!(k.occludes(&prim, ray, &rd, t_max), got.is_some(), "{}: occludes", label::<I>());
    if let Some(h) = got {
        assert!(
            h.t > I::Real::ZERO && h.t <= t_max,
            "{}: t = {} not in (0, {t_max}]",
            label::<I>(),
            h.t
        );
        assert!(
            h.t.is_finite() && h.u.is_finite() && h.v.is_finite(),
            "{}: {h:?} not finite",
            label::<I>()
        );
    }
    got
}

/// The intersection of a ray's line with a triangle's plane, solved independently of the
/// kernels: Cramer's rule on `o + t d = a + u (b - a) + v (c - a)`, i.e.
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
    pub fn margin(&self) -> f64 {
        self.u.min(self.v).min(1.0 - self.u - self.v)
    }

    /// Whether the exact answer is a hit within `(0, t_max]` (closed edges).
    pub fn is_hit(&self, t_max: f64) -> bool {
        self.t > 0.0 && self.t <= t_max && self.margin() >= 0.0
    }
}

pub fn sub(p: [f64; 3], q: [f64; 3]) -> [f64; 3] {
    [p[0] - q[0], p[1] - q[1], p[2] - q[2]]
}

/// `det [x y z]` (columns), by cofactor expansion along the first row.
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

/// The reference for a triangle and ray of either precision (converted to `f64` exactly);
/// `None` if the ray is parallel to the plane or the triangle is degenerate.
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
        cos: det.abs() / (norm(ray.dir) * norm(cross(e1, e2))),
    })
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

/// The next representable value below a positive finite `x`.
pub fn prev_down<T: Real>(x: T) -> T {
    if is_f32::<T>() {
        T::from_f64(f32::from_bits((x.to_f64() as f32).to_bits() - 1) as f64)
    } else {
        T::from_f64(f64::from_bits(x.to_f64().to_bits() - 1))
    }
}

/// The triangle `tri` with each vertex converted to `T`.
pub fn cast_tri<T: Real>(a: [f64; 3], b: [f64; 3], c: [f64; 3]) -> Triangle<T> {
    Triangle::new(a, b, c).cast()
}

/// The ray with origin and direction converted to `T`.
pub fn cast_ray<T: Real>(origin: [f64; 3], dir: [f64; 3]) -> Ray<T> {
    Ray::new(origin, dir).cast()
}
