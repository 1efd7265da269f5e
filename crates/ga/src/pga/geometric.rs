//! The geometric products of R(3,0,1) that are not the generated term-by-term expansions.
//!
//! # `Multivector * Multivector`: lane by lane, or three G3 products
//!
//! Where the build has AVX2 and FMA, the product is the kernel `ga-codegen` writes to
//! `generated/lanes.rs`: blades by bitmask, `e0` the block bit and `e1, e2, e3` the lane bits
//! (f32; f64 makes `e3` a second block bit), so output block `B` is a sum of broadcast
//! coefficients of `a` times signed lane permutations of the blocks of `b`, and the products
//! that meet `e0` twice are whole blocks never formed: 24 eight-lane fused multiply-adds for
//! the 192 non-zero terms (the derivation is in `crates/ga-codegen/src/lanes.rs`).
//!
//! Elsewhere it is `blockwise`: every blade of R(3,0,1) is a blade of G3 or `e0` times one,
//! so `a = A + e0 A'` and `b = B + e0 B'` with `A, A', B, B'` in G3. `e0` anticommutes with
//! `e1, e2, e3`, so `X e0 = e0 X̂` (the grade involution), and `e0² = 0`:
//!
//! `a b = A B + e0 (Â B' + A' B)`.
//!
//! That is three G3 geometric products, 192 terms: exactly the non-zero entries of the 16 x 16
//! Cayley table. Each product is G3's kernel behind `T::geometric_product`. The split into G3
//! parts is a relabelling: `e0` times `e1, e2, e3, e123` are `e01, e02, e03, e0123`, and times
//! `e12, e31, e23` are `e012 = -e021`, `e031 = -e013`, `e023 = -e032`, so those three lanes
//! change sign.
//!
//! Both forms sum the same products as the expansion for each coefficient, in another order.
//!
//! # `Motor * Motor`: dual quaternions
//!
//! A motor is `M = R + I τ` with `R` and `τ` rotors of G3 and `I = e0123`, which commutes
//! with every even element and squares to zero. With `e0123 e12 = -e03`, `e0123 e23 = -e01`
//! and `e0123 e31 = -e02`, in the lane order `[s, e12, e23, e31]` of `g3::Rotor::to_array`
//! the rotor is `R = [s, e12, e23, e31]` and `τ = [e0123, -e03, -e01, -e02]`. For
//! `N = S + I σ`:
//!
//! `M N = R S + I (R σ + τ S)`,
//!
//! three quaternion products (G3's `T::rotor_product`, an SSE kernel for f32): the 48 terms of
//! the expansion, on four lanes. That is the portable kernel. Where the build has AVX2 and FMA,
//! `pga::simd` writes the same sum as eight terms, one per blade `x` of the left motor: a
//! broadcast of its coefficient times a signed lane permutation of the right one, the
//! permutations and signs worked out at compile time from the blades' bitmasks. f32 holds a
//! motor in one 8-lane register, in storage order; f64 holds it as the two quaternions above
//! (`R` and `I τ` lane by lane), where a blade without `e0` permutes both alike and one with
//! `e0` takes `R`'s lanes to `τ`'s: twelve 4-lane terms.
//!
//! The tests check every kernel here against the generated term-by-term expansions.

use core::ops::{Mul, MulAssign};

use crate::Scalar;
use crate::pga::{Motor, Multivector};

/// `a` as `A + e0 A'`: the two G3 multivectors in G3's storage order
/// (`1, e1, e2, e12, e3, e31, e23, e123`).
#[inline]
fn split<T: Scalar>(a: Multivector<T>) -> ([T; 8], [T; 8]) {
    (
        [a.s, a.e1, a.e2, a.e12, a.e3, a.e31, a.e23, a.e123],
        [a.e0, a.e01, a.e02, -a.e021, a.e03, -a.e013, -a.e032, a.e0123],
    )
}

/// The grade involution of a G3 multivector in storage order (G3's `grade_involution`).
#[inline]
fn involution<T: Scalar>(c: [T; 8]) -> [T; 8] {
    crate::g3::Multivector { c }.grade_involution().c
}

/// Geometric product `Multivector * Multivector -> Multivector`: the generated lane-by-lane
/// kernel of `generated/lanes.rs` where the build has AVX2 and FMA, else `blockwise` (the
/// portable kernel below).
impl<T: Scalar> Mul<Multivector<T>> for Multivector<T> {
    type Output = Multivector<T>;
    #[inline]
    fn mul(self, b: Multivector<T>) -> Multivector<T> {
        // In place: through copies (`to_array`), the kernel's vector loads would wait on the
        // copies' narrower stores (store forwarding fails).
        Multivector::from_array(T::pga_geometric(self.as_array(), b.as_array()))
    }
}

/// `a b` as `A B + e0 (Â B' + A' B)`, the three G3 products of the module docs (coefficients
/// in basis order): the portable kernel.
#[cfg_attr(
    all(target_arch = "x86_64", target_feature = "avx2", target_feature = "fma", not(test)),
    allow(dead_code)
)]
#[inline]
pub(crate) fn blockwise<T: Scalar>(a: &[T; 16], b: &[T; 16]) -> [T; 16] {
    let ((a0, a1), (b0, b1)) =
        (split(Multivector::from_array(*a)), split(Multivector::from_array(*b)));
    let c = T::geometric_product(&a0, &b0);
    let x = T::geometric_product(&involution(a0), &b1);
    let y = T::geometric_product(&a1, &b0);
    let d: [T; 8] = core::array::from_fn(|i| x[i] + y[i]);
    Multivector {
        s: c[0],
        e0: d[0],
        e1: c[1],
        e2: c[2],
        e3: c[4],
        e01: d[1],
        e02: d[2],
        e03: d[4],
        e12: c[3],
        e31: c[5],
        e23: c[6],
        e021: -d[3],
        e013: -d[5],
        e032: -d[6],
        e123: c[7],
        e0123: d[7],
    }
    .to_array()
}

/// Geometric product `Motor * Motor -> Motor`: composition of motions (`(M2 * M1)` applies
/// `M1` first): the lane kernels of `pga::simd` where the build has AVX2 and FMA, else the
/// dual-quaternion form `R S + I (R σ + τ S)` of the module docs.
impl<T: Scalar> Mul<Motor<T>> for Motor<T> {
    type Output = Motor<T>;
    #[inline]
    fn mul(self, b: Motor<T>) -> Motor<T> {
        if let Some(c) = T::pga_motor_product(self.as_array(), b.as_array()) {
            return Motor::from_array(c);
        }
        // Rotor lanes `[s, e12, e23, e31]`; the e0 half as I times a rotor.
        let rotor = |m: Motor<T>| [m.s, m.e12, m.e23, m.e31];
        let dual = |m: Motor<T>| [m.e0123, -m.e03, -m.e01, -m.e02];
        let (r, tau, s, sigma) = (rotor(self), dual(self), rotor(b), dual(b));
        let rs = T::rotor_product(r, s);
        let (x, y) = (T::rotor_product(r, sigma), T::rotor_product(tau, s));
        let u: [T; 4] = core::array::from_fn(|i| x[i] + y[i]);
        Motor {
            s: rs[0],
            e01: -u[2],
            e02: -u[3],
            e03: -u[1],
            e12: rs[1],
            e31: rs[3],
            e23: rs[2],
            e0123: u[0],
        }
    }
}

impl<T: Scalar> MulAssign for Motor<T> {
    /// `self = self * rhs`: the composite applies `rhs` first, then the old `self`.
    #[inline]
    fn mul_assign(&mut self, rhs: Self) {
        *self = *self * rhs;
    }
}

impl<T: Scalar> MulAssign for Multivector<T> {
    /// `self = self * rhs`.
    #[inline]
    fn mul_assign(&mut self, rhs: Self) {
        *self = *self * rhs;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::g3::geometric::tests::{close, coefficients};
    use crate::pga::generated::{geometric_motor_motor, geometric_multivector_multivector};

    /// Both kernels against the generated 192- and 64-term expansions, in both precisions.
    #[test]
    fn hand_kernels_match_the_generated_expansions() {
        let mut x = coefficients(11);
        for _ in 0..1000 {
            let a = Multivector::<f64>::from_array(core::array::from_fn(|_| x.next().unwrap()));
            let b = Multivector::<f64>::from_array(core::array::from_fn(|_| x.next().unwrap()));
            let want = geometric_multivector_multivector(a, b).to_array();
            assert!(close((a * b).to_array(), want, 1e-14), "{a:?} {b:?}");
            assert!(close(blockwise(&a.to_array(), &b.to_array()), want, 1e-14), "{a:?} {b:?}");
            let f = |m: Multivector<f64>| Multivector::from_array(m.to_array().map(|v| v as f32));
            let want32 = geometric_multivector_multivector(f(a), f(b)).to_array().map(f64::from);
            let got32 = (f(a) * f(b)).to_array().map(f64::from);
            assert!(close(got32, want32, 1e-5), "{a:?} {b:?}");
            let got32 = blockwise(&f(a).to_array(), &f(b).to_array()).map(f64::from);
            assert!(close(got32, want32, 1e-5), "{a:?} {b:?}");

            let m = |x: &mut dyn Iterator<Item = f64>| {
                Motor::<f64>::from_array(core::array::from_fn(|_| x.next().unwrap()))
            };
            let (p, q) = (m(&mut x), m(&mut x));
            assert!(close((p * q).to_array(), geometric_motor_motor(p, q).to_array(), 1e-14));
            let g = |m: Motor<f64>| Motor::from_array(m.to_array().map(|v| v as f32));
            let got32 = (g(p) * g(q)).to_array().map(f64::from);
            let want32 = geometric_motor_motor(g(p), g(q)).to_array().map(f64::from);
            assert!(close(got32, want32, 1e-5), "{p:?} {q:?}");
        }
    }

    /// Each basis blade of the motors times each, exactly, in both precisions.
    #[test]
    fn basis_motor_products_are_the_cayley_table() {
        fn check<T: Scalar>() {
            let e = |k: usize| {
                Motor::<T>::from_array(core::array::from_fn(|n| {
                    T::from_f64(f64::from(u8::from(n == k)))
                }))
            };
            for i in 0..8 {
                for j in 0..8 {
                    assert_eq!(e(i) * e(j), geometric_motor_motor(e(i), e(j)), "{i} {j}");
                }
            }
        }
        check::<f32>();
        check::<f64>();
    }

    /// The relabelling alone: each basis blade times each is the Cayley table's entry.
    #[test]
    fn basis_products_are_the_cayley_table() {
        let e = |k: usize| {
            Multivector::<f64>::from_array(core::array::from_fn(|n| f64::from(u8::from(n == k))))
        };
        for i in 0..16 {
            for j in 0..16 {
                let want = geometric_multivector_multivector(e(i), e(j)).to_array();
                assert_eq!((e(i) * e(j)).to_array(), want, "{i} {j}");
                assert_eq!(blockwise(&e(i).to_array(), &e(j).to_array()), want, "{i} {j}");
            }
        }
    }
}
