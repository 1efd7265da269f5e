//! What every G3 type shares beyond its operators: formatting in the report's style and the
//! component-wise comparisons (`abs_diff_eq`, `is_finite`, `max_abs`).
//!
//! One small macro writes them from each type's `terms`; the operators (`+`, `-`, negation,
//! scaling, and every product) are written by `ga-codegen` in `g3/generated/`.

use core::fmt;

use crate::Scalar;

/// Writes `terms` as the report writes a multivector: `1 + 2e1 - 0.5e23`.
///
/// Zero terms are omitted and an all-zero value prints as `0`. A unit coefficient on a blade
/// is printed (`1e12`) so that every term reads the same way. The formatter's precision, if
/// any, applies to each coefficient (`{:.2}`), and terms that would print as zero at that
/// precision are omitted too (rounding noise such as `1e-17e1` does not clutter `{:.3}`).
pub(crate) fn write_terms<T: Scalar>(
    f: &mut fmt::Formatter<'_>,
    terms: impl IntoIterator<Item = (T, &'static str)>,
) -> fmt::Result {
    let mut first = true;
    for (c, blade) in terms {
        // NaN is not zero, so it is printed rather than silently dropped.
        if c == T::ZERO {
            continue;
        }
        if let Some(p) = f.precision() {
            // Below half a unit in the last printed place the coefficient would print as zero.
            let half_unit = 0.5 * 10f64.powi(-i32::try_from(p).unwrap_or(i32::MAX));
            if c.to_f64().abs() < half_unit {
                continue;
            }
        }
        let negative = c < T::ZERO;
        let magnitude = if negative { -c } else { c };
        match (first, negative) {
            (true, true) => f.write_str("-")?,
            (true, false) => {}
            (false, true) => f.write_str(" - ")?,
            (false, false) => f.write_str(" + ")?,
        }
        match f.precision() {
            Some(p) => write!(f, "{magnitude:.p$}{blade}")?,
            None => write!(f, "{magnitude}{blade}")?,
        }
        first = false;
    }
    if first {
        f.write_str("0")?;
    }
    Ok(())
}

/// Gives a struct of named scalar fields the helper `terms` (report-order coefficients with
/// blade names), then the operations of [`impl_linear`].
macro_rules! impl_fields {
    ($ty:ident { $($field:ident : $blade:literal),+ }) => {
        impl<T: $crate::Scalar> $ty<T> {
            /// The components with their blade names, in the report's order.
            #[inline(always)]
            pub(crate) fn terms(self) -> impl IntoIterator<Item = (T, &'static str)> {
                [$((self.$field, $blade)),+]
            }
        }
        $crate::g3::linear::impl_linear!($ty);
    };
}

/// Implements, for a type with the helper `terms`, `Display` (report style) and `abs_diff_eq`,
/// `is_finite`, `max_abs`.
macro_rules! impl_linear {
    ($ty:ident) => {
        impl<T: $crate::Scalar> core::fmt::Display for $ty<T> {
            fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
                $crate::g3::linear::write_terms(f, self.terms())
            }
        }
        impl<T: $crate::Scalar> $ty<T> {
            /// Whether every component differs from `other`'s by at most `eps`.
            #[must_use]
            #[inline]
            pub fn abs_diff_eq(self, other: Self, eps: T) -> bool {
                self.terms()
                    .into_iter()
                    .zip(other.terms())
                    .all(|((a, _), (b, _))| (a - b).abs() <= eps)
            }
            /// Whether every component is finite (neither infinite nor NaN).
            #[must_use]
            #[inline]
            pub fn is_finite(self) -> bool {
                self.terms().into_iter().all(|(a, _)| a.is_finite())
            }
            /// The largest absolute value among the components.
            #[must_use]
            #[inline]
            pub fn max_abs(self) -> T {
                self.terms().into_iter().fold(T::ZERO, |m, (a, _)| m.max(a.abs()))
            }
        }
    };
}

pub(crate) use {impl_fields, impl_linear};
