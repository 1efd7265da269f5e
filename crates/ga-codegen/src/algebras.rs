//! The table of algebras: signature, basis order and orientation, and the types as sets of
//! blades. Everything the generator writes follows from these three entries.

use crate::model::{AlgebraSpec, Dual, Inner, Regressive, Storage, TypeSpec};

/// Every algebra `ga` holds, in the order they are written.
#[must_use]
pub fn all() -> Vec<AlgebraSpec> {
    vec![g3()]
}

/// G(3,0,0), the report's algebra. Its types (with their hand-written geometry, `Display` and
/// the SIMD layout of `Multivector`) are declared by hand in `crates/ga/src/g3`; only the
/// products are written here, with the report's inner product.
fn g3() -> AlgebraSpec {
    AlgebraSpec {
        name: "g3",
        title: "G(3,0,0)",
        dir: "crates/ga/src/g3/generated",
        module: "crate::g3",
        generators: &[('1', 1.0), ('2', 1.0), ('3', 1.0)],
        basis: &["1", "e1", "e2", "e3", "e12", "e23", "e31", "e123"],
        types: vec![
            TypeSpec::fields("Vector", "", &["e1", "e2", "e3"]),
            TypeSpec::fields("Bivector", "", &["e12", "e23", "e31"]),
            TypeSpec::fields("Trivector", "", &["e123"]),
            TypeSpec::fields("Rotor", "", &["1", "e12", "e23", "e31"]),
            TypeSpec {
                name: "Multivector",
                doc: "",
                blades: &["1", "e1", "e2", "e3", "e12", "e23", "e31", "e123"],
                // `Multivector` stores `1, e1, e2, e12, e3, e31, e23, e123` (the bitmask order
                // its SIMD kernel wants); slot of each blade above.
                storage: Storage::Array(&[0, 1, 2, 4, 3, 6, 5, 7]),
            },
        ],
        inner: Inner::Hestenes,
        regressive: Regressive::ViaDual,
        dual: Dual::InversePseudoscalar,
        emit_types: false,
        // Written by hand next to SIMD kernels (`g3/geometric.rs`); the generated scalar forms
        // become `pub(crate)` functions they are checked against.
        hand_written: &[
            ("geometric", "Multivector", "Multivector"),
            ("geometric", "Rotor", "Rotor"),
        ],
        versors: &["Vector", "Bivector", "Rotor"],
        sandwiched: &["Vector", "Bivector", "Trivector", "Rotor"],
    }
}
