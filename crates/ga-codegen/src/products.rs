//! The products the generator writes, each defined by the reference algebra's own operation.

use ga_reference::Multivector;

use crate::model::{AlgebraSpec, Dual, Inner, Regressive};

/// A bilinear product and how it is spelled in Rust.
pub struct Product {
    /// The key used in file names, function names and the table's `hand_written` list.
    pub key: &'static str,
    /// As the impl docs name it, `"Geometric product"`.
    pub doc: &'static str,
    /// The symbol in docs, `*`.
    pub symbol: &'static str,
    /// The trait, `Mul` (from `core::ops` when `operator`), or `LeftContraction`.
    pub trait_name: &'static str,
    /// The trait's method.
    pub method: &'static str,
    /// Whether the trait is an operator of `core::ops`.
    pub operator: bool,
    /// The file the impls go to.
    pub file: &'static str,
}

/// Every bilinear product, in the order written.
pub const PRODUCTS: [Product; 8] = [
    Product {
        key: "geometric",
        doc: "Geometric product",
        symbol: "*",
        trait_name: "Mul",
        method: "mul",
        operator: true,
        file: "geometric",
    },
    Product {
        key: "outer",
        doc: "Outer product",
        symbol: "^",
        trait_name: "BitXor",
        method: "bitxor",
        operator: true,
        file: "outer",
    },
    Product {
        key: "inner",
        doc: "Inner product",
        symbol: "|",
        trait_name: "BitOr",
        method: "bitor",
        operator: true,
        file: "inner",
    },
    Product {
        key: "regressive",
        doc: "Regressive product",
        symbol: "&",
        trait_name: "BitAnd",
        method: "bitand",
        operator: true,
        file: "regressive",
    },
    Product {
        key: "left_contraction",
        doc: "Left contraction",
        symbol: "⌋",
        trait_name: "LeftContraction",
        method: "left_contraction",
        operator: false,
        file: "contractions",
    },
    Product {
        key: "right_contraction",
        doc: "Right contraction",
        symbol: "⌊",
        trait_name: "RightContraction",
        method: "right_contraction",
        operator: false,
        file: "contractions",
    },
    Product {
        key: "scalar_product",
        doc: "Scalar product",
        symbol: "∗",
        trait_name: "ScalarProduct",
        method: "scalar_product",
        operator: false,
        file: "contractions",
    },
    Product {
        key: "commutator",
        doc: "Commutator product",
        symbol: "×",
        trait_name: "Commutator",
        method: "commutator",
        operator: false,
        file: "commutator",
    },
];

/// The reference algebra's definition of product `key` in `spec`'s conventions.
///
/// # Panics
///
/// If `key` is not a product, or the dual-based regressive product is asked of a degenerate
/// metric.
pub fn evaluate(spec: &AlgebraSpec, key: &str, a: &Multivector, b: &Multivector) -> Multivector {
    match key {
        "geometric" => a.geometric(b),
        "outer" => a.outer(b),
        "inner" => match spec.inner {
            Inner::Hestenes => a.inner(b),
            Inner::FatDot => a.fat_dot(b),
            Inner::LeftContraction => a.left_contraction(b),
        },
        "regressive" => match spec.regressive {
            Regressive::ViaDual => {
                let dual = |m: &Multivector| m.dual().expect("ViaDual needs an invertible I");
                dual(a).outer(&dual(b)).undual()
            }
            Regressive::Complement => a.regressive(b),
        },
        "left_contraction" => a.left_contraction(b),
        "right_contraction" => a.right_contraction(b),
        "scalar_product" => a.algebra().scalar(a.scalar_product(b)),
        "commutator" => a.commutator(b),
        _ => panic!("no product {key}"),
    }
}

/// The reference dual and undual of `spec`.
///
/// # Panics
///
/// If the dual `A I⁻¹` is asked of a degenerate metric.
pub fn dual(spec: &AlgebraSpec, m: &Multivector, undual: bool) -> Multivector {
    match (spec.dual, undual) {
        (Dual::InversePseudoscalar, false) => m.dual().expect("A I^-1 needs an invertible I"),
        (Dual::InversePseudoscalar, true) => m.undual(),
        (Dual::Complement, false) => m.right_complement(),
        (Dual::Complement, true) => m.left_complement(),
    }
}
