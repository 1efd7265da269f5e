//! Exact sign predicates: a floating-point filter with a rigorous error bound, and an exact
//! fallback when the filter cannot decide.
//!
//! Each predicate is the sign of a polynomial in the input coordinates. It is first evaluated
//! in `f64`, together with a bound on the rounding error of that evaluation that holds for
//! every finite input (underflow included); if the value is farther from zero than the bound
//! its sign is the exact sign (a semi-static filter, as in Shewchuk's adaptive predicates).
//! Otherwise the polynomial is evaluated again, with no rounding at all, on dyadic rationals
//! (an internal module: big-integer mantissas and power-of-two exponents).
//!
//! # The error bounds
//!
//! `u = 2^-53` is the unit roundoff; `fl(x op y) = (x op y)(1 + e) + h` with `|e| <= u` and
//! `|h| <= 2^-1075` (the `h` only for products landing in the subnormal range: sums and
//! differences that land there are exact). A product of `n` factors `(1 + e_i)` lies within
//! `gamma_n = n u / (1 - n u)` of 1.
//!
//! A 3x3 determinant `det[p, q, r] = p . (q x r)` is evaluated as
//! `((p0 c0 + p1 c1) + p2 c2)` with `c = q x r`, `c0 = q1 r2 - q2 r1` and so on. Written out,
//! it is a signed sum of six monomials `p_i q_j r_k`. When some columns are rounded
//! differences (`p = fl(a - o)`), every monomial picks up one rounding per rounded factor, one
//! for the product in `c`, one for the subtraction in `c`, one for the product with `p`, and at
//! most two for the final sum:
//!
//! | determinant | rounded factors | roundings per monomial | bound used |
//! |---|---|---|---|
//! | edge test `det[a - o, b - o, d]` | 2 | 7 | `8u * P` |
//! | plane side `det[a - o, b - o, c - o]` | 3 | 8 | `9u * P` |
//!
//! so `|computed - exact| <= gamma_k * P_exact`, where `P_exact` is the sum of the absolute
//! values of the six exact monomials (the permanent). `P` is the permanent evaluated in `f64`
//! from the same rounded values; all its terms are non-negative and it goes through the same
//! `k` roundings, so `P_exact <= P / (1 - gamma_k)`, and `gamma_k / (1 - gamma_k) < (k + 1) u`
//! with room to spare for rounding the bound itself.
//!
//! Underflow adds an absolute error of at most `2^-1075` per product in `c` (two per
//! component), which the product with `p_i` scales by `|p_i|`, plus `2^-1075` for each of the
//! three outer products: in all less than `2^-1073 (|p0| + |p1| + |p2| + 1)`. The filters add
//! `GUARD (|p0| + |p1| + |p2| + 1)` with `GUARD = 2^-1069`, sixteen times that, which also
//! absorbs the underflow of the permanent itself.
//!
//! Infinities and NaNs make the value or the bound infinite or NaN, and every comparison with
//! them is false, so the filter never certifies a sign for a non-finite input: those inputs
//! reach the exact path, which rejects them (`None`).

use intersect::Triangle;

use crate::Sign;
use crate::dyadic::{Dyadic, cross3, det3, sub3};

/// Unit roundoff of `f64`: `2^-53`.
const U: f64 = f64::EPSILON / 2.0;

/// Relative error coefficient for the edge test `det[a - o, b - o, d]` (7 roundings).
pub(crate) const EDGE_REL: f64 = 8.0 * U;

/// Relative error coefficient for the plane side `det[a - o, b - o, c - o]` (8 roundings).
pub(crate) const ORIENT_REL: f64 = 9.0 * U;

/// Absolute error coefficient that covers gradual underflow: `2^-1069`.
pub(crate) const GUARD: f64 = f64::MIN_POSITIVE / (1u64 << 47) as f64;

/// A value computed in `f64` and a bound on its distance from the exact value.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Filtered {
    /// The computed value.
    pub(crate) value: f64,
    /// `|value - exact| <= bound`, for finite inputs.
    pub(crate) bound: f64,
}

impl Filtered {
    /// The exact sign if the filter certifies it (never [`Sign::Zero`]), else `None`.
    #[inline(always)]
    pub(crate) fn sign(self) -> Option<Sign> {
        if self.value > self.bound {
            Some(Sign::Positive)
        } else if -self.value > self.bound {
            Some(Sign::Negative)
        } else {
            None
        }
    }
}

/// `p - q` in `f64` (one rounding per component).
pub(crate) use intersect::vec3::sub;

/// `det[p, q, r]` in `f64` with its error bound, where `rel` is the relative coefficient for
/// the number of rounded columns (see the module docs). `p` and `q` (and `r`, for
/// [`ORIENT_REL`]) are the rounded differences; the bound is relative to the exact determinant
/// of the unrounded differences.
#[inline(always)]
pub(crate) fn det_filtered(p: [f64; 3], q: [f64; 3], r: [f64; 3], rel: f64) -> Filtered {
    // Separate multiplications and additions (Rust does not contract them into FMAs), so the
    // rounding count in the module docs is the one the machine performs.
    let (q1r2, q2r1) = (q[1] * r[2], q[2] * r[1]);
    let (q2r0, q0r2) = (q[2] * r[0], q[0] * r[2]);
    let (q0r1, q1r0) = (q[0] * r[1], q[1] * r[0]);
    let value = (p[0] * (q1r2 - q2r1) + p[1] * (q2r0 - q0r2)) + p[2] * (q0r1 - q1r0);
    let (a0, a1, a2) = (p[0].abs(), p[1].abs(), p[2].abs());
    let permanent = (a0 * (q1r2.abs() + q2r1.abs()) + a1 * (q2r0.abs() + q0r2.abs()))
        + a2 * (q0r1.abs() + q1r0.abs());
    let bound = rel * permanent + GUARD * (((a0 + a1) + a2) + 1.0);
    Filtered { value, bound }
}

/// The exact sign of `det[p - o, q - o, d]`, the edge test of edge `(p, q)` for the ray
/// `o + t d`, or `None` if an input is not finite.
///
/// For a triangle `(a, b, c)` whose normal `(b - a) x (c - a)` points against `d` (the ray
/// sees its front), the ray meets the interior exactly when the three edge tests of
/// `(a, b)`, `(b, c)`, `(c, a)` are all negative; from behind, when all are positive.
///
/// ```
/// use exact::{Sign, predicates::edge_sign};
///
/// let (o, d) = ([0.0, 0.0, -1.0], [0.0, 0.0, 1.0]);
/// assert_eq!(edge_sign(o, d, [1.0, -1.0, 0.0], [1.0, 1.0, 0.0]), Some(Sign::Positive));
/// assert_eq!(edge_sign(o, d, [1.0, 1.0, 0.0], [1.0, -1.0, 0.0]), Some(Sign::Negative));
/// // The ray (the z axis) lies in the plane of the edge's line: an exact zero.
/// assert_eq!(edge_sign(o, d, [-0.1, 0.0, 3.0], [0.3, 0.0, 7.0]), Some(Sign::Zero));
/// assert_eq!(edge_sign(o, [f64::NAN, 0.0, 1.0], [1.0, -1.0, 0.0], [1.0, 1.0, 0.0]), None);
/// ```
#[must_use]
pub fn edge_sign(o: [f64; 3], d: [f64; 3], p: [f64; 3], q: [f64; 3]) -> Option<Sign> {
    det_filtered(sub(p, o), sub(q, o), d, EDGE_REL).sign().or_else(|| {
        let [o, d, p, q] = dyadic_points([o, d, p, q])?;
        Some(det3(&sub3(&p, &o), &sub3(&q, &o), &d).sign())
    })
}

/// [`edge_sign`] with the tie rule: the sign for the ray whose origin is moved to
/// `o + (e, e^2, e^3)` with `e -> 0+` (simulation of simplicity), or `None` if an input is
/// not finite.
///
/// # Derivation
///
/// With `P = p - o` and `Q = q - o`, moving the origin by `delta` gives, by linearity of the
/// determinant in each column,
///
/// ```text
/// det[P - delta, Q - delta, d] = det[P, Q, d] - det[delta, Q, d] - det[P, delta, d]
///                              = det[P, Q, d] + det[delta, P - Q, d]
///                              = det[P, Q, d] + delta . ((p - q) x d)
/// ```
///
/// (`det[delta, delta, d] = 0`). With `w = (p - q) x d` and `delta = (e, e^2, e^3)` this is
/// `E + w0 e + w1 e^2 + w2 e^3`, whose sign for small enough `e > 0` is the sign of `E` if
/// `E != 0`, else of the first non-zero of `w0, w1, w2`. All of them are evaluated exactly.
///
/// The result is [`Sign::Zero`] only when `E = 0` and `w = 0`: the edge is parallel to `d`
/// (or has zero length, or `d = 0`), so the ray is parallel to the plane of any triangle
/// with that edge and grazes it.
///
/// Swapping `p` and `q` negates `E` and `w` alike, so the two triangles on either side of an
/// edge (which run it in opposite directions when consistently oriented) always get opposite
/// signs for it: one perturbed ray crosses the edge line to exactly one side.
///
/// ```
/// use exact::{Sign, predicates::edge_sign_perturbed};
///
/// let (o, d) = ([0.5, 0.0, -1.0], [0.0, 0.0, 1.0]);
/// let (p, q) = ([0.0, 0.0, 0.0], [1.0, 0.0, 0.0]);
/// // The ray passes through the edge: (p - q) x d = (0, 1, 0), so the sign comes from e^2.
/// assert_eq!(edge_sign_perturbed(o, d, p, q), Some(Sign::Positive));
/// assert_eq!(edge_sign_perturbed(o, d, q, p), Some(Sign::Negative));
/// // An edge parallel to the ray stays zero (grazing).
/// assert_eq!(edge_sign_perturbed(o, d, p, [0.0, 0.0, 1.0]), Some(Sign::Zero));
/// ```
#[must_use]
pub fn edge_sign_perturbed(o: [f64; 3], d: [f64; 3], p: [f64; 3], q: [f64; 3]) -> Option<Sign> {
    det_filtered(sub(p, o), sub(q, o), d, EDGE_REL)
        .sign()
        .or_else(|| edge_sign_perturbed_exact(o, d, p, q))
}

/// The exact path of [`edge_sign_perturbed`].
pub(crate) fn edge_sign_perturbed_exact(
    o: [f64; 3],
    d: [f64; 3],
    p: [f64; 3],
    q: [f64; 3],
) -> Option<Sign> {
    let [o, d, p, q] = dyadic_points([o, d, p, q])?;
    let e = det3(&sub3(&p, &o), &sub3(&q, &o), &d);
    if !e.is_zero() {
        return Some(e.sign());
    }
    let w = cross3(&sub3(&p, &q), &d);
    Some(w.iter().map(Dyadic::sign).find(|s| *s != Sign::Zero).unwrap_or(Sign::Zero))
}

/// The exact sign of `det[a - o, b - o, c - o]`, or `None` if an input is not finite.
///
/// It is positive when `o` lies on the side of the plane of `(a, b, c)` that the normal
/// `(b - a) x (c - a)` points away from, zero when `o` is on the plane. For a ray `o + t d`
/// that meets the plane, `t = det[a - o, b - o, c - o] / ((b - a) x (c - a)) . d`
/// (see [`crate`] docs), so `t > 0` exactly when this sign matches the sign of the
/// denominator.
///
/// ```
/// use exact::{Sign, predicates::orient3d};
///
/// let (a, b, c) = ([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
/// assert_eq!(orient3d([0.2, 0.2, -1.0], a, b, c), Some(Sign::Positive));
/// assert_eq!(orient3d([0.2, 0.2, 1e-300], a, b, c), Some(Sign::Negative));
/// assert_eq!(orient3d([7.0, -3.0, 0.0], a, b, c), Some(Sign::Zero));
/// ```
#[must_use]
pub fn orient3d(o: [f64; 3], a: [f64; 3], b: [f64; 3], c: [f64; 3]) -> Option<Sign> {
    det_filtered(sub(a, o), sub(b, o), sub(c, o), ORIENT_REL)
        .sign()
        .or_else(|| orient3d_exact(o, a, b, c))
}

/// The exact path of [`orient3d`].
pub(crate) fn orient3d_exact(o: [f64; 3], a: [f64; 3], b: [f64; 3], c: [f64; 3]) -> Option<Sign> {
    let [o, a, b, c] = dyadic_points([o, a, b, c])?;
    Some(det3(&sub3(&a, &o), &sub3(&b, &o), &sub3(&c, &o)).sign())
}

/// Whether the triangle has zero area, decided exactly: its normal `(b - a) x (c - a)` is
/// exactly the zero vector (two vertices coincide or all three are collinear). A triangle
/// with a non-finite coordinate counts as degenerate too.
///
/// Each normal component is a 2x2 determinant of rounded differences: 4 roundings per
/// monomial (two differences, the product, the subtraction), so the filter bound is
/// `5u` times its permanent, plus the underflow guard.
///
/// ```
/// use exact::predicates::is_degenerate;
/// use intersect::Triangle;
///
/// assert!(is_degenerate(&Triangle::new([0.0; 3], [1.0, 1.0, 1.0], [3.0, 3.0, 3.0])));
/// assert!(!is_degenerate(&Triangle::new([0.0; 3], [1.0, 1.0, 1.0], [3.0, 3.0, 3.0000001])));
/// ```
#[must_use]
pub fn is_degenerate(tri: &Triangle<f64>) -> bool {
    // Checked first: the filter below could certify a normal component that does not involve
    // the non-finite coordinate.
    if !tri.vertices().as_flattened().iter().all(|x| x.is_finite()) {
        return true;
    }
    let (p, q) = (sub(tri.b, tri.a), sub(tri.c, tri.a));
    let certainly_nonzero = |i: usize, j: usize| {
        let (x, y) = (p[i] * q[j], p[j] * q[i]);
        let bound = 5.0 * U * (x.abs() + y.abs()) + GUARD;
        (x - y).abs() > bound
    };
    if certainly_nonzero(1, 2) || certainly_nonzero(2, 0) || certainly_nonzero(0, 1) {
        return false;
    }
    let Some([a, b, c]) = dyadic_points([tri.a, tri.b, tri.c]) else {
        return true; // unreachable: the coordinates are finite
    };
    cross3(&sub3(&b, &a), &sub3(&c, &a)).iter().all(Dyadic::is_zero)
}

/// The exact values of `N` points, or `None` if a coordinate is not finite.
pub(crate) fn dyadic_points<const N: usize>(points: [[f64; 3]; N]) -> Option<[[Dyadic; 3]; N]> {
    let converted: Option<Vec<[Dyadic; 3]>> = points.into_iter().map(Dyadic::from_point).collect();
    converted?.try_into().ok()
}
