//! The regressive product (meet) `&` between the G3 types where it is not identically zero.
//!
//! Defined through the dual: `a & b = ((a I⁻¹) ^ (b I⁻¹)) I`, i.e. `undual(dual(a) ^ dual(b))`
//! with `dual(x) = x I⁻¹` and `undual(x) = x I` (see [`Multivector::dual`]). It is the outer
//! product of the complements: two planes meet in a line (bivector & bivector is a vector), a
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

// The operator traits name the product (`Mul`, `BitXor`, ...) but each kernel is a sum of
// products of coefficients, which is what clippy's heuristic flags.
#![allow(clippy::suspicious_arithmetic_impl)]

use core::ops::BitAnd;

use crate::Scalar;
use crate::g3::{Bivector, Multivector, Rotor, Trivector, Vector};

/// Regressive product `Bivector & Bivector -> Vector`.
impl<T: Scalar> BitAnd<Bivector<T>> for Bivector<T> {
    type Output = Vector<T>;
    #[inline]
    fn bitand(self, b: Bivector<T>) -> Vector<T> {
        // Blade meets: e12 ∨ e23 = -e2, e12 ∨ e31 = e1, e23 ∨ e12 = e2, e23 ∨ e31 = -e3,
        //   e31 ∨ e12 = -e1, e31 ∨ e23 = e3
        let a = self;
        Vector {
            e1: a.e12 * b.e31 - a.e31 * b.e12,
            e2: a.e23 * b.e12 - a.e12 * b.e23,
            e3: a.e31 * b.e23 - a.e23 * b.e31,
        }
    }
}

/// Regressive product `Bivector & Vector -> scalar`.
impl<T: Scalar> BitAnd<Vector<T>> for Bivector<T> {
    type Output = T;
    #[inline]
    fn bitand(self, b: Vector<T>) -> T {
        // Blade meets: e12 ∨ e3 = 1, e23 ∨ e1 = 1, e31 ∨ e2 = 1
        let a = self;
        a.e12 * b.e3 + a.e23 * b.e1 + a.e31 * b.e2
    }
}

/// Regressive product `Vector & Bivector -> scalar`.
impl<T: Scalar> BitAnd<Bivector<T>> for Vector<T> {
    type Output = T;
    #[inline]
    fn bitand(self, b: Bivector<T>) -> T {
        // Blade meets: e1 ∨ e23 = 1, e2 ∨ e31 = 1, e3 ∨ e12 = 1
        let a = self;
        a.e1 * b.e23 + a.e2 * b.e31 + a.e3 * b.e12
    }
}

/// Regressive product `Trivector & Vector -> Vector`.
impl<T: Scalar> BitAnd<Vector<T>> for Trivector<T> {
    type Output = Vector<T>;
    #[inline]
    fn bitand(self, b: Vector<T>) -> Vector<T> {
        // Blade meets: e123 ∨ e1 = e1, e123 ∨ e2 = e2, e123 ∨ e3 = e3
        let a = self;
        Vector { e1: a.e123 * b.e1, e2: a.e123 * b.e2, e3: a.e123 * b.e3 }
    }
}

/// Regressive product `Vector & Trivector -> Vector`.
impl<T: Scalar> BitAnd<Trivector<T>> for Vector<T> {
    type Output = Vector<T>;
    #[inline]
    fn bitand(self, b: Trivector<T>) -> Vector<T> {
        // Blade meets: e1 ∨ e123 = e1, e2 ∨ e123 = e2, e3 ∨ e123 = e3
        let a = self;
        Vector { e1: a.e1 * b.e123, e2: a.e2 * b.e123, e3: a.e3 * b.e123 }
    }
}

/// Regressive product `Trivector & Bivector -> Bivector`.
impl<T: Scalar> BitAnd<Bivector<T>> for Trivector<T> {
    type Output = Bivector<T>;
    #[inline]
    fn bitand(self, b: Bivector<T>) -> Bivector<T> {
        // Blade meets: e123 ∨ e12 = e12, e123 ∨ e23 = e23, e123 ∨ e31 = e31
        let a = self;
        Bivector { e12: a.e123 * b.e12, e23: a.e123 * b.e23, e31: a.e123 * b.e31 }
    }
}

/// Regressive product `Bivector & Trivector -> Bivector`.
impl<T: Scalar> BitAnd<Trivector<T>> for Bivector<T> {
    type Output = Bivector<T>;
    #[inline]
    fn bitand(self, b: Trivector<T>) -> Bivector<T> {
        // Blade meets: e12 ∨ e123 = e12, e23 ∨ e123 = e23, e31 ∨ e123 = e31
        let a = self;
        Bivector { e12: a.e12 * b.e123, e23: a.e23 * b.e123, e31: a.e31 * b.e123 }
    }
}

/// Regressive product `Trivector & Trivector -> Trivector`.
impl<T: Scalar> BitAnd<Trivector<T>> for Trivector<T> {
    type Output = Trivector<T>;
    #[inline]
    fn bitand(self, b: Trivector<T>) -> Trivector<T> {
        // Blade meets: e123 ∨ e123 = e123
        let a = self;
        Trivector { e123: a.e123 * b.e123 }
    }
}

/// Regressive product `Vector & Rotor -> scalar`.
impl<T: Scalar> BitAnd<Rotor<T>> for Vector<T> {
    type Output = T;
    #[inline]
    fn bitand(self, b: Rotor<T>) -> T {
        // A scalar meets only the pseudoscalar (`s & x = 0` for `x` of grade below 3), so
        // only the rotor's bivector part takes part: `Vector & Bivector`.
        self & b.bivector()
    }
}

/// Regressive product `Bivector & Rotor -> Vector`.
impl<T: Scalar> BitAnd<Rotor<T>> for Bivector<T> {
    type Output = Vector<T>;
    #[inline]
    fn bitand(self, b: Rotor<T>) -> Vector<T> {
        // A scalar meets only the pseudoscalar (`s & x = 0` for `x` of grade below 3), so
        // only the rotor's bivector part takes part: `Bivector & Bivector`.
        self & b.bivector()
    }
}

/// Regressive product `Trivector & Rotor -> Rotor`.
impl<T: Scalar> BitAnd<Rotor<T>> for Trivector<T> {
    type Output = Rotor<T>;
    #[inline]
    fn bitand(self, b: Rotor<T>) -> Rotor<T> {
        // Blade meets: e123 ∨ s = 1, e123 ∨ e12 = e12, e123 ∨ e23 = e23, e123 ∨ e31 = e31:
        //   the pseudoscalar is the identity of the meet, so this is scaling.
        b * self.e123
    }
}

/// Regressive product `Rotor & Vector -> scalar`.
impl<T: Scalar> BitAnd<Vector<T>> for Rotor<T> {
    type Output = T;
    #[inline]
    fn bitand(self, b: Vector<T>) -> T {
        // A scalar meets only the pseudoscalar (`s & x = 0` for `x` of grade below 3), so
        // only the rotor's bivector part takes part: `Bivector & Vector`.
        self.bivector() & b
    }
}

/// Regressive product `Rotor & Bivector -> Vector`.
impl<T: Scalar> BitAnd<Bivector<T>> for Rotor<T> {
    type Output = Vector<T>;
    #[inline]
    fn bitand(self, b: Bivector<T>) -> Vector<T> {
        // A scalar meets only the pseudoscalar (`s & x = 0` for `x` of grade below 3), so
        // only the rotor's bivector part takes part: `Bivector & Bivector`.
        self.bivector() & b
    }
}

/// Regressive product `Rotor & Trivector -> Rotor`.
impl<T: Scalar> BitAnd<Trivector<T>> for Rotor<T> {
    type Output = Rotor<T>;
    #[inline]
    fn bitand(self, b: Trivector<T>) -> Rotor<T> {
        // Blade meets: s ∨ e123 = 1, e12 ∨ e123 = e12, e23 ∨ e123 = e23, e31 ∨ e123 = e31:
        //   the pseudoscalar is the identity of the meet, so this is scaling.
        self * b.e123
    }
}

/// Regressive product `Rotor & Rotor -> Vector`.
impl<T: Scalar> BitAnd<Rotor<T>> for Rotor<T> {
    type Output = Vector<T>;
    #[inline]
    fn bitand(self, b: Rotor<T>) -> Vector<T> {
        // A scalar meets only the pseudoscalar (`s & x = 0` for `x` of grade below 3), so
        // only the rotors' bivector parts take part: `Bivector & Bivector`.
        self.bivector() & b.bivector()
    }
}

/// Regressive product `Vector & Multivector -> Multivector`.
impl<T: Scalar> BitAnd<Multivector<T>> for Vector<T> {
    type Output = Multivector<T>;
    #[inline]
    fn bitand(self, b: Multivector<T>) -> Multivector<T> {
        // The Cayley-table terms (module docs) whose factors both types hold.
        let a = self;
        Multivector::new(
            a.e1 * b.e23() + a.e2 * b.e31() + a.e3 * b.e12(),
            a.e1 * b.e123(),
            a.e2 * b.e123(),
            a.e3 * b.e123(),
            T::ZERO,
            T::ZERO,
            T::ZERO,
            T::ZERO,
        )
    }
}

/// Regressive product `Bivector & Multivector -> Multivector`.
impl<T: Scalar> BitAnd<Multivector<T>> for Bivector<T> {
    type Output = Multivector<T>;
    #[inline]
    fn bitand(self, b: Multivector<T>) -> Multivector<T> {
        // The Cayley-table terms (module docs) whose factors both types hold.
        let a = self;
        Multivector::new(
            a.e12 * b.e3() + a.e23 * b.e1() + a.e31 * b.e2(),
            a.e12 * b.e31() - a.e31 * b.e12(),
            a.e23 * b.e12() - a.e12 * b.e23(),
            a.e31 * b.e23() - a.e23 * b.e31(),
            a.e12 * b.e123(),
            a.e23 * b.e123(),
            a.e31 * b.e123(),
            T::ZERO,
        )
    }
}

/// Regressive product `Trivector & Multivector -> Multivector`.
impl<T: Scalar> BitAnd<Multivector<T>> for Trivector<T> {
    type Output = Multivector<T>;
    #[inline]
    fn bitand(self, b: Multivector<T>) -> Multivector<T> {
        // The Cayley-table terms (module docs) whose factors both types hold.
        let a = self;
        Multivector::new(
            a.e123 * b.s(),
            a.e123 * b.e1(),
            a.e123 * b.e2(),
            a.e123 * b.e3(),
            a.e123 * b.e12(),
            a.e123 * b.e23(),
            a.e123 * b.e31(),
            a.e123 * b.e123(),
        )
    }
}

/// Regressive product `Rotor & Multivector -> Multivector`.
impl<T: Scalar> BitAnd<Multivector<T>> for Rotor<T> {
    type Output = Multivector<T>;
    #[inline]
    fn bitand(self, b: Multivector<T>) -> Multivector<T> {
        // The Cayley-table terms (module docs) whose factors both types hold.
        let a = self;
        Multivector::new(
            a.s * b.e123() + a.e12 * b.e3() + a.e23 * b.e1() + a.e31 * b.e2(),
            a.e12 * b.e31() - a.e31 * b.e12(),
            a.e23 * b.e12() - a.e12 * b.e23(),
            a.e31 * b.e23() - a.e23 * b.e31(),
            a.e12 * b.e123(),
            a.e23 * b.e123(),
            a.e31 * b.e123(),
            T::ZERO,
        )
    }
}

/// Regressive product `Multivector & Vector -> Multivector`.
impl<T: Scalar> BitAnd<Vector<T>> for Multivector<T> {
    type Output = Multivector<T>;
    #[inline]
    fn bitand(self, b: Vector<T>) -> Multivector<T> {
        // The Cayley-table terms (module docs) whose factors both types hold.
        let a = self;
        Multivector::new(
            a.e12() * b.e3 + a.e23() * b.e1 + a.e31() * b.e2,
            a.e123() * b.e1,
            a.e123() * b.e2,
            a.e123() * b.e3,
            T::ZERO,
            T::ZERO,
            T::ZERO,
            T::ZERO,
        )
    }
}

/// Regressive product `Multivector & Bivector -> Multivector`.
impl<T: Scalar> BitAnd<Bivector<T>> for Multivector<T> {
    type Output = Multivector<T>;
    #[inline]
    fn bitand(self, b: Bivector<T>) -> Multivector<T> {
        // The Cayley-table terms (module docs) whose factors both types hold.
        let a = self;
        Multivector::new(
            a.e1() * b.e23 + a.e2() * b.e31 + a.e3() * b.e12,
            a.e12() * b.e31 - a.e31() * b.e12,
            a.e23() * b.e12 - a.e12() * b.e23,
            a.e31() * b.e23 - a.e23() * b.e31,
            a.e123() * b.e12,
            a.e123() * b.e23,
            a.e123() * b.e31,
            T::ZERO,
        )
    }
}

/// Regressive product `Multivector & Trivector -> Multivector`.
impl<T: Scalar> BitAnd<Trivector<T>> for Multivector<T> {
    type Output = Multivector<T>;
    #[inline]
    fn bitand(self, b: Trivector<T>) -> Multivector<T> {
        // The Cayley-table terms (module docs) whose factors both types hold.
        let a = self;
        Multivector::new(
            a.s() * b.e123,
            a.e1() * b.e123,
            a.e2() * b.e123,
            a.e3() * b.e123,
            a.e12() * b.e123,
            a.e23() * b.e123,
            a.e31() * b.e123,
            a.e123() * b.e123,
        )
    }
}

/// Regressive product `Multivector & Rotor -> Multivector`.
impl<T: Scalar> BitAnd<Rotor<T>> for Multivector<T> {
    type Output = Multivector<T>;
    #[inline]
    fn bitand(self, b: Rotor<T>) -> Multivector<T> {
        // The Cayley-table terms (module docs) whose factors both types hold.
        let a = self;
        Multivector::new(
            a.e1() * b.e23 + a.e2() * b.e31 + a.e3() * b.e12 + a.e123() * b.s,
            a.e12() * b.e31 - a.e31() * b.e12,
            a.e23() * b.e12 - a.e12() * b.e23,
            a.e31() * b.e23 - a.e23() * b.e31,
            a.e123() * b.e12,
            a.e123() * b.e23,
            a.e123() * b.e31,
            T::ZERO,
        )
    }
}

/// Regressive product `Multivector & Multivector -> Multivector`.
impl<T: Scalar> BitAnd<Multivector<T>> for Multivector<T> {
    type Output = Multivector<T>;
    #[inline]
    fn bitand(self, b: Multivector<T>) -> Multivector<T> {
        // The Cayley-table terms (module docs) whose factors both types hold.
        let a = self;
        Multivector::new(
            a.s() * b.e123()
                + a.e1() * b.e23()
                + a.e2() * b.e31()
                + a.e3() * b.e12()
                + a.e12() * b.e3()
                + a.e23() * b.e1()
                + a.e31() * b.e2()
                + a.e123() * b.s(),
            a.e1() * b.e123() + a.e12() * b.e31() - a.e31() * b.e12() + a.e123() * b.e1(),
            a.e2() * b.e123() - a.e12() * b.e23() + a.e23() * b.e12() + a.e123() * b.e2(),
            a.e3() * b.e123() - a.e23() * b.e31() + a.e31() * b.e23() + a.e123() * b.e3(),
            a.e12() * b.e123() + a.e123() * b.e12(),
            a.e23() * b.e123() + a.e123() * b.e23(),
            a.e31() * b.e123() + a.e123() * b.e31(),
            a.e123() * b.e123(),
        )
    }
}
