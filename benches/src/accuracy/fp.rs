//! Small floating-point tools: error-free sums that tell whether an operation was exact,
//! rounding to `f32`, units in the last place, and the few vector operations the generators
//! need.

/// `a + b` if the sum is exact in `f64`, else `None` (Knuth's two-sum: the rounding error of
/// a sum is itself a double, and it is zero exactly when the sum is exact).
#[must_use]
pub fn exact_add(a: f64, b: f64) -> Option<f64> {
    let s = a + b;
    if !s.is_finite() {
        return None;
    }
    let bb = s - a;
    let err = (a - (s - bb)) + (b - bb);
    (err == 0.0).then_some(s)
}

/// `a - b` if the difference is exact in `f64`, else `None`.
#[must_use]
pub fn exact_sub(a: f64, b: f64) -> Option<f64> {
    exact_add(a, -b)
}

/// `a * b` if the product is exact in `f64`, else `None` (the fused multiply-add gives the
/// product's rounding error exactly).
#[must_use]
pub fn exact_mul(a: f64, b: f64) -> Option<f64> {
    let p = a * b;
    if !p.is_finite() || (p != 0.0 && p.abs() < f64::MIN_POSITIVE) {
        // Subnormal products may have lost bits that the fused multiply-add cannot see.
        return None;
    }
    (a.mul_add(b, -p) == 0.0).then_some(p)
}

/// Componentwise [`exact_add`].
#[must_use]
pub fn exact_add3(a: [f64; 3], b: [f64; 3]) -> Option<[f64; 3]> {
    Some([exact_add(a[0], b[0])?, exact_add(a[1], b[1])?, exact_add(a[2], b[2])?])
}

/// Componentwise [`exact_sub`].
#[must_use]
pub fn exact_sub3(a: [f64; 3], b: [f64; 3]) -> Option<[f64; 3]> {
    Some([exact_sub(a[0], b[0])?, exact_sub(a[1], b[1])?, exact_sub(a[2], b[2])?])
}

/// `v * s` componentwise if every product is exact.
#[must_use]
pub fn exact_scale3(v: [f64; 3], s: f64) -> Option<[f64; 3]> {
    Some([exact_mul(v[0], s)?, exact_mul(v[1], s)?, exact_mul(v[2], s)?])
}

/// The nearest `f32` value, as an `f64`.
#[must_use]
pub fn round32(x: f64) -> f64 {
    f64::from(x as f32)
}

/// [`round32`] on each coordinate.
#[must_use]
pub fn round32_3(p: [f64; 3]) -> [f64; 3] {
    p.map(round32)
}

/// Whether every coordinate is an `f32` value (so that casting to `f32` changes nothing).
#[must_use]
pub fn is_f32_3(p: [f64; 3]) -> bool {
    p.iter().all(|&x| round32(x) == x || x.is_nan())
}

/// The unit in the last place of `x` in a format with `digits` significant bits (24 or 53):
/// `2^(e - digits + 1)` for `2^e <= |x| < 2^(e+1)`, and the format's smallest subnormal
/// spacing below its normal range.
#[must_use]
pub fn ulp(x: f64, digits: u32) -> f64 {
    let x = x.abs();
    let (min_exp, digits) = if digits == f32::MANTISSA_DIGITS {
        (f32::MIN_EXP - 1, 24)
    } else {
        (f64::MIN_EXP - 1, 53)
    };
    let e = if x > 0.0 && x.is_finite() { exponent(x).max(min_exp) } else { min_exp };
    pow2(e - digits + 1)
}

/// `floor(log2 |x|)` of a finite non-zero double, from its bits (subnormals included).
#[must_use]
pub fn exponent(x: f64) -> i32 {
    let bits = x.abs().to_bits();
    let biased = ((bits >> 52) & 0x7ff) as i32;
    if biased == 0 {
        // Subnormal: the leading one is in the fraction.
        let frac = bits & ((1u64 << 52) - 1);
        -1074 + (63 - frac.leading_zeros() as i32)
    } else {
        biased - 1023
    }
}

/// `2^e` for `-1074 <= e <= 1023` (exact), 0 below, infinity above.
#[must_use]
pub fn pow2(e: i32) -> f64 {
    if e > 1023 {
        f64::INFINITY
    } else if e >= -1022 {
        f64::from_bits(((e + 1023) as u64) << 52)
    } else if e >= -1074 {
        f64::from_bits(1u64 << (e + 1074))
    } else {
        0.0
    }
}

/// The `[f64; 3]` helpers, from the seam (re-exported for the accuracy modules).
pub use intersect::vec3::{add, cross, dot, length, scale, sub};

/// `a / |a|`, or `None` for a zero or non-finite vector.
#[must_use]
pub fn normalize(a: [f64; 3]) -> Option<[f64; 3]> {
    let l = length(a);
    (l > 0.0 && l.is_finite()).then(|| a.map(|x| x / l))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exactness_is_detected() {
        assert_eq!(exact_add(1.0, 2.0f64.powi(-52)), Some(1.0 + f64::EPSILON));
        assert_eq!(exact_add(1.0, 2.0f64.powi(-54)), None);
        assert_eq!(exact_sub(1.0, 2.0f64.powi(-60)), None);
        assert_eq!(exact_sub(0.75, 0.5), Some(0.25));
        assert_eq!(exact_mul(3.0, 0.5), Some(1.5));
        assert_eq!(exact_mul(0.1, 0.1), None);
        assert_eq!(exact_add(f64::MAX, f64::MAX), None);
    }

    #[test]
    fn ulps_and_exponents() {
        assert_eq!(ulp(1.0, 24), f64::from(f32::EPSILON));
        assert_eq!(ulp(1.0, 53), f64::EPSILON);
        assert_eq!(ulp(1.5, 53), f64::EPSILON);
        assert_eq!(ulp(-2.0, 24), 2.0 * f64::from(f32::EPSILON));
        assert_eq!(ulp(0.0, 53), f64::from_bits(1));
        assert_eq!(ulp(1e-40, 24), f64::from(f32::from_bits(1)));
        assert_eq!(exponent(f64::from_bits(1)), -1074);
        assert_eq!(exponent(0.75), -1);
        assert_eq!(pow2(-1074), f64::from_bits(1));
        assert_eq!(pow2(3), 8.0);
    }

    #[test]
    fn f32_rounding() {
        assert!(is_f32_3([0.5, 1.0, -3.25]));
        assert!(!is_f32_3([0.1, 1.0, 2.0]));
        assert_eq!(round32(0.1), f64::from(0.1f32));
    }
}
