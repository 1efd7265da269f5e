//! [`Accel`]: a back end's prepared triangles in BVH order, with closest-hit and any-hit
//! queries and their brute-force references.
//!
//! ```
//! use intersect::{Algebra, Guarantees, Intersector, Method, Ray, Triangle, TriangleHit};
//! use bvh::accel::Accel;
//!
//! /// A toy back end for rays along +z: the triangle's plane must be z = const.
//! struct Flat;
//!
//! impl Intersector for Flat {
//!     type Real = f64;
//!     type Prim = Triangle<f64>;
//!     type RayData = ();
//!     type Block = ();
//!     const NAME: &'static str = "flat";
//!     const ALGEBRA: Algebra = Algebra::La;
//!     const METHOD: Method = Method::Report;
//!     const GUARANTEES: Guarantees = Guarantees { watertight: false, exact: false };
//!     const VARIANT: Option<&'static str> = None;
//!
//!     fn prepare(&self, tri: &Triangle<f64>) -> Triangle<f64> {
//!         *tri
//!     }
//!     fn prepare_ray(&self, _ray: &Ray<f64>) {}
//!     fn intersect(&self, p: &Triangle<f64>, ray: &Ray<f64>, _: &(), t_max: f64)
//!         -> Option<TriangleHit<f64>>
//!     {
//!         let t = (p.a[2] - ray.origin[2]) / ray.dir[2];
//!         // Barycentrics of the right triangle a, a + (1, 0, 0), a + (0, 1, 0).
//!         let (u, v) = (ray.origin[0] - p.a[0], ray.origin[1] - p.a[1]);
//!         (t > 0.0 && t <= t_max && u >= 0.0 && v >= 0.0 && u + v <= 1.0)
//!             .then_some(TriangleHit { t, u, v })
//!     }
//! }
//!
//! let near = Triangle::new([0.0, 0.0, 2.0], [1.0, 0.0, 2.0], [0.0, 1.0, 2.0]);
//! let far = Triangle::new([0.0, 0.0, 5.0], [1.0, 0.0, 5.0], [0.0, 1.0, 5.0]);
//! let scene = Accel::build(Flat, &[far, near]);
//!
//! let ray = Ray::new([0.25, 0.25, 0.0], [0.0, 0.0, 1.0]);
//! let hit = scene.closest_hit(&ray).unwrap();
//! assert_eq!((hit.prim, hit.t), (1, 2.0)); // `near`, index 1 in the slice given to build
//! assert_eq!(scene.closest_hit_brute_force(&ray), Some(hit));
//! assert!(scene.any_hit(&ray, 10.0) && !scene.any_hit(&ray, 1.0));
//! ```

use core::ops::Range;
use std::time::{Duration, Instant};

use intersect::{Hit, Intersector, Ray, Triangle, TriangleHit};
use rayon::prelude::*;

use crate::Bvh;
use crate::traverse::{AnyLeaf, ClosestLeaf};

/// Rays per batch of the packet queries (a multiple of [`crate::PACKET`]: a 16 x 16 tile).
const BATCH: usize = 256;

/// Scenes with at least this many triangles prepare them in parallel.
const PARALLEL_PREPARE: usize = 16384;

/// Sizes and build times of an [`Accel`].
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct AccelStats {
    /// Number of triangles.
    pub triangles: usize,
    /// Number of BVH nodes.
    pub nodes: usize,
    /// Number of BVH leaves.
    pub leaves: usize,
    /// Nodes on the longest path from the root to a leaf.
    pub depth: usize,
    /// Time to compute the boxes and build the BVH.
    pub bvh_build: Duration,
    /// Time to run [`Intersector::prepare`] on every triangle.
    pub prepare: Duration,
    /// Bytes of BVH nodes and the slot-to-triangle map.
    pub bvh_bytes: usize,
    /// Bytes of the back end's prepared triangles ([`Intersector::Prim`]) and their blocks
    /// ([`Intersector::Block`]).
    pub prim_bytes: usize,
}

impl AccelStats {
    /// Total build time (BVH and preparation).
    #[must_use]
    pub fn build_time(&self) -> Duration {
        self.bvh_build + self.prepare
    }

    /// Total bytes (BVH, map and prepared triangles).
    #[must_use]
    pub fn total_bytes(&self) -> usize {
        self.bvh_bytes + self.prim_bytes
    }

    /// Total bytes per triangle (0 for an empty scene).
    #[must_use]
    pub fn bytes_per_triangle(&self) -> f64 {
        if self.triangles == 0 { 0.0 } else { self.total_bytes() as f64 / self.triangles as f64 }
    }
}

/// A scene ready for ray queries with one back end: the intersector, a BVH in the back end's
/// precision and the prepared triangles stored in the BVH's leaf order.
///
/// Hits report triangle indices in the order of the slice given to [`Accel::build`] (for a
/// loaded mesh, the file order documented in the `scene` crate).
pub struct Accel<I: Intersector> {
    intersector: I,
    bvh: Bvh<I::Real>,
    /// Prepared triangles; `prims[slot]` is triangle `bvh.order()[slot]`.
    prims: Vec<I::Prim>,
    /// The kernel's blocks of `prims` ([`Intersector::prepare_blocks`]); none if it has none.
    blocks: Vec<I::Block>,
    stats: AccelStats,
}

impl<I: Intersector> Accel<I> {
    /// Builds the BVH over `triangles` and prepares each triangle for `intersector`, in
    /// parallel on rayon's current thread pool when there are many triangles.
    ///
    /// Triangles should have finite coordinates (the loader guarantees it): a triangle with
    /// NaN coordinates may be skipped by the BVH even where the kernel would report a hit.
    ///
    /// # Panics
    ///
    /// If there are more than [`MAX_SLOTS`](crate::MAX_SLOTS) (2^28) triangles.
    #[must_use]
    pub fn build(intersector: I, triangles: &[Triangle<I::Real>]) -> Self {
        let start = Instant::now();
        let bvh = Bvh::from_triangles(triangles).with_leaves_aligned(I::BLOCK);
        let bvh_build = start.elapsed();

        let start = Instant::now();
        // Padding slots (between leaves, for the kernel's blocks) hold a degenerate triangle,
        // which no query reaches.
        let padding = Triangle::default();
        let prepare_one =
            |&i: &u32| intersector.prepare(triangles.get(i as usize).unwrap_or(&padding));
        let prims: Vec<I::Prim> =
            if triangles.len() >= PARALLEL_PREPARE && rayon::current_num_threads() > 1 {
                bvh.order().par_iter().map(prepare_one).collect()
            } else {
                bvh.order().iter().map(prepare_one).collect()
            };
        let blocks = intersector.prepare_blocks(&prims);
        let prepare = start.elapsed();

        let stats = AccelStats {
            triangles: triangles.len(),
            nodes: bvh.node_count(),
            leaves: bvh.leaf_count(),
            depth: bvh.depth(),
            bvh_build,
            prepare,
            bvh_bytes: bvh.bytes(),
            prim_bytes: prims.len() * size_of::<I::Prim>() + blocks.len() * size_of::<I::Block>(),
        };
        Self { intersector, bvh, prims, blocks, stats }
    }

    /// The prepared triangles of the leaf in `slots`, and its blocks (followed by others).
    #[inline(always)]
    fn leaf(&self, slots: Range<usize>) -> (&[I::Prim], &[I::Block]) {
        let blocks = self.blocks.get(slots.start / I::BLOCK..).unwrap_or_default();
        (&self.prims[slots], blocks)
    }

    /// The back end.
    #[must_use]
    pub fn intersector(&self) -> &I {
        &self.intersector
    }

    /// The BVH.
    #[must_use]
    pub fn bvh(&self) -> &Bvh<I::Real> {
        &self.bvh
    }

    /// Sizes and build times.
    #[must_use]
    pub fn stats(&self) -> AccelStats {
        self.stats
    }

    /// Number of triangles.
    #[must_use]
    pub fn len(&self) -> usize {
        self.stats.triangles
    }

    /// Whether the scene has no triangle.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.stats.triangles == 0
    }

    /// The nearest hit along `ray` (`t > 0`), if any. Of several hits at the same distance,
    /// the one with the lowest triangle index ([`Hit::nearer_than`]).
    #[must_use]
    #[inline]
    pub fn closest_hit(&self, ray: &Ray<I::Real>) -> Option<Hit<I::Real>> {
        self.closest_hit_within(ray, <I::Real as intersect::Real>::INFINITY)
    }

    /// The nearest hit along `ray` with `0 < t <= t_max`, if any (ties as in
    /// [`Accel::closest_hit`]).
    #[must_use]
    #[inline]
    pub fn closest_hit_within(&self, ray: &Ray<I::Real>, t_max: I::Real) -> Option<Hit<I::Real>> {
        self.closest_where(ray, t_max, |_| true)
    }

    /// The nearest hit along `ray` with `t_min <= t <= t_max` (and `t > 0`, as always), if
    /// any: a segment of the ray, for shadow rays and the like. For `t_min <= 0` this is
    /// [`Accel::closest_hit_within`], bit for bit; a NaN bound finds nothing.
    ///
    /// A ray meets a triangle's plane at most once, so each triangle has one candidate `t`:
    /// rejecting the candidates before `t_min` triangle by triangle, inside the search, finds
    /// exactly the nearest hit of the segment (the box tests still cull by `t_max` alone).
    #[must_use]
    #[inline]
    pub fn closest_hit_between(
        &self,
        ray: &Ray<I::Real>,
        t_min: I::Real,
        t_max: I::Real,
    ) -> Option<Hit<I::Real>> {
        if t_min <= <I::Real as intersect::Real>::ZERO {
            return self.closest_hit_within(ray, t_max);
        }
        self.closest_where(ray, t_max, |t| t >= t_min)
    }

    /// The search of the closest-hit queries: the nearest hit within `t_max` among those whose
    /// `t` passes `accept`.
    #[inline]
    fn closest_where(
        &self,
        ray: &Ray<I::Real>,
        t_max: I::Real,
        accept: impl Fn(I::Real) -> bool,
    ) -> Option<Hit<I::Real>> {
        // Prepared when the ray first reaches a leaf (the same bits as up front): rays that
        // miss the mesh's boxes never pay for it.
        let mut search = Closest { accel: self, ray, data: None, accept, best: None };
        self.bvh.closest_visit(ray, t_max, &mut search);
        search.best
    }

    /// The kernel on the triangles of `slots`: keeps in `best` the nearest hit under
    /// [`Hit::nearer_than`] whose `t` passes `accept`, and lowers `limit` to it.
    #[inline(always)]
    fn closest_in_leaf(
        &self,
        slots: Range<usize>,
        ray: &Ray<I::Real>,
        ray_data: &I::RayData,
        limit: &mut I::Real,
        accept: impl Fn(I::Real) -> bool,
        best: &mut Option<Hit<I::Real>>,
    ) {
        let order = &self.bvh.order()[slots.start..];
        // The kernel reports `t <= limit`: equal distances come through so that
        // `nearer_than` can pick the lower index whatever the visiting order.
        let mut keep = |k: usize, h: TriangleHit<I::Real>, limit: &mut I::Real| {
            if accept(h.t) {
                let hit = Hit::new(order[k], h);
                if best.is_none_or(|b| hit.nearer_than(&b)) {
                    *best = Some(hit);
                    *limit = hit.t;
                }
            }
        };
        let (prims, blocks) = self.leaf(slots);
        self.intersector.intersect_leaf(prims, blocks, ray, ray_data, limit, &mut keep);
    }

    /// [`Accel::closest_hit_within`] for every ray of `rays` with the same `t_max`, into
    /// `out`: the same answers, bit for bit and ties included, found by packets of coherent
    /// rays ([`Bvh::closest_packet`]). For the pixels of a camera, in 8 x 8 blocks; incoherent
    /// rays are faster one by one (see [Packets](crate#packets)).
    ///
    /// # Panics
    ///
    /// If `rays` and `out` differ in length.
    pub fn closest_hits_packet(
        &self,
        rays: &[Ray<I::Real>],
        t_max: I::Real,
        out: &mut [Option<Hit<I::Real>>],
    ) {
        assert_eq!(rays.len(), out.len(), "one answer per ray");
        let Some(first) = rays.first() else { return };
        // Each ray's prepared data at its position in the batch, so that a leaf hands the
        // kernel the positions of its rays rather than copies of them; slots are filled with
        // a copy of the first ray's until their own ray is prepared (`ready`).
        let mut data = vec![self.intersector.prepare_ray(first); BATCH.min(rays.len())];
        // In batches whose per-ray state stays in the cache, however many rays come at once.
        for (rays, out) in rays.chunks(BATCH).zip(out.chunks_mut(BATCH)) {
            out.fill(None);
            // Prepared when a ray first reaches a leaf (the same bits as up front): most rays
            // of a frame where the mesh is small never do.
            let mut ready = [0u64; BATCH / 64];
            let mut limits = [t_max; BATCH];
            let limits = &mut limits[..rays.len()];
            let hint = |slots: Range<usize>| prefetch(&self.prims[slots]);
            self.bvh.closest_packet(
                rays,
                limits,
                |slots, members, limits| {
                    self.prepare_members(rays, members, &mut data, &mut ready);
                    let (first, order) = (slots.start, self.bvh.order());
                    let prims = &self.prims[slots];
                    self.intersector.intersect_group(
                        prims,
                        rays,
                        &data,
                        members,
                        limits,
                        &mut |r, k, h, limit| {
                            // As `closest_in_leaf` keeps the nearest hit of one ray.
                            let hit = Hit::new(order[first + k], h);
                            let best = &mut out[r];
                            if best.is_none_or(|b| hit.nearer_than(&b)) {
                                *best = Some(hit);
                                *limit = hit.t;
                            }
                        },
                    );
                },
                hint,
            );
        }
    }

    /// [`Accel::any_hit`] for every ray of `rays` with the same `t_max`, into `out`: the same
    /// answers, found by packets of coherent rays ([`Bvh::any_packet`]); see
    /// [`Accel::closest_hits_packet`].
    ///
    /// # Panics
    ///
    /// If `rays` and `out` differ in length.
    pub fn any_hits_packet(&self, rays: &[Ray<I::Real>], t_max: I::Real, out: &mut [bool]) {
        assert_eq!(rays.len(), out.len(), "one answer per ray");
        let Some(first) = rays.first() else { return };
        // Prepared lazily and in place, as in `closest_hits_packet`.
        let mut data = vec![self.intersector.prepare_ray(first); BATCH.min(rays.len())];
        let bounds = [t_max; BATCH];
        for (rays, out) in rays.chunks(BATCH).zip(out.chunks_mut(BATCH)) {
            let mut ready = [0u64; BATCH / 64];
            // What `occludes_leaf` reads: the leaf's blocks, or its triangles without blocks.
            let hint = |slots: Range<usize>| {
                let (prims, blocks) = self.leaf(slots);
                if core::mem::size_of::<I::Block>() == 0 {
                    prefetch(prims);
                } else {
                    prefetch(&blocks[..prims.len().div_ceil(I::BLOCK)]);
                }
            };
            let limits = &bounds[..rays.len()];
            self.bvh.any_packet(
                rays,
                limits,
                out,
                |slots, members| {
                    self.prepare_members(rays, members, &mut data, &mut ready);
                    let (prims, blocks) = self.leaf(slots);
                    let mut found = 0u64;
                    for (j, &i) in members.iter().enumerate() {
                        let hit = self
                            .intersector
                            .occludes_leaf(prims, blocks, &rays[i], &data[i], t_max);
                        found |= u64::from(hit) << j;
                    }
                    found
                },
                hint,
            );
        }
    }

    /// Prepares the rays `members` of a batch that are not prepared yet (`ready`), into their
    /// slots of `data`.
    #[inline(always)]
    fn prepare_members(
        &self,
        rays: &[Ray<I::Real>],
        members: &[usize],
        data: &mut [I::RayData],
        ready: &mut [u64; BATCH / 64],
    ) {
        for &i in members {
            if ready[i / 64] >> (i % 64) & 1 == 0 {
                ready[i / 64] |= 1 << (i % 64);
                data[i] = self.intersector.prepare_ray(&rays[i]);
            }
        }
    }

    /// Whether `ray` hits any triangle with `0 < t <= t_max`; stops at the first hit found.
    #[must_use]
    #[inline]
    pub fn any_hit(&self, ray: &Ray<I::Real>, t_max: I::Real) -> bool {
        // Prepared lazily, as in `closest_where`.
        self.bvh.any_visit(ray, t_max, Any { accel: self, ray, data: None, t_max })
    }

    /// Whether `ray` hits any triangle with `t_min <= t <= t_max` (and `t > 0`); for
    /// `t_min <= 0` this is [`Accel::any_hit`]. Beyond 0 the kernels' `occludes` cannot say
    /// where the hit is, so each candidate is found with `intersect` and its `t` checked.
    #[must_use]
    #[inline]
    pub fn any_hit_between(&self, ray: &Ray<I::Real>, t_min: I::Real, t_max: I::Real) -> bool {
        if t_min <= <I::Real as intersect::Real>::ZERO {
            return self.any_hit(ray, t_max);
        }
        let ray_data = self.intersector.prepare_ray(ray);
        self.bvh.any(ray, t_max, |slots| {
            self.prims[slots].iter().any(|p| {
                self.intersector.intersect(p, ray, &ray_data, t_max).is_some_and(|h| h.t >= t_min)
            })
        })
    }

    /// A triangle `ray` hits with `t_min <= t <= t_max` (and `t > 0`), if any: the first one
    /// the search meets, not the nearest (its index in the input order). It answers what
    /// [`Accel::any_hit_between`] answers, and also says which triangle.
    #[must_use]
    #[inline]
    pub fn any_hit_triangle(
        &self,
        ray: &Ray<I::Real>,
        t_min: I::Real,
        t_max: I::Real,
    ) -> Option<u32> {
        let ray_data = self.intersector.prepare_ray(ray);
        let order = self.bvh.order();
        let mut found = None;
        self.bvh.any(ray, t_max, |slots| {
            let first = slots.start;
            let k = self.prims[slots].iter().position(|p| {
                self.intersector.intersect(p, ray, &ray_data, t_max).is_some_and(|h| h.t >= t_min)
            });
            found = k.map(|k| order[first + k]);
            found.is_some()
        });
        found
    }

    /// Reference for [`Accel::closest_hit`]: tests every triangle, no BVH. The result does not
    /// depend on the order of the tests, since ties go to the lower triangle index.
    #[must_use]
    pub fn closest_hit_brute_force(&self, ray: &Ray<I::Real>) -> Option<Hit<I::Real>> {
        let ray_data = self.intersector.prepare_ray(ray);
        let inf = <I::Real as intersect::Real>::INFINITY;
        let mut best: Option<Hit<I::Real>> = None;
        for (prim, &index) in self.prims.iter().zip(self.bvh.order()) {
            if let Some(h) = self.intersector.intersect(prim, ray, &ray_data, inf) {
                let hit = Hit::new(index, h);
                if best.is_none_or(|b| hit.nearer_than(&b)) {
                    best = Some(hit);
                }
            }
        }
        best
    }

    /// Reference for [`Accel::any_hit`]: tests every triangle, no BVH.
    #[must_use]
    pub fn any_hit_brute_force(&self, ray: &Ray<I::Real>, t_max: I::Real) -> bool {
        let ray_data = self.intersector.prepare_ray(ray);
        self.prims.iter().any(|p| self.intersector.occludes(p, ray, &ray_data, t_max))
    }
}

/// The leaf visit of [`Accel::closest_where`], a type rather than a closure so that it is
/// compiled into the traversal loop (see `ClosestLeaf`).
struct Closest<'a, I: Intersector, A> {
    accel: &'a Accel<I>,
    ray: &'a Ray<I::Real>,
    /// The ray prepared for the kernel, once it reaches a leaf.
    data: Option<I::RayData>,
    accept: A,
    best: Option<Hit<I::Real>>,
}

impl<I: Intersector, A: Fn(I::Real) -> bool> ClosestLeaf<I::Real> for &mut Closest<'_, I, A> {
    #[inline(always)]
    fn visit(&mut self, slots: Range<usize>, limit: &mut I::Real) {
        let Closest { accel, ray, data, accept, best } = &mut **self;
        let data = data.get_or_insert_with(|| accel.intersector.prepare_ray(ray));
        accel.closest_in_leaf(slots, ray, data, limit, &*accept, best);
    }
}

/// The leaf visit of [`Accel::any_hit`] (see [`Closest`]).
struct Any<'a, I: Intersector> {
    accel: &'a Accel<I>,
    ray: &'a Ray<I::Real>,
    data: Option<I::RayData>,
    t_max: I::Real,
}

impl<I: Intersector> AnyLeaf for Any<'_, I> {
    #[inline(always)]
    fn visit(&mut self, slots: Range<usize>) -> bool {
        let Any { accel, ray, data, t_max } = self;
        let data = data.get_or_insert_with(|| accel.intersector.prepare_ray(ray));
        let (prims, blocks) = accel.leaf(slots);
        accel.intersector.occludes_leaf(prims, blocks, ray, data, *t_max)
    }
}

/// Asks the CPU to bring the cache lines of `items` into L1 (no effect elsewhere).
#[inline(always)]
fn prefetch<T>(items: &[T]) {
    let (start, bytes) = (items.as_ptr().cast::<u8>(), core::mem::size_of_val(items));
    for offset in (0..bytes).step_by(64) {
        #[cfg(target_arch = "x86_64")]
        // SAFETY: a prefetch reads and writes nothing and never faults, whatever the address
        // (Intel SDM, PREFETCHh); SSE is part of x86-64.
        unsafe {
            use core::arch::x86_64::{_MM_HINT_T0, _mm_prefetch};
            _mm_prefetch::<_MM_HINT_T0>(start.wrapping_add(offset).cast());
        }
        #[cfg(not(target_arch = "x86_64"))]
        let _ = (start, offset);
    }
}
