//! The right contraction `a ⌊ b` for every pair of G3 types where it is not identically zero: the
//! pairs on which it equals an operator, then the expanded kernels (see [`super`]).

use super::RightContraction;
use crate::Scalar;
use crate::g3::{Bivector, Multivector, Rotor, Trivector, Vector};

same_as_operator! {
    RightContraction::right_contraction, "Right contraction", "⌊";
    Vector | Vector -> T,
    Bivector | Vector -> Vector<T>,
    Bivector | Bivector -> T,
    Trivector | Vector -> Bivector<T>,
    Trivector | Bivector -> Vector<T>,
    Trivector | Trivector -> T,
    Trivector * Rotor -> Multivector<T>,
    Trivector * Multivector -> Multivector<T>,
    Rotor | Vector -> Vector<T>,
    Rotor | Bivector -> T,
    Multivector | Vector -> Multivector<T>,
}

/// Right contraction `Vector ⌊ Rotor -> Vector`.
impl<T: Scalar> RightContraction<Rotor<T>> for Vector<T> {
    type Output = Vector<T>;
    #[inline]
    fn right_contraction(self, b: Rotor<T>) -> Vector<T> {
        // Blade products: e1 ⌊ s = e1, e2 ⌊ s = e2, e3 ⌊ s = e3 (a vector contracts by a
        //   bivector to zero), so this is scaling by the rotor's scalar part.
        self * b.s
    }
}

/// Right contraction `Vector ⌊ Multivector -> Multivector`.
impl<T: Scalar> RightContraction<Multivector<T>> for Vector<T> {
    type Output = Multivector<T>;
    #[inline]
    fn right_contraction(self, b: Multivector<T>) -> Multivector<T> {
        // The Cayley-table terms (`geometric` module docs) that this product keeps.
        let a = self;
        Multivector::new(
            a.e1 * b.e1() + a.e2 * b.e2() + a.e3 * b.e3(),
            a.e1 * b.s(),
            a.e2 * b.s(),
            a.e3 * b.s(),
            T::ZERO,
            T::ZERO,
            T::ZERO,
            T::ZERO,
        )
    }
}

/// Right contraction `Bivector ⌊ Rotor -> Rotor`.
impl<T: Scalar> RightContraction<Rotor<T>> for Bivector<T> {
    type Output = Rotor<T>;
    #[inline]
    fn right_contraction(self, b: Rotor<T>) -> Rotor<T> {
        // Blade products: e12 ⌊ s = e12, e12 ⌊ e12 = -1, e23 ⌊ s = e23, e23 ⌊ e23 = -1,
        //   e31 ⌊ s = e31, e31 ⌊ e31 = -1
        let a = self;
        Rotor {
            s: -a.e12 * b.e12 - a.e23 * b.e23 - a.e31 * b.e31,
            e12: a.e12 * b.s,
            e23: a.e23 * b.s,
            e31: a.e31 * b.s,
        }
    }
}

/// Right contraction `Bivector ⌊ Multivector -> Multivector`.
impl<T: Scalar> RightContraction<Multivector<T>> for Bivector<T> {
    type Output = Multivector<T>;
    #[inline]
    fn right_contraction(self, b: Multivector<T>) -> Multivector<T> {
        // The Cayley-table terms (`geometric` module docs) that this product keeps.
        let a = self;
        Multivector::new(
            -a.e12 * b.e12() - a.e23 * b.e23() - a.e31 * b.e31(),
            a.e12 * b.e2() - a.e31 * b.e3(),
            a.e23 * b.e3() - a.e12 * b.e1(),
            a.e31 * b.e1() - a.e23 * b.e2(),
            a.e12 * b.s(),
            a.e23 * b.s(),
            a.e31 * b.s(),
            T::ZERO,
        )
    }
}

/// Right contraction `Rotor ⌊ Rotor -> Rotor`.
impl<T: Scalar> RightContraction<Rotor<T>> for Rotor<T> {
    type Output = Rotor<T>;
    #[inline]
    fn right_contraction(self, b: Rotor<T>) -> Rotor<T> {
        // Blade products: s ⌊ s = 1, e12 ⌊ s = e12, e12 ⌊ e12 = -1, e23 ⌊ s = e23, e23 ⌊ e23 = -1,
        //   e31 ⌊ s = e31, e31 ⌊ e31 = -1
        let a = self;
        Rotor {
            s: a.s * b.s - a.e12 * b.e12 - a.e23 * b.e23 - a.e31 * b.e31,
            e12: a.e12 * b.s,
            e23: a.e23 * b.s,
            e31: a.e31 * b.s,
        }
    }
}

/// Right contraction `Rotor ⌊ Multivector -> Multivector`.
impl<T: Scalar> RightContraction<Multivector<T>> for Rotor<T> {
    type Output = Multivector<T>;
    #[inline]
    fn right_contraction(self, b: Multivector<T>) -> Multivector<T> {
        // The Cayley-table terms (`geometric` module docs) that this product keeps.
        let a = self;
        Multivector::new(
            a.s * b.s() - a.e12 * b.e12() - a.e23 * b.e23() - a.e31 * b.e31(),
            a.e12 * b.e2() - a.e31 * b.e3(),
            a.e23 * b.e3() - a.e12 * b.e1(),
            a.e31 * b.e1() - a.e23 * b.e2(),
            a.e12 * b.s(),
            a.e23 * b.s(),
            a.e31 * b.s(),
            T::ZERO,
        )
    }
}

/// Right contraction `Multivector ⌊ Bivector -> Multivector`.
impl<T: Scalar> RightContraction<Bivector<T>> for Multivector<T> {
    type Output = Multivector<T>;
    #[inline]
    fn right_contraction(self, b: Bivector<T>) -> Multivector<T> {
        // The Cayley-table terms (`geometric` module docs) that this product keeps.
        let a = self;
        Multivector::new(
            -a.e12() * b.e12 - a.e23() * b.e23 - a.e31() * b.e31,
            -a.e123() * b.e23,
            -a.e123() * b.e31,
            -a.e123() * b.e12,
            T::ZERO,
            T::ZERO,
            T::ZERO,
            T::ZERO,
        )
    }
}

/// Right contraction `Multivector ⌊ Trivector -> scalar`.
impl<T: Scalar> RightContraction<Trivector<T>> for Multivector<T> {
    type Output = T;
    #[inline]
    fn right_contraction(self, b: Trivector<T>) -> T {
        // The Cayley-table terms (`geometric` module docs) that this product keeps.
        let a = self;
        -a.e123() * b.e123
    }
}

/// Right contraction `Multivector ⌊ Rotor -> Multivector`.
impl<T: Scalar> RightContraction<Rotor<T>> for Multivector<T> {
    type Output = Multivector<T>;
    #[inline]
    fn right_contraction(self, b: Rotor<T>) -> Multivector<T> {
        // The Cayley-table terms (`geometric` module docs) that this product keeps.
        let a = self;
        Multivector::new(
            a.s() * b.s - a.e12() * b.e12 - a.e23() * b.e23 - a.e31() * b.e31,
            a.e1() * b.s - a.e123() * b.e23,
            a.e2() * b.s - a.e123() * b.e31,
            a.e3() * b.s - a.e123() * b.e12,
            a.e12() * b.s,
            a.e23() * b.s,
            a.e31() * b.s,
            a.e123() * b.s,
        )
    }
}

/// Right contraction `Multivector ⌊ Multivector -> Multivector`.
impl<T: Scalar> RightContraction<Multivector<T>> for Multivector<T> {
    type Output = Multivector<T>;
    #[inline]
    fn right_contraction(self, b: Multivector<T>) -> Multivector<T> {
        // The Cayley-table terms (`geometric` module docs) that this product keeps.
        let a = self;
        Multivector::new(
            a.s() * b.s() + a.e1() * b.e1() + a.e2() * b.e2() + a.e3() * b.e3()
                - a.e12() * b.e12()
                - a.e23() * b.e23()
                - a.e31() * b.e31()
                - a.e123() * b.e123(),
            a.e1() * b.s() + a.e12() * b.e2() - a.e31() * b.e3() - a.e123() * b.e23(),
            a.e2() * b.s() - a.e12() * b.e1() + a.e23() * b.e3() - a.e123() * b.e31(),
            a.e3() * b.s() - a.e23() * b.e2() + a.e31() * b.e1() - a.e123() * b.e12(),
            a.e12() * b.s() + a.e123() * b.e3(),
            a.e23() * b.s() + a.e123() * b.e1(),
            a.e31() * b.s() + a.e123() * b.e2(),
            a.e123() * b.s(),
        )
    }
}
