//! The closest-hit leaf stage of the watertight cells of the GA algebras: a leaf's triangles
//! four at a time ([`Intersector::intersect_leaf`]), as `la` tests them, each cell computing
//! its edge values and distance in its own algebra on four-lane multivectors
//! ([`ga::Lanes4`]). Any-hit queries keep the one-by-one loop ([`Intersector::occludes_leaf`]'s
//! default): the same block test there was 15-20% slower on the bunny's primary rays than
//! testing the triangles in turn, for reasons not found (`results/README.md`).
//!
//! A cell's block test computes, for the four triangles of a block, exactly what its
//! `intersect` computes for one: the same generated products on [`Lanes4`] coefficients,
//! whose lanes are the scalar operations in the same order. The decisions below are
//! [`crate::watertight::decide_edges`] and [`crate::watertight::finish`] lane by lane, with
//! the same operations. A lane whose edge values hold an exact zero (or NaN) is handed to the
//! cell's `intersect`, which takes the exact fallback as it would one by one. And the hits are
//! reported in lane order, each checked against the limit that the hits before it left
//! ([`intersect::report_block`], which `la`'s leaf stage calls too): the hits are those of the
//! one-by-one loop, bit for bit (`intersect::conformance::leaf` tests it).

use ga::lanes::Mask;
use ga::{Lanes4, Real};
use intersect::{Intersector, Ray, TriangleHit};

/// Triangles per block: four lanes.
pub const BLOCK: usize = 4;

/// What a cell's block test found: the lanes that hit within the limit it was given, the
/// lanes for the cell's `intersect` (an exact zero or NaN among their edge values), and
/// `t`, `u`, `v` per lane (meaningful on the hits).
pub type BlockHits<T> = (Mask, Mask, [[T; BLOCK]; 3]);

// Each cell ends its block test by calling `decide_edges`, computing its distance and calling
// `finish` itself: a shared helper that took the distance as a closure compiled slower
// (`results/README.md`).

/// [`crate::watertight::decide_edges`] on four triangles: the lanes inside (three non-zero
/// edge values of one sign) and the lanes for the exact fallback (neither proven outside nor
/// all decided), within `lanes`.
#[inline(always)]
#[must_use]
pub fn decide_edges<T: Real>(w: [Lanes4<T>; 3], lanes: Mask) -> (Mask, Mask) {
    let zero = Lanes4::splat(T::ZERO);
    let decided = |x: Lanes4<T>| zero.lt(x.abs());
    let sign = Lanes4::splat(T::ONE).copy_sign(w[0]);
    let outside = ((w[1] * sign).lt(zero) | (w[2] * sign).lt(zero)) & decided(w[0]);
    let all = decided(w[0]) & decided(w[1]) & decided(w[2]);
    (all & !outside & lanes, !all & !outside & lanes)
}

/// [`crate::watertight::finish`] on four triangles: the lanes that hit within `t_max`, and
/// `t`, `u = w_b / det`, `v = w_c / det`.
#[inline(always)]
#[must_use]
pub fn finish<T: Real>(
    [w_a, w_b, w_c]: [Lanes4<T>; 3],
    num: Lanes4<T>,
    den: Lanes4<T>,
    t_max: T,
) -> (Mask, [[T; BLOCK]; 3]) {
    let (zero, one) = (Lanes4::splat(T::ZERO), Lanes4::splat(T::ONE));
    let det = w_a + w_b + w_c;
    let num_s = num * one.copy_sign(den);
    let slack = Lanes4::splat(T::ONE + T::EPSILON * T::from_f64(4.0));
    let limit = Lanes4::splat(t_max);
    let near = !det.eq(zero) & zero.lt(num_s) & num_s.le(limit * den.abs() * slack);
    let t = num / den;
    let inv_det = one / det;
    let hit = near & zero.lt(t) & t.le(limit) & t.finite() & det.finite();
    (hit, [t.0, (w_b * inv_det).0, (w_c * inv_det).0])
}

/// A cell's test of a block: what its `intersect` computes, four triangles at a time.
pub trait BlockTest: Intersector {
    /// What the block test needs of a ray in every lane (its origin, its basis, ...), made
    /// once per leaf.
    type Wide;

    /// The ray's [`BlockTest::Wide`] data.
    fn wide(ray: &Ray<Self::Real>, rd: &Self::RayData) -> Self::Wide;

    /// The test of the triangles of `block` in `lanes` against `ray` within `t_max`.
    fn block_test(
        block: &Self::Block,
        lanes: Mask,
        ray: &Self::Wide,
        t_max: Self::Real,
    ) -> BlockHits<Self::Real>;
}

/// The closest-hit leaf query of an [`Intersector`] impl whose kernel has a [`BlockTest`]:
/// [`Intersector::intersect_leaf`] by [`intersect_leaf`]. Used inside the impl, beside
/// `type Block`, `const BLOCK` and `prepare_blocks`.
#[macro_export]
macro_rules! closest_hits_in_blocks {
    () => {
        #[inline(always)]
        fn intersect_leaf<F>(
            &self,
            prims: &[Self::Prim],
            blocks: &[Self::Block],
            ray: &intersect::Ray<Self::Real>,
            rd: &Self::RayData,
            limit: &mut Self::Real,
            found: &mut F,
        ) where
            F: FnMut(usize, intersect::TriangleHit<Self::Real>, &mut Self::Real),
        {
            $crate::blocks::intersect_leaf(self, prims, blocks, (ray, rd), limit, found);
        }
    };
}

/// [`Intersector::intersect_leaf`] for a cell with a [`BlockTest`] (see the
/// [module documentation](self)).
#[inline(always)]
pub fn intersect_leaf<I: BlockTest, F>(
    kernel: &I,
    prims: &[I::Prim],
    blocks: &[I::Block],
    (ray, rd): (&Ray<I::Real>, &I::RayData),
    limit: &mut I::Real,
    found: &mut F,
) where
    F: FnMut(usize, TriangleHit<I::Real>, &mut I::Real),
{
    let wide = I::wide(ray, rd);
    for (b, block) in blocks[..prims.len().div_ceil(BLOCK)].iter().enumerate() {
        let lanes = intersect::block_lanes::<I>(b, prims.len());
        let (hits, fallback, out) = I::block_test(block, lanes, &wide, *limit);
        intersect::report_block(kernel, prims, b, (hits, fallback), &out, (ray, rd), limit, found);
    }
}

/// The blocks of a scene's triangles, [`BLOCK`] at a time, each from the lanes' `split`
/// parts (`split(prim)` gives a triangle's part for each of a block's `N` fields); lanes past
/// the end hold zeros.
pub fn blocks_of<P, T: Real, const N: usize, B>(
    prims: &[P],
    split: impl Fn(&P) -> [T; N],
    make: impl Fn([Lanes4<T>; N]) -> B,
) -> Vec<B> {
    prims
        .chunks(BLOCK)
        .map(|chunk| {
            let mut fields = [Lanes4::splat(T::ZERO); N];
            for (l, prim) in chunk.iter().enumerate() {
                for (f, x) in fields.iter_mut().zip(split(prim)) {
                    f.0[l] = x;
                }
            }
            make(fields)
        })
        .collect()
}
