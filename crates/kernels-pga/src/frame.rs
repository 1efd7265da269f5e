//! The frame method in PGA: the frame/PGA cell (`pga-frame`), the twin of `la-frame`
//! (`kernels_la::Frame`) and `g3-frame`, with the plane and the reciprocal frame as planes.
//!
//! # The method (Havel and Herout 2010; Baldwin and Weber 2016)
//!
//! `la-frame` precomputes, with `e1 = b - a`, `e2 = c - a`, `N = e1 × e2`, the unit normal
//! `n = N / |N|` and the reciprocal frame `m_b = (e2 × N) / |N|²`, `m_c = (N × e1) / |N|²`, so
//! that for a point `p` of the plane `(p - a) · m_b` and `(p - a) · m_c` are its barycentric
//! weights of `b` and `c`. In R(3,0,1) an affine function of the point is a plane: seen from
//! `a` (the frame whose origin is `a`, as `la-frame` measures from it), three planes through
//! that origin
//!
//! ```text
//! π  = n1 e1 + n2 e2 + n3 e3          the triangle's plane, unit normal
//! πb = m_b1 e1 + m_b2 e2 + m_b3 e3     λb(x) = (πb ^ X) / w   (the e0123 coefficient)
//! πc = m_c1 e1 + m_c2 e2 + m_c3 e3     λc(x) = (πc ^ X) / w
//! ```
//!
//! since `πb ^ X = (m_b · x_h + e0 w) e0123` for the point `X` of weight `w` and homogeneous
//! coordinates `x_h` ([`Plane ^ Point`](ga::pga::Plane)), and the `e0` offsets are 0 in this
//! frame. Computed in `f64` from the vertices (as `la-frame`, `g3-frame` and `ga`) and rounded
//! once. (Planes with their offsets from the world origin, `e0 = -m_b · a`, would spare the
//! vertex but lose the digits of the distance from the world origin in every product; the
//! conformance kit's translation sweep rejects that form.)
//!
//! Per test, the ray's origin seen from `a`, `O' = O - A + E123` (the point at `o - a`), its
//! line `L = O' & D` meets the plane in the homogeneous point `X = L ^ π`, of weight
//! `den = n · d` ([`Line::meet_plane`](ga::pga::Line::meet_plane)); `t` is read from the
//! plane, `num = -(π & O') = (a - o) · n` (`la-frame`'s `num`). The undivided barycentric
//! values are then one outer product each:
//!
//! ```text
//! U = (πb ^ X) e0123 = den λb        V = (πc ^ X) e0123 = den λc
//! ```
//!
//! Expanding the meet, `x_h = (o - a) den - d (n · (o - a))`, so `U = num (d · m_b) -
//! den (s · m_b)` with `s = a - o`: `la-frame`'s `U`, term for term, and the decisions below
//! see the same four values up to rounding.
//!
//! # Decisions, in `la-frame`'s (and `ga`'s) order
//!
//! With `σ` the sign of `den`: the three edges as one branch,
//! `min(σU, σV, |den| - σ(U + V)) >= 0` (closed edges, no tie rule, not watertight; NaN is
//! rejected), then the distance `0 < σ num <= t_max |den| (1 + 4 ε)`, then one division and
//! `0 < t <= t_max`, `t` finite, on the divided `t`.
//!
//! # Per-triangle data, cost
//!
//! - Per triangle: the point `A` and three [`Plane`]s, 16 numbers: 64 B in `f32`, 128 B in
//!   `f64` (`la-frame` stores `a`, `n`, `m_b`, `m_c` in 64 B and 96 B: the point's weight and
//!   the planes' zero offsets are the 4 numbers the algebra's types carry more). A degenerate
//!   triangle (decided exactly) gets zero planes, which no ray hits.
//! - Per ray: nothing.
//! - Per test, as the generated products are written: the origin seen from `a` (8
//!   additions), the ray's line `Point & Point` (12 multiplies, 6 subtractions), the meet `Line ^
//!   Plane` (12 multiplies, 8 additions), 2 `Plane ^ Point` (4 multiplies, 3 additions each) and a
//!   `Plane & Point` (the same) for `num`: 36 multiplies and 31 additions where `la-frame` has 6
//!   dot products, 4 multiplies and 2 subtractions (22 multiplies, 14 additions); then the same
//!   edge and distance tests and one division, for hits only. The extra terms are the line's
//!   moment `(o - a) × d` and the meet's homogeneous point, which `la-frame` never forms.

use core::marker::PhantomData;

use ga::Scalar;
use ga::pga::{Plane, Point};
use intersect::{Algebra, Guarantees, Intersector, Method, Ray, Real, Triangle, TriangleHit};

use kernels_g3::frame::{decide, hit, occluded};

use crate::{direction, is_degenerate, plane_through, point, round_plane, seen_from};

/// The frame method in PGA (`NAME = "pga-frame"`): the triangle's plane and its two
/// barycentric planes precomputed, one outer product per barycentric.
///
/// See the [module documentation](self).
///
/// ```
/// use intersect::{Intersector, Ray, Triangle};
/// use kernels_pga::PgaFrame;
///
/// let k = PgaFrame::<f32>::new();
/// let prim = k.prepare(&Triangle::new([0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [0.0, 2.0, 0.0]));
/// let ray = Ray::new([0.5, 1.0, 3.0], [0.0, 0.0, -1.0]);
/// let hit = k.intersect(&prim, &ray, &(), f32::INFINITY).unwrap();
/// assert_eq!((hit.t, hit.u, hit.v), (3.0, 0.25, 0.5));
/// assert!(k.intersect(&prim, &ray, &(), 2.5).is_none());
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct PgaFrame<T>(PhantomData<T>);

impl<T> PgaFrame<T> {
    /// The kernel (it has no state).
    #[must_use]
    pub const fn new() -> Self {
        Self(PhantomData)
    }
}

/// What [`PgaFrame`] keeps of a triangle: the point `A`, and seen from it the plane with a
/// unit normal and the barycentric planes of `b` and `c`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PgaFramePrim<T> {
    a: Point<T>,
    plane: Plane<T>,
    b: Plane<T>,
    c: Plane<T>,
}

impl<T: Scalar> PgaFramePrim<T> {
    fn new(tri: &Triangle<T>) -> Self {
        let a = point(tri.a);
        if is_degenerate(tri) {
            return Self { a, ..Self::default() };
        }
        let [a64, b64, c64] = tri.vertices().map(|p| p.map(Real::to_f64));
        // The join's normal is N = (b - a) × (c - a); the reciprocal frame from it.
        let n = plane_through(point(a64), point(b64), point(c64)).normal();
        let n2 = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
        let (e1, e2) = (sub(b64, a64), sub(c64, a64));
        let through_a = |v: [f64; 3], scale: f64| {
            round_plane(Plane::from_normal_offset(v.map(|x| x * scale), 0.0))
        };
        Self {
            a,
            plane: through_a(n, n2.sqrt().recip()),
            b: through_a(cross(e2, n), n2.recip()),
            c: through_a(cross(n, e1), n2.recip()),
        }
    }
}

/// `p - q` (per-triangle precomputation only, in `f64`).
fn sub(p: [f64; 3], q: [f64; 3]) -> [f64; 3] {
    [p[0] - q[0], p[1] - q[1], p[2] - q[2]]
}

/// `p × q` (per-triangle precomputation only, in `f64`).
fn cross(p: [f64; 3], q: [f64; 3]) -> [f64; 3] {
    [p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]]
}

impl<T: Scalar> Intersector for PgaFrame<T> {
    type Real = T;
    type Prim = PgaFramePrim<T>;
    type RayData = ();
    type Block = ();
    const NAME: &'static str = "pga-frame";
    const ALGEBRA: Algebra = Algebra::Pga;
    const METHOD: Method = Method::Frame;
    const GUARANTEES: Guarantees = Guarantees { watertight: false, exact: false };
    const VARIANT: Option<&'static str> = None;

    fn prepare(&self, tri: &Triangle<T>) -> PgaFramePrim<T> {
        PgaFramePrim::new(tri)
    }

    #[inline(always)]
    fn prepare_ray(&self, _ray: &Ray<T>) {}

    #[inline(always)]
    fn intersect(
        &self,
        prim: &PgaFramePrim<T>,
        ray: &Ray<T>,
        _: &(),
        t_max: T,
    ) -> Option<TriangleHit<T>> {
        hit(decide(undivided(prim, ray), t_max)?, t_max)
    }

    #[inline(always)]
    fn occludes(&self, prim: &PgaFramePrim<T>, ray: &Ray<T>, _: &(), t_max: T) -> bool {
        decide(undivided(prim, ray), t_max).is_some_and(|c| occluded(&c, t_max))
    }
}

/// The undivided `[num, den, U, V]` of the derivation, from the planes; the decisions on them
/// (the edges as one branch, then `0 < t <= t_max` before the division, loosened by 4 ulps
/// of 1) are `la-frame`'s and `g3-frame`'s, in the shared [`kernels_g3::frame::decide`].
#[inline(always)]
fn undivided<T: Scalar>(prim: &PgaFramePrim<T>, ray: &Ray<T>) -> [T; 4] {
    let PgaFramePrim { a, plane, b, c } = *prim;
    let o = seen_from(point(ray.origin), a);
    let x = (o & direction(ray.dir)) ^ plane;
    let (num, den) = (-(plane & o), x.weight());
    [num, den, (b ^ x).e0123, (c ^ x).e0123]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn prim_holds_the_barycentric_planes() {
        // e1 = (2, 0, 0), e2 = (1, 4, 0): N = (0, 0, 8), m_b = (1/2, -1/8, 0), m_c = (0, 1/4, 0);
        // seen from a, each plane vanishes at a and gives 1 at its own vertex.
        let tri = Triangle::new([1.0, 1.0, 1.0], [3.0, 1.0, 1.0], [2.0, 5.0, 1.0]);
        let prim = PgaFramePrim::<f64>::new(&tri);
        assert_eq!(prim.plane, Plane::new(0.0, 0.0, 0.0, 1.0));
        assert_eq!(prim.b, Plane::new(0.0, 0.5, -0.125, 0.0));
        assert_eq!(prim.c, Plane::new(0.0, 0.0, 0.25, 0.0));
        let [pa, pb, pc] = tri.vertices().map(|v| seen_from(point(v), prim.a));
        assert_eq!([prim.b & pa, prim.b & pb, prim.b & pc], [0.0, 1.0, 0.0]);
        assert_eq!([prim.c & pa, prim.c & pb, prim.c & pc], [0.0, 0.0, 1.0]);
        let flat = Triangle::new([1.0f32, 2.0, 3.0], [2.0, 4.0, 6.0], [3.0, 6.0, 9.0]);
        let prim = PgaFramePrim::<f32>::new(&flat);
        assert_eq!([prim.plane, prim.b, prim.c], [Plane::ZERO; 3]);
    }
}
