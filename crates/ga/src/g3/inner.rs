//! The report's inner product `|` between the G3 types.
//!
//! For an `r`-blade and an `s`-blade, `a | b` is the grade `|r - s|` part of their geometric
//! product, and it is zero when either side is a scalar (report figure 2.7; this is Hestenes'
//! inner product, not a contraction). So `e1 | e12 = e2`, `e12 | e1 = -e2` and
//! `e12 | e12 = -1`: two bivectors of the same orientation have a *negative* inner product.
//! The contractions are the methods `left_contraction` and `right_contraction` (see
//! [`contraction`](crate::g3::contraction)).
//!
//! Every pair of types has the operator; a rotor's scalar part takes no part. Result types,
//! `a | b` (`T` is the scalar):
//!
//! | `a` \ `b` | Vector | Bivector | Trivector | Rotor | Multivector |
//! |---|---|---|---|---|---|
//! | Vector | `T` | Vector | Bivector | Vector | Multivector |
//! | Bivector | Vector | `T` | Vector | `T` | Multivector |
//! | Trivector | Bivector | Vector | `T` | Vector | Multivector |
//! | Rotor | Vector | `T` | Vector | `T` | Multivector |
//! | Multivector | Multivector | Multivector | Multivector | Multivector | Multivector |
//!
//! The kernels are written by `ga-codegen` (`g3/generated/inner.rs`) with only their non-zero
//! terms; the tests check every pair against the `ga-reference` crate.
