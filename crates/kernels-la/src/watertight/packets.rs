//! Several rays against one triangle at a time: the leaf stage of packet traversal
//! ([`Intersector::intersect_group`]), steps 2-8 of the kernel for [`LANES`] rays in the lanes
//! of plain arrays, which the compiler vectorises (AVX2: eight `f32` lanes in one register).
//! See [Several pairs at once](super#several-pairs-at-once) for why the hits are those of
//! [`Intersector::intersect`], bit for bit.

use intersect::{Intersector, Ray, TriangleHit};

use super::{Watertight, WatertightPrim, WatertightRay};
use crate::GlamReal;

impl<T: GlamReal> Watertight<T> {
    /// One block of rays of [`Intersector::intersect_group`]: every triangle in turn against the
    /// block's lanes, reporting each lane's hit in order of its ray.
    #[allow(clippy::too_many_arguments)] // the group's parts, as the trait hands them over
    #[inline(always)]
    pub(super) fn rays<F>(
        &self,
        block: &Rays<T>,
        k: [u32; 3],
        prims: &[WatertightPrim<T>],
        rays: &[Ray<T>],
        data: &[WatertightRay<T>],
        limits: &mut [T],
        found: &mut F,
    ) where
        F: FnMut(usize, usize, TriangleHit<T>, &mut T),
    {
        let [kx, ky, kz] = k.map(|a| a as usize);
        let (members, n) = (&block.members, block.n);
        let live = (1u32 << n) - 1;
        let (mut e, mut z, mut out) =
            ([[T::ZERO; LANES]; 3], [[T::ZERO; LANES]; 3], [[T::ZERO; LANES]; 3]);
        for (p, prim) in prims.iter().enumerate() {
            let rows = [kx, ky, kz].map(|a| T::lanes(prim.axes[a]));
            let (candidates, zeros) = block.edges(rows, &mut e, &mut z);
            let mut hits = 0;
            if candidates & live != 0 {
                let lane_limits: [T; LANES] =
                    core::array::from_fn(|l| limits[members[l.min(n - 1)]]);
                hits = block.distances(&e, &z, &lane_limits, &mut out) & candidates;
            }
            let mut report = (hits | zeros) & live;
            while report != 0 {
                let l = report.trailing_zeros() as usize;
                report &= report - 1;
                let r = members[l];
                let hit = if zeros >> l & 1 == 1 {
                    self.intersect(prim, &rays[r], &data[r], limits[r])
                } else {
                    Some(TriangleHit { t: out[0][l], u: out[1][l], v: out[2][l] })
                };
                if let Some(hit) = hit {
                    found(r, p, hit, &mut limits[r]);
                }
            }
        }
    }
}

/// Rays per block of [`Intersector::intersect_group`] for [`Watertight`].
pub const LANES: usize = 16;

/// The lanes of one block of rays of [`Intersector::intersect_group`]: rays `members[..n]` of the
/// group, which share the permutation `k`, as structure of arrays (lanes past `n` repeat the
/// last ray and are never reported).
pub(super) struct Rays<T> {
    n: usize,
    members: [usize; LANES],
    origin: [[T; LANES]; 3],
    shear: [[T; LANES]; 3],
}

impl<T: GlamReal> Rays<T> {
    pub(super) fn new(data: &[WatertightRay<T>], members: [usize; LANES], n: usize) -> Self {
        let at = |l: usize| &data[members[l.min(n - 1)]];
        Rays {
            n,
            members,
            origin: core::array::from_fn(|a| core::array::from_fn(|l| at(l).origin[a])),
            shear: core::array::from_fn(|a| core::array::from_fn(|l| at(l).shear[a])),
        }
    }

    /// Steps 2, 3 and 5 for every lane against the triangle whose vertices, in the block's
    /// permuted axes, are `rows = [xs, ys, zs]`: the edge functions `(W, U, V)` into `e`, the
    /// sheared `z` of the three vertices into `z`, and two masks of lanes: those whose edge
    /// functions are nonzero with one sign (candidates), and those with an exact zero.
    #[inline(always)]
    fn edges(
        &self,
        rows: [[T; 3]; 3],
        e: &mut [[T; LANES]; 3],
        z: &mut [[T; LANES]; 3],
    ) -> (u32, u32) {
        let [xs, ys, zs] = rows;
        let (mut candidates, mut zeros) = (0, 0);
        for l in 0..LANES {
            let [ox, oy, oz] = [self.origin[0][l], self.origin[1][l], self.origin[2][l]];
            let [sx, sy] = [self.shear[0][l], self.shear[1][l]];
            let zl = zs.map(|v| v - oz);
            let x = [0, 1, 2].map(|i| (xs[i] - ox) - zl[i] * sx);
            let y = [0, 1, 2].map(|i| (ys[i] - oy) - zl[i] * sy);
            let w = x[1] * y[0] - y[1] * x[0];
            let u = x[2] * y[1] - y[2] * x[1];
            let v = x[0] * y[2] - y[0] * x[2];
            // Signs as the single-ray test reads them; a NaN lane misses either way.
            let negative = [w, u, v].map(|f| f < T::ZERO);
            let same = negative[0] == negative[1] && negative[1] == negative[2];
            let zero = w == T::ZERO || u == T::ZERO || v == T::ZERO;
            candidates |= u32::from(same && !zero) << l;
            zeros |= u32::from(zero) << l;
            (e[0][l], e[1][l], e[2][l]) = (w, u, v);
            (z[0][l], z[1][l], z[2][l]) = (zl[0], zl[1], zl[2]);
        }
        (candidates, zeros)
    }

    /// Steps 6-8 for every lane, from [`Self::edges`]' values, within `limits`: the mask of
    /// lanes that hit (meaningful on the candidates), their `t`, `u`, `v` in `out`.
    #[inline(always)]
    fn distances(
        &self,
        e: &[[T; LANES]; 3],
        z: &[[T; LANES]; 3],
        limits: &[T; LANES],
        out: &mut [[T; LANES]; 3],
    ) -> u32 {
        let slack = T::ONE + T::EPSILON * T::from_f64(4.0);
        let mut hits = 0;
        for l in 0..LANES {
            let (w, u, v, sz) = (e[0][l], e[1][l], e[2][l], self.shear[2][l]);
            let det = (w + u) + v;
            let t_scaled = (w * (z[2][l] * sz) + u * (z[0][l] * sz)) + v * (z[1][l] * sz);
            let (t_signed, det_abs) =
                if det < T::ZERO { (-t_scaled, -det) } else { (t_scaled, det) };
            let limit = limits[l];
            let inv_det = T::ONE / det;
            let t = t_scaled * inv_det;
            let hit = det != T::ZERO
                && t_signed > T::ZERO
                && t_signed <= limit * det_abs * slack
                && t > T::ZERO
                && t <= limit
                && t.is_finite();
            hits |= u32::from(hit) << l;
            (out[0][l], out[1][l], out[2][l]) = (t, v * inv_det, w * inv_det);
        }
        hits
    }
}
