//! Exact arithmetic on dyadic rationals `m * 2^e` (`m` a big integer): the slow path.
//!
//! Every finite `f64` is such a number, and sums, differences and products of dyadic
//! rationals are dyadic rationals again, so the polynomials this crate evaluates (3x3
//! determinants of coordinate differences) are computed here with no rounding at all, over the
//! whole range of `f64`, subnormals included. The representation is deliberately naive (one
//! heap-allocated big integer per value, exponents aligned by shifting) because this path only
//! runs when the floating-point filter cannot certify a sign, and being obviously right matters
//! more here than being fast.

use core::cmp::Ordering;
use core::ops::{Add, Mul, Neg, Sub};

use num_bigint::{BigInt, Sign as BigSign};
use num_integer::Integer;

use crate::Sign;

/// An exact dyadic rational `mant * 2^exp`.
#[derive(Clone, Debug)]
pub(crate) struct Dyadic {
    mant: BigInt,
    exp: i64,
}

impl Dyadic {
    /// The exact value of `x`, or `None` if `x` is infinite or NaN.
    pub(crate) fn from_f64(x: f64) -> Option<Self> {
        if !x.is_finite() {
            return None;
        }
        // IEEE 754 binary64: 1 sign bit, 11 exponent bits, 52 fraction bits. A normal number
        // is (2^52 + fraction) * 2^(biased - 1075); a subnormal (biased exponent 0) is
        // fraction * 2^-1074. Both are integers times a power of two, exactly.
        let bits = x.to_bits();
        let fraction = bits & ((1u64 << 52) - 1);
        let biased = i64::try_from((bits >> 52) & 0x7ff).unwrap_or(0);
        let (mant, exp) =
            if biased == 0 { (fraction, -1074) } else { (fraction | (1u64 << 52), biased - 1075) };
        // Drop trailing zero bits (1e4 becomes 10000 * 2^0, not 5^4 2^56 * 2^-52): smaller
        // mantissas make every later product cheaper.
        let zeros = if mant == 0 { 0 } else { mant.trailing_zeros() };
        let (mant, exp) = (mant >> zeros, exp + i64::from(zeros));
        let mant = BigInt::from(mant);
        Some(Self { mant: if x.is_sign_negative() { -mant } else { mant }, exp })
    }

    /// The exact values of three coordinates.
    pub(crate) fn from_point(p: [f64; 3]) -> Option<[Self; 3]> {
        Some([Self::from_f64(p[0])?, Self::from_f64(p[1])?, Self::from_f64(p[2])?])
    }

    /// The sign of the value.
    pub(crate) fn sign(&self) -> Sign {
        match self.mant.sign() {
            BigSign::Minus => Sign::Negative,
            BigSign::NoSign => Sign::Zero,
            BigSign::Plus => Sign::Positive,
        }
    }

    /// Whether the value is zero.
    pub(crate) fn is_zero(&self) -> bool {
        self.sign() == Sign::Zero
    }

    /// `self + sign * other`, exactly: the mantissa with the larger exponent is shifted left
    /// to the smaller exponent.
    fn add_signed(&self, other: &Self, negate: bool) -> Self {
        // An exact zero has an arbitrary exponent: it must not take part in the alignment.
        if other.is_zero() {
            return self.clone();
        }
        if self.is_zero() {
            return if negate { -other } else { other.clone() };
        }
        let combine = |a: BigInt, b: &BigInt| if negate { a - b } else { a + b };
        match self.exp.cmp(&other.exp) {
            Ordering::Equal => {
                Self { mant: combine(self.mant.clone(), &other.mant), exp: self.exp }
            }
            Ordering::Greater => {
                let shifted = &self.mant << shift_amount(self.exp - other.exp);
                Self { mant: combine(shifted, &other.mant), exp: other.exp }
            }
            Ordering::Less => {
                let shifted = &other.mant << shift_amount(other.exp - self.exp);
                Self { mant: combine(self.mant.clone(), &shifted), exp: self.exp }
            }
        }
    }

    /// `num / den` rounded to the nearest `f64` (ties to even), or `None` if `den` is zero.
    ///
    /// The quotient is correctly rounded unless it lies in the subnormal range (below
    /// `2^-1022`), where a second rounding can move it by one unit of `2^-1074`; a quotient
    /// beyond the largest finite `f64` gives an infinity.
    pub(crate) fn ratio_to_f64(num: &Self, den: &Self) -> Option<f64> {
        if den.is_zero() {
            return None;
        }
        if num.is_zero() {
            return Some(0.0);
        }
        let negative = num.mant.sign() != den.mant.sign();
        let (mut a, mut b) = (num.mant.magnitude().clone(), den.mant.magnitude().clone());
        // Scale so that the integer quotient a / b has 55 or 56 bits: with 53 bits kept, the
        // next bit is the rounding bit and everything below it (the remaining quotient bits
        // and the remainder) only matters as "zero or not", the sticky bit.
        let lead = i64::try_from(a.bits()).unwrap_or(i64::MAX)
            - i64::try_from(b.bits()).unwrap_or(i64::MAX);
        let scale = 55 - lead;
        if scale >= 0 {
            a <<= shift_amount(scale);
        } else {
            b <<= shift_amount(-scale);
        }
        let (quotient, remainder) = a.div_rem(&b);
        // 2^54 <= quotient < 2^56, so it fits in a u64 with room for one more bit. Appending
        // the sticky bit below it makes the u64 -> f64 conversion (which rounds to nearest,
        // ties to even, as IEEE 754 requires) round exactly as the true quotient would: the
        // two agree on every bit above the sticky position, and the true quotient is an exact
        // tie only if the sticky bit is zero.
        let digits = quotient.to_u64_digits();
        let q = digits.first().copied().unwrap_or(0);
        let sticky = u64::from(remainder.bits() != 0);
        let rounded = ((q << 1) | sticky) as f64;
        let exp = num.exp - den.exp - scale - 1;
        let magnitude = scale_by_power_of_two(rounded, exp);
        Some(if negative { -magnitude } else { magnitude })
    }
}

/// A shift that fits in `usize`. Exponent differences of finite `f64` polynomials of degree 3
/// stay below 10,000, so this never saturates in practice; saturating keeps it panic-free.
fn shift_amount(diff: i64) -> usize {
    usize::try_from(diff).unwrap_or(usize::MAX)
}

/// `x * 2^exp`, exact unless the result is subnormal or overflows.
fn scale_by_power_of_two(mut x: f64, mut exp: i64) -> f64 {
    // 2^k for |k| <= 1000 is a normal f64, so step there in chunks.
    let step = |k: i64| f64::from_bits(u64::try_from(k + 1023).unwrap_or(0) << 52);
    while exp > 1000 {
        x *= step(1000);
        exp -= 1000;
        if x.is_infinite() {
            return x;
        }
    }
    while exp < -1000 {
        x *= step(-1000);
        exp += 1000;
        if x == 0.0 {
            return x;
        }
    }
    x * step(exp)
}

impl Add for &Dyadic {
    type Output = Dyadic;
    fn add(self, other: &Dyadic) -> Dyadic {
        self.add_signed(other, false)
    }
}

impl Sub for &Dyadic {
    type Output = Dyadic;
    fn sub(self, other: &Dyadic) -> Dyadic {
        self.add_signed(other, true)
    }
}

impl Mul for &Dyadic {
    type Output = Dyadic;
    fn mul(self, other: &Dyadic) -> Dyadic {
        Dyadic { mant: &self.mant * &other.mant, exp: self.exp + other.exp }
    }
}

impl Neg for &Dyadic {
    type Output = Dyadic;
    fn neg(self) -> Dyadic {
        Dyadic { mant: -&self.mant, exp: self.exp }
    }
}

/// `p - q`, exactly.
pub(crate) fn sub3(p: &[Dyadic; 3], q: &[Dyadic; 3]) -> [Dyadic; 3] {
    [&p[0] - &q[0], &p[1] - &q[1], &p[2] - &q[2]]
}

/// `p x q`, exactly.
pub(crate) fn cross3(p: &[Dyadic; 3], q: &[Dyadic; 3]) -> [Dyadic; 3] {
    [
        &(&p[1] * &q[2]) - &(&p[2] * &q[1]),
        &(&p[2] * &q[0]) - &(&p[0] * &q[2]),
        &(&p[0] * &q[1]) - &(&p[1] * &q[0]),
    ]
}

/// `p . q`, exactly.
pub(crate) fn dot3(p: &[Dyadic; 3], q: &[Dyadic; 3]) -> Dyadic {
    &(&(&p[0] * &q[0]) + &(&p[1] * &q[1])) + &(&p[2] * &q[2])
}

/// `det[p, q, r] = p . (q x r)`, exactly.
pub(crate) fn det3(p: &[Dyadic; 3], q: &[Dyadic; 3], r: &[Dyadic; 3]) -> Dyadic {
    dot3(p, &cross3(q, r))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn d(x: f64) -> Dyadic {
        Dyadic::from_f64(x).unwrap()
    }

    #[test]
    fn conversion_round_trips_through_the_ratio() {
        // x / 1 must come back unchanged for normal, subnormal and extreme values.
        for x in [1.0, -0.1, 3.0e-310, -f64::MIN_POSITIVE, f64::MAX, 5e-324, 1e300, 12345.678] {
            assert_eq!(Dyadic::ratio_to_f64(&d(x), &d(1.0)), Some(x), "{x}");
        }
        assert!(Dyadic::from_f64(f64::NAN).is_none());
        assert!(Dyadic::from_f64(f64::NEG_INFINITY).is_none());
        assert_eq!(d(0.0).sign(), Sign::Zero);
        assert_eq!(d(-0.0).sign(), Sign::Zero);
    }

    #[test]
    fn sums_and_products_are_exact() {
        // 1 + 2^-100 - 1 is 2^-100 exactly (f64 arithmetic would give 0).
        let tiny = f64::from_bits((1023 - 100) << 52);
        let r = &(&d(1.0) + &d(tiny)) - &d(1.0);
        assert_eq!(Dyadic::ratio_to_f64(&r, &d(1.0)), Some(tiny));
        // (1 + 2^-52)^2 = 1 + 2^-51 + 2^-104; minus (1 + 2^-51) leaves 2^-104.
        let x = 1.0 + f64::EPSILON;
        let r = &(&d(x) * &d(x)) - &d(1.0 + 2.0 * f64::EPSILON);
        assert_eq!(Dyadic::ratio_to_f64(&r, &d(1.0)), Some(f64::EPSILON * f64::EPSILON));
        assert_eq!((&d(3.0) - &d(3.0)).sign(), Sign::Zero);
        assert_eq!((&d(-2.5) * &d(4.0)).sign(), Sign::Negative);
    }

    #[test]
    fn ratios_round_to_nearest_even() {
        assert_eq!(Dyadic::ratio_to_f64(&d(1.0), &d(3.0)), Some(1.0 / 3.0));
        assert_eq!(Dyadic::ratio_to_f64(&d(-2.0), &d(7.0)), Some(-2.0 / 7.0));
        assert_eq!(Dyadic::ratio_to_f64(&d(1e300), &d(1e-300)), Some(f64::INFINITY));
        assert_eq!(Dyadic::ratio_to_f64(&d(1.0), &d(0.0)), None);
        // (2^53 + 1) / 1 is a tie between 2^53 and 2^53 + 2: even wins (2^53).
        let big = &d(9_007_199_254_740_992.0) + &d(1.0);
        assert_eq!(Dyadic::ratio_to_f64(&big, &d(1.0)), Some(9_007_199_254_740_992.0));
        // (2^53 + 3) / 1 is a tie between 2^53 + 2 and 2^53 + 4: even wins (2^53 + 4).
        let big = &d(9_007_199_254_740_992.0) + &d(3.0);
        assert_eq!(Dyadic::ratio_to_f64(&big, &d(1.0)), Some(9_007_199_254_740_996.0));
        // Just above the tie rounds up.
        let above = &big + &d(1e-30);
        assert_eq!(Dyadic::ratio_to_f64(&above, &d(1.0)), Some(9_007_199_254_740_996.0));
        let below = &(&d(9_007_199_254_740_992.0) + &d(1.0)) + &d(1e-30);
        assert_eq!(Dyadic::ratio_to_f64(&below, &d(1.0)), Some(9_007_199_254_740_994.0));
    }
}
