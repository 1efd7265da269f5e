//! The commutator product `a × b` for every pair of G3 types where it is not identically zero: the
//! pairs on which it equals an operator, then the expanded kernels (see [`super`]).

use super::Commutator;
use crate::Scalar;
use crate::g3::{Bivector, Multivector, Rotor, Vector};

same_as_operator! {
    Commutator::commutator, "Commutator product", "×";
    Vector ^ Vector -> Bivector<T>,
    Vector | Bivector -> Vector<T>,
    Vector | Rotor -> Vector<T>,
    Bivector | Vector -> Vector<T>,
    Rotor | Vector -> Vector<T>,
}

/// Commutator product `Vector × Multivector -> Multivector`.
impl<T: Scalar> Commutator<Multivector<T>> for Vector<T> {
    type Output = Multivector<T>;
    #[inline]
    fn commutator(self, b: Multivector<T>) -> Multivector<T> {
        // The Cayley-table terms (`geometric` module docs) that this product keeps.
        let a = self;
        Multivector::new(
            T::ZERO,
            a.e3 * b.e31() - a.e2 * b.e12(),
            a.e1 * b.e12() - a.e3 * b.e23(),
            a.e2 * b.e23() - a.e1 * b.e31(),
            a.e1 * b.e2() - a.e2 * b.e1(),
            a.e2 * b.e3() - a.e3 * b.e2(),
            a.e3 * b.e1() - a.e1 * b.e3(),
            T::ZERO,
        )
    }
}

/// Commutator product `Bivector × Bivector -> Bivector`.
impl<T: Scalar> Commutator<Bivector<T>> for Bivector<T> {
    type Output = Bivector<T>;
    #[inline]
    fn commutator(self, b: Bivector<T>) -> Bivector<T> {
        // Blade products that anticommute: e12 × e23 = -e31, e12 × e31 = e23, e23 × e12 = e31,
        //   e23 × e31 = -e12, e31 × e12 = -e23, e31 × e23 = e12
        let a = self;
        Bivector {
            e12: a.e31 * b.e23 - a.e23 * b.e31,
            e23: a.e12 * b.e31 - a.e31 * b.e12,
            e31: a.e23 * b.e12 - a.e12 * b.e23,
        }
    }
}

/// Commutator product `Bivector × Rotor -> Bivector`.
impl<T: Scalar> Commutator<Rotor<T>> for Bivector<T> {
    type Output = Bivector<T>;
    #[inline]
    fn commutator(self, b: Rotor<T>) -> Bivector<T> {
        // A scalar commutes with everything, so only the rotor's bivector part takes part:
        // `Bivector × Bivector`.
        self.commutator(b.bivector())
    }
}

/// Commutator product `Bivector × Multivector -> Multivector`.
impl<T: Scalar> Commutator<Multivector<T>> for Bivector<T> {
    type Output = Multivector<T>;
    #[inline]
    fn commutator(self, b: Multivector<T>) -> Multivector<T> {
        // The Cayley-table terms (`geometric` module docs) that this product keeps.
        let a = self;
        Multivector::new(
            T::ZERO,
            a.e12 * b.e2() - a.e31 * b.e3(),
            a.e23 * b.e3() - a.e12 * b.e1(),
            a.e31 * b.e1() - a.e23 * b.e2(),
            a.e31 * b.e23() - a.e23 * b.e31(),
            a.e12 * b.e31() - a.e31 * b.e12(),
            a.e23 * b.e12() - a.e12 * b.e23(),
            T::ZERO,
        )
    }
}

/// Commutator product `Rotor × Bivector -> Bivector`.
impl<T: Scalar> Commutator<Bivector<T>> for Rotor<T> {
    type Output = Bivector<T>;
    #[inline]
    fn commutator(self, b: Bivector<T>) -> Bivector<T> {
        // A scalar commutes with everything, so only the rotor's bivector part takes part:
        // `Bivector × Bivector`.
        self.bivector().commutator(b)
    }
}

/// Commutator product `Rotor × Rotor -> Bivector`.
impl<T: Scalar> Commutator<Rotor<T>> for Rotor<T> {
    type Output = Bivector<T>;
    #[inline]
    fn commutator(self, b: Rotor<T>) -> Bivector<T> {
        // A scalar commutes with everything, so only the rotors' bivector parts take part:
        // `Bivector × Bivector`.
        self.bivector().commutator(b.bivector())
    }
}

/// Commutator product `Rotor × Multivector -> Multivector`.
impl<T: Scalar> Commutator<Multivector<T>> for Rotor<T> {
    type Output = Multivector<T>;
    #[inline]
    fn commutator(self, b: Multivector<T>) -> Multivector<T> {
        // A scalar commutes with everything, so only the rotor's bivector part takes part:
        // `Bivector × Multivector`.
        self.bivector().commutator(b)
    }
}

/// Commutator product `Multivector × Vector -> Multivector`.
impl<T: Scalar> Commutator<Vector<T>> for Multivector<T> {
    type Output = Multivector<T>;
    #[inline]
    fn commutator(self, b: Vector<T>) -> Multivector<T> {
        // The Cayley-table terms (`geometric` module docs) that this product keeps.
        let a = self;
        Multivector::new(
            T::ZERO,
            a.e12() * b.e2 - a.e31() * b.e3,
            a.e23() * b.e3 - a.e12() * b.e1,
            a.e31() * b.e1 - a.e23() * b.e2,
            a.e1() * b.e2 - a.e2() * b.e1,
            a.e2() * b.e3 - a.e3() * b.e2,
            a.e3() * b.e1 - a.e1() * b.e3,
            T::ZERO,
        )
    }
}

/// Commutator product `Multivector × Bivector -> Multivector`.
impl<T: Scalar> Commutator<Bivector<T>> for Multivector<T> {
    type Output = Multivector<T>;
    #[inline]
    fn commutator(self, b: Bivector<T>) -> Multivector<T> {
        // The Cayley-table terms (`geometric` module docs) that this product keeps.
        let a = self;
        Multivector::new(
            T::ZERO,
            a.e3() * b.e31 - a.e2() * b.e12,
            a.e1() * b.e12 - a.e3() * b.e23,
            a.e2() * b.e23 - a.e1() * b.e31,
            a.e31() * b.e23 - a.e23() * b.e31,
            a.e12() * b.e31 - a.e31() * b.e12,
            a.e23() * b.e12 - a.e12() * b.e23,
            T::ZERO,
        )
    }
}

/// Commutator product `Multivector × Rotor -> Multivector`.
impl<T: Scalar> Commutator<Rotor<T>> for Multivector<T> {
    type Output = Multivector<T>;
    #[inline]
    fn commutator(self, b: Rotor<T>) -> Multivector<T> {
        // A scalar commutes with everything, so only the rotor's bivector part takes part:
        // `Multivector × Bivector`.
        self.commutator(b.bivector())
    }
}

/// Commutator product `Multivector × Multivector -> Multivector`.
impl<T: Scalar> Commutator<Multivector<T>> for Multivector<T> {
    type Output = Multivector<T>;
    #[inline]
    fn commutator(self, b: Multivector<T>) -> Multivector<T> {
        // The Cayley-table terms (`geometric` module docs) that this product keeps.
        let a = self;
        Multivector::new(
            T::ZERO,
            a.e3() * b.e31() - a.e2() * b.e12() + a.e12() * b.e2() - a.e31() * b.e3(),
            a.e1() * b.e12() - a.e3() * b.e23() - a.e12() * b.e1() + a.e23() * b.e3(),
            a.e2() * b.e23() - a.e1() * b.e31() - a.e23() * b.e2() + a.e31() * b.e1(),
            a.e1() * b.e2() - a.e2() * b.e1() - a.e23() * b.e31() + a.e31() * b.e23(),
            a.e2() * b.e3() - a.e3() * b.e2() + a.e12() * b.e31() - a.e31() * b.e12(),
            a.e3() * b.e1() - a.e1() * b.e3() - a.e12() * b.e23() + a.e23() * b.e12(),
            T::ZERO,
        )
    }
}
