//! The regressive product (meet) `&` between the G3 types where it is not identically zero.
//!
//! Defined through the dual: `a & b = ((a I⁻¹) ^ (b I⁻¹)) I`, i.e. `undual(dual(a) ^ dual(b))`
//! with `dual(x) = x I⁻¹` and `undual(x) = x I` (see
//! [`Multivector::dual`](crate::g3::Multivector::dual)). It is the outer product of the
//! complements: two planes meet in a line (bivector & bivector is a vector), a
//! plane and a line in a point (bivector & vector is a scalar), and the pseudoscalar `I` is
//! its identity (`I & x = x`). For example `e12 & e23 = -e2` and `e12 & e3 = 1`. Pairs whose
//! meet always vanishes in 3D (vector & vector) have no operator.
//!
//! Result types, `a & b` (`T` is the scalar, `—` no operator):
//!
//! | `a` \ `b` | Vector | Bivector | Trivector | Rotor | Multivector |
//! |---|---|---|---|---|---|
//! | Vector | — | `T` | Vector | `T` | Multivector |
//! | Bivector | `T` | Vector | Bivector | Vector | Multivector |
//! | Trivector | Vector | Bivector | Trivector | Rotor | Multivector |
//! | Rotor | `T` | Vector | Rotor | Vector | Multivector |
//! | Multivector | Multivector | Multivector | Multivector | Multivector | Multivector |
//!
//! The kernels are written by `ga-codegen` (`g3/generated/regressive.rs`) with only their non-zero
//! terms; the tests check every pair against the `ga-reference` crate.
