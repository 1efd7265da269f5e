//! The frame method in plain G3 types: the frame/G3 cell (`g3-frame`), beside which `ga`
//! ([`crate::G3Frame`], hand four-lane SIMD over the triangle stored by axis) is a labelled
//! variant.
//!
//! # The method
//!
//! [`crate::frame`]'s, unchanged: per triangle the vertex `a`, the unit normal
//! `n = N* / |N|` and the reciprocal frame `m_b = N⁻¹ | (a - c)`, `m_c = N⁻¹ | (b - a)` of
//! `N = (b - a) ∧ (c - a)`, computed in `f64` and rounded once by [`G3FramePrim::new`] (the
//! same numbers as `ga`'s). Per test, with `s = a - o` and the ray direction `u`:
//!
//! ```text
//! num = s | n        den = u | n                  (t = num / den)
//! U = num (u | m_b) - den (s | m_b)               (u = U / den, the weight of b)
//! V = num (u | m_c) - den (s | m_c)               (v = V / den, the weight of c)
//! ```
//!
//! each `|` the report's inner product of two [`Vector`]s, then `ga`'s decisions in `ga`'s
//! order ([`crate::frame`]'s `decide`, shared): the three edges as one branch
//! (`min(σU, σV, |den| - σ(U + V)) >= 0`, closed edges, no tie rule, not watertight), the
//! distance `0 < σ num <= t_max |den|` with `ga`'s slack, and one division for a hit.
//!
//! # Per-triangle data, cost
//!
//! - Per triangle: `a`, `n`, `m_b`, `m_c` as four [`Vector`]s, 48 B in `f32`, 96 B in `f64`
//!   (`ga`: the same 12 numbers by axis, the same bytes).
//! - Per ray: nothing.
//! - Per test: 1 vector subtraction (3), 6 inner products of vectors (3 multiplies and 2
//!   additions each, as the `ga` crate writes `Vector | Vector`), 4 multiplies and 2
//!   subtractions (`U`, `V`), then `ga`'s edge test and distance test: about 50 scalar
//!   operations where `ga` has 13 on four lanes.
//!
//! The difference from `ga` is only how the four values are computed, so the two give the same
//! decisions up to the rounding of those values (`ga` fuses multiply-adds, the `ga` crate's
//! inner product does not).

use core::marker::PhantomData;

use ga::g3::Vector;
use intersect::{Algebra, Guarantees, Intersector, Method, Ray, Triangle, TriangleHit};

use crate::GaReal;
use crate::frame::{Candidate, G3FramePrim, decide, hit, occluded};
use crate::real::private::Float;

/// The frame method written in `ga::g3` types (`NAME = "g3-frame"`): the frame/G3 cell.
///
/// See the [module documentation](self).
///
/// ```
/// use intersect::{Intersector, Ray, Triangle};
/// use kernels_g3::{G3Frame, G3FrameCell};
///
/// let tri = Triangle::new([0.0f32, 0.0, 0.0], [2.0, 0.0, 0.0], [0.0, 2.0, 0.0]);
/// let ray = Ray::new([0.5, 1.0, 3.0], [0.0, 0.0, -1.0]);
/// let k = G3FrameCell::<f32>::new();
/// let hit = k.intersect(&k.prepare(&tri), &ray, &(), f32::INFINITY).unwrap();
/// assert_eq!((hit.t, hit.u, hit.v), (3.0, 0.25, 0.5));
/// // The hand-SIMD variant gives the same hit here.
/// let ga = G3Frame::<f32>::new();
/// assert_eq!(ga.intersect(&ga.prepare(&tri), &ray, &(), f32::INFINITY), Some(hit));
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct G3FrameCell<T>(PhantomData<T>);

impl<T> G3FrameCell<T> {
    /// The kernel (it has no state).
    #[must_use]
    pub const fn new() -> Self {
        Self(PhantomData)
    }
}

/// What [`G3FrameCell`] keeps of a triangle: `a`, `n`, `m_b`, `m_c` (those of
/// [`G3FramePrim`]), one [`Vector`] each.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct G3FrameCellPrim<T> {
    a: Vector<T>,
    n: Vector<T>,
    m_b: Vector<T>,
    m_c: Vector<T>,
}

impl<T: GaReal> Intersector for G3FrameCell<T> {
    type Real = T;
    type Prim = G3FrameCellPrim<T>;
    type RayData = ();
    type Block = ();
    const NAME: &'static str = "g3-frame";
    const ALGEBRA: Algebra = Algebra::G3;
    const METHOD: Method = Method::Frame;
    const GUARANTEES: Guarantees = Guarantees { watertight: false, exact: false };
    const VARIANT: Option<&'static str> = None;

    fn prepare(&self, tri: &Triangle<T>) -> G3FrameCellPrim<T> {
        let frame = G3FramePrim::new(tri);
        G3FrameCellPrim { a: frame.a(), n: frame.n(), m_b: frame.m_b(), m_c: frame.m_c() }
    }

    #[inline(always)]
    fn prepare_ray(&self, _ray: &Ray<T>) {}

    #[inline(always)]
    fn intersect(
        &self,
        prim: &G3FrameCellPrim<T>,
        ray: &Ray<T>,
        _: &(),
        t_max: T,
    ) -> Option<TriangleHit<T>> {
        hit(candidate(prim, ray, t_max)?, t_max)
    }

    #[inline(always)]
    fn occludes(&self, prim: &G3FrameCellPrim<T>, ray: &Ray<T>, _: &(), t_max: T) -> bool {
        candidate(prim, ray, t_max).is_some_and(|c| occluded(&c, t_max))
    }
}

/// The four undivided values in GA types, then the frame method's decisions.
#[inline(always)]
fn candidate<T: Float>(prim: &G3FrameCellPrim<T>, ray: &Ray<T>, t_max: T) -> Option<Candidate<T>> {
    let G3FrameCellPrim { a, n, m_b, m_c } = *prim;
    let (s, u) = (a - Vector::from_array(ray.origin), Vector::from_array(ray.dir));
    let (num, den) = (s | n, u | n);
    let weight = |m: Vector<T>| num * (u | m) - den * (s | m);
    decide([num, den, weight(m_b), weight(m_c)], t_max)
}
