//! Moller-Trumbore (1997) in CGA: the mt/CGA cell, the twin of `la-mt`
//! (`kernels_la::MollerTrumbore`) and `g3-mt`, with every determinant an outer product of
//! Euclidean vectors of R(4,1).
//!
//! # Derivation
//!
//! A point of the triangle is `a + u e1 + v e2` (`e1 = b - a`, `e2 = c - a`), a point of the
//! ray `o + t d`; equating them gives `[-d e1 e2] (t, u, v)^T = s` with `s = o - a`, solved by
//! Cramer's rule. Every quantity of the method is a *direction* (a difference of points), and
//! in CGA a direction is a Euclidean vector `x` (no `e4`, `e5` part: `x · e∞ = 0`); the
//! determinant of three of them is the `e123` coefficient of their outer product,
//! `x ∧ y ∧ z = det[x y z] e123` (no `e4`, `e5` factor can appear). With the shared bivectors
//!
//! ```text
//! P = d ∧ e2          det = (e1 ∧ P)₁₂₃
//! Q = s ∧ e1          u = (s ∧ P)₁₂₃ / det    v = (d ∧ Q)₁₂₃ / det    t = (e2 ∧ Q)₁₂₃ / det
//! ```
//!
//! (`la-mt`'s `p = d × e2`, `q = s × e1` and its four triple products). The points
//! `a`, `o` enter only through `s = o - a`, so the conformal embedding, and its `½x²`
//! rounding (see [`crate`], "Precision"), never appears: measured from vertex `a`, as `la-mt`.
//!
//! # Decisions, per-triangle data, cost
//!
//! `la-mt`'s, in its order: `det == 0` or non-finite is a miss; one reciprocal of `det`;
//! `0 <= u <= 1`, then `Q`, then `v >= 0` and `u + v <= 1` (closed edges, no tie rule, not
//! watertight); then `0 < t <= t_max` with `t` finite. Each test fails on NaN.
//!
//! - Per triangle: `a`, `e1`, `e2` as [`Vector`]s of five coefficients (the `e4`, `e5` ones
//!   zero, stored because the type has them): 60 B in `f32`, 120 B in `f64` (`la-mt`: 48 B
//!   and 72 B). A degenerate triangle (decided exactly) gets zero edges, so `det` is 0.
//! - Per ray: nothing.
//! - Per test: 2 vector subtractions of five coefficients (`s`; the `e4`, `e5` ones are
//!   `0 - 0`), 2 `Vector ∧ Vector` (the ten bivector coefficients are written, but only the
//!   three of `e12`, `e13`, `e23` are read by what follows: 6 multiplies and 3 subtractions
//!   each after dead-code elimination), 4 `Vector ∧ Bivector` read at `e123` (3 multiplies, 2
//!   additions each), 1 reciprocal and 3 multiplies: `la-mt`'s operation count, since the
//!   compiler drops every coefficient nobody reads (the zero `e4`, `e5` coefficients only meet
//!   coefficients that are dropped).

use core::marker::PhantomData;

use ga::Scalar;
use ga::cga::Vector;
use intersect::{Algebra, Guarantees, Intersector, Method, Ray, Triangle, TriangleHit};

use crate::flat::vector;
use crate::is_degenerate;

/// Moller-Trumbore with determinants as outer products in R(4,1) (`NAME = "cga-mt"`).
///
/// See the [module derivation](self).
///
/// ```
/// use intersect::{Intersector, Ray, Triangle};
/// use kernels_cga::CgaMt;
///
/// let k = CgaMt::<f32>::new();
/// let prim = k.prepare(&Triangle::new([0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [0.0, 2.0, 0.0]));
/// let ray = Ray::new([0.5, 0.5, 3.0], [0.0, 0.0, -1.0]);
/// let hit = k.intersect(&prim, &ray, &(), f32::INFINITY).unwrap();
/// assert_eq!((hit.t, hit.u, hit.v), (3.0, 0.25, 0.25));
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct CgaMt<T>(PhantomData<T>);

impl<T> CgaMt<T> {
    /// The kernel (it has no state).
    #[must_use]
    pub const fn new() -> Self {
        Self(PhantomData)
    }
}

/// What [`CgaMt`] keeps of a triangle: vertex `a` and edges `e1 = b - a`, `e2 = c - a`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct CgaMtPrim<T> {
    a: Vector<T>,
    e1: Vector<T>,
    e2: Vector<T>,
}

impl<T: Scalar> Intersector for CgaMt<T> {
    type Real = T;
    type Prim = CgaMtPrim<T>;
    type RayData = ();
    type Block = ();
    const NAME: &'static str = "cga-mt";
    const ALGEBRA: Algebra = Algebra::Cga;
    const METHOD: Method = Method::MollerTrumbore;
    const GUARANTEES: Guarantees = Guarantees { watertight: false, exact: false };
    const VARIANT: Option<&'static str> = None;

    fn prepare(&self, tri: &Triangle<T>) -> CgaMtPrim<T> {
        let a = vector(tri.a);
        if is_degenerate(tri) {
            // Zero edges make `det` exactly 0 for every ray: never hit.
            return CgaMtPrim { a, e1: Vector::ZERO, e2: Vector::ZERO };
        }
        CgaMtPrim { a, e1: vector(tri.b) - a, e2: vector(tri.c) - a }
    }

    #[inline(always)]
    fn prepare_ray(&self, _ray: &Ray<T>) {}

    #[inline]
    fn intersect(
        &self,
        prim: &CgaMtPrim<T>,
        ray: &Ray<T>,
        _: &(),
        t_max: T,
    ) -> Option<TriangleHit<T>> {
        let CgaMtPrim { a, e1, e2 } = *prim;
        let d = vector(ray.dir);
        // det[e1 d e2] e123 = e1 ∧ d ∧ e2: zero when the ray is parallel to the plane.
        let p = d ^ e2;
        let det = (e1 ^ p).e123;
        if det == T::ZERO || !det.is_finite() {
            return None;
        }
        let inv_det = det.recip();

        let s = vector(ray.origin) - a;
        let u = (s ^ p).e123 * inv_det;
        if !(u >= T::ZERO && u <= T::ONE) {
            return None;
        }

        let q = s ^ e1;
        let v = (d ^ q).e123 * inv_det;
        if !(v >= T::ZERO && u + v <= T::ONE) {
            return None;
        }

        // `t` can overflow for a nearly parallel ray (tiny `det`): an infinite `t` is no hit.
        let t = (e2 ^ q).e123 * inv_det;
        (t > T::ZERO && t <= t_max && t.is_finite()).then_some(TriangleHit { t, u, v })
    }
}
