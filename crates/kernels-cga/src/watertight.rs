//! A watertight kernel in CGA: the watertight/CGA cell, the twin of `g3-watertight`
//! (`kernels_g3::G3WatertightCell`), each edge tested by the outer product of its two points
//! with the ray's flat line.
//!
//! # Derivation
//!
//! For points `P`, `Q` and a line `L`, the 5-blade `P ∧ Q ∧ L` is zero exactly when the
//! points and the line lie in one plane, that is when the edge's line `P ∧ Q ∧ e∞` meets the
//! ray's line (or is parallel to it), and its sign says on which side of the ray the edge
//! passes. With the ray's line `L = up(o) ∧ d ∧ e∞` and the vertices `up(a)`, `up(b)`,
//! `up(c)`, the three values
//!
//! ```text
//! w_a = (up(b) ∧ up(c)) ∧ L,   w_b = (up(c) ∧ up(a)) ∧ L,   w_c = (up(a) ∧ up(b)) ∧ L
//! ```
//!
//! are `g3-watertight`'s edge trivectors `((vi - o) ∧ (vj - o)) ∧ d` times `eₒ ∧ e∞`: all
//! `>= 0` or all `<= 0` exactly when the ray passes through the closed triangle, and
//! proportional to the barycentric weights (`u = w_b / det`, `v = w_c / det`,
//! `det = w_a + w_b + w_c`).
//!
//! **Evaluated in the ray's frame.** The blade is invariant under the rigid motion taking
//! `o` to the origin and `d` to `e3`, and adding a multiple of `d` to a point changes
//! nothing (`d ∧ L = 0`). So each vertex is taken to its two coordinates in the plane
//! orthogonal to the ray, `x = (v - o) · ex`, `y = (v - o) · ey` (the orthonormal basis
//! `ex`, `ey` of [`CgaWatertightRay`], as `g3-watertight`'s), as the point
//! `P = eₒ + x e1 + y e2` (equal to `up` here, since `L` has the factor `e∞`), and the ray's
//! line is the constant `L₀ = eₒ ∧ e3 ∧ e∞ = e345`. Then
//!
//! ```text
//! (P ∧ Q) ∧ L₀ = (x_P y_Q - y_P x_Q) e12345
//! ```
//!
//! exactly: the generated product sums the ten coefficients of `P ∧ Q` times those of `L₀`,
//! nine of which are exact zeros (computed as such from `eₒ`'s `∓½` and `e∞`'s `1`), so every
//! other term is `±0` and the sum is the one rounded `e12` coefficient of `P ∧ Q`,
//! `fl(fl(x_P y_Q) - fl(y_P x_Q))` (no fused multiply-add: Rust does not contract).
//!
//! # Why it is watertight
//!
//! As `g3-watertight`, whose decisions this cell calls
//! ([`kernels_g3::watertight::decide_edges`] and [`kernels_g3::watertight::finish`]): a
//! shared edge is evaluated by the neighbour as `(Q ∧ P) ∧ L₀`, the same two rounded products
//! in the other order, exactly the negated value; a non-zero value has the exact sign of
//! the projected orientation (rounding is monotonic); an exact zero sends the three values
//! to the exact fallback (`orient2d` on the projected coordinates) with the tie rule of a
//! ray moved by `ε ex + ε² ey`. The projected coordinates of a vertex depend only on the
//! vertex and the ray, so neighbours see the same ones. (The same value computed as
//! `up(a) ∧ up(b) ∧ L` in world coordinates is exactly antisymmetric too, but its sign is
//! rounded, not exact, which left cracks at vertices in `g3-watertight`'s experiments; and
//! `up(x)` stored as `½x² ± ½` would lose all digits in `f32` far from the origin.) The
//! exact fallback uses the `robust` crate's `orient2d`, outside the algebra, as
//! `g3-watertight` does: rounded arithmetic in any algebra cannot decide an exact zero.
//!
//! # Per-triangle data, cost, tie rule
//!
//! - Per triangle: the three vertices and the unit normal (for the distance, as
//!   `g3-watertight`: `t = ((a - o) · n) / (d · n)`, the dual plane `n` through `a` evaluated
//!   at the ray's point), four five-coefficient [`Vector`]s: 80 B in `f32`, 160 B in `f64`
//!   (`g3-watertight`: 48 B and 96 B).
//! - Per ray: the orthonormal basis `ex`, `ey` (a square root and two divisions).
//! - Per test: 3 five-coefficient subtractions, 6 inner products `Vector | Vector` (5
//!   multiplies and 4 additions each, two of each on zero `e4`, `e5` coefficients), 3 points
//!   (adding `eₒ`), 3 `Vector ∧ Vector` and 3 `Bivector ∧ Trivector` read at `e12345` (10
//!   products and 9 additions each, nine products on exact zeros: the compiler keeps them,
//!   since `0 × x` is not foldable in IEEE arithmetic), then `g3-watertight`'s sign test,
//!   distance test (2 inner products) and division.
//! - Tie rule: `g3-watertight`'s (an exact zero takes the sign it has for the ray moved by
//!   `ε ex + ε² ey`).

use core::marker::PhantomData;

use ga::cga::{Trivector, Vector};
use ga::lanes::Mask;
use ga::{Coefficient, Lanes4, Scalar};
use intersect::{Algebra, Guarantees, Intersector, Method, Ray, Real, Triangle, TriangleHit};
use kernels_g3::blocks::{self, BLOCK, BlockHits, BlockTest};
use kernels_g3::watertight::{decide_edges, finish};

use crate::flat::vector;
use crate::{cross64, is_degenerate, round64};

/// Watertight edge tests as outer products of points with the ray's flat line
/// (`NAME = "cga-watertight"`).
///
/// See the [module derivation](self).
///
/// ```
/// use intersect::{Intersector, Ray, Triangle};
/// use kernels_cga::CgaWatertight;
///
/// let k = CgaWatertight::<f32>::new();
/// let prim = k.prepare(&Triangle::new([0.0, 0.0, 2.0], [4.0, 0.0, 2.0], [0.0, 4.0, 2.0]));
/// let ray = Ray::new([1.0, 2.0, -1.0], [0.0, 0.0, 1.0]);
/// let hit = k.intersect(&prim, &ray, &k.prepare_ray(&ray), f32::INFINITY).unwrap();
/// assert_eq!((hit.t, hit.u, hit.v), (3.0, 0.25, 0.5));
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct CgaWatertight<T>(PhantomData<T>);

impl<T> CgaWatertight<T> {
    /// The kernel (it has no state).
    #[must_use]
    pub const fn new() -> Self {
        Self(PhantomData)
    }
}

/// What [`CgaWatertight`] keeps of a triangle: its vertices and its unit normal.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct CgaWatertightPrim<T> {
    a: Vector<T>,
    b: Vector<T>,
    c: Vector<T>,
    n: Vector<T>,
}

/// What [`CgaWatertight`] keeps of a ray: an orthonormal basis `ex`, `ey` of the plane
/// orthogonal to it, with `ex ∧ ey ∧ d` positive.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct CgaWatertightRay<T> {
    ex: Vector<T>,
    ey: Vector<T>,
}

/// What [`CgaWatertight`] keeps of [`BLOCK`] consecutive triangles for its leaf stage
/// (`kernels_g3::blocks`): the same vertices and normals as four-lane [`Vector`]s, one
/// triangle per lane (lanes past the scene's end hold zeros and are never tested). 320 B in
/// `f32`, 640 B in `f64`, beside the [`CgaWatertightPrim`]s, which the exact fallback reads.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct CgaWatertightBlock<T> {
    vertices: [Vector<Lanes4<T>>; 3],
    n: Vector<Lanes4<T>>,
}

impl<T: Scalar> Intersector for CgaWatertight<T> {
    type Real = T;
    type Prim = CgaWatertightPrim<T>;
    type RayData = CgaWatertightRay<T>;
    type Block = CgaWatertightBlock<T>;
    const BLOCK: usize = BLOCK;
    const NAME: &'static str = "cga-watertight";
    const ALGEBRA: Algebra = Algebra::Cga;
    const METHOD: Method = Method::Watertight;
    const GUARANTEES: Guarantees = Guarantees { watertight: true, exact: false };
    const VARIANT: Option<&'static str> = None;

    fn prepare(&self, tri: &Triangle<T>) -> CgaWatertightPrim<T> {
        let [a, b, c] = if is_degenerate(tri) { [tri.a; 3] } else { tri.vertices() };
        let n = if is_degenerate(tri) {
            Vector::ZERO
        } else {
            let [a64, b64, c64] = tri.vertices().map(|p| p.map(Real::to_f64));
            let sub = |p: [f64; 3], q: [f64; 3]| [p[0] - q[0], p[1] - q[1], p[2] - q[2]];
            let normal = cross64(sub(b64, a64), sub(c64, a64));
            let inv_len = normal.iter().map(|x| x * x).sum::<f64>().sqrt().recip();
            vector(round64(normal.map(|x| x * inv_len)))
        };
        CgaWatertightPrim { a: vector(a), b: vector(b), c: vector(c), n }
    }

    /// `g3-watertight`'s basis: the columns of the reflection taking `e3` to the unit
    /// direction (Frisvad's construction, Duff et al.'s branch-free form).
    #[inline]
    fn prepare_ray(&self, ray: &Ray<T>) -> CgaWatertightRay<T> {
        let dir = vector(ray.dir);
        let n = dir * dir.norm().recip();
        let sigma = T::ONE.copy_sign(n.e3);
        let k = -(sigma + n.e3).recip();
        let xy = k * n.e1 * n.e2;
        let (e1, e2) = (T::ONE + sigma * k * n.e1 * n.e1, sigma + k * n.e2 * n.e2);
        CgaWatertightRay {
            ex: vector([e1, sigma * xy, -sigma * n.e1]),
            ey: vector([xy, e2, -n.e2]),
        }
    }

    #[inline]
    fn intersect(
        &self,
        prim: &CgaWatertightPrim<T>,
        ray: &Ray<T>,
        rd: &CgaWatertightRay<T>,
        t_max: T,
    ) -> Option<TriangleHit<T>> {
        let CgaWatertightPrim { a, b, c, n } = *prim;
        let o = vector(ray.origin);
        let frame = [Vector::E_O, rd.ex, rd.ey];
        let seen = |v: Vector<T>| seen_along(v, o, frame);
        let [pa, pb, pc] = [seen(a), seen(b), seen(c)];
        let line = ray_line();
        let edge = |p, q| edge_value(p, q, line);
        // w_a is the edge opposite a, and so on.
        let w = [edge(pb, pc), edge(pc, pa), edge(pa, pb)];
        let w = decide_edges(w, || [pa, pb, pc].map(|p| [p.e1, p.e2]))?;
        let (num, den) = (-((Vector::E_O + (o - a)) | n), vector(ray.dir) | n);
        finish(w, num, den, t_max)
    }

    fn prepare_blocks(&self, prims: &[CgaWatertightPrim<T>]) -> Vec<CgaWatertightBlock<T>> {
        let split = |p: &CgaWatertightPrim<T>| {
            let parts = [p.a, p.b, p.c, p.n].map(|v| [v.e1, v.e2, v.e3, v.e4, v.e5]);
            core::array::from_fn::<T, 20, _>(|i| parts[i / 5][i % 5])
        };
        blocks::blocks_of(prims, split, |f: [Lanes4<T>; 20]| {
            let v = |i: usize| Vector {
                e1: f[i],
                e2: f[i + 1],
                e3: f[i + 2],
                e4: f[i + 3],
                e5: f[i + 4],
            };
            CgaWatertightBlock { vertices: [v(0), v(5), v(10)], n: v(15) }
        })
    }

    kernels_g3::closest_hits_in_blocks!();
}

/// A vertex `v` in the ray's frame, as the point `eₒ + x e1 + y e2` with `x = (v - o) · ex`,
/// `y = (v - o) · ey`; `[e_o, ex, ey] = frame`. Written for any coefficient: one triangle's
/// vertex in `T`, four triangles' in [`Lanes4`].
#[inline(always)]
fn seen_along<C: Coefficient>(v: Vector<C>, o: Vector<C>, frame: [Vector<C>; 3]) -> Vector<C> {
    let [e_o, ex, ey] = frame;
    let s = v - o;
    let z = C::ZERO;
    e_o + Vector { e1: s | ex, e2: s | ey, e3: z, e4: z, e5: z }
}

/// The ray's line in its own frame: `eₒ ∧ e3 ∧ e∞ = e345`.
#[inline(always)]
fn ray_line<T: Scalar>() -> Trivector<T> {
    Vector::E_O ^ Vector::E3 ^ Vector::E_INF
}

/// `(P ∧ Q) ∧ L₀` for two vertices in the ray's frame (see the module documentation).
#[inline(always)]
fn edge_value<C: Coefficient>(p: Vector<C>, q: Vector<C>, line: Trivector<C>) -> C {
    ((p ^ q) ^ line).e12345
}

/// The ray's origin, frame, line and direction in every lane, for the block tests.
pub struct WideRay<T> {
    o: Vector<Lanes4<T>>,
    frame: [Vector<Lanes4<T>>; 3],
    line: Trivector<Lanes4<T>>,
    dir: Vector<Lanes4<T>>,
}

/// `v` in every lane.
#[inline(always)]
fn wide<T: Scalar>(v: Vector<T>) -> Vector<Lanes4<T>> {
    let s = Lanes4::splat;
    Vector { e1: s(v.e1), e2: s(v.e2), e3: s(v.e3), e4: s(v.e4), e5: s(v.e5) }
}

impl<T: Scalar> BlockTest for CgaWatertight<T> {
    type Wide = WideRay<T>;

    #[inline(always)]
    fn wide(ray: &Ray<T>, rd: &CgaWatertightRay<T>) -> WideRay<T> {
        let (l, s) = (ray_line::<T>(), Lanes4::splat);
        let line = Trivector {
            e123: s(l.e123),
            e124: s(l.e124),
            e125: s(l.e125),
            e134: s(l.e134),
            e135: s(l.e135),
            e145: s(l.e145),
            e234: s(l.e234),
            e235: s(l.e235),
            e245: s(l.e245),
            e345: s(l.e345),
        };
        WideRay {
            o: wide(vector(ray.origin)),
            frame: [wide(Vector::E_O), wide(rd.ex), wide(rd.ey)],
            line,
            dir: wide(vector(ray.dir)),
        }
    }

    /// `intersect` on four triangles at once: the same products on four-lane vectors, the
    /// decisions of `kernels_g3::blocks`.
    #[inline(always)]
    fn block_test(
        block: &CgaWatertightBlock<T>,
        lanes: Mask,
        wide: &WideRay<T>,
        t_max: T,
    ) -> BlockHits<T> {
        let [a, b, c] = block.vertices;
        let seen = |v| seen_along(v, wide.o, wide.frame);
        let [pa, pb, pc] = [seen(a), seen(b), seen(c)];
        let edge = |p, q| edge_value(p, q, wide.line);
        let w = [edge(pb, pc), edge(pc, pa), edge(pa, pb)];
        let (inside, fallback) = blocks::decide_edges(w, lanes);
        if inside == 0 {
            return (0, fallback, [[T::ZERO; BLOCK]; 3]);
        }
        let n = block.n;
        let (num, den) = (-((wide.frame[0] + (wide.o - a)) | n), wide.dir | n);
        let (hits, out) = blocks::finish(w, num, den, t_max);
        (hits & inside, fallback, out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::flat::point;

    #[test]
    fn the_ray_line_in_its_frame_is_e345_and_edges_are_the_2d_orientation() {
        let line: Trivector<f64> = Vector::E_O ^ Vector::E3 ^ Vector::E_INF;
        let mut want = Trivector::ZERO;
        want.e345 = 1.0;
        assert_eq!(line, want);
        let (p, q) = (point(vector([0.1f32, 0.7, 0.0])), point(vector([-0.3f32, 0.2, 0.0])));
        let w = ((p ^ q) ^ (Vector::E_O ^ Vector::E3 ^ Vector::E_INF)).e12345;
        assert_eq!(w.to_bits(), (0.1f32 * 0.2 - 0.7 * -0.3).to_bits());
        assert_eq!(((q ^ p) ^ (Vector::E_O ^ Vector::E3 ^ Vector::E_INF)).e12345, -w);
    }
}
