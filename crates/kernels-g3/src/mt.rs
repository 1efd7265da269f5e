//! Moller-Trumbore (1997) in G3: the mt/G3 cell, the twin of `la-mt`
//! (`kernels_la::MollerTrumbore`), with every determinant a trivector.
//!
//! # Derivation
//!
//! A point of the triangle is `a + u e1 + v e2` (`e1 = b - a`, `e2 = c - a`), a point of the
//! ray `o + t d`; equating them gives `[-d e1 e2] (t, u, v)^T = s` with `s = o - a`. Cramer's
//! rule needs four 3x3 determinants, and in G3 a determinant is an outer product:
//! `x ∧ y ∧ z = det[x y z] I`. `la-mt` writes each as a triple product `(x × y) · z`, sharing
//! two cross products; here the shared factors are the bivectors
//!
//! ```text
//! P = d ∧ e2          det = e1 ∧ P = det[e1 d e2] I      (la-mt: e1 · (d × e2))
//! Q = s ∧ e1          u = (s ∧ P) / det
//!                     v = (d ∧ Q) / det                  t = (e2 ∧ Q) / det
//! ```
//!
//! where a ratio of trivectors is the ratio of their `e123` coefficients (their duals). Each
//! `Vector ∧ Vector` has the components of the cross product (`(x ∧ y)* = x × y`), and each
//! `Vector ∧ Bivector` is the triple product, so the operations are `la-mt`'s one for one.
//!
//! # Decisions, per-triangle data, cost
//!
//! `la-mt`'s, in its order: `det == 0` or non-finite is a miss (no scale-dependent epsilon);
//! one reciprocal of `det`; `0 <= u <= 1`, then `Q`, then `v >= 0` and `u + v <= 1` (closed
//! edges, no tie rule, not watertight); then `0 < t <= t_max` with `t` finite. Each test is
//! written so that NaN fails it.
//!
//! - Per triangle: `a`, `e1`, `e2` as [`Vector`]s, 36 B in `f32` (`la-mt` stores 48 B: glam's
//!   `Vec3A` is padded to 16 B), 72 B in `f64`; a degenerate triangle (decided exactly)
//!   gets zero edges, so `det` is exactly 0 for every ray.
//! - Per ray: nothing.
//! - Per test: 2 outer products of vectors (6 multiplies, 3 subtractions each), 4 outer
//!   products of a vector and a bivector (3 multiplies, 2 additions each), 1 subtraction of
//!   vectors, 1 reciprocal and 3 multiplies: `la-mt`'s 2 crosses, 4 dots and reciprocal.

use core::marker::PhantomData;

use ga::g3::Vector;
use intersect::{Algebra, Guarantees, Intersector, Method, Ray, Triangle, TriangleHit};

use crate::real::private::Float;
use crate::{GaReal, is_degenerate};

/// Moller-Trumbore with trivector determinants (`NAME = "g3-mt"`).
///
/// See the [module derivation](self).
///
/// ```
/// use intersect::{Intersector, Ray, Triangle};
/// use kernels_g3::G3Mt;
///
/// let k = G3Mt::<f32>::new();
/// let prim = k.prepare(&Triangle::new([0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [0.0, 2.0, 0.0]));
/// let ray = Ray::new([0.5, 0.5, 3.0], [0.0, 0.0, -1.0]);
/// let hit = k.intersect(&prim, &ray, &(), f32::INFINITY).unwrap();
/// assert_eq!((hit.t, hit.u, hit.v), (3.0, 0.25, 0.25));
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct G3Mt<T>(PhantomData<T>);

impl<T> G3Mt<T> {
    /// The kernel (it has no state).
    #[must_use]
    pub const fn new() -> Self {
        Self(PhantomData)
    }
}

/// What [`G3Mt`] keeps of a triangle: vertex `a` and edges `e1 = b - a`, `e2 = c - a`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct G3MtPrim<T> {
    a: Vector<T>,
    e1: Vector<T>,
    e2: Vector<T>,
}

impl<T: GaReal> Intersector for G3Mt<T> {
    type Real = T;
    type Prim = G3MtPrim<T>;
    type RayData = ();
    type Block = ();
    const NAME: &'static str = "g3-mt";
    const ALGEBRA: Algebra = Algebra::G3;
    const METHOD: Method = Method::MollerTrumbore;
    const GUARANTEES: Guarantees = Guarantees { watertight: false, exact: false };
    const VARIANT: Option<&'static str> = None;

    fn prepare(&self, tri: &Triangle<T>) -> G3MtPrim<T> {
        let a = Vector::from_array(tri.a);
        if is_degenerate(tri) {
            // Zero edges make `det` exactly 0 for every ray: never hit.
            return G3MtPrim { a, e1: Vector::ZERO, e2: Vector::ZERO };
        }
        G3MtPrim { a, e1: Vector::from_array(tri.b) - a, e2: Vector::from_array(tri.c) - a }
    }

    #[inline(always)]
    fn prepare_ray(&self, _ray: &Ray<T>) {}

    #[inline]
    fn intersect(
        &self,
        prim: &G3MtPrim<T>,
        ray: &Ray<T>,
        _: &(),
        t_max: T,
    ) -> Option<TriangleHit<T>> {
        intersect(prim, ray, t_max)
    }
}

#[inline(always)]
fn intersect<T: Float>(prim: &G3MtPrim<T>, ray: &Ray<T>, t_max: T) -> Option<TriangleHit<T>> {
    let G3MtPrim { a, e1, e2 } = *prim;
    let d = Vector::from_array(ray.dir);
    // det[e1 d e2] I = e1 ∧ d ∧ e2: zero when the ray is parallel to the plane (as rounded).
    let p = d ^ e2;
    let det = (e1 ^ p).dual();
    if det == T::ZERO || !det.is_finite() {
        return None;
    }
    let inv_det = det.recip();

    let s = Vector::from_array(ray.origin) - a;
    let u = (s ^ p).dual() * inv_det;
    if !(u >= T::ZERO && u <= T::ONE) {
        return None;
    }

    let q = s ^ e1;
    let v = (d ^ q).dual() * inv_det;
    if !(v >= T::ZERO && u + v <= T::ONE) {
        return None;
    }

    // `t` can overflow for a nearly parallel ray (tiny `det`): an infinite `t` is no hit.
    let t = (e2 ^ q).dual() * inv_det;
    (t > T::ZERO && t <= t_max && t.is_finite()).then_some(TriangleHit { t, u, v })
}
