//! The report's method (T. Chauncey, sections 3.1 to 3.3) in CGA: the report/CGA cell, the
//! twin of `la-report` (`kernels_la::Report`) and `ga-report`, everything computed per ray,
//! every step a conformal object.
//!
//! # The steps, in `la-report`'s order
//!
//! Per ray `o + t d` and triangle `a, b, c`, in the frame translated to `a` (see [`crate`],
//! "Precision"): the points `A = eₒ`, `B = eₒ + (b - a)`, `C = eₒ + (c - a)`,
//! `O = eₒ + (o - a)` (equal to `up(x)` in every product below: each one either has a factor
//! `e∞` or meets a dual plane, see the private `flat` module) and `D = d`.
//!
//! 1. **Plane from the triangle (3.1).** The plane through the three points is the
//!    quadvector `Π = A ∧ B ∧ C ∧ e∞`, and its dual `π = Π I⁻¹` the dual plane
//!    `k (n + δ e∞)`. It is normalised as `la-report` normalises `N`: `π · π = k² n²` (the
//!    `e∞` part is null: its `e4` and `e5` squares cancel exactly), one square root and one
//!    reciprocal; a zero or non-finite reciprocal (degenerate triangle) is a miss.
//! 2. **Line-plane intersection (3.2).** The dual plane evaluates the affine function
//!    `X · π = x · n - δ` of a point, and `D · π = d · n` of a direction, so the ray's point
//!    `O + t D` lies on the plane at `t = -(O · π) / (D · π)`: `la-report`'s
//!    `-((o · n) - off) / den`. (This is the meet `L & Π` of the ray's flat line
//!    `L = O ∧ D ∧ e∞` with the plane, a flat point whose weight is `den` and whose
//!    position is `o + t d`; written through the dual plane it costs two inner products
//!    instead of the ten-coefficient regressive product.) `den == 0` or a non-finite `t` is
//!    a miss, then `0 < t <= t_max`; the point is `P = eₒ + (o - a) + t d`.
//! 3. **Point in triangle (3.3).** For each edge in the report's order `ab`, `bc`, `ac`,
//!    with the remaining vertex as the reference, the edge's flat line
//!    `E = S ∧ T ∧ e∞` (`S`, `T` its points) spans two planes: `E ∧ P` through the hit point
//!    and `E ∧ R` through the third vertex. The inner product of two planes is
//!    `-(n₁ · n₂)` of their normals (the blades `e_ij45` that carry the normal square to
//!    `-1`; the `e1234`, `e1235` terms carrying `δ` cancel), so
//!    `s = -((E ∧ P) · (E ∧ R))` is `la-report`'s `A · B` (`A = e × (p - start)`,
//!    `B = e × (third - start)`): `P` is on the inner side when the two planes through the
//!    edge have the same orientation, `s >= 0`, edges closed. Each is tested before the next
//!    is computed.
//! 4. **Barycentrics from the same planes.** `E ∧ P = λ (E ∧ R)` on the triangle's plane,
//!    with `λ` the weight of the vertex opposite the edge, so `λ = s / (-(E ∧ R) · (E ∧ R))`:
//!    `u = s_ac / |B_ac|²`, `v = s_ab / |B_ab|²` as `la-report`, finite or a miss.
//!
//! # Per-triangle data, cost, tie rule
//!
//! - Per triangle: the three vertices, nothing derived (degenerate triangles stored as three
//!   copies of `a`, so `Π` is exactly 0), as five-coefficient [`Vector`]s: 60 B in `f32`, 120 B
//!   in `f64` (`la-report`: 48 B and 72 B).
//! - Per ray: nothing.
//! - Per test: 3 vector subtractions and 3 additions of `eₒ` (the points), the plane
//!   (`Vector ∧ Vector`, `∧ Vector`, `∧ e∞`: 10 + 10 + 5 coefficients), its dual (5 sign
//!   changes), `π · π` (5 multiplies, 4 additions), a square root and a reciprocal, a scale
//!   (5 multiplies), 2 inner products (`O · π`, `D · π`), a division, the point `P`, then per
//!   edge a flat line (2 outer products, 10 coefficients each), 2 planes (`Trivector ∧
//!   Vector`, 5 coefficients) and their inner product (5 multiplies), and 2 more inner
//!   products and 2 divisions for `u`, `v`. The terms the conformal model adds over
//!   `la-report` are the `eₒ`, `e∞` coefficients of every object (the `δ` parts of the
//!   planes, which cancel in each inner product, and the `e4`, `e5` halves of each point).
//! - Tie rule: none, edges are closed; not watertight. Measured from vertex `a`, so `t`
//!   keeps its digits far from the world origin (where `la-report`, measuring its plane
//!   offset from the origin, loses about three at `1e3` scene sizes).
//!
//! NaN or infinite input misses: the plane cannot be normalised, `t` is not finite, or a
//! comparison with NaN fails; nothing here can panic.

use core::marker::PhantomData;

use ga::Scalar;
use ga::cga::{Trivector, Vector};
use intersect::{Algebra, Guarantees, Intersector, Method, Ray, Triangle, TriangleHit};

use crate::flat::{point, vector};
use crate::is_degenerate;

/// The report's method in CGA, step by step, per ray (`NAME = "cga-report"`).
///
/// See the [module documentation](self) for the steps.
///
/// ```
/// use intersect::{Intersector, Ray, Triangle};
/// use kernels_cga::CgaReport;
///
/// let k = CgaReport::<f64>::new();
/// let prim = k.prepare(&Triangle::new([0.0, 0.0, -2.0], [4.0, 0.0, -2.0], [0.0, 4.0, -2.0]));
/// let ray = Ray::new([1.0, 2.0, 1.0], [0.0, 0.0, -1.0]);
/// let hit = k.intersect(&prim, &ray, &(), f64::INFINITY).unwrap();
/// assert_eq!((hit.t, hit.u, hit.v), (3.0, 0.25, 0.5));
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct CgaReport<T>(PhantomData<T>);

impl<T> CgaReport<T> {
    /// The kernel (it has no state).
    #[must_use]
    pub const fn new() -> Self {
        Self(PhantomData)
    }
}

/// What [`CgaReport`] keeps of a triangle: its three vertices, nothing derived.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct CgaReportPrim<T> {
    a: Vector<T>,
    b: Vector<T>,
    c: Vector<T>,
}

impl<T: Scalar> Intersector for CgaReport<T> {
    type Real = T;
    type Prim = CgaReportPrim<T>;
    type RayData = ();
    type Block = ();
    const NAME: &'static str = "cga-report";
    const ALGEBRA: Algebra = Algebra::Cga;
    const METHOD: Method = Method::Report;
    const GUARANTEES: Guarantees = Guarantees { watertight: false, exact: false };
    const VARIANT: Option<&'static str> = None;

    fn prepare(&self, tri: &Triangle<T>) -> CgaReportPrim<T> {
        let [a, b, c] = if is_degenerate(tri) { [tri.a; 3] } else { tri.vertices() };
        CgaReportPrim { a: vector(a), b: vector(b), c: vector(c) }
    }

    #[inline]
    fn prepare_ray(&self, _ray: &Ray<T>) {}

    #[inline]
    fn intersect(
        &self,
        prim: &CgaReportPrim<T>,
        ray: &Ray<T>,
        _: &(),
        t_max: T,
    ) -> Option<TriangleHit<T>> {
        let CgaReportPrim { a, b, c } = *prim;
        // The points in the frame translated to `a`.
        let (pa, pb, pc) = (Vector::E_O, point(b - a), point(c - a));

        // Step 1 (3.1): the plane through the points, as a normalised dual plane.
        let plane = (pa ^ pb ^ pc ^ Vector::E_INF).dual();
        let r = plane.scalar_product(plane).sqrt().recip();
        if !(r.is_finite() && r > T::ZERO) {
            return None;
        }
        let plane = plane * r;

        // Step 2 (3.2): the ray's point on the plane.
        let (o, d) = (point(vector(ray.origin) - a), vector(ray.dir));
        let den = d | plane;
        let t = -(o | plane) / den;
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
        let (s_ab, bb_ab) = edge_side(pa, pb, pc, p);
        if !inner_side(s_ab) {
            return None;
        }
        let (s_bc, _) = edge_side(pb, pc, pa, p);
        if !inner_side(s_bc) {
            return None;
        }
        let (s_ac, bb_ac) = edge_side(pa, pc, pb, p);
        if !inner_side(s_ac) {
            return None;
        }

        // Step 4: λ = s / |B|², the weight of the vertex opposite each edge.
        let (u, v) = (s_ac / bb_ac, s_ab / bb_ab);
        (u.is_finite() && v.is_finite()).then_some(TriangleHit { t, u, v })
    }
}

/// The report's edge test for the edge `start -> end` with `third` the remaining vertex, on
/// planes through the edge's flat line: `s = -((E ∧ P) · (E ∧ R))` (`>= 0` on the inner side)
/// and `-((E ∧ R) · (E ∧ R))`, the squared norm of the triangle's plane.
#[inline(always)]
fn edge_side<T: Scalar>(
    start: Vector<T>,
    end: Vector<T>,
    third: Vector<T>,
    p: Vector<T>,
) -> (T, T) {
    let edge: Trivector<T> = start ^ end ^ Vector::E_INF;
    let (through_p, through_third) = (edge ^ p, edge ^ third);
    (-(through_p | through_third), -through_third.scalar_product(through_third))
}
