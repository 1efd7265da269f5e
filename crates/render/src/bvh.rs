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

    /// Grows the box to hold `p`.
    pub fn grow_point(&mut self, p: [T; 3]) {
        for (k, x) in p.into_iter().enumerate() {
            self.min[k] = self.min[k].min(x);
            self.max[k] = self.max[k].max(x);
        }
    }

    /// Grows the box to hold `other`.
    pub fn grow(&mut self, other: &Self) {
        for k in 0..3 {
            self.min[k] = self.min[k].min(other.min[k]);
            self.max[k] = self.max[k].max(other.max[k]);
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
        let order: Vec<u32> = (0..n as u32).collect();
        if n == 0 {
            return Self { nodes: Vec::new(), order, depth: 0 };
        }
        let mut builder = Builder {
            boxes,
            centroids: boxes.iter().map(Aabb::center).collect(),
            order,
            // A binary tree with leaves of >= 1 primitive has at most 2n - 1 nodes.
            nodes: Vec::with_capacity(2 * n),
            depth: 0,
        };
        builder.node(0, n, 0);
        let Builder { mut nodes, order, depth, .. } = builder;
        nodes.shrink_to_fit();
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
            // `max`/`min` return the other operand when one is NaN (0 * inf: the ray lies in
            // the face plane), so such a slab constrains nothing; `near` and `far` are never
            // NaN themselves.
            near = near.max((lo - self.origin[k]) * self.inv_dir[k]);
            far = far.min((hi - self.origin[k]) * self.inv_dir[k]);
        }
        (near <= far * slack::<T>()).then_some(near)
    }
}

/// Build state: the boxes, their centroids and the slot order being partitioned in place.
struct Builder<'a, T> {
    boxes: &'a [Aabb<T>],
    centroids: Vec<[T; 3]>,
    order: Vec<u32>,
    nodes: Vec<Node<T>>,
    depth: usize,
}

/// A candidate SAH split: bin boundary `bin` (left holds bins `0..=bin`) on `axis`.
#[derive(Clone, Copy)]
struct Split {
    axis: usize,
    bin: usize,
    cost: f64,
}

/// Maps centroid coordinates to bins along one axis.
#[derive(Clone, Copy)]
struct Binning {
    min: f64,
    scale: f64,
}

impl Binning {
    fn new(min: f64, extent: f64) -> Self {
        // Slightly under BINS / extent so that the largest centroid lands in the last bin.
        Self { min, scale: BINS as f64 * (1.0 - 1e-9) / extent }
    }

    #[inline(always)]
    fn bin(&self, c: f64) -> usize {
        // `as usize` saturates (and maps NaN to 0); `min` guards the top.
        (((c - self.min) * self.scale) as usize).min(BINS - 1)
    }
}

impl<T: Real> Builder<'_, T> {
    /// Builds the subtree over slots `start..end` at `depth`; returns its node index.
    fn node(&mut self, start: usize, end: usize, depth: usize) -> usize {
        self.depth = self.depth.max(depth);
        let index = self.nodes.len();
        let mut bounds = Aabb::empty();
        let mut centroid_bounds = Aabb::empty();
        for &p in &self.order[start..end] {
            bounds.grow(&self.boxes[p as usize]);
            centroid_bounds.grow_point(self.centroids[p as usize]);
        }
        self.nodes.push(Node { bounds: bounds.padded(), offset: start as u32, count: 0 });
        let n = end - start;
        let mid = match self.choose_split(start, end, depth, &bounds, &centroid_bounds) {
            Some(mid) => mid,
            None => {
                self.nodes[index].count = n as u32;
                return index;
            }
        };
        self.node(start, mid, depth + 1);
        let right = self.node(mid, end, depth + 1);
        self.nodes[index].offset = right as u32;
        index
    }

    /// Partitions slots `start..end` and returns the first slot of the second child, or
    /// `None` if the node should be a leaf.
    fn choose_split(
        &mut self,
        start: usize,
        end: usize,
        depth: usize,
        bounds: &Aabb<T>,
        centroid_bounds: &Aabb<T>,
    ) -> Option<usize> {
        let n = end - start;
        if n == 1 {
            return None;
        }
        let extent = centroid_bounds.extent().map(Real::to_f64);
        // SAH is allowed only while a fall-back to median splits (which halve the count) from
        // each child can still finish above MAX_DEPTH; see `Bvh::build`.
        let sah_allowed = depth + 1 + ceil_log2(n) < MAX_DEPTH;
        let flat = !extent.iter().any(|&e| e > 0.0);
        if !sah_allowed || flat {
            return (n > MAX_LEAF).then(|| self.median_split(start, end, &extent));
        }
        let split = self.best_split(start, end, centroid_bounds, &extent);
        let area = bounds.half_area();
        let cost = |s: &Split| {
            if area > 0.0 { TRAVERSAL_COST + s.cost / area } else { TRAVERSAL_COST }
        };
        match split {
            Some(s) if n > MAX_LEAF || cost(&s) < n as f64 => {
                let binning = Binning::new(centroid_bounds.min[s.axis].to_f64(), extent[s.axis]);
                let centroids = &self.centroids;
                let mid = partition(&mut self.order[start..end], |p| {
                    binning.bin(centroids[p as usize][s.axis].to_f64()) <= s.bin
                });
                Some(start + mid)
            }
            Some(_) => None,
            // Every axis put all centroids in one bin (possible only with extents so small
            // that binning cannot separate them).
            None => (n > MAX_LEAF).then(|| self.median_split(start, end, &extent)),
        }
    }

    /// The cheapest binned SAH split over all axes: `cost` is `n_l A_l + n_r A_r` (half
    /// areas). `None` if no axis has two non-empty sides.
    fn best_split(
        &self,
        start: usize,
        end: usize,
        centroid_bounds: &Aabb<T>,
        extent: &[f64; 3],
    ) -> Option<Split> {
        let mut bins = [[(Aabb::<T>::empty(), 0u32); BINS]; 3];
        let binnings: [Option<Binning>; 3] = core::array::from_fn(|k| {
            (extent[k] > 0.0).then(|| Binning::new(centroid_bounds.min[k].to_f64(), extent[k]))
        });
        for &p in &self.order[start..end] {
            let c = self.centroids[p as usize];
            let b = &self.boxes[p as usize];
            for k in 0..3 {
                if let Some(binning) = &binnings[k] {
                    let slot = &mut bins[k][binning.bin(c[k].to_f64())];
                    slot.0.grow(b);
                    slot.1 += 1;
                }
            }
        }
        let mut best: Option<Split> = None;
        for (axis, bins) in bins.iter().enumerate() {
            if binnings[axis].is_none() {
                continue;
            }
            // Right-to-left sweep: cost of everything right of each boundary.
            let mut right_cost = [0.0f64; BINS];
            let mut acc = Aabb::empty();
            let mut count = 0u32;
            for i in (1..BINS).rev() {
                acc.grow(&bins[i].0);
                count += bins[i].1;
                right_cost[i - 1] =
                    if count > 0 { f64::from(count) * acc.half_area() } else { -1.0 };
            }
            let mut acc = Aabb::empty();
            let mut count = 0u32;
            for (i, bin) in bins.iter().enumerate().take(BINS - 1) {
                acc.grow(&bin.0);
                count += bin.1;
                if count == 0 || right_cost[i] < 0.0 {
                    continue;
                }
                let cost = f64::from(count) * acc.half_area() + right_cost[i];
                if best.is_none_or(|b| cost < b.cost) {
                    best = Some(Split { axis, bin: i, cost });
                }
            }
        }
        best
    }

    /// Splits slots `start..end` at their middle by centroid along the widest axis.
    fn median_split(&mut self, start: usize, end: usize, extent: &[f64; 3]) -> usize {
        let mut axis = 0;
        for k in 1..3 {
            if extent[k] > extent[axis] {
                axis = k;
            }
        }
        let mid = (end - start) / 2;
        let centroids = &self.centroids;
        self.order[start..end].select_nth_unstable_by(mid, |&a, &b| {
            let ca = centroids[a as usize][axis].to_f64();
            let cb = centroids[b as usize][axis].to_f64();
            ca.total_cmp(&cb)
        });
        start + mid
    }
}

/// Moves the elements satisfying `left` to the front; returns how many there are.
fn partition(v: &mut [u32], mut left: impl FnMut(u32) -> bool) -> usize {
    let mut i = 0;
    let mut j = v.len();
    while i < j {
        if left(v[i]) {
            i += 1;
        } else {
            j -= 1;
            v.swap(i, j);
        }
    }
    i
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
    fn partition_keeps_every_element() {
        let mut v: Vec<u32> = (0..100).collect();
        let mid = partition(&mut v, |x| x % 3 == 0);
        assert_eq!(mid, 34);
        assert!(v[..mid].iter().all(|x| x % 3 == 0));
        assert!(v[mid..].iter().all(|x| x % 3 != 0));
        v.sort_unstable();
        assert_eq!(v, (0..100).collect::<Vec<_>>());
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
