//! Measures: the exact error of a reported hit distance, and order statistics of a sample.

use intersect::{Ray, Triangle};
use num_bigint::BigInt;
use num_traits::{Signed, ToPrimitive, Zero};

use super::fp::{pow2, ulp};

/// The error of a reported hit distance `t` against the exact one, `t* = N / D` (the ray's
/// parameter where its line meets the triangle's plane; see the `exact` crate docs for
/// `N` and `D`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TError {
    /// `|t - t*| / |t*|`, computed exactly and rounded once (to within `2^-59`).
    pub relative: f64,
    /// `|t - t*|` in units of the last place of `t*` in the kernel's precision.
    pub ulps: f64,
    /// `t*`, rounded.
    pub exact: f64,
}

/// The exact error of `t` for `ray` and `tri` (all `f64` values, as the kernel saw them after
/// casting to `f64`), or `None` when the line is parallel to the plane (`D = 0`), meets it at
/// the origin (`N = 0`), or an input is not finite. `digits` is the kernel's precision (24 or
/// 53) for the `ulps` figure.
///
/// Every input is an integer multiple of the smallest power of two among them, so `N` and
/// `D` (cubic in the coordinate differences) are computed exactly as big integers, and so is
/// `t D - N`; only the final ratios are rounded.
#[must_use]
pub fn t_error(tri: &Triangle<f64>, ray: &Ray<f64>, t: f64, digits: u32) -> Option<TError> {
    let values: Vec<f64> =
        [ray.origin, ray.dir, tri.a, tri.b, tri.c].iter().flatten().copied().chain([t]).collect();
    if values.iter().any(|x| !x.is_finite()) {
        return None;
    }
    let parts: Vec<(i64, i32)> = values.iter().map(|&x| split(x)).collect();
    let base = parts.iter().filter(|(m, _)| *m != 0).map(|(_, e)| *e).min().unwrap_or(0);
    let big = |k: usize| -> BigInt {
        let (m, e) = parts[k];
        BigInt::from(m) << (e - base) as usize
    };
    let point = |k: usize| -> [BigInt; 3] { [big(k), big(k + 1), big(k + 2)] };
    let (o, d, a, b, c) = (point(0), point(3), point(6), point(9), point(12));
    let diff = |p: &[BigInt; 3]| -> [BigInt; 3] { core::array::from_fn(|k| &p[k] - &o[k]) };
    let (pa, pb, pc) = (diff(&a), diff(&b), diff(&c));
    let n = det(&pa, &pb, &pc);
    let den = det(&pa, &pb, &d) + det(&pb, &pc, &d) + det(&pc, &pa, &d);
    if n.is_zero() || den.is_zero() {
        return None;
    }
    // t = mt 2^et exactly; compare t D with N at a common power of two.
    let (mt, et) = split(t);
    let (td, n_scaled) = if et >= 0 {
        ((BigInt::from(mt) * &den) << et as usize, n.clone())
    } else {
        (BigInt::from(mt) * &den, n.clone() << (-et) as usize)
    };
    let relative = ratio(&(td - &n_scaled).abs(), &n_scaled.abs());
    let exact = ratio(&n, &den);
    Some(TError { relative, ulps: relative * exact.abs() / ulp(exact, digits), exact })
}

/// The exact sign (-1, 0 or 1) of `n . d`, with `n = (b - a) x (c - a)` the triangle's
/// normal: negative when the ray meets the triangle's front. `None` for non-finite input.
///
/// Computed as the determinant `det[b - a, c - a, d]` on big integers (every input an integer
/// multiple of the smallest power of two among them), so it is exact however the triangle
/// and the direction are conditioned.
#[must_use]
pub fn facing_sign(tri: &Triangle<f64>, dir: [f64; 3]) -> Option<i32> {
    let values: Vec<f64> = [tri.a, tri.b, tri.c, dir].iter().flatten().copied().collect();
    if values.iter().any(|x| !x.is_finite()) {
        return None;
    }
    let parts: Vec<(i64, i32)> = values.iter().map(|&x| split(x)).collect();
    let base = parts.iter().filter(|(m, _)| *m != 0).map(|(_, e)| *e).min().unwrap_or(0);
    let big = |k: usize| -> BigInt {
        let (m, e) = parts[k];
        BigInt::from(m) << (e - base) as usize
    };
    let point = |k: usize| -> [BigInt; 3] { [big(k), big(k + 1), big(k + 2)] };
    let (a, b, c, d) = (point(0), point(3), point(6), point(9));
    let ab: [BigInt; 3] = core::array::from_fn(|k| &b[k] - &a[k]);
    let ac: [BigInt; 3] = core::array::from_fn(|k| &c[k] - &a[k]);
    let v = det(&ab, &ac, &d);
    Some(if v.is_zero() {
        0
    } else if v.is_positive() {
        1
    } else {
        -1
    })
}

/// `x = m 2^e` with an integer `m` of at most 53 bits (`(0, 0)` for zero).
fn split(x: f64) -> (i64, i32) {
    if x == 0.0 {
        return (0, 0);
    }
    let bits = x.to_bits();
    let biased = ((bits >> 52) & 0x7ff) as i32;
    let frac = (bits & ((1u64 << 52) - 1)) as i64;
    let (m, e) = if biased == 0 { (frac, -1074) } else { (frac | (1i64 << 52), biased - 1075) };
    (if x < 0.0 { -m } else { m }, e)
}

fn det(p: &[BigInt; 3], q: &[BigInt; 3], r: &[BigInt; 3]) -> BigInt {
    &p[0] * (&q[1] * &r[2] - &q[2] * &r[1]) - &p[1] * (&q[0] * &r[2] - &q[2] * &r[0])
        + &p[2] * (&q[0] * &r[1] - &q[1] * &r[0])
}

/// `a / b` rounded to `f64` (to within a couple of units of `2^-60` relative); `b != 0`.
fn ratio(a: &BigInt, b: &BigInt) -> f64 {
    let top = |x: &BigInt| -> (f64, i64) {
        let shift = (x.bits() as i64 - 62).max(0);
        ((x >> shift as usize).to_f64().unwrap_or(f64::NAN), shift)
    };
    let ((fa, sa), (fb, sb)) = (top(a), top(b));
    let e = sa - sb;
    let q = fa / fb;
    // Apply 2^e in two steps so that neither factor overflows on its own.
    let half = (e / 2).clamp(-1100, 1100) as i32;
    let rest = (e - e / 2).clamp(-1100, 1100) as i32;
    q * pow2(half.clamp(-1074, 1023)) * pow2(rest.clamp(-1074, 1023))
}

/// The median, 99.9th percentile and maximum of a sample (nearest rank), or `None` when the
/// sample is empty.
#[must_use]
pub fn quantiles(sample: &mut [f64]) -> Option<Quantiles> {
    if sample.is_empty() {
        return None;
    }
    sample.sort_unstable_by(f64::total_cmp);
    let rank = |q: f64| -> f64 {
        let k = ((q * sample.len() as f64).ceil() as usize).clamp(1, sample.len());
        sample[k - 1]
    };
    Some(Quantiles { median: rank(0.5), p999: rank(0.999), max: sample[sample.len() - 1] })
}

/// Order statistics of an error sample.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Quantiles {
    /// The median (nearest rank).
    pub median: f64,
    /// The 99.9th percentile (nearest rank).
    pub p999: f64,
    /// The largest value.
    pub max: f64,
}

/// Events per million: `count / total * 1e6` (0 when `total` is 0).
#[must_use]
pub fn per_million(count: u64, total: u64) -> f64 {
    if total == 0 { 0.0 } else { count as f64 / total as f64 * 1e6 }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exact_distance_errors() {
        let tri = Triangle::new([0.0, 0.0, 3.0], [1.0, 0.0, 3.0], [0.0, 1.0, 3.0]);
        let ray = Ray::new([0.25, 0.25, 0.0], [0.0, 0.0, 2.0]);
        // t* = 1.5 exactly.
        let exact = t_error(&tri, &ray, 1.5, 53).unwrap();
        assert_eq!((exact.relative, exact.ulps, exact.exact), (0.0, 0.0, 1.5));
        let off = t_error(&tri, &ray, 1.5 + 3.0 * f64::EPSILON, 53).unwrap();
        assert_eq!(off.ulps, 3.0);
        assert_eq!(off.relative, 2.0 * f64::EPSILON);
        let off32 = t_error(&tri, &ray, 1.5 - f64::from(f32::EPSILON), 24).unwrap();
        assert_eq!(off32.ulps, 1.0);
        // t* = 1/3: the correctly rounded double is within half an ulp.
        let third = Ray::new([0.25, 0.25, 0.0], [0.0, 0.0, 9.0]);
        let e = t_error(&tri, &third, 1.0 / 3.0, 53).unwrap();
        assert!(e.ulps > 0.0 && e.ulps <= 0.5, "{e:?}");
        // Parallel rays have no distance.
        assert!(t_error(&tri, &Ray::new([0.0; 3], [1.0, 0.0, 0.0]), 1.0, 53).is_none());
        // Tiny and huge magnitudes side by side.
        let s = 2f64.powi(-1000);
        let tiny = Triangle::new([0.0, 0.0, s], [s, 0.0, s], [0.0, s, s]);
        let down = Ray::new([0.0; 3], [0.0, 0.0, 2f64.powi(-700)]);
        let e = t_error(&tiny, &down, 2f64.powi(-300), 53).unwrap();
        assert_eq!((e.relative, e.exact), (0.0, 2f64.powi(-300)));
    }

    #[test]
    fn facing_signs_are_exact() {
        let tri = Triangle::new([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
        assert_eq!(facing_sign(&tri, [0.0, 0.0, -1.0]), Some(-1));
        assert_eq!(facing_sign(&tri, [0.3, 0.2, 1e-300]), Some(1));
        assert_eq!(facing_sign(&tri, [0.3, 0.2, 0.0]), Some(0));
        assert_eq!(facing_sign(&tri, [f64::NAN, 0.0, 1.0]), None);
    }

    #[test]
    fn nearest_rank_quantiles() {
        let mut v: Vec<f64> = (1..=1000).map(f64::from).rev().collect();
        let q = quantiles(&mut v).unwrap();
        assert_eq!((q.median, q.p999, q.max), (500.0, 999.0, 1000.0));
        assert!(quantiles(&mut []).is_none());
        assert_eq!(per_million(3, 2_000_000), 1.5);
    }
}
