//! Conversions between the G3 types: widening with `From`, narrowing with `TryFrom`.
//!
//! Narrowing never drops a component silently: a multivector converts to a grade type only when
//! every coefficient outside that type is exactly zero, otherwise [`NarrowError`] names the
//! first offending blade.

use core::fmt;

use crate::Scalar;
use crate::g3::multivector::BASIS;
use crate::g3::{Bivector, Multivector, Rotor, Trivector, Vector};

/// A multivector had a non-zero component that the target type cannot hold.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct NarrowError {
    /// The type converted to (`"Vector"`, `"Bivector"`, ...).
    pub target: &'static str,
    /// The first blade, in the report's basis order, whose coefficient was non-zero.
    pub blade: &'static str,
}

impl fmt::Display for NarrowError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "cannot convert multivector to {}: its {} component is non-zero",
            self.target, self.blade
        )
    }
}

impl std::error::Error for NarrowError {}

/// Checks that every coefficient not listed in `keep` (indices in the report's order) is zero.
pub(crate) fn check_zero<T: Scalar>(
    m: &Multivector<T>,
    target: &'static str,
    keep: &[usize],
) -> Result<(), NarrowError> {
    for (k, c) in m.to_array().into_iter().enumerate() {
        // `!=` rather than `== 0` negated: NaN outside the grade is an error too.
        if !keep.contains(&k) && c != T::ZERO {
            return Err(NarrowError { target, blade: BASIS[k] });
        }
    }
    Ok(())
}

impl<T: Scalar> From<T> for Multivector<T> {
    #[inline]
    fn from(s: T) -> Self {
        Self::scalar(s)
    }
}

impl<T: Scalar> From<Vector<T>> for Multivector<T> {
    #[inline]
    fn from(v: Vector<T>) -> Self {
        Self::new(T::ZERO, v.e1, v.e2, v.e3, T::ZERO, T::ZERO, T::ZERO, T::ZERO)
    }
}

impl<T: Scalar> From<Bivector<T>> for Multivector<T> {
    #[inline]
    fn from(b: Bivector<T>) -> Self {
        Self::new(T::ZERO, T::ZERO, T::ZERO, T::ZERO, b.e12, b.e23, b.e31, T::ZERO)
    }
}

impl<T: Scalar> From<Trivector<T>> for Multivector<T> {
    #[inline]
    fn from(t: Trivector<T>) -> Self {
        Self::new(T::ZERO, T::ZERO, T::ZERO, T::ZERO, T::ZERO, T::ZERO, T::ZERO, t.e123)
    }
}

impl<T: Scalar> From<Rotor<T>> for Multivector<T> {
    #[inline]
    fn from(r: Rotor<T>) -> Self {
        Self::new(r.s, T::ZERO, T::ZERO, T::ZERO, r.e12, r.e23, r.e31, T::ZERO)
    }
}

impl<T: Scalar> From<T> for Rotor<T> {
    #[inline]
    fn from(s: T) -> Self {
        Self::new(s, T::ZERO, T::ZERO, T::ZERO)
    }
}

impl<T: Scalar> From<Bivector<T>> for Rotor<T> {
    #[inline]
    fn from(b: Bivector<T>) -> Self {
        Self::from_scalar_bivector(T::ZERO, b)
    }
}

impl<T: Scalar> TryFrom<Multivector<T>> for Vector<T> {
    type Error = NarrowError;
    #[inline]
    fn try_from(m: Multivector<T>) -> Result<Self, NarrowError> {
        check_zero(&m, "Vector", &[1, 2, 3])?;
        Ok(m.vector_part())
    }
}

impl<T: Scalar> TryFrom<Multivector<T>> for Bivector<T> {
    type Error = NarrowError;
    #[inline]
    fn try_from(m: Multivector<T>) -> Result<Self, NarrowError> {
        check_zero(&m, "Bivector", &[4, 5, 6])?;
        Ok(m.bivector_part())
    }
}

impl<T: Scalar> TryFrom<Multivector<T>> for Trivector<T> {
    type Error = NarrowError;
    #[inline]
    fn try_from(m: Multivector<T>) -> Result<Self, NarrowError> {
        check_zero(&m, "Trivector", &[7])?;
        Ok(m.trivector_part())
    }
}

impl<T: Scalar> TryFrom<Multivector<T>> for Rotor<T> {
    type Error = NarrowError;
    #[inline]
    fn try_from(m: Multivector<T>) -> Result<Self, NarrowError> {
        check_zero(&m, "Rotor", &[0, 4, 5, 6])?;
        Ok(m.even_part())
    }
}

impl<T: Scalar> TryFrom<Rotor<T>> for Bivector<T> {
    type Error = NarrowError;
    #[inline]
    fn try_from(r: Rotor<T>) -> Result<Self, NarrowError> {
        if r.s == T::ZERO {
            Ok(r.bivector())
        } else {
            Err(NarrowError { target: "Bivector", blade: BASIS[0] })
        }
    }
}
