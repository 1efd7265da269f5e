//! A bounding volume hierarchy over boxes: binned SAH build, flattened depth-first nodes and
//! robust ordered traversal.
//!
//! The tree knows nothing about triangles or kernels: it is built from one [`Aabb`] per
//! primitive and reports, during traversal, ranges of *slots* (positions in
//! [`Bvh::order`]) whose boxes the ray may touch. [`crate::accel::Accel`] stores its
//! primitives in slot order and runs the kernel on those ranges.
//!
//! # Build
//!
//! Binned surface area heuristic ([`BINS`] bins per axis over the centroid bounds, all three
//! axes tried), leaves of at most [`MAX_LEAF`] primitives, in-place partitioning of one index
//! array, so the build is `O(n log n)` with no allocation per node. Nodes are written in
//! depth-first order: an interior node's first child follows it directly, the second child's
//! index is stored. Depth never exceeds [`MAX_DEPTH`]: near that depth the builder switches
//! from SAH to median splits, which halve the count, so the fixed traversal stack can never
//! overflow.
//!
//! # Why no hit is lost to rounding
//!
//! A kernel may report a hit that a slab test computed in floating point would miss: the ray
//! grazes a face of the box, or the hit lies on the box's boundary. Three measures keep every
//! box test conservative, so that BVH queries return exactly what brute force returns:
//!
//! - Boxes are the exact min/max of the vertices in the tree's own precision `T`, then padded
//!   outwards by [`PAD_ULPS`] units in the last place of the box's largest coordinate, which
//!   absorbs a kernel's rounding at triangle edges.
//! - The far distance of the slab test is multiplied by `1 + 2 gamma(3)` (Ize, "Robust BVH Ray
//!   Traversal", JCGT 2013), which bounds the rounding of `(plane - origin) * inv_dir`; the
//!   current best distance is compared with the same factor, and a node whose entry distance
//!   equals the best distance is still visited, so ties are resolved by
//!   [`intersect::Hit::nearer_than`] and not by traversal order.
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

use core::ops::Range;

use intersect::{Ray, Real, Triangle};

/// Number of bins per axis in the SAH build.
pub const BINS: usize = 16;
/// Largest number of primitives in a leaf.
pub const MAX_LEAF: usize = 8;
/// Largest depth of a leaf (the root has depth 0); the traversal stack holds this many entries.
pub const MAX_DEPTH: usize = 64;
/// Outward padding of node boxes, in units in the last place of the box's largest coordinate.
pub const PAD_ULPS: u32 = 32;

/// SAH cost of one node traversal step, relative to one primitive test.
const TRAVERSAL_COST: f64 = 1.0;

/// `min(a, b)`, ignoring `b` if it is NaN (a compare and a select: one `minss`/`minsd`, cheaper
/// than the NaN-symmetric `f64::min`). `a` is never NaN where this is used.
#[inline(always)]
fn min_or<T: PartialOrd>(a: T, b: T) -> T {
    if b < a { b } else { a }
}

/// `max(a, b)`, ignoring `b` if it is NaN (see [`min_or`]).
#[inline(always)]
fn max_or<T: PartialOrd>(a: T, b: T) -> T {
    if b > a { b } else { a }
}

/// An axis-aligned bounding box. The empty box has `min = +inf`, `max = -inf`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aabb<T> {
    /// Lower corner.
    pub min: [T; 3],
    /// Upper corner.
    pub max: [T; 3],
}

impl<T: Real> Default for Aabb<T> {
    fn default() -> Self {
        Self::empty()
    }
}

impl<T: Real> Aabb<T> {
    /// The empty box: growing it by a point gives that point's box.
    #[must_use]
    pub fn empty() -> Self {
        Self { min: [T::INFINITY; 3], max: [-T::INFINITY; 3] }
    }

    /// The smallest box holding all `points` (empty if there are none).
    #[must_use]
    pub fn from_points(points: &[[T; 3]]) -> Self {
        let mut b = Self::empty();
        for p in points {
            b.grow_point(*p);
        }
        b
    }

    /// The exact box of a triangle's three vertices.
    #[must_use]
    pub fn of_triangle(tri: &Triangle<T>) -> Self {
        Self::from_points(&tri.vertices())
    }

    /// Whether the box holds no point.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        !(0..3).all(|k| self.min[k] <= self.max[k])
    }

    /// Grows the box to hold `p` (NaN coordinates are ignored).
    #[inline]
    pub fn grow_point(&mut self, p: [T; 3]) {
        for (k, x) in p.into_iter().enumerate() {
            self.min[k] = min_or(self.min[k], x);
            self.max[k] = max_or(self.max[k], x);
        }
    }

    /// Grows the box to hold `other` (NaN coordinates are ignored).
    #[inline]
    pub fn grow(&mut self, other: &Self) {
        for k in 0..3 {
            self.min[k] = min_or(self.min[k], other.min[k]);
            self.max[k] = max_or(self.max[k], other.max[k]);
        }
    }

    /// The smallest box holding both.
    #[must_use]
    pub fn union(&self, other: &Self) -> Self {
        let mut b = *self;
        b.grow(other);
        b
    }

    /// Whether `other` lies inside `self` (boundary included). The empty box lies in every box.
    #[must_use]
    pub fn contains(&self, other: &Self) -> bool {
        other.is_empty()
            || (0..3).all(|k| self.min[k] <= other.min[k] && other.max[k] <= self.max[k])
    }

    /// Whether the point lies inside the box (boundary included).
    #[must_use]
    pub fn contains_point(&self, p: [T; 3]) -> bool {
        (0..3).all(|k| self.min[k] <= p[k] && p[k] <= self.max[k])
    }

    /// The centre of the box.
    #[must_use]
    pub fn center(&self) -> [T; 3] {
        let half = T::from_f64(0.5);
        core::array::from_fn(|k| (self.min[k] + self.max[k]) * half)
    }

    /// The edge lengths (`max - min`).
    #[must_use]
    pub fn extent(&self) -> [T; 3] {
        core::array::from_fn(|k| self.max[k] - self.min[k])
    }

    /// Half the surface area, in `f64` (0 for an empty box): the SAH only needs ratios.
    #[must_use]
    pub fn half_area(&self) -> f64 {
        if self.is_empty() {
            return 0.0;
        }
        let [x, y, z] = self.extent().map(Real::to_f64);
        x * y + y * z + z * x
    }

    /// The box grown outwards by [`PAD_ULPS`] units in the last place of its largest
    /// coordinate magnitude (see the [module documentation](self) for why).
    #[must_use]
    pub fn padded(&self) -> Self {
        if self.is_empty() {
            return *self;
        }
        let mut magnitude = T::ZERO;
        for k in 0..3 {
            magnitude = magnitude.max(self.min[k].abs()).max(self.max[k].abs());
        }
        // `pad >= PAD_ULPS * ulp(c)` for every coordinate `c` of the box, so the subtraction
        // and addition below move each face by many ulps and never round back.
        let pad = magnitude * T::EPSILON * T::from_f64(f64::from(PAD_ULPS));
        Self { min: self.min.map(|m| m - pad), max: self.max.map(|m| m + pad) }
    }
}

/// One node of the flattened tree.
#[derive(Clone, Copy, Debug)]
struct Node<T> {
    /// Padded bounds of everything below.
    bounds: Aabb<T>,
    /// Leaf: first slot. Interior: index of the second child (the first is the next node).
    offset: u32,
    /// Leaf: number of primitives (at least 1). Interior: 0.
    count: u32,
}

/// What a node is, as seen from outside.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum NodeKind {
    /// A leaf holding the primitives in these slots of [`Bvh::order`].
    Leaf(Range<usize>),
    /// An interior node with two children (node indices).
    Interior {
        /// First child (always the node right after its parent).
        left: usize,
        /// Second child.
        right: usize,
    },
}

/// A bounding volume hierarchy with boxes in precision `T`.
#[derive(Clone, Debug)]
pub struct Bvh<T> {
    nodes: Vec<Node<T>>,
    /// `order[slot]` is the original index of the primitive stored at `slot`.
    order: Vec<u32>,
    depth: usize,
}

impl<T: Real> Bvh<T> {
    /// Builds the tree over one box per primitive (binned SAH, see the
    /// [module documentation](self)).
    ///
    /// Boxes should be finite; a box with NaN coordinates never meets any ray.
    ///
    /// # Panics
    ///
    /// If there are more than `u32::MAX` boxes.
    #[must_use]
    pub fn build(boxes: &[Aabb<T>]) -> Self {
        let n = boxes.len();
        assert!(u32::try_from(n).is_ok(), "a BVH holds at most u32::MAX primitives, got {n}");
        if n == 0 {
            return Self { nodes: Vec::new(), order: Vec::new(), depth: 0 };
        }
        let mut builder = Builder {
            refs: boxes
                .iter()
                .enumerate()
                .map(|(i, b)| PrimRef { bounds: *b, index: i as u32 })
                .collect(),
            // A binary tree with leaves of >= 1 primitive has at most 2n - 1 nodes.
            nodes: Vec::with_capacity(2 * n),
            depth: 0,
            bins: Vec::with_capacity(3 * BINS),
        };
        let info = NodeInfo::of(&builder.refs);
        builder.node(0, n, 0, &info);
        let Builder { mut nodes, refs, depth, .. } = builder;
        nodes.shrink_to_fit();
        let order = refs.iter().map(|r| r.index).collect();
        Self { nodes, order, depth }
    }

    /// Slot order: `order()[slot]` is the original index of the primitive stored at `slot`.
    #[must_use]
    pub fn order(&self) -> &[u32] {
        &self.order
    }

    /// Number of primitives.
    #[must_use]
    pub fn len(&self) -> usize {
        self.order.len()
    }

    /// Whether the tree holds no primitive.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.order.is_empty()
    }

    /// Number of nodes (interior and leaves).
    #[must_use]
    pub fn node_count(&self) -> usize {
        self.nodes.len()
    }

    /// Number of leaves.
    #[must_use]
    pub fn leaf_count(&self) -> usize {
        self.nodes.iter().filter(|n| n.count > 0).count()
    }

    /// Depth of the deepest leaf (the root has depth 0); at most [`MAX_DEPTH`]` - 1`.
    #[must_use]
    pub fn depth(&self) -> usize {
        self.depth
    }

    /// Bytes held by the nodes and the slot order.
    #[must_use]
    pub fn bytes(&self) -> usize {
        self.nodes.len() * size_of::<Node<T>>() + self.order.len() * size_of::<u32>()
    }

    /// The padded bounds of node `i` (node 0 is the root).
    ///
    /// # Panics
    ///
    /// If `i >= self.node_count()`.
    #[must_use]
    pub fn node_bounds(&self, i: usize) -> Aabb<T> {
        self.nodes[i].bounds
    }

    /// Whether node `i` is a leaf or an interior node, and what it points to.
    ///
    /// # Panics
    ///
    /// If `i >= self.node_count()`.
    #[must_use]
    pub fn node_kind(&self, i: usize) -> NodeKind {
        let n = &self.nodes[i];
        if n.count > 0 {
            NodeKind::Leaf(n.offset as usize..(n.offset + n.count) as usize)
        } else {
            NodeKind::Interior { left: i + 1, right: n.offset as usize }
        }
    }

    /// Visits the leaves that `ray` may reach within `(0, t_max]`, nearest first.
    ///
    /// `leaf` gets a range of slots and the current distance limit, which it lowers when it
    /// finds a nearer hit; nodes entered beyond the limit are skipped from then on (a node
    /// entered exactly at the limit is still visited, so ties can be resolved by the caller).
    #[inline]
    pub fn closest<F>(&self, ray: &Ray<T>, t_max: T, mut leaf: F)
    where
        F: FnMut(Range<usize>, &mut T),
    {
        let Some(root) = self.nodes.first() else { return };
        let slabs = Slabs::new(ray);
        let mut limit = t_max;
        if slabs.entry(&root.bounds, limit).is_none() {
            return;
        }
        let mut stack = [(0u32, T::ZERO); MAX_DEPTH];
        let mut sp = 0;
        let mut node = 0usize;
        loop {
            let n = &self.nodes[node];
            let next = if n.count > 0 {
                leaf(n.offset as usize..(n.offset + n.count) as usize, &mut limit);
                None
            } else {
                let (left, right) = (node + 1, n.offset as usize);
                let tl = slabs.entry(&self.nodes[left].bounds, limit);
                let tr = slabs.entry(&self.nodes[right].bounds, limit);
                match (tl, tr) {
                    (Some(a), Some(b)) => {
                        // Nearer child first; the other waits with its entry distance.
                        let (near, far, t_far) =
                            if a <= b { (left, right, b) } else { (right, left, a) };
                        stack[sp] = (far as u32, t_far);
                        sp += 1;
                        Some(near)
                    }
                    (Some(_), None) => Some(left),
                    (None, Some(_)) => Some(right),
                    (None, None) => None,
                }
            };
            node = match next {
                Some(i) => i,
                None => {
                    // Pop until a node that still starts within the (possibly lowered) limit.
                    let bound = limit * slack::<T>();
                    loop {
                        if sp == 0 {
                            return;
                        }
                        sp -= 1;
                        let (i, t_entry) = stack[sp];
                        if t_entry <= bound {
                            break i as usize;
                        }
                    }
                }
            };
        }
    }

    /// Visits the leaves that `ray` may reach within `(0, t_max]` until `leaf` returns `true`;
    /// returns whether it did.
    #[inline]
    pub fn any<F>(&self, ray: &Ray<T>, t_max: T, mut leaf: F) -> bool
    where
        F: FnMut(Range<usize>) -> bool,
    {
        let Some(root) = self.nodes.first() else { return false };
        let slabs = Slabs::new(ray);
        if slabs.entry(&root.bounds, t_max).is_none() {
            return false;
        }
        let mut stack = [0u32; MAX_DEPTH];
        let mut sp = 0;
        let mut node = 0usize;
        loop {
            let n = &self.nodes[node];
            if n.count > 0 {
                if leaf(n.offset as usize..(n.offset + n.count) as usize) {
                    return true;
                }
            } else {
                let (left, right) = (node + 1, n.offset as usize);
                let hit_left = slabs.entry(&self.nodes[left].bounds, t_max).is_some();
                let hit_right = slabs.entry(&self.nodes[right].bounds, t_max).is_some();
                match (hit_left, hit_right) {
                    (true, true) => {
                        stack[sp] = right as u32;
                        sp += 1;
                        node = left;
                        continue;
                    }
                    (true, false) => {
                        node = left;
                        continue;
                    }
                    (false, true) => {
                        node = right;
                        continue;
                    }
                    (false, false) => {}
                }
            }
            if sp == 0 {
                return false;
            }
            sp -= 1;
            node = stack[sp] as usize;
        }
    }
}

/// `1 + 2 gamma(3)` with `gamma(n) = n u / (1 - n u)` and `u` the unit roundoff: the factor by
/// which a slab distance `(plane - origin) * inv_dir` may be too small (Ize 2013).
#[inline(always)]
fn slack<T: Real>() -> T {
    let u = T::EPSILON.to_f64() * 0.5;
    let gamma3 = 3.0 * u / (1.0 - 3.0 * u);
    // Rounding `1 + 2 gamma(3)` to `T` may lose up to half an ulp; one more ulp keeps it an
    // upper bound.
    T::from_f64(1.0 + 2.0 * gamma3) + T::EPSILON
}

/// A ray prepared for slab tests: origin, inverse direction and which face of each slab it
/// enters first.
struct Slabs<T> {
    origin: [T; 3],
    inv_dir: [T; 3],
    negative: [bool; 3],
}

impl<T: Real> Slabs<T> {
    #[inline(always)]
    fn new(ray: &Ray<T>) -> Self {
        // A zero component gives +-inf, with the sign of the zero: the slab then either holds
        // the whole ray or none of it.
        let inv_dir = ray.dir.map(|d| T::ONE / d);
        // Decided on the inverse so that -0.0 (inverse -inf) counts as negative.
        let negative = inv_dir.map(|d| d < T::ZERO);
        Self { origin: ray.origin, inv_dir, negative }
    }

    /// The entry distance of the ray into `b` if the ray meets it within `(0, limit]`,
    /// conservatively.
    #[inline(always)]
    fn entry(&self, b: &Aabb<T>, limit: T) -> Option<T> {
        let mut near = T::ZERO;
        let mut far = limit;
        for k in 0..3 {
            let (lo, hi) =
                if self.negative[k] { (b.max[k], b.min[k]) } else { (b.min[k], b.max[k]) };
            // `max_or`/`min_or` ignore a NaN distance (0 * inf: the ray lies in the face
            // plane), so such a slab constrains nothing; `near` and `far` are never NaN
            // themselves (a NaN `limit` makes every box miss).
            near = max_or(near, (lo - self.origin[k]) * self.inv_dir[k]);
            far = min_or(far, (hi - self.origin[k]) * self.inv_dir[k]);
        }
        (near <= far * slack::<T>()).then_some(near)
    }
}

/// A primitive during the build: its box and original index, moved around by partitioning so
/// that each node's primitives are contiguous in memory (no gather through an index array).
#[derive(Clone, Copy)]
struct PrimRef<T> {
    bounds: Aabb<T>,
    index: u32,
}

impl<T: Real> PrimRef<T> {
    /// Twice the box centre along `axis`, in f64: binning needs only an affine image of the
    /// centroid, and the f64 sum of two `T` values cannot overflow.
    #[inline(always)]
    fn centroid2(&self, axis: usize) -> f64 {
        self.bounds.min[axis].to_f64() + self.bounds.max[axis].to_f64()
    }
}

/// What a node needs to know of its primitives: their bounds and their (doubled) centroid
/// bounds.
#[derive(Clone, Copy)]
struct NodeInfo<T> {
    bounds: Aabb<T>,
    cmin: [f64; 3],
    cmax: [f64; 3],
}

impl<T: Real> NodeInfo<T> {
    fn empty() -> Self {
        Self { bounds: Aabb::empty(), cmin: [f64::INFINITY; 3], cmax: [f64::NEG_INFINITY; 3] }
    }

    #[inline(always)]
    fn add(&mut self, r: &PrimRef<T>) {
        self.bounds.grow(&r.bounds);
        for k in 0..3 {
            let c = r.centroid2(k);
            self.cmin[k] = min_or(self.cmin[k], c);
            self.cmax[k] = max_or(self.cmax[k], c);
        }
    }

    fn of(refs: &[PrimRef<T>]) -> Self {
        let mut info = Self::empty();
        for r in refs {
            info.add(r);
        }
        info
    }
}

/// One SAH bin: the union of its primitives' boxes and their number.
#[derive(Clone, Copy)]
struct Bin<T> {
    bounds: Aabb<T>,
    count: u32,
}

/// Build state: the primitives being partitioned in place, the nodes written so far, and bins
/// reused from node to node.
struct Builder<T> {
    refs: Vec<PrimRef<T>>,
    nodes: Vec<Node<T>>,
    depth: usize,
    bins: Vec<Bin<T>>,
}

/// A candidate SAH split: the left side holds bins `0..=bin` of `binning` on `axis`.
#[derive(Clone, Copy)]
struct Split {
    axis: usize,
    bin: usize,
    binning: Binning,
    cost: f64,
}

/// Maps (doubled) centroid coordinates to `count` bins along one axis.
#[derive(Clone, Copy)]
struct Binning {
    min: f64,
    scale: f64,
    count: usize,
}

impl Binning {
    fn new(min: f64, extent: f64, count: usize) -> Self {
        // Slightly under count / extent so that the largest centroid lands in the last bin;
        // 0 for a flat axis (everything in bin 0).
        let scale = if extent > 0.0 { count as f64 * (1.0 - 1e-9) / extent } else { 0.0 };
        Self { min, scale, count }
    }

    #[inline(always)]
    fn bin(&self, c: f64) -> usize {
        // `as usize` saturates (and maps NaN to 0); `min` guards the top.
        (((c - self.min) * self.scale) as usize).min(self.count - 1)
    }
}

impl<T: Real> Builder<T> {
    /// Builds the subtree over `refs[start..end]` (described by `info`) at `depth`; returns
    /// its node index.
    fn node(&mut self, start: usize, end: usize, depth: usize, info: &NodeInfo<T>) -> usize {
        self.depth = self.depth.max(depth);
        let index = self.nodes.len();
        self.nodes.push(Node { bounds: info.bounds.padded(), offset: start as u32, count: 0 });
        let n = end - start;
        let Some((mid, left, right)) = self.choose_split(start, end, depth, info) else {
            self.nodes[index].count = n as u32;
            return index;
        };
        self.node(start, mid, depth + 1, &left);
        let right = self.node(mid, end, depth + 1, &right);
        self.nodes[index].offset = right as u32;
        index
    }

    /// Partitions `refs[start..end]` and returns the first index of the second child with
    /// both children's descriptions, or `None` if the node should be a leaf.
    fn choose_split(
        &mut self,
        start: usize,
        end: usize,
        depth: usize,
        info: &NodeInfo<T>,
    ) -> Option<(usize, NodeInfo<T>, NodeInfo<T>)> {
        let n = end - start;
        if n == 1 {
            return None;
        }
        let extent: [f64; 3] = core::array::from_fn(|k| info.cmax[k] - info.cmin[k]);
        // SAH is allowed only while a fall-back to median splits (which halve the count) from
        // each child can still finish above MAX_DEPTH.
        let sah_allowed = depth + 1 + ceil_log2(n) < MAX_DEPTH;
        let flat = !extent.iter().any(|&e| e > 0.0);
        if !sah_allowed || flat {
            return (n > MAX_LEAF).then(|| self.median_split(start, end, &extent));
        }
        let area = info.bounds.half_area();
        let split_cost = |s: &Split| {
            if area > 0.0 { TRAVERSAL_COST + s.cost / area } else { TRAVERSAL_COST }
        };
        match self.best_split(start, end, info.cmin, &extent) {
            Some(s) if n > MAX_LEAF || split_cost(&s) < n as f64 => {
                let (mid, left, right) = partition(&mut self.refs[start..end], |r| {
                    s.binning.bin(r.centroid2(s.axis)) <= s.bin
                });
                Some((start + mid, left, right))
            }
            Some(_) => None,
            // Every axis put all centroids in one bin (possible only with extents so small
            // that binning cannot separate them).
            None => (n > MAX_LEAF).then(|| self.median_split(start, end, &extent)),
        }
    }

    /// The cheapest binned SAH split over all axes: `cost` is `n_l A_l + n_r A_r` (half
    /// areas). `None` if no axis has two non-empty sides. Small nodes use fewer bins.
    fn best_split(
        &mut self,
        start: usize,
        end: usize,
        cmin: [f64; 3],
        extent: &[f64; 3],
    ) -> Option<Split> {
        let count = BINS.min(end - start);
        // A flat axis bins everything into its bin 0 (no branch in the loop below) and is
        // skipped when costs are swept.
        let binnings: [Binning; 3] =
            core::array::from_fn(|k| Binning::new(cmin[k], extent[k], count));
        let empty = Bin { bounds: Aabb::empty(), count: 0 };
        self.bins.clear();
        self.bins.resize(3 * count, empty);
        for r in &self.refs[start..end] {
            for (k, binning) in binnings.iter().enumerate() {
                let bin = &mut self.bins[k * count + binning.bin(r.centroid2(k))];
                bin.bounds.grow(&r.bounds);
                bin.count += 1;
            }
        }
        let mut best: Option<Split> = None;
        let mut right_cost = [0.0f64; BINS];
        for (axis, &binning) in binnings.iter().enumerate() {
            if extent[axis] <= 0.0 {
                continue;
            }
            let bins = &self.bins[axis * count..(axis + 1) * count];
            // Right-to-left sweep: cost of everything right of each boundary (-1: nothing).
            let mut acc = Aabb::empty();
            let mut on_right = 0u32;
            for i in (1..count).rev() {
                acc.grow(&bins[i].bounds);
                on_right += bins[i].count;
                right_cost[i - 1] =
                    if on_right > 0 { f64::from(on_right) * acc.half_area() } else { -1.0 };
            }
            let mut acc = Aabb::empty();
            let mut on_left = 0u32;
            for (i, bin) in bins[..count - 1].iter().enumerate() {
                acc.grow(&bin.bounds);
                on_left += bin.count;
                if on_left == 0 || right_cost[i] < 0.0 {
                    continue;
                }
                let cost = f64::from(on_left) * acc.half_area() + right_cost[i];
                if best.is_none_or(|b| cost < b.cost) {
                    best = Some(Split { axis, bin: i, binning, cost });
                }
            }
        }
        best
    }

    /// Splits `refs[start..end]` at their middle by centroid along the widest axis.
    fn median_split(
        &mut self,
        start: usize,
        end: usize,
        extent: &[f64; 3],
    ) -> (usize, NodeInfo<T>, NodeInfo<T>) {
        let mut axis = 0;
        for k in 1..3 {
            if extent[k] > extent[axis] {
                axis = k;
            }
        }
        let mid = start + (end - start) / 2;
        self.refs[start..end].select_nth_unstable_by(mid - start, |a, b| {
            a.centroid2(axis).total_cmp(&b.centroid2(axis))
        });
        (mid, NodeInfo::of(&self.refs[start..mid]), NodeInfo::of(&self.refs[mid..end]))
    }
}

/// Moves the primitives satisfying `left` to the front; returns how many there are and the
/// descriptions of both sides, gathered on the way (each primitive is looked at once).
fn partition<T: Real>(
    v: &mut [PrimRef<T>],
    mut left: impl FnMut(&PrimRef<T>) -> bool,
) -> (usize, NodeInfo<T>, NodeInfo<T>) {
    let (mut l, mut r) = (NodeInfo::empty(), NodeInfo::empty());
    let mut i = 0;
    let mut j = v.len();
    while i < j {
        if left(&v[i]) {
            l.add(&v[i]);
            i += 1;
        } else {
            r.add(&v[i]);
            j -= 1;
            v.swap(i, j);
        }
    }
    (i, l, r)
}

/// `ceil(log2(n))` for `n >= 1`.
fn ceil_log2(n: usize) -> usize {
    (usize::BITS - (n - 1).leading_zeros()) as usize
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ceil_log2_values() {
        assert_eq!([1, 2, 3, 4, 5, 8, 9].map(ceil_log2), [0, 1, 2, 2, 3, 3, 4]);
    }

    #[test]
    fn partition_keeps_every_element_and_describes_both_sides() {
        let mut v: Vec<PrimRef<f64>> = (0..100)
            .map(|i| {
                let x = f64::from(i);
                PrimRef { bounds: Aabb { min: [x, 0.0, 0.0], max: [x, 1.0, 2.0] }, index: i }
            })
            .collect();
        let (mid, l, r) = partition(&mut v, |p| p.index % 3 == 0);
        assert_eq!(mid, 34);
        assert!(v[..mid].iter().all(|p| p.index % 3 == 0));
        assert!(v[mid..].iter().all(|p| p.index % 3 != 0));
        assert_eq!((l.bounds.min[0], l.bounds.max[0]), (0.0, 99.0));
        assert_eq!((r.bounds.min[0], r.bounds.max[0]), (1.0, 98.0));
        assert_eq!((l.cmin[2], l.cmax[2], r.cmin[0]), (2.0, 2.0, 2.0));
        let mut idx: Vec<u32> = v.iter().map(|p| p.index).collect();
        idx.sort_unstable();
        assert_eq!(idx, (0..100).collect::<Vec<_>>());
    }

    #[test]
    fn padding_moves_every_face_outwards() {
        let b = Aabb { min: [1.0f32, -3.0, 0.0], max: [2.0, 1e6, 0.0] };
        let p = b.padded();
        for k in 0..3 {
            assert!(p.min[k] < b.min[k] && p.max[k] > b.max[k]);
        }
    }

    #[test]
    fn slab_test_with_zero_direction_components() {
        let b = Aabb { min: [0.0f64, 0.0, 0.0], max: [1.0, 1.0, 1.0] };
        // Ray lying in the face plane x = 0, along +z from below.
        let s = Slabs::new(&Ray::new([0.0, 0.5, -1.0], [0.0, 0.0, 1.0]));
        assert_eq!(s.entry(&b, f64::INFINITY), Some(1.0));
        // Same with -0.0 components.
        let s = Slabs::new(&Ray::new([0.0, 0.5, -1.0], [-0.0, -0.0, 1.0]));
        assert_eq!(s.entry(&b, f64::INFINITY), Some(1.0));
        // Parallel to the slab but outside it.
        let s = Slabs::new(&Ray::new([2.0, 0.5, -1.0], [0.0, 0.0, 1.0]));
        assert_eq!(s.entry(&b, f64::INFINITY), None);
        // Behind the origin, and beyond the limit.
        let s = Slabs::new(&Ray::new([0.5, 0.5, 3.0], [0.0, 0.0, 1.0]));
        assert_eq!(s.entry(&b, f64::INFINITY), None);
        let s = Slabs::new(&Ray::new([0.5, 0.5, -3.0], [0.0, 0.0, 1.0]));
        assert_eq!(s.entry(&b, 2.5), None);
        assert_eq!(s.entry(&b, 3.0), Some(3.0));
    }
}
