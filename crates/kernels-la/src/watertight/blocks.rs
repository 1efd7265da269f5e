//! One ray against four triangles at a time: the leaf stage of single rays
//! ([`Intersector::intersect_leaf`], [`Intersector::occludes_leaf`]), steps 2-8 of the kernel
//! in glam's 4-vectors, one triangle per lane, from [`WatertightBlock`]s, which hold a leaf's
//! vertices axis by axis (a BVH starts every leaf at a multiple of [`BLOCK`], so a leaf's
//! triangles are the first lanes of its blocks). See
//! [Several pairs at once](super#several-pairs-at-once) for why the hits are those of
//! [`Intersector::intersect`], bit for bit.

#[cfg(doc)]
use intersect::Intersector;

use super::{Watertight, WatertightPrim, WatertightRay};
use crate::GlamReal;

/// Triangles per [`WatertightBlock`] (glam's 4-vectors: one SSE register in `f32`).
pub const BLOCK: usize = 4;

/// What [`Watertight`] keeps of [`BLOCK`] consecutive triangles of a scene, for
/// [`Intersector::intersect_leaf`]: their vertices axis by axis, `rows[axis][vertex][lane]`, one
/// lane per triangle (lanes past the scene's end hold zeros and are never tested). 144 bytes in
/// `f32`, 288 in `f64`: 36 and 72 bytes per triangle, beside the triangles' [`WatertightPrim`]s,
/// which the exact fallback and the packets read.
#[derive(Clone, Copy, Debug, PartialEq)]
#[repr(C, align(16))]
pub struct WatertightBlock<T> {
    rows: [[[T; BLOCK]; 3]; 3],
}

impl<T: GlamReal> Watertight<T> {
    /// The blocks of a scene's `prims`: block `b` holds `prims[BLOCK b..BLOCK (b + 1)]`.
    pub(super) fn blocks_of(prims: &[WatertightPrim<T>]) -> Vec<WatertightBlock<T>> {
        prims
            .chunks(BLOCK)
            .map(|chunk| {
                let mut rows = [[[T::ZERO; BLOCK]; 3]; 3];
                for (l, prim) in chunk.iter().enumerate() {
                    for (axis, row) in rows.iter_mut().enumerate() {
                        let [a, b, c] = T::lanes(prim.axes[axis]);
                        (row[0][l], row[1][l], row[2][l]) = (a, b, c);
                    }
                }
                WatertightBlock { rows }
            })
            .collect()
    }

    /// Steps 2-5 of `ray` against every lane of `block` in `lanes`: the candidates and the
    /// exact-zero lanes (both within `lanes`), the edge functions `(W, U, V)` and the
    /// vertices' unsheared `z`, four lanes each (glam's 4-vectors).
    #[inline(always)]
    pub(super) fn block_edges(
        block: &WatertightBlock<T>,
        lanes: u32,
        rd: &WatertightRay<T>,
    ) -> (u32, u32, [T::Q; 3], [T::Q; 3]) {
        let [kx, ky, kz] = rd.k.map(|a| a as usize);
        let [ox, oy, oz, sx, sy, _] = rd.splats;
        let z = [0, 1, 2].map(|i| T::q_load(&block.rows[kz][i]) - oz);
        let x = [0, 1, 2].map(|i| (T::q_load(&block.rows[kx][i]) - ox) - z[i] * sx);
        let y = [0, 1, 2].map(|i| (T::q_load(&block.rows[ky][i]) - oy) - z[i] * sy);
        let w = x[1] * y[0] - y[1] * x[0];
        let u = x[2] * y[1] - y[2] * x[1];
        let v = x[0] * y[2] - y[0] * x[2];
        let zero = T::q_splat(T::ZERO);
        let negative = [w, u, v].map(|f| T::q_lt(f, zero));
        let same = !(negative[0] ^ negative[1]) & !(negative[1] ^ negative[2]);
        let zeros = (T::q_eq(w, zero) | T::q_eq(u, zero) | T::q_eq(v, zero)) & lanes;
        (same & !zeros & lanes, zeros, [w, u, v], z)
    }

    /// Steps 6-8 for the four lanes of [`Self::block_edges`]' values within `limit`: the mask
    /// of lanes that hit (meaningful on the candidates), and `t`, `u`, `v`.
    #[inline(always)]
    pub(super) fn block_distances(
        e: [T::Q; 3],
        z: [T::Q; 3],
        sz: T::Q,
        limit: T,
    ) -> (u32, [[T; BLOCK]; 3]) {
        let slack = T::ONE + T::EPSILON * T::from_f64(4.0);
        let [w, u, v] = e;
        let zero = T::q_splat(T::ZERO);
        let det = (w + u) + v;
        let t_scaled = (w * (z[2] * sz) + u * (z[0] * sz)) + v * (z[1] * sz);
        let negative = T::q_lt(det, zero);
        let (t_signed, det_abs) =
            (T::q_negate_where(negative, t_scaled), T::q_negate_where(negative, det));
        let limit_q = T::q_splat(limit);
        let inv_det = T::q_splat(T::ONE) / det;
        let t = t_scaled * inv_det;
        let hit = !T::q_eq(det, zero)
            & T::q_lt(zero, t_signed)
            & T::q_le(t_signed, limit_q * det_abs * T::q_splat(slack))
            & T::q_lt(zero, t)
            & T::q_le(t, limit_q)
            & T::q_finite(t);
        (hit & 0xf, [T::q_lanes(t), T::q_lanes(v * inv_det), T::q_lanes(w * inv_det)])
    }
}
