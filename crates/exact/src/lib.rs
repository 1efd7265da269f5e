//! The exact reference ray-triangle test that the other back ends are judged against.
//!
//! [`Exact`] implements [`Intersector`] for `f64` rays and triangles. Hit or miss is decided
//! exactly for the `f64` values it is given, with a tie rule for rays through edges and
//! vertices; the reported `t`, `u` and `v` are the exact values rounded once to `f64`.
//! To judge an `f32` back end, cast its `f32` rays and triangles to `f64` (exact), and the
//! reference answers for exactly the values the `f32` kernel saw.
//!
//! ```
//! use exact::Exact;
//! use intersect::{Intersector, Ray, Triangle};
//!
//! // Two triangles sharing the edge from (0, 0, 0) to (1, 1, 0), consistently oriented.
//! let first = Triangle::new([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0]);
//! let second = Triangle::new([0.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]);
//! // A ray through the midpoint of the shared edge (target - origin is exact here).
//! let origin = [0.125, 0.75, 3.0];
//! let ray = Ray::new(origin, [0.5 - origin[0], 0.5 - origin[1], -origin[2]]);
//!
//! let exact = Exact;
//! let hit = |tri| exact.intersect(&exact.prepare(tri), &ray, &(), f64::INFINITY);
//! // Exactly one of the two is hit, never both, never neither: by the tie rule below, the
//! // one on the +x side of the edge as seen along the ray.
//! let (first_hit, second_hit) = (hit(&first), hit(&second));
//! assert!(first_hit.is_some() && second_hit.is_none());
//! // The ray reaches the edge at t = 1, halfway from a to c, and that is reported exactly.
//! let first_hit = first_hit.unwrap();
//! assert_eq!((first_hit.t, first_hit.u, first_hit.v), (1.0, 0.0, 0.5));
//! ```
//!
//! # What it guarantees
//!
//! For finite inputs (rays, triangles and `t_max`):
//!
//! - **Hit or miss is exact.** A hit is reported exactly when the ray, with the tie rule
//!   below, meets the closed triangle at some `t` with `0 < t <= t_max` (the contract of
//!   [`Intersector`]). Every decision is the sign of a polynomial in the inputs, evaluated
//!   with a floating-point filter and, when the filter cannot decide, exactly (see
//!   [`predicates`]). Backfaces are not culled.
//! - **The tie rule** (a ray exactly through an edge or a vertex): the ray is decided as if
//!   its origin were moved to `o + (e, e^2, e^3)` for an infinitesimal `e > 0`, one and the
//!   same move for every triangle (simulation of simplicity). The moved ray passes through no
//!   edge and no vertex of a triangle it is not parallel to, so it either crosses a
//!   triangle's interior or misses it. Hence:
//!   - a ray through the interior of an edge shared by two triangles that lie on opposite
//!     sides of the edge as seen along the ray (two consistently oriented triangles that both
//!     face the ray, or both face away, such as any two neighbours on a flat or convex
//!     surface) hits **exactly one** of them: the one on the `+x` side of the edge as seen
//!     along the ray; if the plane through the edge and the ray contains the `x` direction,
//!     the one on the `+y` side; if it contains `x` and `y`, the `+z` side. Where the surface
//!     folds over at the edge (a silhouette seen exactly edge-on), the ray hits both or
//!     neither, as any slightly moved ray would;
//!   - a ray through a vertex whose triangles cover a neighbourhood of it once as seen along
//!     the ray (a flat fan, the tip of a convex cone, any vertex of a closed convex mesh)
//!     hits **exactly one** of them;
//!   - the decision does not depend on the order of the triangles, nor on the order of a
//!     triangle's vertices (reversing it negates all three edge tests);
//!   - the move is sideways only: `0 < t <= t_max` is tested on the unperturbed `t`, so a
//!     ray whose origin lies exactly on a triangle's plane (`t = 0`) misses it.
//! - **Grazing rays miss.** A ray parallel to a triangle's plane (in the plane or not) never
//!   hits it: for such a ray the edge tests sum to exactly zero, so their perturbed signs
//!   cannot all agree (see [`predicates::edge_sign_perturbed`]).
//! - **Degenerate triangles never hit**: zero area decided exactly
//!   ([`predicates::is_degenerate`]), checked once in [`Intersector::prepare`].
//! - **t, u, v are correctly rounded**: each is the exact rational value (below) rounded to the
//!   nearest `f64`, ties to even, so the relative error is at most `2^-53` (half an ulp),
//!   whatever the conditioning of the ray and the triangle, grazing included. Exceptions: a
//!   `t` below `2^-1022` may be off by one unit of `2^-1074` (double rounding in the
//!   subnormal range), a `t` that would round to 0 is reported as the smallest positive `f64`
//!   (to keep `t > 0`), and a `t` beyond `f64::MAX` (possible only with `t_max` infinite) is
//!   reported as infinity.
//!
//! Any NaN or infinite coordinate, and a NaN or non-positive `t_max`, gives a miss; nothing
//! panics.
//!
//! # The formulas
//!
//! With `A = a - o`, `B = b - o`, `C = c - o` for the ray `o + t d` and triangle `(a, b, c)`:
//!
//! - Edge tests: `E_ab = det[A, B, d]`, `E_bc = det[B, C, d]`, `E_ca = det[C, A, d]`, the
//!   signed volumes spanned by the ray and each edge (Plucker products). The line of the ray
//!   meets the triangle where all three have one sign.
//! - Their sum is the denominator: `E_ab + E_bc + E_ca = (A x B + B x C + C x A) . d =
//!   ((B - A) x (C - A)) . d = n . d =: D`, with `n = (b - a) x (c - a)`.
//! - Barycentrics: the `E`s do not change when `o` slides along `d`, so they may be taken at
//!   the hit point `p`, where `E_bc`, `E_ca`, `E_ab` are `n . d` times the signed areas of
//!   `(p, b, c)`, `(a, p, c)`, `(a, b, p)` over that of `(a, b, c)`: the weights of `a`, `b`,
//!   `c`. Hence `u = E_ca / D` (weight of `b`) and `v = E_ab / D` (weight of `c`).
//! - Distance: the plane is `n . (x - a) = 0`, so `t = n . (a - o) / (n . d) = N / D` with
//!   `N = n . A = ((B - A) x (C - A)) . A = (B x C) . A = det[A, B, C]`.
//! - Range: on a hit all `E`s share one sign `s` and at least one is non-zero, so `D` has
//!   sign `s`; then `t > 0` exactly when `N` has sign `s`, and `t <= t_max` exactly when
//!   `N - t_max D` is zero or of sign `-s`. Both signs are decided exactly.
//!
//! # What it costs
//!
//! Measured with `cargo bench -p exact` (2-core shared machine, so only the ratios
//! are trustworthy), per ray-triangle test:
//!
//! | case | cost |
//! |---|---|
//! | plain `f64` Moller-Trumbore, for scale | ~12 ns |
//! | filter decides (any ray not within a few ulps of an edge), [`Intersector::occludes`] | ~75 ns |
//! | one edge test falls back to exact arithmetic (ray exactly through an edge) | ~1.5 us |
//! | a hit through [`Intersector::intersect`] (exact `t`, `u`, `v`, three big divisions) | ~4.5 us |
//!
//! So the reference costs a few times a plain kernel on misses, which are most tests of a
//! traversal, and microseconds per hit and per near-edge test. [`Intersector::occludes`] and
//! [`Exact::crossing`] never compute `t`, `u` and `v`.

#![deny(missing_docs)]

mod dyadic;
pub mod predicates;

use intersect::{Algebra, Guarantees, Intersector, Method, Ray, Triangle, TriangleHit};

use crate::dyadic::{Dyadic, det3, sub3};
use crate::predicates::{
    EDGE_REL, Filtered, GUARD, ORIENT_REL, det_filtered, dyadic_points, edge_sign_perturbed_exact,
    is_degenerate, orient3d_exact, sub,
};

/// The sign of an exactly evaluated quantity.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Sign {
    /// Less than zero.
    Negative,
    /// Exactly zero.
    Zero,
    /// Greater than zero.
    Positive,
}

/// The exact reference back end: see the [crate documentation](crate).
#[derive(Clone, Copy, Debug, Default)]
pub struct Exact;

/// A triangle as [`Exact`] stores it: the vertices and whether it can be hit at all.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ExactTriangle {
    tri: Triangle<f64>,
    hittable: bool,
}

impl ExactTriangle {
    /// The triangle.
    #[must_use]
    pub const fn triangle(&self) -> &Triangle<f64> {
        &self.tri
    }

    /// Whether any ray can hit it: all coordinates finite and the area not exactly zero.
    #[must_use]
    pub const fn is_hittable(&self) -> bool {
        self.hittable
    }
}

impl Exact {
    /// From which side `ray` crosses the triangle, if it hits it with `0 < t <= t_max`:
    /// [`Sign::Negative`] from the front (the side the normal `(b - a) x (c - a)` points to),
    /// [`Sign::Positive`] from the back. Never [`Sign::Zero`]. Hit or miss is decided exactly
    /// as in [`Intersector::intersect`], without computing `t`, `u` and `v`.
    ///
    /// ```
    /// use exact::{Exact, Sign};
    /// use intersect::{Ray, Triangle};
    ///
    /// let tri = Triangle::new([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
    /// let down = Ray::new([0.25, 0.25, 1.0], [0.0, 0.0, -1.0]);
    /// assert_eq!(Exact.crossing(&tri, &down, f64::INFINITY), Some(Sign::Negative));
    /// assert_eq!(Exact.crossing(&tri, &down, 0.5), None);
    /// ```
    #[must_use]
    pub fn crossing(&self, tri: &Triangle<f64>, ray: &Ray<f64>, t_max: f64) -> Option<Sign> {
        if is_degenerate(tri) { None } else { crossing(tri, ray, t_max) }
    }
}

impl Intersector for Exact {
    type Real = f64;
    type Prim = ExactTriangle;
    type RayData = ();
    type Block = ();
    const NAME: &'static str = "exact";
    const ALGEBRA: Algebra = Algebra::La;
    const METHOD: Method = Method::Watertight;
    const GUARANTEES: Guarantees = Guarantees { watertight: true, exact: true };
    const VARIANT: Option<&'static str> = None;

    fn prepare(&self, tri: &Triangle<f64>) -> ExactTriangle {
        // `is_degenerate` also reports non-finite triangles as degenerate.
        ExactTriangle { tri: *tri, hittable: !is_degenerate(tri) }
    }

    fn prepare_ray(&self, _ray: &Ray<f64>) {}

    fn intersect(
        &self,
        prim: &ExactTriangle,
        ray: &Ray<f64>,
        _ray_data: &(),
        t_max: f64,
    ) -> Option<TriangleHit<f64>> {
        if !prim.hittable {
            return None;
        }
        crossing(&prim.tri, ray, t_max)?;
        exact_hit(&prim.tri, ray)
    }

    fn occludes(&self, prim: &ExactTriangle, ray: &Ray<f64>, _ray_data: &(), t_max: f64) -> bool {
        prim.hittable && crossing(&prim.tri, ray, t_max).is_some()
    }
}

/// The side from which the ray crosses the triangle within `(0, t_max]`, decided exactly
/// (see the crate docs for the formulas), or `None` for a miss.
///
/// A hit needs every edge test to have been decided, and together the three edge tests
/// involve every coordinate of the ray and the triangle; each is decided either by the
/// filter (which never certifies a non-finite input) or exactly (which rejects non-finite
/// inputs). So a hit implies finite inputs.
fn crossing(tri: &Triangle<f64>, ray: &Ray<f64>, t_max: f64) -> Option<Sign> {
    // Also rejects a NaN t_max: no t satisfies 0 < t <= t_max.
    if t_max.is_nan() || t_max <= 0.0 {
        return None;
    }
    let (o, d) = (ray.origin, ray.dir);
    let (pa, pb, pc) = (sub(tri.a, o), sub(tri.b, o), sub(tri.c, o));
    let (eab, ebc) = (det_filtered(pa, pb, d, EDGE_REL), det_filtered(pb, pc, d, EDGE_REL));
    // Most misses are already decided by two edges: skip the third.
    if let (Some(x), Some(y)) = (eab.sign(), ebc.sign())
        && x != y
    {
        return None;
    }
    let edges = [eab, ebc, det_filtered(pc, pa, d, EDGE_REL)];
    let certified = edges.map(Filtered::sign);

    // Two certified signs that differ decide a miss before any exact work.
    let mut side = None;
    for s in certified.into_iter().flatten() {
        if *side.get_or_insert(s) != s {
            return None;
        }
    }
    let vertex_pairs = [(tri.a, tri.b), (tri.b, tri.c), (tri.c, tri.a)];
    for (s, (p, q)) in certified.into_iter().zip(vertex_pairs) {
        if s.is_none() {
            let s = edge_sign_perturbed_exact(o, d, p, q)?;
            if s == Sign::Zero || *side.get_or_insert(s) != s {
                return None;
            }
        }
    }
    let side = side?;

    // t > 0: N = det[A, B, C] has the sign of D, which is `side`.
    let n = det_filtered(pa, pb, pc, ORIENT_REL);
    if n.sign().or_else(|| orient3d_exact(o, tri.a, tri.b, tri.c))? != side {
        return None;
    }

    // t <= t_max: F = N - t_max D is zero or of the sign opposite to `side`.
    if t_max < f64::INFINITY && beyond_sign(&n, &edges, t_max, tri, ray)? == side {
        return None;
    }
    Some(side)
}

/// The exact sign of `F = N - t_max (E_ab + E_bc + E_ca)`, from the filtered values of `N` and
/// the `E`s, or exactly.
///
/// Filter: `F` is computed as `N - t_max ((E_ab + E_bc) + E_ca)` from the filtered values.
/// Propagated error: at most `bound(N) + t_max (bound(E_ab) + bound(E_bc) + bound(E_ca))`.
/// New roundings (two additions, one product, one subtraction): at most
/// `4u (1 + 2u) T` with `T = |N| + t_max (|E_ab| + |E_bc| + |E_ca|)`, plus `2^-1075` of
/// underflow in the product. The bound below uses `5u T` and adds `GUARD`, which leaves room
/// for the rounding of the bound itself (the input bounds already carry more than 10% slack).
fn beyond_sign(
    n: &Filtered,
    edges: &[Filtered; 3],
    t_max: f64,
    tri: &Triangle<f64>,
    ray: &Ray<f64>,
) -> Option<Sign> {
    beyond_filtered(n, edges, t_max).sign().or_else(|| {
        let [o, d, a, b, c] = dyadic_points([ray.origin, ray.dir, tri.a, tri.b, tri.c])?;
        let t_max = Dyadic::from_f64(t_max)?;
        let (pa, pb, pc) = (sub3(&a, &o), sub3(&b, &o), sub3(&c, &o));
        let den = &(&det3(&pa, &pb, &d) + &det3(&pb, &pc, &d)) + &det3(&pc, &pa, &d);
        Some((&det3(&pa, &pb, &pc) - &(&t_max * &den)).sign())
    })
}

/// The filtered value of `F = N - t_max (E_ab + E_bc + E_ca)` (derivation at [`beyond_sign`]).
fn beyond_filtered(n: &Filtered, edges: &[Filtered; 3], t_max: f64) -> Filtered {
    let [eab, ebc, eca] = edges;
    let value = n.value - t_max * ((eab.value + ebc.value) + eca.value);
    let sum_abs = (eab.value.abs() + ebc.value.abs()) + eca.value.abs();
    let sum_bounds = (eab.bound + ebc.bound) + eca.bound;
    let bound = (n.bound + t_max * sum_bounds)
        + 5.0 * (f64::EPSILON / 2.0) * (n.value.abs() + t_max * sum_abs)
        + GUARD;
    Filtered { value, bound }
}

/// `t = N / D`, `u = E_ca / D`, `v = E_ab / D` computed exactly and rounded once each.
/// Called only after [`crossing`] reported a hit, so `D != 0` and the inputs are finite.
fn exact_hit(tri: &Triangle<f64>, ray: &Ray<f64>) -> Option<TriangleHit<f64>> {
    let [o, d, a, b, c] = dyadic_points([ray.origin, ray.dir, tri.a, tri.b, tri.c])?;
    let (pa, pb, pc) = (sub3(&a, &o), sub3(&b, &o), sub3(&c, &o));
    let (eab, ebc, eca) = (det3(&pa, &pb, &d), det3(&pb, &pc, &d), det3(&pc, &pa, &d));
    let den = &(&eab + &ebc) + &eca;
    let t = Dyadic::ratio_to_f64(&det3(&pa, &pb, &pc), &den)?;
    // N / D > 0 exactly; only a quotient below half the smallest subnormal rounds to 0.
    let t = if t == 0.0 { f64::from_bits(1) } else { t };
    let u = Dyadic::ratio_to_f64(&eca, &den)?;
    let v = Dyadic::ratio_to_f64(&eab, &den)?;
    Some(TriangleHit { t, u, v })
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_rational::BigRational;
    use num_traits::{Signed, ToPrimitive};
    use rand::{Rng, SeedableRng};
    use rand_pcg::Pcg64;

    fn q(x: f64) -> BigRational {
        BigRational::from_float(x).unwrap()
    }

    fn q_det(p: [&BigRational; 3], r: [&BigRational; 3], s: [&BigRational; 3]) -> BigRational {
        p[0] * (r[1] * s[2] - r[2] * s[1]) - p[1] * (r[0] * s[2] - r[2] * s[0])
            + p[2] * (r[0] * s[1] - r[1] * s[0])
    }

    /// `x` with a random sign and binary exponent in `lo..hi`, zero one time in ten.
    fn wide(rng: &mut Pcg64, lo: i32, hi: i32) -> f64 {
        if rng.random_range(0..10) == 0 {
            return 0.0;
        }
        let x = rng.random_range(1.0..2.0) * 2f64.powi(rng.random_range(lo..hi));
        let x = if rng.random_bool(0.5) { x } else { -x };
        // powi of a large negative power underflows in steps; scale twice to stay exact-ish.
        x * 2f64.powi(rng.random_range(-60..0))
    }

    /// Points whose determinants nearly vanish: a plane through lattice points, one ulp off.
    fn near_coplanar(rng: &mut Pcg64) -> [[f64; 3]; 4] {
        let lattice = |rng: &mut Pcg64| -> [f64; 3] {
            core::array::from_fn(|_| 1e4 + f64::from(rng.random_range(-4096..4096)) / 1024.0)
        };
        let (o, a, b) = (lattice(rng), lattice(rng), lattice(rng));
        let (s, t) =
            (f64::from(rng.random_range(-8..8)) / 8.0, f64::from(rng.random_range(-8..8)) / 8.0);
        let mut c: [f64; 3] =
            core::array::from_fn(|k| o[k] + s * (a[k] - o[k]) + t * (b[k] - o[k]));
        let k = rng.random_range(0..3);
        c[k] = f64::from_bits(c[k].to_bits() + rng.random_range(0..3));
        [o, a, b, c]
    }

    /// The filters' error bounds hold: `|computed - exact| <= bound` whenever the bound is
    /// finite, on inputs from the subnormal range to `2^300` (underflow guard) and on nearly
    /// vanishing determinants (the relative part).
    #[test]
    fn filter_bounds_hold_against_exact_rationals() {
        let mut rng = Pcg64::seed_from_u64(40);
        let mut worst: f64 = 0.0;
        for case in 0..2000 {
            let [o, a, b, c]: [[f64; 3]; 4] = if case % 2 == 0 {
                near_coplanar(&mut rng)
            } else {
                let (lo, hi) = [(-1000, -900), (-400, 300), (-1010, 0)][case % 3];
                core::array::from_fn(|_| core::array::from_fn(|_| wide(&mut rng, lo, hi)))
            };
            let d = c;
            let (qo, qa, qb, qc) = (o.map(q), a.map(q), b.map(q), c.map(q));
            let diff = |p: &[BigRational; 3]| -> [BigRational; 3] {
                core::array::from_fn(|k| &p[k] - &qo[k])
            };
            let (qa_o, qb_o, qc_o) = (diff(&qa), diff(&qb), diff(&qc));
            let edge = det_filtered(sub(a, o), sub(b, o), d, EDGE_REL);
            let edge_exact = q_det(qa_o.each_ref(), qb_o.each_ref(), qc.each_ref());
            let orient = det_filtered(sub(a, o), sub(b, o), sub(c, o), ORIENT_REL);
            let orient_exact = q_det(qa_o.each_ref(), qb_o.each_ref(), qc_o.each_ref());
            for (f, exact) in [(edge, &edge_exact), (orient, &orient_exact)] {
                if f.bound.is_finite() && f.value.is_finite() {
                    let err = (q(f.value) - exact).abs();
                    assert!(err <= q(f.bound), "{o:?} {a:?} {b:?} {c:?}: {f:?}");
                    if f.bound > 0.0 {
                        worst = worst.max((err / q(f.bound)).to_f64().unwrap_or(0.0));
                    }
                }
            }
            // F = N - t_max (E_ab + E_bc + E_ca), with the three edge tests of (a, b, c).
            let edges = [
                det_filtered(sub(a, o), sub(b, o), d, EDGE_REL),
                det_filtered(sub(b, o), sub(c, o), d, EDGE_REL),
                det_filtered(sub(c, o), sub(a, o), d, EDGE_REL),
            ];
            let qd = &qc;
            let e_sum = q_det(qa_o.each_ref(), qb_o.each_ref(), qd.each_ref())
                + q_det(qb_o.each_ref(), qc_o.each_ref(), qd.each_ref())
                + q_det(qc_o.each_ref(), qa_o.each_ref(), qd.each_ref());
            let t_max = rng.random_range(0.01..100.0);
            let f = beyond_filtered(&orient, &edges, t_max);
            if f.bound.is_finite() && f.value.is_finite() {
                let exact = &orient_exact - q(t_max) * e_sum;
                assert!((q(f.value) - exact).abs() <= q(f.bound), "F {o:?} {a:?} {b:?} {c:?}");
            }
        }
        // The bounds are not absurdly loose either: some errors come within a factor 1000.
        assert!(worst > 1e-3, "worst error / bound = {worst}");
    }

    /// The edge tests alone already reject degenerate triangles (their sum, `n . d`, is zero);
    /// `prepare` checks degeneracy as well, so test the sign logic without that check.
    #[test]
    fn the_sign_logic_alone_never_hits_a_degenerate_triangle() {
        let segment = Triangle::new([0.0, 0.0, 0.0], [1.0, 1.0, 0.0], [2.0, 2.0, 0.0]);
        let point = Triangle::new([0.5, 0.5, 0.0], [0.5, 0.5, 0.0], [0.5, 0.5, 0.0]);
        for tri in [segment, point] {
            for (origin, dir) in [
                ([0.5, 0.5, 1.0], [0.0, 0.0, -1.0]),
                ([0.0, 1.0, 1.0], [0.5, -0.5, -1.0]),
                ([1.0, 1.0, 1.0], [0.0, 0.0, -1.0]),
                ([-1.0, -1.0, 0.0], [1.0, 1.0, 0.0]),
            ] {
                assert_eq!(crossing(&tri, &Ray::new(origin, dir), f64::INFINITY), None);
            }
        }
    }
}
