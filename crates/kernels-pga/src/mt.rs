//! Moller-Trumbore (1997) in PGA: the mt/PGA cell (`pga-mt`), the twin of `la-mt`
//! (`kernels_la::MollerTrumbore`) and `g3-mt`, with every determinant a join of ideal points.
//!
//! # Derivation
//!
//! A point of the triangle is `a + u e1 + v e2` (`e1 = b - a`, `e2 = c - a`), a point of the
//! ray `o + t d`; equating them gives `[-d e1 e2] (t, u, v)^T = s` with `s = o - a`, solved by
//! Cramer's rule with four 3x3 determinants. In R(3,0,1) the vectors `d`, `e1`, `e2`, `s` are
//! ideal points (weight 0: `E1 = B - A` of two points of weight 1 is the ideal point of
//! `b - a`), and a determinant is a join: the join of two ideal points `X & Y` is the ideal
//! line with moment `x × y` (`Point & Point`: direction `w_X y - w_Y x = 0`), and its join with
//! a third ideal point `Z` is the plane through the origin-free line and `Z`, which for ideal
//! arguments has only an `e0` part: `(X & Y) & Z = -det[x y z] e0` (the generated
//! `Line & Point`'s `e0 = -(m · z)`). `la-mt`'s two shared cross products become two shared
//! ideal lines:
//!
//! ```text
//! P = D & E2          det = -((P & E1) e0)         (la-mt: e1 · (d × e2))
//! Q = S & E1          u = -((P & S) e0) / det
//!                     v = -((Q & D) e0) / det      t = -((Q & E2) e0) / det
//! ```
//!
//! # Decisions, per-triangle data, cost
//!
//! `la-mt`'s, in its order: `det == 0` or non-finite is a miss (no scale-dependent epsilon);
//! one reciprocal of `det`; `0 <= u <= 1`, then `Q`, then `v >= 0` and `u + v <= 1` (closed
//! edges, no tie rule, not watertight); then `0 < t <= t_max` with `t` finite. Each test is
//! written so that NaN fails it.
//!
//! - Per triangle: `A` (a point) and `E1`, `E2` (ideal points), 4 coefficients each: 48 B in
//!   `f32` (`la-mt`: 48 B, 3 numbers padded to 4; `g3-mt` 36 B), 96 B in `f64` (`la-mt`: 72
//!   B). A degenerate triangle (decided exactly) gets zero edges, so `det` is exactly 0.
//! - Per ray: nothing.
//! - Per test, as the generated products are written: 2 joins `Point & Point` (12 multiplies,
//!   6 subtractions each), 4 `Line & Point` (12 multiplies, 8 additions each), 1 subtraction
//!   of points (4), 1 reciprocal and 3 multiplies. Only the moments of `P`, `Q` and the `e0`
//!   parts of the planes are read: the rest (the directions `w_X y - w_Y x` and the plane
//!   normals, all multiplied by the zero weights) is dead code the compiler may drop, which
//!   leaves `la-mt`'s 2 crosses, 4 dots and reciprocal; the instruction counts of `results/`
//!   say what it keeps.

use core::marker::PhantomData;

use ga::Scalar;
use ga::pga::{Line, Point};
use intersect::{Algebra, Guarantees, Intersector, Method, Ray, Triangle, TriangleHit};

use crate::{direction, is_degenerate, point};

/// Moller-Trumbore with its determinants as joins of ideal points (`NAME = "pga-mt"`).
///
/// See the [module derivation](self).
///
/// ```
/// use intersect::{Intersector, Ray, Triangle};
/// use kernels_pga::PgaMt;
///
/// let k = PgaMt::<f32>::new();
/// let prim = k.prepare(&Triangle::new([0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [0.0, 2.0, 0.0]));
/// let ray = Ray::new([0.5, 0.5, 3.0], [0.0, 0.0, -1.0]);
/// let hit = k.intersect(&prim, &ray, &(), f32::INFINITY).unwrap();
/// assert_eq!((hit.t, hit.u, hit.v), (3.0, 0.25, 0.25));
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct PgaMt<T>(PhantomData<T>);

impl<T> PgaMt<T> {
    /// The kernel (it has no state).
    #[must_use]
    pub const fn new() -> Self {
        Self(PhantomData)
    }
}

/// What [`PgaMt`] keeps of a triangle: the point `A` and the ideal points `E1 = B - A`,
/// `E2 = C - A`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PgaMtPrim<T> {
    a: Point<T>,
    e1: Point<T>,
    e2: Point<T>,
}

impl<T: Scalar> Intersector for PgaMt<T> {
    type Real = T;
    type Prim = PgaMtPrim<T>;
    type RayData = ();
    type Block = ();
    const NAME: &'static str = "pga-mt";
    const ALGEBRA: Algebra = Algebra::Pga;
    const METHOD: Method = Method::MollerTrumbore;
    const GUARANTEES: Guarantees = Guarantees { watertight: false, exact: false };
    const VARIANT: Option<&'static str> = None;

    fn prepare(&self, tri: &Triangle<T>) -> PgaMtPrim<T> {
        let a = point(tri.a);
        if is_degenerate(tri) {
            // Zero edges make `det` exactly 0 for every ray: never hit.
            return PgaMtPrim { a, e1: Point::ZERO, e2: Point::ZERO };
        }
        PgaMtPrim { a, e1: point(tri.b) - a, e2: point(tri.c) - a }
    }

    #[inline(always)]
    fn prepare_ray(&self, _ray: &Ray<T>) {}

    #[inline]
    fn intersect(
        &self,
        prim: &PgaMtPrim<T>,
        ray: &Ray<T>,
        _: &(),
        t_max: T,
    ) -> Option<TriangleHit<T>> {
        let PgaMtPrim { a, e1, e2 } = *prim;
        let d = direction(ray.dir);
        // det[e1 d e2]: zero when the ray is parallel to the plane (as rounded).
        let p = d & e2;
        let det = volume(p, e1);
        if det == T::ZERO || !det.is_finite() {
            return None;
        }
        let inv_det = det.recip();

        let s = point(ray.origin) - a;
        let u = volume(p, s) * inv_det;
        if !(u >= T::ZERO && u <= T::ONE) {
            return None;
        }

        let q = s & e1;
        let v = volume(q, d) * inv_det;
        if !(v >= T::ZERO && u + v <= T::ONE) {
            return None;
        }

        // `t` can overflow for a nearly parallel ray (tiny `det`): an infinite `t` is no hit.
        let t = volume(q, e2) * inv_det;
        (t > T::ZERO && t <= t_max && t.is_finite()).then_some(TriangleHit { t, u, v })
    }
}

/// `det[x y z]` for the ideal line `X & Y` and the ideal point `Z`: minus the `e0`
/// coefficient of their join.
#[inline(always)]
fn volume<T: Scalar>(xy: Line<T>, z: Point<T>) -> T {
    -(xy & z).e0
}
