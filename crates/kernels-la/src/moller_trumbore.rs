//! Moller-Trumbore: T. Moller and B. Trumbore, "Fast, Minimum Storage Ray/Triangle
//! Intersection", Journal of Graphics Tools 2(1), 1997.
//!
//! # Derivation
//!
//! A point of the triangle is `a + u e1 + v e2` with `e1 = b - a`, `e2 = c - a`; a point of the
//! ray is `o + t d`. Equating them gives a 3x3 linear system in `(t, u, v)`:
//!
//! ```text
//! [-d  e1  e2] (t, u, v)^T = o - a =: s
//! ```
//!
//! Cramer's rule, with each 3x3 determinant written as a scalar triple product
//! `det[x y z] = (x x y) . z`, and the two cross products shared between the four
//! determinants:
//!
//! ```text
//! p   = d x e2          det = e1 . p          (det[-d e1 e2] = (d x e2) . e1)
//! q   = s x e1
//! u   = (s . p) / det   v = (d . q) / det     t = (e2 . q) / det
//! ```
//!
//! The paper computes `u`, tests it, then computes `q` and `v`, tests, then `t`: each test
//! rejects most rays before the next cross product is paid for. This file follows the
//! paper's non-culling variant (both faces hit, one reciprocal of `det`).
//!
//! # Choices
//!
//! - **No epsilon on `det`.** The paper rejects `|det| < EPSILON` with a fixed constant. `det`
//!   has the dimension length^2 x |d| (it is the triple product of `d`, `e1`, `e2`), so a fixed
//!   constant is a scale-dependent threshold: it rejects whole meshes modelled in millimetres
//!   and accepts near-parallel rays on meshes modelled in kilometres. Here only `det == 0`
//!   (ray exactly parallel to the plane as computed, or a degenerate triangle) and a
//!   non-finite `det` (NaN or infinite input) are rejected. A near-parallel ray then gives
//!   large `|u|`, `|v|` that fail the barycentric tests, or a finite hit that is as right as
//!   the rounding allows. Multiplying all coordinates by a power of two changes no answer.
//! - **Closed barycentric tests** `u >= 0`, `v >= 0`, `u + v <= 1`: points on edges count.
//!   Each is written so that NaN fails it (`!(u >= 0.0 && ...)`).
//! - **Degenerate triangles** (zero area, decided exactly in [`crate::is_degenerate`]) are
//!   stored with zero edges, so `det` is exactly 0 for every ray and they are never hit.
//!
//! # Why it is not watertight
//!
//! `u` and `v` are computed per triangle from that triangle's own `a`, `e1`, `e2`. For a ray
//! through an edge shared by two triangles, each triangle rounds its own (different)
//! expressions, so the two computed edge coordinates are not negatives of each other: both
//! can come out slightly outside (a crack, the ray passes between them) or both inside (the
//! edge is hit twice). The edge vectors `b - a` themselves are rounded, which makes this
//! worse far from the origin. See `tests/watertight.rs` for measured rates.

use core::marker::PhantomData;

use intersect::{Algebra, Guarantees, Intersector, Method, Ray, Triangle, TriangleHit};

use crate::{GlamReal, is_degenerate};

/// The Moller-Trumbore kernel (1997), without a scale-dependent epsilon.
///
/// Fast and small (one vertex and two edges per triangle, nothing per ray), but not
/// watertight: rays through shared edges can miss both triangles. See the
/// [module derivation](crate::moller_trumbore) and the [crate
/// table](crate#what-each-kernel-guarantees).
///
/// ```
/// use intersect::{Intersector, Ray, Triangle};
/// use kernels_la::MollerTrumbore;
///
/// let mt = MollerTrumbore::<f32>::new();
/// let prim = mt.prepare(&Triangle::new([0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [0.0, 2.0, 0.0]));
/// let ray = Ray::new([0.5, 0.5, 3.0], [0.0, 0.0, -1.0]);
/// let hit = mt.intersect(&prim, &ray, &(), f32::INFINITY).unwrap();
/// assert_eq!((hit.t, hit.u, hit.v), (3.0, 0.25, 0.25));
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct MollerTrumbore<T>(PhantomData<T>);

impl<T> MollerTrumbore<T> {
    /// The kernel (it has no state).
    #[must_use]
    pub const fn new() -> Self {
        Self(PhantomData)
    }
}

/// What [`MollerTrumbore`] keeps of a triangle: vertex `a` and edges `e1 = b - a`,
/// `e2 = c - a`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MtPrim<T: GlamReal> {
    a: T::V,
    e1: T::V,
    e2: T::V,
}

impl<T: GlamReal> Intersector for MollerTrumbore<T> {
    type Real = T;
    type Prim = MtPrim<T>;
    type RayData = ();
    type Block = ();
    const NAME: &'static str = "la-mt";
    const ALGEBRA: Algebra = Algebra::La;
    const METHOD: Method = Method::MollerTrumbore;
    const GUARANTEES: Guarantees = Guarantees { watertight: false, exact: false };
    const VARIANT: Option<&'static str> = None;

    fn prepare(&self, tri: &Triangle<T>) -> MtPrim<T> {
        let a = T::load(tri.a);
        if is_degenerate(tri) {
            // Zero edges make `det` exactly 0 for every ray: never hit.
            let zero = T::splat(T::ZERO);
            return MtPrim { a, e1: zero, e2: zero };
        }
        MtPrim { a, e1: T::load(tri.b) - a, e2: T::load(tri.c) - a }
    }

    #[inline(always)]
    fn prepare_ray(&self, _ray: &Ray<T>) {}

    #[inline]
    fn intersect(
        &self,
        prim: &MtPrim<T>,
        ray: &Ray<T>,
        _ray_data: &(),
        t_max: T,
    ) -> Option<TriangleHit<T>> {
        let dir = T::load(ray.dir);
        // det[-d e1 e2]: zero when the ray is parallel to the plane (as rounded). Rejecting
        // only exact zero (and NaN/infinity) keeps the test independent of the mesh's scale.
        let p = T::cross(dir, prim.e2);
        let det = T::dot(prim.e1, p);
        if det == T::ZERO || !det.is_finite() {
            return None;
        }
        let inv_det = T::ONE / det;

        let s = T::load(ray.origin) - prim.a;
        let u = T::dot(s, p) * inv_det;
        if !(u >= T::ZERO && u <= T::ONE) {
            return None;
        }

        let q = T::cross(s, prim.e1);
        let v = T::dot(dir, q) * inv_det;
        if !(v >= T::ZERO && u + v <= T::ONE) {
            return None;
        }

        // `t` can still overflow for a nearly parallel ray (tiny `det`); an infinite `t` is no
        // hit even when `t_max` is infinite.
        let t = T::dot(prim.e2, q) * inv_det;
        (t > T::ZERO && t <= t_max && t.is_finite()).then_some(TriangleHit { t, u, v })
    }
}
