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

// The operator traits name the product (`Mul`, `BitXor`, ...) but each kernel is a sum of
// products of coefficients, which is what clippy's heuristic flags.
#![allow(clippy::suspicious_arithmetic_impl)]

use core::ops::BitOr;

use crate::Scalar;
use crate::g3::{Bivector, Multivector, Rotor, Trivector, Vector};

/// Inner product (the report's) `Vector | Vector -> scalar`.
impl<T: Scalar> BitOr<Vector<T>> for Vector<T> {
    type Output = T;
    #[inline]
    fn bitor(self, b: Vector<T>) -> T {
        // Blade products: e1 · e1 = 1, e2 · e2 = 1, e3 · e3 = 1
        let a = self;
        a.e1 * b.e1 + a.e2 * b.e2 + a.e3 * b.e3
    }
}

/// Inner product (the report's) `Vector | Bivector -> Vector`.
impl<T: Scalar> BitOr<Bivector<T>> for Vector<T> {
    type Output = Vector<T>;
    #[inline]
    fn bitor(self, b: Bivector<T>) -> Vector<T> {
        // Blade products: e1 · e12 = e2, e1 · e31 = -e3, e2 · e12 = -e1, e2 · e23 = e3,
        //   e3 · e23 = -e2, e3 · e31 = e1
        let a = self;
        Vector {
            e1: a.e3 * b.e31 - a.e2 * b.e12,
            e2: a.e1 * b.e12 - a.e3 * b.e23,
            e3: a.e2 * b.e23 - a.e1 * b.e31,
        }
    }
}

/// Inner product (the report's) `Bivector | Vector -> Vector`.
impl<T: Scalar> BitOr<Vector<T>> for Bivector<T> {
    type Output = Vector<T>;
    #[inline]
    fn bitor(self, b: Vector<T>) -> Vector<T> {
        // Blade products: e12 · e1 = -e2, e12 · e2 = e1, e23 · e2 = -e3, e23 · e3 = e2,
        //   e31 · e1 = e3, e31 · e3 = -e1
        let a = self;
        Vector {
            e1: a.e12 * b.e2 - a.e31 * b.e3,
            e2: a.e23 * b.e3 - a.e12 * b.e1,
            e3: a.e31 * b.e1 - a.e23 * b.e2,
        }
    }
}

/// Inner product (the report's) `Vector | Trivector -> Bivector`.
impl<T: Scalar> BitOr<Trivector<T>> for Vector<T> {
    type Output = Bivector<T>;
    #[inline]
    fn bitor(self, b: Trivector<T>) -> Bivector<T> {
        // Blade products: e1 · e123 = e23, e2 · e123 = e31, e3 · e123 = e12
        let a = self;
        Bivector { e12: a.e3 * b.e123, e23: a.e1 * b.e123, e31: a.e2 * b.e123 }
    }
}

/// Inner product (the report's) `Trivector | Vector -> Bivector`.
impl<T: Scalar> BitOr<Vector<T>> for Trivector<T> {
    type Output = Bivector<T>;
    #[inline]
    fn bitor(self, b: Vector<T>) -> Bivector<T> {
        // Blade products: e123 · e1 = e23, e123 · e2 = e31, e123 · e3 = e12
        let a = self;
        Bivector { e12: a.e123 * b.e3, e23: a.e123 * b.e1, e31: a.e123 * b.e2 }
    }
}

/// Inner product (the report's) `Bivector | Bivector -> scalar`.
impl<T: Scalar> BitOr<Bivector<T>> for Bivector<T> {
    type Output = T;
    #[inline]
    fn bitor(self, b: Bivector<T>) -> T {
        // Blade products: e12 · e12 = -1, e23 · e23 = -1, e31 · e31 = -1
        let a = self;
        -a.e12 * b.e12 - a.e23 * b.e23 - a.e31 * b.e31
    }
}

/// Inner product (the report's) `Bivector | Trivector -> Vector`.
impl<T: Scalar> BitOr<Trivector<T>> for Bivector<T> {
    type Output = Vector<T>;
    #[inline]
    fn bitor(self, b: Trivector<T>) -> Vector<T> {
        // Blade products: e12 · e123 = -e3, e23 · e123 = -e1, e31 · e123 = -e2
        let a = self;
        Vector { e1: -a.e23 * b.e123, e2: -a.e31 * b.e123, e3: -a.e12 * b.e123 }
    }
}

/// Inner product (the report's) `Trivector | Bivector -> Vector`.
impl<T: Scalar> BitOr<Bivector<T>> for Trivector<T> {
    type Output = Vector<T>;
    #[inline]
    fn bitor(self, b: Bivector<T>) -> Vector<T> {
        // Blade products: e123 · e12 = -e3, e123 · e23 = -e1, e123 · e31 = -e2
        let a = self;
        Vector { e1: -a.e123 * b.e23, e2: -a.e123 * b.e31, e3: -a.e123 * b.e12 }
    }
}

/// Inner product (the report's) `Trivector | Trivector -> scalar`.
impl<T: Scalar> BitOr<Trivector<T>> for Trivector<T> {
    type Output = T;
    #[inline]
    fn bitor(self, b: Trivector<T>) -> T {
        // Blade products: e123 · e123 = -1
        let a = self;
        -a.e123 * b.e123
    }
}

/// Inner product (the report's) `Vector | Rotor -> Vector`.
impl<T: Scalar> BitOr<Rotor<T>> for Vector<T> {
    type Output = Vector<T>;
    #[inline]
    fn bitor(self, b: Rotor<T>) -> Vector<T> {
        // A scalar's inner product with anything is zero (figure 2.7, row s), so only the
        // rotor's bivector part takes part: `Vector | Bivector`.
        self | b.bivector()
    }
}

/// Inner product (the report's) `Bivector | Rotor -> scalar`.
impl<T: Scalar> BitOr<Rotor<T>> for Bivector<T> {
    type Output = T;
    #[inline]
    fn bitor(self, b: Rotor<T>) -> T {
        // A scalar's inner product with anything is zero (figure 2.7, row s), so only the
        // rotor's bivector part takes part: `Bivector | Bivector`.
        self | b.bivector()
    }
}

/// Inner product (the report's) `Trivector | Rotor -> Vector`.
impl<T: Scalar> BitOr<Rotor<T>> for Trivector<T> {
    type Output = Vector<T>;
    #[inline]
    fn bitor(self, b: Rotor<T>) -> Vector<T> {
        // A scalar's inner product with anything is zero (figure 2.7, row s), so only the
        // rotor's bivector part takes part: `Trivector | Bivector`.
        self | b.bivector()
    }
}

/// Inner product (the report's) `Rotor | Vector -> Vector`.
impl<T: Scalar> BitOr<Vector<T>> for Rotor<T> {
    type Output = Vector<T>;
    #[inline]
    fn bitor(self, b: Vector<T>) -> Vector<T> {
        // A scalar's inner product with anything is zero (figure 2.7, row s), so only the
        // rotor's bivector part takes part: `Bivector | Vector`.
        self.bivector() | b
    }
}

/// Inner product (the report's) `Rotor | Bivector -> scalar`.
impl<T: Scalar> BitOr<Bivector<T>> for Rotor<T> {
    type Output = T;
    #[inline]
    fn bitor(self, b: Bivector<T>) -> T {
        // A scalar's inner product with anything is zero (figure 2.7, row s), so only the
        // rotor's bivector part takes part: `Bivector | Bivector`.
        self.bivector() | b
    }
}

/// Inner product (the report's) `Rotor | Trivector -> Vector`.
impl<T: Scalar> BitOr<Trivector<T>> for Rotor<T> {
    type Output = Vector<T>;
    #[inline]
    fn bitor(self, b: Trivector<T>) -> Vector<T> {
        // A scalar's inner product with anything is zero (figure 2.7, row s), so only the
        // rotor's bivector part takes part: `Bivector | Trivector`.
        self.bivector() | b
    }
}

/// Inner product (the report's) `Rotor | Rotor -> scalar`.
impl<T: Scalar> BitOr<Rotor<T>> for Rotor<T> {
    type Output = T;
    #[inline]
    fn bitor(self, b: Rotor<T>) -> T {
        // A scalar's inner product with anything is zero (figure 2.7, row s), so only the
        // rotors' bivector parts take part: `Bivector | Bivector`.
        self.bivector() | b.bivector()
    }
}

/// Inner product (the report's) `Vector | Multivector -> Multivector`.
impl<T: Scalar> BitOr<Multivector<T>> for Vector<T> {
    type Output = Multivector<T>;
    #[inline]
    fn bitor(self, b: Multivector<T>) -> Multivector<T> {
        // The Cayley-table terms (module docs) whose factors both types hold.
        let a = self;
        Multivector::new(
            a.e1 * b.e1() + a.e2 * b.e2() + a.e3 * b.e3(),
            a.e3 * b.e31() - a.e2 * b.e12(),
            a.e1 * b.e12() - a.e3 * b.e23(),
            a.e2 * b.e23() - a.e1 * b.e31(),
            a.e3 * b.e123(),
            a.e1 * b.e123(),
            a.e2 * b.e123(),
            T::ZERO,
        )
    }
}

/// Inner product (the report's) `Bivector | Multivector -> Multivector`.
impl<T: Scalar> BitOr<Multivector<T>> for Bivector<T> {
    type Output = Multivector<T>;
    #[inline]
    fn bitor(self, b: Multivector<T>) -> Multivector<T> {
        // The Cayley-table terms (module docs) whose factors both types hold.
        let a = self;
        Multivector::new(
            -a.e12 * b.e12() - a.e23 * b.e23() - a.e31 * b.e31(),
            a.e12 * b.e2() - a.e23 * b.e123() - a.e31 * b.e3(),
            a.e23 * b.e3() - a.e12 * b.e1() - a.e31 * b.e123(),
            a.e31 * b.e1() - a.e12 * b.e123() - a.e23 * b.e2(),
            T::ZERO,
            T::ZERO,
            T::ZERO,
            T::ZERO,
        )
    }
}

/// Inner product (the report's) `Trivector | Multivector -> Multivector`.
impl<T: Scalar> BitOr<Multivector<T>> for Trivector<T> {
    type Output = Multivector<T>;
    #[inline]
    fn bitor(self, b: Multivector<T>) -> Multivector<T> {
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
            T::ZERO,
        )
    }
}

/// Inner product (the report's) `Rotor | Multivector -> Multivector`.
impl<T: Scalar> BitOr<Multivector<T>> for Rotor<T> {
    type Output = Multivector<T>;
    #[inline]
    fn bitor(self, b: Multivector<T>) -> Multivector<T> {
        // The Cayley-table terms (module docs) whose factors both types hold.
        let a = self;
        Multivector::new(
            -a.e12 * b.e12() - a.e23 * b.e23() - a.e31 * b.e31(),
            a.e12 * b.e2() - a.e23 * b.e123() - a.e31 * b.e3(),
            a.e23 * b.e3() - a.e12 * b.e1() - a.e31 * b.e123(),
            a.e31 * b.e1() - a.e12 * b.e123() - a.e23 * b.e2(),
            T::ZERO,
            T::ZERO,
            T::ZERO,
            T::ZERO,
        )
    }
}

/// Inner product (the report's) `Multivector | Vector -> Multivector`.
impl<T: Scalar> BitOr<Vector<T>> for Multivector<T> {
    type Output = Multivector<T>;
    #[inline]
    fn bitor(self, b: Vector<T>) -> Multivector<T> {
        // The Cayley-table terms (module docs) whose factors both types hold.
        let a = self;
        Multivector::new(
            a.e1() * b.e1 + a.e2() * b.e2 + a.e3() * b.e3,
            a.e12() * b.e2 - a.e31() * b.e3,
            a.e23() * b.e3 - a.e12() * b.e1,
            a.e31() * b.e1 - a.e23() * b.e2,
            a.e123() * b.e3,
            a.e123() * b.e1,
            a.e123() * b.e2,
            T::ZERO,
        )
    }
}

/// Inner product (the report's) `Multivector | Bivector -> Multivector`.
impl<T: Scalar> BitOr<Bivector<T>> for Multivector<T> {
    type Output = Multivector<T>;
    #[inline]
    fn bitor(self, b: Bivector<T>) -> Multivector<T> {
        // The Cayley-table terms (module docs) whose factors both types hold.
        let a = self;
        Multivector::new(
            -a.e12() * b.e12 - a.e23() * b.e23 - a.e31() * b.e31,
            a.e3() * b.e31 - a.e2() * b.e12 - a.e123() * b.e23,
            a.e1() * b.e12 - a.e3() * b.e23 - a.e123() * b.e31,
            a.e2() * b.e23 - a.e1() * b.e31 - a.e123() * b.e12,
            T::ZERO,
            T::ZERO,
            T::ZERO,
            T::ZERO,
        )
    }
}

/// Inner product (the report's) `Multivector | Trivector -> Multivector`.
impl<T: Scalar> BitOr<Trivector<T>> for Multivector<T> {
    type Output = Multivector<T>;
    #[inline]
    fn bitor(self, b: Trivector<T>) -> Multivector<T> {
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
            T::ZERO,
        )
    }
}

/// Inner product (the report's) `Multivector | Rotor -> Multivector`.
impl<T: Scalar> BitOr<Rotor<T>> for Multivector<T> {
    type Output = Multivector<T>;
    #[inline]
    fn bitor(self, b: Rotor<T>) -> Multivector<T> {
        // The Cayley-table terms (module docs) whose factors both types hold.
        let a = self;
        Multivector::new(
            -a.e12() * b.e12 - a.e23() * b.e23 - a.e31() * b.e31,
            a.e3() * b.e31 - a.e2() * b.e12 - a.e123() * b.e23,
            a.e1() * b.e12 - a.e3() * b.e23 - a.e123() * b.e31,
            a.e2() * b.e23 - a.e1() * b.e31 - a.e123() * b.e12,
            T::ZERO,
            T::ZERO,
            T::ZERO,
            T::ZERO,
        )
    }
}

/// Inner product (the report's) `Multivector | Multivector -> Multivector`.
impl<T: Scalar> BitOr<Multivector<T>> for Multivector<T> {
    type Output = Multivector<T>;
    #[inline]
    fn bitor(self, b: Multivector<T>) -> Multivector<T> {
        // The Cayley-table terms (module docs) whose factors both types hold.
        let a = self;
        Multivector::new(
            a.e1() * b.e1() + a.e2() * b.e2() + a.e3() * b.e3()
                - a.e12() * b.e12()
                - a.e23() * b.e23()
                - a.e31() * b.e31()
                - a.e123() * b.e123(),
            a.e3() * b.e31() - a.e2() * b.e12() + a.e12() * b.e2()
                - a.e23() * b.e123()
                - a.e31() * b.e3()
                - a.e123() * b.e23(),
            a.e1() * b.e12() - a.e3() * b.e23() - a.e12() * b.e1() + a.e23() * b.e3()
                - a.e31() * b.e123()
                - a.e123() * b.e31(),
            a.e2() * b.e23() - a.e1() * b.e31() - a.e12() * b.e123() - a.e23() * b.e2()
                + a.e31() * b.e1()
                - a.e123() * b.e12(),
            a.e3() * b.e123() + a.e123() * b.e3(),
            a.e1() * b.e123() + a.e123() * b.e1(),
            a.e2() * b.e123() + a.e123() * b.e2(),
            T::ZERO,
        )
    }
}
