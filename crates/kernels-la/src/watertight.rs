//! Watertight ray/triangle intersection: S. Woop, C. Benthin, I. Wald, "Watertight
//! Ray/Triangle Intersection", Journal of Computer Graphics Techniques 2(1), 2013.
//!
//! # Derivation (the paper's steps, in the order the code takes them)
//!
//! 1. **Per ray: a coordinate frame where the ray is the +z axis through the origin**
//!    (paper section 3, Fig. 5). Let `kz` be the axis where `|d|` is largest, `kx`, `ky` the
//!    next two cyclically; if `d[kz] < 0` swap `kx` and `ky`, so that the permutation plus
//!    the sign of `d[kz]` preserve orientation and every triangle keeps its winding. The
//!    shear `Sx = d[kx]/d[kz]`, `Sy = d[ky]/d[kz]`, `Sz = 1/d[kz]` maps `d` to `(0, 0, 1)`.
//!    Choosing `kz` as the dominant axis keeps `|Sx|, |Sy| <= 1`. This is [`WatertightRay`],
//!    computed once per ray.
//! 2. **Per triangle: translate, permute, shear** each vertex `P` into
//!    `P' = (Px - Sx Pz, Py - Sy Pz, Sz Pz)` with `P = vertex - o` in permuted axes. The
//!    ray is now the positive z axis; whether it hits is a 2D point-in-triangle test of the
//!    origin against `(A'x, A'y), (B'x, B'y), (C'x, C'y)`.
//! 3. **Edge functions** `U = C'x B'y - C'y B'x`, `V = A'x C'y - A'y C'x`,
//!    `W = B'x A'y - B'y A'x`: twice the signed areas of the sub-triangles the origin makes
//!    with the edges `BC`, `CA`, `AB`, i.e. the unnormalised barycentrics of `a`, `b`, `c`.
//! 4. **Exact fallback**: if any of `U, V, W` is exactly 0 the origin may lie on an edge,
//!    and rounding decides on which side; recompute all three with an exact sign (`f32`: in
//!    `f64`, as in the paper; `f64`: Kahan's difference of products, see below).
//! 5. **Inside test, both faces**: hit only if all three edge functions have the same sign.
//!    An exact zero (the ray passes exactly through the edge's line) is decided by the tie
//!    rule below, so that exactly one of two neighbours owns a shared edge or vertex.
//! 6. `det = U + V + W`; `det == 0` means the projected triangle has no area (ray parallel
//!    to the plane, or a degenerate triangle): miss.
//! 7. **Distance without division**: `T = U A'z + V B'z + W C'z` is `t * det`. With
//!    `s = sign(det)`, a hit needs `0 < T s <= t_max |det|`; `T s` and `|det|` are the paper's
//!    `xorf(T, sign_mask(det))` and `xorf(det, sign_mask(det))`.
//! 8. Only then divide: `t = T / det`, and the barycentrics `u = V / det` (weight of `b`),
//!    `v = W / det` (weight of `c`).
//!
//! # Why it is watertight
//!
//! A vertex's transformed coordinates depend only on that vertex and the ray, so two
//! triangles that share a vertex see the same `(P'x, P'y)`. An edge function is
//! `a*b - c*d` of those coordinates; for a shared edge the neighbour (wound consistently)
//! evaluates the same edge in the opposite direction, `c*d - a*b`, and IEEE rounding of
//! products and differences is symmetric, so it gets exactly the negated value. A nonzero
//! computed value has the exact sign (rounding is monotonic: `ab > cd` implies
//! `fl(ab) >= fl(cd)`), and a zero is recomputed with an exact sign. So both triangles agree
//! on which side of their common edge the ray passes, and the union of a fan of triangles
//! leaves no point out: no cracks. This needs consistent vertex values (the same
//! floating-point numbers in both triangles), which indexed meshes give for free.
//!
//! # Ties: a ray exactly through an edge or a vertex
//!
//! A closed triangle would count a ray exactly on a shared edge twice. Instead an exact zero
//! gets the sign it would have if the ray were moved by the infinitesimal
//! `δ = (ε, ε²)` in the sheared plane (`ε → 0+`), a symbolic perturbation in the spirit of
//! Edelsbrunner and Mücke's simulation of simplicity (and of rasterisation's top-left rule).
//! Moving the ray by `δ` moves every vertex by `-δ`, and for the edge from `P` to `Q`,
//! `E = Q'x P'y - Q'y P'x`,
//!
//! ```text
//! E(δ) = (Q'x - δx)(P'y - δy) - (Q'y - δy)(P'x - δx)
//!      = E + ε (Q'y - P'y) + ε² (P'x - Q'x)          (the δx δy terms cancel)
//! ```
//!
//! so a zero `E` takes the sign of `Q'y - P'y`, or if that is 0 of `P'x - Q'x` (a difference
//! of two floats is 0 only when they are equal, so its sign is exact); if both are 0 the edge
//! projects to a point (it is parallel to the ray) and the triangle, of zero projected area,
//! is missed. The neighbour evaluates the edge from `Q` to `P` and gets the opposite tie sign,
//! so exactly one of them owns the edge; around a vertex every sign is the exact sign at one
//! perturbed point, which lies in exactly one triangle of the fan. The rule runs only when an
//! edge function is exactly 0, so it costs nothing on the common path. (In `f32`, an exact
//! edge value below the smallest subnormal rounds to 0 and is decided by the rule too: still
//! consistent across the edge, but only reachable with coordinates below about `1e-22`.)
//!
//! # Implementation notes
//!
//! - [`WatertightPrim`] stores the three vertices **transposed**: one vector of the three
//!   `x`, one of the three `y`, one of the three `z`. Step 2 then handles all three vertices
//!   of the triangle at once: `X = (A'x, B'x, C'x)` is one subtract-multiply-subtract on
//!   whole vectors, with rows picked by the per-ray permutation. Each lane computes exactly
//!   the paper's scalar expression, so nothing in the argument above changes.
//! - Step 3 is `rotate(X) * Y - rotate(Y) * X`, which gives `(W, U, V)` in lanes 0, 1, 2.
//!   Multiply and subtract are separate operations on purpose: a fused multiply-add would
//!   round `a*b - c*d` and `c*d - a*b` differently and break the exact negation.
//! - The sign-aware distance test of step 7 is loosened by a few ulps, and the decision is
//!   made on the divided `t` (`0 < t <= t_max`, finite). Without the slack the undivided test
//!   could reject a hit whose rounded `t` equals `t_max`, so `intersect(.., t_max = hit.t)`
//!   would miss its own hit and ties between triangles would depend on traversal order.
//! - NaN anywhere fails every comparison that accepts, so it is a miss; no branch can panic
//!   (the axis indices are always in `0..3`).
//!
//! # Several pairs at once
//!
//! Two leaf stages run steps 2-8 for several (ray, triangle) pairs at a time, one pair per
//! lane:
//!
//! - [`Intersector::intersect_group`] (packet traversal, `packets`): [`LANES`] rays against
//!   one triangle, in plain arrays the compiler vectorises (AVX2: eight `f32` lanes in one
//!   register). The rays of a block share their permutation `k` (a block is formed per
//!   permutation; coherent rays mostly share one), so the triangle's rows are picked once and
//!   broadcast.
//! - [`Intersector::intersect_leaf`] and [`Intersector::occludes_leaf`] (single rays,
//!   `blocks`): one ray against the [`BLOCK`] triangles of a [`WatertightBlock`] in glam's
//!   4-vectors, the block's vertices stored axis by axis so that the ray's permutation picks
//!   whole rows. The BVH starts every leaf at a multiple of [`BLOCK`] (`Intersector::BLOCK`),
//!   so a leaf's triangles are the first lanes of its blocks, found from its first slot. A
//!   block's lanes are tested at once, then reported in order, each hit checked against the
//!   limit as the hits before it in the leaf lowered it: the single-ray test accepts exactly
//!   `t <= limit` for the same rounded `t` (the distance test of step 7 never rejects what
//!   that accepts), so this is the loop's answer. The ray's origin and shear are kept
//!   broadcast in [`WatertightRay`], once per ray rather than once per leaf.
//!
//! Each lane computes every value with the operations of the single-ray code in the same
//! order: `z = v - o_z`, `x = (v - o_x) - z Sx`, the edge functions
//! `next.x * this.y - next.y * this.x`, `det = (W + U) + V` and `T = (W C'z + U A'z) + V B'z`
//! (glam's `element_sum` and `dot` order), the same slack and the same final division. So its
//! hits are those of [`Intersector::intersect`], bit for bit (`conformance::group` and
//! `conformance::leaf` check it). A lane with an exactly zero edge function (step 4, the
//! exact fallback and the tie rule) is handed to `intersect` itself.

mod blocks;
mod packets;

use core::marker::PhantomData;

pub use blocks::{BLOCK, WatertightBlock};
pub use packets::LANES;
use packets::Rays;

use intersect::{Algebra, Guarantees, Intersector, Method, Ray, Triangle, TriangleHit};

use crate::{GlamReal, is_degenerate};

/// The watertight kernel of Woop, Benthin and Wald (2013): no cracks along shared edges.
///
/// The default back end (`NAME = "la"`). See the [module derivation](crate::watertight) and the
/// [crate table](crate#what-each-kernel-guarantees).
///
/// ```
/// use intersect::{Intersector, Ray, Triangle};
/// use kernels_la::Watertight;
///
/// let wt = Watertight::<f64>::new();
/// let lower = Triangle::new([0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [0.0, 2.0, 0.0]);
/// let upper = Triangle::new([2.0, 0.0, 0.0], [2.0, 2.0, 0.0], [0.0, 2.0, 0.0]);
/// // Aimed exactly at a point of their shared edge: exactly one of them owns it.
/// let ray = Ray::new([1.0, 1.0, 3.0], [0.0, 0.0, -1.0]);
/// let rd = wt.prepare_ray(&ray);
/// let hits = [lower, upper].map(|tri| wt.intersect(&wt.prepare(&tri), &ray, &rd, f64::INFINITY));
/// assert_eq!(hits.iter().flatten().count(), 1);
/// assert_eq!(hits.iter().flatten().next().unwrap().t, 3.0);
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Watertight<T>(PhantomData<T>);

impl<T> Watertight<T> {
    /// The kernel (it has no state).
    #[must_use]
    pub const fn new() -> Self {
        Self(PhantomData)
    }
}

/// What [`Watertight`] keeps of a triangle: its three vertices, transposed (`xs` holds
/// `(a.x, b.x, c.x)`, and so on), so one vector operation transforms all three.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WatertightPrim<T: GlamReal> {
    /// `[xs, ys, zs]`, indexed by axis.
    axes: [T::V; 3],
}

/// What [`Watertight`] computes once per ray (paper, Fig. 5): the axis permutation, the
/// origin in permuted axes, and the shear that maps the direction to `(0, 0, 1)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WatertightRay<T: GlamReal> {
    /// `[kx, ky, kz]`: `kz` is the dominant axis of the direction.
    k: [u32; 3],
    /// `(o[kx], o[ky], o[kz])`.
    origin: [T; 3],
    /// `(Sx, Sy, Sz) = (d[kx], d[ky], 1) / d[kz]`.
    shear: [T; 3],
    /// `origin` and `shear`, each in every lane of a 4-vector, for the leaf blocks.
    splats: [T::Q; 6],
}

impl<T: GlamReal> Intersector for Watertight<T> {
    type Real = T;
    type Prim = WatertightPrim<T>;
    type RayData = WatertightRay<T>;
    type Block = WatertightBlock<T>;
    const NAME: &'static str = "la";
    const BLOCK: usize = BLOCK;
    const ALGEBRA: Algebra = Algebra::La;
    const METHOD: Method = Method::Watertight;
    const GUARANTEES: Guarantees = Guarantees { watertight: true, exact: false };
    const VARIANT: Option<&'static str> = None;

    fn prepare(&self, tri: &Triangle<T>) -> WatertightPrim<T> {
        // A degenerate triangle becomes three copies of `a`: every edge function is then
        // `x*y - y*x`, exactly 0, so `det == 0` and it is never hit. Without this, rounding in
        // the shear can give an exactly collinear triangle a sliver of area.
        let [a, b, c] = if is_degenerate(tri) { [tri.a; 3] } else { tri.vertices() };
        WatertightPrim { axes: core::array::from_fn(|k| T::load([a[k], b[k], c[k]])) }
    }

    #[inline]
    fn prepare_ray(&self, ray: &Ray<T>) -> WatertightRay<T> {
        // Components read where the ray lies, one by one: a copy of `dir` indexed by a
        // computed axis would be a store and a wider load across it, which the CPU cannot
        // forward (a stall on every ray's first leaf).
        let (d, o) = (&ray.dir, &ray.origin);
        let [ax, ay, az] = [d[0].abs(), d[1].abs(), d[2].abs()];
        // Ties go to the later axis; NaN picks some axis and poisons the shear below.
        let kz = if ax > ay {
            if ax > az { 0 } else { 2 }
        } else if ay > az {
            1
        } else {
            2
        };
        let (mut kx, mut ky) = ([1, 2, 0][kz], [2, 0, 1][kz]);
        // Looking down -z mirrors the xy plane; swapping x and y mirrors it back, so a
        // counter-clockwise triangle stays counter-clockwise (the signs of U, V, W stay
        // meaningful).
        let dz = d[kz];
        if dz < T::ZERO {
            core::mem::swap(&mut kx, &mut ky);
        }
        // Divisions, as in the paper, rather than multiplications by 1/d[kz]: one rounding
        // each.
        let origin = [o[kx], o[ky], o[kz]];
        let shear = [d[kx] / dz, d[ky] / dz, T::ONE / dz];
        let [ox, oy, oz] = origin.map(T::q_splat);
        let [sx, sy, sz] = shear.map(T::q_splat);
        WatertightRay {
            k: [kx as u32, ky as u32, kz as u32],
            origin,
            shear,
            splats: [ox, oy, oz, sx, sy, sz],
        }
    }

    #[inline(always)]
    fn intersect(
        &self,
        prim: &WatertightPrim<T>,
        _ray: &Ray<T>,
        rd: &WatertightRay<T>,
        t_max: T,
    ) -> Option<TriangleHit<T>> {
        let [kx, ky, kz] = rd.k.map(|a| a as usize);
        let [sx, sy, sz] = rd.shear;

        // Step 2: all three vertices relative to the origin, permuted and sheared.
        // Lane i of each vector belongs to vertex i (a, b, c).
        let z = prim.axes[kz] - T::splat(rd.origin[2]);
        let x = (prim.axes[kx] - T::splat(rd.origin[0])) - z * sx;
        let y = (prim.axes[ky] - T::splat(rd.origin[1])) - z * sy;

        // Step 3: lanes (W, U, V); lane i is the edge from vertex i to vertex i + 1, i.e.
        // `next.x * this.y - next.y * this.x`.
        let mut wuv = T::rotate(x) * y - T::rotate(y) * x;

        // Step 4: an exact zero may be a rounded nonzero; redo all three with an exact sign,
        // and if a zero remains the ray is exactly on an edge's line: the tie rule decides.
        // Step 5: both-sided inside test, on the sign bits (one branch). A NaN lane's sign bit
        // is arbitrary; a NaN that passes makes `det` NaN, which fails the distance test
        // below, so it is a miss either way.
        if T::any_zero(wuv) {
            wuv = T::edge_functions_exact_sign(x, y);
            if T::any_zero(wuv) {
                if !inside_with_ties::<T>(wuv, x, y) {
                    return None;
                }
            } else if T::mixed_signs(wuv) {
                return None;
            }
        } else if T::mixed_signs(wuv) {
            return None;
        }

        // Step 6. (An infinite `det`, from overflowed edge values, is a miss below: `t`
        // becomes 0 or NaN.)
        let det = T::sum(wuv);
        if det == T::ZERO {
            return None;
        }

        // Step 7: T = U A'z + V B'z + W C'z, i.e. (W, U, V) . (C'z, A'z, B'z).
        let t_scaled = T::dot(wuv, T::rotate_back(z * sz));
        let (t_signed, det_abs) = if det < T::ZERO { (-t_scaled, -det) } else { (t_scaled, det) };
        // Loosened by 4 ulps of 1 so that it never rejects what the exact test below accepts
        // (if |T| / |det| rounds to at most t_max, then |T| <= t_max |det| (1 + half an ulp),
        // and the product t_max |det| itself is rounded).
        let slack = T::ONE + T::EPSILON * T::from_f64(4.0);
        if !(t_signed > T::ZERO && t_signed <= t_max * det_abs * slack) {
            return None;
        }

        // Step 8: one reciprocal, only for a (probable) hit.
        let inv_det = T::ONE / det;
        let t = t_scaled * inv_det;
        let [weight_c, _, weight_b] = T::lanes(wuv);
        (t > T::ZERO && t <= t_max && t.is_finite()).then(|| TriangleHit {
            t,
            u: weight_b * inv_det,
            v: weight_c * inv_det,
        })
    }

    /// Blocks of up to [`LANES`] rays that share a permutation, each tested lane-wise against
    /// every triangle in turn (see [Several pairs at once](self#several-pairs-at-once)).
    #[inline]
    fn intersect_group<F>(
        &self,
        prims: &[WatertightPrim<T>],
        rays: &[Ray<T>],
        data: &[WatertightRay<T>],
        members: &[usize],
        limits: &mut [T],
        found: &mut F,
    ) where
        F: FnMut(usize, usize, TriangleHit<T>, &mut T),
    {
        if members.len() < 2 {
            return intersect::one_ray_at_a_time(self, prims, rays, data, members, limits, found);
        }
        // At most 64 members at a time: a mask of 64 bits holds those still to place.
        for chunk in members.chunks(64) {
            let mut left: u64 = u64::MAX >> (64 - chunk.len());
            while left != 0 {
                let k = data[chunk[left.trailing_zeros() as usize]].k;
                let mut block = [0; LANES];
                let mut n = 0;
                let mut scan = left;
                while scan != 0 && n < LANES {
                    let m = scan.trailing_zeros() as usize;
                    scan &= scan - 1;
                    if data[chunk[m]].k == k {
                        block[n] = chunk[m];
                        n += 1;
                        left &= !(1 << m);
                    }
                }
                let block = Rays::new(data, block, n);
                self.rays(&block, k, prims, rays, data, limits, found);
            }
        }
    }

    fn prepare_blocks(&self, prims: &[WatertightPrim<T>]) -> Vec<WatertightBlock<T>> {
        Self::blocks_of(prims)
    }

    /// Each block's lanes tested at once, then reported in order, each hit checked against
    /// the limit as the hits before it lowered it, and each exact-zero lane handed to
    /// [`Intersector::intersect`] with the limit of its turn (see
    /// [Several pairs at once](self#several-pairs-at-once)).
    #[inline(always)]
    fn intersect_leaf<F>(
        &self,
        prims: &[WatertightPrim<T>],
        blocks: &[WatertightBlock<T>],
        ray: &Ray<T>,
        rd: &WatertightRay<T>,
        limit: &mut T,
        found: &mut F,
    ) where
        F: FnMut(usize, TriangleHit<T>, &mut T),
    {
        for (b, block) in blocks[..prims.len().div_ceil(BLOCK)].iter().enumerate() {
            let lanes = intersect::block_lanes::<Self>(b, prims.len());
            let (candidates, zeros, e, z) = Self::block_edges(block, lanes, rd);
            if candidates | zeros == 0 {
                continue;
            }
            let (mut hits, mut out) = (0, [[T::ZERO; BLOCK]; 3]);
            if candidates != 0 {
                let (mask, values) = Self::block_distances(e, z, rd.splats[5], *limit);
                (hits, out) = (mask & candidates, values);
            }
            intersect::report_block(self, prims, b, (hits, zeros), &out, (ray, rd), limit, found);
        }
    }

    #[inline(always)]
    fn occludes_leaf(
        &self,
        prims: &[WatertightPrim<T>],
        blocks: &[WatertightBlock<T>],
        ray: &Ray<T>,
        rd: &WatertightRay<T>,
        t_max: T,
    ) -> bool {
        for (b, block) in blocks[..prims.len().div_ceil(BLOCK)].iter().enumerate() {
            let lanes = intersect::block_lanes::<Self>(b, prims.len());
            let (candidates, mut zeros, e, z) = Self::block_edges(block, lanes, rd);
            let hits = |(mask, _): (u32, _)| mask & candidates != 0;
            if candidates != 0 && hits(Self::block_distances(e, z, rd.splats[5], t_max)) {
                return true;
            }
            while zeros != 0 {
                let k = b * BLOCK + zeros.trailing_zeros() as usize;
                zeros &= zeros - 1;
                if self.occludes(&prims[k], ray, rd, t_max) {
                    return true;
                }
            }
        }
        false
    }
}

/// The inside test when some edge function is exactly 0, with the tie rule of the
/// [module documentation](self#ties-a-ray-exactly-through-an-edge-or-a-vertex): a zero takes
/// the sign of `Q'y - P'y`, else of `P'x - Q'x`, for the edge from `P` to `Q`. Hit only if
/// all three signs are equal and non-zero. `wuv` is `(W, U, V)`: lane `i` is the edge from
/// vertex `i` to vertex `i + 1`, and `x`, `y` hold the sheared vertices.
#[cold]
#[inline(never)]
fn inside_with_ties<T: GlamReal>(wuv: T::V, x: T::V, y: T::V) -> bool {
    let (e, x, y) = (T::lanes(wuv), T::lanes(x), T::lanes(y));
    let signs: [i8; 3] = core::array::from_fn(|i| {
        let j = (i + 1) % 3;
        // NaN has no sign: 0, a miss (it never reaches the perturbation terms either).
        let sign = |v: T| i8::from(v > T::ZERO) - i8::from(v < T::ZERO);
        if e[i] == T::ZERO {
            match sign(y[j] - y[i]) {
                0 => sign(x[i] - x[j]),
                s => s,
            }
        } else {
            sign(e[i])
        }
    });
    signs[0] != 0 && signs[0] == signs[1] && signs[1] == signs[2]
}
