//! A generic Clifford algebra over `f64`: the oracle the specialised kernels of `ga` are tested
//! against, and the source of the sign and blade tables `ga-codegen` writes them from.
//!
//! The crate has no dependencies and knows nothing of `ga`, so that the generator never depends on
//! what it writes.
//!
//! Nothing here is fast and nothing here is clever. A basis blade is a bitmask (bit `i` set means
//! generator `e_{i+1}` is a factor, factors in increasing order), a multivector is an array of
//! `2^n` coefficients indexed by bitmask, and every product is the double loop over pairs of
//! blades: the product of two blades is the blade `a XOR b`, times the sign of the swaps that
//! bring the factors into canonical order, times the squares of the generators they share.
//! Each product of the algebra (outer, contractions, the report's inner product, scalar
//! product) is that loop keeping only the pairs whose grades satisfy its rule. Because all of it
//! is the textbook definition with no case analysis, a hand-expanded kernel that disagrees with it
//! is wrong.
//!
//! Any diagonal metric with up to [`MAX_GENERATORS`] generators is supported, so the same oracle
//! serves G(3,0,0), projective R(3,0,1) and conformal R(4,1).
//!
//! ```
//! use ga_reference::Algebra;
//!
//! let g3 = Algebra::new(3, 0, 0);
//! let (e1, e2) = (g3.generator(0), g3.generator(1));
//! // e1 e2 = e12 and e2 e1 = -e12: the blade 0b011 with opposite signs.
//! assert_eq!((&e1 * &e2).coefficient(0b011), 1.0);
//! assert_eq!((&e2 * &e1).coefficient(0b011), -1.0);
//!
//! // Projective geometric algebra: the fourth generator squares to zero.
//! let pga = Algebra::new(3, 0, 1);
//! let e0 = pga.generator(3);
//! assert_eq!((&e0 * &e0).max_abs(), 0.0);
//! ```
//!
//! # Basis order and the report's basis
//!
//! Blades are stored in bitmask order: `1, e1, e2, e12, e3, e13, e23, e123` for three generators.
//! The report (and `ga::g3`) uses the order `1, e1, e2, e3, e12, e23, e31, e123`, and its `e31`
//! is `e3 e1 = -e13`. [`G3_REPORT_BASIS`], [`from_g3_report`] and [`to_g3_report`] convert,
//! signs included. Any other basis (another order, other orientations, such as projective
//! geometric algebra's `e021, e013, e032`) is a list of `(bitmask, sign)` pairs:
//! [`blade_from_factors`] computes each pair from the blade written as a product of generators,
//! and [`from_basis`] and [`to_basis`] convert coefficients.
//!
//! ```
//! use ga_reference::{Algebra, blade_from_factors, from_basis, to_basis};
//!
//! // e31 = e3 e1 = -e13: bitmask 0b101, sign -1 (generators are 0-based indices).
//! assert_eq!(blade_from_factors(&[2, 0]), (0b101, -1.0));
//! let basis = [(0b000, 1.0), (0b101, -1.0)];
//! let m = from_basis(Algebra::new(3, 0, 0), &basis, &[2.0, 3.0]);
//! assert_eq!(m.coefficient(0b101), -3.0);
//! assert_eq!(to_basis(&m, &basis), vec![2.0, 3.0]);
//! ```

#![deny(missing_docs)]

use std::fmt;
use std::ops::{Add, BitXor, Mul, Neg, Sub};

/// The most generators an [`Algebra`] may have.
pub const MAX_GENERATORS: usize = 6;

/// The most basis blades a [`Multivector`] may have (`2^MAX_GENERATORS`).
pub const MAX_BLADES: usize = 1 << MAX_GENERATORS;

/// The report's G3 basis `1, e1, e2, e3, e12, e23, e31, e123` as `(bitmask, sign)`: report
/// blade `k` equals `sign` times the canonical blade `bitmask`.
///
/// Only `e31` carries a minus sign: `e3 e1 = -e1 e3`, and the canonical blade `0b101` is `e1 e3`.
pub const G3_REPORT_BASIS: [(usize, f64); 8] = [
    (0b000, 1.0),
    (0b001, 1.0),
    (0b010, 1.0),
    (0b100, 1.0),
    (0b011, 1.0),
    (0b110, 1.0),
    (0b101, -1.0),
    (0b111, 1.0),
];

/// Names of the report's G3 basis blades, in the report's order (`"1"` is the scalar).
pub const G3_REPORT_NAMES: [&str; 8] = ["1", "e1", "e2", "e3", "e12", "e23", "e31", "e123"];

/// The grade of a basis blade: how many generators it is the product of.
#[must_use]
pub fn grade_of(blade: usize) -> usize {
    blade.count_ones() as usize
}

/// The sign picked up by reordering the product of canonical blades `a` and `b` into canonical
/// (increasing) order, ignoring the metric.
///
/// Every generator of `a` must move right past every generator of `b` with a smaller index;
/// each such move is one swap of anticommuting generators.
#[must_use]
pub fn reordering_sign(a: usize, b: usize) -> f64 {
    let mut swaps = 0;
    let mut rest = a >> 1;
    while rest != 0 {
        swaps += (rest & b).count_ones();
        rest >>= 1;
    }
    if swaps % 2 == 0 { 1.0 } else { -1.0 }
}

/// A real Clifford algebra with a diagonal metric on up to [`MAX_GENERATORS`] generators.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Algebra {
    squares: [f64; MAX_GENERATORS],
    dimension: usize,
}

impl Algebra {
    /// The algebra R(p, q, r): generators `0..p` square to +1, the next `q` to -1, the last `r`
    /// to 0.
    ///
    /// # Panics
    ///
    /// If `p + q + r` exceeds [`MAX_GENERATORS`].
    #[must_use]
    pub fn new(p: usize, q: usize, r: usize) -> Self {
        let squares: Vec<f64> = std::iter::repeat_n(1.0, p)
            .chain(std::iter::repeat_n(-1.0, q))
            .chain(std::iter::repeat_n(0.0, r))
            .collect();
        Self::from_metric(&squares)
    }

    /// An algebra whose generator `i` squares to `squares[i]` (any order of +1, -1 and 0, e.g.
    /// `[0, 1, 1, 1]` for PGA with `e0` first).
    ///
    /// # Panics
    ///
    /// If there are more than [`MAX_GENERATORS`] squares.
    #[must_use]
    pub fn from_metric(squares: &[f64]) -> Self {
        assert!(
            squares.len() <= MAX_GENERATORS,
            "at most {MAX_GENERATORS} generators, got {}",
            squares.len()
        );
        let mut all = [0.0; MAX_GENERATORS];
        all[..squares.len()].copy_from_slice(squares);
        Self { squares: all, dimension: squares.len() }
    }

    /// The number of generators.
    #[must_use]
    pub fn dimension(&self) -> usize {
        self.dimension
    }

    /// The number of basis blades, `2^dimension`.
    #[must_use]
    pub fn blade_count(&self) -> usize {
        1 << self.dimension
    }

    /// What each generator squares to.
    #[must_use]
    pub fn metric(&self) -> &[f64] {
        &self.squares[..self.dimension]
    }

    /// The geometric product of canonical blades: `e_a e_b = factor * e_blade`, returned as
    /// `(factor, blade)`. The factor is 0 when a shared generator squares to 0.
    #[must_use]
    pub fn blade_product(&self, a: usize, b: usize) -> (f64, usize) {
        let shared = a & b;
        let metric: f64 = (0..self.dimension)
            .filter(|i| shared & (1 << i) != 0)
            .map(|i| self.squares[i])
            .product();
        (reordering_sign(a, b) * metric, a ^ b)
    }

    /// The zero multivector.
    #[must_use]
    pub fn zero(&self) -> Multivector {
        Multivector { algebra: *self, coefficients: [0.0; MAX_BLADES] }
    }

    /// A scalar.
    #[must_use]
    pub fn scalar(&self, value: f64) -> Multivector {
        self.blade(0, value)
    }

    /// `value` times the canonical blade `blade` (a bitmask).
    ///
    /// # Panics
    ///
    /// If `blade` is not a blade of this algebra.
    #[must_use]
    pub fn blade(&self, blade: usize, value: f64) -> Multivector {
        assert!(
            blade < self.blade_count(),
            "blade {blade:#b} outside a {}-D algebra",
            self.dimension
        );
        let mut m = self.zero();
        m.coefficients[blade] = value;
        m
    }

    /// Generator `e_{index+1}` (0-based index).
    ///
    /// # Panics
    ///
    /// If `index` is not below [`Algebra::dimension`].
    #[must_use]
    pub fn generator(&self, index: usize) -> Multivector {
        assert!(index < self.dimension, "generator {index} outside a {}-D algebra", self.dimension);
        self.blade(1 << index, 1.0)
    }

    /// The unit pseudoscalar `e1 e2 ... en`.
    #[must_use]
    pub fn pseudoscalar(&self) -> Multivector {
        self.blade(self.blade_count() - 1, 1.0)
    }

    /// A multivector from coefficients in bitmask order.
    ///
    /// # Panics
    ///
    /// If `coefficients` does not have exactly [`Algebra::blade_count`] entries.
    #[must_use]
    pub fn from_coefficients(&self, coefficients: &[f64]) -> Multivector {
        assert_eq!(coefficients.len(), self.blade_count(), "one coefficient per blade");
        let mut m = self.zero();
        m.coefficients[..coefficients.len()].copy_from_slice(coefficients);
        m
    }
}

/// The report's G3 coefficients (`1, e1, e2, e3, e12, e23, e31, e123`) as a multivector of
/// G(3,0,0) in bitmask order, signs converted.
#[must_use]
pub fn from_g3_report(coefficients: [f64; 8]) -> Multivector {
    let mut m = Algebra::new(3, 0, 0).zero();
    for (&(blade, sign), value) in G3_REPORT_BASIS.iter().zip(coefficients) {
        m.coefficients[blade] = sign * value;
    }
    m
}

/// The coefficients of a three-generator multivector in the report's basis
/// (`1, e1, e2, e3, e12, e23, e31, e123`), signs converted.
///
/// # Panics
///
/// If the multivector's algebra does not have exactly three generators.
#[must_use]
pub fn to_g3_report(m: &Multivector) -> [f64; 8] {
    assert_eq!(m.algebra.dimension, 3, "the report's basis has three generators");
    G3_REPORT_BASIS.map(|(blade, sign)| sign * m.coefficients[blade])
}

/// The canonical blade and sign of the product of distinct generators in the given order
/// (0-based indices): `e_f0 e_f1 ... = sign * e_bitmask`, e.g. `[2, 0]` (`e3 e1`) is
/// `(0b101, -1.0)`.
///
/// # Panics
///
/// If a generator repeats or an index is at least [`MAX_GENERATORS`].
#[must_use]
pub fn blade_from_factors(factors: &[usize]) -> (usize, f64) {
    let mut blade = 0;
    let mut sign = 1.0;
    for &f in factors {
        assert!(f < MAX_GENERATORS, "generator {f} beyond {MAX_GENERATORS}");
        assert!(blade & (1 << f) == 0, "generator {f} repeats in {factors:?}");
        sign *= reordering_sign(blade, 1 << f);
        blade |= 1 << f;
    }
    (blade, sign)
}

/// The multivector of `algebra` whose coefficient on the `k`-th blade of `basis` is
/// `coefficients[k]`, where basis blade `k` is `basis[k].1` times the canonical blade
/// `basis[k].0`.
///
/// # Panics
///
/// If the lengths differ or a blade lies outside the algebra.
#[must_use]
pub fn from_basis(algebra: Algebra, basis: &[(usize, f64)], coefficients: &[f64]) -> Multivector {
    assert_eq!(basis.len(), coefficients.len(), "one coefficient per basis blade");
    let mut m = algebra.zero();
    for (&(blade, sign), &value) in basis.iter().zip(coefficients) {
        assert!(blade < algebra.blade_count(), "blade {blade:#b} outside the algebra");
        m.coefficients[blade] += sign * value;
    }
    m
}

/// The coefficients of `m` on the blades of `basis` (see [`from_basis`]); blades the basis does
/// not list are dropped.
#[must_use]
pub fn to_basis(m: &Multivector, basis: &[(usize, f64)]) -> Vec<f64> {
    basis.iter().map(|&(blade, sign)| sign * m.coefficients[blade]).collect()
}

/// An element of an [`Algebra`]: one `f64` per basis blade, in bitmask order.
#[derive(Clone, PartialEq)]
pub struct Multivector {
    algebra: Algebra,
    coefficients: [f64; MAX_BLADES],
}

impl Multivector {
    /// The algebra this multivector belongs to.
    #[must_use]
    pub fn algebra(&self) -> Algebra {
        self.algebra
    }

    /// The coefficients, one per blade of the algebra, in bitmask order.
    #[must_use]
    pub fn coefficients(&self) -> &[f64] {
        &self.coefficients[..self.algebra.blade_count()]
    }

    /// The coefficient of the canonical blade `blade` (a bitmask).
    #[must_use]
    pub fn coefficient(&self, blade: usize) -> f64 {
        self.coefficients[blade]
    }

    /// The scalar (grade 0) part.
    #[must_use]
    pub fn scalar_part(&self) -> f64 {
        self.coefficients[0]
    }

    /// The largest absolute coefficient (the max norm, used for tolerances).
    #[must_use]
    pub fn max_abs(&self) -> f64 {
        self.coefficients().iter().fold(0.0, |m, c| m.max(c.abs()))
    }

    /// Applies `f(blade, coefficient)` to every coefficient.
    #[must_use]
    pub fn map(&self, f: impl Fn(usize, f64) -> f64) -> Self {
        let mut out = self.algebra.zero();
        for (blade, &c) in self.coefficients().iter().enumerate() {
            out.coefficients[blade] = f(blade, c);
        }
        out
    }

    /// `self` times a scalar.
    #[must_use]
    pub fn scale(&self, factor: f64) -> Self {
        self.map(|_, c| c * factor)
    }

    /// The sum over all pairs of blades `(a, b)` whose grades pass `keep(grade a, grade b,
    /// grade of a b)` of `A_a B_b e_a e_b`. Every bilinear product of the algebra is this loop.
    fn filtered_product(&self, other: &Self, keep: impl Fn(usize, usize, usize) -> bool) -> Self {
        assert_eq!(self.algebra, other.algebra, "operands from different algebras");
        let mut out = self.algebra.zero();
        for (a, &ca) in self.coefficients().iter().enumerate() {
            if ca == 0.0 {
                continue;
            }
            for (b, &cb) in other.coefficients().iter().enumerate() {
                if cb == 0.0 || !keep(grade_of(a), grade_of(b), grade_of(a ^ b)) {
                    continue;
                }
                let (factor, blade) = self.algebra.blade_product(a, b);
                out.coefficients[blade] += factor * ca * cb;
            }
        }
        out
    }

    /// The geometric product `A B`.
    #[must_use]
    pub fn geometric(&self, other: &Self) -> Self {
        self.filtered_product(other, |_, _, _| true)
    }

    /// The outer (wedge) product `A ^ B`: the grade `r + s` part of each blade product.
    #[must_use]
    pub fn outer(&self, other: &Self) -> Self {
        self.filtered_product(other, |r, s, t| t == r + s)
    }

    /// The left contraction `A _| B`: the grade `s - r` part of each blade product, zero when
    /// `r > s`.
    #[must_use]
    pub fn left_contraction(&self, other: &Self) -> Self {
        self.filtered_product(other, |r, s, t| r <= s && t == s - r)
    }

    /// The right contraction `A |_ B`: the grade `r - s` part of each blade product, zero when
    /// `s > r`.
    #[must_use]
    pub fn right_contraction(&self, other: &Self) -> Self {
        self.filtered_product(other, |r, s, t| s <= r && t == r - s)
    }

    /// The report's inner product (its figure 2.7, also Hestenes' inner product): the grade
    /// `|r - s|` part of each blade product, and zero when either blade is a scalar.
    #[must_use]
    pub fn inner(&self, other: &Self) -> Self {
        self.filtered_product(other, |r, s, t| r != 0 && s != 0 && t == r.abs_diff(s))
    }

    /// The "fat dot" product (Dorst's dot, the inner product of projective geometric algebra as
    /// bivector.net and Klein use it): the grade `|r - s|` part of each blade product, scalars
    /// included (so `1 . B = B`, unlike [`Multivector::inner`]).
    #[must_use]
    pub fn fat_dot(&self, other: &Self) -> Self {
        self.filtered_product(other, |r, s, t| t == r.abs_diff(s))
    }

    /// The scalar product `<A B>_0`.
    #[must_use]
    pub fn scalar_product(&self, other: &Self) -> f64 {
        self.filtered_product(other, |_, _, t| t == 0).scalar_part()
    }

    /// The commutator product `(A B - B A) / 2`.
    #[must_use]
    pub fn commutator(&self, other: &Self) -> Self {
        (&self.geometric(other) - &other.geometric(self)).scale(0.5)
    }

    /// The grade `k` part `<A>_k`.
    #[must_use]
    pub fn grade(&self, k: usize) -> Self {
        self.map(|blade, c| if grade_of(blade) == k { c } else { 0.0 })
    }

    /// The reverse: each grade-`k` blade times `(-1)^(k(k-1)/2)`.
    #[must_use]
    pub fn reverse(&self) -> Self {
        self.map(|blade, c| {
            let k = grade_of(blade);
            if (k * k.saturating_sub(1) / 2).is_multiple_of(2) { c } else { -c }
        })
    }

    /// The grade involution: each grade-`k` blade times `(-1)^k`.
    #[must_use]
    pub fn grade_involution(&self) -> Self {
        self.map(|blade, c| if grade_of(blade).is_multiple_of(2) { c } else { -c })
    }

    /// The Clifford conjugate: reverse composed with grade involution, `(-1)^(k(k+1)/2)`.
    #[must_use]
    pub fn conjugate(&self) -> Self {
        self.reverse().grade_involution()
    }

    /// The dual `A I^-1`, or `None` when the pseudoscalar is not invertible (degenerate metric;
    /// use [`Multivector::right_complement`] there).
    #[must_use]
    pub fn dual(&self) -> Option<Self> {
        let inverse_pseudoscalar = self.algebra.pseudoscalar().inverse()?;
        Some(self.geometric(&inverse_pseudoscalar))
    }

    /// The undual `A I`, the inverse of [`Multivector::dual`] where that exists.
    #[must_use]
    pub fn undual(&self) -> Self {
        self.geometric(&self.algebra.pseudoscalar())
    }

    /// The metric-free right complement: `e_A` maps to `s e_Ā` with `e_A ^ (s e_Ā) = I`.
    #[must_use]
    pub fn right_complement(&self) -> Self {
        self.complement(reordering_sign)
    }

    /// The metric-free left complement: `e_A` maps to `s e_Ā` with `(s e_Ā) ^ e_A = I`; the
    /// inverse of [`Multivector::right_complement`].
    #[must_use]
    pub fn left_complement(&self) -> Self {
        self.complement(|blade, rest| reordering_sign(rest, blade))
    }

    fn complement(&self, sign: impl Fn(usize, usize) -> f64) -> Self {
        let full = self.algebra.blade_count() - 1;
        let mut out = self.algebra.zero();
        for (blade, &c) in self.coefficients().iter().enumerate() {
            let rest = full ^ blade;
            out.coefficients[rest] = sign(blade, rest) * c;
        }
        out
    }

    /// The regressive product (meet) `A v B`, through complements so that it needs no metric:
    /// `left_complement(right_complement(A) ^ right_complement(B))`.
    #[must_use]
    pub fn regressive(&self, other: &Self) -> Self {
        self.right_complement().outer(&other.right_complement()).left_complement()
    }

    /// `<A ~A>_0`, the squared norm; for a Euclidean metric the sum of squared coefficients.
    #[must_use]
    pub fn norm_squared(&self) -> f64 {
        self.scalar_product(&self.reverse())
    }

    /// `sqrt(|<A ~A>_0|)`.
    #[must_use]
    pub fn norm(&self) -> f64 {
        self.norm_squared().abs().sqrt()
    }

    /// The sandwich `V X ~V` (a rotation when `V` is a unit rotor).
    #[must_use]
    pub fn sandwich(&self, x: &Self) -> Self {
        self.geometric(x).geometric(&self.reverse())
    }

    /// The inverse `A^-1` with `A A^-1 = A^-1 A = 1`, or `None` when `A` is singular.
    ///
    /// Found by solving the linear system `A X = 1` (the matrix of left multiplication by `A`)
    /// with Gaussian elimination, so it needs no formula that holds only for versors or only in
    /// some dimensions. In a finite-dimensional associative algebra a right inverse is also a
    /// left inverse. `A` counts as singular when a pivot falls below `1e-12` times the largest
    /// entry of the matrix.
    #[must_use]
    pub fn inverse(&self) -> Option<Self> {
        let n = self.algebra.blade_count();
        // Column j of the matrix holds the coefficients of A e_j; the last column is the
        // right-hand side, the scalar 1.
        let mut rows: Vec<Vec<f64>> = vec![vec![0.0; n + 1]; n];
        for j in 0..n {
            let column = self.geometric(&self.algebra.blade(j, 1.0));
            for (i, row) in rows.iter_mut().enumerate() {
                row[j] = column.coefficients[i];
            }
        }
        rows[0][n] = 1.0;
        let scale = rows.iter().flat_map(|r| r[..n].iter()).fold(0.0_f64, |m, x| m.max(x.abs()));
        if scale == 0.0 {
            return None;
        }
        for col in 0..n {
            let pivot = (col..n)
                .max_by(|&a, &b| rows[a][col].abs().total_cmp(&rows[b][col].abs()))
                .expect("non-empty range");
            if rows[pivot][col].abs() <= 1e-12 * scale {
                return None;
            }
            rows.swap(col, pivot);
            let pivot_row = rows[col].clone();
            for (i, row) in rows.iter_mut().enumerate() {
                if i != col {
                    let f = row[col] / pivot_row[col];
                    for (x, p) in row.iter_mut().zip(&pivot_row) {
                        *x -= f * p;
                    }
                }
            }
        }
        let mut out = self.algebra.zero();
        for (i, row) in rows.iter().enumerate() {
            out.coefficients[i] = row[n] / row[i];
        }
        Some(out)
    }

    /// The exponential `e^A` by its power series, with scaling and squaring so that the series
    /// converges in a few terms: `e^A = (e^(A / 2^s))^(2^s)`.
    #[must_use]
    pub fn exp(&self) -> Self {
        let size: f64 = self.coefficients().iter().map(|c| c.abs()).sum();
        // Halve until the sum of absolute coefficients is below 1/2; 24 terms then leave a
        // remainder far below f64 precision.
        let halvings = if size > 0.5 { (size / 0.5).log2().ceil() as i32 } else { 0 };
        let small = self.scale(0.5_f64.powi(halvings));
        let mut term = self.algebra.scalar(1.0);
        let mut sum = term.clone();
        for k in 1..=24 {
            term = term.geometric(&small).scale(1.0 / f64::from(k));
            sum = &sum + &term;
        }
        for _ in 0..halvings {
            sum = sum.geometric(&sum);
        }
        sum
    }
}

/// `"e13"` for the canonical blade `0b101`, `"1"` for the scalar.
#[must_use]
pub fn blade_name(blade: usize) -> String {
    if blade == 0 {
        return "1".to_owned();
    }
    let digits: String = (0..MAX_GENERATORS)
        .filter(|i| blade & (1 << i) != 0)
        .map(|i| (i + 1).to_string())
        .collect();
    format!("e{digits}")
}

/// Prints only the non-zero terms, e.g. `1 - 2 e1 + 0.5 e13`.
impl fmt::Debug for Multivector {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let mut first = true;
        for (blade, &c) in self.coefficients().iter().enumerate() {
            if c == 0.0 {
                continue;
            }
            let sign = if c < 0.0 { "-" } else { "+" };
            match (first, blade) {
                (true, 0) => write!(f, "{c}")?,
                (true, _) => write!(f, "{c} {}", blade_name(blade))?,
                (false, 0) => write!(f, " {sign} {}", c.abs())?,
                (false, _) => write!(f, " {sign} {} {}", c.abs(), blade_name(blade))?,
            }
            first = false;
        }
        if first {
            write!(f, "0")?;
        }
        Ok(())
    }
}

impl Add for &Multivector {
    type Output = Multivector;
    fn add(self, other: &Multivector) -> Multivector {
        assert_eq!(self.algebra, other.algebra, "operands from different algebras");
        self.map(|blade, c| c + other.coefficients[blade])
    }
}

impl Sub for &Multivector {
    type Output = Multivector;
    fn sub(self, other: &Multivector) -> Multivector {
        assert_eq!(self.algebra, other.algebra, "operands from different algebras");
        self.map(|blade, c| c - other.coefficients[blade])
    }
}

impl Neg for &Multivector {
    type Output = Multivector;
    fn neg(self) -> Multivector {
        self.scale(-1.0)
    }
}

/// The geometric product.
impl Mul for &Multivector {
    type Output = Multivector;
    fn mul(self, other: &Multivector) -> Multivector {
        self.geometric(other)
    }
}

/// The outer product.
impl BitXor for &Multivector {
    type Output = Multivector;
    fn bitxor(self, other: &Multivector) -> Multivector {
        self.outer(other)
    }
}
