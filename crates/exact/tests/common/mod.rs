//! Independent exact arithmetic for the tests: `BigRational` from `num-rational`, which shares
//! no code with the crate's own dyadic fallback, and plain formulas written out again.

#![allow(dead_code)] // each test file uses a different part of this module

use exact::Sign;
use num_rational::BigRational;
use num_traits::{Signed, Zero};

pub type Q = BigRational;
pub type Q3 = [Q; 3];

pub fn q(x: f64) -> Q {
    BigRational::from_float(x).expect("finite input")
}

pub fn q3(p: [f64; 3]) -> Q3 {
    p.map(q)
}

pub fn sub(p: &Q3, r: &Q3) -> Q3 {
    [&p[0] - &r[0], &p[1] - &r[1], &p[2] - &r[2]]
}

pub fn cross(p: &Q3, r: &Q3) -> Q3 {
    [&p[1] * &r[2] - &p[2] * &r[1], &p[2] * &r[0] - &p[0] * &r[2], &p[0] * &r[1] - &p[1] * &r[0]]
}

pub fn dot(p: &Q3, r: &Q3) -> Q {
    &p[0] * &r[0] + &p[1] * &r[1] + &p[2] * &r[2]
}

/// `det[p, q, r]` by the rule of Sarrus (a different expansion from the crate's `p . (q x r)`).
pub fn det(p: &Q3, r: &Q3, s: &Q3) -> Q {
    &p[0] * &r[1] * &s[2] + &r[0] * &s[1] * &p[2] + &s[0] * &p[1] * &r[2]
        - &s[0] * &r[1] * &p[2]
        - &r[0] * &p[1] * &s[2]
        - &p[0] * &s[1] * &r[2]
}

pub fn sign(x: &Q) -> Sign {
    if x.is_zero() {
        Sign::Zero
    } else if x.is_positive() {
        Sign::Positive
    } else {
        Sign::Negative
    }
}

/// A polynomial in the infinitesimal `e`, coefficients by ascending degree.
type Poly = Vec<Q>;

fn poly_add(a: &Poly, b: &Poly) -> Poly {
    (0..a.len().max(b.len()))
        .map(|i| {
            a.get(i).cloned().unwrap_or_else(Q::zero) + b.get(i).cloned().unwrap_or_else(Q::zero)
        })
        .collect()
}

fn poly_neg(a: &Poly) -> Poly {
    a.iter().map(|x| -x).collect()
}

fn poly_mul(a: &Poly, b: &Poly) -> Poly {
    let mut out = vec![Q::zero(); a.len() + b.len() - 1];
    for (i, x) in a.iter().enumerate() {
        for (j, y) in b.iter().enumerate() {
            out[i + j] += x * y;
        }
    }
    out
}

/// The sign of `det[p - o', q - o', d]` for the origin moved to `o' = o + (e, e^2, e^3)`,
/// `e -> 0+`, computed as a polynomial in `e` (Sarrus' rule over polynomials with exact
/// rational coefficients) whose lowest non-zero coefficient gives the sign. This uses none of
/// the crate's derivation of the perturbed sign.
pub fn perturbed_edge_sign(o: [f64; 3], d: [f64; 3], p: [f64; 3], r: [f64; 3]) -> Sign {
    let moved: [Poly; 3] = core::array::from_fn(|i| {
        let mut c = vec![Q::zero(); i + 2];
        c[0] = q(o[i]);
        c[i + 1] = Q::from_integer(1.into());
        c
    });
    let column = |x: [f64; 3]| -> [Poly; 3] {
        core::array::from_fn(|i| poly_add(&vec![q(x[i])], &poly_neg(&moved[i])))
    };
    let (m0, m1, m2) = (column(p), column(r), d.map(|x| vec![q(x)]));
    let term = |x: &Poly, y: &Poly, z: &Poly| poly_mul(&poly_mul(x, y), z);
    let plus =
        [term(&m0[0], &m1[1], &m2[2]), term(&m1[0], &m2[1], &m0[2]), term(&m2[0], &m0[1], &m1[2])];
    let minus =
        [term(&m2[0], &m1[1], &m0[2]), term(&m1[0], &m0[1], &m2[2]), term(&m0[0], &m2[1], &m1[2])];
    let total = plus
        .iter()
        .chain(minus.iter().map(poly_neg).collect::<Vec<_>>().iter())
        .fold(Vec::new(), |acc: Poly, t| poly_add(&acc, t));
    total.iter().map(sign).find(|s| *s != Sign::Zero).unwrap_or(Sign::Zero)
}

/// `x` is the `f64` nearest to the exact value `exact` (no representable number is closer).
pub fn is_nearest(x: f64, exact: &Q) -> bool {
    let err = (q(x) - exact).abs();
    [x.next_up(), x.next_down()].iter().all(|n| !n.is_finite() || (q(*n) - exact).abs() >= err)
}
