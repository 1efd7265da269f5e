//! Plücker coordinates in PGA, `line & line`: the plucker/PGA cell (`pga-plucker`), the twin
//! of `la-plucker` (`kernels_la::Plucker`, the six-vector form) and `g3-plucker`.
//!
//! # Derivation
//!
//! In R(3,0,1) a line is a bivector whose six coefficients are its Plücker coordinates:
//! direction `(e23, e31, e12)` and moment `(e01, e02, e03)` about the world origin
//! ([`ga::pga::geometry`]). The join of two points is the line through them, `P & Q` with
//! direction `q - p` and moment `p × q`, exactly `la-plucker`'s edge line `(q - p, p x q)`, and
//! the ray's line is `L = O & D` (the point `O` and the ideal point `D`: direction `d`, moment
//! `o × d`). The regressive product of two lines is a scalar,
//!
//! ```text
//! L1 & L2 = m1 · d2 + d1 · m2
//! ```
//!
//! `la-plucker`'s permuted inner product `side(L1, L2)`, written in the algebra: zero exactly
//! when the lines meet (or are parallel), its sign the side one passes the other. As there,
//! `L & E_pq = det[d, p - o, q - p]`, and for a ray meeting the plane at barycentrics
//! `(λa, λb, λc)`, `L & E_bc = λa det`, `L & E_ca = λb det`, `L & E_ab = λc det` with
//! `det = N · d`: the ray passes through the closed triangle exactly when the three are all
//! `>= 0` or all `<= 0`, `det` is their sum, `u = w_b / det`, `v = w_c / det`.
//!
//! The distance is the plane's: the triangle's plane `π` with a unit normal, precomputed, and
//! `t = (π & (A - O)) / (π & D)` (`A - O` the ideal point of `a - o`: `(a - o) · n`, and
//! `π & D = n · d`, `la-plucker`'s `num` and `den`), tested against `(0, t_max]` before the
//! division, as `la-plucker` does. (`-(π & O)` is the same number in exact arithmetic, but
//! loses the digits of the distance from the world origin to the plane's offset.)
//!
//! # Per-triangle and per-ray data
//!
//! - Per triangle: the three edge lines `B & C`, `C & A`, `A & B` (joined in `f64` and
//!   rounded once), the point `A` and the plane `π` (unit normal and offset, in `f64`,
//!   rounded once): 26 numbers, 104 B in `f32`, 208 B in `f64` (`la-plucker` stores the edge
//!   lines, `a` and `n`: 24 numbers padded to 128 B, 192 B; the point's weight and the
//!   plane's offset are the 2 more numbers the algebra's types carry). A
//!   degenerate triangle (decided exactly) gets zero lines and plane: every side is 0, and it
//!   is never hit.
//! - Per ray: its line `O & D` ([`PgaPluckerRay`]).
//!
//! # Decisions and tie rule (the row's, shared with `la-plucker`)
//!
//! The three sides, then one test that they are all `>= 0` or all `<= 0` (closed edges, no
//! tie rule; NaN fails both), then `det == 0` is a miss, then the distance test with the
//! frame cells' slack (4 ulps of 1), the division, `0 < t <= t_max` and `t`, `det` finite.
//! Not watertight, for `la-plucker`'s reasons: a side is a rounded sum of six products whose
//! sign may be wrong near a shared vertex, and the moments are about the world origin.
//!
//! # Cost per test
//!
//! 3 `Line & Line` (6 multiplies, 5 additions each: `la-plucker`'s 6 dot products, term for
//! term), the sign test, 2 additions (`det`), a point subtraction (4) and 2 `Plane & Point`
//! (4 multiplies, 3 additions each; `la-plucker`: a subtraction and 2 dots, 6 multiplies) for
//! the distance; one division and 2 multiplies for a hit.

use core::marker::PhantomData;

use ga::Scalar;
use ga::pga::{Line, Plane, Point};
use intersect::{Algebra, Guarantees, Intersector, Method, Ray, Real, Triangle, TriangleHit};

use kernels_g3::watertight::finish;

use crate::{direction, is_degenerate, point, round_line, round_plane, unit_plane};

/// Plücker coordinates as PGA lines, each edge test one `line & line` (`NAME =
/// "pga-plucker"`).
///
/// See the [module derivation](self).
///
/// ```
/// use intersect::{Intersector, Ray, Triangle};
/// use kernels_pga::PgaPlucker;
///
/// let k = PgaPlucker::<f64>::new();
/// let prim = k.prepare(&Triangle::new([0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [0.0, 2.0, 0.0]));
/// let ray = Ray::new([0.5, 1.0, 3.0], [0.0, 0.0, -1.0]);
/// let hit = k.intersect(&prim, &ray, &k.prepare_ray(&ray), f64::INFINITY).unwrap();
/// assert_eq!((hit.t, hit.u, hit.v), (3.0, 0.25, 0.5));
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct PgaPlucker<T>(PhantomData<T>);

impl<T> PgaPlucker<T> {
    /// The kernel (it has no state).
    #[must_use]
    pub const fn new() -> Self {
        Self(PhantomData)
    }
}

/// What [`PgaPlucker`] keeps of a triangle: the lines of the edges opposite `a`, `b`, `c`
/// (`B & C`, `C & A`, `A & B`), the vertex `A` and the plane with a unit normal.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PgaPluckerPrim<T> {
    edges: [Line<T>; 3],
    a: Point<T>,
    plane: Plane<T>,
}

/// What [`PgaPlucker`] keeps of a ray: its line `O & D`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PgaPluckerRay<T> {
    line: Line<T>,
}

impl<T: Scalar> Intersector for PgaPlucker<T> {
    type Real = T;
    type Prim = PgaPluckerPrim<T>;
    type RayData = PgaPluckerRay<T>;
    type Block = ();
    const NAME: &'static str = "pga-plucker";
    const ALGEBRA: Algebra = Algebra::Pga;
    const METHOD: Method = Method::Plucker;
    const GUARANTEES: Guarantees = Guarantees { watertight: false, exact: false };
    const VARIANT: Option<&'static str> = None;

    fn prepare(&self, tri: &Triangle<T>) -> PgaPluckerPrim<T> {
        if is_degenerate(tri) {
            return PgaPluckerPrim::default();
        }
        let [a, b, c] = tri.vertices().map(|p| point(p.map(Real::to_f64)));
        PgaPluckerPrim {
            edges: [b & c, c & a, a & b].map(round_line),
            a: point(tri.a),
            plane: round_plane(unit_plane(a, b, c)),
        }
    }

    #[inline]
    fn prepare_ray(&self, ray: &Ray<T>) -> PgaPluckerRay<T> {
        PgaPluckerRay { line: point(ray.origin) & direction(ray.dir) }
    }

    #[inline]
    fn intersect(
        &self,
        prim: &PgaPluckerPrim<T>,
        ray: &Ray<T>,
        rd: &PgaPluckerRay<T>,
        t_max: T,
    ) -> Option<TriangleHit<T>> {
        // The regressive product of the ray's line with each edge's line.
        let [w_a, w_b, w_c] = prim.edges.map(|e| rd.line & e);
        let zero = T::ZERO;
        let front = (w_a >= zero) & (w_b >= zero) & (w_c >= zero);
        let back = (w_a <= zero) & (w_b <= zero) & (w_c <= zero);
        if !(front | back) {
            return None;
        }
        // t = (π & (A - O)) / (π & D), tested before dividing, then the barycentrics.
        let plane = prim.plane;
        let (num, den) = (plane & (prim.a - point(ray.origin)), plane & direction(ray.dir));
        finish([w_a, w_b, w_c], num, den, t_max)
    }
}
