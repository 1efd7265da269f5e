//! [`Trivector`]: grade 3, a multiple of the pseudoscalar `I = e123`.

use crate::Scalar;
use crate::g3::linear::impl_fields;

/// A trivector (grade 3), an oriented volume: `e123·I` with `I = e1 e2 e3`.
///
/// `I` commutes with everything in G3 and `I² = -1`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[repr(C)]
pub struct Trivector<T> {
    /// Coefficient of `e123 = e1 e2 e3`.
    pub e123: T,
}

impl_fields!(Trivector { e123: "e123" });

impl<T: Scalar> Trivector<T> {
    /// The zero trivector.
    pub const ZERO: Self = Self::new(T::ZERO);
    /// The unit pseudoscalar `I = e123` (right-handed).
    pub const I: Self = Self::new(T::ONE);
    /// The same as [`Trivector::I`], by its basis name.
    pub const E123: Self = Self::I;

    /// `e123 I`.
    #[must_use]
    #[inline]
    pub const fn new(e123: T) -> Self {
        Self { e123 }
    }

    /// `|T|² = T T̃ = e123²`.
    #[must_use]
    #[inline]
    pub fn norm_squared(self) -> T {
        self.e123 * self.e123
    }

    /// `|T| = |e123|`, the volume.
    #[must_use]
    #[inline]
    pub fn norm(self) -> T {
        self.e123.abs()
    }

    /// `(t I)⁻¹ = -I / t` (`I² = -1`), or `None` for zero or a non-finite result.
    #[must_use]
    #[inline]
    pub fn inverse(self) -> Option<Self> {
        let r = self.e123.recip();
        r.is_finite().then(|| Self::new(-r))
    }

    /// The reverse `T̃ = -T` (`e3 e2 e1 = -e1 e2 e3`).
    #[must_use]
    #[inline]
    pub fn reverse(self) -> Self {
        -self
    }

    /// The grade involution `T̂ = -T` (odd grade).
    #[must_use]
    #[inline]
    pub fn grade_involution(self) -> Self {
        -self
    }

    /// The Clifford conjugate `T̄ = T`.
    #[must_use]
    #[inline]
    pub fn conjugate(self) -> Self {
        self
    }

    /// The dual `(t I) I⁻¹ = t`, a scalar.
    #[must_use]
    #[inline]
    pub fn dual(self) -> T {
        self.e123
    }

    /// The undual `(t I) I = -t`, a scalar (`I² = -1`).
    #[must_use]
    #[inline]
    pub fn undual(self) -> T {
        -self.e123
    }

    /// The trivector `s I` whose [`dual`](Trivector::dual) is `s` (the undual of a scalar).
    #[must_use]
    #[inline]
    pub fn from_dual(s: T) -> Self {
        Self::new(s)
    }
}
