//! The edge-trivector watertight method in plain G3 types: the watertight/G3 cell
//! (`g3-watertight`), beside which `ga-plucker` ([`crate::G3Watertight`], hand four-lane SIMD
//! over the triangle stored by axis) is a labelled variant.
//!
//! # The method
//!
//! [`crate::watertight`]'s, unchanged (its derivation holds here word for word). Per ray, the
//! orthonormal basis `ex`, `ey` of the plane `D = û*` orthogonal to the ray, with
//! `ex ∧ ey ∧ û = I` ([`G3WatertightRay`], the same per-ray data). Per test, each vertex
//! `v` translated, `s = v - o`, and seen along the ray as the vector of its coordinates in
//! that basis, `p = (s | ex) e1 + (s | ey) e2`: the frame `(ex, ey, û)` taken to
//! `(e1, e2, e3)`. The edge trivector of the edge from `p` to `q` is then
//!
//! ```text
//! ((s_p ∧ s_q) ∧ û)* = (p ∧ q)_e12 = p.e1 q.e2 - p.e2 q.e1
//! ```
//!
//! (the rotation of the frame keeps outer products, and `e12 ∧ e3 = e123`), which the `ga`
//! crate's `Vector ^ Vector` computes as two products and a subtraction, never fused: so
//! `(q ^ p).e12 == -(p ^ q).e12` exactly, bit for bit (shared edges), and a non-zero value
//! has the exact sign of the rounded coordinates (shared vertices). The tests of this module
//! check both on the `ga` crate's product, so that a change there that fused it would be
//! caught. An exact zero is decided as `ga-plucker` decides it: all three values recomputed
//! with Shewchuk's `orient2d` and the tie rule (a zero takes the sign it has for the ray
//! moved by `ε ex + ε² ey`), off the common path.
//!
//! # Decisions, per-triangle data, cost
//!
//! `ga-plucker`'s decisions in its order, shared (`watertight::decide_edges` and `finish`):
//! the outside test first (`w_b` or `w_c` of the other sign than `w_a`), then zeros to the
//! exact fallback, `det = w_a + w_b + w_c`, the distance `t = (s_a | n) / (u | n)` tested
//! before the division with the same slack, one division, and `u = w_b / det`,
//! `v = w_c / det`. Watertight, with the tie rule of `la` and `ga-plucker`.
//!
//! - Per triangle: the three vertices and the unit normal (computed in `f64`, rounded once),
//!   four [`Vector`]s: 48 B in `f32`, 96 B in `f64` (`ga-plucker`: the same 12 numbers by
//!   axis).
//! - Per ray: the basis (a square root and two divisions).
//! - Per test: 3 vector subtractions (9), 6 inner products of vectors (3 multiplies and 2
//!   additions each), 3 outer products of which only the `e12` part is used (2 multiplies
//!   and a subtraction each), the sign test, then 1 vector subtraction and 2 inner products
//!   for the distance: about 55 scalar operations where `ga-plucker` has about 25, most on
//!   four lanes.

use core::marker::PhantomData;

use ga::g3::Vector;
use ga::lanes::Mask;
use ga::{Coefficient, Lanes4};
use intersect::{Algebra, Guarantees, Intersector, Method, Ray, Triangle, TriangleHit};

use crate::blocks::{self, BLOCK, BlockHits, BlockTest};
use crate::real::private::Float;
use crate::watertight::{decide_edges, finish, prepare_ray, unit_normal};
use crate::{G3WatertightRay, GaReal, is_degenerate};

/// The watertight edge-trivector method written in `ga::g3` types (`NAME = "g3-watertight"`):
/// the watertight/G3 cell.
///
/// See the [module documentation](self).
///
/// ```
/// use intersect::{Intersector, Ray, Triangle};
/// use kernels_g3::G3WatertightCell;
///
/// // Two triangles sharing the edge from (1, 0, 0) to (0, 1, 0).
/// let left = Triangle::new([0.0f32, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
/// let right = Triangle::new([1.0f32, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]);
/// let k = G3WatertightCell::<f32>::new();
/// // A ray aimed at a point of the shared edge hits exactly one of them.
/// let ray = Ray::new([0.5f32, 0.5, 1.0], [0.0, 0.0, -1.0]);
/// let rd = k.prepare_ray(&ray);
/// let hits = [left, right].map(|tri| k.intersect(&k.prepare(&tri), &ray, &rd, f32::INFINITY));
/// assert_eq!(hits.iter().flatten().count(), 1);
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct G3WatertightCell<T>(PhantomData<T>);

impl<T> G3WatertightCell<T> {
    /// The kernel (it has no state).
    #[must_use]
    pub const fn new() -> Self {
        Self(PhantomData)
    }
}

/// What [`G3WatertightCell`] keeps of a triangle: its vertices as they are (neighbours must
/// see the same numbers) and its unit normal. A degenerate triangle is stored as three copies
/// of `a` with a zero normal, which no ray hits.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct G3WatertightCellPrim<T> {
    a: Vector<T>,
    b: Vector<T>,
    c: Vector<T>,
    n: Vector<T>,
}

/// What [`G3WatertightCell`] keeps of [`BLOCK`] consecutive triangles for its leaf stage
/// ([`crate::blocks`]): the same vertices and normals as four-lane [`Vector`]s, one triangle
/// per lane (lanes past the scene's end hold zeros and are never tested). 192 B in `f32`,
/// 384 B in `f64`, beside the triangles' [`G3WatertightCellPrim`]s, which the exact fallback
/// reads. (The normals read from those instead, for the lanes the ray passes inside, cost
/// a cache line more per block on incoherent rays: `results/README.md`.)
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct G3WatertightCellBlock<T> {
    vertices: [Vector<Lanes4<T>>; 3],
    n: Vector<Lanes4<T>>,
}

impl<T: GaReal> Intersector for G3WatertightCell<T> {
    type Real = T;
    type Prim = G3WatertightCellPrim<T>;
    type RayData = G3WatertightRay<T>;
    type Block = G3WatertightCellBlock<T>;
    const BLOCK: usize = BLOCK;
    const NAME: &'static str = "g3-watertight";
    const ALGEBRA: Algebra = Algebra::G3;
    const METHOD: Method = Method::Watertight;
    const GUARANTEES: Guarantees = Guarantees { watertight: true, exact: false };
    const VARIANT: Option<&'static str> = None;

    fn prepare(&self, tri: &Triangle<T>) -> G3WatertightCellPrim<T> {
        let [a, b, c] = if is_degenerate(tri) { [tri.a; 3] } else { tri.vertices() };
        let [a, b, c] = [a, b, c].map(Vector::from_array);
        G3WatertightCellPrim { a, b, c, n: unit_normal(tri) }
    }

    #[inline]
    fn prepare_ray(&self, ray: &Ray<T>) -> G3WatertightRay<T> {
        prepare_ray(ray)
    }

    #[inline]
    fn intersect(
        &self,
        prim: &G3WatertightCellPrim<T>,
        ray: &Ray<T>,
        rd: &G3WatertightRay<T>,
        t_max: T,
    ) -> Option<TriangleHit<T>> {
        intersect(prim, ray, rd, t_max)
    }

    fn prepare_blocks(&self, prims: &[G3WatertightCellPrim<T>]) -> Vec<G3WatertightCellBlock<T>> {
        let split = |p: &G3WatertightCellPrim<T>| {
            let v = [p.a, p.b, p.c, p.n].map(Vector::to_array);
            core::array::from_fn::<T, 12, _>(|i| v[i / 3][i % 3])
        };
        blocks::blocks_of(prims, split, |f: [Lanes4<T>; 12]| {
            let v = |i: usize| Vector { e1: f[i], e2: f[i + 1], e3: f[i + 2] };
            G3WatertightCellBlock { vertices: [v(0), v(3), v(6)], n: v(9) }
        })
    }

    crate::closest_hits_in_blocks!();
}

/// A vertex seen along the ray: its coordinates in the basis `ex`, `ey` of the plane
/// orthogonal to the ray, as the vector `x e1 + y e2`. Written for any coefficient: one
/// triangle's vertex in `T`, four triangles' in [`Lanes4`].
#[inline(always)]
fn seen_along<C: Coefficient>(v: Vector<C>, o: Vector<C>, [ex, ey]: [Vector<C>; 2]) -> Vector<C> {
    let s = v - o;
    Vector { e1: s | ex, e2: s | ey, e3: C::ZERO }
}

/// `((s_p ∧ s_q) ∧ û)*` for two vertices seen along the ray (see the module documentation).
#[inline(always)]
fn edge_trivector<C: Coefficient>(p: Vector<C>, q: Vector<C>) -> C {
    (p ^ q).e12
}

/// The ray's origin, basis and direction in every lane, for the block tests.
pub struct WideRay<T> {
    o: Vector<Lanes4<T>>,
    basis: [Vector<Lanes4<T>>; 2],
    dir: Vector<Lanes4<T>>,
}

impl<T: GaReal> BlockTest for G3WatertightCell<T> {
    type Wide = WideRay<T>;

    #[inline(always)]
    fn wide(ray: &Ray<T>, rd: &G3WatertightRay<T>) -> WideRay<T> {
        let wide = |v: Vector<T>| Vector {
            e1: Lanes4::splat(v.e1),
            e2: Lanes4::splat(v.e2),
            e3: Lanes4::splat(v.e3),
        };
        WideRay {
            o: wide(Vector::from_array(ray.origin)),
            basis: [wide(rd.ex), wide(rd.ey)],
            dir: wide(Vector::from_array(ray.dir)),
        }
    }

    /// [`intersect`] on four triangles at once: the same products on four-lane vectors, the
    /// decisions of [`crate::blocks`].
    #[inline(always)]
    fn block_test(
        block: &G3WatertightCellBlock<T>,
        lanes: Mask,
        wide: &WideRay<T>,
        t_max: T,
    ) -> BlockHits<T> {
        let [a, b, c] = block.vertices;
        let seen = |v| seen_along(v, wide.o, wide.basis);
        let [pa, pb, pc] = [seen(a), seen(b), seen(c)];
        let w = [edge_trivector(pb, pc), edge_trivector(pc, pa), edge_trivector(pa, pb)];
        let (inside, fallback) = blocks::decide_edges(w, lanes);
        if inside == 0 {
            return (0, fallback, [[T::ZERO; BLOCK]; 3]);
        }
        let (num, den) = ((a - wide.o) | block.n, wide.dir | block.n);
        let (hits, out) = blocks::finish(w, num, den, t_max);
        (hits & inside, fallback, out)
    }
}

#[inline(always)]
fn intersect<T: Float>(
    prim: &G3WatertightCellPrim<T>,
    ray: &Ray<T>,
    rd: &G3WatertightRay<T>,
    t_max: T,
) -> Option<TriangleHit<T>> {
    let G3WatertightCellPrim { a, b, c, n } = *prim;
    let o = Vector::from_array(ray.origin);
    let [pa, pb, pc] = [a, b, c].map(|v| seen_along(v, o, [rd.ex, rd.ey]));
    // w_a is the edge opposite a, and so on.
    let w = [edge_trivector(pb, pc), edge_trivector(pc, pa), edge_trivector(pa, pb)];
    let w = decide_edges(w, || [pa, pb, pc].map(|p| [p.e1, p.e2]))?;
    let (num, den) = ((a - o) | n, Vector::from_array(ray.dir) | n);
    finish(w, num, den, t_max)
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};
    use rand_pcg::Pcg64;
    use robust::{Coord, orient2d};

    /// The `ga` crate's outer product, as this cell uses it: swapping the two vectors negates
    /// the `e12` part exactly, and a non-zero value has the exact sign (`orient2d`), on nearly
    /// collinear points where rounding decides (`q = α p + tiny e`).
    fn outer_product_is_antisymmetric_and_exactly_signed<T: Float>() {
        let mut rng = Pcg64::seed_from_u64(0x6a_1603);
        let mut vector = |r: f64| {
            let mut x = || T::from_f64(rng.random_range(-r..r));
            Vector::new(x(), x(), T::ZERO)
        };
        let (mut zeros, mut nonzero) = (0, 0);
        for n in 0..100_000 {
            let (p, e) = (vector(1.0), vector(1.0));
            let alpha = T::from_f64(f64::from(n % 7) * 0.3 - 1.0);
            let tiny = T::from_f64(10f64.powi(-(n % 20)));
            let q = p * alpha + e * tiny;
            let w = edge_trivector(p, q);
            assert!(w == -edge_trivector(q, p), "{p:?} {q:?}");
            let point = |v: Vector<T>| Coord { x: v.e1.to_f64(), y: v.e2.to_f64() };
            let exact = orient2d(point(p), point(q), Coord { x: 0.0, y: 0.0 });
            if w == T::ZERO {
                zeros += 1;
            } else {
                nonzero += 1;
                assert_eq!(w > T::ZERO, exact > 0.0, "{p:?} {q:?}: {w:?} vs {exact}");
            }
        }
        assert!(zeros > 0 && nonzero > 50_000, "{zeros} zeros, {nonzero} non-zero");
    }

    #[test]
    fn outer_product_is_antisymmetric_and_exactly_signed_in_both_precisions() {
        outer_product_is_antisymmetric_and_exactly_signed::<f32>();
        outer_product_is_antisymmetric_and_exactly_signed::<f64>();
    }
}
