//! The scalar type of the algebra: the workspace's [`real::Real`] and this crate's kernels.

/// Per-precision kernels, in a private module so that [`Scalar`] cannot be implemented outside
/// this crate (it stays `f32` and `f64`) and the hooks stay out of its public docs.
mod sealed {
    pub trait Kernels: Sized {
        /// The geometric product of two multivectors, coefficients in storage order.
        fn geometric_product(a: &[Self; 8], b: &[Self; 8]) -> [Self; 8];
        /// The product of two rotors `[s, e12, e23, e31]`.
        fn rotor_product(a: [Self; 4], b: [Self; 4]) -> [Self; 4];
        /// The reverse `[s, -e12, -e23, -e31]` of a rotor.
        fn rotor_reverse(a: [Self; 4]) -> [Self; 4];
        /// `Σ_k columns[k] p[k]`: a 4×4 matrix, by columns, times a 4-vector.
        fn map_point(columns: &[[Self; 4]; 4], p: [Self; 4]) -> [Self; 4];
        /// `y = offset + Σ_k columns[k] p[k]`, and `y`'s first three lanes divided by its last.
        fn map_down(columns: &[[Self; 4]; 4], offset: [Self; 4], p: [Self; 4]) -> [Self; 3];
        /// The geometric product of two R(3,0,1) multivectors, coefficients in basis order.
        fn pga_geometric(a: &[Self; 16], b: &[Self; 16]) -> [Self; 16];
        /// The product of two R(3,0,1) motors, coefficients in storage order, where this
        /// precision has a kernel of its own (else the dual-quaternion form of `pga::geometric`).
        fn pga_motor_product(a: &[Self; 8], b: &[Self; 8]) -> Option<[Self; 8]>;
        /// `Line ^ Plane` in R(3,0,1), coefficients in storage order, where this precision
        /// has a kernel of its own (else the generated expansion).
        fn pga_meet_line_plane(line: &[Self; 6], plane: &[Self; 4]) -> Option<[Self; 4]>;
        /// `p / p[3]` in the first three lanes (the last is 1 or `p[3] / p[3]`).
        fn divide_by_last(p: [Self; 4]) -> [Self; 4];
        /// The geometric product of two R(4,1) multivectors, coefficients in basis order.
        fn cga_geometric(a: &[Self; 32], b: &[Self; 32]) -> [Self; 32];
    }
}

/// The scalar type of the algebra: [`real::Real`] (re-exported as [`crate::Real`]), which says
/// what a float the project computes in is, plus the algebra's own per-precision kernels.
///
/// Implemented for `f32` and `f64`, and only for them. Every type in [`crate::g3`] is generic
/// over this trait so that one implementation serves both precisions. The one thing it adds to
/// [`real::Real`] is a concern of this crate alone: the hooks by which the products pick, per
/// precision, the AVX2 kernels of `g3::simd` or the portable code (private, so they stay out
/// of the public API). Everything else, `mul_add` and `mul_add_if_fma` included, is
/// [`real::Real`]'s.
///
/// Generic code names the items through the type (`T::ZERO`, `T::from_f64(x)`); a path
/// through this trait (`<T as Scalar>::ZERO`) does not reach a supertrait's items, so write
/// `<T as Real>::ZERO` where a path is needed.
pub trait Scalar: real::Real + sealed::Kernels {}

impl Scalar for f32 {}
impl Scalar for f64 {}

/// Whether the SIMD kernels of `g3::simd` are compiled in.
macro_rules! with_simd {
    ($simd:expr, $portable:expr) => {{
        #[cfg(all(target_arch = "x86_64", target_feature = "avx2", target_feature = "fma"))]
        {
            $simd
        }
        #[cfg(not(all(target_arch = "x86_64", target_feature = "avx2", target_feature = "fma")))]
        {
            $portable
        }
    }};
}

impl sealed::Kernels for f32 {
    #[inline]
    fn geometric_product(a: &[f32; 8], b: &[f32; 8]) -> [f32; 8] {
        with_simd!(crate::g3::simd::geometric_f32(a, b), portable_geometric(a, b))
    }
    #[inline]
    fn rotor_product(a: [f32; 4], b: [f32; 4]) -> [f32; 4] {
        with_simd!(crate::g3::simd::rotor_product_f32(a, b), portable_rotor_product(a, b))
    }
    #[inline]
    fn rotor_reverse(a: [f32; 4]) -> [f32; 4] {
        with_simd!(crate::g3::simd::rotor_reverse_f32(a), [a[0], -a[1], -a[2], -a[3]])
    }
    #[inline]
    fn map_point(columns: &[[f32; 4]; 4], p: [f32; 4]) -> [f32; 4] {
        with_simd!(crate::pga::simd::map_point_f32(columns, p), portable_map_point(columns, p))
    }
    #[inline]
    fn map_down(columns: &[[f32; 4]; 4], offset: [f32; 4], p: [f32; 4]) -> [f32; 3] {
        with_simd!(
            crate::cga::simd::map_down_f32(columns, offset, p),
            portable_map_down(columns, offset, p)
        )
    }
    #[inline]
    fn pga_geometric(a: &[f32; 16], b: &[f32; 16]) -> [f32; 16] {
        with_simd!(
            crate::pga::generated::lanes::geometric_f32(a, b),
            crate::pga::geometric::blockwise(a, b)
        )
    }
    #[inline]
    fn pga_motor_product(a: &[f32; 8], b: &[f32; 8]) -> Option<[f32; 8]> {
        with_simd!(Some(crate::pga::simd::motor_product_f32(a, b)), {
            let _ = (a, b);
            None
        })
    }
    #[inline]
    fn pga_meet_line_plane(line: &[f32; 6], plane: &[f32; 4]) -> Option<[f32; 4]> {
        with_simd!(Some(crate::pga::simd::meet_line_plane_f32(line, plane)), {
            let _ = (line, plane);
            None
        })
    }
    #[inline]
    fn divide_by_last(p: [f32; 4]) -> [f32; 4] {
        with_simd!(crate::pga::simd::divide_by_last_f32(p), portable_divide_by_last(p))
    }
    #[inline]
    fn cga_geometric(a: &[f32; 32], b: &[f32; 32]) -> [f32; 32] {
        with_simd!(
            crate::cga::generated::lanes::geometric_f32(a, b),
            crate::cga::geometric::blockwise(a, b)
        )
    }
}

impl sealed::Kernels for f64 {
    #[inline]
    fn geometric_product(a: &[f64; 8], b: &[f64; 8]) -> [f64; 8] {
        with_simd!(crate::g3::simd::geometric_f64(a, b), portable_geometric(a, b))
    }
    #[inline]
    fn rotor_product(a: [f64; 4], b: [f64; 4]) -> [f64; 4] {
        // The portable form already vectorises well for f64 (glam's DQuat is scalar code).
        portable_rotor_product(a, b)
    }
    #[inline]
    fn rotor_reverse(a: [f64; 4]) -> [f64; 4] {
        [a[0], -a[1], -a[2], -a[3]]
    }
    #[inline]
    fn map_point(columns: &[[f64; 4]; 4], p: [f64; 4]) -> [f64; 4] {
        with_simd!(crate::pga::simd::map_point_f64(columns, p), portable_map_point(columns, p))
    }
    #[inline]
    fn map_down(columns: &[[f64; 4]; 4], offset: [f64; 4], p: [f64; 4]) -> [f64; 3] {
        with_simd!(
            crate::cga::simd::map_down_f64(columns, offset, p),
            portable_map_down(columns, offset, p)
        )
    }
    #[inline]
    fn pga_geometric(a: &[f64; 16], b: &[f64; 16]) -> [f64; 16] {
        with_simd!(
            crate::pga::generated::lanes::geometric_f64(a, b),
            crate::pga::geometric::blockwise(a, b)
        )
    }
    #[inline]
    fn pga_motor_product(a: &[f64; 8], b: &[f64; 8]) -> Option<[f64; 8]> {
        with_simd!(Some(crate::pga::simd::motor_product_f64(a, b)), {
            let _ = (a, b);
            None
        })
    }
    #[inline]
    fn pga_meet_line_plane(_: &[f64; 6], _: &[f64; 4]) -> Option<[f64; 4]> {
        // The generated expansion: the f32 kernel's form on four f64 lanes, whose permutations
        // cross the register's halves, measured 3% slower (results/README.md).
        None
    }
    #[inline]
    fn divide_by_last(p: [f64; 4]) -> [f64; 4] {
        // Three scalar divisions: a 4-lane f64 division occupies the divider as long, and
        // measured slower (results/README.md).
        portable_divide_by_last(p)
    }
    #[inline]
    fn cga_geometric(a: &[f64; 32], b: &[f64; 32]) -> [f64; 32] {
        with_simd!(
            crate::cga::generated::lanes::geometric_f64(a, b),
            crate::cga::geometric::blockwise(a, b)
        )
    }
}

#[allow(dead_code)] // unused when every precision has a SIMD kernel
#[inline]
fn portable_map_down<T: Scalar>(c: &[[T; 4]; 4], o: [T; 4], p: [T; 4]) -> [T; 3] {
    let y: [T; 4] = core::array::from_fn(|l| {
        c[3][l].mul_add_if_fma(
            p[3],
            c[2][l].mul_add_if_fma(
                p[2],
                c[1][l].mul_add_if_fma(p[1], c[0][l].mul_add_if_fma(p[0], o[l])),
            ),
        )
    });
    [y[0] / y[3], y[1] / y[3], y[2] / y[3]]
}

/// `p / p[3]` in the first three lanes, three scalar divisions.
#[inline]
fn portable_divide_by_last<T: Scalar>(p: [T; 4]) -> [T; 4] {
    [p[0] / p[3], p[1] / p[3], p[2] / p[3], T::ONE]
}

#[allow(dead_code)] // unused when every precision has a SIMD kernel
#[inline]
fn portable_map_point<T: Scalar>(c: &[[T; 4]; 4], p: [T; 4]) -> [T; 4] {
    core::array::from_fn(|l| {
        c[3][l].mul_add_if_fma(
            p[3],
            c[2][l].mul_add_if_fma(p[2], c[1][l].mul_add_if_fma(p[1], c[0][l] * p[0])),
        )
    })
}

#[inline]
fn portable_rotor_product<T: Scalar>(a: [T; 4], b: [T; 4]) -> [T; 4] {
    use crate::g3::Rotor;
    crate::g3::geometric::rotor_product_portable(Rotor::from_array(a), Rotor::from_array(b))
        .to_array()
}

#[allow(dead_code)] // unused when every precision has a SIMD kernel
#[inline]
fn portable_geometric<T: Scalar>(a: &[T; 8], b: &[T; 8]) -> [T; 8] {
    use crate::g3::Multivector;
    crate::g3::geometric::geometric_portable(Multivector { c: *a }, Multivector { c: *b }).c
}
