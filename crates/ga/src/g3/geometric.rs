//! The geometric product `*` between every pair of G3 types.
//!
//! Each kernel is the bilinear expansion of its two operands over the Cayley table below (row
//! times column, with `e31 = e3 e1`), keeping only the terms whose blades both types hold, so
//! no zero grade is ever multiplied. The result is the smallest type holding every grade that
//! can appear: vector times vector is a [`Rotor`] (scalar plus bivector), vector times bivector
//! is odd (vector plus trivector) and so a [`Multivector`]. The tests in `tests/` compare every
//! kernel against the generic bitmask algebra in the generic algebra of the `ga-reference` crate.
//!
//! |  ·   |  1   |  e1  |  e2  |  e3  | e12  | e23  | e31  | e123 |
//! |------|------|------|------|------|------|------|------|------|
//! | 1    |   1  |  e1  |  e2  |  e3  |  e12 |  e23 |  e31 | e123 |
//! | e1   |  e1  |   1  |  e12 | -e31 |  e2  | e123 | -e3  |  e23 |
//! | e2   |  e2  | -e12 |   1  |  e23 | -e1  |  e3  | e123 |  e31 |
//! | e3   |  e3  |  e31 | -e23 |   1  | e123 | -e2  |  e1  |  e12 |
//! | e12  |  e12 | -e2  |  e1  | e123 |  -1  | -e31 |  e23 | -e3  |
//! | e23  |  e23 | e123 | -e3  |  e2  |  e31 |  -1  | -e12 | -e1  |
//! | e31  |  e31 |  e3  | e123 | -e1  | -e23 |  e12 |  -1  | -e2  |
//! | e123 | e123 |  e23 |  e31 |  e12 | -e3  | -e1  | -e2  |  -1  |
//!
//! (Report figure 2.5 prints this table transposed: its entry in row `e1`, column `e2` is
//! `-e12`, which is `e2 e1`; see [`crate::errata`].)
//!
//! # The full product
//!
//! `Multivector * Multivector` needs all 64 terms. On x86-64 with AVX2 and FMA it uses the
//! structure of the table in the bitmask basis `1, e1, e2, e12, e3, e13, e23, e123`, where
//! `e_k e_j = ±e_(k XOR j)`: `a b = Σ_k a_k (e_k b)`, and `e_k b` is `b` with its lanes permuted
//! by `l ↦ l XOR k` (in-register shuffles) and a fixed sign pattern. With `b` in two 4-lane
//! registers that is 16 fused multiply-adds, 6 shuffles and 6 sign flips; `Multivector` stores
//! its coefficients in that order (with `e31` for `e13`) so no reordering is needed. Other
//! targets use the 64 terms written out. `Rotor * Rotor` uses the same idea on the four lanes
//! `1, e12, e23, e31` (bitmasks `0, 3, 6, 5`, closed under XOR), like a quaternion product.

// The operator traits name the product (`Mul`, `BitXor`, ...) but each kernel is a sum of
// products of coefficients, which is what clippy's heuristic flags.
#![allow(clippy::suspicious_arithmetic_impl)]

use core::ops::{Mul, MulAssign};

use crate::Scalar;
use crate::g3::{Bivector, Multivector, Rotor, Trivector, Vector};

/// Geometric product `Vector * Vector -> Rotor`.
impl<T: Scalar> Mul<Vector<T>> for Vector<T> {
    type Output = Rotor<T>;
    #[inline]
    fn mul(self, b: Vector<T>) -> Rotor<T> {
        // Blade products: e1 e1 = 1, e1 e2 = e12, e1 e3 = -e31, e2 e1 = -e12, e2 e2 = 1,
        //   e2 e3 = e23, e3 e1 = e31, e3 e2 = -e23, e3 e3 = 1
        let a = self;
        Rotor {
            s: a.e1 * b.e1 + a.e2 * b.e2 + a.e3 * b.e3,
            e12: a.e1 * b.e2 - a.e2 * b.e1,
            e23: a.e2 * b.e3 - a.e3 * b.e2,
            e31: a.e3 * b.e1 - a.e1 * b.e3,
        }
    }
}

/// Geometric product `Vector * Bivector -> Multivector`.
impl<T: Scalar> Mul<Bivector<T>> for Vector<T> {
    type Output = Multivector<T>;
    #[inline]
    fn mul(self, b: Bivector<T>) -> Multivector<T> {
        // Blade products: e1 e12 = e2, e1 e23 = e123, e1 e31 = -e3, e2 e12 = -e1, e2 e23 = e3,
        //   e2 e31 = e123, e3 e12 = e123, e3 e23 = -e2, e3 e31 = e1
        let a = self;
        Multivector::new(
            T::ZERO,
            a.e3 * b.e31 - a.e2 * b.e12,
            a.e1 * b.e12 - a.e3 * b.e23,
            a.e2 * b.e23 - a.e1 * b.e31,
            T::ZERO,
            T::ZERO,
            T::ZERO,
            a.e1 * b.e23 + a.e2 * b.e31 + a.e3 * b.e12,
        )
    }
}

/// Geometric product `Vector * Trivector -> Bivector`.
impl<T: Scalar> Mul<Trivector<T>> for Vector<T> {
    type Output = Bivector<T>;
    #[inline]
    fn mul(self, b: Trivector<T>) -> Bivector<T> {
        // Blade products: e1 e123 = e23, e2 e123 = e31, e3 e123 = e12
        let a = self;
        Bivector { e12: a.e3 * b.e123, e23: a.e1 * b.e123, e31: a.e2 * b.e123 }
    }
}

/// Geometric product `Vector * Rotor -> Multivector`.
impl<T: Scalar> Mul<Rotor<T>> for Vector<T> {
    type Output = Multivector<T>;
    #[inline]
    fn mul(self, b: Rotor<T>) -> Multivector<T> {
        // Blade products: e1 s = e1, e1 e12 = e2, e1 e23 = e123, e1 e31 = -e3, e2 s = e2,
        //   e2 e12 = -e1, e2 e23 = e3, e2 e31 = e123, e3 s = e3, e3 e12 = e123, e3 e23 = -e2,
        //   e3 e31 = e1
        let a = self;
        Multivector::new(
            T::ZERO,
            a.e1 * b.s - a.e2 * b.e12 + a.e3 * b.e31,
            a.e1 * b.e12 + a.e2 * b.s - a.e3 * b.e23,
            a.e2 * b.e23 - a.e1 * b.e31 + a.e3 * b.s,
            T::ZERO,
            T::ZERO,
            T::ZERO,
            a.e1 * b.e23 + a.e2 * b.e31 + a.e3 * b.e12,
        )
    }
}

/// Geometric product `Vector * Multivector -> Multivector`.
impl<T: Scalar> Mul<Multivector<T>> for Vector<T> {
    type Output = Multivector<T>;
    #[inline]
    fn mul(self, b: Multivector<T>) -> Multivector<T> {
        // The Cayley-table terms (module docs) whose factors both types hold.
        let a = self;
        Multivector::new(
            a.e1 * b.e1() + a.e2 * b.e2() + a.e3 * b.e3(),
            a.e1 * b.s() - a.e2 * b.e12() + a.e3 * b.e31(),
            a.e1 * b.e12() + a.e2 * b.s() - a.e3 * b.e23(),
            a.e2 * b.e23() - a.e1 * b.e31() + a.e3 * b.s(),
            a.e1 * b.e2() - a.e2 * b.e1() + a.e3 * b.e123(),
            a.e1 * b.e123() + a.e2 * b.e3() - a.e3 * b.e2(),
            a.e2 * b.e123() - a.e1 * b.e3() + a.e3 * b.e1(),
            a.e1 * b.e23() + a.e2 * b.e31() + a.e3 * b.e12(),
        )
    }
}

/// Geometric product `Bivector * Vector -> Multivector`.
impl<T: Scalar> Mul<Vector<T>> for Bivector<T> {
    type Output = Multivector<T>;
    #[inline]
    fn mul(self, b: Vector<T>) -> Multivector<T> {
        // Blade products: e12 e1 = -e2, e12 e2 = e1, e12 e3 = e123, e23 e1 = e123, e23 e2 = -e3,
        //   e23 e3 = e2, e31 e1 = e3, e31 e2 = e123, e31 e3 = -e1
        let a = self;
        Multivector::new(
            T::ZERO,
            a.e12 * b.e2 - a.e31 * b.e3,
            a.e23 * b.e3 - a.e12 * b.e1,
            a.e31 * b.e1 - a.e23 * b.e2,
            T::ZERO,
            T::ZERO,
            T::ZERO,
            a.e12 * b.e3 + a.e23 * b.e1 + a.e31 * b.e2,
        )
    }
}

/// Geometric product `Bivector * Bivector -> Rotor`.
impl<T: Scalar> Mul<Bivector<T>> for Bivector<T> {
    type Output = Rotor<T>;
    #[inline]
    fn mul(self, b: Bivector<T>) -> Rotor<T> {
        // Blade products: e12 e12 = -1, e12 e23 = -e31, e12 e31 = e23, e23 e12 = e31,
        //   e23 e23 = -1, e23 e31 = -e12, e31 e12 = -e23, e31 e23 = e12, e31 e31 = -1
        let a = self;
        Rotor {
            s: -a.e12 * b.e12 - a.e23 * b.e23 - a.e31 * b.e31,
            e12: a.e31 * b.e23 - a.e23 * b.e31,
            e23: a.e12 * b.e31 - a.e31 * b.e12,
            e31: a.e23 * b.e12 - a.e12 * b.e23,
        }
    }
}

/// Geometric product `Bivector * Trivector -> Vector`.
impl<T: Scalar> Mul<Trivector<T>> for Bivector<T> {
    type Output = Vector<T>;
    #[inline]
    fn mul(self, b: Trivector<T>) -> Vector<T> {
        // Blade products: e12 e123 = -e3, e23 e123 = -e1, e31 e123 = -e2
        let a = self;
        Vector { e1: -a.e23 * b.e123, e2: -a.e31 * b.e123, e3: -a.e12 * b.e123 }
    }
}

/// Geometric product `Bivector * Rotor -> Rotor`.
impl<T: Scalar> Mul<Rotor<T>> for Bivector<T> {
    type Output = Rotor<T>;
    #[inline]
    fn mul(self, b: Rotor<T>) -> Rotor<T> {
        // Blade products: e12 s = e12, e12 e12 = -1, e12 e23 = -e31, e12 e31 = e23, e23 s = e23,
        //   e23 e12 = e31, e23 e23 = -1, e23 e31 = -e12, e31 s = e31, e31 e12 = -e23,
        //   e31 e23 = e12, e31 e31 = -1
        let a = self;
        Rotor {
            s: -a.e12 * b.e12 - a.e23 * b.e23 - a.e31 * b.e31,
            e12: a.e12 * b.s - a.e23 * b.e31 + a.e31 * b.e23,
            e23: a.e12 * b.e31 + a.e23 * b.s - a.e31 * b.e12,
            e31: a.e23 * b.e12 - a.e12 * b.e23 + a.e31 * b.s,
        }
    }
}

/// Geometric product `Bivector * Multivector -> Multivector`.
impl<T: Scalar> Mul<Multivector<T>> for Bivector<T> {
    type Output = Multivector<T>;
    #[inline]
    fn mul(self, b: Multivector<T>) -> Multivector<T> {
        // The Cayley-table terms (module docs) whose factors both types hold.
        let a = self;
        Multivector::new(
            -a.e12 * b.e12() - a.e23 * b.e23() - a.e31 * b.e31(),
            a.e12 * b.e2() - a.e23 * b.e123() - a.e31 * b.e3(),
            a.e23 * b.e3() - a.e12 * b.e1() - a.e31 * b.e123(),
            a.e31 * b.e1() - a.e12 * b.e123() - a.e23 * b.e2(),
            a.e12 * b.s() - a.e23 * b.e31() + a.e31 * b.e23(),
            a.e12 * b.e31() + a.e23 * b.s() - a.e31 * b.e12(),
            a.e23 * b.e12() - a.e12 * b.e23() + a.e31 * b.s(),
            a.e12 * b.e3() + a.e23 * b.e1() + a.e31 * b.e2(),
        )
    }
}

/// Geometric product `Trivector * Vector -> Bivector`.
impl<T: Scalar> Mul<Vector<T>> for Trivector<T> {
    type Output = Bivector<T>;
    #[inline]
    fn mul(self, b: Vector<T>) -> Bivector<T> {
        // Blade products: e123 e1 = e23, e123 e2 = e31, e123 e3 = e12
        let a = self;
        Bivector { e12: a.e123 * b.e3, e23: a.e123 * b.e1, e31: a.e123 * b.e2 }
    }
}

/// Geometric product `Trivector * Bivector -> Vector`.
impl<T: Scalar> Mul<Bivector<T>> for Trivector<T> {
    type Output = Vector<T>;
    #[inline]
    fn mul(self, b: Bivector<T>) -> Vector<T> {
        // Blade products: e123 e12 = -e3, e123 e23 = -e1, e123 e31 = -e2
        let a = self;
        Vector { e1: -a.e123 * b.e23, e2: -a.e123 * b.e31, e3: -a.e123 * b.e12 }
    }
}

/// Geometric product `Trivector * Trivector -> scalar`.
impl<T: Scalar> Mul<Trivector<T>> for Trivector<T> {
    type Output = T;
    #[inline]
    fn mul(self, b: Trivector<T>) -> T {
        // Blade products: e123 e123 = -1
        let a = self;
        -a.e123 * b.e123
    }
}

/// Geometric product `Trivector * Rotor -> Multivector`.
impl<T: Scalar> Mul<Rotor<T>> for Trivector<T> {
    type Output = Multivector<T>;
    #[inline]
    fn mul(self, b: Rotor<T>) -> Multivector<T> {
        // Blade products: e123 s = e123, e123 e12 = -e3, e123 e23 = -e1, e123 e31 = -e2
        let a = self;
        Multivector::new(
            T::ZERO,
            -a.e123 * b.e23,
            -a.e123 * b.e31,
            -a.e123 * b.e12,
            T::ZERO,
            T::ZERO,
            T::ZERO,
            a.e123 * b.s,
        )
    }
}

/// Geometric product `Trivector * Multivector -> Multivector`.
impl<T: Scalar> Mul<Multivector<T>> for Trivector<T> {
    type Output = Multivector<T>;
    #[inline]
    fn mul(self, b: Multivector<T>) -> Multivector<T> {
        // The Cayley-table terms (module docs) whose factors both types hold.
        let a = self;
        Multivector::new(
            -a.e123 * b.e123(),
            -a.e123 * b.e23(),
            -a.e123 * b.e31(),
            -a.e123 * b.e12(),
            a.e123 * b.e3(),
            a.e123 * b.e1(),
            a.e123 * b.e2(),
            a.e123 * b.s(),
        )
    }
}

/// Geometric product `Rotor * Vector -> Multivector`.
impl<T: Scalar> Mul<Vector<T>> for Rotor<T> {
    type Output = Multivector<T>;
    #[inline]
    fn mul(self, b: Vector<T>) -> Multivector<T> {
        // Blade products: s e1 = e1, s e2 = e2, s e3 = e3, e12 e1 = -e2, e12 e2 = e1,
        //   e12 e3 = e123, e23 e1 = e123, e23 e2 = -e3, e23 e3 = e2, e31 e1 = e3, e31 e2 = e123,
        //   e31 e3 = -e1
        let a = self;
        Multivector::new(
            T::ZERO,
            a.s * b.e1 + a.e12 * b.e2 - a.e31 * b.e3,
            a.s * b.e2 - a.e12 * b.e1 + a.e23 * b.e3,
            a.s * b.e3 - a.e23 * b.e2 + a.e31 * b.e1,
            T::ZERO,
            T::ZERO,
            T::ZERO,
            a.e12 * b.e3 + a.e23 * b.e1 + a.e31 * b.e2,
        )
    }
}

/// Geometric product `Rotor * Bivector -> Rotor`.
impl<T: Scalar> Mul<Bivector<T>> for Rotor<T> {
    type Output = Rotor<T>;
    #[inline]
    fn mul(self, b: Bivector<T>) -> Rotor<T> {
        // Blade products: s e12 = e12, s e23 = e23, s e31 = e31, e12 e12 = -1, e12 e23 = -e31,
        //   e12 e31 = e23, e23 e12 = e31, e23 e23 = -1, e23 e31 = -e12, e31 e12 = -e23,
        //   e31 e23 = e12, e31 e31 = -1
        let a = self;
        Rotor {
            s: -a.e12 * b.e12 - a.e23 * b.e23 - a.e31 * b.e31,
            e12: a.s * b.e12 - a.e23 * b.e31 + a.e31 * b.e23,
            e23: a.s * b.e23 + a.e12 * b.e31 - a.e31 * b.e12,
            e31: a.s * b.e31 - a.e12 * b.e23 + a.e23 * b.e12,
        }
    }
}

/// Geometric product `Rotor * Trivector -> Multivector`.
impl<T: Scalar> Mul<Trivector<T>> for Rotor<T> {
    type Output = Multivector<T>;
    #[inline]
    fn mul(self, b: Trivector<T>) -> Multivector<T> {
        // Blade products: s e123 = e123, e12 e123 = -e3, e23 e123 = -e1, e31 e123 = -e2
        let a = self;
        Multivector::new(
            T::ZERO,
            -a.e23 * b.e123,
            -a.e31 * b.e123,
            -a.e12 * b.e123,
            T::ZERO,
            T::ZERO,
            T::ZERO,
            a.s * b.e123,
        )
    }
}

/// Geometric product `Rotor * Multivector -> Multivector`.
impl<T: Scalar> Mul<Multivector<T>> for Rotor<T> {
    type Output = Multivector<T>;
    #[inline]
    fn mul(self, b: Multivector<T>) -> Multivector<T> {
        // The Cayley-table terms (module docs) whose factors both types hold.
        let a = self;
        Multivector::new(
            a.s * b.s() - a.e12 * b.e12() - a.e23 * b.e23() - a.e31 * b.e31(),
            a.s * b.e1() + a.e12 * b.e2() - a.e23 * b.e123() - a.e31 * b.e3(),
            a.s * b.e2() - a.e12 * b.e1() + a.e23 * b.e3() - a.e31 * b.e123(),
            a.s * b.e3() - a.e12 * b.e123() - a.e23 * b.e2() + a.e31 * b.e1(),
            a.s * b.e12() + a.e12 * b.s() - a.e23 * b.e31() + a.e31 * b.e23(),
            a.s * b.e23() + a.e12 * b.e31() + a.e23 * b.s() - a.e31 * b.e12(),
            a.s * b.e31() - a.e12 * b.e23() + a.e23 * b.e12() + a.e31 * b.s(),
            a.s * b.e123() + a.e12 * b.e3() + a.e23 * b.e1() + a.e31 * b.e2(),
        )
    }
}

/// Geometric product `Multivector * Vector -> Multivector`.
impl<T: Scalar> Mul<Vector<T>> for Multivector<T> {
    type Output = Multivector<T>;
    #[inline]
    fn mul(self, b: Vector<T>) -> Multivector<T> {
        // The Cayley-table terms (module docs) whose factors both types hold.
        let a = self;
        Multivector::new(
            a.e1() * b.e1 + a.e2() * b.e2 + a.e3() * b.e3,
            a.s() * b.e1 + a.e12() * b.e2 - a.e31() * b.e3,
            a.s() * b.e2 - a.e12() * b.e1 + a.e23() * b.e3,
            a.s() * b.e3 - a.e23() * b.e2 + a.e31() * b.e1,
            a.e1() * b.e2 - a.e2() * b.e1 + a.e123() * b.e3,
            a.e2() * b.e3 - a.e3() * b.e2 + a.e123() * b.e1,
            a.e3() * b.e1 - a.e1() * b.e3 + a.e123() * b.e2,
            a.e12() * b.e3 + a.e23() * b.e1 + a.e31() * b.e2,
        )
    }
}

/// Geometric product `Multivector * Bivector -> Multivector`.
impl<T: Scalar> Mul<Bivector<T>> for Multivector<T> {
    type Output = Multivector<T>;
    #[inline]
    fn mul(self, b: Bivector<T>) -> Multivector<T> {
        // The Cayley-table terms (module docs) whose factors both types hold.
        let a = self;
        Multivector::new(
            -a.e12() * b.e12 - a.e23() * b.e23 - a.e31() * b.e31,
            a.e3() * b.e31 - a.e2() * b.e12 - a.e123() * b.e23,
            a.e1() * b.e12 - a.e3() * b.e23 - a.e123() * b.e31,
            a.e2() * b.e23 - a.e1() * b.e31 - a.e123() * b.e12,
            a.s() * b.e12 - a.e23() * b.e31 + a.e31() * b.e23,
            a.s() * b.e23 + a.e12() * b.e31 - a.e31() * b.e12,
            a.s() * b.e31 - a.e12() * b.e23 + a.e23() * b.e12,
            a.e1() * b.e23 + a.e2() * b.e31 + a.e3() * b.e12,
        )
    }
}

/// Geometric product `Multivector * Trivector -> Multivector`.
impl<T: Scalar> Mul<Trivector<T>> for Multivector<T> {
    type Output = Multivector<T>;
    #[inline]
    fn mul(self, b: Trivector<T>) -> Multivector<T> {
        // The Cayley-table terms (module docs) whose factors both types hold.
        let a = self;
        Multivector::new(
            -a.e123() * b.e123,
            -a.e23() * b.e123,
            -a.e31() * b.e123,
            -a.e12() * b.e123,
            a.e3() * b.e123,
            a.e1() * b.e123,
            a.e2() * b.e123,
            a.s() * b.e123,
        )
    }
}

/// Geometric product `Multivector * Rotor -> Multivector`.
impl<T: Scalar> Mul<Rotor<T>> for Multivector<T> {
    type Output = Multivector<T>;
    #[inline]
    fn mul(self, b: Rotor<T>) -> Multivector<T> {
        // The Cayley-table terms (module docs) whose factors both types hold.
        let a = self;
        Multivector::new(
            a.s() * b.s - a.e12() * b.e12 - a.e23() * b.e23 - a.e31() * b.e31,
            a.e1() * b.s - a.e2() * b.e12 + a.e3() * b.e31 - a.e123() * b.e23,
            a.e1() * b.e12 + a.e2() * b.s - a.e3() * b.e23 - a.e123() * b.e31,
            a.e2() * b.e23 - a.e1() * b.e31 + a.e3() * b.s - a.e123() * b.e12,
            a.s() * b.e12 + a.e12() * b.s - a.e23() * b.e31 + a.e31() * b.e23,
            a.s() * b.e23 + a.e12() * b.e31 + a.e23() * b.s - a.e31() * b.e12,
            a.s() * b.e31 - a.e12() * b.e23 + a.e23() * b.e12 + a.e31() * b.s,
            a.e1() * b.e23 + a.e2() * b.e31 + a.e3() * b.e12 + a.e123() * b.s,
        )
    }
}

// The products with SIMD kernels, and the assigning operators.

/// Geometric product `Multivector * Multivector -> Multivector`, all 64 terms of the Cayley
/// table. On x86-64 with AVX2 and FMA (this workspace builds with `-C target-cpu=x86-64-v3`)
/// it is the SIMD kernel of the module docs; elsewhere the 64 terms written out.
impl<T: Scalar> Mul<Multivector<T>> for Multivector<T> {
    type Output = Multivector<T>;
    #[inline]
    fn mul(self, b: Multivector<T>) -> Multivector<T> {
        Multivector { c: T::geometric_product(&self.c, &b.c) }
    }
}

/// The geometric product of two multivectors written out term by term (the Cayley table), for
/// targets without a SIMD kernel and as its check.
#[inline]
pub(crate) fn geometric_portable<T: Scalar>(
    a: Multivector<T>,
    b: Multivector<T>,
) -> Multivector<T> {
    Multivector::new(
        a.s() * b.s() + a.e1() * b.e1() + a.e2() * b.e2() + a.e3() * b.e3()
            - a.e12() * b.e12()
            - a.e23() * b.e23()
            - a.e31() * b.e31()
            - a.e123() * b.e123(),
        a.s() * b.e1() + a.e1() * b.s() - a.e2() * b.e12() + a.e3() * b.e31() + a.e12() * b.e2()
            - a.e23() * b.e123()
            - a.e31() * b.e3()
            - a.e123() * b.e23(),
        a.s() * b.e2() + a.e1() * b.e12() + a.e2() * b.s() - a.e3() * b.e23() - a.e12() * b.e1()
            + a.e23() * b.e3()
            - a.e31() * b.e123()
            - a.e123() * b.e31(),
        a.s() * b.e3() - a.e1() * b.e31() + a.e2() * b.e23() + a.e3() * b.s()
            - a.e12() * b.e123()
            - a.e23() * b.e2()
            + a.e31() * b.e1()
            - a.e123() * b.e12(),
        a.s() * b.e12() + a.e1() * b.e2() - a.e2() * b.e1() + a.e3() * b.e123() + a.e12() * b.s()
            - a.e23() * b.e31()
            + a.e31() * b.e23()
            + a.e123() * b.e3(),
        a.s() * b.e23() + a.e1() * b.e123() + a.e2() * b.e3() - a.e3() * b.e2()
            + a.e12() * b.e31()
            + a.e23() * b.s()
            - a.e31() * b.e12()
            + a.e123() * b.e1(),
        a.s() * b.e31() - a.e1() * b.e3() + a.e2() * b.e123() + a.e3() * b.e1() - a.e12() * b.e23()
            + a.e23() * b.e12()
            + a.e31() * b.s()
            + a.e123() * b.e2(),
        a.s() * b.e123()
            + a.e1() * b.e23()
            + a.e2() * b.e31()
            + a.e3() * b.e12()
            + a.e12() * b.e3()
            + a.e23() * b.e1()
            + a.e31() * b.e2()
            + a.e123() * b.s(),
    )
}

/// Geometric product `Rotor * Rotor -> Rotor`: composition of rotations (`(R2 * R1)` applies
/// `R1` first). The same 16 products as a quaternion product; for f32 on x86-64 with AVX2 and
/// FMA it is an SSE kernel, elsewhere the lane-by-lane expansion below.
impl<T: Scalar> Mul<Rotor<T>> for Rotor<T> {
    type Output = Rotor<T>;
    #[inline]
    fn mul(self, b: Rotor<T>) -> Rotor<T> {
        Rotor::from_array(T::rotor_product(self.to_array(), b.to_array()))
    }
}

/// The rotor product written lane by lane, for targets without a SIMD kernel and as its check.
#[inline]
pub(crate) fn rotor_product_portable<T: Scalar>(a: Rotor<T>, b: Rotor<T>) -> Rotor<T> {
    // a b = Σ_k a_k (e_k b) over a's blades 1, e12, e23, e31, with
    //   1 b   = [ b.s,    b.e12,  b.e23,  b.e31]
    //   e12 b = [-b.e12,  b.s,    b.e31, -b.e23]   (e12 e12 = -1, e12 e23 = -e31, e12 e31 = e23)
    //   e23 b = [-b.e23, -b.e31,  b.s,    b.e12]   (e23 e31 = -e12, e23 e12 = e31)
    //   e31 b = [-b.e31,  b.e23, -b.e12,  b.s  ]   (e31 e12 = -e23, e31 e23 = e12)
    // Lanes s, e12, e23, e31 are the blade bitmasks {0, 3, 6, 5}, a group under XOR, so row k
    // reads b's lanes in the order l XOR k and its signs can ride on the broadcast a_k. Written
    // lane by lane with one shape, the optimiser turns it into broadcasts, shuffles and FMAs.
    let (n12, n23, n31) = (-a.e12, -a.e23, -a.e31);
    let lane = |x: [T; 4], y: [T; 4]| {
        x[3].mul_add(y[3], x[2].mul_add(y[2], x[1].mul_add(y[1], x[0] * y[0])))
    };
    Rotor::new(
        lane([a.s, n12, n23, n31], [b.s, b.e12, b.e23, b.e31]),
        lane([a.s, a.e12, n23, a.e31], [b.e12, b.s, b.e31, b.e23]),
        lane([a.s, a.e12, a.e23, n31], [b.e23, b.e31, b.s, b.e12]),
        lane([a.s, n12, a.e23, a.e31], [b.e31, b.e23, b.e12, b.s]),
    )
}

impl<T: Scalar> MulAssign for Rotor<T> {
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
