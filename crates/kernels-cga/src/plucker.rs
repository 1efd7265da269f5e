//! Plücker coordinates in CGA: the plucker/CGA cell, the twin of `la-plucker`
//! (`kernels_la::Plucker`) and `g3-plucker`, with the ray and the edges as flat lines.
//!
//! # Derivation
//!
//! The flat line through `p` with direction `d` is `L = up(p) ∧ d ∧ e∞ = (eₒ + p) ∧ d ∧ e∞`
//! (the private `flat` module): its ten coefficients hold the direction `d` (on `e_i45`) and
//! the moment `p ∧ d` twice (on `e_ij4` and `e_ij5`; `e123` is 0). These are the Plücker
//! coordinates, as blades. Two flat lines meet, in the regressive product, in a multiple of
//! the point at infinity:
//!
//! ```text
//! L₁ & L₂ = w e∞,     w = d₁ · m₂ + d₂ · m₁      (m the moment vectors)
//! ```
//!
//! `la-plucker`'s permuted inner product, which is zero exactly when the lines meet (or are
//! parallel) and whose sign says on which side of one the other passes. `w` is read as
//! `-((L₁ & L₂) · e5)` (`e∞ · e5 = e5² = -1`: exact, where `-(X · eₒ)`, the same value,
//! would multiply by `∓½` and lose the last bit of subnormal values, leaving a zero side
//! beside a non-zero `det`). With the ray's line `L = up(o) ∧ d ∧ e∞` (per ray)
//! and the edges' lines `E_a = up(b) ∧ (c - b) ∧ e∞`, `E_b` (from `c` to `a`), `E_c` (from `a`
//! to `b`) (per triangle), the ray passes through the closed triangle exactly when
//! `w_a, w_b, w_c` are all `>= 0` or all `<= 0`, and they are the barycentric weights times
//! `det = w_a + w_b + w_c`: `u = w_b / det`, `v = w_c / det`.
//!
//! The distance is the plane's, as in `la-plucker`: the dual plane `ν` through `a` with the
//! unit normal (in the frame translated to `a`, `δ = 0`), evaluated at the ray's point
//! `O = eₒ + (o - a)`: `num = -(O · ν) = (a - o) · n`, `den = d · ν = d · n`.
//!
//! # Decisions, per-triangle data, cost
//!
//! `la-plucker`'s, in its order: the three sides (closed, both faces), `det == 0` a miss, then
//! `0 < num σ <= t_max |den| (1 + 4ε)`, then `t = num / den`, `0 < t <= t_max`, `t` and `det`
//! finite. No tie rule.
//!
//! - Per triangle: the three edge lines as [`Trivector`]s (computed in `f64` from the
//!   vertices and rounded once; ten coefficients each, of which `e123` is 0 and the moment
//!   is stored twice: the algebra's line has these blades), `a` and `ν` as five-coefficient
//!   [`Vector`]s: 40 scalars, 160 B in `f32`, 320 B in `f64` (`la-plucker`: 128 B, 192 B).
//! - Per ray: the ray's flat line (two outer products).
//! - Per test: 3 regressive products `Trivector & Trivector` of which the `e5` coefficient
//!   is read (6 multiplies and 5 additions: `la-plucker`'s permuted inner product), each
//!   contracted with `e5` (a sign change); the sign
//!   tests; 2 additions (`det`); `o - a`, `eₒ +`, 2 inner products of five coefficients
//!   (`num`, `den`); the distance test; a division and a reciprocal for a hit.
//!
//! # Why it is not watertight
//!
//! Two triangles sharing an edge store the same line with opposite orientation, computed from
//! the same two vertices in the other order, so `w` is (up to rounding of the `f64`
//! precomputation) negated; but its sign is a rounded sum of six products, not exact, and an
//! exact zero has no tie rule, so rays through edges and vertices can pass between
//! neighbours or hit both, as with `la-plucker`. Moments are taken about the world origin, so
//! edge decisions lose digits far from it, as `la-plucker`'s do.

use core::marker::PhantomData;

use ga::Scalar;
use ga::cga::{Trivector, Vector};
use intersect::{Algebra, Guarantees, Intersector, Method, Ray, Real, Triangle, TriangleHit};

use kernels_g3::watertight::finish;

use crate::flat::{line, point, vector};
use crate::{cross64, is_degenerate, round64};

/// Plücker coordinates as CGA flat lines (`NAME = "cga-plucker"`).
///
/// See the [module derivation](self).
///
/// ```
/// use intersect::{Intersector, Ray, Triangle};
/// use kernels_cga::CgaPlucker;
///
/// let k = CgaPlucker::<f64>::new();
/// let prim = k.prepare(&Triangle::new([0.0, 0.0, 2.0], [4.0, 0.0, 2.0], [0.0, 4.0, 2.0]));
/// let ray = Ray::new([1.0, 2.0, -1.0], [0.0, 0.0, 1.0]);
/// let hit = k.intersect(&prim, &ray, &k.prepare_ray(&ray), f64::INFINITY).unwrap();
/// assert_eq!((hit.t, hit.u, hit.v), (3.0, 0.25, 0.5));
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct CgaPlucker<T>(PhantomData<T>);

impl<T> CgaPlucker<T> {
    /// The kernel (it has no state).
    #[must_use]
    pub const fn new() -> Self {
        Self(PhantomData)
    }
}

/// What [`CgaPlucker`] keeps of a triangle: the flat lines of its edges (opposite `a`, `b`,
/// `c`), vertex `a` and the dual plane `ν` through `a` (unit normal, `δ = 0` at `a`).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct CgaPluckerPrim<T> {
    edges: [Trivector<T>; 3],
    a: Vector<T>,
    nu: Vector<T>,
}

/// What [`CgaPlucker`] keeps of a ray: its flat line `up(o) ∧ d ∧ e∞`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct CgaPluckerRay<T> {
    line: Trivector<T>,
}

impl<T: Scalar> Intersector for CgaPlucker<T> {
    type Real = T;
    type Prim = CgaPluckerPrim<T>;
    type RayData = CgaPluckerRay<T>;
    type Block = ();
    const NAME: &'static str = "cga-plucker";
    const ALGEBRA: Algebra = Algebra::Cga;
    const METHOD: Method = Method::Plucker;
    const GUARANTEES: Guarantees = Guarantees { watertight: false, exact: false };
    const VARIANT: Option<&'static str> = None;

    fn prepare(&self, tri: &Triangle<T>) -> CgaPluckerPrim<T> {
        let a = vector(tri.a);
        if is_degenerate(tri) {
            // Zero lines make every side 0, so `det` is 0: never hit.
            return CgaPluckerPrim { edges: [Trivector::ZERO; 3], a, nu: Vector::ZERO };
        }
        let [a64, b64, c64] = tri.vertices().map(|p| vector(p.map(Real::to_f64)));
        let edge = |p: Vector<f64>, q: Vector<f64>| {
            Trivector::from_array(line(p, q - p).to_array().map(T::from_f64))
        };
        let e = |v: Vector<f64>| [v.e1, v.e2, v.e3];
        let normal = cross64(e(b64 - a64), e(c64 - a64));
        let inv_len = normal.iter().map(|x| x * x).sum::<f64>().sqrt().recip();
        CgaPluckerPrim {
            edges: [edge(b64, c64), edge(c64, a64), edge(a64, b64)],
            a,
            nu: vector(round64(normal.map(|x| x * inv_len))),
        }
    }

    #[inline]
    fn prepare_ray(&self, ray: &Ray<T>) -> CgaPluckerRay<T> {
        CgaPluckerRay { line: line(vector(ray.origin), vector(ray.dir)) }
    }

    #[inline]
    fn intersect(
        &self,
        prim: &CgaPluckerPrim<T>,
        ray: &Ray<T>,
        rd: &CgaPluckerRay<T>,
        t_max: T,
    ) -> Option<TriangleHit<T>> {
        // The side of each edge's line the ray's line passes: L & E = w e∞.
        let side = |edge: Trivector<T>| -((rd.line & edge) | Vector::E5);
        let [w_a, w_b, w_c] = prim.edges.map(side);
        let zero = T::ZERO;
        let front = (w_a >= zero) & (w_b >= zero) & (w_c >= zero);
        let back = (w_a <= zero) & (w_b <= zero) & (w_c <= zero);
        if !(front | back) {
            return None;
        }
        // t = ((a - o) . n) / (d . n) from the dual plane: `det`, then the distance tested
        // before dividing, then the barycentrics, `la-plucker`'s tail (shared with
        // `g3-watertight`).
        let num = -(point(vector(ray.origin) - prim.a) | prim.nu);
        let den = vector(ray.dir) | prim.nu;
        finish([w_a, w_b, w_c], num, den, t_max)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The regressive product of two flat lines is `la-plucker`'s permuted inner product
    /// times `e∞`, computed here from the Plücker six-vectors by hand.
    #[test]
    fn the_meet_of_two_flat_lines_is_the_permuted_inner_product() {
        let (p, d) = ([1.0, -2.0, 0.5], [0.25, 3.0, -1.0]);
        let (q, e) = ([-3.0, 0.5, 2.0], [2.0, -0.5, 1.5]);
        let (m1, m2) = (cross64(p, d), cross64(q, e));
        let dot = |x: [f64; 3], y: [f64; 3]| x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
        let want = dot(d, m2) + dot(e, m1);
        let meet = line(vector(p), vector(d)) & line(vector(q), vector(e));
        assert_eq!(meet, Vector::E_INF * want);
        assert_eq!(-(meet | Vector::E5), want);
        assert_eq!(-(meet | Vector::E_O), want);
    }
}
