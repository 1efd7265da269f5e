//! The wide node: the boxes of up to [`WIDTH`] children as `f32` planes in
//! structure-of-arrays order (one 32-byte row per plane, one lane per child), and one 32-bit
//! reference per child.
//!
//! A reference is either an interior node's index or, with the top bit set, a leaf: its first
//! slot and its size, `LEAF | first << 3 | (count - 1)`. Leaves are not nodes of their own: a
//! ray tests a leaf's box in its parent, with its siblings, and then runs the kernel on its
//! slots. Unused lanes hold the empty box (`+inf` lower planes, `-inf` upper planes), which no
//! ray with a finite origin meets, so the box test needs no validity mask.

use core::ops::Range;

/// Children per node: one AVX register of `f32` per plane.
pub const WIDTH: usize = 8;

/// Bit marking a reference as a leaf.
pub(crate) const LEAF: u32 = 1 << 31;
/// Bits holding `count - 1` in a leaf reference.
const COUNT_BITS: u32 = 3;
/// Slots a leaf reference can address: the first slot gets the 28 bits left.
pub const MAX_SLOTS: usize = 1 << (31 - COUNT_BITS);

/// The reference of the leaf holding `count` (1 to 8) primitives from slot `first`.
#[inline]
pub fn leaf_ref(first: usize, count: usize) -> u32 {
    debug_assert!((1..=1 << COUNT_BITS).contains(&count) && first + count <= MAX_SLOTS);
    LEAF | (first as u32) << COUNT_BITS | (count as u32 - 1)
}

/// Whether a reference is a leaf.
#[inline(always)]
pub fn is_leaf(r: u32) -> bool {
    r & LEAF != 0
}

/// The slots of a leaf reference.
#[inline(always)]
pub fn leaf_slots(r: u32) -> Range<usize> {
    let first = ((r & !LEAF) >> COUNT_BITS) as usize;
    first..first + (r & ((1 << COUNT_BITS) - 1)) as usize + 1
}

/// One node: `planes[p][lane]` with `p` = 0, 1, 2 the lower x, y, z faces and 3, 4, 5 the upper
/// ones; `refs[lane]` the child (224 bytes, 32-byte aligned for aligned vector loads).
#[derive(Clone, Copy, Debug)]
#[repr(C, align(32))]
pub struct Node {
    /// The children's boxes, plane by plane.
    pub planes: [[f32; WIDTH]; 6],
    /// The children.
    pub refs: [u32; WIDTH],
}

impl Node {
    /// A node with every lane empty. The empty lanes' references name a one-primitive leaf at
    /// slot 0, which is harmless should a ray with a non-finite origin reach one.
    pub const EMPTY: Node = Node {
        planes: [
            [f32::INFINITY; WIDTH],
            [f32::INFINITY; WIDTH],
            [f32::INFINITY; WIDTH],
            [f32::NEG_INFINITY; WIDTH],
            [f32::NEG_INFINITY; WIDTH],
            [f32::NEG_INFINITY; WIDTH],
        ],
        refs: [LEAF; WIDTH],
    };

    /// Sets lane `lane` to the box `[lo, hi]` and reference `r`.
    #[inline]
    pub fn set(&mut self, lane: usize, lo: [f32; 3], hi: [f32; 3], r: u32) {
        for k in 0..3 {
            self.planes[k][lane] = lo[k];
            self.planes[k + 3][lane] = hi[k];
        }
        self.refs[lane] = r;
    }

    /// Whether lane `lane` holds a child (its box is not the empty box).
    #[inline]
    pub fn is_used(&self, lane: usize) -> bool {
        self.planes[0][lane] <= self.planes[3][lane]
    }

    /// The box of lane `lane`: `(lower corner, upper corner)`.
    #[inline]
    pub fn lane_box(&self, lane: usize) -> ([f32; 3], [f32; 3]) {
        (
            core::array::from_fn(|k| self.planes[k][lane]),
            core::array::from_fn(|k| self.planes[k + 3][lane]),
        )
    }
}

/// The largest `f32` at most `x` (NaN stays NaN).
#[inline]
pub fn f32_down(x: f64) -> f32 {
    let y = x as f32;
    if f64::from(y) > x { y.next_down() } else { y }
}

/// The smallest `f32` at least `x` (NaN stays NaN).
#[inline]
pub fn f32_up(x: f64) -> f32 {
    let y = x as f32;
    if f64::from(y) < x { y.next_up() } else { y }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn leaf_references_round_trip() {
        for (first, count) in [(0, 1), (5, 8), (MAX_SLOTS - 3, 3), (1 << 20, 4)] {
            let r = leaf_ref(first, count);
            assert!(is_leaf(r));
            assert_eq!(leaf_slots(r), first..first + count);
        }
        assert!(!is_leaf(12345));
        assert_eq!(size_of::<Node>(), 224);
    }

    #[test]
    fn outward_rounding_to_f32() {
        let x = 0.1f64;
        assert!(f64::from(f32_down(x)) <= x && f64::from(f32_up(x)) >= x);
        assert!(f64::from(f32_down(x)) < x && f64::from(f32_up(x)) > x);
        assert_eq!(f32_down(0.5), 0.5);
        assert_eq!(f32_up(0.5), 0.5);
        // Beyond f32's range: an infinite bound on the outer side, the largest finite inside.
        assert_eq!(f32_up(1e300), f32::INFINITY);
        assert_eq!(f32_down(1e300), f32::MAX);
        assert_eq!(f32_down(-1e300), f32::NEG_INFINITY);
        assert!(f32_down(f64::NAN).is_nan());
        // Across zero and subnormals.
        assert_eq!(f32_down(-1e-60), -f32::from_bits(1));
        assert_eq!(f32_up(1e-60), f32::from_bits(1));
        assert_eq!(f32_up(-1e-60), -0.0);
        for x in [1.0f64 / 3.0, -2.0 / 3.0, 1e30, -1e-40] {
            let (d, u) = (f32_down(x), f32_up(x));
            assert!(f64::from(d) < x && x < f64::from(u));
            assert_eq!(u.to_bits().abs_diff(d.to_bits()), 1, "{x}");
        }
    }
}
