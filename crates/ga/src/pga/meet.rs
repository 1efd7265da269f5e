//! `Line ^ Plane`, the point where a line meets a plane, written for the vector units (f32).
//!
//! For the line `a` (`e01, e02, e03, e12, e31, e23`) and the plane `b` (`e0, e1, e2, e3`), the
//! outer product is (the generated expansion, `generated::outer_line_plane`)
//!
//! ```text
//! e021 = e02 b1 - e01 b2 - e12 b0
//! e013 = e01 b3 - e03 b1 - e31 b0
//! e032 = e03 b2 - e02 b3 - e23 b0
//! e123 = e12 b3 + e31 b2 + e23 b1
//! ```
//!
//! Each coefficient is three products, so the point in storage order (`e021, e013, e032,
//! e123`) is three lane-wise products of lane permutations, each lane's two negative terms
//! placed where the permutations are cheapest:
//!
//! ```text
//! X1 Y1 = [e02, e01, e03, e12] [b1, b3, b2, b3]
//! X2 Y2 = [e01, e03, e23, e31] [b2, b1, b0, b2]
//! X3 Y3 = [e12, e31, e02, e23] [b0, b0, b3, b1]
//! P = X1 Y1 + s (X2 Y2 + X3 Y3),  s = [-1, -1, -1, 1]
//! ```
//!
//! `pga::simd` forms the `X` from two loads of the line (`[e01, e02, e03, e12]` and `[e31,
//! e23]`) and the `Y` from the plane: seven permutations and four multiplies or fused
//! multiply-adds where the expansion takes twelve products and eight sums. Each coefficient
//! sums the same three products, in another order and with fused roundings: exact wherever
//! the expansion is (products and sums of small integers), and within a few units in the last
//! place of it elsewhere (tested against it).
//!
//! f64 and the portable builds use the expansion: the same form on four f64 lanes, whose
//! permutations cross the register's halves, measured 3% slower (`results/README.md`).

use core::ops::BitXor;

use crate::Scalar;
use crate::pga::{Line, Plane, Point};

/// Outer product `Line ^ Plane -> Point`: the meet of the line and the plane (the module docs).
impl<T: Scalar> BitXor<Plane<T>> for Line<T> {
    type Output = Point<T>;
    #[inline]
    fn bitxor(self, b: Plane<T>) -> Point<T> {
        match T::pga_meet_line_plane(self.as_array(), b.as_array()) {
            Some(p) => Point::from_array(p),
            None => crate::pga::generated::outer_line_plane(self, b),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::g3::geometric::tests::{close, coefficients};
    use crate::pga::generated::outer_line_plane;

    /// The kernel against the generated expansion: exactly on small integers, closely on
    /// random inputs, in both precisions.
    #[test]
    fn meet_matches_the_expansion() {
        fn check<T: Scalar>(tolerance: f64) {
            let mut x = coefficients(5);
            let mut n = 0u64;
            for _ in 0..1000 {
                let line: [f64; 6] = core::array::from_fn(|_| x.next().unwrap());
                let plane: [f64; 4] = core::array::from_fn(|_| x.next().unwrap());
                let (l, p) = (line.map(T::from_f64), plane.map(T::from_f64));
                let (l, p) = (Line::from_array(l), Plane::from_array(p));
                let got = (l ^ p).to_array().map(T::to_f64);
                let want = outer_line_plane(l, p).to_array().map(T::to_f64);
                assert!(close(got, want, tolerance), "{line:?} {plane:?}");
                // Small integers: every product and sum exact on both sides.
                n = n.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
                let int = |k: u32| T::from_f64(f64::from((n >> k) as u8 % 17) - 8.0);
                let l = Line::from_array(core::array::from_fn(|k| int(8 * k as u32)));
                let p = Plane::from_array(core::array::from_fn(|k| int(48 + 4 * k as u32)));
                assert_eq!(l ^ p, outer_line_plane(l, p));
            }
        }
        check::<f32>(1e-5);
        check::<f64>(1e-13);
    }
}
