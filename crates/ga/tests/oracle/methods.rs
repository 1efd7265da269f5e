//! The method products against the reference: left and right contractions, the scalar
//! product and the commutator on every pair of types that has them, and a check that the pairs
//! without them are identically zero.

use ga::g3::{
    Bivector, Commutator, LeftContraction, Multivector, RightContraction, Rotor, ScalarProduct,
    Trivector, Vector,
};
use ga_reference::Multivector as Reference;

use super::{F32, F64, check_binary, g3, regressive};

/// Checks the method `$method` for each listed pair of types, at precision `$t`.
macro_rules! method {
    ($t:ty, $tol:expr, $method:ident, $reference:expr; $($a:ident $b:ident),+ $(,)?) => {
        $(
            check_binary::<$a<$t>, $b<$t>, _>(
                concat!(
                    stringify!($a), ".", stringify!($method), "(", stringify!($b), ") (",
                    stringify!($t), ")"
                ),
                $tol,
                |x, y| x.$method(y),
                $reference,
            );
        )+
    };
}

/// The reference scalar product as a multivector, to compare like the other products.
fn scalar_product(a: &Reference, b: &Reference) -> Reference {
    g3().scalar(a.scalar_product(b))
}

/// Left and right contractions on every pair where they are not identically zero (the rest
/// are checked to vanish in `pairs_without_an_impl_are_identically_zero`).
#[test]
fn contractions() {
    method!(f64, F64, left_contraction, Reference::left_contraction;
        Vector Vector, Vector Bivector, Vector Trivector, Vector Rotor, Vector Multivector,
        Bivector Bivector, Bivector Trivector, Bivector Rotor, Bivector Multivector,
        Trivector Trivector, Trivector Multivector,
        Rotor Vector, Rotor Bivector, Rotor Trivector, Rotor Rotor, Rotor Multivector,
        Multivector Vector, Multivector Bivector, Multivector Trivector, Multivector Rotor,
        Multivector Multivector,
    );
    method!(f32, F32, left_contraction, Reference::left_contraction;
        Vector Bivector, Rotor Bivector, Rotor Multivector, Multivector Multivector);
    method!(f64, F64, right_contraction, Reference::right_contraction;
        Vector Vector, Vector Rotor, Vector Multivector,
        Bivector Vector, Bivector Bivector, Bivector Rotor, Bivector Multivector,
        Trivector Vector, Trivector Bivector, Trivector Trivector, Trivector Rotor,
        Trivector Multivector,
        Rotor Vector, Rotor Bivector, Rotor Rotor, Rotor Multivector,
        Multivector Vector, Multivector Bivector, Multivector Trivector, Multivector Rotor,
        Multivector Multivector,
    );
    method!(f32, F32, right_contraction, Reference::right_contraction;
        Bivector Rotor, Multivector Trivector, Multivector Multivector);
}

/// The scalar product and the commutator product on every pair where they are not
/// identically zero.
#[test]
fn scalar_product_and_commutator() {
    method!(f64, F64, scalar_product, scalar_product;
        Vector Vector, Vector Multivector,
        Bivector Bivector, Bivector Rotor, Bivector Multivector,
        Trivector Trivector, Trivector Multivector,
        Rotor Bivector, Rotor Rotor, Rotor Multivector,
        Multivector Vector, Multivector Bivector, Multivector Trivector, Multivector Rotor,
        Multivector Multivector,
    );
    method!(f32, F32, scalar_product, scalar_product; Rotor Rotor, Multivector Multivector);
    method!(f64, F64, commutator, Reference::commutator;
        Vector Vector, Vector Bivector, Vector Rotor, Vector Multivector,
        Bivector Vector, Bivector Bivector, Bivector Rotor, Bivector Multivector,
        Rotor Vector, Rotor Bivector, Rotor Rotor, Rotor Multivector,
        Multivector Vector, Multivector Bivector, Multivector Rotor, Multivector Multivector,
    );
    method!(f32, F32, commutator, Reference::commutator;
        Bivector Bivector, Rotor Rotor, Multivector Multivector);
    check_binary::<Vector<f64>, Vector<f64>, _>("Vector::cross", F64, Vector::cross, |a, b| {
        a.outer(b).dual().expect("G3 is not degenerate")
    });
}

/// The traits serve generic code, with the same kernels as the inherent methods.
#[test]
fn method_traits_in_generic_code() {
    fn left<A: LeftContraction<B>, B>(a: A, b: B) -> A::Output {
        a.left_contraction(b)
    }
    check_binary::<Rotor<f64>, Bivector<f64>, _>(
        "left via trait",
        F64,
        left,
        Reference::left_contraction,
    );
    check_binary::<Multivector<f64>, Vector<f64>, _>(
        "right via trait",
        F64,
        RightContraction::right_contraction,
        Reference::right_contraction,
    );
    check_binary::<Vector<f64>, Multivector<f64>, f64>(
        "scalar product via trait",
        F64,
        ScalarProduct::scalar_product,
        scalar_product,
    );
    check_binary::<Rotor<f64>, Multivector<f64>, _>(
        "commutator via trait",
        F64,
        Commutator::commutator,
        Reference::commutator,
    );
}

/// The pairs that get no operator or method: their products vanish for all inputs in 3D, so
/// leaving them out loses nothing. Checked on random inputs against the reference, as a zero
/// scalar result (which also asserts that the reference produces no other grade).
#[test]
fn pairs_without_an_impl_are_identically_zero() {
    macro_rules! zero {
        ($what:literal, $reference:expr; $($a:ident $b:ident),+ $(,)?) => {$(
            check_binary::<$a<f64>, $b<f64>, f64>(
                concat!(stringify!($a), " ", $what, " ", stringify!($b), " is zero"),
                F64,
                |_, _| 0.0,
                $reference,
            );
        )+};
    }
    zero!("^", Reference::outer;
        Vector Trivector, Bivector Bivector, Bivector Trivector,
        Trivector Vector, Trivector Bivector, Trivector Trivector,
    );
    zero!("&", regressive; Vector Vector);
    zero!("left_contraction", Reference::left_contraction;
        Bivector Vector, Trivector Vector, Trivector Bivector, Trivector Rotor);
    zero!("right_contraction", Reference::right_contraction;
        Vector Bivector, Vector Trivector, Bivector Trivector, Rotor Trivector);
    zero!("scalar_product", scalar_product;
        Vector Bivector, Vector Trivector, Vector Rotor, Bivector Vector, Bivector Trivector,
        Trivector Vector, Trivector Bivector, Trivector Rotor, Rotor Vector, Rotor Trivector,
    );
    zero!("commutator", Reference::commutator;
        Vector Trivector, Bivector Trivector, Rotor Trivector, Multivector Trivector,
        Trivector Vector, Trivector Bivector, Trivector Trivector, Trivector Rotor,
        Trivector Multivector,
    );
}
