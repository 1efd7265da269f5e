//! A watertight GA kernel: each edge is tested by the trivector it spans with the ray.
//!
//! # Derivation
//!
//! Translate the triangle so that the ray starts at the origin: `sa = a - o`, `sb = b - o`,
//! `sc = c - o`, each rounded once. For the edge from `sa` to `sb`, the trivector
//!
//! ```text
//! E_ab = (sa ∧ sb) ∧ u        (u the ray direction)
//! ```
//!
//! is the signed volume spanned by the edge bivector and the ray: zero when the ray's line
//! meets the edge's line, and its sign says on which side of the edge the ray passes. If the
//! ray meets the plane at `p = o + t u = a λa + b λb + c λc`, then `sa - t u = a - p`, and
//! adding a multiple of `u` to a factor does not change `∧ u`, so
//!
//! ```text
//! E_ab = ((a - p) ∧ (b - p)) ∧ u = λc ((b - a) ∧ (c - a)) ∧ u = λc (N ∧ u)
//! ```
//!
//! (`(a - p) ∧ (b - p)` is the bivector of the sub-triangle `a, b, p`, a `λc` share of the
//! whole triangle's `N`). Likewise `E_bc = λa (N ∧ u)`, `E_ca = λb (N ∧ u)`. Writing `w` for
//! the dual scalar `E*`: the ray passes through the closed triangle exactly when `w_a`,
//! `w_b`, `w_c` are all `>= 0` or all `<= 0` (both faces), and
//! `det = w_a + w_b + w_c = (N ∧ u)*` is the report's denominator `(u ∧ N)*`, so the
//! barycentrics are `u = w_b / det`, `v = w_c / det`.
//!
//! The distance is the plane's, as in [`crate::Ga`]: `t = (sa · n) / (u · n)` with the unit
//! normal `n = N* / |N|` precomputed, tested against `(0, t_max]` before the division. (It
//! could be had from the edge values alone, `t = (w_a sa + w_b sb + w_c sc) · u⁻¹ / det`, but
//! their rounding errors scale with the squared distance to the triangle, not its size; that
//! `t` is several times less accurate for distant triangles and costs more.)
//!
//! # Why it is watertight
//!
//! 1. **Shared edges.** `E_ab` depends only on the two vertices of the edge and the ray; the
//!    translated vertices `sa`, `sb` are each rounded from one vertex and the origin, so two
//!    triangles that share an edge see the same `sa`, `sb`. The neighbour evaluates the edge
//!    as `(sb ∧ sa) ∧ u`. Every component of `sb ∧ sa` is `y - x` where `sa ∧ sb` has `x - y`,
//!    with the same rounded products (multiplication commutes exactly), and IEEE rounding is
//!    symmetric, so `fl(y - x) = -fl(x - y)`; the outer product with `u` then sums exactly
//!    negated products. The neighbour's value is the exact negation, bit for bit (the kernel
//!    uses separate multiplies and adds, never a fused multiply-add, which would round the two
//!    orders differently). So the two triangles cannot both be on the outer side of the edge:
//!    a ray through the edge hits at least one of them (both, when the value is 0). If the
//!    neighbour is wound the other way it computes the same value, not its negation, and
//!    accepts the other sign instead: the conclusion is the same.
//! 2. **Shared vertices.** Near a vertex all of the edges meeting there give values near 0,
//!    where rounding may give a wrong sign, and consistent-but-wrong signs around a fan could
//!    leave a crack. So each value whose magnitude is within the rounding error bound below is
//!    recomputed with its exact sign (Shewchuk's adaptive `orient3d` on the same rounded
//!    `sa`, `sb`, `u`, which converts to `f64` exactly). Every sign used is then the exact
//!    sign of the same triple product of the same per-vertex points, for every triangle: the
//!    triangles around a vertex cover its neighbourhood exactly as the rounded mesh does.
//!
//! **Error bound.** Each component of `sa ∧ sb` is a difference of two rounded products, each
//! term of `(.) ∧ u` one more rounding, and the sum two more: the computed `w` is within
//! `γ5 Σk (|x_k| + |y_k|) |u_k| <= 15 ε M² |u|∞` of the exact value (`ε` the machine epsilon,
//! `γ5 = 5(ε/2) / (1 - 5ε/2)`, `M` the largest coordinate of the three translated vertices,
//! `Σk (|x_k| + |y_k|) <= 6 M²`). The kernel uses `32 ε M² |u|∞` plus the smallest normal
//! number (for underflow), computed per test with `M` from the translated vertices.
//!
//! # Cost per test
//!
//! 9 subtractions (translation), 3 edge bivectors (6 multiplies and 3 subtractions each) and
//! their outer products with `u` (3 multiplies, 2 additions each), the error bound (9 absolute
//! values, 8 maxima, 2 multiplies, 1 addition) and 3 comparisons against it, then the sign
//! test; then the distance (2 inner products) and, for a hit, one division. About 70
//! operations before the inside test, against 21 in all for [`crate::Ga`]. The exact
//! fallback (a few hundred operations) runs only for rays within rounding distance of an edge
//! line.

use core::marker::PhantomData;

use ga::g3::Vector;
use intersect::{Intersector, Ray, Triangle, TriangleHit};
use robust::{Coord3D, orient3d};

use crate::real::private::Float;
use crate::{GaReal, is_degenerate};

/// The watertight GA kernel (`NAME = "ga-plucker"`): edge tests are trivectors
/// `((vi - o) ∧ (vj - o)) ∧ u`, exactly antisymmetric, with exact signs near zero.
///
/// See the [module derivation](self) and the [crate table](crate#the-kernels).
///
/// ```
/// use intersect::{Intersector, Ray, Triangle};
/// use ga_tracer::GaPlucker;
///
/// // Two triangles sharing the edge from (1, 0, 0) to (0, 1, 0).
/// let left = Triangle::new([0.0f32, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
/// let right = Triangle::new([1.0f32, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]);
/// let k = GaPlucker::<f32>::new();
/// // A ray aimed at a point of the shared edge hits at least one of them.
/// let ray = Ray::new([0.3f32, 0.7, 1.0], [0.0, 0.0, -1.0]);
/// let rd = k.prepare_ray(&ray);
/// let hits = [left, right].map(|tri| k.intersect(&k.prepare(&tri), &ray, &rd, f32::INFINITY));
/// assert!(hits.iter().any(Option::is_some));
/// assert_eq!(hits.iter().flatten().next().unwrap().t, 1.0);
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct GaPlucker<T>(PhantomData<T>);

impl<T> GaPlucker<T> {
    /// The kernel (it has no state).
    #[must_use]
    pub const fn new() -> Self {
        Self(PhantomData)
    }
}

/// What [`GaPlucker`] keeps of a triangle: its three vertices, which the edge tests use as
/// they are (two triangles sharing a vertex must see the same numbers), and the unit normal
/// for the distance (12 scalars).
///
/// A degenerate triangle is stored as three copies of `a` with a zero normal: every edge
/// bivector is then exactly zero, and so is `u · n`, for every ray.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PluckerPrim<T> {
    a: Vector<T>,
    b: Vector<T>,
    c: Vector<T>,
    n: Vector<T>,
}

/// What [`GaPlucker`] computes once per ray: the factor of the error bound.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PluckerRay<T> {
    /// `32 ε |u|∞`: times `M²` it bounds the rounding error of an edge value.
    error_factor: T,
}

impl<T: GaReal> Intersector for GaPlucker<T> {
    type Real = T;
    type Prim = PluckerPrim<T>;
    type RayData = PluckerRay<T>;
    const NAME: &'static str = "ga-plucker";

    fn prepare(&self, tri: &Triangle<T>) -> PluckerPrim<T> {
        let [a, b, c] = if is_degenerate(tri) { [tri.a; 3] } else { tri.vertices() };
        PluckerPrim {
            a: Vector::from_array(a),
            b: Vector::from_array(b),
            c: Vector::from_array(c),
            n: unit_normal(tri),
        }
    }

    #[inline]
    fn prepare_ray(&self, ray: &Ray<T>) -> PluckerRay<T> {
        prepare_ray(ray)
    }

    #[inline]
    fn intersect(
        &self,
        prim: &PluckerPrim<T>,
        ray: &Ray<T>,
        rd: &PluckerRay<T>,
        t_max: T,
    ) -> Option<TriangleHit<T>> {
        intersect(prim, ray, rd, t_max)
    }
}

#[inline]
fn prepare_ray<T: Float>(ray: &Ray<T>) -> PluckerRay<T> {
    PluckerRay {
        error_factor: T::from_f64(32.0) * T::EPSILON * Vector::from_array(ray.dir).max_abs(),
    }
}

#[inline]
fn intersect<T: Float>(
    prim: &PluckerPrim<T>,
    ray: &Ray<T>,
    rd: &PluckerRay<T>,
    t_max: T,
) -> Option<TriangleHit<T>> {
    let o = Vector::from_array(ray.origin);
    let dir = Vector::from_array(ray.dir);
    let (sa, sb, sc) = (prim.a - o, prim.b - o, prim.c - o);

    // The edge trivectors, as their dual scalars; w_a is the edge opposite a, and so on.
    let mut w = [((sb ^ sc) ^ dir).e123, ((sc ^ sa) ^ dir).e123, ((sa ^ sb) ^ dir).e123];

    // Values within the rounding error of zero get their exact sign.
    let m = max3(sa.max_abs(), sb.max_abs(), sc.max_abs());
    let bound = rd.error_factor * m * m + T::MIN_POSITIVE;
    if !(w[0].abs() > bound && w[1].abs() > bound && w[2].abs() > bound) {
        w = exact_signs(w, [sa, sb, sc], dir, bound)?;
    }

    // Inside (both faces, closed edges): no two values of opposite signs.
    let [w_a, w_b, w_c] = w;
    let any_negative = w_a < T::ZERO || w_b < T::ZERO || w_c < T::ZERO;
    let any_positive = w_a > T::ZERO || w_b > T::ZERO || w_c > T::ZERO;
    if any_negative && any_positive {
        return None;
    }
    let det = w_a + w_b + w_c;
    if det == T::ZERO {
        return None;
    }

    // t = (sa · n) / (u · n), tested before dividing (see `Ga`).
    let num = sa | prim.n;
    let den = dir | prim.n;
    let num_s = num.xor_sign(den);
    let slack = T::ONE + T::EPSILON * T::from_f64(4.0);
    if !(num_s > T::ZERO && num_s <= t_max * den.abs() * slack) {
        return None;
    }
    let t = num / den;
    let inv_det = T::ONE / det;
    (t > T::ZERO && t <= t_max && t.is_finite()).then(|| TriangleHit {
        t,
        u: w_b * inv_det,
        v: w_c * inv_det,
    })
}

/// `N* / |N|` for `N = (b - a) ∧ (c - a)`, computed in `f64` and rounded once; zero for a
/// degenerate triangle.
fn unit_normal<T: GaReal>(tri: &Triangle<T>) -> Vector<T> {
    if is_degenerate(tri) {
        return Vector::ZERO;
    }
    let [a, b, c] = tri.vertices().map(|p| Vector::from_array(p.map(ga::Scalar::to_f64)));
    let n = ((b - a) ^ (c - a)).dual().normalize();
    Vector::from_array(n.to_array().map(ga::Scalar::from_f64))
}

fn max3<T: Float>(x: T, y: T, z: T) -> T {
    x.max(y).max(z)
}

/// Replaces each value of `w` whose magnitude is at most `bound` by one with the exact sign
/// of `(si ∧ sj) ∧ u`; `None` (a miss) for non-finite input, where no sign is meaningful.
#[cold]
#[inline(never)]
fn exact_signs<T: Float>(
    mut w: [T; 3],
    s: [Vector<T>; 3],
    dir: Vector<T>,
    bound: T,
) -> Option<[T; 3]> {
    if !(s.iter().all(|v| v.is_finite()) && dir.is_finite()) {
        return None;
    }
    let point = |v: Vector<T>| Coord3D { x: v.e1.to_f64(), y: v.e2.to_f64(), z: v.e3.to_f64() };
    let zero = Coord3D { x: 0.0, y: 0.0, z: 0.0 };
    // orient3d(p, q, r, 0) is det[p q r] = ((p ∧ q) ∧ r)*, exactly signed.
    let trusted = |w: T| w.abs() > bound;
    for (k, wk) in w.iter_mut().enumerate() {
        if !trusted(*wk) {
            let (i, j) = ((k + 1) % 3, (k + 2) % 3);
            *wk = T::from_f64_keep_sign(orient3d(point(s[i]), point(s[j]), point(dir), zero));
        }
    }
    Some(w)
}
