//! Plücker coordinates in glam, the six-vector form: the plucker/LA cell (`la-plucker`), the
//! twin of `g3-plucker` (`kernels_g3::G3Plucker`).
//!
//! # Derivation
//!
//! The line through `p` with direction `d` has the Plücker coordinates `(d, m)`, `m = p x d`
//! its moment about the world origin (any point of the line gives the same `m`). For two
//! lines the *permuted inner product*
//!
//! ```text
//! side(L1, L2) = d1 . m2 + d2 . m1
//! ```
//!
//! is zero exactly when they meet (or are parallel), and its sign says which way one passes
//! the other. For the ray `L = (d, o x d)` and the edge from `p` to `q`,
//! `E = (q - p, p x q)` (`p x (q - p) = p x q`),
//!
//! ```text
//! side(L, E) = d . (p x q) + (q - p) . (o x d) = det[d, p - o, q - p]
//! ```
//!
//! (expand both triple products; the `o x` terms of `p x q` and `(q - p) . (o x d)` combine
//! into `det[d, -o, q - p]`). That is `ga-plucker`'s edge trivector `((p - o) ∧ (q - o)) ∧ d`:
//! for a ray meeting the plane at barycentrics `(λa, λb, λc)`, `side(L, E_bc) = λa det`,
//! `side(L, E_ca) = λb det`, `side(L, E_ab) = λc det` with `det = N . d`, `N = (b - a) x
//! (c - a)`. So the ray passes through the closed triangle exactly when the three sides are
//! all `>= 0` or all `<= 0` (both faces), `det` is their sum, `u = w_b / det` and
//! `v = w_c / det` (`w_a = side(L, E_bc)`, `w_b = side(L, E_ca)`, `w_c = side(L, E_ab)`).
//!
//! The distance is the plane's: `t = ((a - o) . n) / (d . n)` with the unit normal `n`,
//! tested against `(0, t_max]` before the division, as the frame and watertight cells do.
//!
//! # Per-triangle and per-ray data
//!
//! - Per triangle: the three edge lines `(e, m)` (`e = q - p`, `m = p x q`, computed in `f64`
//!   and rounded once), the vertex `a` and the unit normal `n`: 8 glam vectors, 128 B in `f32`
//!   (`Vec3A` is padded to 16 B; `g3-plucker` stores the same 24 numbers in 96 B), 192 B in
//!   `f64`. A degenerate triangle (decided exactly) gets zero lines and normal: every side is
//!   0, and it is never hit.
//! - Per ray: its line `(d, o x d)` ([`PluckerRay`]).
//!
//! # Decisions and tie rule (the row's, shared with `g3-plucker`)
//!
//! The three sides, then one test that they are all `>= 0` or all `<= 0` (closed edges: a
//! ray exactly through an edge counts for both neighbours, no tie rule; NaN fails both), then
//! `det == 0` is a miss, then the distance test with the frame cells' slack (4 ulps of 1),
//! the division, `0 < t <= t_max` and `t`, `det` finite.
//!
//! Neighbours compute a shared edge's line from opposite ends: `e` and `m = p x q` are both
//! negated exactly (rounding is symmetric), so their sides are exact negatives. But a side
//! is a rounded sum of six products, whose sign may be wrong near a shared vertex: not
//! watertight. And the moments are about the world origin: a triangle far from it has long
//! moments whose difference is the side, so the edge decisions lose about as many digits as
//! the distance to the origin has over the triangle's size (as `ga-report`'s plane offset).
//!
//! # Cost per test
//!
//! 6 dot products (the sides: 18 multiplies, 15 additions), the sign test, 1 vector
//! subtraction and 2 dots (the distance), 2 additions (`det`); one division and 2 multiplies
//! for a hit.

use core::marker::PhantomData;

use glam::DVec3;
use intersect::{Algebra, Guarantees, Intersector, Method, Ray, Real, Triangle, TriangleHit};

use crate::{GlamReal, is_degenerate};

/// Plücker coordinates, the six-vector form (`NAME = "la-plucker"`).
///
/// See the [module derivation](self).
///
/// ```
/// use intersect::{Intersector, Ray, Triangle};
/// use kernels_la::Plucker;
///
/// let k = Plucker::<f64>::new();
/// let prim = k.prepare(&Triangle::new([0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [0.0, 2.0, 0.0]));
/// let ray = Ray::new([0.5, 1.0, 3.0], [0.0, 0.0, -1.0]);
/// let hit = k.intersect(&prim, &ray, &k.prepare_ray(&ray), f64::INFINITY).unwrap();
/// assert_eq!((hit.t, hit.u, hit.v), (3.0, 0.25, 0.5));
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Plucker<T>(PhantomData<T>);

impl<T> Plucker<T> {
    /// The kernel (it has no state).
    #[must_use]
    pub const fn new() -> Self {
        Self(PhantomData)
    }
}

/// What [`Plucker`] keeps of a triangle: the lines of the edges `bc`, `ca`, `ab` (directions
/// and moments), the vertex `a` and the unit normal `n`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PluckerPrim<T: GlamReal> {
    /// Edge directions `c - b`, `a - c`, `b - a` (the edge opposite `a`, `b`, `c`).
    e: [T::V; 3],
    /// Edge moments `b x c`, `c x a`, `a x b`.
    m: [T::V; 3],
    a: T::V,
    n: T::V,
}

/// What [`Plucker`] computes once per ray: its line `(d, o x d)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PluckerRay<T: GlamReal> {
    d: T::V,
    m: T::V,
}

impl<T: GlamReal> Intersector for Plucker<T> {
    type Real = T;
    type Prim = PluckerPrim<T>;
    type RayData = PluckerRay<T>;
    type Block = ();
    const NAME: &'static str = "la-plucker";
    const ALGEBRA: Algebra = Algebra::La;
    const METHOD: Method = Method::Plucker;
    const GUARANTEES: Guarantees = Guarantees { watertight: false, exact: false };
    const VARIANT: Option<&'static str> = None;

    fn prepare(&self, tri: &Triangle<T>) -> PluckerPrim<T> {
        let zero = T::splat(T::ZERO);
        let a = T::load(tri.a);
        if is_degenerate(tri) {
            return PluckerPrim { e: [zero; 3], m: [zero; 3], a, n: zero };
        }
        let round = |v: DVec3| T::load(v.to_array().map(T::from_f64));
        let [a64, b64, c64] = tri.vertices().map(|p| DVec3::from_array(p.map(Real::to_f64)));
        let normal = (b64 - a64).cross(c64 - a64);
        let edges = [(b64, c64), (c64, a64), (a64, b64)];
        PluckerPrim {
            e: edges.map(|(p, q)| round(q - p)),
            m: edges.map(|(p, q)| round(p.cross(q))),
            a,
            n: round(normal * normal.length().recip()),
        }
    }

    #[inline]
    fn prepare_ray(&self, ray: &Ray<T>) -> PluckerRay<T> {
        let d = T::load(ray.dir);
        PluckerRay { d, m: T::cross(T::load(ray.origin), d) }
    }

    #[inline]
    fn intersect(
        &self,
        prim: &PluckerPrim<T>,
        ray: &Ray<T>,
        rd: &PluckerRay<T>,
        t_max: T,
    ) -> Option<TriangleHit<T>> {
        // The permuted inner product of the ray's line with each edge's line.
        let side = |k: usize| T::dot(rd.d, prim.m[k]) + T::dot(prim.e[k], rd.m);
        let [w_a, w_b, w_c] = [side(0), side(1), side(2)];
        let zero = T::ZERO;
        let front = (w_a >= zero) & (w_b >= zero) & (w_c >= zero);
        let back = (w_a <= zero) & (w_b <= zero) & (w_c <= zero);
        if !(front | back) {
            return None;
        }
        let det = w_a + w_b + w_c;
        if det == zero {
            return None;
        }

        // t = ((a - o) . n) / (d . n), tested before dividing.
        let num = T::dot(prim.a - T::load(ray.origin), prim.n);
        let den = T::dot(rd.d, prim.n);
        let num_s = num * T::ONE.copy_sign(den);
        let slack = T::ONE + T::EPSILON * T::from_f64(4.0);
        if !(num_s > zero && num_s <= t_max * den.abs() * slack) {
            return None;
        }
        let t = num / den;
        let inv_det = T::ONE / det;
        (t > zero && t <= t_max && t.is_finite() && det.is_finite()).then(|| TriangleHit {
            t,
            u: w_b * inv_det,
            v: w_c * inv_det,
        })
    }
}
