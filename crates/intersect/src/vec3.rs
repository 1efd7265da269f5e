//! The few `[f64; 3]` operations that the back ends, the renderer, the benches and the tests
//! all need, written once. Plain arrays, as at the seam: no vector type of either algebra.
//!
//! Each is the textbook formula evaluated left to right with separate multiplications and
//! additions (Rust never contracts them into fused multiply-adds), so every caller gets the
//! same bits on every target.
//!
//! ```
//! use intersect::vec3::{cross, dot, length, sub};
//!
//! let (x, y) = ([1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
//! assert_eq!(cross(x, y), [0.0, 0.0, 1.0]);
//! assert_eq!(dot(sub(x, y), x), 1.0);
//! assert_eq!(length([3.0, 4.0, 0.0]), 5.0);
//! ```

/// `a - b`.
#[inline(always)]
#[must_use]
pub fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// `a + b`.
#[inline(always)]
#[must_use]
pub fn add(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

/// `a * s`.
#[inline(always)]
#[must_use]
pub fn scale(a: [f64; 3], s: f64) -> [f64; 3] {
    a.map(|x| x * s)
}

/// The dot product `a0 b0 + a1 b1 + a2 b2`.
#[inline(always)]
#[must_use]
pub fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// The cross product `a x b`.
#[inline(always)]
#[must_use]
pub fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

/// The Euclidean length `sqrt(a . a)`.
#[inline(always)]
#[must_use]
pub fn length(a: [f64; 3]) -> f64 {
    dot(a, a).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cross_is_orthogonal_and_follows_the_right_hand_rule() {
        let (a, b) = ([1.0, 2.0, 3.0], [-4.0, 0.5, 2.0]);
        let c = cross(a, b);
        assert_eq!((dot(a, c), dot(b, c)), (0.0, 0.0));
        assert_eq!(c, [2.5, -14.0, 8.5]);
        assert_eq!(cross(b, a), scale(c, -1.0));
        assert_eq!(add(sub(a, b), b), a);
        assert_eq!(length([2.0, 3.0, 6.0]), 7.0);
    }
}
