//! The vector parts of the `ga` and `ga-plucker` kernels, on four lanes.
//!
//! Both kernels store a triangle by axis, three rows of four numbers (see
//! [`crate::frame`] and [`crate::watertight`]), so that what they compute for three vectors
//! (inner products with `n`, `m_b`, `m_c`; projections of `a`, `b`, `c`) is one expression over
//! the rows, one vector per lane. On x86-64 with AVX2 and FMA (this workspace builds with
//! `-C target-cpu=x86-64-v3`) a row is one SSE register in `f32` and one AVX register in `f64`;
//! elsewhere the same expressions run lane by lane.
//!
//! **Same bits either way.** [`frame_products`] and [`edge_trivectors`] are the lane-by-lane
//! definitions, and every vector operation of the four-lane forms is one of their scalar
//! operations on each lane, with the same operands in the same order: a fused multiply-add
//! where they fuse, separate operations where they do not. So both forms round alike, and a
//! test checks it bit for bit on random input, NaN and infinities included.

use ga::Scalar;
use ga::g3::Vector;

/// The `ga` kernel's undivided values `[num, den, U, V]`, lane by lane: for a triangle stored
/// by axis (`axes[k] = (n_k, m_b_k, m_c_k, a_k)`) and a ray, with `s = a - o`, `num = s · n`,
/// `den = u · n`, `U = num (u · m_b) - den (s · m_b)` and `V` likewise with `m_c`. Each inner
/// product is `x_1 row_1[j]`, plus `x_2 row_2[j]`, plus `x_3 row_3[j]`, in that order, with
/// fused multiply-adds where the build has them; `U` is rounded once after `den (s · m_b)`.
#[cfg_attr(
    all(target_arch = "x86_64", target_feature = "avx2", target_feature = "fma"),
    allow(dead_code, reason = "with AVX2 and FMA only the tests use it, as the reference")
)]
#[inline(always)]
pub fn frame_products<T: Scalar>(axes: &[[T; 4]; 3], origin: &[T; 3], dir: &[T; 3]) -> [T; 4] {
    let [x, y, z] = axes;
    let s = [x[3] - origin[0], y[3] - origin[1], z[3] - origin[2]];
    let mad = T::mul_add_if_fma;
    let inner = |v: &[T; 3], j: usize| mad(v[2], z[j], mad(v[1], y[j], v[0] * x[j]));
    let (num, den) = (inner(&s, 0), inner(dir, 0));
    let edge = |j| mad(num, inner(dir, j), -(den * inner(&s, j)));
    [num, den, edge(1), edge(2)]
}

/// The `ga-plucker` kernel's projections, lane by lane: for a triangle stored by axis
/// (`axes[k] = (a_k, b_k, c_k, n_k)`) and a ray's basis `ex`, `ey`, returns `[x, y, w]`, where
/// lane `j < 3` of `x` and `y` holds vertex `j`'s coordinates `(v_j - o) · ex` and
/// `(v_j - o) · ey`, and of `w` the edge value opposite it, `x_p y_q - y_p x_q` with
/// `p = j + 1` and `q = j + 2` (mod 3). Lane 3 is of no use. A coordinate is `s_1 e_1`, plus
/// `s_2 e_2`, plus `s_3 e_3`, with fused multiply-adds where the build has them; an edge value
/// is two products and a subtraction, never fused (see [`crate::watertight`]).
#[cfg_attr(
    all(target_arch = "x86_64", target_feature = "avx2", target_feature = "fma"),
    allow(dead_code, reason = "with AVX2 and FMA only the tests use it, as the reference")
)]
#[inline(always)]
pub fn edge_trivectors<T: Scalar>(
    axes: &[[T; 4]; 3],
    origin: &[T; 3],
    ex: &[T; 3],
    ey: &[T; 3],
) -> [[T; 4]; 3] {
    let coords = |e: &[T; 3]| -> [T; 4] {
        core::array::from_fn(|j| {
            let s: [T; 3] = core::array::from_fn(|k| axes[k][j] - origin[k]);
            s[2].mul_add_if_fma(e[2], s[1].mul_add_if_fma(e[1], s[0] * e[0]))
        })
    };
    let (x, y) = (coords(ex), coords(ey));
    // Lane 3 pairs with itself, as the four-lane rotations leave it.
    let next = |j: usize, by: usize| if j == 3 { 3 } else { (j + by) % 3 };
    let w = core::array::from_fn(|j| {
        let (p, q) = (next(j, 1), next(j, 2));
        x[p] * y[q] - y[p] * x[q]
    });
    [x, y, w]
}

/// The four-lane forms, one per precision; the kernels call these.
#[cfg(all(target_arch = "x86_64", target_feature = "avx2", target_feature = "fma"))]
pub use x86::{edge_trivectors_f32, edge_trivectors_f64, frame_products_f32, frame_products_f64};

#[cfg(all(target_arch = "x86_64", target_feature = "avx2", target_feature = "fma"))]
mod x86 {
    //! SSE registers for `f32`, AVX registers for `f64`; the same code for both, written
    //! once by `four_lanes!` over the two sets of intrinsics. A lane permutation's
    //! immediate picks, for each result lane (two bits each, lane 0 lowest), a source lane.

    use core::arch::x86_64::*;

    macro_rules! four_lanes {
        ($t:ty, $frame:ident, $edges:ident, $load:ident, $store:ident, $set1:ident,
         $sub:ident, $mul:ident, $fmadd:ident, $fmsub:ident, $permute:ident, $first:ident) => {
            /// [`super::frame_products`] on four lanes.
            #[inline(always)]
            pub fn $frame(axes: &[[$t; 4]; 3], origin: &[$t; 3], dir: &[$t; 3]) -> [$t; 4] {
                // SAFETY: compiled only when the build enables AVX2 and FMA; each row is four
                // numbers (unaligned loads).
                unsafe {
                    let [x, y, z] = axes.each_ref().map(|row| $load(row.as_ptr()));
                    let inner = |v: [_; 3]| $fmadd(v[2], z, $fmadd(v[1], y, $mul(v[0], x)));
                    // s_k = a_k - o_k in every lane: each row's fourth lane, broadcast.
                    let a = [x, y, z].map(|row| $permute::<0b11_11_11_11>(row));
                    let along_s = inner(core::array::from_fn(|k| $sub(a[k], $set1(origin[k]))));
                    let along_u = inner(dir.map(|d| $set1(d)));
                    let num = $permute::<0>(along_s);
                    let den = $permute::<0>(along_u);
                    // Lanes 1 and 2: U and V.
                    let edges = $fmsub(num, along_u, $mul(den, along_s));
                    [
                        $first(num),
                        $first(den),
                        $first($permute::<1>(edges)),
                        $first($permute::<2>(edges)),
                    ]
                }
            }

            /// [`super::edge_trivectors`] on four lanes.
            #[inline(always)]
            pub fn $edges(
                axes: &[[$t; 4]; 3],
                origin: &[$t; 3],
                ex: &[$t; 3],
                ey: &[$t; 3],
            ) -> [[$t; 4]; 3] {
                // SAFETY: compiled only when the build enables AVX2 and FMA; the loads read
                // and the stores write four numbers of each row (unaligned).
                unsafe {
                    let rows = axes.each_ref().map(|row| $load(row.as_ptr()));
                    let s: [_; 3] = core::array::from_fn(|k| $sub(rows[k], $set1(origin[k])));
                    let coords = |e: &[$t; 3]| {
                        let e = e.map(|x| $set1(x));
                        $fmadd(s[2], e[2], $fmadd(s[1], e[1], $mul(s[0], e[0])))
                    };
                    let (x, y) = (coords(ex), coords(ey));
                    // (v1, v2, v0, v3) and (v2, v0, v1, v3).
                    let next = |v| $permute::<0b11_00_10_01>(v);
                    let after = |v| $permute::<0b11_01_00_10>(v);
                    let w = $sub($mul(next(x), after(y)), $mul(next(y), after(x)));
                    let mut out = [[0.0; 4]; 3];
                    for (row, v) in out.iter_mut().zip([x, y, w]) {
                        $store(row.as_mut_ptr(), v);
                    }
                    out
                }
            }
        };
    }

    four_lanes!(
        f32,
        frame_products_f32,
        edge_trivectors_f32,
        _mm_loadu_ps,
        _mm_storeu_ps,
        _mm_set1_ps,
        _mm_sub_ps,
        _mm_mul_ps,
        _mm_fmadd_ps,
        _mm_fmsub_ps,
        _mm_permute_ps,
        _mm_cvtss_f32
    );
    four_lanes!(
        f64,
        frame_products_f64,
        edge_trivectors_f64,
        _mm256_loadu_pd,
        _mm256_storeu_pd,
        _mm256_set1_pd,
        _mm256_sub_pd,
        _mm256_mul_pd,
        _mm256_fmadd_pd,
        _mm256_fmsub_pd,
        _mm256_permute4x64_pd,
        _mm256_cvtsd_f64
    );
}

/// Without AVX2 and FMA the four-lane forms are the lane-by-lane definitions.
#[cfg(not(all(target_arch = "x86_64", target_feature = "avx2", target_feature = "fma")))]
pub use {
    edge_trivectors as edge_trivectors_f32, edge_trivectors as edge_trivectors_f64,
    frame_products as frame_products_f32, frame_products as frame_products_f64,
};

/// The vector in lane `lane` of a triangle stored by axis.
#[inline(always)]
pub fn lane<T: Scalar>(axes: &[[T; 4]; 3], lane: usize) -> Vector<T> {
    Vector::from_array(axes.map(|row| row[lane]))
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};
    use rand_pcg::Pcg64;

    /// Bits equal, or both NaN (payloads may differ).
    fn same<T: Scalar>(
        got: impl IntoIterator<Item = T>,
        want: impl IntoIterator<Item = T>,
    ) -> bool {
        got.into_iter().zip(want).all(|(g, w)| {
            g.to_f64().to_bits() == w.to_f64().to_bits() || (g.is_nan() && w.is_nan())
        })
    }

    /// Lanes 0 to 2 of the projections (lane 3 is of no use).
    fn lanes<T: Copy>(p: [[T; 4]; 3]) -> impl Iterator<Item = T> {
        p.into_iter().flat_map(|row| row.into_iter().take(3))
    }

    /// The documented values written out once more with std's own arithmetic, lane by lane
    /// and independently of the code under test (which, built without AVX2 and FMA, *is* the
    /// lane-by-lane definition): `[num, den, U, V]` of [`frame_products`] and `[x, y, w]` of
    /// [`edge_trivectors`], multiply-adds fused exactly when the build has FMA.
    macro_rules! by_hand {
        ($t:ty) => {{
            let mad = |a: $t, b: $t, c: $t| {
                if cfg!(target_feature = "fma") { a.mul_add(b, c) } else { a * b + c }
            };
            let dot = move |v: [$t; 3], w: [$t; 3]| mad(v[2], w[2], mad(v[1], w[1], v[0] * w[0]));
            let frame = move |axes: &[[$t; 4]; 3], origin: &[$t; 3], dir: &[$t; 3]| {
                let column = |j: usize| [axes[0][j], axes[1][j], axes[2][j]];
                let s =
                    [column(3)[0] - origin[0], column(3)[1] - origin[1], column(3)[2] - origin[2]];
                let (num, den) = (dot(s, column(0)), dot(*dir, column(0)));
                let edge = |j: usize| mad(num, dot(*dir, column(j)), -(den * dot(s, column(j))));
                [num, den, edge(1), edge(2)]
            };
            let plucker = move |axes: &[[$t; 4]; 3], o: &[$t; 3], ex: &[$t; 3], ey: &[$t; 3]| {
                let vertex = |j: usize| [axes[0][j] - o[0], axes[1][j] - o[1], axes[2][j] - o[2]];
                let x: [$t; 3] = core::array::from_fn(|j| dot(vertex(j), *ex));
                let y: [$t; 3] = core::array::from_fn(|j| dot(vertex(j), *ey));
                let w: [$t; 3] = core::array::from_fn(|j| {
                    let (p, q) = ((j + 1) % 3, (j + 2) % 3);
                    x[p] * y[q] - y[p] * x[q]
                });
                [x, y, w]
            };
            (frame, plucker)
        }};
    }

    macro_rules! check {
        ($t:ty, $frame:ident, $edges:ident, $seed:expr) => {
            let mut rng = Pcg64::seed_from_u64($seed);
            let value = |rng: &mut Pcg64| -> $t {
                match rng.random_range(0..40) {
                    0 => <$t>::NAN,
                    1 => <$t>::INFINITY,
                    2 => 0.0,
                    _ => {
                        rng.random_range(-100.0..100.0) * (10.0 as $t).powi(rng.random_range(-3..3))
                    }
                }
            };
            let (frame, plucker) = by_hand!($t);
            for _ in 0..100_000 {
                let axes: [[$t; 4]; 3] =
                    core::array::from_fn(|_| core::array::from_fn(|_| value(&mut rng)));
                let [origin, dir, ex]: [[$t; 3]; 3] =
                    core::array::from_fn(|_| core::array::from_fn(|_| value(&mut rng)));
                let want = frame(&axes, &origin, &dir);
                let got = $frame(&axes, &origin, &dir);
                assert!(same(got, want), "{axes:?} {origin:?} {dir:?}: {got:?} {want:?}");
                let generic = frame_products(&axes, &origin, &dir);
                assert!(same(generic, want), "{axes:?} {origin:?} {dir:?}: {generic:?} {want:?}");
                let want = plucker(&axes, &origin, &ex, &dir).into_iter().flatten();
                let got = $edges(&axes, &origin, &ex, &dir);
                assert!(same(lanes(got), want.clone()), "{axes:?} {origin:?} {ex:?} {dir:?}");
                let generic = edge_trivectors(&axes, &origin, &ex, &dir);
                assert!(same(lanes(generic), want), "{axes:?} {origin:?} {ex:?} {dir:?}");
            }
        };
    }

    /// The four-lane forms (with AVX2 and FMA; without, the lane-by-lane definitions they
    /// then are) and the lane-by-lane definitions give the same bits as the values written
    /// out by hand, NaN and infinities included.
    #[test]
    fn four_lane_forms_match_lane_by_lane() {
        check!(f32, frame_products_f32, edge_trivectors_f32, 0x6a_4002);
        check!(f64, frame_products_f64, edge_trivectors_f64, 0x6a_4003);
    }
}
