//! The build: binned SAH splits, grouped eight at a time into wide nodes, subtrees in parallel.
//!
//! Each set of primitives is *planned* once, when it is made: binned along all three axes
//! ([`BINS`] bins over the centroid bounds, fewer for small sets) to find its cheapest SAH
//! split, or marked a leaf. A wide node starts as one planned set and repeatedly splits the
//! child with the largest surface area (the one a ray is most likely to enter) until it has
//! [`WIDTH`] children or none is worth splitting (Wald et al., "Getting Rid of Packets", 2008;
//! what Embree's builders do). Children that are not leaves become wide nodes in turn. Every
//! primitive is binned and partitioned once per binary split above it, as in a binary build,
//! and no binary tree is ever stored.
//!
//! The build works in `f32` whatever the tree's precision: every primitive box is rounded
//! outwards to `f32` first ([`PrimRef::new`]), so one code path, four-lane SIMD throughout,
//! serves both precisions, and the node boxes it produces are `f32` anyway. Subtrees of at
//! least [`PARALLEL_MIN`] primitives are built in parallel on rayon's current pool, each into
//! its own node array, then appended with their node references shifted.

use rayon::prelude::*;

use intersect::Real;

use super::aabb::Aabb;
use super::node::{Node, WIDTH, f32_down, f32_up, leaf_ref};
use super::simd::F4;
use super::{BINS, MAX_DEPTH, MAX_LEAF, PAD_ULPS};

/// SAH cost of one binary split's traversal, relative to one primitive test. Measured, not
/// derived: on the bunny (one thread, `la` f32) 1.0 gave 12,396 nodes and 1.8 triangles per
/// leaf; 3.0 gives 4,951 nodes and 4.3 per leaf, 3.1 MB less memory, incoherent rays about 25%
/// faster (they wait on memory) and primary rays about 7% faster; 4.0 and 6.0 were no better.
const TRAVERSAL_COST: f64 = 3.0;

/// Sets at least this large build their children in parallel (when the pool has threads).
pub const PARALLEL_MIN: usize = 8192;

/// A primitive during the build: its box rounded outwards to `f32` and its original index,
/// stored in lane 3 of `lo` (bit for bit; an index below 2^28 is a small positive float, never
/// a NaN, and lane 3 is ignored by everything that reads the box). 32 bytes, moved around by
/// partitioning so that each set's primitives are contiguous.
#[derive(Clone, Copy, Debug)]
#[repr(C, align(16))]
pub struct PrimRef {
    lo: [f32; 4],
    hi: [f32; 4],
}

impl PrimRef {
    /// The reference of primitive `index` with box `b`.
    #[inline]
    pub fn new<T: Real>(b: &Aabb<T>, index: u32) -> Self {
        let [x, y, z] = b.min.map(|v| f32_down(v.to_f64()));
        let [u, v, w] = b.max.map(|v| f32_up(v.to_f64()));
        Self { lo: [x, y, z, f32::from_bits(index)], hi: [u, v, w, 0.0] }
    }

    /// The original index.
    #[inline(always)]
    pub fn index(&self) -> u32 {
        self.lo[3].to_bits()
    }

    #[inline(always)]
    fn lo(&self) -> F4 {
        F4::new(self.lo)
    }

    #[inline(always)]
    fn hi(&self) -> F4 {
        F4::new(self.hi)
    }

    /// Twice the box centre: binning needs only an affine image of the centroid.
    #[inline(always)]
    fn centroid2(&self) -> F4 {
        self.lo().add(self.hi())
    }
}

/// What a set needs to know of its primitives: the union of their boxes and the bounds of
/// their doubled centroids. Primitives with NaN coordinates add nothing.
#[derive(Clone, Copy, Debug)]
pub struct Info {
    lo: F4,
    hi: F4,
    clo: F4,
    chi: F4,
}

impl Info {
    fn empty() -> Self {
        let (inf, ninf) = (F4::splat(f32::INFINITY), F4::splat(f32::NEG_INFINITY));
        Self { lo: inf, hi: ninf, clo: inf, chi: ninf }
    }

    #[inline(always)]
    fn add(&mut self, r: &PrimRef) {
        let c = r.centroid2();
        self.lo = self.lo.min(r.lo());
        self.hi = self.hi.max(r.hi());
        self.clo = self.clo.min(c);
        self.chi = self.chi.max(c);
    }

    fn merge(mut self, other: Self) -> Self {
        self.lo = self.lo.min(other.lo);
        self.hi = self.hi.max(other.hi);
        self.clo = self.clo.min(other.clo);
        self.chi = self.chi.max(other.chi);
        self
    }

    /// The description of `refs`, computed in parallel chunks when there are many.
    pub fn of(refs: &[PrimRef]) -> Self {
        if refs.len() >= PARALLEL_MIN && rayon::current_num_threads() > 1 {
            return refs
                .par_chunks(PARALLEL_MIN)
                .map(Self::of_sequential)
                .reduce(Self::empty, Self::merge);
        }
        Self::of_sequential(refs)
    }

    fn of_sequential(refs: &[PrimRef]) -> Self {
        let mut info = Self::empty();
        for r in refs {
            info.add(r);
        }
        info
    }

    /// The box, `(lower corner, upper corner)`.
    fn bounds(&self) -> ([f32; 3], [f32; 3]) {
        let (lo, hi) = (self.lo.to_array(), self.hi.to_array());
        ([lo[0], lo[1], lo[2]], [hi[0], hi[1], hi[2]])
    }

    /// Half the surface area of the box, in `f64` (0 if empty).
    fn half_area(&self) -> f64 {
        let (lo, hi) = self.bounds();
        half_area(lo, hi)
    }
}

/// Half the surface area of the box `[lo, hi]` in `f64` (0 if empty).
fn half_area(lo: [f32; 3], hi: [f32; 3]) -> f64 {
    if !(0..3).all(|k| lo[k] <= hi[k]) {
        return 0.0;
    }
    let [x, y, z]: [f64; 3] = core::array::from_fn(|k| f64::from(hi[k]) - f64::from(lo[k]));
    x * y + y * z + z * x
}

/// The box of a node lane for a set with bounds `[lo, hi]`: grown by [`PAD_ULPS`] units in
/// the last place of precision `T` of its largest coordinate magnitude, then rounded outwards
/// to `f32` (see the module documentation of [`super`] for why). The empty box stays empty.
pub fn lane_box<T: Real>(lo: [f32; 3], hi: [f32; 3]) -> ([f32; 3], [f32; 3]) {
    if !(0..3).all(|k| lo[k] <= hi[k]) {
        return ([f32::INFINITY; 3], [f32::NEG_INFINITY; 3]);
    }
    let magnitude =
        (0..3).fold(0.0f64, |m, k| m.max(f64::from(lo[k]).abs()).max(f64::from(hi[k]).abs()));
    let pad = magnitude * T::EPSILON.to_f64() * f64::from(PAD_ULPS);
    (lo.map(|x| f32_down(f64::from(x) - pad)), hi.map(|x| f32_up(f64::from(x) + pad)))
}

/// Maps (doubled) centroids to `count` bins per axis.
#[derive(Clone, Copy, Debug)]
struct Binning {
    min: F4,
    scale: F4,
    count: usize,
}

impl Binning {
    fn new(info: &Info, count: usize) -> Self {
        // Slightly under count / extent, so that the largest centroid lands in the last bin
        // (the clamp in `bins` catches what rounding still pushes over); 0 for a flat or
        // non-finite axis (everything in bin 0).
        let extent = info.chi.sub(info.clo);
        let scale = F4::splat(count as f32 * (1.0 - 1e-6)).div(extent).to_array();
        let ok = extent.to_array().map(|e| e > 0.0 && e.is_finite());
        let scale = core::array::from_fn(|k| if k < 3 && ok[k] { scale[k] } else { 0.0 });
        Self { min: info.clo, scale: F4::new(scale), count }
    }

    /// The bins of `r` along x, y, z (lane 3: junk).
    #[inline(always)]
    fn bins(&self, r: &PrimRef) -> [u32; 4] {
        r.centroid2().sub(self.min).mul(self.scale).bins(self.count as i32 - 1)
    }
}

/// What to do with a set.
#[derive(Clone, Copy, Debug)]
enum Plan {
    /// Make it a leaf.
    Leaf,
    /// Split it: bins `0..=bin` of `binning` along `axis` go left.
    Sah { axis: usize, bin: u32, binning: Binning },
    /// Split it at the median centroid along `axis` (SAH unusable or not allowed).
    Median { axis: usize },
    /// Split it before position `mid` (a small set, already sorted by `sweep`).
    At { mid: usize },
}

/// A planned set: `refs[start..end]` of the slice being built, its description, its plan and
/// the number of binary splits above it.
#[derive(Clone, Copy, Debug)]
struct Set {
    start: usize,
    end: usize,
    info: Info,
    /// Half the surface area of the box.
    area: f64,
    plan: Plan,
    depth: usize,
}

impl Set {
    fn new(
        scratch: &mut Scratch,
        refs: &mut [PrimRef],
        (start, end): (usize, usize),
        info: Info,
        depth: usize,
    ) -> Self {
        let area = info.half_area();
        let plan = plan(scratch, &mut refs[start..end], &info, area, depth);
        Self { start, end, info, area, plan, depth }
    }

    fn len(&self) -> usize {
        self.end - self.start
    }
}

/// The SAH bins of one axis: the union of the boxes of each bin's primitives, and their
/// number. Fixed-size arrays, indexed with `& (BINS - 1)`, so the compiler sees every index in
/// bounds (`Binning::bins` already clamps them below `count <= BINS`).
#[derive(Clone, Copy)]
struct AxisBins {
    lo: [F4; BINS],
    hi: [F4; BINS],
    count: [u32; BINS],
}

const _: () = assert!(BINS.is_power_of_two());

/// Bins and sweep buffers reused from set to set (one per thread of the build): a set clears
/// only the bins it uses, so small sets cost little.
pub struct Scratch {
    /// Two sets of bins for the three axes (see `best_split`).
    axes: [[AxisBins; 3]; 4],
    /// `right_cost[i]`: primitives right of boundary `i` times the half area of their box.
    right_cost: [f32; BINS],
}

impl Scratch {
    pub fn new() -> Self {
        let empty =
            AxisBins { lo: [F4::INFINITY; BINS], hi: [F4::NEG_INFINITY; BINS], count: [0; BINS] };
        Self { axes: [[empty; 3]; 4], right_cost: [0.0; BINS] }
    }
}

/// Decides whether `refs` (described by `info`, `depth` splits below the root) becomes a leaf
/// or is split, and how.
fn plan(scratch: &mut Scratch, refs: &mut [PrimRef], info: &Info, area: f64, depth: usize) -> Plan {
    let n = refs.len();
    if n == 1 {
        return Plan::Leaf;
    }
    let (clo, chi) = (info.clo.to_array(), info.chi.to_array());
    let extent: [f32; 3] = core::array::from_fn(|k| chi[k] - clo[k]);
    let widest = (1..3).fold(0, |a, k| if extent[k] > extent[a] { k } else { a });
    let median = || if n > MAX_LEAF { Plan::Median { axis: widest } } else { Plan::Leaf };
    // SAH is allowed only while a fall-back to median splits (which halve the count) from
    // each child can still finish above MAX_DEPTH.
    let sah_allowed = depth + 1 + ceil_log2(n) < MAX_DEPTH;
    let flat = !extent.iter().any(|&e| e > 0.0);
    if !sah_allowed || flat {
        return median();
    }
    let found =
        if n <= SWEEP_MAX { Some(sweep(refs, widest)) } else { best_split(scratch, refs, info) };
    match found {
        Some((plan, cost)) => {
            let split_cost = if area > 0.0 { TRAVERSAL_COST + cost / area } else { TRAVERSAL_COST };
            if n > MAX_LEAF || split_cost < n as f64 { plan } else { Plan::Leaf }
        }
        // Every axis put all centroids in one bin (possible only with extents so small that
        // binning cannot separate them).
        None => median(),
    }
}

/// Sets of at most this many primitives are planned by [`sweep`] rather than by binning.
const SWEEP_MAX: usize = 16;

/// The exact SAH split of a small set along `axis`: sorts `refs` by centroid (insertion sort:
/// the set is small, and often sorted already, its parent having been sorted along the same
/// axis), then sweeps every boundary. Far cheaper than binning three axes for the many small
/// sets near the leaves, and as good: with at most [`SWEEP_MAX`] primitives every boundary
/// is tried. Returns the plan and its cost `n_l A_l + n_r A_r`.
fn sweep(refs: &mut [PrimRef], axis: usize) -> (Plan, f64) {
    let n = refs.len();
    debug_assert!((2..=SWEEP_MAX).contains(&n));
    let key = |r: &PrimRef| r.lo[axis] + r.hi[axis];
    for i in 1..n {
        let mut j = i;
        let k = key(&refs[i]);
        while j > 0 && key(&refs[j - 1]) > k {
            j -= 1;
        }
        if j < i {
            refs[j..=i].rotate_right(1);
        }
    }
    // right_cost[i]: primitives i + 1.. times the half area of their box.
    let mut right_cost = [0.0f32; SWEEP_MAX];
    let (mut lo, mut hi) = (F4::INFINITY, F4::NEG_INFINITY);
    for i in (1..n).rev() {
        lo = lo.min(refs[i].lo());
        hi = hi.max(refs[i].hi());
        right_cost[i - 1] = (n - i) as f32 * lo.half_area(hi);
    }
    let (mut lo, mut hi) = (F4::INFINITY, F4::NEG_INFINITY);
    let mut best = (1, f32::INFINITY);
    for (i, r) in refs[..n - 1].iter().enumerate() {
        lo = lo.min(r.lo());
        hi = hi.max(r.hi());
        let cost = (i + 1) as f32 * lo.half_area(hi) + right_cost[i];
        if cost < best.1 {
            best = (i + 1, cost);
        }
    }
    (Plan::At { mid: best.0 }, f64::from(best.1))
}

/// The cheapest binned SAH split over all axes and its cost `n_l A_l + n_r A_r` (half areas);
/// `None` if no axis has two non-empty sides. Small sets use fewer bins.
fn best_split(scratch: &mut Scratch, refs: &[PrimRef], info: &Info) -> Option<(Plan, f64)> {
    let n = refs.len() as u32;
    let count = bin_count(refs.len());
    let binning = Binning::new(info, count);
    // Large sets alternate between two sets of bins: consecutive primitives of a mesh often
    // fall into the same bins, and one set would chain every update through memory.
    let split = refs.len() >= 64;
    for axes in if split { &mut scratch.axes[..] } else { &mut scratch.axes[..1] } {
        for axis in axes {
            axis.lo[..count].fill(F4::INFINITY);
            axis.hi[..count].fill(F4::NEG_INFINITY);
            axis.count[..count].fill(0);
        }
    }
    let [first, rest @ ..] = &mut scratch.axes;
    if split {
        let [second, third, fourth] = rest;
        let mut quads = refs.chunks_exact(4);
        for quad in &mut quads {
            bin_one(first, &binning, &quad[0]);
            bin_one(second, &binning, &quad[1]);
            bin_one(third, &binning, &quad[2]);
            bin_one(fourth, &binning, &quad[3]);
        }
        for r in quads.remainder() {
            bin_one(first, &binning, r);
        }
        for other in [&*second, &*third, &*fourth] {
            for (a, b) in first.iter_mut().zip(other.iter()) {
                for i in 0..count {
                    a.lo[i] = a.lo[i].min(b.lo[i]);
                    a.hi[i] = a.hi[i].max(b.hi[i]);
                    a.count[i] += b.count[i];
                }
            }
        }
    } else {
        for r in refs {
            bin_one(first, &binning, r);
        }
    }
    // (axis, last bin on the left, cost n_l A_l + n_r A_r)
    let mut best = (0, 0, f32::INFINITY);
    let scale = binning.scale.to_array();
    let right_cost = &mut scratch.right_cost;
    for (axis, bins) in scratch.axes[0].iter().enumerate() {
        if scale[axis] == 0.0 {
            continue;
        }
        // Right to left, then left to right; only boxes of non-empty sides are measured, so
        // `half_area` never sees an empty box.
        let (mut lo, mut hi) = (F4::INFINITY, F4::NEG_INFINITY);
        let mut on_right = 0;
        for i in (1..count).rev() {
            lo = lo.min(bins.lo[i]);
            hi = hi.max(bins.hi[i]);
            on_right += bins.count[i];
            right_cost[i - 1] = on_right as f32 * lo.half_area(hi);
        }
        let (mut lo, mut hi) = (F4::INFINITY, F4::NEG_INFINITY);
        let mut on_left = 0;
        #[allow(clippy::needless_range_loop, reason = "three arrays and `right_cost` by bin")]
        for i in 0..count - 1 {
            lo = lo.min(bins.lo[i]);
            hi = hi.max(bins.hi[i]);
            on_left += bins.count[i];
            if on_left == 0 {
                continue;
            }
            if on_left == n {
                break;
            }
            let cost = on_left as f32 * lo.half_area(hi) + right_cost[i];
            if cost < best.2 {
                best = (axis, i, cost);
            }
        }
    }
    let (axis, bin, cost) = best;
    (cost < f32::INFINITY).then(|| (Plan::Sah { axis, bin: bin as u32, binning }, f64::from(cost)))
}

/// Adds `r` to its bin along each axis.
#[inline(always)]
fn bin_one(axes: &mut [AxisBins; 3], binning: &Binning, r: &PrimRef) {
    let b = binning.bins(r).map(|b| b as usize & (BINS - 1));
    let (lo, hi) = (r.lo(), r.hi());
    for (axis, &b) in axes.iter_mut().zip(&b) {
        axis.lo[b] = axis.lo[b].min(lo);
        axis.hi[b] = axis.hi[b].max(hi);
        axis.count[b] += 1;
    }
}

/// Bins per axis for a set of `n` primitives: many where the split decides much (near the
/// root) and the binning is a small part of the work, few for the many small sets.
fn bin_count(n: usize) -> usize {
    let bins = if n >= 4096 {
        BINS
    } else if n >= 256 {
        16
    } else {
        8
    };
    bins.min(n)
}

/// Splits `refs` as `plan` says; returns the size of the left side and both descriptions.
fn split(refs: &mut [PrimRef], plan: Plan) -> (usize, Info, Info) {
    match plan {
        Plan::Sah { axis, bin, binning } => partition(refs, |r| binning.bins(r)[axis] <= bin),
        Plan::Median { axis } => {
            let mid = refs.len() / 2;
            refs.select_nth_unstable_by(mid, |a, b| {
                a.centroid2().to_array()[axis].total_cmp(&b.centroid2().to_array()[axis])
            });
            (mid, Info::of(&refs[..mid]), Info::of(&refs[mid..]))
        }
        Plan::At { mid } => (mid, Info::of(&refs[..mid]), Info::of(&refs[mid..])),
        Plan::Leaf => unreachable!("leaves are never split"),
    }
}

/// Moves the primitives satisfying `left` to the front; returns how many there are and the
/// descriptions of both sides, gathered on the way (each primitive is tested and described
/// once, and only misplaced ones move: one swap per pair, as in Hoare's partition).
fn partition(refs: &mut [PrimRef], mut left: impl FnMut(&PrimRef) -> bool) -> (usize, Info, Info) {
    let (mut l, mut r) = (Info::empty(), Info::empty());
    let (mut i, mut j) = (0, refs.len());
    loop {
        while i < j && left(&refs[i]) {
            l.add(&refs[i]);
            i += 1;
        }
        while i < j && !left(&refs[j - 1]) {
            j -= 1;
            r.add(&refs[j]);
        }
        if i == j {
            return (i, l, r);
        }
        // refs[i] belongs right and refs[j - 1] left.
        j -= 1;
        refs.swap(i, j);
        l.add(&refs[i]);
        r.add(&refs[j]);
        i += 1;
    }
}

/// Builds the tree over `refs` (described by `info`) into `out`, whose first node is the
/// root. The root is always a node, even for a single leaf.
pub fn build<T: Real>(refs: &mut [PrimRef], info: Info) -> Vec<Node> {
    let mut out = Vec::with_capacity(refs.len() / 4 + 1);
    let mut scratch = Scratch::new();
    let root = Set::new(&mut scratch, refs, (0, refs.len()), info, 0);
    if matches!(root.plan, Plan::Leaf) {
        let mut node = Node::EMPTY;
        let (lo, hi) = root.info.bounds();
        let (lo, hi) = lane_box::<T>(lo, hi);
        node.set(0, lo, hi, leaf_ref(0, refs.len()));
        out.push(node);
    } else {
        node_into::<T>(&mut scratch, &mut out, refs, 0, root);
    }
    out
}

/// Builds the wide node for `set` (planned to be split; `refs` is the slice its range refers
/// to, starting at slot `base`) and its subtrees into `out`; returns the node's index in `out`.
fn node_into<T: Real>(
    scratch: &mut Scratch,
    out: &mut Vec<Node>,
    refs: &mut [PrimRef],
    base: usize,
    set: Set,
) -> u32 {
    // Open the largest splittable child until the node is full.
    let mut kids = [set; WIDTH];
    let mut len = 1;
    while len < WIDTH {
        let mut pick: Option<(usize, f64)> = None;
        for (i, kid) in kids[..len].iter().enumerate() {
            if !matches!(kid.plan, Plan::Leaf) && pick.is_none_or(|(_, a)| kid.area > a) {
                pick = Some((i, kid.area));
            }
        }
        let Some((i, _)) = pick else { break };
        let kid = kids[i];
        let (mid, left, right) = split(&mut refs[kid.start..kid.end], kid.plan);
        let mid = kid.start + mid;
        kids[i] = Set::new(scratch, refs, (kid.start, mid), left, kid.depth + 1);
        kids[len] = Set::new(scratch, refs, (mid, kid.end), right, kid.depth + 1);
        len += 1;
    }
    let kids = &mut kids[..len];

    let index = out.len();
    out.push(Node::EMPTY);
    for (lane, kid) in kids.iter().enumerate() {
        let (lo, hi) = kid.info.bounds();
        let (lo, hi) = lane_box::<T>(lo, hi);
        let r =
            if matches!(kid.plan, Plan::Leaf) { leaf_ref(base + kid.start, kid.len()) } else { 0 };
        out[index].set(lane, lo, hi, r);
    }

    let parallel = set.len() >= PARALLEL_MIN && rayon::current_num_threads() > 1;
    if !parallel {
        for (lane, kid) in kids.iter().enumerate() {
            if !matches!(kid.plan, Plan::Leaf) {
                let local = Set { start: 0, end: kid.len(), ..*kid };
                let slice = &mut refs[kid.start..kid.end];
                let child = node_into::<T>(scratch, out, slice, base + kid.start, local);
                out[index].refs[lane] = child;
            }
        }
        return index as u32;
    }

    // Parallel: cut `refs` into the children's disjoint slices, build each interior child
    // into its own array, then append them with their references shifted.
    let mut order: Vec<usize> = (0..kids.len()).collect();
    order.sort_unstable_by_key(|&lane| kids[lane].start);
    let mut jobs = Vec::with_capacity(kids.len());
    let mut rest = refs;
    let mut consumed = 0;
    for lane in order {
        let kid = kids[lane];
        let (_, tail) = rest.split_at_mut(kid.start - consumed);
        let (mine, tail) = tail.split_at_mut(kid.len());
        rest = tail;
        consumed = kid.end;
        if !matches!(kid.plan, Plan::Leaf) {
            jobs.push((lane, mine, Set { start: 0, end: kid.len(), ..kid }, base + kid.start));
        }
    }
    let mut built: Vec<(usize, Vec<Node>)> = jobs
        .into_par_iter()
        .map(|(lane, slice, local, slot)| {
            let mut nodes = Vec::with_capacity(slice.len() / 4 + 1);
            node_into::<T>(&mut Scratch::new(), &mut nodes, slice, slot, local);
            (lane, nodes)
        })
        .collect();
    // In lane order, as the sequential build appends them: the layout does not depend on the
    // number of threads.
    built.sort_unstable_by_key(|&(lane, _)| lane);
    for (lane, mut nodes) in built {
        let offset = out.len() as u32;
        for node in &mut nodes {
            for r in &mut node.refs {
                if !super::node::is_leaf(*r) {
                    *r += offset;
                }
            }
        }
        out.append(&mut nodes);
        out[index].refs[lane] = offset;
    }
    index as u32
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

    fn refs_along_x(n: u32) -> Vec<PrimRef> {
        (0..n)
            .map(|i| {
                let x = f64::from(i);
                PrimRef::new(&Aabb { min: [x, 0.0, 0.0], max: [x, 1.0, 2.0] }, i)
            })
            .collect()
    }

    #[test]
    fn partition_keeps_every_element_and_describes_both_sides() {
        let mut v = refs_along_x(100);
        let (mid, l, r) = partition(&mut v, |p| p.index() % 3 == 0);
        assert_eq!(mid, 34);
        assert!(v[..mid].iter().all(|p| p.index() % 3 == 0));
        assert!(v[mid..].iter().all(|p| p.index() % 3 != 0));
        assert_eq!((l.bounds().0[0], l.bounds().1[0]), (0.0, 99.0));
        assert_eq!((r.bounds().0[0], r.bounds().1[0]), (1.0, 98.0));
        // Doubled centroids: z from 0 + 2.
        assert_eq!(
            (l.clo.to_array()[2], l.chi.to_array()[2], r.clo.to_array()[0]),
            (2.0, 2.0, 2.0)
        );
        let mut idx: Vec<u32> = v.iter().map(PrimRef::index).collect();
        idx.sort_unstable();
        assert_eq!(idx, (0..100).collect::<Vec<_>>());
    }

    #[test]
    fn f64_boxes_are_rounded_outwards() {
        let b = Aabb { min: [0.1f64, -0.1, 1e-50], max: [0.3, 1e300, 2.0] };
        let r = PrimRef::new(&b, 7);
        for k in 0..3 {
            assert!(f64::from(r.lo[k]) <= b.min[k] && f64::from(r.hi[k]) >= b.max[k]);
        }
        assert_eq!(r.index(), 7);
    }

    #[test]
    fn sah_splits_two_clusters_apart() {
        let mut v: Vec<PrimRef> = (0..64)
            .map(|i| {
                let x = if i % 2 == 0 { 0.0 } else { 100.0 } + f64::from(i) * 0.01;
                PrimRef::new(&Aabb { min: [x, 0.0, 0.0], max: [x + 0.1, 0.1, 0.1] }, i)
            })
            .collect();
        let info = Info::of(&v);
        let plan = plan(&mut Scratch::new(), &mut v, &info, info.half_area(), 0);
        assert!(matches!(plan, Plan::Sah { axis: 0, .. }), "{plan:?}");
        let (mid, l, r) = split(&mut v, plan);
        assert_eq!(mid, 32);
        assert!(l.bounds().1[0] < 1.0 && r.bounds().0[0] > 99.0);
    }

    /// The sweep's split is the cheapest of all boundaries of the centroid order, computed
    /// independently in `f64`.
    #[test]
    fn sweep_finds_the_cheapest_boundary() {
        use rand::{Rng, SeedableRng};
        let mut rng = rand_pcg::Pcg64::seed_from_u64(9);
        for n in 2..=SWEEP_MAX {
            for axis in 0..3 {
                let mut v: Vec<PrimRef> = (0..n as u32)
                    .map(|i| {
                        let c: [f64; 3] = core::array::from_fn(|_| rng.random_range(-1.0..1.0));
                        let h: [f64; 3] = core::array::from_fn(|_| rng.random_range(0.0..0.3));
                        let b = Aabb {
                            min: core::array::from_fn(|k| c[k] - h[k]),
                            max: core::array::from_fn(|k| c[k] + h[k]),
                        };
                        PrimRef::new(&b, i)
                    })
                    .collect();
                let (Plan::At { mid }, cost) = sweep(&mut v, axis) else { panic!() };
                let c = |r: &PrimRef| f64::from(r.lo[axis]) + f64::from(r.hi[axis]);
                assert!(v.windows(2).all(|w| c(&w[0]) <= c(&w[1])), "sorted by centroid");
                let side = |rs: &[PrimRef]| {
                    let lo: [f64; 3] = core::array::from_fn(|k| {
                        rs.iter().map(|r| f64::from(r.lo[k])).fold(f64::INFINITY, f64::min)
                    });
                    let hi: [f64; 3] = core::array::from_fn(|k| {
                        rs.iter().map(|r| f64::from(r.hi[k])).fold(f64::NEG_INFINITY, f64::max)
                    });
                    let [x, y, z]: [f64; 3] = core::array::from_fn(|k| hi[k] - lo[k]);
                    rs.len() as f64 * (x * y + y * z + z * x)
                };
                let costs: Vec<f64> = (1..n).map(|k| side(&v[..k]) + side(&v[k..])).collect();
                let best = costs.iter().copied().fold(f64::INFINITY, f64::min);
                assert!((cost - best).abs() <= 1e-5 * best, "n {n}: {cost} vs {best}");
                assert!((costs[mid - 1] - best).abs() <= 1e-5 * best, "n {n}: boundary {mid}");
            }
        }
    }

    #[test]
    fn lane_boxes_grow_outwards_and_empty_stays_empty() {
        let (lo, hi) = lane_box::<f32>([1.0, -3.0, 0.0], [2.0, 1e6, 0.0]);
        assert!(lo[0] < 1.0 && lo[1] < -3.0 && lo[2] < 0.0);
        assert!(hi[0] > 2.0 && hi[1] > 1e6 && hi[2] > 0.0);
        let (lo, hi) = lane_box::<f64>([1.0; 3], [1.0; 3]);
        assert!(lo.iter().all(|&x| x < 1.0) && hi.iter().all(|&x| x > 1.0));
        let (lo, hi) = lane_box::<f64>([f32::INFINITY; 3], [f32::NEG_INFINITY; 3]);
        assert!(lo[0] > hi[0]);
    }
}
