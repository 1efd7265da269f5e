//! The watertight method in PGA: the watertight/PGA cell (`pga-watertight`), the twin of `la`
//! (Woop, Benthin, Wald 2013) and `g3-watertight`: each vertex seen along the ray by its
//! incidences with two planes of the ray's pencil, edge functions from those, exact signs.
//!
//! # Derivation
//!
//! Per ray, two planes `Πx`, `Πy` through the world origin whose normals `ex`, `ey` are an
//! orthonormal basis of the plane orthogonal to the ray, `ex × ey = d / |d|` (`g3-watertight`'s
//! basis, by the same formula). Moved to the ray's origin they contain the ray's line: they
//! span its pencil of planes, and a point's two incidences with them are its coordinates seen
//! along the ray. Per test each vertex is translated first, `S = V - O` (a difference of two
//! points of weight 1: the ideal point of `v - o`), and its coordinates are the regressive
//! products `x = Πx & S = ex · (v - o)`, `y = Πy & S` (the generated `Plane & Point`). The edge
//! function of the edge from `p` to `q` is the orientation of the two projected vertices,
//!
//! ```text
//! w = x_p y_q - y_p x_q = det[d, p - o, q - o] / |d|
//! ```
//!
//! which is `L & (P & Q)`, the regressive product of the ray's line with the edge's line, up to
//! the positive factor `|d|`: for a ray meeting the plane at barycentrics `(λa, λb, λc)`,
//! `w_a = λa det`, `w_b = λb det`, `w_c = λc det`, and the ray passes through the closed
//! triangle exactly when the three are all `>= 0` or all `<= 0`, `det` their sum,
//! `u = w_b / det`, `v = w_c / det`.
//!
//! # Why not `L & E` with shared edge lines
//!
//! Edge lines joined once per edge (in `f64`, in a canonical vertex order, so that neighbours
//! store the same six numbers up to sign) give exactly antisymmetric values on shared edges,
//! but each value is a rounded sum of six products, whose sign is not exact: around a shared
//! vertex, where all the values are near zero, rounded signs can leave every triangle of the
//! fan rejecting the ray (a crack), and a fallback taken only on exact zeros never sees it
//! (the G3 row measured 1.5% of vertex-aimed rays lost by the 3D form of the same values, see
//! `kernels_g3::watertight`). The coordinates above are per vertex, shared by every triangle
//! that has the vertex, so the signs below are the exact orientations of one planar picture.
//!
//! # Why it is watertight (as `la` and `g3-watertight`)
//!
//! 1. **Shared edges.** `x_p y_q` and `y_p x_q` are two rounded products (never fused), and
//!    the neighbour computes `x_q y_p - y_q x_p`: exactly `-w`, bit for bit.
//! 2. **Shared vertices.** Rounding is monotonic, so a non-zero computed `w` has the exact
//!    sign of `x_p y_q - y_p x_q` for the rounded coordinates; an exact zero may hide either
//!    sign, so then all three are recomputed exactly (Shewchuk's `orient2d`).
//! 3. **Ties.** An exact zero takes the sign it has for the ray moved by `ε ex + ε² ey`: the
//!    sign of `y_p - y_q`, or if 0 of `x_q - x_p` (both 0: the edge is parallel to the ray,
//!    a miss), as in `g3-watertight` and `la` (whose perturbation is `(ε, ε²)` in its sheared
//!    plane). Exactly one of two neighbours owns a shared edge.
//!
//! # Decisions, per-triangle data, cost
//!
//! `g3-watertight`'s decisions in its order: the outside test first (`w_b` or `w_c` of the
//! other sign than a non-zero `w_a`), then zeros to the exact fallback, `det`, the distance
//! `t = (π & (A - O)) / (π & D)` from the triangle's plane with a unit normal (`A - O` the
//! ideal point of `a - o`, so that no digits are lost to the distance from the world origin:
//! `π & A = 0`, so this is `-(π & O)`), tested before the division with the frame cells'
//! slack, one division, the barycentrics.
//!
//! - Per triangle: the three vertices as [`Point`]s (neighbours must see the same numbers) and
//!   the plane (unit normal, offset: `f64`, rounded once): 16 numbers, 64 B in `f32`, 128 B in
//!   `f64` (`la`: 3 vertices, 48 B and 72 B; `g3-watertight`: vertices and normal, 48 B, 96
//!   B). A degenerate triangle is stored as three copies of `a` with a zero plane.
//! - Per ray: the planes `Πx`, `Πy` ([`PgaWatertightRay`]: a square root and two divisions).
//! - Per test, as the generated products are written: 3 point subtractions (4 each), 6
//!   `Plane & Point` (4 multiplies, 3 additions each: the `e0 · e123` term is `0 · 0`), 3 edge
//!   functions (2 multiplies, 1 subtraction each), the sign test, then a point subtraction
//!   and 2 `Plane & Point` for the distance: about 75 operations before the distance test where
//!   `la` has about 20 (its shear has one coordinate fewer per vertex and no square root per ray).

use core::marker::PhantomData;

use ga::lanes::Mask;
use ga::pga::{Plane, Point};
use ga::{Coefficient, Lanes4, Scalar};
use intersect::{Algebra, Guarantees, Intersector, Method, Ray, Real, Triangle, TriangleHit};
use kernels_g3::blocks::{self, BLOCK, BlockHits, BlockTest};
use kernels_g3::watertight::finish;
use robust::{Coord, orient2d};

use crate::{direction, is_degenerate, point, round_plane, unit_plane};

/// The watertight method in PGA (`NAME = "pga-watertight"`): vertices seen along the ray by
/// two planes of its pencil, exactly antisymmetric and exactly signed edge functions.
///
/// See the [module documentation](self).
///
/// ```
/// use intersect::{Intersector, Ray, Triangle};
/// use kernels_pga::PgaWatertight;
///
/// // Two triangles sharing the edge from (1, 0, 0) to (0, 1, 0).
/// let left = Triangle::new([0.0f32, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
/// let right = Triangle::new([1.0f32, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]);
/// let k = PgaWatertight::<f32>::new();
/// // A ray aimed at a point of the shared edge hits exactly one of them.
/// let ray = Ray::new([0.5f32, 0.5, 1.0], [0.0, 0.0, -1.0]);
/// let rd = k.prepare_ray(&ray);
/// let hits = [left, right].map(|tri| k.intersect(&k.prepare(&tri), &ray, &rd, f32::INFINITY));
/// assert_eq!(hits.iter().flatten().count(), 1);
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct PgaWatertight<T>(PhantomData<T>);

impl<T> PgaWatertight<T> {
    /// The kernel (it has no state).
    #[must_use]
    pub const fn new() -> Self {
        Self(PhantomData)
    }
}

/// What [`PgaWatertight`] keeps of a triangle: its vertices as they are and its plane.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PgaWatertightPrim<T> {
    vertices: [Point<T>; 3],
    plane: Plane<T>,
}

/// What [`PgaWatertight`] keeps of a ray: the planes `Πx`, `Πy` through the origin whose
/// normals are an orthonormal basis orthogonal to the ray, `ex × ey = d / |d|`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PgaWatertightRay<T> {
    x: Plane<T>,
    y: Plane<T>,
}

/// What [`PgaWatertight`] keeps of [`BLOCK`] consecutive triangles for its leaf stage
/// (`kernels_g3::blocks`): the same vertices and planes as four-lane [`Point`]s and
/// [`Plane`]s, one triangle per lane (lanes past the scene's end hold zeros and are never
/// tested). 256 B in `f32`, 512 B in `f64`, beside the [`PgaWatertightPrim`]s, which the
/// exact fallback reads.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PgaWatertightBlock<T> {
    vertices: [Point<Lanes4<T>>; 3],
    plane: Plane<Lanes4<T>>,
}

impl<T: Scalar> Intersector for PgaWatertight<T> {
    type Real = T;
    type Prim = PgaWatertightPrim<T>;
    type RayData = PgaWatertightRay<T>;
    type Block = PgaWatertightBlock<T>;
    const BLOCK: usize = BLOCK;
    const NAME: &'static str = "pga-watertight";
    const ALGEBRA: Algebra = Algebra::Pga;
    const METHOD: Method = Method::Watertight;
    const GUARANTEES: Guarantees = Guarantees { watertight: true, exact: false };
    const VARIANT: Option<&'static str> = None;

    fn prepare(&self, tri: &Triangle<T>) -> PgaWatertightPrim<T> {
        if is_degenerate(tri) {
            return PgaWatertightPrim { vertices: [point(tri.a); 3], plane: Plane::ZERO };
        }
        let [a, b, c] = tri.vertices().map(|p| point(p.map(Real::to_f64)));
        PgaWatertightPrim {
            vertices: tri.vertices().map(point),
            plane: round_plane(unit_plane(a, b, c)),
        }
    }

    #[inline]
    fn prepare_ray(&self, ray: &Ray<T>) -> PgaWatertightRay<T> {
        // g3-watertight's basis: Duff et al.'s branchless orthonormal basis of û.
        let [d1, d2, d3] = ray.dir;
        let r = (d1 * d1 + d2 * d2 + d3 * d3).sqrt().recip();
        let (n1, n2, n3) = (d1 * r, d2 * r, d3 * r);
        let sigma = T::ONE.copy_sign(n3);
        let k = -(sigma + n3).recip();
        let xy = k * n1 * n2;
        PgaWatertightRay {
            x: Plane::new(T::ZERO, T::ONE + sigma * k * n1 * n1, sigma * xy, -sigma * n1),
            y: Plane::new(T::ZERO, xy, sigma + k * n2 * n2, -n2),
        }
    }

    #[inline]
    fn intersect(
        &self,
        prim: &PgaWatertightPrim<T>,
        ray: &Ray<T>,
        rd: &PgaWatertightRay<T>,
        t_max: T,
    ) -> Option<TriangleHit<T>> {
        let o = point(ray.origin);
        // Each vertex translated to the ray's origin and seen along the ray.
        let [pa, pb, pc] = prim.vertices.map(|v| {
            let s = v - o;
            [rd.x & s, rd.y & s]
        });
        // w_a is the edge opposite a, and so on.
        let w = [edge(pb, pc), edge(pc, pa), edge(pa, pb)];
        let w = decide_edges(w, [pa, pb, pc])?;
        // t = (π & (A - O)) / (π & D): `a - o` first, as `la` and `g3-watertight` translate.
        let plane = prim.plane;
        finish(w, plane & (prim.vertices[0] - o), plane & direction(ray.dir), t_max)
    }

    fn prepare_blocks(&self, prims: &[PgaWatertightPrim<T>]) -> Vec<PgaWatertightBlock<T>> {
        let split = |p: &PgaWatertightPrim<T>| {
            let [a, b, c] = p.vertices.map(|v| [v.e021, v.e013, v.e032, v.e123]);
            let n = [p.plane.e0, p.plane.e1, p.plane.e2, p.plane.e3];
            let parts = [a, b, c, n];
            core::array::from_fn::<T, 16, _>(|i| parts[i / 4][i % 4])
        };
        blocks::blocks_of(prims, split, |f: [Lanes4<T>; 16]| {
            let v = |i: usize| Point { e021: f[i], e013: f[i + 1], e032: f[i + 2], e123: f[i + 3] };
            let plane = Plane { e0: f[12], e1: f[13], e2: f[14], e3: f[15] };
            PgaWatertightBlock { vertices: [v(0), v(4), v(8)], plane }
        })
    }

    kernels_g3::closest_hits_in_blocks!();
}

/// The ray's origin, planes and direction in every lane, for the block tests.
pub struct WideRay<T> {
    o: Point<Lanes4<T>>,
    x: Plane<Lanes4<T>>,
    y: Plane<Lanes4<T>>,
    dir: Point<Lanes4<T>>,
}

impl<T: Scalar> BlockTest for PgaWatertight<T> {
    type Wide = WideRay<T>;

    #[inline(always)]
    fn wide(ray: &Ray<T>, rd: &PgaWatertightRay<T>) -> WideRay<T> {
        let s = Lanes4::splat;
        let point = |p: Point<T>| Point {
            e021: s(p.e021),
            e013: s(p.e013),
            e032: s(p.e032),
            e123: s(p.e123),
        };
        let plane = |p: Plane<T>| Plane { e0: s(p.e0), e1: s(p.e1), e2: s(p.e2), e3: s(p.e3) };
        WideRay {
            o: point(crate::point(ray.origin)),
            x: plane(rd.x),
            y: plane(rd.y),
            dir: point(direction(ray.dir)),
        }
    }

    /// `intersect` on four triangles at once: the same products on four-lane points and
    /// planes, the decisions of `kernels_g3::blocks`.
    #[inline(always)]
    fn block_test(
        block: &PgaWatertightBlock<T>,
        lanes: Mask,
        wide: &WideRay<T>,
        t_max: T,
    ) -> BlockHits<T> {
        let [a, b, c] = block.vertices;
        let seen = |v: Point<Lanes4<T>>| {
            let s = v - wide.o;
            [wide.x & s, wide.y & s]
        };
        let [pa, pb, pc] = [seen(a), seen(b), seen(c)];
        let w = [edge(pb, pc), edge(pc, pa), edge(pa, pb)];
        let (inside, fallback) = blocks::decide_edges(w, lanes);
        if inside == 0 {
            return (0, fallback, [[T::ZERO; BLOCK]; 3]);
        }
        let (num, den) = (block.plane & (a - wide.o), block.plane & wide.dir);
        let (hits, out) = blocks::finish(w, num, den, t_max);
        (hits & inside, fallback, out)
    }
}

/// The edge function of two vertices seen along the ray, `x_p y_q - y_p x_q`, with separate
/// multiplies and a subtraction so that `edge(q, p) == -edge(p, q)` exactly.
#[inline(always)]
fn edge<C: Coefficient>(p: [C; 2], q: [C; 2]) -> C {
    p[0] * q[1] - p[1] * q[0]
}

/// `g3-watertight`'s sign decisions: outside first, then the exact fallback for zeros (and
/// NaN), else the three non-zero values of one sign.
#[inline(always)]
fn decide_edges<T: Scalar>(w: [T; 3], points: [[T; 2]; 3]) -> Option<[T; 3]> {
    let decided = |x: T| x.abs() > T::ZERO;
    let sign = T::ONE.copy_sign(w[0]);
    if ((w[1] * sign < T::ZERO) | (w[2] * sign < T::ZERO)) & decided(w[0]) {
        return None;
    }
    if decided(w[0]) & decided(w[1]) & decided(w[2]) { Some(w) } else { inside_exact(points) }
}

/// The three edge functions recomputed exactly (`orient2d`), each exact zero given its tie
/// sign; `Some` with the exact values rounded (zeros kept) if all three signs agree.
#[cold]
fn inside_exact<T: Scalar>(p: [[T; 2]; 3]) -> Option<[T; 3]> {
    if !p.iter().flatten().all(|x| x.is_finite()) {
        return None;
    }
    let coord = |q: [T; 2]| Coord { x: q[0].to_f64(), y: q[1].to_f64() };
    let origin = Coord { x: 0.0, y: 0.0 };
    let edges = [(1, 2), (2, 0), (0, 1)];
    // orient2d(p, q, 0) = x_p y_q - y_p x_q, exactly signed.
    let w = edges.map(|(i, j)| orient2d(coord(p[i]), coord(p[j]), origin));
    let sign = |v: T| i8::from(v > T::ZERO) - i8::from(v < T::ZERO);
    let signs: [i8; 3] = core::array::from_fn(|k| {
        let (i, j) = edges[k];
        if w[k] == 0.0 {
            match sign(p[i][1] - p[j][1]) {
                0 => sign(p[j][0] - p[i][0]),
                s => s,
            }
        } else {
            sign(T::from_f64_keep_sign(w[k]))
        }
    });
    if !(signs[0] != 0 && signs[0] == signs[1] && signs[1] == signs[2]) {
        return None;
    }
    Some(w.map(T::from_f64_keep_sign))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The per-ray planes have orthonormal normals orthogonal to the ray, right-handed
    /// (`ex × ey` along `d`), for the axes (both signs) and an oblique direction.
    #[test]
    fn pencil_planes_are_an_orthonormal_basis() {
        let dirs = [[0.0, 0.0, 1.0], [0.0, 0.0, -1.0], [1.0, 0.0, 0.0], [0.0, -3.0, 0.0]];
        for dir in dirs.into_iter().chain([[1.0, 2.0, -2.0]]) {
            let rd = PgaWatertight::<f64>::new().prepare_ray(&Ray::new([0.0; 3], dir));
            let (ex, ey) = (rd.x.normal(), rd.y.normal());
            let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
            let len = dot(dir, dir).sqrt();
            let cross = [
                ex[1] * ey[2] - ex[2] * ey[1],
                ex[2] * ey[0] - ex[0] * ey[2],
                ex[0] * ey[1] - ex[1] * ey[0],
            ];
            for (got, want) in [(dot(ex, ex), 1.0), (dot(ey, ey), 1.0), (dot(ex, ey), 0.0)] {
                assert!((got - want).abs() < 1e-15, "{dir:?}");
            }
            assert!(dot(ex, dir).abs() < 1e-15 && dot(ey, dir).abs() < 1e-15, "{dir:?}");
            assert!((dot(cross, dir) - len).abs() < 1e-14, "{dir:?}: {cross:?}");
            assert_eq!((rd.x.e0, rd.y.e0), (0.0, 0.0));
        }
    }

    /// Swapping two vertices negates the edge function exactly, whatever the rounding.
    #[test]
    fn edge_function_is_exactly_antisymmetric() {
        let mut x = 0.1234f32;
        for _ in 0..10_000 {
            let mut next = || {
                x = (x * 3.7 + 0.31).fract() - 0.5;
                x
            };
            let (p, q) = ([next(), next()], [next(), next() * 1e-3]);
            assert_eq!(edge(p, q), -edge(q, p), "{p:?} {q:?}");
        }
    }
}
