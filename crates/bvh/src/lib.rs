//! A wide bounding volume hierarchy over boxes: binned SAH build, eight children per node with
//! `f32` boxes tested eight at a time, robust ordered traversal.
//!
//! The tree knows nothing about triangles or kernels: it is built from one [`Aabb`] per
//! primitive and reports, during traversal, ranges of *slots* (positions in
//! [`Bvh::order`]) whose boxes the ray may touch. [`accel::Accel`] stores a back end's
//! prepared triangles in slot order and runs its kernel on those ranges: closest-hit and
//! any-hit queries, with brute-force references. The crate needs only the
//! [`Intersector`](intersect::Intersector) seam and rayon: no file format, no image.
//!
//! ```
//! use intersect::Ray;
//! use bvh::{Aabb, Bvh};
//!
//! // Three unit boxes along x.
//! let boxes: Vec<Aabb<f32>> = (0..3)
//!     .map(|i| {
//!         let x = i as f32 * 2.0;
//!         Aabb { min: [x, 0.0, 0.0], max: [x + 1.0, 1.0, 1.0] }
//!     })
//!     .collect();
//! let bvh = Bvh::build(&boxes);
//! // A ray along -x from the right reaches every box; one along +y above them, none.
//! let visited = |ray: Ray<f32>| {
//!     let mut met = Vec::new();
//!     bvh.closest(&ray, f32::INFINITY, |slots, _limit| {
//!         met.extend(slots.map(|slot| bvh.order()[slot]));
//!     });
//!     met.sort();
//!     met
//! };
//! assert_eq!(visited(Ray::new([10.0, 0.5, 0.5], [-1.0, 0.0, 0.0])), [0, 1, 2]);
//! assert!(visited(Ray::new([0.5, 2.0, 0.5], [0.0, 1.0, 0.0])).is_empty());
//! ```
//!
//! # Layout
//!
//! Each node holds the boxes of up to [`WIDTH`] = 8 children as six rows of eight `f32` (the
//! lower x, y, z planes, then the upper ones: one AVX register each) and a 32-bit reference
//! per child: another node, or a leaf (first slot and size, at most [`MAX_LEAF`] primitives).
//! Leaves are not nodes: their boxes sit in their parent with their siblings'. A node is 224
//! bytes. Nodes are stored depth-first from the root, node 0. For a back end that tests a
//! leaf's triangles in blocks ([`intersect::Intersector::BLOCK`]), every leaf starts at a
//! multiple of the block ([`Bvh::with_leaves_aligned`], the slots between leaves padding), so
//! that the leaf's blocks are found from its first slot without a table.
//!
//! # Build
//!
//! Binned surface area heuristic ([`BINS`] bins per axis over the centroid bounds, all three
//! axes tried, a split's traversal costing three primitive tests); each node splits its
//! largest child until it has eight, so the tree is what a binary SAH tree collapsed greedily
//! would be, without building the binary tree. Everything
//! is partitioned in place in one array, with no allocation per node; subtrees of many
//! primitives are built in parallel on rayon's current thread pool. Depth never exceeds
//! [`MAX_DEPTH`] binary splits: near that depth the builder switches from SAH to median
//! splits, which halve the count, so the fixed traversal stack can never overflow. See the
//! `build` module for the details.
//!
//! # Traversal
//!
//! The ray is prepared once: its origin, inverse direction, and for each axis the plane row
//! it enters through. A node test computes the entry and exit distances of the eight boxes
//! with AVX2 where the build enables it (the workspace's x86-64 baseline does), lane by lane
//! otherwise. Closest-hit queries visit the children met nearest first and stack the
//! others with their entry distances, skipping those that start beyond the best hit found;
//! any-hit queries stop at the first hit. The stack is a fixed array on the call stack: no
//! allocation per ray.
//!
//! # Packets
//!
//! [`Bvh::closest_packet`] and [`Bvh::any_packet`] (and [`accel::Accel::closest_hits_packet`],
//! [`accel::Accel::any_hits_packet`]) trace many rays at once: chunks of [`PACKET`] rays, split
//! by the signs of their directions, walk the tree together. A node is tested once per packet,
//! against an interval bound of its rays (their origins' and inverse directions' ranges per
//! axis), which is conservative for every ray's own rounded box test; at a leaf each ray runs
//! the single-ray box test, and the rays that pass meet the leaf's triangles together (for
//! closest hits through [`intersect::Intersector::intersect_group`], which a kernel may run
//! several rays at a time, handed the positions of the rays, not copies). The hits are
//! those of single rays, ties included (the `packet` module's docs give the argument; the
//! tests check it on every back end). Coherent rays (a block of pixels from one eye) share
//! most of their nodes, so the packet pays one node test where single rays pay one each;
//! incoherent rays give wide intervals that meet most boxes, so they keep the single-ray
//! queries. The rule: a caller tracing a camera's pixels uses the packet queries in 8 x 8
//! blocks (`render::trace::render_frame` does), everything else the single-ray ones; within a
//! chunk, an octant holding fewer than [`MIN_PACKET`] rays is traced ray by ray.
//!
//! # Precision of the boxes
//!
//! Boxes are stored in `f32` for both precisions: half the memory and twice the lanes of
//! `f64`. For an `f64` tree every box is rounded *outwards* to `f32` (lower faces down, upper
//! faces up, see `f32_down`/`f32_up` in the node module), so it contains the exact `f64` box,
//! and `f64` rays test the `f32` planes converted back to `f64` (exactly) in `f64` arithmetic.
//! An `f64` tree's boxes are at most one `f32` ulp larger than they would be in `f64`, which
//! costs a few extra box hits, never a missed triangle.
//!
//! # Why no hit is lost to rounding
//!
//! A kernel may report a hit that a slab test computed in floating point would miss: the ray
//! grazes a face of the box, or the hit lies on the box's boundary. Three measures keep every
//! box test conservative, so that BVH queries return exactly what brute force returns:
//!
//! - Boxes are the exact min/max of the vertices, padded outwards by [`PAD_ULPS`] units in the
//!   last place (of the tree's precision `T`) of the box's largest coordinate, which absorbs a
//!   kernel's rounding at triangle edges, then rounded outwards to `f32`.
//! - The far distance of the slab test is multiplied by `1 + 2 gamma(3)` (Ize, "Robust BVH Ray
//!   Traversal", JCGT 2013), which bounds the rounding of `(plane - origin) * inv_dir` in the
//!   ray's precision (single rays fold the factor into the inverse used for far planes, once
//!   per ray: the same four roundings in another order); the current best distance is
//!   compared with the same factor, and a child whose entry distance equals the best distance
//!   is still visited, so ties are resolved by [`intersect::Hit::nearer_than`] and not by
//!   traversal order. (The distance is computed as
//!   a subtraction then a multiplication, never as one fused multiply-add with a precomputed
//!   `origin * inv_dir`, whose error is not bounded relative to the result.)
//! - Zero direction components give infinite inverse components; the `0 * inf = NaN` of a ray
//!   lying in a box's face plane is ignored by the NaN-skipping `min`/`max`, so that slab
//!   simply imposes no constraint (conservative).
//!
//! What this assumes of a kernel: a reported hit lies within its triangle's box grown by the
//! padding, and its `t` is within the `gamma(3)` slack of the distance to that point. Kernels
//! meet this for every triangle of positive area whose hit they compute to a few ulps; a
//! kernel that reports rounding noise as hits on (nearly) degenerate triangles may see such
//! hits differ between the BVH and brute force, which is why the
//! [`Intersector`](intersect::Intersector) contract says degenerate triangles are never hit.
//! A ray with a non-finite origin or direction component meets no box.

#![deny(missing_docs)]

mod aabb;
pub mod accel;
mod build;
mod node;
mod packet;
mod simd;
mod traverse;

use core::marker::PhantomData;
use core::ops::Range;

use intersect::{Ray, Real, Triangle};
use rayon::prelude::*;

pub use aabb::Aabb;
pub use node::{MAX_SLOTS, WIDTH};
pub use packet::{MIN_PACKET, PACKET};
pub use simd::{ISA_ENV, Isa};

use build::{Info, PARALLEL_MIN, PrimRef};
use node::{Node, is_leaf, leaf_ref, leaf_slots};
use traverse::{AnyLeaf, Baseline, ClosestLeaf};

/// Largest number of bins per axis in the SAH build (sets of at least 4096 primitives; 16
/// bins from 256, 8 below, at most one per primitive).
pub const BINS: usize = 32;
/// Largest number of primitives in a leaf.
pub const MAX_LEAF: usize = 8;
/// Largest number of binary splits above a leaf; at most this many nodes lie on a path from
/// the root, which bounds the traversal stack.
pub const MAX_DEPTH: usize = 64;
/// Outward padding of node boxes, in units in the last place of the box's largest coordinate.
pub const PAD_ULPS: u32 = 32;

/// The [`Bvh::order`] entry of a slot that holds no primitive (see
/// [`Bvh::with_leaves_aligned`]).
pub const PADDING: u32 = u32::MAX;

/// A child of a node, as seen from outside.
#[derive(Clone, Debug, PartialEq)]
pub enum Child<T> {
    /// Another node.
    Node {
        /// Its index.
        index: usize,
        /// Its box as stored in the parent.
        bounds: Aabb<T>,
    },
    /// A leaf holding the primitives in these slots of [`Bvh::order`].
    Leaf {
        /// The slots.
        slots: Range<usize>,
        /// Its box as stored in the parent.
        bounds: Aabb<T>,
    },
}

impl<T: Copy> Child<T> {
    /// The child's box.
    #[must_use]
    pub fn bounds(&self) -> Aabb<T> {
        match self {
            Child::Node { bounds, .. } | Child::Leaf { bounds, .. } => *bounds,
        }
    }
}

/// A bounding volume hierarchy for rays of precision `T`.
#[derive(Clone, Debug)]
pub struct Bvh<T> {
    nodes: Vec<Node>,
    /// `order[slot]` is the original index of the primitive stored at `slot`, or [`PADDING`].
    order: Vec<u32>,
    /// Number of primitives (`order` less its padding).
    count: usize,
    depth: usize,
    leaves: usize,
    precision: PhantomData<T>,
}

impl<T: Real> Bvh<T> {
    /// Builds the tree over one box per primitive (binned SAH, see the
    /// [module documentation](self)), in parallel on rayon's current thread pool when there
    /// are many.
    ///
    /// Boxes should be finite; a box with NaN coordinates never meets any ray.
    ///
    /// # Panics
    ///
    /// If there are more than [`MAX_SLOTS`] (2^28) boxes.
    #[must_use]
    pub fn build(boxes: &[Aabb<T>]) -> Self {
        Self::build_with(boxes.len(), |i| boxes[i])
    }

    /// [`Bvh::build`] over the boxes of `triangles`, without storing them first.
    ///
    /// # Panics
    ///
    /// If there are more than [`MAX_SLOTS`] (2^28) triangles.
    #[must_use]
    pub fn from_triangles(triangles: &[Triangle<T>]) -> Self {
        Self::build_with(triangles.len(), |i| Aabb::of_triangle(&triangles[i]))
    }

    fn build_with(n: usize, box_of: impl Fn(usize) -> Aabb<T> + Sync) -> Self {
        assert!(n <= MAX_SLOTS, "a BVH holds at most {MAX_SLOTS} primitives, got {n}");
        if n == 0 {
            return Self {
                nodes: Vec::new(),
                order: Vec::new(),
                count: 0,
                depth: 0,
                leaves: 0,
                precision: PhantomData,
            };
        }
        let make = |i: usize| PrimRef::new(&box_of(i), i as u32);
        let mut refs: Vec<PrimRef> = if n >= PARALLEL_MIN && rayon::current_num_threads() > 1 {
            (0..n).into_par_iter().map(make).collect()
        } else {
            (0..n).map(make).collect()
        };
        let info = Info::of(&refs);
        let nodes = build::build::<T>(&mut refs, info);
        let order = refs.iter().map(PrimRef::index).collect();
        let mut bvh = Self { nodes, order, count: n, depth: 0, leaves: 0, precision: PhantomData };
        (bvh.depth, bvh.leaves) = bvh.measure();
        bvh
    }

    /// The depth (nodes on the longest path from the root to a leaf) and the number of leaves.
    fn measure(&self) -> (usize, usize) {
        let (mut depth, mut leaves) = (0, 0);
        let mut stack = vec![(0usize, 1usize)];
        while let Some((i, d)) = stack.pop() {
            depth = depth.max(d);
            let node = &self.nodes[i];
            for lane in (0..WIDTH).filter(|&lane| node.is_used(lane)) {
                let r = node.refs[lane];
                if is_leaf(r) {
                    leaves += 1;
                } else {
                    stack.push((r as usize, d + 1));
                }
            }
        }
        (depth, leaves)
    }

    /// Slot order: `order()[slot]` is the original index of the primitive stored at `slot`,
    /// or [`PADDING`] for a slot between leaves (only in a tree from
    /// [`Bvh::with_leaves_aligned`]).
    #[must_use]
    pub fn order(&self) -> &[u32] {
        &self.order
    }

    /// Number of primitives.
    #[must_use]
    pub fn len(&self) -> usize {
        self.count
    }

    /// Whether the tree holds no primitive.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.count == 0
    }

    /// The same tree with every leaf moved to start at a multiple of `align` slots, the slots
    /// left between leaves marked [`PADDING`] in [`Bvh::order`]; `align` 1 leaves it as it is.
    /// For a back end that lays out a leaf's primitives in blocks of `align`
    /// ([`intersect::Intersector::BLOCK`]): a leaf's primitives are then the first lanes of
    /// whole blocks, found from the leaf's first slot alone.
    ///
    /// # Panics
    ///
    /// If `align` is 0, or if the padded slots exceed [`MAX_SLOTS`].
    #[must_use]
    pub fn with_leaves_aligned(mut self, align: usize) -> Self {
        assert!(align > 0, "leaves align to a positive number of slots");
        if align == 1 {
            return self;
        }
        // Every leaf reference, by its first slot (leaves partition the slots in order).
        let mut leaves: Vec<(usize, usize)> = (0..self.nodes.len())
            .flat_map(|i| (0..WIDTH).map(move |lane| (i, lane)))
            .filter(|&(i, lane)| self.nodes[i].is_used(lane) && is_leaf(self.nodes[i].refs[lane]))
            .collect();
        leaves.sort_unstable_by_key(|&(i, lane)| leaf_slots(self.nodes[i].refs[lane]).start);
        let mut order = Vec::with_capacity(self.order.len() + leaves.len() * (align - 1));
        for (i, lane) in leaves {
            let slots = leaf_slots(self.nodes[i].refs[lane]);
            order.resize(order.len().next_multiple_of(align), PADDING);
            assert!(order.len() + slots.len() <= MAX_SLOTS, "too many slots to align leaves");
            self.nodes[i].refs[lane] = leaf_ref(order.len(), slots.len());
            order.extend_from_slice(&self.order[slots]);
        }
        order.resize(order.len().next_multiple_of(align), PADDING);
        self.order = order;
        self
    }

    /// Number of nodes (leaves are not nodes: they live in their parents' lanes).
    #[must_use]
    pub fn node_count(&self) -> usize {
        self.nodes.len()
    }

    /// Number of leaves.
    #[must_use]
    pub fn leaf_count(&self) -> usize {
        self.leaves
    }

    /// Nodes on the longest path from the root to a leaf (0 for an empty tree, 1 when the
    /// root's children are all leaves); at most [`MAX_DEPTH`].
    #[must_use]
    pub fn depth(&self) -> usize {
        self.depth
    }

    /// Bytes held by the nodes and the slot order.
    #[must_use]
    pub fn bytes(&self) -> usize {
        self.nodes.len() * size_of::<Node>() + self.order.len() * size_of::<u32>()
    }

    /// The children of node `i` (node 0 is the root), in lane order.
    ///
    /// # Panics
    ///
    /// If `i >= self.node_count()`.
    #[must_use]
    pub fn children(&self, i: usize) -> Vec<Child<T>> {
        let node = &self.nodes[i];
        (0..WIDTH)
            .filter(|&lane| node.is_used(lane))
            .map(|lane| {
                let (lo, hi) = node.lane_box(lane);
                let bounds = Aabb {
                    min: lo.map(|x| T::from_f64(f64::from(x))),
                    max: hi.map(|x| T::from_f64(f64::from(x))),
                };
                let r = node.refs[lane];
                if is_leaf(r) {
                    Child::Leaf { slots: leaf_slots(r), bounds }
                } else {
                    Child::Node { index: r as usize, bounds }
                }
            })
            .collect()
    }

    /// The union of the boxes of node `i`'s children.
    ///
    /// # Panics
    ///
    /// If `i >= self.node_count()`.
    #[must_use]
    pub fn node_bounds(&self, i: usize) -> Aabb<T> {
        self.children(i).iter().fold(Aabb::empty(), |b, c| b.union(&c.bounds()))
    }

    /// Visits the leaves that `ray` may reach within `(0, t_max]`, nearest first.
    ///
    /// `leaf` gets a range of slots and the current distance limit, which it lowers when it
    /// finds a nearer hit; children entered beyond the limit are skipped from then on (one
    /// entered exactly at the limit is still visited, so ties can be resolved by the caller).
    /// The node test is [`Isa::current`]'s (`f32`) or [`Isa::current_f64`]'s.
    #[inline]
    pub fn closest<F>(&self, ray: &Ray<T>, t_max: T, leaf: F)
    where
        F: FnMut(Range<usize>, &mut T),
    {
        // SAFETY: `Isa::current*` is `Avx512` only on a CPU that has it.
        unsafe { self.closest_unchecked(Self::isa(), ray, t_max, leaf) }
    }

    /// [`Bvh::closest`] with a leaf visitor of the crate's own, compiled into the loop.
    #[inline]
    pub(crate) fn closest_visit<L: ClosestLeaf<T>>(&self, ray: &Ray<T>, t_max: T, leaf: L) {
        // SAFETY: `Isa::current*` is `Avx512` only on a CPU that has it.
        unsafe { self.closest_unchecked(Self::isa(), ray, t_max, leaf) }
    }

    /// [`Bvh::any`] with a leaf visitor of the crate's own, compiled into the loop.
    #[inline]
    pub(crate) fn any_visit<L: AnyLeaf>(&self, ray: &Ray<T>, t_max: T, leaf: L) -> bool {
        // SAFETY: `Isa::current*` is `Avx512` only on a CPU that has it.
        unsafe { self.any_unchecked(Self::isa(), ray, t_max, leaf) }
    }

    /// The node test of this precision in this process.
    #[inline(always)]
    fn isa() -> Isa {
        if T::MANTISSA_DIGITS <= f32::MANTISSA_DIGITS { Isa::current() } else { Isa::current_f64() }
    }

    /// [`Bvh::closest`] with the node test of `isa` instead of this process's (the same
    /// leaves in the same order, the same limits: for tests and benches that pair the
    /// instruction sets in one process). An `isa` the CPU lacks runs the baseline.
    #[inline]
    pub fn closest_with<F>(&self, isa: Isa, ray: &Ray<T>, t_max: T, leaf: F)
    where
        F: FnMut(Range<usize>, &mut T),
    {
        let isa = if isa == Isa::detected() { isa } else { Isa::Baseline };
        // SAFETY: `isa` is `Avx512` only if the CPU has it.
        unsafe { self.closest_unchecked(isa, ray, t_max, leaf) }
    }

    /// # Safety
    ///
    /// `isa` is [`Isa::Avx512`] only on a CPU with AVX-512F and VL.
    #[inline(always)]
    unsafe fn closest_unchecked<F>(&self, isa: Isa, ray: &Ray<T>, t_max: T, leaf: F)
    where
        F: ClosestLeaf<T>,
    {
        #[cfg(target_arch = "x86_64")]
        if isa == Isa::Avx512 {
            // SAFETY: the caller guarantees AVX-512F and VL.
            unsafe {
                let test = traverse::Avx512::assume();
                if T::MANTISSA_DIGITS <= f32::MANTISSA_DIGITS {
                    traverse::closest_avx512::<f32, T, F>(test, &self.nodes, ray, t_max, leaf);
                } else {
                    traverse::closest_avx512::<f64, T, F>(test, &self.nodes, ray, t_max, leaf);
                }
            }
            return;
        }
        let _ = isa;
        // The branch is on a constant: each precision keeps only its own traversal.
        if T::MANTISSA_DIGITS <= f32::MANTISSA_DIGITS {
            traverse::closest::<f32, T, F>(Baseline, &self.nodes, ray, t_max, leaf);
        } else {
            traverse::closest::<f64, T, F>(Baseline, &self.nodes, ray, t_max, leaf);
        }
    }

    /// [`Bvh::closest`] for many rays at once: packets of coherent rays walk the tree
    /// together (see [Packets](self#packets)). `rays` are cut into chunks of [`PACKET`] in the
    /// order given, so neighbours should be coherent (an 8 x 8 block of pixels from one eye).
    ///
    /// `leaf` gets a range of slots, the positions in `rays` of the rays that reach it
    /// (ascending), and `limits`, whose entries for those rays it lowers when it finds nearer
    /// hits; `limits` holds each ray's `t_max` on entry and its last limit on return. Every
    /// ray is offered every leaf that [`Bvh::closest`] could offer it, and maybe more, in
    /// another order: a caller that keeps the nearest hit under a total order (as
    /// [`Accel`](accel::Accel) does) gets the single-ray answers.
    ///
    /// `hint` gets a leaf's slots as soon as the packet finds it may reach the leaf, ahead of
    /// the visit, so that the caller can prefetch what the leaf's test will read: the packet
    /// path waits on memory at most of its leaves on large meshes.
    ///
    /// # Panics
    ///
    /// If `rays` and `limits` differ in length.
    pub fn closest_packet<F, H>(&self, rays: &[Ray<T>], limits: &mut [T], leaf: F, hint: H)
    where
        F: FnMut(Range<usize>, &[usize], &mut [T]),
        H: Fn(Range<usize>),
    {
        if T::MANTISSA_DIGITS <= f32::MANTISSA_DIGITS {
            packet::closest::<f32, T, F, H>(&self.nodes, rays, limits, leaf, hint);
        } else {
            packet::closest::<f64, T, F, H>(&self.nodes, rays, limits, leaf, hint);
        }
    }

    /// [`Bvh::any`] for many rays at once, in packets as [`Bvh::closest_packet`]: `leaf` gets
    /// a range of slots and the positions of the rays that reach it (ascending, at most
    /// [`PACKET`]), and returns which of them hit there (bit `j` for the `j`-th; those rays
    /// then stop); `hit[i]` says on return whether `leaf` reported a hit for ray `i` within
    /// `(0, limits[i]]`. `hint` as for [`Bvh::closest_packet`].
    ///
    /// # Panics
    ///
    /// If `rays`, `limits` and `hit` differ in length.
    pub fn any_packet<F, H>(
        &self,
        rays: &[Ray<T>],
        limits: &[T],
        hit: &mut [bool],
        leaf: F,
        hint: H,
    ) where
        F: FnMut(Range<usize>, &[usize]) -> u64,
        H: Fn(Range<usize>),
    {
        if T::MANTISSA_DIGITS <= f32::MANTISSA_DIGITS {
            packet::any::<f32, T, F, H>(&self.nodes, rays, limits, hit, leaf, hint);
        } else {
            packet::any::<f64, T, F, H>(&self.nodes, rays, limits, hit, leaf, hint);
        }
    }

    /// Visits the leaves that `ray` may reach within `(0, t_max]` until `leaf` returns `true`;
    /// returns whether it did. The node test is that of [`Bvh::closest`].
    #[inline]
    pub fn any<F>(&self, ray: &Ray<T>, t_max: T, leaf: F) -> bool
    where
        F: FnMut(Range<usize>) -> bool,
    {
        // SAFETY: `Isa::current*` is `Avx512` only on a CPU that has it.
        unsafe { self.any_unchecked(Self::isa(), ray, t_max, leaf) }
    }

    /// [`Bvh::any`] with the node test of `isa` (see [`Bvh::closest_with`]).
    #[inline]
    pub fn any_with<F>(&self, isa: Isa, ray: &Ray<T>, t_max: T, leaf: F) -> bool
    where
        F: FnMut(Range<usize>) -> bool,
    {
        let isa = if isa == Isa::detected() { isa } else { Isa::Baseline };
        // SAFETY: `isa` is `Avx512` only if the CPU has it.
        unsafe { self.any_unchecked(isa, ray, t_max, leaf) }
    }

    /// # Safety
    ///
    /// `isa` is [`Isa::Avx512`] only on a CPU with AVX-512F and VL.
    #[inline(always)]
    unsafe fn any_unchecked<F>(&self, isa: Isa, ray: &Ray<T>, t_max: T, leaf: F) -> bool
    where
        F: AnyLeaf,
    {
        #[cfg(target_arch = "x86_64")]
        if isa == Isa::Avx512 {
            // SAFETY: the caller guarantees AVX-512F and VL.
            return unsafe {
                let test = traverse::Avx512::assume();
                if T::MANTISSA_DIGITS <= f32::MANTISSA_DIGITS {
                    traverse::any_avx512::<f32, T, F>(test, &self.nodes, ray, t_max, leaf)
                } else {
                    traverse::any_avx512::<f64, T, F>(test, &self.nodes, ray, t_max, leaf)
                }
            };
        }
        let _ = isa;
        if T::MANTISSA_DIGITS <= f32::MANTISSA_DIGITS {
            traverse::any::<f32, T, F>(Baseline, &self.nodes, ray, t_max, leaf)
        } else {
            traverse::any::<f64, T, F>(Baseline, &self.nodes, ray, t_max, leaf)
        }
    }
}
