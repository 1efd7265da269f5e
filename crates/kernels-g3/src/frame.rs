//! The report's mathematics with the per-triangle work done once, at scene build, and only
//! grade-specialised types in the kernel.
//!
//! # Derivation
//!
//! Let `N = (b - a) ∧ (c - a)` be the triangle's bivector (report 3.1, unnormalised: its
//! magnitude is twice the area) and `p = a + λb (b - a) + λc (c - a)` a point of its plane.
//!
//! **The plane (3.1, 3.2).** The plane is `((x - a) ∧ N)* = 0`; for a vector `x`,
//! `(x ∧ N)* = x · N*`, so with the unit normal `n = N* / |N|` it is `(x - a) · n = 0`. On
//! the ray `x = o + t u` this gives the report's `t = -((o ∧ B)* - d) / (u ∧ B)*` with the
//! offset measured from `a` instead of the world origin:
//!
//! ```text
//! s = a - o            the vertex a seen from the ray origin
//! den = u · n          (u ∧ B)*, the report's denominator
//! num = s · n          -((o ∧ B)* - d), with d = a · n
//! t = num / den
//! ```
//!
//! **The edges (3.3).** The report compares the edge bivector `(b - a) ∧ (p - a)` with
//! `N`. For `p` in the plane it is a multiple of `N`: substituting `p`,
//! `(b - a) ∧ (p - a) = λc (b - a) ∧ (c - a) = λc N`. So `λc = ((b - a) ∧ (p - a)) | N⁻¹`
//! (`N⁻¹ = N / (N | N)`, `N | N = -|N|²`), and this is linear in `x = p - a`: for a vector
//! `e` and a bivector `N`,
//!
//! ```text
//! (e ∧ x) | N = <(e x - e · x) N>₀ = <e x N>₀ = <x N e>₀ = x · <N e>₁ = x · (N | e)
//! ```
//!
//! (the scalar `e · x` times `N` has no scalar part; the scalar part is invariant under cyclic
//! permutation). Hence `λc = (p - a) · m_c` with the vector `m_c = N⁻¹ | (b - a)`. The same for
//! the edge from `c` to `a`, whose bivector `(a - c) ∧ (p - c) = λb N` gives
//! `λb = (p - c) · m_b = (p - a) · m_b` with `m_b = N⁻¹ | (a - c)` (`m_b` is orthogonal to
//! `a - c`, so the start point does not matter). `m_b`, `m_c` lie in the plane, `m_b` at
//! right angles to `c - a`, `m_c` to `b - a`: they are the reciprocal frame of
//! `(b - a, c - a)` (`m_b · (b - a) = 1`, `m_b · (c - a) = 0`, and so on). Each edge test of
//! the report is now one inner product with the hit point, and its value *is* the barycentric
//! coordinate; the third edge is `λa = 1 - λb - λc`.
//!
//! **Without a division.** The hit point relative to `a`, scaled by `den`, is
//!
//! ```text
//! q = den (p - a) = den (t u - s) = num u - den s       (= -n | (u ∧ s), the normal's inner
//!                                                          product with the ray's moment about a)
//! U = q · m_b = den λb      V = q · m_c = den λc        W = den - U - V = den λa
//! ```
//!
//! and, the inner product being linear, `U = num (u · m_b) - den (s · m_b)` and
//! `V = num (u · m_c) - den (s · m_c)`: everything the test needs is the six inner products of
//! `u` and `s` with the three vectors `n`, `m_b`, `m_c`, and two products on top.
//!
//! With `σ = sign(den)`: inside is `σU >= 0`, `σV >= 0`, `σ(U + V) <= |den|` (closed edges),
//! and `0 < t <= t_max` is `0 < σ num <= t_max |den|`. `σx` is a product with `±1`,
//! exact (see below for why not a bit operation). `den = 0` (ray parallel to the plane, or a
//! degenerate triangle, stored with `n = 0`) fails the distance test for every `t_max`. Only then
//! does the kernel divide: `t = num / den`, `u = U / den`, `v = V / den`.
//!
//! # Per-triangle data: 12 scalars, stored by axis
//!
//! `a`, `n`, `m_b`, `m_c` (48 bytes in `f32`, 96 in `f64`), computed in `f64` and rounded once,
//! stored by axis: row `k` holds `(n_k, m_b_k, m_c_k, a_k)`. Then `x · n`, `x · m_b`, `x · m_c` for
//! a vector `x` are one vector expression over the three rows, `x_1 row_1 + x_2 row_2 + x_3 row_3`
//! (one multiply and two fused multiply-adds on four lanes), and `s = a - o` comes from the
//! rows' fourth lanes.
//! Storing `a` rather than the offsets `a · n`, `a · m_b`, `a · m_c` costs the same per test
//! (three subtractions `a - o` instead of three additions of offsets) and puts the only
//! cancellation into one subtraction of nearby points, as Moller-Trumbore and the watertight
//! kernel do, instead of a difference of distances from the world origin.
//!
//! # Cost per test
//!
//! Counting a fused multiply-add as one operation, on four lanes where the machine has them
//! (x86-64 with AVX2 and FMA, as this workspace builds: one SSE register per row in `f32`, one
//! AVX register in `f64`): `s`, 3 broadcasts of the fourth lanes and 3 subtractions; the inner
//! products of `s` and of `u` with `n`, `m_b`, `m_c`, 3 vector operations each; `U` and `V`, 1
//! multiply and 1 multiply-add after broadcasting `num` and `den`; the edge test, 2 additions,
//! 2 minima and 1 comparison on scalars; the distance test, 2 multiplies (`t_max |den|`, the
//! slack below) and 2 comparisons. The sign flips `σx` are exact products with `±1`. About 25
//! operations, 13 of them on four lanes; written out on scalars, 33 (Moller-Trumbore: 27 and a
//! reciprocal). Elsewhere the same expressions run lane by lane with the same roundings
//! (`src/lanes.rs`), so both forms give the same bits. One division, only for a hit.
//!
//! The four-lane form replaced a scalar one (`q = num u - den s`, then `q · m_b` and `q · m_c`,
//! three scalar inner products after two) because it measured faster; the figures of that and
//! every later choice below are in `results/README.md` ("Kernel design experiments").
//!
//! # One predictable branch: the edges first
//!
//! Both tests are needed for a hit, so their order does not change any result, only the
//! time. The distance test alone is cheaper (11 operations), but a ray from inside a mesh
//! finds about half of the planes of the triangles it is tested against in front of it: a
//! coin toss for the branch predictor. A mispredicted branch throws away the work the
//! processor has started beyond it, including the loads of the next BVH node and triangles,
//! so the memory latencies that would have overlapped are paid one after the other. The
//! edge test fails for nearly every triangle tested (about 11% of the tests on the bunny's
//! incoherent rays are hits), so it is decided first, with the three comparisons folded into
//! one (`min(σU, σV, |den| - σ(U + V)) >= 0`, the minima being branch-free instructions), and
//! the distance test runs only for rays inside the edges. Combining the comparisons with `&` or
//! `|` instead of a minimum does not give one branch: the compiler splits a branch on them into
//! a chain of branches, the first of them the same coin toss.
//!
//! The minimum is the processor's (`x < y ? x : y`, one `minss`), not `f32::min`, whose
//! NaN rule costs a compare and a blend per minimum and needed a second branch for a NaN `w`;
//! and σ is taken off by a product with `±1` rather than a bit operation, which the compiler
//! ran through the integer registers.
//!
//! # Not watertight
//!
//! `U`, `V` are computed from each triangle's own `a`, `m_b`, `m_c`, so two triangles sharing
//! an edge round differently: a ray through the edge can pass between them. See
//! [`crate::G3Watertight`] for a kernel that cannot.

use core::marker::PhantomData;

use ga::g3::Vector;
use intersect::{Algebra, Guarantees, Intersector, Method, Ray, Triangle, TriangleHit};

use crate::real::private::Float;
use crate::{GaReal, is_degenerate};

/// The report's mathematics with per-triangle precomputation (`NAME = "ga"`), written as hand
/// four-lane SIMD over the triangle's rows: a labelled variant
/// ([`VARIANT`](Intersector::VARIANT)) beside the frame/G3 cell, not the cell itself, since
/// its per-test code touches no GA type (GA appears only in `prepare`).
///
/// See the [module derivation](self) and the [crate table](crate#the-kernels).
///
/// ```
/// use intersect::{Intersector, Ray, Triangle};
/// use kernels_g3::G3Frame;
///
/// let k = G3Frame::<f32>::new();
/// let prim = k.prepare(&Triangle::new([0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [0.0, 2.0, 0.0]));
/// let ray = Ray::new([0.5, 1.0, 3.0], [0.0, 0.0, -1.0]);
/// let hit = k.intersect(&prim, &ray, &(), f32::INFINITY).unwrap();
/// assert_eq!((hit.t, hit.u, hit.v), (3.0, 0.25, 0.5));
/// // Only within (0, t_max]: the triangle is 3 units away.
/// assert!(k.intersect(&prim, &ray, &(), 2.5).is_none());
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct G3Frame<T>(PhantomData<T>);

impl<T> G3Frame<T> {
    /// The kernel (it has no state).
    #[must_use]
    pub const fn new() -> Self {
        Self(PhantomData)
    }
}

/// What [`G3Frame`] keeps of a triangle (12 scalars): the vertex `a`, the unit normal
/// `n = N* / |N|`, and the reciprocal frame `m_b = N⁻¹ | (a - c)`, `m_c = N⁻¹ | (b - a)`, whose
/// inner products with `p - a` are the barycentric weights of `b` and `c`. Stored by axis:
/// `axes[k]` is `(n_k, m_b_k, m_c_k, a_k)` (see the [module documentation](self)).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[repr(C, align(16))]
pub struct G3FramePrim<T> {
    axes: [[T; 4]; 3],
}

impl<T: GaReal> G3FramePrim<T> {
    /// The data from its four vectors.
    fn from_vectors(a: Vector<T>, n: Vector<T>, m_b: Vector<T>, m_c: Vector<T>) -> Self {
        let [a, n, m_b, m_c] = [a, n, m_b, m_c].map(Vector::to_array);
        Self { axes: core::array::from_fn(|k| [n[k], m_b[k], m_c[k], a[k]]) }
    }

    /// The vertex `a`.
    #[must_use]
    pub fn a(&self) -> Vector<T> {
        crate::lanes::lane(&self.axes, 3)
    }

    /// The unit normal `n` (zero for a degenerate triangle).
    #[must_use]
    pub fn n(&self) -> Vector<T> {
        crate::lanes::lane(&self.axes, 0)
    }

    /// `m_b = N⁻¹ | (a - c)`: `(p - a) · m_b` is the barycentric weight of `b`.
    #[must_use]
    pub fn m_b(&self) -> Vector<T> {
        crate::lanes::lane(&self.axes, 1)
    }

    /// `m_c = N⁻¹ | (b - a)`: `(p - a) · m_c` is the barycentric weight of `c`.
    #[must_use]
    pub fn m_c(&self) -> Vector<T> {
        crate::lanes::lane(&self.axes, 2)
    }

    /// The data of triangle `tri`, computed in `f64` and rounded once to `T`.
    ///
    /// A degenerate triangle (see [`is_degenerate`]) gets `n = m_b = m_c = 0`, which no ray
    /// hits. Non-finite vertices give non-finite data, which no ray hits either.
    #[must_use]
    #[allow(clippy::eq_op, reason = "N | N, a bivector's inner product with itself, is meant")]
    pub fn new(tri: &Triangle<T>) -> Self {
        let a = Vector::from_array(tri.a);
        if is_degenerate(tri) {
            return Self::from_vectors(a, Vector::ZERO, Vector::ZERO, Vector::ZERO);
        }
        let [a64, b64, c64] = tri.vertices().map(|p| Vector::from_array(p.map(to_f64)));
        // N = (b - a) ∧ (c - a), the report's B before normalisation.
        let bivector = (b64 - a64) ^ (c64 - a64);
        // N⁻¹ = N / (N | N): for a blade, N N = N | N = -|N|².
        let inverse = bivector * (bivector | bivector).recip();
        // The plane ((x - a) ∧ N)* = 0 is (x - a) · N* = 0: its unit dual normal.
        let n = bivector.dual() * bivector.norm().recip();
        // Edge c -> a: (a - c) ∧ (p - c) = λb N, so λb = ((a - c) ∧ (p - c)) | N⁻¹
        // = (p - c) · (N⁻¹ | (a - c)) = (p - a) · m_b.
        let m_b = inverse | (a64 - c64);
        // Edge a -> b: (b - a) ∧ (p - a) = λc N, so λc = (p - a) · (N⁻¹ | (b - a)).
        let m_c = inverse | (b64 - a64);
        let round = |v: Vector<f64>| Vector::from_array(v.to_array().map(ga::Real::from_f64));
        Self::from_vectors(a, round(n), round(m_b), round(m_c))
    }
}

fn to_f64<T: GaReal>(x: T) -> f64 {
    ga::Real::to_f64(x)
}

impl<T: GaReal> Intersector for G3Frame<T> {
    type Real = T;
    type Prim = G3FramePrim<T>;
    type RayData = ();
    type Block = ();
    const NAME: &'static str = "ga";
    const ALGEBRA: Algebra = Algebra::G3;
    const METHOD: Method = Method::Frame;
    const GUARANTEES: Guarantees = Guarantees { watertight: false, exact: false };
    const VARIANT: Option<&'static str> = Some("hand four-lane SIMD over arrays");

    fn prepare(&self, tri: &Triangle<T>) -> G3FramePrim<T> {
        G3FramePrim::new(tri)
    }

    #[inline(always)]
    fn prepare_ray(&self, _ray: &Ray<T>) {}

    #[inline(always)]
    fn intersect(
        &self,
        prim: &G3FramePrim<T>,
        ray: &Ray<T>,
        _: &(),
        t_max: T,
    ) -> Option<TriangleHit<T>> {
        intersect(prim, ray, t_max)
    }

    #[inline(always)]
    fn occludes(&self, prim: &G3FramePrim<T>, ray: &Ray<T>, _: &(), t_max: T) -> bool {
        occludes(prim, ray, t_max)
    }
}

#[inline(always)]
fn intersect<T: Float>(prim: &G3FramePrim<T>, ray: &Ray<T>, t_max: T) -> Option<TriangleHit<T>> {
    hit(candidate(prim, ray, t_max)?, t_max)
}

/// The same test and the same rounded `t` as [`intersect`], without the barycentrics.
#[inline(always)]
fn occludes<T: Float>(prim: &G3FramePrim<T>, ray: &Ray<T>, t_max: T) -> bool {
    candidate(prim, ray, t_max).is_some_and(|c| occluded(&c, t_max))
}

/// The hit of a [`Candidate`]: one division, then `0 < t <= t_max` on the divided `t`.
#[inline(always)]
pub fn hit<T: ga::Scalar>(c: Candidate<T>, t_max: T) -> Option<TriangleHit<T>> {
    let inv_den = T::ONE / c.den;
    let t = c.num * inv_den;
    hit_distance_ok(t, t_max).then(|| TriangleHit { t, u: c.u * inv_den, v: c.v * inv_den })
}

/// Whether [`hit`] finds the hit, without the barycentrics (the same rounded `t`).
#[inline(always)]
pub fn occluded<T: ga::Scalar>(c: &Candidate<T>, t_max: T) -> bool {
    hit_distance_ok(c.num * (T::ONE / c.den), t_max)
}

/// The undivided hit: `t = num / den`, `u = U / den`, `v = V / den` (made by [`decide`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Candidate<T> {
    num: T,
    den: T,
    u: T,
    v: T,
}

/// The decision on undivided values (see the module derivation).
#[inline(always)]
fn candidate<T: Float>(prim: &G3FramePrim<T>, ray: &Ray<T>, t_max: T) -> Option<Candidate<T>> {
    // s = a - o; num = s · n, den = u · n; U = num (u · m_b) - den (s · m_b), V likewise.
    decide(T::frame_products(&prim.axes, &ray.origin, &ray.dir), t_max)
}

/// The frame method's decisions on its undivided values `[num, den, U, V]`, in its order: the
/// edges as one branch, then the distance (see the module documentation). Shared by the
/// frame/G3 cell ([`crate::G3FrameCell`]), which computes the four values in GA types, and
/// the frame/CGA cell (`kernels_cga::CgaFrame`), which computes them with dual planes.
#[inline(always)]
pub fn decide<T: ga::Scalar>([num, den, u, v]: [T; 4], t_max: T) -> Option<Candidate<T>> {
    let abs_den = den.abs();

    // The edges: σU >= 0, σV >= 0 and σ(U + V) <= |den| as one branch (see the module
    // documentation). σ is taken off by a product with ±1 (exact), and `fl(|den| - x) >= 0`
    // exactly when `|den| >= x`. `lesser(x, y)` is the processor's minimum (`minss`), which
    // returns `y` when either is NaN; `w` is NaN whenever `u`, `v` or `den` is, and comes
    // last, so a NaN reaches the comparison, which rejects it.
    let sign = T::ONE.copy_sign(den);
    let (u_s, v_s) = (u * sign, v * sign);
    let w = abs_den - (u_s + v_s);
    let lesser = |x: T, y: T| if x < y { x } else { y };
    let least = lesser(lesser(u_s, v_s), w);
    if least < T::ZERO || least.is_nan() {
        return None;
    }

    // 0 < t <= t_max as 0 < σ num <= t_max |den|, loosened by a few ulps so that it never
    // rejects a hit whose rounded t is exactly t_max (the final decision is made on the
    // divided t): then `intersect(.., t_max = hit.t)` finds the same hit.
    let num_s = num * sign;
    let slack = T::ONE + T::EPSILON * T::from_f64(4.0);
    if !(num_s > T::ZERO && num_s <= t_max * abs_den * slack) {
        return None;
    }
    Some(Candidate { num, den, u, v })
}

/// `0 < t <= t_max` and `t` finite, on the divided `t`.
#[inline(always)]
fn hit_distance_ok<T: ga::Scalar>(t: T, t_max: T) -> bool {
    t > T::ZERO && t <= t_max && t.is_finite()
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};
    use rand_pcg::Pcg64;

    /// `m_b`, `m_c` are the reciprocal frame of the edges `b - a`, `c - a` (so `(p - a) · m`
    /// are the barycentrics of `b` and `c`) and `n` is the unit normal, for random triangles.
    #[test]
    fn prim_holds_the_reciprocal_frame_and_the_unit_normal() {
        let mut rng = Pcg64::seed_from_u64(0x6a_4001);
        for _ in 0..10_000 {
            let mut p = || [0; 3].map(|_| rng.random_range(-10.0..10.0));
            let tri = Triangle::new(p(), p(), p());
            let prim = G3FramePrim::<f64>::new(&tri);
            let (n, m_b, m_c) = (prim.n(), prim.m_b(), prim.m_c());
            assert_eq!(prim.a().to_array(), tri.a);
            let [a, b, c] = tri.vertices().map(Vector::from_array);
            let (e1, e2) = (b - a, c - a);
            // Conditioning: thin triangles make the frame long.
            let scale = e1.norm() * e2.norm() / (e1 ^ e2).norm();
            let tol = 1e-13 * scale * scale;
            for (x, want) in [
                (m_b | e1, 1.0),
                (m_b | e2, 0.0),
                (m_c | e1, 0.0),
                (m_c | e2, 1.0),
                (m_b | n, 0.0),
                (m_c | n, 0.0),
            ] {
                assert!((x - want).abs() <= tol, "{x} vs {want} for {tri:?}");
            }
            assert!((n.norm() - 1.0).abs() <= 1e-15);
            assert!((n | e1).abs() <= 1e-14 * e1.norm() && (n | e2).abs() <= 1e-14 * e2.norm());
            // Right-handed with the vertex order: n points to where (b - a) x (c - a) does.
            assert!((n | e1.cross(e2)) > 0.0);
        }
    }

    /// A minimum may drop a NaN argument, so the one-branch edge test must reject NaN itself:
    /// here `U` is NaN while `V` and the distance are fine.
    #[test]
    fn a_nan_edge_value_is_a_miss() {
        let frame = |m_b| {
            G3FramePrim::<f32>::from_vectors(
                Vector::ZERO,
                Vector::new(0.0, 0.0, 1.0),
                m_b,
                Vector::new(0.0, 1.0, 0.0),
            )
        };
        let prim = frame(Vector::new(f32::NAN, 0.0, 0.0));
        let ray = Ray::new([0.1, 0.1, 1.0], [0.0, 0.0, -1.0]);
        assert!(intersect(&prim, &ray, f32::INFINITY).is_none());
        assert!(!occludes(&prim, &ray, f32::INFINITY));
        // The same with a finite frame is a hit: the NaN alone decides.
        let prim = frame(Vector::new(1.0, 0.0, 0.0));
        assert!(intersect(&prim, &ray, f32::INFINITY).is_some());
    }

    #[test]
    fn degenerate_triangles_get_a_zero_frame() {
        let tri = Triangle::new([1.0, 2.0, 3.0], [2.0, 4.0, 6.0], [3.0, 6.0, 9.0]);
        let prim = G3FramePrim::<f32>::new(&tri.cast());
        assert_eq!((prim.n(), prim.m_b(), prim.m_c()), (Vector::ZERO, Vector::ZERO, Vector::ZERO));
    }
}
