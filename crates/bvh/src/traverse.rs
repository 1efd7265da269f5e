//! Traversal: a ray prepared once (origin, inverse direction, which face of each slab it
//! enters first), eight child boxes tested at a time, nearest child first, a fixed stack.
//!
//! The box test runs in the ray's precision: `f32` rays test the `f32` planes as they are,
//! `f64` rays convert them to `f64` (exactly) and test in `f64`. With AVX2 (the workspace's
//! x86-64 baseline, `-C target-cpu=x86-64-v3`, enables it) eight boxes take twelve vector
//! subtractions and multiplications, six minima and maxima and one compare; without, the same
//! arithmetic runs lane by lane.
//!
//! With AVX-512 (chosen at run time, see [`Isa`](crate::simd::Isa)) the whole loop is compiled
//! a second time inside a function that enables it ([`closest_avx512`], [`any_avx512`]), so
//! that the node test ([`Avx512`]) and everything else the loop inlines use the wider
//! instruction set: the compares go straight into a mask register. The operations and their
//! order are those of the AVX2 test, so the entry distances and masks are the same bits.
//! (`f64` boxes can also be tested in one 8-lane register, `avx512::hits_f64_zmm`, and are
//! not: see `results/README.md`.)

use core::mem::MaybeUninit;
use core::ops::{Div, Mul, Range, Sub};

use intersect::{Ray, Real};

use super::MAX_DEPTH;
use super::aabb::{max_or, min_or};
use super::node::{Node, WIDTH, is_leaf, leaf_slots};

/// Entries of the traversal stack: at most `WIDTH - 1` siblings wait per level of the path.
const STACK: usize = (WIDTH - 1) * MAX_DEPTH + 1;

/// `1 + 2 gamma(3)` with `gamma(n) = n u / (1 - n u)` and `u = eps / 2`: the factor by which a
/// slab distance `(plane - origin) * inv_dir` may be too small (Ize 2013).
const fn ize_factor(eps: f64) -> f64 {
    let u = eps * 0.5;
    let gamma3 = 3.0 * u / (1.0 - 3.0 * u);
    1.0 + 2.0 * gamma3
}

/// The distance type of a traversal: `f32` or `f64`, the ray's precision.
pub trait Lane:
    Copy + PartialOrd + Sub<Output = Self> + Mul<Output = Self> + Div<Output = Self>
{
    /// 0.
    const ZERO: Self;
    /// [`ize_factor`] rounded up to this precision (rounding may lose half an ulp; one more
    /// ulp keeps it an upper bound).
    const SLACK: Self;
    /// From an `f64` that holds a value of the tree's precision (exact).
    fn from_f64(x: f64) -> Self;
    /// A sort key, increasing with the value for values `>= 0`, with 3 low bits free.
    fn key(self) -> u64;
    /// The lanes of `node` whose box `ray` meets within `(0, limit]` (bit `i` for lane `i`),
    /// conservatively, and their entry distances in `t`. `bound` is the limit times
    /// [`Lane::SLACK`], the widening Ize's bound asks of the far distance: the exit distances
    /// are widened in the ray's set-up (`inv_far`), so none of it is left on the node's
    /// dependency chain. `(plane - origin) * (inv_dir * SLACK)` and `((plane - origin) *
    /// inv_dir) * SLACK` round four times each, so the bound holds as it did.
    fn hits(node: &Node, ray: &Prepared<Self>, bound: Self, t: &mut [Self; WIDTH]) -> u32;
    /// [`Lane::hits`] with AVX-512, the same bits.
    ///
    /// # Safety
    ///
    /// The CPU must have AVX-512F and AVX-512VL.
    #[cfg(target_arch = "x86_64")]
    unsafe fn hits_avx512(
        node: &Node,
        ray: &Prepared<Self>,
        bound: Self,
        t: &mut [Self; WIDTH],
    ) -> u32;
}

/// A node test: the instruction set the traversal loop is compiled for.
pub trait NodeTest: Copy {
    /// [`Lane::hits`] in this instruction set.
    fn hits<S: Lane>(self, node: &Node, ray: &Prepared<S>, bound: S, t: &mut [S; WIDTH]) -> u32;
}

/// The build's own node test ([`Lane::hits`]).
#[derive(Clone, Copy, Debug)]
pub struct Baseline;

impl NodeTest for Baseline {
    #[inline(always)]
    fn hits<S: Lane>(self, node: &Node, ray: &Prepared<S>, bound: S, t: &mut [S; WIDTH]) -> u32 {
        S::hits(node, ray, bound, t)
    }
}

/// The AVX-512 node test; a value exists only on a CPU that has AVX-512F and VL.
#[cfg(target_arch = "x86_64")]
#[derive(Clone, Copy, Debug)]
pub struct Avx512(());

#[cfg(target_arch = "x86_64")]
impl Avx512 {
    /// The test, which the caller knows the CPU runs.
    ///
    /// # Safety
    ///
    /// The CPU must have AVX-512F and AVX-512VL.
    #[inline(always)]
    pub unsafe fn assume() -> Self {
        Self(())
    }
}

#[cfg(target_arch = "x86_64")]
impl NodeTest for Avx512 {
    #[inline(always)]
    fn hits<S: Lane>(self, node: &Node, ray: &Prepared<S>, bound: S, t: &mut [S; WIDTH]) -> u32 {
        // SAFETY: an `Avx512` is made only by `Avx512::assume`, on a CPU with AVX-512F and VL.
        unsafe { S::hits_avx512(node, ray, bound, t) }
    }
}

/// A ray prepared for box tests in precision `S`.
#[derive(Clone, Copy, Debug)]
pub struct Prepared<S> {
    origin: [S; 3],
    inv_dir: [S; 3],
    /// `inv_dir` times [`Lane::SLACK`]: the far distances come out already widened (see
    /// [`Lane::hits`]).
    inv_far: [S; 3],
    /// The plane row (see [`Node::planes`]) the ray enters through along each axis.
    near: [usize; 3],
    /// The plane row it leaves through.
    far: [usize; 3],
}

impl<S: Lane> Prepared<S> {
    /// `None` for a ray with a non-finite coordinate: it meets nothing.
    #[inline(always)]
    pub fn new<T: Real>(ray: &Ray<T>) -> Option<Self> {
        if !ray.origin.iter().chain(&ray.dir).all(|x| x.is_finite()) {
            return None;
        }
        // A zero component gives +-inf, with the sign of the zero: the slab then either holds
        // the whole ray or none of it.
        let inv = ray.dir.map(|d| T::ONE / d);
        // Decided on the inverse so that -0.0 (inverse -inf) counts as negative.
        let negative = inv.map(|d| d < T::ZERO);
        Some(Self {
            origin: ray.origin.map(|x| S::from_f64(x.to_f64())),
            inv_dir: inv.map(|x| S::from_f64(x.to_f64())),
            inv_far: inv.map(|x| S::from_f64(x.to_f64()) * S::SLACK),
            near: core::array::from_fn(|k| if negative[k] { k + 3 } else { k }),
            far: core::array::from_fn(|k| if negative[k] { k } else { k + 3 }),
        })
    }

    /// Lane-by-lane box test, for machines without AVX2 (and the tests).
    #[cfg_attr(
        all(target_arch = "x86_64", target_feature = "avx2"),
        allow(dead_code, reason = "with AVX2 only the tests use it, as the reference")
    )]
    #[inline(always)]
    fn hits_scalar(&self, node: &Node, bound: S, t: &mut [S; WIDTH]) -> u32
    where
        S: From<f32>,
    {
        let mut mask = 0;
        for (lane, t) in t.iter_mut().enumerate() {
            let mut near = S::ZERO;
            let mut far = bound;
            for k in 0..3 {
                let lo = S::from(node.planes[self.near[k]][lane]);
                let hi = S::from(node.planes[self.far[k]][lane]);
                // `max_or`/`min_or` ignore a NaN distance (0 * inf: the ray lies in the face
                // plane), so such a slab constrains nothing.
                near = max_or(near, (lo - self.origin[k]) * self.inv_dir[k]);
                far = min_or(far, (hi - self.origin[k]) * self.inv_far[k]);
            }
            *t = near;
            mask |= u32::from(near <= far) << lane;
        }
        mask
    }
}

impl Lane for f32 {
    const ZERO: f32 = 0.0;
    const SLACK: f32 = ize_factor(f32::EPSILON as f64) as f32 + f32::EPSILON;
    #[inline(always)]
    fn from_f64(x: f64) -> f32 {
        x as f32
    }
    #[inline(always)]
    fn key(self) -> u64 {
        u64::from(self.to_bits()) << 3
    }
    #[inline(always)]
    fn hits(node: &Node, ray: &Prepared<f32>, bound: f32, t: &mut [f32; WIDTH]) -> u32 {
        #[cfg(all(target_arch = "x86_64", target_feature = "avx2"))]
        {
            avx2::hits_f32(node, ray, bound, t)
        }
        #[cfg(not(all(target_arch = "x86_64", target_feature = "avx2")))]
        {
            ray.hits_scalar(node, bound, t)
        }
    }
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    unsafe fn hits_avx512(
        node: &Node,
        ray: &Prepared<f32>,
        bound: f32,
        t: &mut [f32; WIDTH],
    ) -> u32 {
        // SAFETY: the caller guarantees AVX-512F and VL.
        unsafe { avx512::hits_f32(node, ray, bound, t) }
    }
}

impl Lane for f64 {
    const ZERO: f64 = 0.0;
    const SLACK: f64 = ize_factor(f64::EPSILON) + f64::EPSILON;
    #[inline(always)]
    fn from_f64(x: f64) -> f64 {
        x
    }
    #[inline(always)]
    fn key(self) -> u64 {
        self.to_bits() & !7
    }
    #[inline(always)]
    fn hits(node: &Node, ray: &Prepared<f64>, bound: f64, t: &mut [f64; WIDTH]) -> u32 {
        #[cfg(all(target_arch = "x86_64", target_feature = "avx2"))]
        {
            avx2::hits_f64(node, ray, bound, t)
        }
        #[cfg(not(all(target_arch = "x86_64", target_feature = "avx2")))]
        {
            ray.hits_scalar(node, bound, t)
        }
    }
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    unsafe fn hits_avx512(
        node: &Node,
        ray: &Prepared<f64>,
        bound: f64,
        t: &mut [f64; WIDTH],
    ) -> u32 {
        // SAFETY: the caller guarantees AVX-512F and VL.
        unsafe { avx512::hits_f64(node, ray, bound, t) }
    }
}

#[cfg(all(target_arch = "x86_64", target_feature = "avx2"))]
mod avx2 {
    //! The box tests with AVX2. Operand order matters: `max_ps(a, b)` and `min_ps(a, b)`
    //! return `b` when either is NaN, so a NaN slab distance (first operand) leaves the
    //! running bound (second operand) as it was, as `max_or`/`min_or` do.

    use core::arch::x86_64::*;

    use super::{Node, Prepared, WIDTH};

    #[inline(always)]
    fn plane(node: &Node, row: usize) -> __m256 {
        // SAFETY: AVX is enabled (see above); a row is 8 f32, 32-byte aligned (`Node` is, and
        // rows are 32 bytes).
        unsafe { _mm256_load_ps(node.planes[row].as_ptr()) }
    }

    #[inline(always)]
    pub fn hits_f32(node: &Node, r: &Prepared<f32>, bound: f32, t: &mut [f32; WIDTH]) -> u32 {
        // SAFETY: this module is compiled only when the build enables AVX2; `t` holds the 8
        // f32 of the unaligned store.
        unsafe {
            let mut near = _mm256_setzero_ps();
            let mut far = _mm256_set1_ps(bound);
            for k in 0..3 {
                let o = _mm256_set1_ps(r.origin[k]);
                let inv = _mm256_set1_ps(r.inv_dir[k]);
                let inv_far = _mm256_set1_ps(r.inv_far[k]);
                let tn = _mm256_mul_ps(_mm256_sub_ps(plane(node, r.near[k]), o), inv);
                let tf = _mm256_mul_ps(_mm256_sub_ps(plane(node, r.far[k]), o), inv_far);
                near = _mm256_max_ps(tn, near);
                far = _mm256_min_ps(tf, far);
            }
            let inside = _mm256_cmp_ps::<_CMP_LE_OQ>(near, far);
            _mm256_storeu_ps(t.as_mut_ptr(), near);
            _mm256_movemask_ps(inside) as u32
        }
    }

    #[inline(always)]
    fn half(node: &Node, row: usize, high: bool) -> __m256d {
        let offset = if high { 4 } else { 0 };
        // SAFETY: AVX is enabled (see above); 4 of the row's 8 f32, 16-byte aligned (rows
        // are 32-byte aligned).
        unsafe { _mm256_cvtps_pd(_mm_load_ps(node.planes[row].as_ptr().add(offset))) }
    }

    #[inline(always)]
    pub fn hits_f64(node: &Node, r: &Prepared<f64>, bound: f64, t: &mut [f64; WIDTH]) -> u32 {
        let mut mask = 0;
        for (h, high) in [false, true].into_iter().enumerate() {
            // SAFETY: AVX2 is enabled (see above); `t` holds 8 f64, lanes 4h..4h+4 are in
            // bounds of the unaligned store.
            unsafe {
                let mut near = _mm256_setzero_pd();
                let mut far = _mm256_set1_pd(bound);
                for k in 0..3 {
                    let o = _mm256_set1_pd(r.origin[k]);
                    let inv = _mm256_set1_pd(r.inv_dir[k]);
                    let inv_far = _mm256_set1_pd(r.inv_far[k]);
                    let tn = _mm256_mul_pd(_mm256_sub_pd(half(node, r.near[k], high), o), inv);
                    let tf = _mm256_mul_pd(_mm256_sub_pd(half(node, r.far[k], high), o), inv_far);
                    near = _mm256_max_pd(tn, near);
                    far = _mm256_min_pd(tf, far);
                }
                let inside = _mm256_cmp_pd::<_CMP_LE_OQ>(near, far);
                _mm256_storeu_pd(t.as_mut_ptr().add(4 * h), near);
                mask |= (_mm256_movemask_pd(inside) as u32) << (4 * h);
            }
        }
        mask
    }
}

#[cfg(target_arch = "x86_64")]
mod avx512 {
    //! The box tests with AVX-512: the AVX2 tests' operations in the same order (so the same
    //! NaN handling: `max`/`min` return their second operand when either is NaN), the compare
    //! into a mask register.

    use core::arch::x86_64::*;

    use super::{Node, Prepared, WIDTH};

    #[inline]
    #[target_feature(enable = "avx512f,avx512vl")]
    pub fn hits_f32(node: &Node, r: &Prepared<f32>, bound: f32, t: &mut [f32; WIDTH]) -> u32 {
        // SAFETY: a row is 8 f32, 32-byte aligned (`Node` is, and rows are 32 bytes).
        let plane = |row: usize| unsafe { _mm256_load_ps(node.planes[row].as_ptr()) };
        let mut near = _mm256_setzero_ps();
        let mut far = _mm256_set1_ps(bound);
        for k in 0..3 {
            let o = _mm256_set1_ps(r.origin[k]);
            let inv = _mm256_set1_ps(r.inv_dir[k]);
            let inv_far = _mm256_set1_ps(r.inv_far[k]);
            let tn = _mm256_mul_ps(_mm256_sub_ps(plane(r.near[k]), o), inv);
            let tf = _mm256_mul_ps(_mm256_sub_ps(plane(r.far[k]), o), inv_far);
            near = _mm256_max_ps(tn, near);
            far = _mm256_min_ps(tf, far);
        }
        let inside = _mm256_cmp_ps_mask::<_CMP_LE_OQ>(near, far);
        // SAFETY: `t` holds the 8 f32 of the unaligned store.
        unsafe { _mm256_storeu_ps(t.as_mut_ptr(), near) };
        u32::from(inside)
    }

    /// The `f64` test in two 4-lane halves, as AVX2's, with the compare into a mask register
    /// (the kept form: see [`hits_f64_zmm`]).
    #[inline]
    #[target_feature(enable = "avx512f,avx512vl")]
    pub fn hits_f64(node: &Node, r: &Prepared<f64>, bound: f64, t: &mut [f64; WIDTH]) -> u32 {
        let mut mask = 0;
        for h in 0..2 {
            let half = |row: usize| {
                // SAFETY: 4 of the row's 8 f32, 16-byte aligned (rows are 32-byte aligned).
                let lanes = unsafe { _mm_load_ps(node.planes[row][4 * h..].as_ptr()) };
                _mm256_cvtps_pd(lanes)
            };
            let mut near = _mm256_setzero_pd();
            let mut far = _mm256_set1_pd(bound);
            for k in 0..3 {
                let o = _mm256_set1_pd(r.origin[k]);
                let inv = _mm256_set1_pd(r.inv_dir[k]);
                let inv_far = _mm256_set1_pd(r.inv_far[k]);
                let tn = _mm256_mul_pd(_mm256_sub_pd(half(r.near[k]), o), inv);
                let tf = _mm256_mul_pd(_mm256_sub_pd(half(r.far[k]), o), inv_far);
                near = _mm256_max_pd(tn, near);
                far = _mm256_min_pd(tf, far);
            }
            let inside = _mm256_cmp_pd_mask::<_CMP_LE_OQ>(near, far);
            // SAFETY: `t` holds 8 f64; lanes 4h..4h+4 are in bounds of the unaligned store.
            unsafe { _mm256_storeu_pd(t.as_mut_ptr().add(4 * h), near) };
            mask |= u32::from(inside) << (4 * h);
        }
        mask
    }

    /// The `f64` test in one 8-lane register. Measured slower than the halves on the machine
    /// of `results/README.md` ("AVX-512"), kept beside them, tested, for measuring again.
    #[cfg_attr(not(test), expect(dead_code, reason = "measured slower; tested, not traced"))]
    #[inline]
    #[target_feature(enable = "avx512f,avx512vl")]
    pub fn hits_f64_zmm(node: &Node, r: &Prepared<f64>, bound: f64, t: &mut [f64; WIDTH]) -> u32 {
        let plane = |row: usize| {
            // SAFETY: a row is 8 f32, 32-byte aligned (`Node` is, and rows are 32 bytes).
            _mm512_cvtps_pd(unsafe { _mm256_load_ps(node.planes[row].as_ptr()) })
        };
        let mut near = _mm512_setzero_pd();
        let mut far = _mm512_set1_pd(bound);
        for k in 0..3 {
            let o = _mm512_set1_pd(r.origin[k]);
            let inv = _mm512_set1_pd(r.inv_dir[k]);
            let inv_far = _mm512_set1_pd(r.inv_far[k]);
            let tn = _mm512_mul_pd(_mm512_sub_pd(plane(r.near[k]), o), inv);
            let tf = _mm512_mul_pd(_mm512_sub_pd(plane(r.far[k]), o), inv_far);
            near = _mm512_max_pd(tn, near);
            far = _mm512_min_pd(tf, far);
        }
        let inside = _mm512_cmp_pd_mask::<_CMP_LE_OQ>(near, far);
        // SAFETY: `t` holds the 8 f64 of the unaligned store.
        unsafe { _mm512_storeu_pd(t.as_mut_ptr(), near) };
        u32::from(inside)
    }
}

/// A fixed-size stack that is never initialised as a whole (one ray pushes a few entries of
/// its [`STACK`]: clearing them all would cost more than the pushes).
struct Stack<E> {
    items: [MaybeUninit<E>; STACK],
    len: usize,
}

impl<E: Copy> Stack<E> {
    #[inline(always)]
    fn new() -> Self {
        Self { items: [const { MaybeUninit::uninit() }; STACK], len: 0 }
    }

    #[inline(always)]
    fn push(&mut self, e: E) {
        // Bounds-checked: the depth bound of the build makes overflow impossible, and a check
        // is cheaper than trusting it.
        self.items[self.len] = MaybeUninit::new(e);
        self.len += 1;
    }

    #[inline(always)]
    fn pop(&mut self) -> Option<E> {
        self.len = self.len.checked_sub(1)?;
        // SAFETY: entries below `len` were written by `push` and not popped since.
        Some(unsafe { self.items[self.len].assume_init() })
    }
}

/// What a closest-hit traversal does at a leaf: [`closest`] hands it the leaf's slots and the
/// current limit, which it lowers when it finds a nearer hit.
///
/// Closures implement it. A type of one's own whose `visit` is `#[inline(always)]` is
/// compiled into the traversal loop: a closure's body is inlined at the compiler's discretion,
/// and one called from the loop of each instruction set usually is not (a call per leaf, and
/// the loop's registers saved around it).
pub trait ClosestLeaf<T> {
    /// The leaf's slots and the limit to lower.
    fn visit(&mut self, slots: Range<usize>, limit: &mut T);
}

impl<T, F: FnMut(Range<usize>, &mut T)> ClosestLeaf<T> for F {
    #[inline(always)]
    fn visit(&mut self, slots: Range<usize>, limit: &mut T) {
        self(slots, limit);
    }
}

/// What an any-hit traversal does at a leaf: [`any`] hands it the leaf's slots and stops
/// when it returns `true` (see [`ClosestLeaf`] on closures and inlining).
pub trait AnyLeaf {
    /// Whether the ray hits a triangle of these slots.
    fn visit(&mut self, slots: Range<usize>) -> bool;
}

impl<F: FnMut(Range<usize>) -> bool> AnyLeaf for F {
    #[inline(always)]
    fn visit(&mut self, slots: Range<usize>) -> bool {
        self(slots)
    }
}

/// Converts the tree's precision to the lane type (exact: they are the same precision).
#[inline(always)]
fn lane<S: Lane, T: Real>(x: T) -> S {
    S::from_f64(x.to_f64())
}

/// [`closest`] compiled with AVX-512: the loop and everything it inlines (the node test, the
/// caller's leaf closure) in one function that enables the instructions.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx512f,avx512vl")]
pub fn closest_avx512<S, T, F>(test: Avx512, nodes: &[Node], ray: &Ray<T>, t_max: T, leaf: F)
where
    S: Lane + From<f32>,
    T: Real,
    F: ClosestLeaf<T>,
{
    closest::<S, T, F>(test, nodes, ray, t_max, leaf);
}

/// [`any`] compiled with AVX-512 (see [`closest_avx512`]).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx512f,avx512vl")]
pub fn any_avx512<S, T, F>(test: Avx512, nodes: &[Node], ray: &Ray<T>, t_max: T, leaf: F) -> bool
where
    S: Lane + From<f32>,
    T: Real,
    F: AnyLeaf,
{
    any::<S, T, F>(test, nodes, ray, t_max, leaf)
}

/// See [`super::Bvh::closest`].
#[inline(always)]
pub fn closest<S, T, F>(test: impl NodeTest, nodes: &[Node], ray: &Ray<T>, t_max: T, mut leaf: F)
where
    S: Lane + From<f32>,
    T: Real,
    F: ClosestLeaf<T>,
{
    if nodes.is_empty() {
        return;
    }
    let Some(prepared) = Prepared::<S>::new(ray) else { return };
    let mut stack: Stack<(u32, S)> = Stack::new();
    let mut t = [S::ZERO; WIDTH];
    let mut limit = t_max;
    let mut current = 0u32;
    loop {
        if is_leaf(current) {
            leaf.visit(leaf_slots(current), &mut limit);
        } else {
            let node = &nodes[current as usize];
            let mask = test.hits(node, &prepared, lane::<S, T>(limit) * S::SLACK, &mut t);
            if mask != 0 {
                let first = mask.trailing_zeros() as usize;
                let rest = mask & (mask - 1);
                if rest == 0 {
                    current = node.refs[first];
                    continue;
                }
                let second = rest.trailing_zeros() as usize;
                if rest & (rest - 1) == 0 {
                    // Two (the common case): the nearer now, the other on the stack.
                    let (near, far) =
                        if t[second] < t[first] { (second, first) } else { (first, second) };
                    stack.push((node.refs[far], t[far]));
                    current = node.refs[near];
                    continue;
                }
                // Three or more: sort by distance (insertion sort on keys that carry the lane
                // in their low bits), visit the nearest now, stack the others farthest first.
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
                for &key in keys[1..n].iter().rev() {
                    let i = (key & 7) as usize;
                    stack.push((node.refs[i], t[i]));
                }
                current = node.refs[(keys[0] & 7) as usize];
                continue;
            }
        }
        // Pop until a child that still starts within the (possibly lowered) limit; one
        // entered exactly at the limit is visited, so ties are resolved by the caller.
        let bound = lane::<S, T>(limit) * S::SLACK;
        loop {
            let Some((r, t_entry)) = stack.pop() else { return };
            if t_entry <= bound {
                current = r;
                break;
            }
        }
    }
}

/// See [`super::Bvh::any`].
#[inline(always)]
pub fn any<S, T, F>(
    test: impl NodeTest,
    nodes: &[Node],
    ray: &Ray<T>,
    t_max: T,
    mut leaf: F,
) -> bool
where
    S: Lane + From<f32>,
    T: Real,
    F: AnyLeaf,
{
    if nodes.is_empty() {
        return false;
    }
    let Some(prepared) = Prepared::<S>::new(ray) else { return false };
    let bound = lane::<S, T>(t_max) * S::SLACK;
    let mut stack: Stack<u32> = Stack::new();
    let mut t = [S::ZERO; WIDTH];
    let mut current = 0u32;
    loop {
        if is_leaf(current) {
            if leaf.visit(leaf_slots(current)) {
                return true;
            }
        } else {
            let node = &nodes[current as usize];
            let mut mask = test.hits(node, &prepared, bound, &mut t);
            if mask != 0 {
                current = node.refs[mask.trailing_zeros() as usize];
                mask &= mask - 1;
                while mask != 0 {
                    stack.push(node.refs[mask.trailing_zeros() as usize]);
                    mask &= mask - 1;
                }
                continue;
            }
        }
        match stack.pop() {
            Some(r) => current = r,
            None => return false,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::node::leaf_ref;

    fn node_with(boxes: &[([f32; 3], [f32; 3])]) -> Node {
        let mut node = Node::EMPTY;
        for (lane, (lo, hi)) in boxes.iter().enumerate() {
            node.set(lane, *lo, *hi, leaf_ref(lane, 1));
        }
        node
    }

    /// The vector test (with AVX2) and the lane-by-lane test agree, and both match the
    /// expected answers.
    fn check<S: Lane + From<f32> + core::fmt::Debug>(ray: Ray<f64>, limit: f64, expect: u32) {
        let unit = ([0.0f32, 0.0, 0.0], [1.0f32, 1.0, 1.0]);
        let far = ([0.0f32, 0.0, 5.0], [1.0f32, 1.0, 6.0]);
        let beside = ([2.0f32, 0.0, 0.0], [3.0f32, 1.0, 1.0]);
        let node = node_with(&[unit, far, beside]);
        let prepared = Prepared::<S>::new(&ray).unwrap();
        let mut t = [S::ZERO; WIDTH];
        let mut u = [S::ZERO; WIDTH];
        let mask = S::hits(&node, &prepared, S::from_f64(limit), &mut t);
        let scalar = prepared.hits_scalar(&node, S::from_f64(limit), &mut u);
        assert_eq!(mask, expect, "{ray:?} {limit}");
        assert_eq!(scalar, expect, "{ray:?} {limit}");
        for lane in 0..WIDTH {
            if mask >> lane & 1 == 1 {
                assert!(t[lane] == u[lane], "{:?} {:?}", t[lane], u[lane]);
            }
        }
        #[cfg(target_arch = "x86_64")]
        if crate::simd::Isa::detected() == crate::simd::Isa::Avx512 {
            let mut v = [S::ZERO; WIDTH];
            // SAFETY: the CPU has AVX-512F and VL (just detected).
            let wide = unsafe { S::hits_avx512(&node, &prepared, S::from_f64(limit), &mut v) };
            assert_eq!(wide, expect, "avx512: {ray:?} {limit}");
            // Every lane, hit or not: the same entry distances (never NaN: `max` keeps the
            // running bound, which starts at 0, over a NaN distance).
            assert!(t == v, "{t:?} {v:?}");
        }
    }

    #[test]
    fn eight_wide_box_test() {
        for (ray, limit, expect) in [
            // Up the z axis through the unit box and the far box.
            (Ray::new([0.5, 0.5, -1.0], [0.0, 0.0, 1.0]), f64::INFINITY, 0b011),
            (Ray::new([0.5, 0.5, -1.0], [0.0, 0.0, 1.0]), 3.0, 0b001),
            // Exactly at the far box's entry distance: still in.
            (Ray::new([0.5, 0.5, -1.0], [0.0, 0.0, 1.0]), 6.0, 0b011),
            // In the face plane x = 0 (0 * inf = NaN is ignored), and with -0.0 components.
            (Ray::new([0.0, 0.5, -1.0], [0.0, 0.0, 1.0]), f64::INFINITY, 0b011),
            (Ray::new([0.0, 0.5, -1.0], [-0.0, -0.0, 1.0]), f64::INFINITY, 0b011),
            // Along -x from the right: the box beside first, then the unit box.
            (Ray::new([5.0, 0.5, 0.5], [-1.0, 0.0, 0.0]), f64::INFINITY, 0b101),
            // Behind the origin.
            (Ray::new([0.5, 0.5, 7.0], [0.0, 0.0, 1.0]), f64::INFINITY, 0b000),
            // Diagonal from inside the unit box.
            (Ray::new([0.5, 0.5, 0.5], [1.0, 0.01, 0.01]), f64::INFINITY, 0b101),
        ] {
            check::<f32>(ray, limit, expect);
            check::<f64>(ray, limit, expect);
        }
    }

    /// The entry distances themselves, against values worked out by hand (so that a build
    /// without AVX2, where the vector test is the lane-by-lane one, still checks them): up the
    /// z axis from z = -1, the unit box is entered at t = 1, the far box at t = 6; along -x
    /// from x = 5, the box beside at t = 2 and the unit box at t = 4.
    fn entries<S: Lane + From<f32> + core::fmt::Debug>() {
        let unit = ([0.0f32, 0.0, 0.0], [1.0f32, 1.0, 1.0]);
        let far = ([0.0f32, 0.0, 5.0], [1.0f32, 1.0, 6.0]);
        let beside = ([2.0f32, 0.0, 0.0], [3.0f32, 1.0, 1.0]);
        let node = node_with(&[unit, far, beside]);
        for (ray, lanes, want) in [
            (Ray::new([0.5, 0.5, -1.0], [0.0, 0.0, 1.0]), [0, 1], [1.0, 6.0]),
            (Ray::new([5.0, 0.5, 0.5], [-1.0, 0.0, 0.0]), [0, 2], [4.0, 2.0]),
        ] {
            let prepared = Prepared::<S>::new(&ray).unwrap();
            let mut t = [S::ZERO; WIDTH];
            let mask = S::hits(&node, &prepared, S::from_f64(f64::INFINITY), &mut t);
            for (lane, want) in lanes.into_iter().zip(want) {
                assert_eq!(mask >> lane & 1, 1, "{ray:?}: lane {lane}");
                assert!(t[lane] == S::from_f64(want), "{ray:?}: lane {lane}: {:?}", t[lane]);
            }
        }
    }

    /// The kept `f64` AVX-512 test (two halves) and the 8-lane one agree lane for lane.
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn both_avx512_f64_tests_agree() {
        if crate::simd::Isa::detected() != crate::simd::Isa::Avx512 {
            println!("note: this CPU has no AVX-512 (F and VL): nothing to compare");
            return;
        }
        let boxes: Vec<([f32; 3], [f32; 3])> = (0..8)
            .map(|i| {
                let x = i as f32 * 0.75 - 3.0;
                ([x, -1.0, 0.5 * x], [x + 1.5, 1.0, 0.5 * x + 2.0])
            })
            .collect();
        let node = node_with(&boxes);
        for (o, d) in [
            ([-10.0, 0.1, 0.0], [1.0, 0.01, 0.1]),
            ([0.0, 0.0, -5.0], [0.0, 0.0, 1.0]),
            ([3.0, -0.0, 1.0], [-1.0, -0.0, -0.3]),
            ([-1.5, 1.0, 0.0], [0.3, 0.0, 0.2]),
        ] {
            let prepared = Prepared::<f64>::new(&Ray::new(o, d)).unwrap();
            for limit in [f64::INFINITY, 4.0, 0.5] {
                let (mut a, mut b) = ([0.0; WIDTH], [0.0; WIDTH]);
                // SAFETY: the CPU has AVX-512F and VL (just detected).
                let (ma, mb) = unsafe {
                    (
                        avx512::hits_f64(&node, &prepared, limit, &mut a),
                        avx512::hits_f64_zmm(&node, &prepared, limit, &mut b),
                    )
                };
                assert_eq!((ma, a.map(f64::to_bits)), (mb, b.map(f64::to_bits)), "{o:?} {d:?}");
                assert_eq!(ma, f64::hits(&node, &prepared, limit, &mut b), "{o:?} {d:?}");
            }
        }
    }

    #[test]
    fn entry_distances_match_the_slabs() {
        entries::<f32>();
        entries::<f64>();
    }

    #[test]
    fn non_finite_rays_are_not_prepared() {
        assert!(Prepared::<f32>::new(&Ray::new([f64::NAN, 0.0, 0.0], [0.0, 0.0, 1.0])).is_none());
        assert!(Prepared::<f64>::new(&Ray::new([0.0; 3], [f64::INFINITY, 0.0, 1.0])).is_none());
        assert!(Prepared::<f64>::new(&Ray::new([0.0; 3], [0.0, 0.0, 1.0])).is_some());
    }

    #[test]
    fn stack_pushes_and_pops_in_order() {
        let mut s: Stack<u32> = Stack::new();
        assert_eq!(s.pop(), None);
        for i in 0..STACK as u32 {
            s.push(i);
        }
        assert_eq!(s.pop(), Some(STACK as u32 - 1));
        assert_eq!(s.pop(), Some(STACK as u32 - 2));
    }

    #[test]
    fn sort_keys_follow_distances() {
        assert!(0.5f32.key() < 0.75f32.key() && 0.0f32.key() < f32::MIN_POSITIVE.key());
        assert!(1.0f64.key() < 1.5f64.key() && 0.0f64.key() | 7 < 1e-300f64.key());
        assert!(f32::INFINITY.key() > f32::MAX.key());
    }
}
