//! The outer (wedge) product `^` between the G3 types where it is not identically zero.
//!
//! `a ^ b` keeps the grade `r + s` part of the geometric product of an `r`-blade and an
//! `s`-blade (report figure 2.6). Pairs whose outer product always vanishes in 3D (vector ^
//! trivector, bivector ^ bivector, ...) have no operator; convert to
//! [`Multivector`](crate::g3::Multivector) for generic code. The scalar case is ordinary scaling
//! (`*`).
//!
//! Result types, `a ^ b` (`T` is the scalar, `—` no operator):
//!
//! | `a` \ `b` | Vector | Bivector | Trivector | Rotor | Multivector |
//! |---|---|---|---|---|---|
//! | Vector | Bivector | Trivector | — | Multivector | Multivector |
//! | Bivector | Trivector | — | — | Bivector | Multivector |
//! | Trivector | — | — | — | Trivector | Trivector |
//! | Rotor | Multivector | Bivector | Trivector | Rotor | Multivector |
//! | Multivector | Multivector | Multivector | Trivector | Multivector | Multivector |
//!
//! The kernels are written by `ga-codegen` (`g3/generated/outer.rs`) with only their non-zero
//! terms; the tests check every pair against the `ga-reference` crate.
