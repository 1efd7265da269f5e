//! [`Accel`]: a back end's prepared triangles in BVH order, with closest-hit and any-hit
//! queries and their brute-force references.

use std::time::{Duration, Instant};

use intersect::{Hit, Intersector, Ray, Triangle};
use rayon::prelude::*;

use crate::bvh::Bvh;
use crate::scene::Mesh;

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
    /// Bytes of the back end's prepared triangles ([`Intersector::Prim`]).
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
/// loaded mesh, the file order documented in [`crate::scene`]).
pub struct Accel<I: Intersector> {
    intersector: I,
    bvh: Bvh<I::Real>,
    /// Prepared triangles; `prims[slot]` is triangle `bvh.order()[slot]`.
    prims: Vec<I::Prim>,
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
    /// If there are more than [`MAX_SLOTS`](crate::bvh::MAX_SLOTS) (2^28) triangles.
    #[must_use]
    pub fn build(intersector: I, triangles: &[Triangle<I::Real>]) -> Self {
        let start = Instant::now();
        let bvh = Bvh::from_triangles(triangles);
        let bvh_build = start.elapsed();

        let start = Instant::now();
        let prepare_one = |&i: &u32| intersector.prepare(&triangles[i as usize]);
        let prims: Vec<I::Prim> =
            if triangles.len() >= PARALLEL_PREPARE && rayon::current_num_threads() > 1 {
                bvh.order().par_iter().map(prepare_one).collect()
            } else {
                bvh.order().iter().map(prepare_one).collect()
            };
        let prepare = start.elapsed();

        let stats = AccelStats {
            triangles: triangles.len(),
            nodes: bvh.node_count(),
            leaves: bvh.leaf_count(),
            depth: bvh.depth(),
            bvh_build,
            prepare,
            bvh_bytes: bvh.bytes(),
            prim_bytes: prims.len() * size_of::<I::Prim>(),
        };
        Self { intersector, bvh, prims, stats }
    }

    /// [`Accel::build`] over a mesh's triangles, converted to the back end's precision.
    ///
    /// # Panics
    ///
    /// If the mesh has more than `u32::MAX` triangles.
    #[must_use]
    pub fn from_mesh(intersector: I, mesh: &Mesh) -> Self {
        Self::build(intersector, &mesh.triangles::<I::Real>())
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
        self.prims.len()
    }

    /// Whether the scene has no triangle.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.prims.is_empty()
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
        let ray_data = self.intersector.prepare_ray(ray);
        let order = self.bvh.order();
        let mut best: Option<Hit<I::Real>> = None;
        self.bvh.closest(ray, t_max, |slots, limit| {
            let first = slots.start;
            for (k, prim) in self.prims[slots].iter().enumerate() {
                // The kernel reports `t <= limit`: equal distances come through so that
                // `nearer_than` can pick the lower index whatever the visiting order.
                if let Some(h) = self.intersector.intersect(prim, ray, &ray_data, *limit) {
                    let hit = Hit::new(order[first + k], h);
                    if best.is_none_or(|b| hit.nearer_than(&b)) {
                        best = Some(hit);
                        *limit = hit.t;
                    }
                }
            }
        });
        best
    }

    /// Whether `ray` hits any triangle with `0 < t <= t_max`; stops at the first hit found.
    #[must_use]
    #[inline]
    pub fn any_hit(&self, ray: &Ray<I::Real>, t_max: I::Real) -> bool {
        let ray_data = self.intersector.prepare_ray(ray);
        self.bvh.any(ray, t_max, |slots| {
            self.prims[slots].iter().any(|p| self.intersector.occludes(p, ray, &ray_data, t_max))
        })
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
