//! Conformal geometric algebra R(4,1): points, spheres, planes, circles and lines as blades,
//! and every conformal map (rotation, translation, dilation, inversion) as a versor.
//!
//! ```
//! use ga::cga::Vector;
//!
//! // The conformal embedding up(x) = x + x²/2 e∞ + eₒ, with eₒ = (e5 - e4)/2, e∞ = e4 + e5.
//! let up = |x: f64, y: f64, z: f64| {
//!     let h = 0.5 * (x * x + y * y + z * z);
//!     Vector::new(x, y, z, h - 0.5, h + 0.5)
//! };
//! // Points are null vectors, and the inner product of two is -|x - y|²/2.
//! assert_eq!(up(1.0, 2.0, 3.0) | up(1.0, 2.0, 3.0), 0.0);
//! assert_eq!(up(0.0, 0.0, 0.0) | up(3.0, 4.0, 0.0), -12.5);
//! // The outer product of four points is the sphere through them (a quadvector); a fifth point
//! // lies on it exactly when the outer product with it vanishes.
//! let sphere = up(1.0, 0.0, 0.0) ^ up(-1.0, 0.0, 0.0) ^ up(0.0, 1.0, 0.0) ^ up(0.0, 0.0, 1.0);
//! assert_eq!((sphere ^ up(0.0, -1.0, 0.0)).e12345, 0.0);
//! assert_ne!((sphere ^ up(0.0, -2.0, 0.0)).e12345, 0.0);
//! ```
//!
//! # Basis and metric
//!
//! Five generators: `e1, e2, e3` (Euclidean space) and `e4 = e+`, `e5 = e-`, with
//! `e1² = e2² = e3² = e4² = 1` and `e5² = -1`. Every blade is the product of its generators in
//! increasing order (`e13 = e1 e3`, no reordered names), and the thirty-two blades, in the
//! order of [`Multivector::from_array`], `to_array` and the types' fields, go by grade and, within
//! a grade, lexicographically:
//!
//! `1, e1, e2, e3, e4, e5, e12, e13, e14, e15, e23, e24, e25, e34, e35, e45, e123, e124, e125,
//! e134, e135, e145, e234, e235, e245, e345, e1234, e1235, e1245, e1345, e2345, e12345`.
//!
//! The null basis is `eₒ = (e5 - e4)/2` (the origin) and `e∞ = e4 + e5` (the point at
//! infinity), with `eₒ² = e∞² = 0` and `eₒ · e∞ = -1`. A Euclidean point `x` is
//! `up(x) = x + x²/2 e∞ + eₒ` (the example above writes it out), and a null vector `X` maps back
//! by `down(X) = (X₁, X₂, X₃) / (-X · e∞)`, the Euclidean part divided by the weight.
//!
//! | type | blades | holds |
//! |------|--------|-------|
//! | [`Vector`] | grade 1 | points, dual spheres, dual planes |
//! | [`Bivector`] | grade 2 | point pairs (dual), generators of motions |
//! | [`Trivector`] | grade 3 | circles, lines |
//! | [`Quadvector`] | grade 4 | spheres, planes |
//! | [`Pseudoscalar`] | `e12345` | |
//! | [`Rotor`] | `1, e12, e13, e23` | rotations about the origin |
//! | [`Motor`] | grades 0, 2, 4 | rotors, translators, dilators and their products |
//! | [`Multivector`] | all thirty-two | |
//!
//! # Operators
//!
//! As in [`crate::g3`], each operator means one thing and every product returns the smallest
//! type holding every blade it can produce (identically-zero pairs have no impl):
//!
//! - `a * b` geometric product, `a ^ b` outer product;
//! - `a | b` the **left contraction** `a ⌋ b` (Dorst's choice for CGA): grade `s - r` of the
//!   product of an `r`-blade and an `s`-blade, zero when `r > s`, a scalar on the left scales;
//!   so `X | Y = X · Y` for vectors and `X | S` is the inner product of a point with a dual
//!   sphere;
//! - `a & b` the regressive product through the metric-free complements,
//!   `undual(dual(a) ^ dual(b))` with the complements of [`crate::pga`]'s dual;
//! - `left_contraction` (equal to `|`), `right_contraction`, `scalar_product`, `commutator` and
//!   `sandwich` are methods (traits in [`crate::products`]).
//!
//! # Dual
//!
//! The pseudoscalar `I = e12345` squares to `-1`, so `dual(A) = A I⁻¹ = -A I` and
//! `undual(A) = A I`; `undual(dual(A)) = A`. The dual of a quadvector (a sphere) is a vector
//! (the dual sphere).
//!
//! These are the types and products, written by `ga-codegen` from its table (except
//! `Multivector * Multivector`, in `geometric.rs`: the generated lane-by-lane AVX2 kernel, or
//! sixteen G3 products where the build lacks AVX2, checked against the generated expansion),
//! with the matrix of a motor's sandwich on vectors ([`Motor::vector_map`]); geometry (round
//! and flat objects, meets, reflections, rotors, translators, dilators, `exp` and `log`, the
//! closed-form line through two points and its meet with a plane, a motor applied to many
//! points) is built on them by hand in [`geometry`], as methods of these types.
//!
//! # Cayley table of the geometric product
//!
//! Row times column, `e_row e_col`:
//!
#![doc = include_str!("generated/cayley.md")]
//!
//! # Result types
//!
//! The type each product returns for each pair of types (`T` a scalar, `—` no impl: the
//! product is identically zero), as generated:
//!
#![doc = include_str!("generated/products.md")]

pub(crate) mod generated;
pub(crate) mod geometric;
pub mod geometry;
#[cfg(all(target_arch = "x86_64", target_feature = "avx2", target_feature = "fma"))]
pub(crate) mod simd;

pub use generated::{
    Bivector, Motor, Multivector, Pseudoscalar, Quadvector, Rotor, Trivector, Vector,
};
