//! The report's method as written (sections 3.1 to 3.3), its errata corrected, everything
//! computed per ray.
//!
//! # The steps, in the report's order
//!
//! Per ray and triangle `a, b, c`, with the ray `o + t u` (the report's line through `a` with
//! direction `u`; here the line's point is the ray origin `o`):
//!
//! 1. **Plane from the triangle (3.1).** `b' = b - a`, `c' = c - a`, `B = b' ∧ c'`,
//!    normalised, and the plane's *signed* offset `d = a · B*` ([`Plane::try_from_triangle`]).
//!    The report prints `B = a' ∧ c'`, which is zero (erratum E2), takes `d = |a⊥B|`, which
//!    loses the side of the origin the plane is on (E3), and leaves `B` unnormalised, which
//!    the formula of step 2 cannot take (E4). A zero `B` (degenerate triangle) is a miss.
//! 2. **Line-plane intersection (3.2).** `p = o - ((o ∧ B)* - d) u / (u ∧ B)*`
//!    ([`Plane::intersect_line`]), i.e. `t = -((o ∧ B)* - d) / (u ∧ B)*`. `(u ∧ B)* = 0`
//!    means the ray is parallel to the plane: a miss. A hit needs `0 < t <= t_max`.
//! 3. **Point in triangle (3.3).** For each edge in the report's order `ab`, `bc`, `ac`, with
//!    the remaining vertex as the reference: `A = ab ∧ ap`, `B = ab ∧ ac`, `s = A | B`. The
//!    report's inner product has `e12 | e12 = -1`, so bivectors of the *same* orientation give
//!    `s < 0`: `p` is on the inner side of the edge when `s <= 0` (the report says positive,
//!    which accepts no point at all: erratum E7). `s = 0` (on the edge) counts as inside.
//!
//! # Barycentrics from the same bivectors
//!
//! For `p = a + λb (b - a) + λc (c - a)` in the plane, the edge bivector of step 3 is a
//! multiple of the reference bivector:
//!
//! ```text
//! edge ab:  A = (b - a) ∧ (p - a) = λc (b - a) ∧ (c - a) = λc B      (B = ab ∧ ac)
//! edge ac:  A = (c - a) ∧ (p - a) = λb (c - a) ∧ (b - a) = λb B      (B = ac ∧ ab)
//! edge bc:  A = (c - b) ∧ (p - b) = λa (c - b) ∧ (a - b) = λa B      (B = bc ∧ ba)
//! ```
//!
//! (each by `x ∧ x = 0` after substituting `p`). So `λ = (A | B) / (B | B) = s / (B | B)`:
//! the report's test value divided by `B | B = -|B|² < 0`. `s <= 0` is exactly `λ >= 0`, and
//! the seam's `u`, `v` (weights of `b`, `c`) are `s_ac / (B_ac | B_ac)` and
//! `s_ab / (B_ab | B_ab)`. When the computed `p` is slightly off the plane, `A | B` sees only
//! the part of `A` in the plane of `B`: the test applies to `p` projected along the normal.
//!
//! # Cost and range
//!
//! Nothing is precomputed: per test one plane (a normalisation: square root and division),
//! the intersection (a division), three pairs of edge bivectors and their inner products, and
//! two more divisions for `u`, `v`. This is the baseline the other kernels are measured
//! against. The plane's offset is measured from the world origin, so `t` loses precision
//! (cancellation in `(o ∧ B)* - d`) when the ray origin and the triangle are both far from
//! the origin but close to each other. `|B|²` must be finite and non-zero in the working
//! precision: triangles whose edges exceed about `1e19` (`f32`) or `1e154` (`f64`), or are
//! below about `1e-19` / `1e-154`, are missed.
//!
//! NaN or infinite input misses: the plane cannot be normalised, `t` is not finite, or a
//! comparison with NaN fails; nothing here can panic.

use core::marker::PhantomData;

use ga::g3::Vector;
use ga::g3::geometry::{Line, Plane};
use intersect::{Algebra, Guarantees, Intersector, Method, Ray, Triangle, TriangleHit};

use crate::real::private::Float;
use crate::{GaReal, is_degenerate};

/// The report's method, step by step, per ray (`NAME = "ga-report"`): the baseline.
///
/// See the [module documentation](self) for the steps and the
/// [crate table](crate#the-kernels) for what it guarantees and costs.
///
/// ```
/// use intersect::{Intersector, Ray, Triangle};
/// use kernels_g3::G3Report;
///
/// let k = G3Report::<f64>::new();
/// // A triangle in the plane z = -2, behind the world origin; the ray looks down from z = 1.
/// let prim = k.prepare(&Triangle::new([0.0, 0.0, -2.0], [4.0, 0.0, -2.0], [0.0, 4.0, -2.0]));
/// let ray = Ray::new([1.0, 2.0, 1.0], [0.0, 0.0, -1.0]);
/// let hit = k.intersect(&prim, &ray, &(), f64::INFINITY).unwrap();
/// assert_eq!((hit.t, hit.u, hit.v), (3.0, 0.25, 0.5));
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct G3Report<T>(PhantomData<T>);

impl<T> G3Report<T> {
    /// The kernel (it has no state).
    #[must_use]
    pub const fn new() -> Self {
        Self(PhantomData)
    }
}

/// What [`G3Report`] keeps of a triangle: its three vertices as vectors, nothing derived.
///
/// A degenerate triangle is stored as three copies of `a`, so its bivector is exactly zero for
/// every ray (see [`is_degenerate`]).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct G3ReportPrim<T> {
    a: Vector<T>,
    b: Vector<T>,
    c: Vector<T>,
}

impl<T: GaReal> Intersector for G3Report<T> {
    type Real = T;
    type Prim = G3ReportPrim<T>;
    type RayData = ();
    type Block = ();
    const NAME: &'static str = "ga-report";
    const ALGEBRA: Algebra = Algebra::G3;
    const METHOD: Method = Method::Report;
    const GUARANTEES: Guarantees = Guarantees { watertight: false, exact: false };
    const VARIANT: Option<&'static str> = None;

    fn prepare(&self, tri: &Triangle<T>) -> G3ReportPrim<T> {
        let [a, b, c] = if is_degenerate(tri) { [tri.a; 3] } else { tri.vertices() };
        G3ReportPrim {
            a: Vector::from_array(a),
            b: Vector::from_array(b),
            c: Vector::from_array(c),
        }
    }

    #[inline]
    fn prepare_ray(&self, _ray: &Ray<T>) {}

    #[inline]
    fn intersect(
        &self,
        prim: &G3ReportPrim<T>,
        ray: &Ray<T>,
        _: &(),
        t_max: T,
    ) -> Option<TriangleHit<T>> {
        intersect(prim, ray, t_max)
    }
}

/// Steps 1 to 3 and the barycentrics; see the module documentation.
#[inline]
#[allow(clippy::eq_op, reason = "B | B, a bivector's inner product with itself, is the report's")]
fn intersect<T: Float>(prim: &G3ReportPrim<T>, ray: &Ray<T>, t_max: T) -> Option<TriangleHit<T>> {
    let G3ReportPrim { a, b, c } = *prim;

    // Step 1 (3.1): B = (b - a) ∧ (c - a), normalised, with the signed offset a · B*.
    let plane = Plane::try_from_triangle(a, b, c)?;

    // Step 2 (3.2): the line through the ray origin along its direction meets the plane.
    let line = Line::new(Vector::from_array(ray.origin), Vector::from_array(ray.dir));
    let (t, p) = plane.intersect_line(&line)?;
    if !(t > T::ZERO && t <= t_max) {
        return None;
    }

    // Step 3 (3.3): the three edges in the report's order, each against the third vertex.
    // `s <= 0`, written so that NaN is outside (erratum E7: the report has `s > 0`).
    let inner_side = |s: T| s <= T::ZERO;
    let (s_ab, b_ab) = edge_side(a, b, c, p);
    if !inner_side(s_ab) {
        return None;
    }
    let (s_bc, _) = edge_side(b, c, a, p);
    if !inner_side(s_bc) {
        return None;
    }
    let (s_ac, b_ac) = edge_side(a, c, b, p);
    if !inner_side(s_ac) {
        return None;
    }

    // λ = (A | B) / (B | B): the weight of the vertex opposite each edge.
    let u = s_ac / (b_ac | b_ac);
    let v = s_ab / (b_ab | b_ab);
    (u.is_finite() && v.is_finite()).then_some(TriangleHit { t, u, v })
}

/// The report's edge test for the edge `start -> end` with `third` the remaining vertex:
/// `s = A | B` with `A = (end - start) ∧ (p - start)` and `B = (end - start) ∧ (third -
/// start)`. Returns `s` (`<= 0` on the inner side, erratum E7) and `B`.
#[inline]
fn edge_side<T: Float>(
    start: Vector<T>,
    end: Vector<T>,
    third: Vector<T>,
    p: Vector<T>,
) -> (T, ga::g3::Bivector<T>) {
    let edge = end - start;
    let a = edge ^ (p - start);
    let b = edge ^ (third - start);
    (a | b, b)
}
