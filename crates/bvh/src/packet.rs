//! Packet traversal: up to [`PACKET`] coherent rays walk the tree together, one interval box
//! test per node for the whole packet, and each ray tests only the leaves' boxes on its own.
//!
//! # The packet's bounds
//!
//! The rays of a packet share the sign of their inverse direction on every axis (a chunk of
//! rays is split by octant first), so they enter and leave every box through the same planes.
//! Per axis the packet keeps the interval of its origins and the interval of its inverse
//! directions; the entry distance `(plane - o) * inv` of any of its rays is then at least the
//! smaller of two corner products, and the exit distance at most the larger of two (the
//! interval product of `[plane - o_max, plane - o_min]` and `[inv_min, inv_max]`, whose extreme
//! corners the sign of `plane - o` picks). Rounding is monotone, so the corner products
//! computed in floating point bound every ray's own rounded slab distances the same way: the
//! packet's test passes for a box whenever one of its rays' own test (the one the single-ray
//! traversal runs, with the same Ize factor) passes, with the packet's limit the largest of
//! its live rays' limits. A corner `0 * inf` (rays starting in a face plane with a zero
//! direction component) gives NaN, and a NaN bound constrains nothing, as in the ray test.
//!
//! # Why the hits are those of single rays
//!
//! The packet visits, for each of its rays, every node that ray's own traversal would accept at
//! any limit at least its final answer's distance, and at a leaf every ray runs the single-ray
//! box test on the leaf's box (the same arithmetic) before its kernel sees the leaf's
//! triangles. So every ray is offered the triangle of its nearest hit, and keeps, of the real
//! kernel hits it is offered, the least under [`intersect::Hit::nearer_than`]: the answer of
//! its single-ray query, ties included, whatever order the packet visits leaves in. Only the
//! amount of work depends on coherence: rays far apart give wide intervals, which meet many
//! boxes, so incoherent rays should keep the single-ray path.

use core::ops::Range;

use intersect::{Ray, Real};

use super::aabb::{max_or, min_or};
use super::node::{LEAF, Node, WIDTH, is_leaf, leaf_slots};
use super::traverse::{self, Lane};

/// Rays traced together: an 8 x 8 block of pixels.
pub const PACKET: usize = 64;

/// Octant groups of fewer rays than this are traced ray by ray: their interval test would
/// cost more than it saves.
pub const MIN_PACKET: usize = 4;

/// The rays of one packet (one octant of one chunk) in the lane precision `S`, structure of
/// arrays; lanes past `len` are dead (copies of the first ray, never live).
struct Group<S> {
    len: usize,
    /// The ray's position in the caller's slice.
    index: [usize; PACKET],
    origin: [[S; PACKET]; 3],
    inv: [[S; PACKET]; 3],
    limit: [S; PACKET],
    /// Bit `r`: ray `r` is still searching (any-hit queries retire rays that hit).
    live: u64,
    /// The plane row every ray enters through along each axis, and the one it leaves through.
    near: [usize; 3],
    far: [usize; 3],
    /// The origin bound that gives the least entry distance, per axis, and the greatest exit.
    o_near: [S; 3],
    o_far: [S; 3],
    /// The inverse direction of least and of greatest magnitude, per axis.
    i_small: [S; 3],
    i_big: [S; 3],
}

impl<S: Lane + From<f32>> Group<S> {
    /// The packet of the rays `start + members` (positions in `rays`, all finite, all in
    /// `octant`), with their limits. Lanes past the members repeat the first ray, so that
    /// every loop over the lanes runs on whole vectors and the extremes need no count.
    fn new<T: Real>(
        rays: &[Ray<T>],
        start: usize,
        members: &[u8],
        octant: usize,
        limits: &[T],
    ) -> Self {
        let len = members.len();
        let mut g = Group {
            len,
            index: [0; PACKET],
            origin: [[S::ZERO; PACKET]; 3],
            inv: [[S::ZERO; PACKET]; 3],
            limit: [S::ZERO; PACKET],
            live: u64::MAX >> (PACKET - len),
            near: [0; 3],
            far: [0; 3],
            o_near: [S::ZERO; 3],
            o_far: [S::ZERO; 3],
            i_small: [S::ZERO; 3],
            i_big: [S::ZERO; 3],
        };
        for r in 0..PACKET {
            let i = start + usize::from(members[if r < len { r } else { 0 }]);
            let ray = &rays[i];
            g.index[r] = i;
            for k in 0..3 {
                g.origin[k][r] = to_lane(ray.origin[k]);
                g.inv[k][r] = to_lane(ray.dir[k]);
            }
            // Lanes past the members are never live (see `max_limit`).
            g.limit[r] = if r < len { to_lane(limits[i]) } else { S::from(f32::NEG_INFINITY) };
        }
        // As `traverse::Prepared` computes it, `1 / d` in the ray's precision: the lanes have
        // that precision, so this is the same division, a vector at a time.
        let one = S::from(1.0);
        g.inv.iter_mut().flatten().for_each(|x| *x = one / *x);
        for k in 0..3 {
            let negative = octant >> k & 1 == 1;
            (g.near[k], g.far[k]) = if negative { (k + 3, k) } else { (k, k + 3) };
            let (o_min, o_max) = extremes(&g.origin[k]);
            let (i_min, i_max) = extremes(&g.inv[k]);
            // Positive: enter through the lower plane, least entry from the largest origin.
            (g.o_near[k], g.o_far[k]) = if negative { (o_min, o_max) } else { (o_max, o_min) };
            (g.i_small[k], g.i_big[k]) = if negative { (i_max, i_min) } else { (i_min, i_max) };
        }
        g
    }

    /// The lanes of the mask `rays`, their rays' positions in the caller's slice, and how
    /// many: what a leaf gets, so that the kernel may test several rays at once.
    #[inline(always)]
    fn members(&self, rays: u64) -> ([usize; PACKET], [usize; PACKET], usize) {
        let (mut lanes, mut members) = ([0; PACKET], [0; PACKET]);
        let (mut n, mut left) = (0, rays);
        while left != 0 {
            lanes[n] = left.trailing_zeros() as usize;
            members[n] = self.index[lanes[n]];
            left &= left - 1;
            n += 1;
        }
        (lanes, members, n)
    }

    /// The largest limit of the live rays (NaN limits ignored: such a ray meets nothing).
    /// Rays that are not live hold `-inf` (see [`Group::retire`]), so this is the largest of
    /// all lanes, with no chain through the live mask.
    #[inline(always)]
    fn max_limit(&self) -> S {
        fold8(&self.limit, S::from(f32::NEG_INFINITY), max_or)
    }

    /// Ray `r` is done: no longer live, and its limit no longer counts in the packet's.
    #[inline(always)]
    fn retire(&mut self, r: usize) {
        self.live &= !(1 << r);
        self.limit[r] = S::from(f32::NEG_INFINITY);
    }

    /// The packet's interval test of the eight boxes of `node` within `(0, limit]`: bit `i`
    /// if some ray of the packet may meet box `i`, and in `t` a lower bound of their entry
    /// distances.
    #[inline(always)]
    fn hits(&self, node: &Node, limit: S, t: &mut [S; WIDTH]) -> u32 {
        let mut mask = 0;
        for (lane, t) in t.iter_mut().enumerate() {
            let mut near = S::ZERO;
            let mut far = limit;
            for k in 0..3 {
                let a = S::from(node.planes[self.near[k]][lane]) - self.o_near[k];
                let b = S::from(node.planes[self.far[k]][lane]) - self.o_far[k];
                // `min_or(x, y)` is NaN only if `x` is: `0 * i_small` is NaN only when every
                // ray of the packet has an infinite inverse here, and then so is `0 * i_big`.
                let entry = min_or(a * self.i_small[k], a * self.i_big[k]);
                // `max_or(x, y)` keeps a NaN `x`: `0 * i_big` at the exit plane means some ray
                // may lie in that plane, where its slab constrains nothing.
                let exit = max_or(b * self.i_big[k], b * self.i_small[k]);
                near = max_or(near, entry);
                far = min_or(far, exit);
            }
            *t = near;
            mask |= u32::from(near <= far * S::SLACK) << lane;
        }
        mask
    }

    /// The live rays whose own box test (the single-ray traversal's arithmetic) passes for
    /// lane `lane` of `node` within their limits.
    #[inline(always)]
    fn leaf_hits(&self, node: &Node, lane: usize) -> u64 {
        let lo: [S; 3] = core::array::from_fn(|k| S::from(node.planes[self.near[k]][lane]));
        let hi: [S; 3] = core::array::from_fn(|k| S::from(node.planes[self.far[k]][lane]));
        let mut mask = 0u64;
        // Whole vectors of eight rays (lanes past `len` are dead, masked below).
        for r in 0..self.len.next_multiple_of(8).min(PACKET) {
            let mut near = S::ZERO;
            let mut far = self.limit[r];
            for k in 0..3 {
                near = max_or(near, (lo[k] - self.origin[k][r]) * self.inv[k][r]);
                far = min_or(far, (hi[k] - self.origin[k][r]) * self.inv[k][r]);
            }
            mask |= u64::from(near <= far * S::SLACK) << r;
        }
        mask & self.live
    }

    /// The slots of the leaf a stack entry names (see [`target`]) and the live rays whose
    /// own box test passes for it.
    #[inline(always)]
    fn leaf_at(&self, nodes: &[Node], code: u32) -> (Range<usize>, u64) {
        let (parent, lane) = (((code & !LEAF) >> 3) as usize, (code & 7) as usize);
        let node = &nodes[parent];
        (leaf_slots(node.refs[lane]), self.leaf_hits(node, lane))
    }
}

/// The least and greatest of `xs` (no NaN: then the order of the comparisons changes
/// nothing).
#[inline(always)]
fn extremes<S: Lane>(xs: &[S; PACKET]) -> (S, S) {
    (fold8(xs, xs[0], min_or), fold8(xs, xs[0], max_or))
}

/// `f` (`min_or` or `max_or`) over `xs` from `init` as eight running results, one vector of
/// `f32`, then over those: whole vectors, no chain through every lane.
#[inline(always)]
fn fold8<S: Lane>(xs: &[S; PACKET], init: S, f: impl Fn(S, S) -> S + Copy) -> S {
    let mut acc = [init; 8];
    for chunk in xs.chunks_exact(8) {
        for j in 0..8 {
            acc[j] = f(acc[j], chunk[j]);
        }
    }
    acc.into_iter().fold(init, f)
}

/// Converts the tree's precision to the lane type (exact: they are the same precision).
#[inline(always)]
fn to_lane<S: Lane, T: Real>(x: T) -> S {
    S::from_f64(x.to_f64())
}

/// A stack entry's target: a node's index, or (with [`LEAF`] set) a leaf as its parent node
/// and lane, so that the rays can test its box.
#[inline(always)]
fn target(node: usize, lane: usize, r: u32) -> u32 {
    if is_leaf(r) { LEAF | (node as u32) << 3 | lane as u32 } else { r }
}

/// The octant of `ray` (bit `k` set if its inverse direction along `k` is negative, `-0.0`
/// included), or `None` if it has a non-finite coordinate and meets nothing.
fn octant<T: Real>(ray: &Ray<T>) -> Option<usize> {
    if !ray.origin.iter().chain(&ray.dir).all(|x| x.is_finite()) {
        return None;
    }
    // `1 / d < 0` exactly when `d` has its sign bit set (`-0.0` gives `-inf`): no division.
    Some((0..3).map(|k| usize::from(ray.dir[k].to_f64().is_sign_negative()) << k).sum())
}

/// What [`groups`] hands out: a packet (the first position of its chunk in the caller's rays,
/// its rays' positions within the chunk, their octant), or one ray to trace alone.
enum Work<'a> {
    Packet(usize, &'a [u8], usize),
    Single(usize),
}

/// Splits `rays` into chunks of [`PACKET`] and each chunk by octant; hands each group of at
/// least [`MIN_PACKET`] rays to `work` as a packet and each ray of the smaller groups alone.
/// Rays with a non-finite coordinate go nowhere: they meet nothing.
fn groups<T: Real>(rays: &[Ray<T>], mut work: impl FnMut(Work<'_>)) {
    for start in (0..rays.len()).step_by(PACKET) {
        let end = (start + PACKET).min(rays.len());
        // Positions within the chunk: a small array to clear per chunk.
        let mut members = [[0u8; PACKET]; 8];
        let mut counts = [0usize; 8];
        for (i, ray) in rays[start..end].iter().enumerate() {
            if let Some(o) = octant(ray) {
                members[o][counts[o]] = i as u8;
                counts[o] += 1;
            }
        }
        for o in 0..8 {
            let m = &members[o][..counts[o]];
            if m.len() >= MIN_PACKET {
                work(Work::Packet(start, m, o));
            } else {
                m.iter().for_each(|&i| work(Work::Single(start + usize::from(i))));
            }
        }
    }
}

/// Orders the lanes of `mask` by `t` (nearest first) into `out`; returns how many.
#[inline(always)]
fn sorted<S: Lane>(mask: u32, t: &[S; WIDTH], out: &mut [usize; WIDTH]) -> usize {
    let mut keys = [0u64; WIDTH];
    let mut n = 0;
    let mut m = mask;
    while m != 0 {
        let i = m.trailing_zeros() as usize;
        let key = t[i].key() | i as u64;
        let mut j = n;
        while j > 0 && keys[j - 1] > key {
            keys[j] = keys[j - 1];
            j -= 1;
        }
        keys[j] = key;
        n += 1;
        m &= m - 1;
    }
    for (o, key) in out.iter_mut().zip(&keys[..n]) {
        *o = (key & 7) as usize;
    }
    n
}

/// See [`super::Bvh::closest_packet`].
pub fn closest<S, T, F, H>(nodes: &[Node], rays: &[Ray<T>], limits: &mut [T], mut leaf: F, hint: H)
where
    S: Lane + From<f32>,
    T: Real,
    F: FnMut(Range<usize>, &[usize], &mut [T]),
    H: Fn(Range<usize>),
{
    assert_eq!(rays.len(), limits.len(), "one limit per ray");
    if nodes.is_empty() {
        return;
    }
    let mut stack: Vec<(u32, S)> = Vec::with_capacity(64);
    groups(rays, |work| match work {
        Work::Packet(start, members, octant) => {
            let mut g = Group::<S>::new(rays, start, members, octant, limits);
            closest_group(nodes, &mut g, &mut stack, limits, &mut leaf, &hint);
        }
        Work::Single(i) => {
            traverse::closest::<S, T, _>(
                traverse::Baseline,
                nodes,
                &rays[i],
                limits[i],
                |slots: Range<usize>, l: &mut T| {
                    leaf(slots, &[i], limits);
                    *l = limits[i];
                },
            );
        }
    });
}

#[inline(always)]
fn closest_group<S, T, F, H>(
    nodes: &[Node],
    g: &mut Group<S>,
    stack: &mut Vec<(u32, S)>,
    limits: &mut [T],
    leaf: &mut F,
    hint: &H,
) where
    S: Lane + From<f32>,
    T: Real,
    F: FnMut(Range<usize>, &[usize], &mut [T]),
    H: Fn(Range<usize>),
{
    stack.clear();
    let mut limit = g.max_limit();
    let mut t = [S::ZERO; WIDTH];
    let mut order = [0usize; WIDTH];
    let mut current = 0u32;
    loop {
        if is_leaf(current) {
            let (slots, rays) = g.leaf_at(nodes, current);
            if rays != 0 {
                // The rays that reach the leaf, handed over together (their positions in the
                // caller's slice), so that the kernel may test several at once.
                let (lanes, members, n) = g.members(rays);
                leaf(slots, &members[..n], limits);
                let mut lowered = false;
                for (&r, &i) in lanes[..n].iter().zip(&members[..n]) {
                    let now: S = to_lane(limits[i]);
                    if now != g.limit[r] {
                        g.limit[r] = now;
                        lowered = true;
                    }
                }
                if lowered {
                    limit = g.max_limit();
                }
            }
        } else {
            let node = &nodes[current as usize];
            let mask = g.hits(node, limit, &mut t);
            if mask != 0 {
                let n = sorted(mask, &t, &mut order);
                for &i in &order[..n] {
                    if is_leaf(node.refs[i]) {
                        hint(leaf_slots(node.refs[i]));
                    }
                }
                for &i in order[1..n].iter().rev() {
                    stack.push((target(current as usize, i, node.refs[i]), t[i]));
                }
                current = target(current as usize, order[0], node.refs[order[0]]);
                continue;
            }
        }
        // Pop until an entry that still starts within the packet's (possibly lowered) limit.
        let bound = limit * S::SLACK;
        loop {
            let Some((r, entry)) = stack.pop() else { return };
            if entry <= bound {
                current = r;
                break;
            }
        }
    }
}

/// See [`super::Bvh::any_packet`].
pub fn any<S, T, F, H>(
    nodes: &[Node],
    rays: &[Ray<T>],
    limits: &[T],
    hit: &mut [bool],
    mut leaf: F,
    hint: H,
) where
    S: Lane + From<f32>,
    T: Real,
    F: FnMut(Range<usize>, &[usize]) -> u64,
    H: Fn(Range<usize>),
{
    assert_eq!(rays.len(), limits.len(), "one limit per ray");
    assert_eq!(rays.len(), hit.len(), "one answer per ray");
    hit.fill(false);
    if nodes.is_empty() {
        return;
    }
    let mut stack: Vec<u32> = Vec::with_capacity(64);
    groups(rays, |work| match work {
        Work::Packet(start, members, octant) => {
            let mut g = Group::<S>::new(rays, start, members, octant, limits);
            any_group(nodes, &mut g, &mut stack, hit, &mut leaf, &hint);
        }
        Work::Single(i) => {
            hit[i] = traverse::any::<S, T, _>(
                traverse::Baseline,
                nodes,
                &rays[i],
                limits[i],
                |slots: Range<usize>| leaf(slots, &[i]) != 0,
            );
        }
    });
}

#[inline(always)]
fn any_group<S, F, H>(
    nodes: &[Node],
    g: &mut Group<S>,
    stack: &mut Vec<u32>,
    hit: &mut [bool],
    leaf: &mut F,
    hint: &H,
) where
    S: Lane + From<f32>,
    F: FnMut(Range<usize>, &[usize]) -> u64,
    H: Fn(Range<usize>),
{
    stack.clear();
    let mut limit = g.max_limit();
    let mut t = [S::ZERO; WIDTH];
    let mut current = 0u32;
    loop {
        if is_leaf(current) {
            let (slots, rays) = g.leaf_at(nodes, current);
            if rays != 0 {
                // The rays that reach the leaf, handed over together, as for closest hits.
                let (lanes, members, n) = g.members(rays);
                let mut found = leaf(slots, &members[..n]);
                if found != 0 {
                    while found != 0 {
                        let j = found.trailing_zeros() as usize;
                        found &= found - 1;
                        hit[members[j]] = true;
                        g.retire(lanes[j]);
                    }
                    if g.live == 0 {
                        return;
                    }
                    limit = g.max_limit();
                }
            }
        } else {
            let node = &nodes[current as usize];
            let mut mask = g.hits(node, limit, &mut t);
            let mut leaves = mask;
            while leaves != 0 {
                let i = leaves.trailing_zeros() as usize;
                leaves &= leaves - 1;
                if is_leaf(node.refs[i]) {
                    hint(leaf_slots(node.refs[i]));
                }
            }
            if mask != 0 {
                let here = current as usize;
                let first = mask.trailing_zeros() as usize;
                current = target(here, first, node.refs[first]);
                mask &= mask - 1;
                while mask != 0 {
                    let i = mask.trailing_zeros() as usize;
                    stack.push(target(here, i, node.refs[i]));
                    mask &= mask - 1;
                }
                continue;
            }
        }
        match stack.pop() {
            Some(r) => current = r,
            None => return,
        }
    }
}
