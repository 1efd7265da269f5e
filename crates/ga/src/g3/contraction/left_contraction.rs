//! The left contraction `a ⌋ b` for every pair of G3 types where it is not identically zero: the
//! pairs on which it equals an operator, then the expanded kernels (see [`super`]).

use super::LeftContraction;
use crate::Scalar;
use crate::g3::{Bivector, Multivector, Rotor, Trivector, Vector};

same_as_operator! {
    LeftContraction::left_contraction, "Left contraction", "⌋";
    Vector | Vector -> T,
    Vector | Bivector -> Vector<T>,
    Vector | Trivector -> Bivector<T>,
    Vector | Rotor -> Vector<T>,
    Vector | Multivector -> Multivector<T>,
    Bivector | Bivector -> T,
    Bivector | Trivector -> Vector<T>,
    Bivector | Rotor -> T,
    Trivector | Trivector -> T,
    Rotor * Trivector -> Multivector<T>,
    Multivector * Trivector -> Multivector<T>,
}

/// Left contraction `Bivector ⌋ Multivector -> Multivector`.
impl<T: Scalar> LeftContraction<Multivector<T>> for Bivector<T> {
    type Output = Multivector<T>;
    #[inline]
    fn left_contraction(self, b: Multivector<T>) -> Multivector<T> {
        // The Cayley-table terms (`geometric` module docs) that this product keeps.
        let a = self;
        Multivector::new(
            -a.e12 * b.e12() - a.e23 * b.e23() - a.e31 * b.e31(),
            -a.e23 * b.e123(),
            -a.e31 * b.e123(),
            -a.e12 * b.e123(),
            T::ZERO,
            T::ZERO,
            T::ZERO,
            T::ZERO,
        )
    }
}

/// Left contraction `Trivector ⌋ Multivector -> scalar`.
impl<T: Scalar> LeftContraction<Multivector<T>> for Trivector<T> {
    type Output = T;
    #[inline]
    fn left_contraction(self, b: Multivector<T>) -> T {
        // The Cayley-table terms (`geometric` module docs) that this product keeps.
        let a = self;
        -a.e123 * b.e123()
    }
}

/// Left contraction `Rotor ⌋ Vector -> Vector`.
impl<T: Scalar> LeftContraction<Vector<T>> for Rotor<T> {
    type Output = Vector<T>;
    #[inline]
    fn left_contraction(self, b: Vector<T>) -> Vector<T> {
        // Blade products: s ⌋ e1 = e1, s ⌋ e2 = e2, s ⌋ e3 = e3 (a bivector contracts
        //   onto a vector to zero), so this is scaling by the rotor's scalar part.
        b * self.s
    }
}

/// Left contraction `Rotor ⌋ Bivector -> Rotor`.
impl<T: Scalar> LeftContraction<Bivector<T>> for Rotor<T> {
    type Output = Rotor<T>;
    #[inline]
    fn left_contraction(self, b: Bivector<T>) -> Rotor<T> {
        // Blade products: s ⌋ e12 = e12, s ⌋ e23 = e23, s ⌋ e31 = e31, e12 ⌋ e12 = -1,
        //   e23 ⌋ e23 = -1, e31 ⌋ e31 = -1
        let a = self;
        Rotor {
            s: -a.e12 * b.e12 - a.e23 * b.e23 - a.e31 * b.e31,
            e12: a.s * b.e12,
            e23: a.s * b.e23,
            e31: a.s * b.e31,
        }
    }
}

/// Left contraction `Rotor ⌋ Rotor -> Rotor`.
impl<T: Scalar> LeftContraction<Rotor<T>> for Rotor<T> {
    type Output = Rotor<T>;
    #[inline]
    fn left_contraction(self, b: Rotor<T>) -> Rotor<T> {
        // Blade products: s ⌋ s = 1, s ⌋ e12 = e12, s ⌋ e23 = e23, s ⌋ e31 = e31, e12 ⌋ e12 = -1,
        //   e23 ⌋ e23 = -1, e31 ⌋ e31 = -1
        let a = self;
        Rotor {
            s: a.s * b.s - a.e12 * b.e12 - a.e23 * b.e23 - a.e31 * b.e31,
            e12: a.s * b.e12,
            e23: a.s * b.e23,
            e31: a.s * b.e31,
        }
    }
}

/// Left contraction `Rotor ⌋ Multivector -> Multivector`.
impl<T: Scalar> LeftContraction<Multivector<T>> for Rotor<T> {
    type Output = Multivector<T>;
    #[inline]
    fn left_contraction(self, b: Multivector<T>) -> Multivector<T> {
        // The Cayley-table terms (`geometric` module docs) that this product keeps.
        let a = self;
        Multivector::new(
            a.s * b.s() - a.e12 * b.e12() - a.e23 * b.e23() - a.e31 * b.e31(),
            a.s * b.e1() - a.e23 * b.e123(),
            a.s * b.e2() - a.e31 * b.e123(),
            a.s * b.e3() - a.e12 * b.e123(),
            a.s * b.e12(),
            a.s * b.e23(),
            a.s * b.e31(),
            a.s * b.e123(),
        )
    }
}

/// Left contraction `Multivector ⌋ Vector -> Multivector`.
impl<T: Scalar> LeftContraction<Vector<T>> for Multivector<T> {
    type Output = Multivector<T>;
    #[inline]
    fn left_contraction(self, b: Vector<T>) -> Multivector<T> {
        // The Cayley-table terms (`geometric` module docs) that this product keeps.
        let a = self;
        Multivector::new(
            a.e1() * b.e1 + a.e2() * b.e2 + a.e3() * b.e3,
            a.s() * b.e1,
            a.s() * b.e2,
            a.s() * b.e3,
            T::ZERO,
            T::ZERO,
            T::ZERO,
            T::ZERO,
        )
    }
}

/// Left contraction `Multivector ⌋ Bivector -> Multivector`.
impl<T: Scalar> LeftContraction<Bivector<T>> for Multivector<T> {
    type Output = Multivector<T>;
    #[inline]
    fn left_contraction(self, b: Bivector<T>) -> Multivector<T> {
        // The Cayley-table terms (`geometric` module docs) that this product keeps.
        let a = self;
        Multivector::new(
            -a.e12() * b.e12 - a.e23() * b.e23 - a.e31() * b.e31,
            a.e3() * b.e31 - a.e2() * b.e12,
            a.e1() * b.e12 - a.e3() * b.e23,
            a.e2() * b.e23 - a.e1() * b.e31,
            a.s() * b.e12,
            a.s() * b.e23,
            a.s() * b.e31,
            T::ZERO,
        )
    }
}

/// Left contraction `Multivector ⌋ Rotor -> Multivector`.
impl<T: Scalar> LeftContraction<Rotor<T>> for Multivector<T> {
    type Output = Multivector<T>;
    #[inline]
    fn left_contraction(self, b: Rotor<T>) -> Multivector<T> {
        // The Cayley-table terms (`geometric` module docs) that this product keeps.
        let a = self;
        Multivector::new(
            a.s() * b.s - a.e12() * b.e12 - a.e23() * b.e23 - a.e31() * b.e31,
            a.e3() * b.e31 - a.e2() * b.e12,
            a.e1() * b.e12 - a.e3() * b.e23,
            a.e2() * b.e23 - a.e1() * b.e31,
            a.s() * b.e12,
            a.s() * b.e23,
            a.s() * b.e31,
            T::ZERO,
        )
    }
}

/// Left contraction `Multivector ⌋ Multivector -> Multivector`.
impl<T: Scalar> LeftContraction<Multivector<T>> for Multivector<T> {
    type Output = Multivector<T>;
    #[inline]
    fn left_contraction(self, b: Multivector<T>) -> Multivector<T> {
        // The Cayley-table terms (`geometric` module docs) that this product keeps.
        let a = self;
        Multivector::new(
            a.s() * b.s() + a.e1() * b.e1() + a.e2() * b.e2() + a.e3() * b.e3()
                - a.e12() * b.e12()
                - a.e23() * b.e23()
                - a.e31() * b.e31()
                - a.e123() * b.e123(),
            a.s() * b.e1() - a.e2() * b.e12() + a.e3() * b.e31() - a.e23() * b.e123(),
            a.s() * b.e2() + a.e1() * b.e12() - a.e3() * b.e23() - a.e31() * b.e123(),
            a.s() * b.e3() - a.e1() * b.e31() + a.e2() * b.e23() - a.e12() * b.e123(),
            a.s() * b.e12() + a.e3() * b.e123(),
            a.s() * b.e23() + a.e1() * b.e123(),
            a.s() * b.e31() + a.e2() * b.e123(),
            a.s() * b.e123(),
        )
    }
}
