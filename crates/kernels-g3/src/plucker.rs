//! Plücker lines in G3: the plucker/G3 cell (`g3-plucker`), the twin of `la-plucker`
//! (`kernels_la::Plucker`, the six-vector form).
//!
//! # Lines in G3
//!
//! The line through `p` with direction `d` is the pair `(d, M)` of its direction vector and
//! its *moment bivector* `M = p ∧ d` (any point of the line gives the same `M`: `(p + s d) ∧ d
//! = p ∧ d`). The LA six-vector form `(d, m)` with `m = p × d` is its dual: `m = M*`, since
//! `(x ∧ y)* = x × y`, component for component (`m = (M_e23, M_e31, M_e12)`).
//!
//! For two lines `(d1, M1)`, `(d2, M2)` the side test is the trivector
//!
//! ```text
//! side = d1 ∧ M2 + d2 ∧ M1
//! ```
//!
//! which is `(d1 · m2 + d2 · m1) I`, the LA permuted inner product times the pseudoscalar: for
//! a vector and a bivector, `x ∧ B = (x · B*) I`. It is zero exactly when the lines meet; its
//! dual is the signed volume of the two lines. For the ray `(d, o ∧ d)` and the edge from `p`
//! to `q`, `(q - p, p ∧ q)`, it is `((p - o) ∧ (q - o)) ∧ d`, `ga-plucker`'s edge trivector,
//! so `la-plucker`'s derivation holds term for term: the three sides (duals `w_a`, `w_b`,
//! `w_c` for the edges opposite `a`, `b`, `c`) are the barycentrics times `det = (N ∧ d)*`.
//!
//! # Data, decisions, cost (the row's, as `la-plucker`)
//!
//! - Per triangle: the edges' directions `c - b`, `a - c`, `b - a` and moments `b ∧ c`,
//!   `c ∧ a`, `a ∧ b` (computed in `f64` and rounded once), the vertex `a` and the unit normal
//!   `n`: 5 [`Vector`]s and 3 [`Bivector`]s, 24 numbers, 96 B in `f32`, 192 B in `f64`. A
//!   degenerate triangle gets zero lines and normal: never hit.
//! - Per ray: its line `(d, o ∧ d)` ([`G3PluckerRay`]).
//! - Decisions: the three sides, then all `>= 0` or all `<= 0` (closed edges, no tie rule,
//!   not watertight: a side is a rounded sum, exactly negated by the neighbour but not
//!   exactly signed), `det == 0` a miss, the distance `t = ((a - o) | n) / (d | n)` before
//!   the division with the frame cells' slack, one division ([`crate::watertight`]'s tail,
//!   shared).
//! - Per test: 6 outer products of a vector and a bivector (3 multiplies, 2 additions each)
//!   and 3 trivector additions, the sign test, 1 vector subtraction and 2 inner products, 2
//!   additions: `la-plucker`'s 6 dot products, operation for operation.

use core::marker::PhantomData;

use ga::g3::{Bivector, Vector};
use intersect::{Algebra, Guarantees, Intersector, Method, Ray, Triangle, TriangleHit};

use crate::real::private::Float;
use crate::watertight::finish;
use crate::{GaReal, is_degenerate};

/// Plücker lines as direction vectors and moment bivectors (`NAME = "g3-plucker"`).
///
/// See the [module derivation](self).
///
/// ```
/// use intersect::{Intersector, Ray, Triangle};
/// use kernels_g3::G3Plucker;
///
/// let k = G3Plucker::<f64>::new();
/// let prim = k.prepare(&Triangle::new([0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [0.0, 2.0, 0.0]));
/// let ray = Ray::new([0.5, 1.0, 3.0], [0.0, 0.0, -1.0]);
/// let hit = k.intersect(&prim, &ray, &k.prepare_ray(&ray), f64::INFINITY).unwrap();
/// assert_eq!((hit.t, hit.u, hit.v), (3.0, 0.25, 0.5));
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct G3Plucker<T>(PhantomData<T>);

impl<T> G3Plucker<T> {
    /// The kernel (it has no state).
    #[must_use]
    pub const fn new() -> Self {
        Self(PhantomData)
    }
}

/// What [`G3Plucker`] keeps of a triangle: the lines of the edges `bc`, `ca`, `ab`, the
/// vertex `a` and the unit normal `n`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct G3PluckerPrim<T> {
    /// Edge directions `c - b`, `a - c`, `b - a` (the edge opposite `a`, `b`, `c`).
    e: [Vector<T>; 3],
    /// Edge moments `b ∧ c`, `c ∧ a`, `a ∧ b`.
    m: [Bivector<T>; 3],
    a: Vector<T>,
    n: Vector<T>,
}

/// What [`G3Plucker`] computes once per ray: its line, direction `d` and moment `o ∧ d`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct G3PluckerRay<T> {
    d: Vector<T>,
    m: Bivector<T>,
}

impl<T: GaReal> Intersector for G3Plucker<T> {
    type Real = T;
    type Prim = G3PluckerPrim<T>;
    type RayData = G3PluckerRay<T>;
    type Block = ();
    const NAME: &'static str = "g3-plucker";
    const ALGEBRA: Algebra = Algebra::G3;
    const METHOD: Method = Method::Plucker;
    const GUARANTEES: Guarantees = Guarantees { watertight: false, exact: false };
    const VARIANT: Option<&'static str> = None;

    fn prepare(&self, tri: &Triangle<T>) -> G3PluckerPrim<T> {
        let a = Vector::from_array(tri.a);
        if is_degenerate(tri) {
            let (e, m) = ([Vector::ZERO; 3], [Bivector::ZERO; 3]);
            return G3PluckerPrim { e, m, a, n: Vector::ZERO };
        }
        let [a64, b64, c64] = tri.vertices().map(|p| Vector::from_array(p.map(ga::Real::to_f64)));
        let round = |x: [f64; 3]| x.map(ga::Real::from_f64);
        let edges = [(b64, c64), (c64, a64), (a64, b64)];
        G3PluckerPrim {
            e: edges.map(|(p, q)| Vector::from_array(round((q - p).to_array()))),
            m: edges.map(|(p, q)| Bivector::from_array(round((p ^ q).to_array()))),
            a,
            n: crate::watertight::unit_normal(tri),
        }
    }

    #[inline]
    fn prepare_ray(&self, ray: &Ray<T>) -> G3PluckerRay<T> {
        let d = Vector::from_array(ray.dir);
        G3PluckerRay { d, m: Vector::from_array(ray.origin) ^ d }
    }

    #[inline]
    fn intersect(
        &self,
        prim: &G3PluckerPrim<T>,
        ray: &Ray<T>,
        rd: &G3PluckerRay<T>,
        t_max: T,
    ) -> Option<TriangleHit<T>> {
        intersect(prim, ray, rd, t_max)
    }
}

#[inline(always)]
fn intersect<T: Float>(
    prim: &G3PluckerPrim<T>,
    ray: &Ray<T>,
    rd: &G3PluckerRay<T>,
    t_max: T,
) -> Option<TriangleHit<T>> {
    // The side of the ray's line against each edge's line, d ∧ M_e + e ∧ M_ray, as its dual.
    let side = |k: usize| ((rd.d ^ prim.m[k]) + (prim.e[k] ^ rd.m)).dual();
    let w = [side(0), side(1), side(2)];
    let zero = T::ZERO;
    let front = (w[0] >= zero) & (w[1] >= zero) & (w[2] >= zero);
    let back = (w[0] <= zero) & (w[1] <= zero) & (w[2] <= zero);
    if !(front | back) {
        return None;
    }
    let o = Vector::from_array(ray.origin);
    finish(w, (prim.a - o) | prim.n, rd.d | prim.n, t_max)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The side of the ray against an edge is `ga-plucker`'s edge trivector
    /// `((p - o) ∧ (q - o)) ∧ d`, and the moment bivector is the dual of the LA moment.
    #[test]
    fn side_is_the_edge_trivector() {
        let (o, d) = (Vector::new(0.5f64, -1.0, 2.0), Vector::new(0.25, 0.5, -1.0));
        let (p, q) = (Vector::new(1.0, 2.0, -3.0), Vector::new(-2.0, 0.5, 1.5));
        let side = ((d ^ (p ^ q)) + ((q - p) ^ (o ^ d))).dual();
        let trivector = (((p - o) ^ (q - o)) ^ d).dual();
        assert!((side - trivector).abs() <= 1e-12, "{side} {trivector}");
        // The moment bivector's dual is the LA moment p x q, written out.
        let m = Vector::new(
            p.e2 * q.e3 - p.e3 * q.e2,
            p.e3 * q.e1 - p.e1 * q.e3,
            p.e1 * q.e2 - p.e2 * q.e1,
        );
        assert_eq!((p ^ q).dual(), m);
    }
}
