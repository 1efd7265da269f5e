//! The report's method (T. Chauncey, sections 3.1 to 3.3) in glam: the report/LA cell, the
//! twin of `ga-report` (`kernels_g3::G3Report`, the report/G3 cell), everything computed per
//! ray.
//!
//! # The steps, in the report's (and `ga-report`'s) order
//!
//! Per ray `o + t d` and triangle `a, b, c`:
//!
//! 1. **Plane from the triangle (3.1).** `N = (b - a) x (c - a)`, normalised with one square
//!    root and one reciprocal, `n = N / |N|`, and the plane's signed offset `off = a . n`.
//!    This is `ga-report`'s `B = (b - a) ∧ (c - a)` and `d = a · B*`: the cross product is
//!    the dual of the outer product, `(x ∧ y)* = x × y`, with the same three components. A
//!    zero or non-finite `1 / |N|` (degenerate triangle, or overflow) is a miss.
//! 2. **Line-plane intersection (3.2).** `den = d . n`,
//!    `t = -((o . n) - off) / den` (`(o ∧ B)*` and `(u ∧ B)*` are `o . n` and `d . n`), then
//!    `p = o + t d`. `den == 0` (parallel) or a non-finite `t` is a miss, then
//!    `0 < t <= t_max` is required.
//! 3. **Point in triangle (3.3).** For each edge in the report's order `ab`, `bc`, `ac`, with
//!    the remaining vertex as the reference: `A = e x (p - start)`, `B = e x (third -
//!    start)` and `s = A . B`. `ga-report`'s `A | B` of the two bivectors is `-(A . B)` of
//!    their duals (`e12 | e12 = -1`), so its `A | B <= 0` is `A . B >= 0` here: `p` is on the
//!    inner side, edges closed. Each is tested before the next is computed.
//! 4. **Barycentrics from the same vectors.** `A = λ B` with `λ` the weight of the vertex
//!    opposite the edge (see `ga-report`'s derivation), so `λ = (A . B) / (B . B)`:
//!    `u = s_ac / |B_ac|²`, `v = s_ab / |B_ab|²`, finite or a miss.
//!
//! # Per-triangle data, cost, tie rule
//!
//! - Per triangle: the three vertices, nothing derived (degenerate triangles stored as three
//!   copies of `a`, so `N` is exactly 0): 3 glam vectors, 48 B in `f32` (`Vec3A` is padded
//!   to 16 B; `ga-report` stores 36 B), 72 B in `f64`.
//! - Per ray: nothing.
//! - Per test: 2 subtractions and a cross product (`N`), a dot, a square root and a
//!   reciprocal, a scale (`n`), 3 dots (`off`, `o . n`, `d . n`), a division (`t`), a scaled
//!   add (`p`), then per edge 3 subtractions, 2 crosses and a dot, and 2 dots and 2
//!   divisions for `u`, `v`: `ga-report`'s operation for operation.
//! - Tie rule: none, edges are closed (a point on an edge is inside both neighbours); not
//!   watertight. `t` is measured through a plane offset from the world origin, so it loses
//!   about three digits at `1e3` scene sizes from it, as `ga-report` does.
//!
//! NaN or infinite input misses: the plane cannot be normalised, `t` is not finite, or a
//! comparison with NaN fails; nothing here can panic.

use core::marker::PhantomData;

use intersect::{Algebra, Guarantees, Intersector, Method, Ray, Triangle, TriangleHit};

use crate::{GlamReal, is_degenerate};

/// The report's method in glam, step by step, per ray (`NAME = "la-report"`).
///
/// See the [module documentation](self) for the steps.
///
/// ```
/// use intersect::{Intersector, Ray, Triangle};
/// use kernels_la::Report;
///
/// let k = Report::<f64>::new();
/// let prim = k.prepare(&Triangle::new([0.0, 0.0, -2.0], [4.0, 0.0, -2.0], [0.0, 4.0, -2.0]));
/// let ray = Ray::new([1.0, 2.0, 1.0], [0.0, 0.0, -1.0]);
/// let hit = k.intersect(&prim, &ray, &(), f64::INFINITY).unwrap();
/// assert_eq!((hit.t, hit.u, hit.v), (3.0, 0.25, 0.5));
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Report<T>(PhantomData<T>);

impl<T> Report<T> {
    /// The kernel (it has no state).
    #[must_use]
    pub const fn new() -> Self {
        Self(PhantomData)
    }
}

/// What [`Report`] keeps of a triangle: its three vertices, nothing derived.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ReportPrim<T: GlamReal> {
    a: T::V,
    b: T::V,
    c: T::V,
}

impl<T: GlamReal> Intersector for Report<T> {
    type Real = T;
    type Prim = ReportPrim<T>;
    type RayData = ();
    type Block = ();
    const NAME: &'static str = "la-report";
    const ALGEBRA: Algebra = Algebra::La;
    const METHOD: Method = Method::Report;
    const GUARANTEES: Guarantees = Guarantees { watertight: false, exact: false };
    const VARIANT: Option<&'static str> = None;

    fn prepare(&self, tri: &Triangle<T>) -> ReportPrim<T> {
        let [a, b, c] = if is_degenerate(tri) { [tri.a; 3] } else { tri.vertices() };
        ReportPrim { a: T::load(a), b: T::load(b), c: T::load(c) }
    }

    #[inline]
    fn prepare_ray(&self, _ray: &Ray<T>) {}

    #[inline]
    fn intersect(
        &self,
        prim: &ReportPrim<T>,
        ray: &Ray<T>,
        _: &(),
        t_max: T,
    ) -> Option<TriangleHit<T>> {
        let ReportPrim { a, b, c } = *prim;

        // Step 1 (3.1): the unit normal and the signed offset of the plane.
        let big_n = T::cross(b - a, c - a);
        let r = T::ONE / T::dot(big_n, big_n).sqrt();
        if !(r.is_finite() && r > T::ZERO) {
            return None;
        }
        let n = big_n * r;
        let offset = T::dot(a, n);

        // Step 2 (3.2): the ray's line meets the plane.
        let (o, d) = (T::load(ray.origin), T::load(ray.dir));
        let den = T::dot(d, n);
        let t = -(T::dot(o, n) - offset) / den;
        if den == T::ZERO || !t.is_finite() {
            return None;
        }
        let p = o + d * t;
        if !(t > T::ZERO && t <= t_max) {
            return None;
        }

        // Step 3 (3.3): the edges in the report's order, each against the third vertex;
        // `s >= 0` written so that NaN is outside.
        let inner_side = |s: T| s >= T::ZERO;
        let (s_ab, b_ab) = edge_side::<T>(a, b, c, p);
        if !inner_side(s_ab) {
            return None;
        }
        let (s_bc, _) = edge_side::<T>(b, c, a, p);
        if !inner_side(s_bc) {
            return None;
        }
        let (s_ac, b_ac) = edge_side::<T>(a, c, b, p);
        if !inner_side(s_ac) {
            return None;
        }

        // Step 4: λ = (A . B) / (B . B), the weight of the vertex opposite each edge.
        let u = s_ac / T::dot(b_ac, b_ac);
        let v = s_ab / T::dot(b_ab, b_ab);
        (u.is_finite() && v.is_finite()).then_some(TriangleHit { t, u, v })
    }
}

/// The report's edge test for the edge `start -> end` with `third` the remaining vertex:
/// `s = A . B` with `A = (end - start) x (p - start)` and `B = (end - start) x (third -
/// start)`. Returns `s` (`>= 0` on the inner side) and `B`.
#[inline(always)]
fn edge_side<T: GlamReal>(start: T::V, end: T::V, third: T::V, p: T::V) -> (T, T::V) {
    let edge = end - start;
    let a = T::cross(edge, p - start);
    let b = T::cross(edge, third - start);
    (T::dot(a, b), b)
}
