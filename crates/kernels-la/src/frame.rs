//! The frame method in glam: the frame/LA cell (`la-frame`), the twin of `g3-frame` and of
//! its hand-SIMD variant `ga` (`kernels_g3::G3FrameCell`, `kernels_g3::G3Frame`).
//!
//! # The method (Havel and Herout 2010; Baldwin and Weber 2016)
//!
//! Per triangle, with `e1 = b - a`, `e2 = c - a` and `N = e1 x e2`: the vertex `a`, the unit
//! normal `n = N / |N|` and the reciprocal frame of the two edges in the plane,
//!
//! ```text
//! m_b = (e2 x N) / |N|²        m_c = (N x e1) / |N|²
//! ```
//!
//! so that `m_b . e1 = 1`, `m_b . e2 = 0`, `m_c . e1 = 0`, `m_c . e2 = 1` (expand
//! `(e2 x N) . e1 = N . (e1 x e2) = |N|²`) and both are orthogonal to `n`: for a point `p` of
//! the plane, `(p - a) . m_b` and `(p - a) . m_c` are its barycentric weights of `b` and `c`.
//! These are `ga`'s `m_b = N⁻¹ | (a - c)` and `m_c = N⁻¹ | (b - a)` for the bivector
//! `N = e1 ∧ e2`, whose dual is the cross product, and `ga`'s `n = N* / |N|`. Computed in
//! `f64` (glam `DVec3`) and rounded once, as `ga` computes them.
//!
//! Per test, with `s = a - o` and the ray direction `d`, on undivided values:
//!
//! ```text
//! num = s . n        den = d . n                  (t = num / den)
//! U = num (d . m_b) - den (s . m_b)               (u = U / den)
//! V = num (d . m_c) - den (s . m_c)               (v = V / den)
//! ```
//!
//! (`p - a = -s + (num / den) d`, so `(p - a) . m_b = U / den`.)
//!
//! # Decisions, in `ga`'s order
//!
//! With `σ` the sign of `den` (its sign bit, as `ga`): the three edges as one branch,
//! `min(σU, σV, |den| - σ(U + V)) >= 0` with the processor's minimum (closed edges, no tie
//! rule, not watertight; a NaN reaches the comparison and is rejected), then the distance
//! `0 < σ num <= t_max |den| (1 + 4 ε)` (the slack lets `intersect(.., t_max = hit.t)` find its
//! own hit), then one division and `0 < t <= t_max`, `t` finite, on the divided `t`. See
//! `kernels_g3::frame` for why the edges come first and why as one branch.
//!
//! # Per-triangle data, cost
//!
//! - Per triangle: `a`, `n`, `m_b`, `m_c`, four glam vectors: 64 B in `f32` (`Vec3A` is padded
//!   to 16 B; `g3-frame` and `ga` store the same 12 numbers in 48 B), 96 B in `f64`. A
//!   degenerate triangle (decided exactly) gets `n = m_b = m_c = 0`, which no ray hits.
//! - Per ray: nothing.
//! - Per test: 1 vector subtraction, 6 dot products, 4 multiplies and 2 subtractions, then the
//!   edge test (2 sign products, 1 addition, 1 subtraction, 2 minima, 1 comparison) and the
//!   distance test (1 product, 2 multiplies, 2 comparisons); one division, for hits only.

use core::marker::PhantomData;

use glam::DVec3;
use intersect::{Algebra, Guarantees, Intersector, Method, Ray, Real, Triangle, TriangleHit};

use crate::{GlamReal, is_degenerate};

/// The frame method in glam (`NAME = "la-frame"`): precomputed unit normal and reciprocal
/// frame, one dot product per edge.
///
/// See the [module documentation](self).
///
/// ```
/// use intersect::{Intersector, Ray, Triangle};
/// use kernels_la::Frame;
///
/// let k = Frame::<f32>::new();
/// let prim = k.prepare(&Triangle::new([0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [0.0, 2.0, 0.0]));
/// let ray = Ray::new([0.5, 1.0, 3.0], [0.0, 0.0, -1.0]);
/// let hit = k.intersect(&prim, &ray, &(), f32::INFINITY).unwrap();
/// assert_eq!((hit.t, hit.u, hit.v), (3.0, 0.25, 0.5));
/// assert!(k.intersect(&prim, &ray, &(), 2.5).is_none());
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Frame<T>(PhantomData<T>);

impl<T> Frame<T> {
    /// The kernel (it has no state).
    #[must_use]
    pub const fn new() -> Self {
        Self(PhantomData)
    }
}

/// What [`Frame`] keeps of a triangle: the vertex `a`, the unit normal `n` and the reciprocal
/// frame `m_b`, `m_c` (see the [module documentation](self)).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FramePrim<T: GlamReal> {
    a: T::V,
    n: T::V,
    m_b: T::V,
    m_c: T::V,
}

impl<T: GlamReal> FramePrim<T> {
    /// The data of `tri`, computed in `f64` and rounded once to `T`.
    fn new(tri: &Triangle<T>) -> Self {
        let a = T::load(tri.a);
        if is_degenerate(tri) {
            let zero = T::splat(T::ZERO);
            return Self { a, n: zero, m_b: zero, m_c: zero };
        }
        let [a64, b64, c64] = tri.vertices().map(|p| DVec3::from_array(p.map(Real::to_f64)));
        let (e1, e2) = (b64 - a64, c64 - a64);
        let normal = e1.cross(e2);
        let inv_area2 = normal.length_squared().recip();
        let round = |v: DVec3| T::load(v.to_array().map(T::from_f64));
        Self {
            a,
            n: round(normal * normal.length().recip()),
            m_b: round(e2.cross(normal) * inv_area2),
            m_c: round(normal.cross(e1) * inv_area2),
        }
    }
}

impl<T: GlamReal> Intersector for Frame<T> {
    type Real = T;
    type Prim = FramePrim<T>;
    type RayData = ();
    type Block = ();
    const NAME: &'static str = "la-frame";
    const ALGEBRA: Algebra = Algebra::La;
    const METHOD: Method = Method::Frame;
    const GUARANTEES: Guarantees = Guarantees { watertight: false, exact: false };
    const VARIANT: Option<&'static str> = None;

    fn prepare(&self, tri: &Triangle<T>) -> FramePrim<T> {
        FramePrim::new(tri)
    }

    #[inline(always)]
    fn prepare_ray(&self, _ray: &Ray<T>) {}

    #[inline(always)]
    fn intersect(
        &self,
        prim: &FramePrim<T>,
        ray: &Ray<T>,
        _: &(),
        t_max: T,
    ) -> Option<TriangleHit<T>> {
        let [num, den, u, v] = candidate(prim, ray, t_max)?;
        let inv_den = T::ONE / den;
        let t = num * inv_den;
        hit_distance_ok(t, t_max).then(|| TriangleHit { t, u: u * inv_den, v: v * inv_den })
    }

    #[inline(always)]
    fn occludes(&self, prim: &FramePrim<T>, ray: &Ray<T>, _: &(), t_max: T) -> bool {
        candidate(prim, ray, t_max)
            .is_some_and(|[num, den, ..]| hit_distance_ok(num * (T::ONE / den), t_max))
    }
}

/// The undivided values `[num, den, U, V]` of a probable hit, decided as `ga` decides (see
/// the module documentation), or `None`.
#[inline(always)]
fn candidate<T: GlamReal>(prim: &FramePrim<T>, ray: &Ray<T>, t_max: T) -> Option<[T; 4]> {
    let FramePrim { a, n, m_b, m_c } = *prim;
    let (s, d) = (a - T::load(ray.origin), T::load(ray.dir));
    let (num, den) = (T::dot(s, n), T::dot(d, n));
    let u = num * T::dot(d, m_b) - den * T::dot(s, m_b);
    let v = num * T::dot(d, m_c) - den * T::dot(s, m_c);

    // The edges as one branch; σ taken off by an exact product with ±1.
    let abs_den = den.abs();
    let sign = T::ONE.copy_sign(den);
    let (u_s, v_s) = (u * sign, v * sign);
    let w = abs_den - (u_s + v_s);
    let lesser = |x: T, y: T| if x < y { x } else { y };
    let least = lesser(lesser(u_s, v_s), w);
    if least < T::ZERO || least.is_nan() {
        return None;
    }

    // 0 < t <= t_max before the division, loosened by 4 ulps of 1.
    let num_s = num * sign;
    let slack = T::ONE + T::EPSILON * T::from_f64(4.0);
    if !(num_s > T::ZERO && num_s <= t_max * abs_den * slack) {
        return None;
    }
    Some([num, den, u, v])
}

/// `0 < t <= t_max` and `t` finite, on the divided `t`.
#[inline(always)]
fn hit_distance_ok<T: Real>(t: T, t_max: T) -> bool {
    t > T::ZERO && t <= t_max && t.is_finite()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `m_b`, `m_c` are the reciprocal frame of the edges and `n` the unit normal, on a
    /// skewed triangle whose frame is known exactly.
    #[test]
    fn prim_holds_the_reciprocal_frame() {
        // e1 = (2, 0, 0), e2 = (1, 4, 0): N = (0, 0, 8), m_b = (1/2, -1/8, 0), m_c = (0, 1/4, 0).
        let tri = Triangle::new([1.0, 1.0, 1.0], [3.0, 1.0, 1.0], [2.0, 5.0, 1.0]);
        let prim = FramePrim::<f64>::new(&tri);
        assert_eq!(prim.n, DVec3::Z);
        assert_eq!(prim.m_b, DVec3::new(0.5, -0.125, 0.0));
        assert_eq!(prim.m_c, DVec3::new(0.0, 0.25, 0.0));
        let flat = Triangle::new([1.0f32, 2.0, 3.0], [2.0, 4.0, 6.0], [3.0, 6.0, 9.0]);
        let prim = FramePrim::<f32>::new(&flat);
        assert_eq!([prim.n, prim.m_b, prim.m_c], [glam::Vec3A::ZERO; 3]);
    }
}
