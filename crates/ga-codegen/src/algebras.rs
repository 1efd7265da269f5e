//! The table of algebras: signature, basis order and orientation, and the types as sets of
//! blades. Everything the generator writes follows from these three entries.

use crate::model::{AlgebraSpec, Dual, Inner, Regressive, Storage, TypeSpec};

/// Every algebra `ga` holds, in the order they are written.
#[must_use]
pub fn all() -> Vec<AlgebraSpec> {
    vec![g3(), pga(), cga()]
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
        lanes: false,
        versors: &["Vector", "Bivector", "Rotor"],
        sandwiched: &["Vector", "Bivector", "Trivector", "Rotor"],
        maps: &[],
    }
}

/// Projective geometric algebra R(3,0,1), plane-based, in the basis of bivector.net and Klein.
fn pga() -> AlgebraSpec {
    AlgebraSpec {
        name: "pga",
        title: "R(3,0,1)",
        dir: "crates/ga/src/pga/generated",
        module: "crate::pga",
        generators: &[('0', 0.0), ('1', 1.0), ('2', 1.0), ('3', 1.0)],
        basis: &[
            "1", "e0", "e1", "e2", "e3", "e01", "e02", "e03", "e12", "e31", "e23", "e021", "e013",
            "e032", "e123", "e0123",
        ],
        types: vec![
            TypeSpec::fields(
                "Plane",
                "A plane (grade 1) `e0 e0 + e1 e1 + e2 e2 + e3 e3`: the plane \
                 `e1 x + e2 y + e3 z + e0 = 0`.",
                &["e0", "e1", "e2", "e3"],
            ),
            TypeSpec::fields(
                "Line",
                "A line (grade 2): the ideal part `e01, e02, e03` and the Euclidean part \
                 `e12, e31, e23`.",
                &["e01", "e02", "e03", "e12", "e31", "e23"],
            ),
            TypeSpec::fields(
                "Point",
                "A point (grade 3) `x e032 + y e013 + z e021 + w e123`: the Euclidean point \
                 `(x, y, z) / w`, or the direction `(x, y, z)` when `w = 0` (an ideal point).",
                &["e021", "e013", "e032", "e123"],
            ),
            TypeSpec::fields(
                "Motor",
                "A motor (the even subalgebra): rotations, translations and screws.",
                &["1", "e01", "e02", "e03", "e12", "e31", "e23", "e0123"],
            ),
            TypeSpec::fields(
                "Rotor",
                "A rotor: a rotation about an axis through the origin (scalar and Euclidean \
                 bivector).",
                &["1", "e12", "e31", "e23"],
            ),
            TypeSpec::fields(
                "Translator",
                "A translator: a translation (scalar and ideal bivector).",
                &["1", "e01", "e02", "e03"],
            ),
            TypeSpec::fields("Pseudoscalar", "A multiple of the pseudoscalar `e0123`.", &["e0123"]),
            TypeSpec::fields(
                "Multivector",
                "A general multivector of R(3,0,1), sixteen coefficients in the basis order.",
                &[
                    "1", "e0", "e1", "e2", "e3", "e01", "e02", "e03", "e12", "e31", "e23", "e021",
                    "e013", "e032", "e123", "e0123",
                ],
            ),
        ],
        inner: Inner::FatDot,
        regressive: Regressive::Complement,
        dual: Dual::Complement,
        emit_types: true,
        // Written by hand (`pga/geometric.rs`, `pga/meet.rs`) for the vector units; the
        // generated scalar forms become `pub(crate)` functions they are checked against (and
        // the portable builds' kernels where no other is written).
        hand_written: &[
            ("geometric", "Motor", "Motor"),
            ("geometric", "Multivector", "Multivector"),
            ("outer", "Line", "Plane"),
        ],
        lanes: true,
        versors: &["Plane", "Line", "Point", "Motor", "Rotor", "Translator"],
        sandwiched: &["Plane", "Line", "Point", "Motor", "Rotor", "Translator"],
        maps: &[],
    }
}
/// Conformal geometric algebra R(4,1), with `e4 = e+` (`e4² = 1`) and `e5 = e-` (`e5² = -1`),
/// every blade in increasing generator order.
fn cga() -> AlgebraSpec {
    AlgebraSpec {
        name: "cga",
        title: "R(4,1)",
        dir: "crates/ga/src/cga/generated",
        module: "crate::cga",
        generators: &[('1', 1.0), ('2', 1.0), ('3', 1.0), ('4', 1.0), ('5', -1.0)],
        basis: &CGA_BASIS,
        types: vec![
            TypeSpec::fields(
                "Vector",
                "A vector (grade 1): points, dual spheres and dual planes.",
                &CGA_BASIS[1..6],
            ),
            TypeSpec::fields(
                "Bivector",
                "A bivector (grade 2): point pairs (dual).",
                &CGA_BASIS[6..16],
            ),
            TypeSpec::fields(
                "Trivector",
                "A trivector (grade 3): circles and lines.",
                &CGA_BASIS[16..26],
            ),
            TypeSpec::fields(
                "Quadvector",
                "A quadvector (grade 4): spheres and planes.",
                &CGA_BASIS[26..31],
            ),
            TypeSpec::fields(
                "Pseudoscalar",
                "A multiple of the pseudoscalar `e12345`.",
                &["e12345"],
            ),
            TypeSpec::fields(
                "Rotor",
                "A Euclidean rotor: a rotation about the origin (scalar and `e12, e13, e23`).",
                &["1", "e12", "e13", "e23"],
            ),
            TypeSpec::fields(
                "Motor",
                "An element of the even subalgebra (grades 0, 2, 4): rotors, translators, \
                 dilators and their products.",
                &[
                    "1", "e12", "e13", "e14", "e15", "e23", "e24", "e25", "e34", "e35", "e45",
                    "e1234", "e1235", "e1245", "e1345", "e2345",
                ],
            ),
            TypeSpec::fields(
                "Multivector",
                "A general multivector of R(4,1), thirty-two coefficients in the basis order.",
                &CGA_BASIS,
            ),
        ],
        inner: Inner::LeftContraction,
        regressive: Regressive::Complement,
        dual: Dual::InversePseudoscalar,
        emit_types: true,
        // Built from G3's kernels by hand (`cga/geometric.rs`), checked against the generated
        // form.
        hand_written: &[("geometric", "Multivector", "Multivector")],
        lanes: true,
        versors: &["Vector", "Rotor", "Motor"],
        sandwiched: &["Vector", "Bivector", "Trivector", "Quadvector"],
        // `Motor::transform_points`: a motor's map of vectors, worked out once.
        maps: &[("Motor", "Vector")],
    }
}

/// The conformal basis: by grade, and within a grade in lexicographic order of the generators.
static CGA_BASIS: [&str; 32] = [
    "1", "e1", "e2", "e3", "e4", "e5", "e12", "e13", "e14", "e15", "e23", "e24", "e25", "e34",
    "e35", "e45", "e123", "e124", "e125", "e134", "e135", "e145", "e234", "e235", "e245", "e345",
    "e1234", "e1235", "e1245", "e1345", "e2345", "e12345",
];
