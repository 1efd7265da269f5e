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
//! **Rejection from the ray first.** Seen from the ray origin, a distant triangle's vertices
//! are long vectors, nearly parallel to `u`, and `sa ∧ sb` is a small difference of large
//! products: in `f32`, for a mesh a few hundred triangle sizes from the eye, the rounding error
//! is as large as the value. Since adding a multiple of `u` to a factor does not change `∧ u`,
//! the kernel first takes each vertex's rejection from the ray direction (report 2.3.4,
//! `s⊥ = (s ∧ u) u⁻¹ = s - (s · u) u⁻¹`, with `u⁻¹ = u / |u|²` computed once per ray) and
//! computes `w_c = ((sa⊥ ∧ sb⊥) ∧ u)*` and so on. The rejected vectors are as long as the
//! vertices' distances from the ray, so the products are as small as the result.
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
//!    translated, rejected vertices `sa⊥`, `sb⊥` are each computed from one vertex and the
//!    ray, so two triangles that share an edge see the same numbers. The neighbour evaluates
//!    the edge as `(sb⊥ ∧ sa⊥) ∧ u`. Every component of `sb⊥ ∧ sa⊥` is `y - x` where
//!    `sa⊥ ∧ sb⊥` has `x - y`,
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
//!    `sa⊥`, `sb⊥`, `u`, which convert to `f64` exactly). Every sign used is then the exact
//!    sign of the same triple product of the same per-vertex points, for every triangle: the
//!    exact orientations of the vertices projected along `u`, a consistent planar picture of
//!    the mesh, so the triangles around a vertex cover its neighbourhood. Measured on the
//!    tile grid of `tests/watertight.rs` with the fallback disabled: no crack through edges,
//!    but about 1.5% of the rays aimed exactly at vertices passed between the triangles, in
//!    `f32` and in `f64`; with it, none.
//!
//! **Error bound.** Each component of `sa ∧ sb` is a difference of two rounded products, each
//! term of `(.) ∧ u` one more rounding, and the sum two more: the computed `w` is within
//! `γ5 Σk (|x_k| + |y_k|) |u_k| <= 15 ε M² |u|∞` of the exact value (`ε` the machine epsilon,
//! `γ5 = 5(ε/2) / (1 - 5ε/2)`, `M` the largest coordinate of the three rejected vertices,
//! `Σk (|x_k| + |y_k|) <= 6 M²`). The kernel uses `32 ε M² |u|∞` plus the smallest normal
//! number (for underflow), computed per test with `M` from the rejected vertices. Thanks to
//! the rejection the fallback is rare: it runs only for rays within about `100 ε` triangle
//! sizes of an edge line.
//!
//! # Cost per test
//!
//! 9 subtractions (translation), 3 rejections (an inner product and 3 multiply-adds each),
//! 3 edge bivectors (6 multiplies and 3 subtractions each) and their outer products with `u`
//! (3 multiplies, 2 additions each), the error bound (9 absolute values, 8 maxima,
//! 2 multiplies, 1 addition) and 3 comparisons against it, then the sign test; then the
//! distance (2 inner products) and, for a hit, one division. Counting a fused multiply-add as
//! one: 80 operations before the inside test (absolute values are bit operations), about 90
//! in all, against 24 for [`crate::Ga`]. The exact fallback (a few hundred operations) runs
//! only for rays within rounding distance of an edge line.

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

/// What [`GaPlucker`] computes once per ray: the inverse of the direction vector, for the
/// rejections, and the factor of the error bound.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PluckerRay<T> {
    /// `u⁻¹ = u / |u|²`.
    dir_inverse: Vector<T>,
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
    let dir = Vector::from_array(ray.dir);
    PluckerRay {
        dir_inverse: dir * dir.norm_squared().recip(),
        error_factor: T::from_f64(32.0) * T::EPSILON * dir.max_abs(),
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

    // Each vertex's rejection from the ray direction: s - (s · u) u⁻¹.
    let reject = |s: Vector<T>| {
        let along = -(s | dir);
        let inv = rd.dir_inverse;
        Vector::new(
            along.mul_add(inv.e1, s.e1),
            along.mul_add(inv.e2, s.e2),
            along.mul_add(inv.e3, s.e3),
        )
    };
    let (ra, rb, rc) = (reject(sa), reject(sb), reject(sc));

    // The edge trivectors, as their dual scalars; w_a is the edge opposite a, and so on.
    let mut w = [edge_value(rb, rc, dir), edge_value(rc, ra, dir), edge_value(ra, rb, dir)];

    // Values within the rounding error of zero get their exact sign.
    let m = largest_coordinate([ra, rb, rc]);
    let bound = error_bound(rd.error_factor, m);
    if !(w[0].abs() > bound && w[1].abs() > bound && w[2].abs() > bound) {
        w = exact_signs(w, [ra, rb, rc], dir, bound)?;
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

/// `((p ∧ q) ∧ u)*`, the edge value. Written with the algebra's products, which use separate
/// multiplies and adds: `edge_value(q, p, u) == -edge_value(p, q, u)` exactly.
#[inline(always)]
fn edge_value<T: Float>(p: Vector<T>, q: Vector<T>, dir: Vector<T>) -> T {
    ((p ^ q) ^ dir).e123
}

/// The error bound for the edge values of a triangle whose rejected vertices have largest
/// coordinate `m` (see the module documentation).
#[inline(always)]
fn error_bound<T: Float>(error_factor: T, m: T) -> T {
    error_factor * m * m + T::MIN_POSITIVE
}

/// The largest absolute coordinate of three vectors. Plain comparisons (no NaN rules): a NaN
/// coordinate makes the edge values NaN, which send the test to the exact path, which misses.
#[inline(always)]
fn largest_coordinate<T: Float>(vs: [Vector<T>; 3]) -> T {
    let larger = |x: T, y: T| if x > y { x } else { y };
    let mut m = T::ZERO;
    for v in vs {
        m = larger(m, larger(v.e1.abs(), larger(v.e2.abs(), v.e3.abs())));
    }
    m
}

/// Replaces each value of `w` whose magnitude is at most `bound` by one with the exact sign
/// of `(si ∧ sj) ∧ u` (`s` the rejected vertices); `None` (a miss) for non-finite input,
/// where no sign is meaningful.
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

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};
    use rand_pcg::Pcg64;

    fn vector<T: Float>(rng: &mut Pcg64, r: f64) -> Vector<T> {
        Vector::from_array([0; 3].map(|_| T::from_f64(rng.random_range(-r..r))))
    }

    fn sign(x: f64) -> i8 {
        if x > 0.0 {
            1
        } else if x < 0.0 {
            -1
        } else {
            0
        }
    }

    /// Swapping the edge's vertices negates the computed value exactly, for any inputs.
    fn edge_values_are_exactly_antisymmetric<T: Float>() {
        let mut rng = Pcg64::seed_from_u64(0x6a_3001);
        for _ in 0..100_000 {
            let (p, q, d) =
                (vector::<T>(&mut rng, 10.0), vector(&mut rng, 10.0), vector(&mut rng, 1.0));
            let (x, y) = (edge_value(p, q, d), edge_value(q, p, d));
            assert!(x == -y, "{x:?} {y:?} for {p:?} {q:?} {d:?}");
        }
    }

    /// Nearly coplanar `p, q, u` (`q = α p + β u + ε e` with `ε` down to `1e-20`): wherever
    /// the computed value is outside the error bound its sign is the exact one (Shewchuk's
    /// `orient3d`). Inside the bound, rounding does give wrong signs: the fallback is needed.
    fn error_bound_is_sound<T: Float>() {
        let mut rng = Pcg64::seed_from_u64(0x6a_3002);
        let (mut uncertain, mut wrong_when_uncertain) = (0, 0);
        for _ in 0..100_000 {
            let (d, p, e) =
                (vector::<T>(&mut rng, 1.0), vector(&mut rng, 1.0), vector(&mut rng, 1.0));
            let (alpha, beta) = (
                T::from_f64(rng.random_range(-2.0..2.0)),
                T::from_f64(rng.random_range(-2.0..2.0)),
            );
            let tiny = T::from_f64(10f64.powf(-rng.random_range(0.0..20.0)));
            let q = p * alpha + d * beta + e * tiny;
            let w = edge_value(p, q, d);
            let ray = Ray { origin: [T::ZERO; 3], dir: d.to_array() };
            let bound = error_bound(prepare_ray(&ray).error_factor, p.max_abs().max(q.max_abs()));
            let point =
                |v: Vector<T>| Coord3D { x: v.e1.to_f64(), y: v.e2.to_f64(), z: v.e3.to_f64() };
            let exact =
                sign(orient3d(point(p), point(q), point(d), Coord3D { x: 0.0, y: 0.0, z: 0.0 }));
            if w.abs() > bound {
                assert_eq!(sign(w.to_f64()), exact, "{w:?} > {bound:?} for {p:?} {q:?} {d:?}");
            } else {
                uncertain += 1;
                wrong_when_uncertain += usize::from(sign(w.to_f64()) != exact);
            }
        }
        eprintln!("{uncertain} uncertain, {wrong_when_uncertain} of them with a wrong sign");
        assert!(uncertain > 1_000, "the band is exercised: {uncertain}");
        assert!(wrong_when_uncertain > 0, "rounding gives wrong signs in the band");
    }

    #[test]
    fn edge_values_are_exactly_antisymmetric_in_both_precisions() {
        edge_values_are_exactly_antisymmetric::<f32>();
        edge_values_are_exactly_antisymmetric::<f64>();
    }

    #[test]
    fn error_bound_is_sound_in_both_precisions() {
        error_bound_is_sound::<f32>();
        error_bound_is_sound::<f64>();
    }
}
