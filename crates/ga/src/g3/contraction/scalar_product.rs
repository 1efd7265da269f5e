//! The scalar product `a ∗ b` for every pair of G3 types where it is not identically zero: the
//! pairs on which it equals an operator, then the expanded kernels (see [`super`]).

use super::ScalarProduct;
use crate::Scalar;
use crate::g3::{Bivector, Multivector, Rotor, Trivector, Vector};

same_as_operator! {
    ScalarProduct::scalar_product, "Scalar product", "∗";
    Vector | Vector -> T,
    Bivector | Bivector -> T,
    Bivector | Rotor -> T,
    Trivector | Trivector -> T,
    Rotor | Bivector -> T,
}

/// Scalar product `Vector ∗ Multivector -> scalar`.
impl<T: Scalar> ScalarProduct<Multivector<T>> for Vector<T> {
    type Output = T;
    #[inline]
    fn scalar_product(self, b: Multivector<T>) -> T {
        // The Cayley-table terms (`geometric` module docs) that this product keeps.
        let a = self;
        a.e1 * b.e1() + a.e2 * b.e2() + a.e3 * b.e3()
    }
}

/// Scalar product `Bivector ∗ Multivector -> scalar`.
impl<T: Scalar> ScalarProduct<Multivector<T>> for Bivector<T> {
    type Output = T;
    #[inline]
    fn scalar_product(self, b: Multivector<T>) -> T {
        // The Cayley-table terms (`geometric` module docs) that this product keeps.
        let a = self;
        -a.e12 * b.e12() - a.e23 * b.e23() - a.e31 * b.e31()
    }
}

/// Scalar product `Trivector ∗ Multivector -> scalar`.
impl<T: Scalar> ScalarProduct<Multivector<T>> for Trivector<T> {
    type Output = T;
    #[inline]
    fn scalar_product(self, b: Multivector<T>) -> T {
        // The Cayley-table terms (`geometric` module docs) that this product keeps.
        let a = self;
        -a.e123 * b.e123()
    }
}

/// Scalar product `Rotor ∗ Rotor -> scalar`.
impl<T: Scalar> ScalarProduct<Rotor<T>> for Rotor<T> {
    type Output = T;
    #[inline]
    fn scalar_product(self, b: Rotor<T>) -> T {
        // Blade products with a scalar part: s s = 1, e12 e12 = -1, e23 e23 = -1, e31 e31 = -1
        let a = self;
        a.s * b.s - a.e12 * b.e12 - a.e23 * b.e23 - a.e31 * b.e31
    }
}

/// Scalar product `Rotor ∗ Multivector -> scalar`.
impl<T: Scalar> ScalarProduct<Multivector<T>> for Rotor<T> {
    type Output = T;
    #[inline]
    fn scalar_product(self, b: Multivector<T>) -> T {
        // The Cayley-table terms (`geometric` module docs) that this product keeps.
        let a = self;
        a.s * b.s() - a.e12 * b.e12() - a.e23 * b.e23() - a.e31 * b.e31()
    }
}

/// Scalar product `Multivector ∗ Vector -> scalar`.
impl<T: Scalar> ScalarProduct<Vector<T>> for Multivector<T> {
    type Output = T;
    #[inline]
    fn scalar_product(self, b: Vector<T>) -> T {
        // The Cayley-table terms (`geometric` module docs) that this product keeps.
        let a = self;
        a.e1() * b.e1 + a.e2() * b.e2 + a.e3() * b.e3
    }
}

/// Scalar product `Multivector ∗ Bivector -> scalar`.
impl<T: Scalar> ScalarProduct<Bivector<T>> for Multivector<T> {
    type Output = T;
    #[inline]
    fn scalar_product(self, b: Bivector<T>) -> T {
        // The Cayley-table terms (`geometric` module docs) that this product keeps.
        let a = self;
        -a.e12() * b.e12 - a.e23() * b.e23 - a.e31() * b.e31
    }
}

/// Scalar product `Multivector ∗ Trivector -> scalar`.
impl<T: Scalar> ScalarProduct<Trivector<T>> for Multivector<T> {
    type Output = T;
    #[inline]
    fn scalar_product(self, b: Trivector<T>) -> T {
        // The Cayley-table terms (`geometric` module docs) that this product keeps.
        let a = self;
        -a.e123() * b.e123
    }
}

/// Scalar product `Multivector ∗ Rotor -> scalar`.
impl<T: Scalar> ScalarProduct<Rotor<T>> for Multivector<T> {
    type Output = T;
    #[inline]
    fn scalar_product(self, b: Rotor<T>) -> T {
        // The Cayley-table terms (`geometric` module docs) that this product keeps.
        let a = self;
        a.s() * b.s - a.e12() * b.e12 - a.e23() * b.e23 - a.e31() * b.e31
    }
}

/// Scalar product `Multivector ∗ Multivector -> scalar`.
impl<T: Scalar> ScalarProduct<Multivector<T>> for Multivector<T> {
    type Output = T;
    #[inline]
    fn scalar_product(self, b: Multivector<T>) -> T {
        // The Cayley-table terms (`geometric` module docs) that this product keeps.
        let a = self;
        a.s() * b.s() + a.e1() * b.e1() + a.e2() * b.e2() + a.e3() * b.e3()
            - a.e12() * b.e12()
            - a.e23() * b.e23()
            - a.e31() * b.e31()
            - a.e123() * b.e123()
    }
}
