//! The report's method (T. Chauncey, sections 3.1 to 3.3) in PGA: the report/PGA cell
//! (`pga-report`), the twin of `la-report` (`kernels_la::Report`) and `ga-report`
//! (`kernels_g3::G3Report`), everything computed per ray.
//!
//! # The steps, in `la-report`'s order, in R(3,0,1)
//!
//! Per ray `o + t d` (the point `O` and the ideal point `D` of its direction) and triangle
//! `A, B, C` (points of weight 1):
//!
//! 1. **Plane from the triangle (3.1).** The join of `A` with the ideal points of the two
//!    edges, `Π = (A & (B - A)) & (C - A)`: the generated `Line & Point` gives the normal
//!    `N = (b - a) × (c - a)` and the `e0` coefficient `-(a × (b - a)) · (c - a) = -a · N`,
//!    `la-report`'s `N` and `-off` (`A & B & C` is the same plane, but sums its normal from
//!    the moments `a × b`, which cancel far from the world origin). Normalised by one square root
//!    and one reciprocal of its norm (`|N|`, the blades without `e0`): `π = Π / |N|`. A zero or
//!    non-finite reciprocal (degenerate triangle, overflow) is a miss.
//! 2. **Line-plane intersection (3.2).** The ray's line is the join `L = O & D` (direction
//!    `d`, moment `o × d`) and its meet with the plane the homogeneous point `X = L ^ π`,
//!    `(n × (o × d) - c d, n · d)` ([`Line::meet_plane`](ga::pga::Line::meet_plane)). Its
//!    weight `den = n · d` is `la-report`'s denominator, and `t` is read from the plane as
//!    there: `t = -(π & O) / den` (`π & O = n · o + c`, `la-report`'s `o · n - off`).
//!    `den == 0` (parallel: `X` is ideal) or a non-finite `t` is a miss, then
//!    `0 < t <= t_max`. The point is divided once, `x = X / den`, for the edge tests.
//! 3. **Point in triangle (3.3).** For each edge in the report's order `ab`, `bc`, `ac`, with
//!    the remaining vertex as the reference, seen from `start` as `la-report` measures: the
//!    edge's line through the origin `E = E123 & (end - start)`, the planes it spans with
//!    the ideal points `x - start` and `third - start`, whose normals are `la-report`'s
//!    `(end - start) × (x - start)` and `(end - start) × (third - start)` (and whose `e0`
//!    parts are 0), and `s = (E & (x - start)) | (E & (third - start))` (the inner product of
//!    two planes is the dot product of their normals): `s >= 0` puts `x` on the inner side,
//!    edges closed. Each is tested before the next is computed.
//! 4. **Barycentrics from the same planes.** `E & (x - start) = λ (E & (third - start))`, `λ`
//!    the weight of the vertex opposite the edge, so `λ = s / |E & (third - start)|²`:
//!    `u = s_ac / |R_ac|²`, `v = s_ab / |R_ab|²` (`R` the reference plane of the edge, `|R|²`
//!    its `norm_squared`, `R | R`), finite or a miss.
//!
//! # Per-triangle data, cost, tie rule
//!
//! - Per triangle: the three vertices as [`Point`]s (the algebra's points carry a weight, so 4
//!   coefficients each where `la-report` stores 3 padded to 4): 48 B in `f32`, 96 B in `f64`
//!   (`la-report`: 48 B, 72 B). A degenerate triangle is stored as three copies of `a`, so its
//!   plane is exactly 0.
//! - Per ray: nothing.
//! - Per test, as the generated products are written: the plane (2 point subtractions, a
//!   `Point & Point`, 12 multiplies and 6 subtractions, then a `Line & Point`, 12 multiplies
//!   and 8 additions),
//!   its norm (3 multiplies, 2 additions, a square root, a reciprocal) and scale (4
//!   multiplies), the ray's line (12 multiplies, 6 subtractions), the meet `Line ^ Plane`
//!   (12 multiplies, 8 additions), `π & O` (4 multiplies, 3 additions), a division (`t`) and
//!   a reciprocal and 4 multiplies (`x`); then per edge 3 point subtractions, a join (12 and
//!   6), two `Line & Point` (12 and 8 each) and a `Plane | Plane` (3 and 2), and 2 more inner
//!   products and 2 divisions for `u`, `v`. The `e0` parts of the edge planes and the ideal
//!   parts of the point products that nothing reads are dead code the compiler may drop;
//!   what it keeps is what the instruction counts of `results/` measure. `la-report` does the
//!   same steps with 3-component crosses and dots, so this cell computes the homogeneous
//!   coordinate and the `e0` offsets on top of `la-report`'s work.
//! - Tie rule: none, edges are closed; not watertight. `t` is measured through a plane offset
//!   from the world origin, as `la-report` and `ga-report` do.
//!
//! NaN or infinite input misses: the plane cannot be normalised, `t` is not finite, or a
//! comparison with NaN fails; nothing here can panic.

use core::marker::PhantomData;

use ga::Scalar;
use ga::pga::{Line, Plane, Point};
use intersect::{Algebra, Guarantees, Intersector, Method, Ray, Triangle, TriangleHit};

use crate::{direction, is_degenerate, plane_through, point};

/// The report's method in PGA, step by step, per ray (`NAME = "pga-report"`).
///
/// See the [module documentation](self) for the steps.
///
/// ```
/// use intersect::{Intersector, Ray, Triangle};
/// use kernels_pga::PgaReport;
///
/// let k = PgaReport::<f64>::new();
/// let prim = k.prepare(&Triangle::new([0.0, 0.0, -2.0], [4.0, 0.0, -2.0], [0.0, 4.0, -2.0]));
/// let ray = Ray::new([1.0, 2.0, 1.0], [0.0, 0.0, -1.0]);
/// let hit = k.intersect(&prim, &ray, &(), f64::INFINITY).unwrap();
/// assert_eq!((hit.t, hit.u, hit.v), (3.0, 0.25, 0.5));
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct PgaReport<T>(PhantomData<T>);

impl<T> PgaReport<T> {
    /// The kernel (it has no state).
    #[must_use]
    pub const fn new() -> Self {
        Self(PhantomData)
    }
}

/// What [`PgaReport`] keeps of a triangle: its three vertices as points, nothing derived.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PgaReportPrim<T> {
    a: Point<T>,
    b: Point<T>,
    c: Point<T>,
}

impl<T: Scalar> Intersector for PgaReport<T> {
    type Real = T;
    type Prim = PgaReportPrim<T>;
    type RayData = ();
    type Block = ();
    const NAME: &'static str = "pga-report";
    const ALGEBRA: Algebra = Algebra::Pga;
    const METHOD: Method = Method::Report;
    const GUARANTEES: Guarantees = Guarantees { watertight: false, exact: false };
    const VARIANT: Option<&'static str> = None;

    fn prepare(&self, tri: &Triangle<T>) -> PgaReportPrim<T> {
        let [a, b, c] = if is_degenerate(tri) { [tri.a; 3] } else { tri.vertices() };
        PgaReportPrim { a: point(a), b: point(b), c: point(c) }
    }

    #[inline]
    fn prepare_ray(&self, _ray: &Ray<T>) {}

    #[inline]
    fn intersect(
        &self,
        prim: &PgaReportPrim<T>,
        ray: &Ray<T>,
        _: &(),
        t_max: T,
    ) -> Option<TriangleHit<T>> {
        let PgaReportPrim { a, b, c } = *prim;

        // Step 1 (3.1): the plane through the three points, normalised.
        let plane = plane_through(a, b, c);
        let r = plane.norm().recip();
        if !(r.is_finite() && r > T::ZERO) {
            return None;
        }
        let plane = plane * r;

        // Step 2 (3.2): the ray's line meets the plane in a homogeneous point.
        let (o, d) = (point(ray.origin), direction(ray.dir));
        let x = (o & d) ^ plane;
        let den = x.weight();
        let t = -(plane & o) / den;
        if den == T::ZERO || !t.is_finite() {
            return None;
        }
        let x = x * den.recip();
        if !(t > T::ZERO && t <= t_max) {
            return None;
        }

        // Step 3 (3.3): the edges in the report's order, each against the third vertex;
        // `s >= 0` written so that NaN is outside.
        let inner_side = |s: T| s >= T::ZERO;
        let (s_ab, b_ab) = edge_side(a, b, c, x);
        if !inner_side(s_ab) {
            return None;
        }
        let (s_bc, _) = edge_side(b, c, a, x);
        if !inner_side(s_bc) {
            return None;
        }
        let (s_ac, b_ac) = edge_side(a, c, b, x);
        if !inner_side(s_ac) {
            return None;
        }

        // Step 4: λ = s / |E & third|² (the plane's `norm_squared`, its `P | P`).
        let u = s_ac / b_ac.norm_squared();
        let v = s_ab / b_ab.norm_squared();
        (u.is_finite() && v.is_finite()).then_some(TriangleHit { t, u, v })
    }
}

/// The report's edge test for the edge `start -> end` with `third` the remaining vertex, seen
/// from `start`: `s = (E & (x - start)) | (E & (third - start))` with `E` the edge's line
/// through the origin, `>= 0` on the inner side, and the plane `E & (third - start)`.
#[inline(always)]
fn edge_side<T: Scalar>(
    start: Point<T>,
    end: Point<T>,
    third: Point<T>,
    x: Point<T>,
) -> (T, Plane<T>) {
    let edge: Line<T> = Point::from_xyz(T::ZERO, T::ZERO, T::ZERO) & (end - start);
    let reference = edge & (third - start);
    ((edge & (x - start)) | reference, reference)
}
