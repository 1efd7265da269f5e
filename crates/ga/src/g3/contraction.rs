//! The other products of [`Multivector`]: contractions, scalar product, commutator.
//!
//! They are methods rather than operators so that each operator keeps one meaning (see the
//! crate docs). Each expands the Cayley table of [`crate::g3::geometric`]-style products,
//! keeping the terms its grade rule selects.

use crate::Scalar;
use crate::g3::Multivector;

impl<T: Scalar> Multivector<T> {
    /// The left contraction `a ⌋ b`: for an `r`-blade `a` and an `s`-blade `b`, the grade
    /// `s - r` part of `a b`, zero when `r > s`. A scalar contracts as scaling (`λ ⌋ b = λ b`),
    /// which is where it differs from the report's inner product `|`.
    #[must_use]
    #[inline]
    pub fn left_contraction(self, b: Self) -> Self {
        let a = self;
        Self::new(
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

    /// The right contraction `a ⌊ b`: for an `r`-blade `a` and an `s`-blade `b`, the grade
    /// `r - s` part of `a b`, zero when `s > r`.
    #[must_use]
    #[inline]
    pub fn right_contraction(self, b: Self) -> Self {
        let a = self;
        Self::new(
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

    /// The scalar product `⟨a b⟩₀`, the scalar part of the geometric product.
    #[must_use]
    #[inline]
    pub fn scalar_product(self, b: Self) -> T {
        let a = self;
        a.s() * b.s() + a.e1() * b.e1() + a.e2() * b.e2() + a.e3() * b.e3()
            - a.e12() * b.e12()
            - a.e23() * b.e23()
            - a.e31() * b.e31()
            - a.e123() * b.e123()
    }

    /// The commutator product `a × b = (a b - b a) / 2`: the terms of `a b` whose blades
    /// anticommute (the commuting ones cancel).
    #[must_use]
    #[inline]
    pub fn commutator(self, b: Self) -> Self {
        let a = self;
        Self::new(
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
