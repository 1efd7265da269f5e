//! The frame method in CGA (precomputed plane and reciprocal frame: Havel and Herout 2010,
//! Baldwin and Weber 2016): the frame/CGA cell, the twin of `la-frame`
//! (`kernels_la::Frame`) and `g3-frame`, with the plane and the frame as dual planes.
//!
//! # Derivation
//!
//! In CGA a dual plane `π = m + δ e∞` evaluates an affine function of the points: for
//! `X = up(x)`, `X · π = x · m - δ` (`eₒ · e∞ = -1`, `e∞ · m = e∞ · e∞ = 0`). The frame
//! method is three such functions of the point where the ray meets the triangle's plane:
//! the plane itself `ν` (`n` the unit normal) and the two dual planes `μ_b`, `μ_c` through
//! the edges `ac` and `ab` whose values at `x` are the barycentrics `u` and `v`
//! (`m_b = (e2 × N) / |N|²`, `m_c = (N × e1) / |N|²`, the reciprocal frame of `e1`, `e2` in
//! the plane). All three pass through `a`, so in the frame translated to `a` (where every
//! cell measures, see [`crate`], "Precision") they have `δ = 0`.
//!
//! The ray `o + t d` in that frame is the point `O = eₒ + (o - a)` (equal to `up(o - a)` in
//! every product used here, because `ν`, `μ_b`, `μ_c` have no `eₒ` part: the `½x² e∞` term
//! of `up` meets only their zero `e4`, `e5` coefficients) and the direction `D = d`,
//! `D · e∞ = 0`. With `s = a - o`:
//!
//! ```text
//! num = -(O · ν) = s · n            den = D · ν = d · n          t = num / den
//! U   = num (D · μ_b) - den (-(O · μ_b))     V likewise with μ_c     u = U / den, v = V / den
//! ```
//!
//! (`u = μ_b · (o + t d - a)` multiplied by `den`), `la-frame`'s undivided values.
//!
//! # Decisions, per-triangle data, cost
//!
//! `la-frame`'s, in its order: the three edge values `U σ`, `V σ`, `|den| - (U + V) σ`
//! (`σ` the sign of `den`) in one branch (closed edges, NaN outside), then
//! `0 < num σ <= t_max |den| (1 + 4ε)` before the division, one reciprocal, and
//! `0 < t <= t_max`, `t` finite. No tie rule, not watertight.
//!
//! - Per triangle: `a` and `ν`, `μ_b`, `μ_c` (computed in `f64` from the vertices, rounded
//!   once) as four five-coefficient [`Vector`]s, the `e4`, `e5` coefficients zero (`δ = 0`
//!   in the frame at `a`) but stored because the type has them: 80 B in `f32`, 160 B in `f64`
//!   (`la-frame`: 64 B and 96 B). Degenerate triangles get zero planes: `den = 0`, and the
//!   distance test fails.
//! - Per ray: nothing.
//! - Per test: one five-coefficient subtraction (`o - a`), the point `O` (two additions of
//!   `eₒ`'s `∓½`), 6 inner products `Vector | Vector` (5 multiplies and 4 additions each as
//!   generated: the two terms on `e4`, `e5` multiply zero coefficients, which IEEE arithmetic
//!   does not let the compiler drop), 4 multiplies and 2 subtractions for `U`, `V`, then
//!   `la-frame`'s edge and distance tests and, for a hit, a reciprocal and 3 multiplies.

use core::marker::PhantomData;

use ga::Scalar;
use ga::cga::Vector;
use intersect::{Algebra, Guarantees, Intersector, Method, Ray, Real, Triangle, TriangleHit};

use kernels_g3::frame::{decide, hit, occluded};

use crate::flat::{point, vector};
use crate::{cross64, is_degenerate, round64};

/// The frame method with dual planes (`NAME = "cga-frame"`).
///
/// See the [module derivation](self).
///
/// ```
/// use intersect::{Intersector, Ray, Triangle};
/// use kernels_cga::CgaFrame;
///
/// let k = CgaFrame::<f64>::new();
/// let prim = k.prepare(&Triangle::new([0.0, 0.0, 2.0], [4.0, 0.0, 2.0], [0.0, 4.0, 2.0]));
/// let hit = k.intersect(&prim, &Ray::new([1.0, 2.0, -1.0], [0.0, 0.0, 1.0]), &(), 9.0);
/// let hit = hit.unwrap();
/// assert_eq!((hit.t, hit.u, hit.v), (3.0, 0.25, 0.5));
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct CgaFrame<T>(PhantomData<T>);

impl<T> CgaFrame<T> {
    /// The kernel (it has no state).
    #[must_use]
    pub const fn new() -> Self {
        Self(PhantomData)
    }
}

/// What [`CgaFrame`] keeps of a triangle: vertex `a`, and the dual planes `ν` (the
/// triangle's, unit normal), `μ_b`, `μ_c` (the reciprocal frame) through `a`, in the frame
/// translated to `a`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct CgaFramePrim<T> {
    a: Vector<T>,
    nu: Vector<T>,
    mu_b: Vector<T>,
    mu_c: Vector<T>,
}

impl<T: Scalar> Intersector for CgaFrame<T> {
    type Real = T;
    type Prim = CgaFramePrim<T>;
    type RayData = ();
    type Block = ();
    const NAME: &'static str = "cga-frame";
    const ALGEBRA: Algebra = Algebra::Cga;
    const METHOD: Method = Method::Frame;
    const GUARANTEES: Guarantees = Guarantees { watertight: false, exact: false };
    const VARIANT: Option<&'static str> = None;

    fn prepare(&self, tri: &Triangle<T>) -> CgaFramePrim<T> {
        let a = vector(tri.a);
        if is_degenerate(tri) {
            let zero = Vector::ZERO;
            return CgaFramePrim { a, nu: zero, mu_b: zero, mu_c: zero };
        }
        let [a64, b64, c64] = tri.vertices().map(|p| p.map(Real::to_f64));
        let sub = |p: [f64; 3], q: [f64; 3]| [p[0] - q[0], p[1] - q[1], p[2] - q[2]];
        let (e1, e2) = (sub(b64, a64), sub(c64, a64));
        let normal = cross64(e1, e2);
        let area2 = normal.iter().map(|x| x * x).sum::<f64>();
        let (inv_len, inv_area2) = (area2.sqrt().recip(), area2.recip());
        let plane = |m: [f64; 3], scale: f64| vector(round64(m.map(|x| x * scale)));
        CgaFramePrim {
            a,
            nu: plane(normal, inv_len),
            mu_b: plane(cross64(e2, normal), inv_area2),
            mu_c: plane(cross64(normal, e1), inv_area2),
        }
    }

    #[inline(always)]
    fn prepare_ray(&self, _ray: &Ray<T>) {}

    #[inline(always)]
    fn intersect(
        &self,
        prim: &CgaFramePrim<T>,
        ray: &Ray<T>,
        _: &(),
        t_max: T,
    ) -> Option<TriangleHit<T>> {
        hit(decide(undivided(prim, ray), t_max)?, t_max)
    }

    #[inline(always)]
    fn occludes(&self, prim: &CgaFramePrim<T>, ray: &Ray<T>, _: &(), t_max: T) -> bool {
        decide(undivided(prim, ray), t_max).is_some_and(|c| occluded(&c, t_max))
    }
}

/// The undivided `[num, den, U, V]` of the derivation, from the dual planes; the decisions
/// on them (the edges as one branch, then `0 < t <= t_max` before the division, loosened by
/// 4 ulps of 1) are `la-frame`'s and `g3-frame`'s, in the shared
/// [`kernels_g3::frame::decide`].
#[inline(always)]
fn undivided<T: Scalar>(prim: &CgaFramePrim<T>, ray: &Ray<T>) -> [T; 4] {
    let CgaFramePrim { a, nu, mu_b, mu_c } = *prim;
    let (o, d) = (point(vector(ray.origin) - a), vector(ray.dir));
    // -(O · π) = π's value at a - o: the dual planes evaluated at the ray's origin.
    let (num, den) = (-(o | nu), d | nu);
    let u = num * (d | mu_b) - den * -(o | mu_b);
    let v = num * (d | mu_c) - den * -(o | mu_c);
    [num, den, u, v]
}
