//! Geometric algebra for the wedge ray tracers.
//!
//! [`g3`] is the algebra G(3,0,0) of Euclidean 3D space with a type per grade, [`pga`] the
//! projective algebra R(3,0,1) and [`cga`] the conformal algebra R(4,1); [`errata`] lists
//! what the report this project starts from gets wrong and what the code does instead. The
//! products are written by the `ga-codegen` crate from a table of algebras and checked against
//! the generic (slow, obviously correct) Clifford algebra of the `ga-reference` crate, which `ga`
//! itself does not depend on.
//!
//! ```
//! use ga::g3::{Bivector, Multivector, Rotor, Vector};
//!
//! let (a, b) = (Vector::new(1.0, 0.0, 0.0), Vector::new(1.0, 1.0, 0.0));
//! // The geometric product of two vectors is a scalar (the inner product) plus a bivector
//! // (the outer product): a b = a | b + a ^ b.
//! let ab = a * b;
//! assert_eq!(ab.s, a | b);
//! assert_eq!(ab.bivector(), a ^ b);
//! assert_eq!((a ^ b).to_string(), "1e12");
//!
//! // A quarter turn in the e12 plane takes e1 to e2.
//! let r = Rotor::from_angle_plane(std::f64::consts::FRAC_PI_2, Bivector::E12);
//! assert!(r.rotate(Vector::E1).abs_diff_eq(Vector::E2, 1e-15));
//!
//! // Every multivector of G3 that has an inverse gets it in closed form.
//! let m = Multivector::from_array([1.0, 2.0, 0.0, 0.0, 0.5, 0.0, 0.0, 3.0]);
//! let one = m * m.inverse().unwrap();
//! assert!(one.abs_diff_eq(Multivector::ONE, 1e-15));
//! assert_eq!(m.to_string(), "1 + 2e1 + 0.5e12 + 3e123");
//! ```
//!
//! The projective and conformal algebras have the same operators (each module states its
//! basis, metric, dual and Cayley table):
//!
//! ```
//! use ga::{cga, pga};
//!
//! // PGA: the planes x = 0 and y = 0 meet (^) in the z axis, which the origin lies on (its
//! // join & with the origin spans no plane).
//! let line = pga::Plane::new(0.0, 1.0, 0.0, 0.0) ^ pga::Plane::new(0.0, 0.0, 1.0, 0.0);
//! assert_eq!(line & pga::Point::new(0.0, 0.0, 0.0, 1.0), pga::Plane::ZERO);
//!
//! // CGA: the origin e_o = (e5 - e4)/2 is a null vector, and so is e_inf = e4 + e5.
//! let origin = cga::Vector::new(0.0, 0.0, 0.0, -0.5, 0.5);
//! let infinity = cga::Vector::new(0.0, 0.0, 0.0, 1.0, 1.0);
//! assert_eq!((origin | origin, infinity | infinity, origin | infinity), (0.0, 0.0, -1.0));
//! ```
//!
//! # Conventions
//!
//! - **Basis and order.** `1, e1, e2, e3, e12, e23, e31, e123` (the report's order), used by
//!   [`g3::Multivector::from_array`], `to_array` and `Display`. The third bivector is
//!   `e31 = e3 e1`, not `e13`, so the dual maps `e23, e31, e12` to `e1, e2, e3` without signs.
//! - **Metric.** Euclidean, signature (+,+,+): `e1² = e2² = e3² = 1`, so every bivector and the
//!   pseudoscalar square to negative scalars (`e12² = -1`, `e123² = -1`).
//! - **Handedness.** Right-handed: the unit pseudoscalar is `I = e123 = e1 e2 e3`, and
//!   `(e1 ∧ e2)* = e3`, i.e. `(a ∧ b)* = a × b`.
//! - **Operators.** Each means one thing, for every pair of types it is defined on:
//!
//!   | operator | product | e.g. |
//!   |----------|---------|------|
//!   | `a * b` | geometric | `e1 * e2 = e12`, `e1 * e1 = 1` |
//!   | `a ^ b` | outer (wedge) | `e1 ^ e2 = e12`, `e1 ^ e1 = 0` |
//!   | `a \| b` | the report's inner product (below) | `e1 \| e12 = e2`, `e12 \| e12 = -1` |
//!   | `a & b` | regressive (meet) | `e12 & e23 = -e2` |
//!   | `a + b`, `a - b`, `-a` | component-wise | |
//!   | `a * s`, `s * a`, `a / s` | scaling by a scalar `s` | |
//!
//!   Left and right contractions, the scalar product and the commutator are methods
//!   (`a.left_contraction(b)`, `right_contraction`, `scalar_product`, `commutator`) on every
//!   pair of types where they are not identically zero, through the traits listed in
//!   [`g3::contraction`]. Rust's precedence is fixed: `*` and `/` bind tighter than `+` and
//!   `-`, then come `&`, `^` and `|`, in that order. So `a + b ^ c` is `(a + b) ^ c`, not the usual
//!   mathematical reading `a + (b ∧ c)`: write the parentheses.
//! - **Inner product.** `|` is the report's (figure 2.7, Hestenes' inner product): for an
//!   `r`-blade and an `s`-blade, the grade `|r - s|` part of the geometric product, and zero
//!   when either side is a scalar. It is not the left contraction (which scales by scalars and
//!   vanishes for `r > s`).
//! - **Dual.** `A* = A I⁻¹` with `I⁻¹ = -I` (report 2.3.3); `undual(A) = A I` inverts it. A
//!   bivector's dual is its normal: `e12* = e3`.
//! - **Regressive product.** `A & B = undual(dual(A) ^ dual(B)) = ((A I⁻¹) ∧ (B I⁻¹)) I`.
//! - **Products return the smallest type** that holds every grade they can produce:
//!   `Vector * Vector -> Rotor`, `Vector ^ Vector -> Bivector`, `Vector | Vector -> T`,
//!   `Bivector & Bivector -> Vector`. Results with vector and trivector parts (odd) are
//!   [`g3::Multivector`]. Pairs whose product is identically zero in 3D (`Vector ^ Trivector`,
//!   `Vector & Vector`, ...) have no operator.
//! - **Rotations.** A rotor `R = exp(-B θ/2) = cos(θ/2) - B sin(θ/2)` with `B` a unit bivector
//!   acts as `x' = R x R̃` and turns by `+θ` from the plane's first vector toward its second
//!   (`e1` toward `e2` for `B = e12`). As a quaternion that is `w = s`,
//!   `(x, y, z) = -(e23, e31, e12)`: the same rotation as glam's right-handed `Quat`.
//! - **Scalars.** Every type is generic over [`Scalar`], implemented for `f32` and `f64` only.
//!   The products, sums and negations take any [`Coefficient`], so that they also act on
//!   [`Lanes4`], four floats side by side: `Vector<Lanes4<f32>>` is four vectors, and its
//!   products are those of each lane, bit for bit ([`lanes`]).
//!
//! # The `glam` feature
//!
//! Adds `From` conversions between [`g3::Vector`] and glam's `Vec3`, `Vec3A` (f32) and `DVec3`
//! (f64), component-wise, and between [`g3::Rotor`] and `Quat` (f32) and `DQuat` (f64) by
//! `w = s`, `(x, y, z) = -(e23, e31, e12)`. The quaternion units are the negated basis
//! bivectors `i = -e23`, `j = -e31`, `k = -e12` (check: `i j = e23 e31 = -e12 = k`); a rotor
//! about the unit axis `n` is `cos(θ/2) - (n I) sin(θ/2)` with `n I = n1 e23 + n2 e31 + n3 e12`,
//! and glam's quaternion is `cos(θ/2) + (n1 i + n2 j + n3 k) sin(θ/2)`. Both rotate
//! right-handedly about `n`, so `Rotor::rotate` and `Quat * Vec3` agree, and so do products in
//! the same order (tested).

#![deny(missing_docs)]

pub mod cga;
pub mod errata;
pub mod g3;
pub mod lanes;
pub mod pga;
pub mod products;
mod scalar;

pub use lanes::{Coefficient, Lanes4};
/// The workspace's one float trait, which [`Scalar`] extends: re-exported so that code using
/// `ga` can name its items by path (`<T as ga::Real>::ZERO`, `.map(ga::Real::to_f64)`).
pub use real::Real;
pub use scalar::Scalar;
