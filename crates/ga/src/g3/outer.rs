//! The outer (wedge) product `^` between the G3 types where it is not identically zero.
//!
//! `a ^ b` keeps the grade `r + s` part of the geometric product of an `r`-blade and an
//! `s`-blade (report figure 2.6). Pairs whose outer product always vanishes in 3D (vector ^
//! trivector, bivector ^ bivector, ...) have no operator; convert to [`Multivector`] for
//! generic code. The scalar case is ordinary scaling (`*`).
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

// The operator traits name the product (`Mul`, `BitXor`, ...) but each kernel is a sum of
// products of coefficients, which is what clippy's heuristic flags.
#![allow(clippy::suspicious_arithmetic_impl)]

use core::ops::BitXor;

use crate::Scalar;
use crate::g3::{Bivector, Multivector, Rotor, Trivector, Vector};

/// Outer product `Vector ^ Vector -> Bivector`.
impl<T: Scalar> BitXor<Vector<T>> for Vector<T> {
    type Output = Bivector<T>;
    #[inline]
    fn bitxor(self, b: Vector<T>) -> Bivector<T> {
        // Blade products: e1 ∧ e2 = e12, e1 ∧ e3 = -e31, e2 ∧ e1 = -e12, e2 ∧ e3 = e23,
        //   e3 ∧ e1 = e31, e3 ∧ e2 = -e23
        let a = self;
        Bivector {
            e12: a.e1 * b.e2 - a.e2 * b.e1,
            e23: a.e2 * b.e3 - a.e3 * b.e2,
            e31: a.e3 * b.e1 - a.e1 * b.e3,
        }
    }
}

/// Outer product `Vector ^ Bivector -> Trivector`.
impl<T: Scalar> BitXor<Bivector<T>> for Vector<T> {
    type Output = Trivector<T>;
    #[inline]
    fn bitxor(self, b: Bivector<T>) -> Trivector<T> {
        // Blade products: e1 ∧ e23 = e123, e2 ∧ e31 = e123, e3 ∧ e12 = e123
        let a = self;
        Trivector { e123: a.e1 * b.e23 + a.e2 * b.e31 + a.e3 * b.e12 }
    }
}

/// Outer product `Bivector ^ Vector -> Trivector`.
impl<T: Scalar> BitXor<Vector<T>> for Bivector<T> {
    type Output = Trivector<T>;
    #[inline]
    fn bitxor(self, b: Vector<T>) -> Trivector<T> {
        // Blade products: e12 ∧ e3 = e123, e23 ∧ e1 = e123, e31 ∧ e2 = e123
        let a = self;
        Trivector { e123: a.e12 * b.e3 + a.e23 * b.e1 + a.e31 * b.e2 }
    }
}

/// Outer product `Vector ^ Rotor -> Multivector`.
impl<T: Scalar> BitXor<Rotor<T>> for Vector<T> {
    type Output = Multivector<T>;
    #[inline]
    fn bitxor(self, b: Rotor<T>) -> Multivector<T> {
        // Blade products: e1 ∧ s = e1, e1 ∧ e23 = e123, e2 ∧ s = e2, e2 ∧ e31 = e123, e3 ∧ s = e3,
        //   e3 ∧ e12 = e123
        let a = self;
        Multivector::new(
            T::ZERO,
            a.e1 * b.s,
            a.e2 * b.s,
            a.e3 * b.s,
            T::ZERO,
            T::ZERO,
            T::ZERO,
            a.e1 * b.e23 + a.e2 * b.e31 + a.e3 * b.e12,
        )
    }
}

/// Outer product `Bivector ^ Rotor -> Bivector`.
impl<T: Scalar> BitXor<Rotor<T>> for Bivector<T> {
    type Output = Bivector<T>;
    #[inline]
    fn bitxor(self, b: Rotor<T>) -> Bivector<T> {
        // Blade products: e12 ∧ s = e12, e23 ∧ s = e23, e31 ∧ s = e31 (bivector ∧ bivector
        //   vanishes in 3D), so this is scaling by the rotor's scalar part.
        self * b.s
    }
}

/// Outer product `Trivector ^ Rotor -> Trivector`.
impl<T: Scalar> BitXor<Rotor<T>> for Trivector<T> {
    type Output = Trivector<T>;
    #[inline]
    fn bitxor(self, b: Rotor<T>) -> Trivector<T> {
        // Blade products: e123 ∧ s = e123, so this is scaling by the rotor's scalar part.
        self * b.s
    }
}

/// Outer product `Rotor ^ Vector -> Multivector`.
impl<T: Scalar> BitXor<Vector<T>> for Rotor<T> {
    type Output = Multivector<T>;
    #[inline]
    fn bitxor(self, b: Vector<T>) -> Multivector<T> {
        // Blade products: s ∧ e1 = e1, s ∧ e2 = e2, s ∧ e3 = e3, e12 ∧ e3 = e123, e23 ∧ e1 = e123,
        //   e31 ∧ e2 = e123: each equals the product in the other order (a vector's outer
        //   product with a scalar or a bivector commutes), so this is `Vector ^ Rotor`.
        b ^ self
    }
}

/// Outer product `Rotor ^ Bivector -> Bivector`.
impl<T: Scalar> BitXor<Bivector<T>> for Rotor<T> {
    type Output = Bivector<T>;
    #[inline]
    fn bitxor(self, b: Bivector<T>) -> Bivector<T> {
        // Blade products: s ∧ e12 = e12, s ∧ e23 = e23, s ∧ e31 = e31 (bivector ∧ bivector
        //   vanishes in 3D), so this is scaling by the rotor's scalar part.
        b * self.s
    }
}

/// Outer product `Rotor ^ Trivector -> Trivector`.
impl<T: Scalar> BitXor<Trivector<T>> for Rotor<T> {
    type Output = Trivector<T>;
    #[inline]
    fn bitxor(self, b: Trivector<T>) -> Trivector<T> {
        // Blade products: s ∧ e123 = e123, so this is scaling by the rotor's scalar part.
        b * self.s
    }
}

/// Outer product `Rotor ^ Rotor -> Rotor`.
impl<T: Scalar> BitXor<Rotor<T>> for Rotor<T> {
    type Output = Rotor<T>;
    #[inline]
    fn bitxor(self, b: Rotor<T>) -> Rotor<T> {
        // Blade products: s ∧ s = 1, s ∧ e12 = e12, s ∧ e23 = e23, s ∧ e31 = e31, e12 ∧ s = e12,
        //   e23 ∧ s = e23, e31 ∧ s = e31
        let a = self;
        Rotor {
            s: a.s * b.s,
            e12: a.s * b.e12 + a.e12 * b.s,
            e23: a.s * b.e23 + a.e23 * b.s,
            e31: a.s * b.e31 + a.e31 * b.s,
        }
    }
}

/// Outer product `Vector ^ Multivector -> Multivector`.
impl<T: Scalar> BitXor<Multivector<T>> for Vector<T> {
    type Output = Multivector<T>;
    #[inline]
    fn bitxor(self, b: Multivector<T>) -> Multivector<T> {
        // The Cayley-table terms (module docs) whose factors both types hold.
        let a = self;
        Multivector::new(
            T::ZERO,
            a.e1 * b.s(),
            a.e2 * b.s(),
            a.e3 * b.s(),
            a.e1 * b.e2() - a.e2 * b.e1(),
            a.e2 * b.e3() - a.e3 * b.e2(),
            a.e3 * b.e1() - a.e1 * b.e3(),
            a.e1 * b.e23() + a.e2 * b.e31() + a.e3 * b.e12(),
        )
    }
}

/// Outer product `Bivector ^ Multivector -> Multivector`.
impl<T: Scalar> BitXor<Multivector<T>> for Bivector<T> {
    type Output = Multivector<T>;
    #[inline]
    fn bitxor(self, b: Multivector<T>) -> Multivector<T> {
        // The Cayley-table terms (module docs) whose factors both types hold.
        let a = self;
        Multivector::new(
            T::ZERO,
            T::ZERO,
            T::ZERO,
            T::ZERO,
            a.e12 * b.s(),
            a.e23 * b.s(),
            a.e31 * b.s(),
            a.e12 * b.e3() + a.e23 * b.e1() + a.e31 * b.e2(),
        )
    }
}

/// Outer product `Trivector ^ Multivector -> Trivector`.
impl<T: Scalar> BitXor<Multivector<T>> for Trivector<T> {
    type Output = Trivector<T>;
    #[inline]
    fn bitxor(self, b: Multivector<T>) -> Trivector<T> {
        // The Cayley-table terms (module docs) whose factors both types hold.
        let a = self;
        Trivector { e123: a.e123 * b.s() }
    }
}

/// Outer product `Rotor ^ Multivector -> Multivector`.
impl<T: Scalar> BitXor<Multivector<T>> for Rotor<T> {
    type Output = Multivector<T>;
    #[inline]
    fn bitxor(self, b: Multivector<T>) -> Multivector<T> {
        // The Cayley-table terms (module docs) whose factors both types hold.
        let a = self;
        Multivector::new(
            a.s * b.s(),
            a.s * b.e1(),
            a.s * b.e2(),
            a.s * b.e3(),
            a.s * b.e12() + a.e12 * b.s(),
            a.s * b.e23() + a.e23 * b.s(),
            a.s * b.e31() + a.e31 * b.s(),
            a.s * b.e123() + a.e12 * b.e3() + a.e23 * b.e1() + a.e31 * b.e2(),
        )
    }
}

/// Outer product `Multivector ^ Vector -> Multivector`.
impl<T: Scalar> BitXor<Vector<T>> for Multivector<T> {
    type Output = Multivector<T>;
    #[inline]
    fn bitxor(self, b: Vector<T>) -> Multivector<T> {
        // The Cayley-table terms (module docs) whose factors both types hold.
        let a = self;
        Multivector::new(
            T::ZERO,
            a.s() * b.e1,
            a.s() * b.e2,
            a.s() * b.e3,
            a.e1() * b.e2 - a.e2() * b.e1,
            a.e2() * b.e3 - a.e3() * b.e2,
            a.e3() * b.e1 - a.e1() * b.e3,
            a.e12() * b.e3 + a.e23() * b.e1 + a.e31() * b.e2,
        )
    }
}

/// Outer product `Multivector ^ Bivector -> Multivector`.
impl<T: Scalar> BitXor<Bivector<T>> for Multivector<T> {
    type Output = Multivector<T>;
    #[inline]
    fn bitxor(self, b: Bivector<T>) -> Multivector<T> {
        // The Cayley-table terms (module docs) whose factors both types hold.
        let a = self;
        Multivector::new(
            T::ZERO,
            T::ZERO,
            T::ZERO,
            T::ZERO,
            a.s() * b.e12,
            a.s() * b.e23,
            a.s() * b.e31,
            a.e1() * b.e23 + a.e2() * b.e31 + a.e3() * b.e12,
        )
    }
}

/// Outer product `Multivector ^ Trivector -> Trivector`.
impl<T: Scalar> BitXor<Trivector<T>> for Multivector<T> {
    type Output = Trivector<T>;
    #[inline]
    fn bitxor(self, b: Trivector<T>) -> Trivector<T> {
        // The Cayley-table terms (module docs) whose factors both types hold.
        let a = self;
        Trivector { e123: a.s() * b.e123 }
    }
}

/// Outer product `Multivector ^ Rotor -> Multivector`.
impl<T: Scalar> BitXor<Rotor<T>> for Multivector<T> {
    type Output = Multivector<T>;
    #[inline]
    fn bitxor(self, b: Rotor<T>) -> Multivector<T> {
        // The Cayley-table terms (module docs) whose factors both types hold.
        let a = self;
        Multivector::new(
            a.s() * b.s,
            a.e1() * b.s,
            a.e2() * b.s,
            a.e3() * b.s,
            a.s() * b.e12 + a.e12() * b.s,
            a.s() * b.e23 + a.e23() * b.s,
            a.s() * b.e31 + a.e31() * b.s,
            a.e1() * b.e23 + a.e2() * b.e31 + a.e3() * b.e12 + a.e123() * b.s,
        )
    }
}

/// Outer product `Multivector ^ Multivector -> Multivector`.
impl<T: Scalar> BitXor<Multivector<T>> for Multivector<T> {
    type Output = Multivector<T>;
    #[inline]
    fn bitxor(self, b: Multivector<T>) -> Multivector<T> {
        // The Cayley-table terms (module docs) whose factors both types hold.
        let a = self;
        Multivector::new(
            a.s() * b.s(),
            a.s() * b.e1() + a.e1() * b.s(),
            a.s() * b.e2() + a.e2() * b.s(),
            a.s() * b.e3() + a.e3() * b.s(),
            a.s() * b.e12() + a.e1() * b.e2() - a.e2() * b.e1() + a.e12() * b.s(),
            a.s() * b.e23() + a.e2() * b.e3() - a.e3() * b.e2() + a.e23() * b.s(),
            a.s() * b.e31() - a.e1() * b.e3() + a.e3() * b.e1() + a.e31() * b.s(),
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
}
