//! A watertight GA kernel: each edge is tested by the trivector it spans with the ray.
//!
//! # Derivation
//!
//! Translate the triangle so that the ray starts at the origin: `sa = a - o`, `sb = b - o`,
//! `sc = c - o`. For the edge from `sa` to `sb`, the trivector
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
//! the dual scalars `E*`: the ray passes through the closed triangle exactly when `w_a`, `w_b`,
//! `w_c` are all `>= 0` or all `<= 0` (both faces), and `det = w_a + w_b + w_c = (N ∧ u)*` is
//! the report's denominator `(u ∧ N)*`, so the barycentrics are `u = w_b / det`,
//! `v = w_c / det`. A value that is exactly zero (the ray's line meets the edge's line) is
//! decided by the tie rule below, so that a ray exactly through a shared edge or vertex hits
//! exactly one triangle.
//!
//! **Evaluating the trivector in the plane of the ray's dual.** Since adding a multiple of `u`
//! to a factor does not change `∧ u`, only the parts of `sa`, `sb` in the plane `D = û*`
//! orthogonal to the ray count (their rejections from `u`, report 2.3.4). Once per ray the
//! kernel picks an orthonormal basis `ex`, `ey` of `D`, oriented so that `ex ∧ ey ∧ û = I`
//! ([`G3WatertightRay`]); each vertex then has two coordinates `x = s · ex`, `y = s · ey`, the
//! bivector of two projected vertices is `(xa yb - ya xb) ex ∧ ey`, and
//!
//! ```text
//! w_c = ((sa ∧ sb) ∧ û)* = xa yb - ya xb          (and cyclically w_a, w_b)
//! ```
//!
//! Two products and a subtraction instead of the 14 operations of the full outer products,
//! and on coordinates as large as the vertices' distances from the ray, not their distances
//! from the origin: a distant triangle's `sa`, `sb` are long and nearly parallel to `u`, and
//! `(sa ∧ sb) ∧ u` computed in 3D is a small difference of large products whose rounding
//! error, in `f32`, is as large as the value.
//!
//! The distance is the plane's, as in [`crate::G3Frame`]: `t = (sa · n) / (u · n)` with the unit
//! normal `n = N* / |N|` precomputed, tested against `(0, t_max]` before the division. (It
//! could be had from the edge values, `t = (w_a sa + w_b sb + w_c sc) · u / (det |u|²)`, but
//! their rounding errors grow with the squared distance to the triangle, not its size.)
//!
//! # Why it is watertight
//!
//! Two triangles that share a vertex see the same `x`, `y` for it: they are computed from that
//! vertex and the ray alone.
//!
//! 1. **Shared edges: exact antisymmetry.** The neighbour across the edge from `a` to `b`
//!    evaluates it from the other end, `xb ya - yb xa`: the same two rounded products
//!    (multiplication commutes exactly) subtracted in the other order, and IEEE rounding is
//!    symmetric, so it gets exactly `-w_c`, bit for bit. The two triangles cannot both find
//!    the ray on their outer side. (If the neighbour is wound the other way it computes the
//!    same value and accepts the other sign: the same conclusion.) The kernel multiplies and
//!    subtracts separately: a fused multiply-add would round the two orders differently.
//! 2. **Shared vertices: exact signs.** Antisymmetry alone is not enough at a vertex, where
//!    all the edges meeting there give values near 0: consistent but wrong signs around a fan
//!    can leave a crack. An earlier version that evaluated `(sa ∧ sb) ∧ u` with the 3D outer
//!    products (exactly antisymmetric too, but with rounded signs) did: about 1.5% of the
//!    rays aimed exactly at vertices of the tile grid in `tests/watertight.rs` passed
//!    through, in `f32` and `f64`, though none of those aimed at edges. Here the sign is exact:
//!    rounding is monotonic, so `xa yb > ya xb` implies `fl(xa yb) >= fl(ya xb)`, and a non-zero
//!    computed difference has the exact sign of `xa yb - ya xb` for the rounded coordinates. An
//!    exact zero may hide either sign, so then all three values are recomputed exactly (Shewchuk's
//!    adaptive `orient2d`, on coordinates that convert to `f64` exactly). Every sign used is then
//!    the exact orientation of the same projected points, a consistent planar picture of the mesh
//!    seen along the ray, so the triangles around a vertex cover its neighbourhood. The tests find
//!    no crack, through edges or vertices, near the origin or `1e3` grid sizes away from it.
//! 3. **Ties: exactly one owner.** A ray exactly through an edge (an exact zero) would hit
//!    both closed neighbours. Instead a zero gets the sign it would have if the ray were
//!    moved by the infinitesimal `δ = ε ex + ε² ey` (`ε → 0+`; a symbolic perturbation, as in
//!    Edelsbrunner and Mücke's simulation of simplicity, or rasterisation's top-left rule).
//!    Moving the ray by `δ` moves every projected vertex by `-δ`:
//!
//!    ```text
//!    w(δ) = (px - ε)(qy - ε²) - (py - ε²)(qx - ε) = w + ε (py - qy) + ε² (qx - px)
//!    ```
//!
//!    (the `ε³` terms cancel), so a zero takes the sign of `py - qy`, or if that is 0 of
//!    `qx - px` (a difference of two floats is 0 only when they are equal: exact sign); if
//!    both are 0 the edge is parallel to the ray and the triangle, of zero projected area,
//!    is missed. The neighbour evaluates the edge from `q` to `p` and gets the opposite tie
//!    sign (if it is wound the other way, the same sign and the other orientation), so exactly
//!    one of them owns the edge; around a vertex every sign is the exact sign at one
//!    perturbed point, which lies in exactly one triangle of the fan. The rule runs only after
//!    an exact zero, off the common path.
//!
//! This is the watertight test of Woop, Benthin and Wald (2013) written in the algebra: they
//! project along the ray onto a coordinate plane by a shear (cheaper: no square root per ray,
//! one coordinate less per vertex); here the projection is orthogonal, onto the plane `D` in
//! an orthonormal basis.
//!
//! # Cost per test
//!
//! On scalars: 9 subtractions (translation), 6 inner products for the coordinates (18
//! operations with fused multiply-adds), 3 edge values (2 multiplies and a subtraction each),
//! the sign test (the outside test, then 3 comparisons with zero for the fallback), the
//! distance (2 inner products, 2 multiplies, 2 comparisons) and, for a hit, one division and 2
//! more: about 45 operations. [`G3WatertightPrim`] stores the triangle by axis, one vertex per
//! lane, so on four lanes (x86-64 with AVX2 and FMA, as this workspace builds) the translation is 3
//! vector subtractions, the coordinates of all three vertices 6 vector operations, and the
//! three edge values 4 lane rotations, 2 multiplies and 1 subtraction, each lane computing
//! exactly the scalar expression, so every argument below holds lane by lane
//! (`src/lanes.rs`). The outside test, which ends nearly every test, comes first: one
//! branch on `w_b` or `w_c` times `w_a`'s sign (`±1`, exact) being below zero, and a
//! predictable one on `w_a` being neither zero nor NaN. A value below zero is not zero or
//! NaN either, so two edge values of exact, opposite signs put the ray outside, whatever the
//! third. Only then are the three values checked for zeros (the fallback). About 25
//! operations before the distance test, against 24 for [`crate::G3Frame`]. Per ray: an orthonormal
//! basis (a square root and two divisions).
//!
//! The four-lane form, the one-branch sign test and the outside test first were each kept
//! because they measured faster; the figures are in `results/README.md` ("Kernel design
//! experiments").

use core::marker::PhantomData;

use ga::g3::Vector;
use intersect::{Algebra, Guarantees, Intersector, Method, Ray, Triangle, TriangleHit};
use robust::{Coord, orient2d};

use crate::lanes;
use crate::real::private::Float;
use crate::{GaReal, is_degenerate};

/// The watertight GA kernel (`NAME = "ga-plucker"`): edge tests are the trivectors
/// `((vi - o) ∧ (vj - o)) ∧ u`, exactly antisymmetric and exactly signed.
///
/// Its per-test code is hand four-lane SIMD over the triangle's rows, so it is a labelled
/// variant ([`VARIANT`](Intersector::VARIANT)) beside the watertight/G3 cell, not the cell.
///
/// See the [module derivation](self) and the [crate table](crate#the-kernels).
///
/// ```
/// use intersect::{Intersector, Ray, Triangle};
/// use kernels_g3::G3Watertight;
///
/// // Two triangles sharing the edge from (1, 0, 0) to (0, 1, 0).
/// let left = Triangle::new([0.0f32, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
/// let right = Triangle::new([1.0f32, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]);
/// let k = G3Watertight::<f32>::new();
/// // A ray aimed at a point of the shared edge hits exactly one of them.
/// let ray = Ray::new([0.5f32, 0.5, 1.0], [0.0, 0.0, -1.0]);
/// let rd = k.prepare_ray(&ray);
/// let hits = [left, right].map(|tri| k.intersect(&k.prepare(&tri), &ray, &rd, f32::INFINITY));
/// assert_eq!(hits.iter().flatten().count(), 1);
/// assert_eq!(hits.iter().flatten().next().unwrap().t, 1.0);
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct G3Watertight<T>(PhantomData<T>);

impl<T> G3Watertight<T> {
    /// The kernel (it has no state).
    #[must_use]
    pub const fn new() -> Self {
        Self(PhantomData)
    }
}

/// What [`G3Watertight`] keeps of a triangle: its three vertices, which the edge tests use as
/// they are (two triangles sharing a vertex must see the same numbers), and the unit normal
/// for the distance (12 scalars), stored by axis: `axes[k]` is `(a_k, b_k, c_k, n_k)`, so the
/// three vertices are projected at once, one vertex per lane.
///
/// A degenerate triangle is stored as three copies of `a` with a zero normal: every edge
/// value is then exactly zero, and so is `u · n`, for every ray.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[repr(C, align(16))]
pub struct G3WatertightPrim<T> {
    axes: [[T; 4]; 3],
}

/// What [`G3Watertight`] computes once per ray: an orthonormal basis `ex`, `ey` of the plane
/// `D = û*` orthogonal to the ray, with `ex ∧ ey ∧ û = I` (so that a vertex's coordinates in
/// it give the edge trivectors with their signs).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct G3WatertightRay<T> {
    pub(crate) ex: Vector<T>,
    pub(crate) ey: Vector<T>,
}

impl<T: GaReal> Intersector for G3Watertight<T> {
    type Real = T;
    type Prim = G3WatertightPrim<T>;
    type RayData = G3WatertightRay<T>;
    type Block = ();
    const NAME: &'static str = "ga-plucker";
    const ALGEBRA: Algebra = Algebra::G3;
    const METHOD: Method = Method::Watertight;
    const GUARANTEES: Guarantees = Guarantees { watertight: true, exact: false };
    const VARIANT: Option<&'static str> = Some("hand four-lane SIMD over arrays");

    fn prepare(&self, tri: &Triangle<T>) -> G3WatertightPrim<T> {
        let [a, b, c] = if is_degenerate(tri) { [tri.a; 3] } else { tri.vertices() };
        let n = unit_normal(tri).to_array();
        G3WatertightPrim { axes: core::array::from_fn(|k| [a[k], b[k], c[k], n[k]]) }
    }

    #[inline]
    fn prepare_ray(&self, ray: &Ray<T>) -> G3WatertightRay<T> {
        prepare_ray(ray)
    }

    #[inline]
    fn intersect(
        &self,
        prim: &G3WatertightPrim<T>,
        ray: &Ray<T>,
        rd: &G3WatertightRay<T>,
        t_max: T,
    ) -> Option<TriangleHit<T>> {
        intersect(prim, ray, rd, t_max)
    }
}

/// An orthonormal basis of the plane orthogonal to `û = u / |u|`, right-handed with `û`.
///
/// With `σ = ±1` the sign of `û₃` and `k = -1 / (σ + û₃)`:
/// `ex = (1 + σ k û₁², σ k û₁ û₂, -σ û₁)`, `ey = (k û₁ û₂, σ + k û₂², -û₂)`. Both are unit and
/// orthogonal to `û` and to each other (expand, using `û₁² + û₂² + û₃² = 1`), and
/// `ex ∧ ey = û I`, so `ex ∧ ey ∧ û = I`. No branch, and no cancellation: `|σ + û₃| >= 1`.
/// A zero or non-finite direction gives non-finite vectors, and every test then misses.
#[inline]
pub(crate) fn prepare_ray<T: Float>(ray: &Ray<T>) -> G3WatertightRay<T> {
    let dir = Vector::from_array(ray.dir);
    let n = dir * dir.norm().recip();
    let sigma = T::ONE.copy_sign(n.e3);
    let k = -(sigma + n.e3).recip();
    let xy = k * n.e1 * n.e2;
    G3WatertightRay {
        ex: Vector::new(T::ONE + sigma * k * n.e1 * n.e1, sigma * xy, -sigma * n.e1),
        ey: Vector::new(xy, sigma + k * n.e2 * n.e2, -n.e2),
    }
}

#[inline]
fn intersect<T: Float>(
    prim: &G3WatertightPrim<T>,
    ray: &Ray<T>,
    rd: &G3WatertightRay<T>,
    t_max: T,
) -> Option<TriangleHit<T>> {
    // Each vertex's coordinates in the plane orthogonal to the ray (one vertex per lane), and
    // the edge trivectors as their dual scalars: w_a is the edge opposite a, and so on.
    let [x, y, w] =
        T::edge_trivectors(&prim.axes, &ray.origin, &rd.ex.to_array(), &rd.ey.to_array());
    let w = decide_edges([w[0], w[1], w[2]], || [[x[0], y[0]], [x[1], y[1]], [x[2], y[2]]])?;

    // t = (sa · n) / (u · n), tested before dividing (see `G3Frame`).
    // Lane 3 of the rows is the normal, lane 0 the vertex a.
    let n = lanes::lane(&prim.axes, 3);
    let num = dot(lanes::lane(&prim.axes, 0) - Vector::from_array(ray.origin), n);
    let den = dot(Vector::from_array(ray.dir), n);
    finish(w, num, den, t_max)
}

/// The edge decisions of the method, in its order, on the three edge values `w` (`w[j]` the
/// edge opposite vertex `j`), with `points` the vertices' coordinates in the plane orthogonal
/// to the ray for the exact fallback: the values to divide by, or `None` (outside). Shared
/// by the watertight/G3 cell ([`crate::G3WatertightCell`]) and the watertight/CGA cell
/// (`kernels_cga::CgaWatertight`): the same decisions and tie rule along the row.
#[inline(always)]
pub fn decide_edges<T: ga::Scalar>(
    w: [T; 3],
    points: impl FnOnce() -> [[T; 2]; 3],
) -> Option<[T; 3]> {
    // An exact zero may hide either sign (and NaN has none): those are decided exactly, with
    // the tie rule for exact zeros, and `inside_exact` also makes the inside test.
    let decided = |x: T| x.abs() > T::ZERO;
    // Outside, the case of nearly every triangle tested, first: `w_b` or `w_c` is below zero
    // once multiplied by `w_a`'s sign (exact: a product with ±1). A value below zero is
    // neither zero nor NaN, so with `w_a` decided too, two values of exact, opposite signs
    // prove the miss, whatever the third. The compiler combines the two comparisons into one
    // branch, and checks `w_a` in a second that the predictor gets right (it is zero or NaN
    // almost never). A branch per comparison would be a coin toss each (see `G3Frame`'s module
    // documentation, where an OR of three comparisons was split into such a chain).
    let sign = T::ONE.copy_sign(w[0]);
    if ((w[1] * sign < T::ZERO) | (w[2] * sign < T::ZERO)) & decided(w[0]) {
        return None;
    }
    if decided(w[0]) & decided(w[1]) & decided(w[2]) {
        // Inside (both faces): three non-zero values of one sign.
        Some(w)
    } else {
        inside_exact(points())
    }
}

/// The rest of the method after the edges: `det`, the distance `t = num / den` tested before
/// dividing, then the barycentrics `w_b / det`, `w_c / det`.
#[inline(always)]
pub fn finish<T: ga::Scalar>(
    [w_a, w_b, w_c]: [T; 3],
    num: T,
    den: T,
    t_max: T,
) -> Option<TriangleHit<T>> {
    let det = w_a + w_b + w_c;
    if det == T::ZERO {
        return None;
    }
    let num_s = num * T::ONE.copy_sign(den);
    let slack = T::ONE + T::EPSILON * T::from_f64(4.0);
    if !(num_s > T::ZERO && num_s <= t_max * den.abs() * slack) {
        return None;
    }
    let t = num / den;
    let inv_det = T::ONE / det;
    // A non-finite `det` (edge values overflowed, or inf - inf) would give NaN or meaningless
    // barycentrics: a miss. Checked only for a hit.
    (t > T::ZERO && t <= t_max && t.is_finite() && det.is_finite()).then(|| TriangleHit {
        t,
        u: w_b * inv_det,
        v: w_c * inv_det,
    })
}

/// `((p ∧ q) ∧ û)*` from the coordinates of `p`, `q` in the plane orthogonal to the ray:
/// `px qy - py qx`, with separate multiplies and a subtraction, so that
/// `edge_value(q, p) == -edge_value(p, q)` exactly and a non-zero value has the exact sign.
/// The kernel computes the three of a triangle at once, with the same operations
/// ([`Float::edge_trivectors`]); the tests check this form.
#[cfg(test)]
fn edge_value<T: Float>(p: [T; 2], q: [T; 2]) -> T {
    p[0] * q[1] - p[1] * q[0]
}

/// The inner product `x | y` of two vectors, with fused multiply-adds.
#[inline(always)]
fn dot<T: Float>(x: Vector<T>, y: Vector<T>) -> T {
    x.e1.mul_add_if_fma(y.e1, x.e2.mul_add_if_fma(y.e2, x.e3 * y.e3))
}

/// The three edge values with exact signs (Shewchuk's `orient2d` of the two points and the
/// ray's trace at the origin of the plane), an exact zero decided by the tie rule (see
/// [the module documentation](self#why-it-is-watertight), point 3). `None` (a miss) when the
/// ray is outside, or for non-finite input, where no sign is meaningful.
#[cold]
#[inline(never)]
fn inside_exact<T: ga::Scalar>(p: [[T; 2]; 3]) -> Option<[T; 3]> {
    if !p.iter().flatten().all(|x| x.is_finite()) {
        return None;
    }
    let point = |q: [T; 2]| Coord { x: q[0].to_f64(), y: q[1].to_f64() };
    let origin = Coord { x: 0.0, y: 0.0 };
    // orient2d(p, q, 0) = px qy - py qx, exactly signed (NaN only if f64 overflowed).
    let edges = [(1, 2), (2, 0), (0, 1)];
    let w = edges.map(|(i, j)| orient2d(point(p[i]), point(p[j]), origin));
    // NaN has no sign: 0, a miss.
    let sign = |v: T| i8::from(v > T::ZERO) - i8::from(v < T::ZERO);
    let signs: [i8; 3] = core::array::from_fn(|k| {
        let ((i, j), value) = (edges[k], w[k]);
        if value == 0.0 {
            match sign(p[i][1] - p[j][1]) {
                0 => sign(p[j][0] - p[i][0]),
                s => s,
            }
        } else {
            sign(T::from_f64_keep_sign(value))
        }
    });
    if !(signs[0] != 0 && signs[0] == signs[1] && signs[1] == signs[2]) {
        return None;
    }
    // The zeros stay zeros: the ray is on the edge, the barycentric weight is 0.
    Some(w.map(T::from_f64_keep_sign))
}

/// `N* / |N|` for `N = (b - a) ∧ (c - a)`, computed in `f64` and rounded once; zero for a
/// degenerate triangle.
pub(crate) fn unit_normal<T: GaReal>(tri: &Triangle<T>) -> Vector<T> {
    if is_degenerate(tri) {
        return Vector::ZERO;
    }
    let [a, b, c] = tri.vertices().map(|p| Vector::from_array(p.map(ga::Real::to_f64)));
    let n = ((b - a) ^ (c - a)).dual().normalize();
    Vector::from_array(n.to_array().map(ga::Real::from_f64))
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};
    use rand_pcg::Pcg64;

    fn vector<T: Float>(rng: &mut Pcg64, r: f64) -> Vector<T> {
        Vector::from_array([0; 3].map(|_| T::from_f64(rng.random_range(-r..r))))
    }

    fn ray<T: Float>(dir: Vector<T>) -> Ray<T> {
        Ray { origin: [T::ZERO; 3], dir: dir.to_array() }
    }

    /// The per-ray basis is orthonormal and `ex ∧ ey ∧ û = I`, for random directions and
    /// for the axes (both signs, where `σ + û₃` is smallest).
    fn basis_is_orthonormal_and_right_handed<T: Float>() {
        let mut rng = Pcg64::seed_from_u64(0x6a_3000);
        let axes = [Vector::E1, Vector::E2, Vector::E3].into_iter().flat_map(|e| [e, -e]);
        let random = (0..10_000).map(|_| vector::<T>(&mut rng, 4.0));
        let tol = T::EPSILON.to_f64() * 8.0;
        for d in axes.chain(random) {
            let G3WatertightRay { ex, ey } = prepare_ray(&ray(d));
            let u = d * d.norm().recip();
            for (x, want) in [
                (ex.norm_squared(), 1.0),
                (ey.norm_squared(), 1.0),
                (ex | ey, 0.0),
                (ex | u, 0.0),
                (ey | u, 0.0),
            ] {
                assert!((x.to_f64() - want).abs() <= tol, "{d:?}: {x:?}");
            }
            let volume = ((ex ^ ey) ^ u).e123;
            assert!((volume.to_f64() - 1.0).abs() <= tol, "{d:?}: {volume:?}");
        }
    }

    /// Swapping the edge's vertices negates the computed value exactly, for any inputs.
    fn edge_values_are_exactly_antisymmetric<T: Float>() {
        let mut rng = Pcg64::seed_from_u64(0x6a_3001);
        for _ in 0..100_000 {
            let (p, q) = (vector::<T>(&mut rng, 10.0), vector::<T>(&mut rng, 10.0));
            let (p, q) = ([p.e1, p.e2], [q.e1, q.e2]);
            let (x, y) = (edge_value(p, q), edge_value(q, p));
            assert!(x == -y, "{x:?} {y:?} for {p:?} {q:?}");
        }
    }

    /// Nearly collinear `p, q` (`q = α p + ε e` with `ε` down to `1e-20`): a non-zero computed
    /// value always has the exact sign (Shewchuk's `orient2d`); zeros do occur.
    fn nonzero_edge_values_have_exact_signs<T: Float>() {
        let mut rng = Pcg64::seed_from_u64(0x6a_3002);
        let sign = |x: f64| (x > 0.0) as i8 - (x < 0.0) as i8;
        let mut zeros = 0;
        for _ in 0..100_000 {
            let (p, e) = (vector::<T>(&mut rng, 1.0), vector::<T>(&mut rng, 1.0));
            let alpha = T::from_f64(rng.random_range(-2.0..2.0));
            let tiny = T::from_f64(10f64.powf(-rng.random_range(0.0..20.0)));
            let q = p * alpha + e * tiny;
            let (p, q) = ([p.e1, p.e2], [q.e1, q.e2]);
            let w = edge_value(p, q).to_f64();
            let point = |v: [T; 2]| Coord { x: v[0].to_f64(), y: v[1].to_f64() };
            let exact = orient2d(point(p), point(q), Coord { x: 0.0, y: 0.0 });
            if w == 0.0 {
                zeros += 1;
            } else {
                assert_eq!(sign(w), sign(exact), "{p:?} {q:?}");
            }
        }
        assert!(zeros > 0, "the fallback's case occurs");
    }

    #[test]
    fn basis_is_orthonormal_and_right_handed_in_both_precisions() {
        basis_is_orthonormal_and_right_handed::<f32>();
        basis_is_orthonormal_and_right_handed::<f64>();
    }

    #[test]
    fn edge_values_are_exactly_antisymmetric_in_both_precisions() {
        edge_values_are_exactly_antisymmetric::<f32>();
        edge_values_are_exactly_antisymmetric::<f64>();
    }

    #[test]
    fn nonzero_edge_values_have_exact_signs_in_both_precisions() {
        nonzero_edge_values_have_exact_signs::<f32>();
        nonzero_edge_values_have_exact_signs::<f64>();
    }
}
