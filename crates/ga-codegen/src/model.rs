//! The algebra table's types, and the blade arithmetic derived from them with `ga-reference`.

use ga_reference::{Algebra, Multivector, blade_from_factors, grade_of};

/// One algebra of the table.
pub struct AlgebraSpec {
    /// The module name, `"pga"`.
    pub name: &'static str,
    /// The signature as written in docs, `"R(3,0,1)"`.
    pub title: &'static str,
    /// The directory the generated files go to, relative to the workspace root.
    pub dir: &'static str,
    /// The Rust path of the module the types live in.
    pub module: &'static str,
    /// Each generator's name (a single character, the digit in blade names) and square.
    pub generators: &'static [(char, f64)],
    /// The basis blades in the documented order: `"1"` or `e` followed by generator names, the
    /// blade being the product of those generators in that order (`e31 = e3 e1`).
    pub basis: &'static [&'static str],
    /// The types, each a set of basis blades.
    pub types: Vec<TypeSpec>,
    /// Which inner product `|` is.
    pub inner: Inner,
    /// How the regressive product `&` is defined.
    pub regressive: Regressive,
    /// Which dual `dual()` is.
    pub dual: Dual,
    /// Whether the generator writes the types themselves (structs, constructors, constants,
    /// linear operations, involutions, duals, norms) or only their products.
    pub emit_types: bool,
    /// `(product, left, right)` kernels written by hand; the generated form becomes a
    /// `pub(crate)` function named `{product}_{left}_{right}` (snake case) to check them with.
    pub hand_written: &'static [(&'static str, &'static str, &'static str)],
    /// Whether `Multivector * Multivector` also gets the lane-by-lane AVX2 kernel of
    /// [`crate::lanes`] (in `lanes.rs`).
    pub lanes: bool,
    /// The types that may be the versor of a sandwich.
    pub versors: &'static [&'static str],
    /// The types a versor may be applied to.
    pub sandwiched: &'static [&'static str],
    /// `(versor, operand)` pairs whose sandwich is also written as a matrix, the method
    /// `versor.{operand}_map()` (snake case): for applying one versor to many operands.
    pub maps: &'static [(&'static str, &'static str)],
}

/// A type of an algebra: a named set of blades.
pub struct TypeSpec {
    /// The type's name.
    pub name: &'static str,
    /// The first line of its documentation (only used where the type is generated).
    pub doc: &'static str,
    /// Its blades, in field order.
    pub blades: &'static [&'static str],
    /// How its coefficients are stored.
    pub storage: Storage,
}

impl TypeSpec {
    /// A struct with one public field per blade.
    #[must_use]
    pub fn fields(name: &'static str, doc: &'static str, blades: &'static [&'static str]) -> Self {
        Self { name, doc, blades, storage: Storage::Fields }
    }
}

/// How a type stores its coefficients.
pub enum Storage {
    /// One public field per blade, named after it (`s` for the scalar).
    Fields,
    /// A private array `c`; entry `k` is the storage slot of the type's `k`-th blade.
    Array(&'static [usize]),
}

/// The choice of inner product for `|`.
#[derive(Clone, Copy, PartialEq, Eq)]
pub enum Inner {
    /// Hestenes' (the report's): grade `|r - s|`, zero when either side is a scalar.
    Hestenes,
    /// The "fat dot": grade `|r - s|`, scalars included.
    FatDot,
    /// The left contraction.
    LeftContraction,
}

/// The definition of the regressive product.
#[derive(Clone, Copy, PartialEq, Eq)]
pub enum Regressive {
    /// `undual(dual(a) ^ dual(b))` with the dual `A I⁻¹`.
    ViaDual,
    /// Through the metric-free complements (works in degenerate metrics).
    Complement,
}

/// The definition of `dual()`.
#[derive(Clone, Copy, PartialEq, Eq)]
pub enum Dual {
    /// `A I⁻¹`, with `undual(A) = A I`.
    InversePseudoscalar,
    /// The right complement (`e_A ^ dual(e_A) = I`), with the left complement as undual.
    Complement,
}

/// One blade of the documented basis.
pub struct Blade {
    /// `"e021"` (`"1"` for the scalar).
    pub name: String,
    /// The field name: the blade name, `s` for the scalar.
    pub field: String,
    /// The canonical (increasing order) blade as a bitmask.
    pub mask: usize,
    /// The blade is `sign` times the canonical blade.
    pub sign: f64,
    /// Its grade.
    pub grade: usize,
}

/// An algebra of the table with its blades resolved against the reference algebra.
pub struct Resolved<'a> {
    /// The table entry.
    pub spec: &'a AlgebraSpec,
    /// The reference algebra with the same metric.
    pub reference: Algebra,
    /// The documented basis.
    pub blades: Vec<Blade>,
    /// For each type, the indices (into `blades`) of its blades.
    pub type_blades: Vec<Vec<usize>>,
}

/// A bilinear product as a table: `table[i][j]` lists `(k, c)`: `e_i op e_j = Σ c e_k`.
pub type Table = Vec<Vec<Vec<(usize, i32)>>>;

impl<'a> Resolved<'a> {
    /// Resolves the blade names of `spec`.
    ///
    /// # Panics
    ///
    /// If a blade name is malformed, a blade repeats, or a type names a blade not in the basis.
    #[must_use]
    pub fn new(spec: &'a AlgebraSpec) -> Self {
        let metric: Vec<f64> = spec.generators.iter().map(|g| g.1).collect();
        let reference = Algebra::from_metric(&metric);
        let blades: Vec<Blade> = spec
            .basis
            .iter()
            .map(|&name| {
                let factors: Vec<usize> = if name == "1" {
                    Vec::new()
                } else {
                    let digits = name.strip_prefix('e').expect("blade names start with e");
                    digits
                        .chars()
                        .map(|c| {
                            spec.generators
                                .iter()
                                .position(|g| g.0 == c)
                                .unwrap_or_else(|| panic!("{name}: no generator {c}"))
                        })
                        .collect()
                };
                let (mask, sign) = blade_from_factors(&factors);
                let field = if name == "1" { "s".to_owned() } else { name.to_owned() };
                Blade { name: name.to_owned(), field, mask, sign, grade: grade_of(mask) }
            })
            .collect();
        let mut seen: Vec<usize> = blades.iter().map(|b| b.mask).collect();
        seen.sort_unstable();
        seen.dedup();
        assert_eq!(seen.len(), reference.blade_count(), "{}: basis is not complete", spec.name);
        assert_eq!(blades.len(), reference.blade_count(), "{}: a blade repeats", spec.name);
        let type_blades = spec
            .types
            .iter()
            .map(|t| {
                t.blades
                    .iter()
                    .map(|b| {
                        blades
                            .iter()
                            .position(|x| x.name == *b)
                            .unwrap_or_else(|| panic!("{}: no blade {b}", t.name))
                    })
                    .collect()
            })
            .collect();
        Self { spec, reference, blades, type_blades }
    }

    /// Declared blade `i` as a reference multivector.
    #[must_use]
    pub fn basis_blade(&self, i: usize) -> Multivector {
        self.reference.blade(self.blades[i].mask, self.blades[i].sign)
    }

    /// The non-zero coefficients of `m` in the declared basis, as integers.
    ///
    /// # Panics
    ///
    /// If a coefficient is not an integer (products of basis blades are ±1, 0, or ±2 in
    /// sandwiches).
    #[must_use]
    pub fn declared(&self, m: &Multivector) -> Vec<(usize, i32)> {
        self.blades
            .iter()
            .enumerate()
            .filter_map(|(k, b)| {
                let c = b.sign * m.coefficient(b.mask);
                assert_eq!(c, c.round(), "non-integer coefficient {c}");
                // In range: every coefficient is a small integer.
                #[allow(clippy::cast_possible_truncation)]
                (c != 0.0).then_some((k, c as i32))
            })
            .collect()
    }

    /// The table of a bilinear product, evaluated on every pair of basis blades.
    #[must_use]
    pub fn table(&self, op: impl Fn(&Multivector, &Multivector) -> Multivector) -> Table {
        let n = self.blades.len();
        (0..n)
            .map(|i| {
                (0..n)
                    .map(|j| self.declared(&op(&self.basis_blade(i), &self.basis_blade(j))))
                    .collect()
            })
            .collect()
    }

    /// The type index of `name`.
    ///
    /// # Panics
    ///
    /// If there is no such type.
    #[must_use]
    pub fn type_index(&self, name: &str) -> usize {
        self.spec
            .types
            .iter()
            .position(|t| t.name == name)
            .unwrap_or_else(|| panic!("{}: no type {name}", self.spec.name))
    }

    /// The smallest type that holds every blade of `needed` (blade indices), preferring types
    /// with no grade beyond those of `needed`; `None` is the scalar type `T` (only for the
    /// scalar blade).
    ///
    /// # Panics
    ///
    /// If no type holds them all.
    #[must_use]
    pub fn smallest_type(&self, needed: &[usize]) -> Option<usize> {
        if needed.iter().all(|&k| self.blades[k].grade == 0) {
            return None;
        }
        let grades: Vec<usize> = needed.iter().map(|&k| self.blades[k].grade).collect();
        let best = self
            .type_blades
            .iter()
            .enumerate()
            .filter(|(_, blades)| needed.iter().all(|k| blades.contains(k)))
            .min_by_key(|(_, blades)| {
                let extra = blades.iter().filter(|&&k| !grades.contains(&self.blades[k].grade));
                (extra.count() > 0, blades.len())
            });
        Some(best.unwrap_or_else(|| panic!("{}: no type holds {needed:?}", self.spec.name)).0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn blades_and_result_types_follow_the_table() {
        let specs = crate::algebras::all();
        let g3 = Resolved::new(&specs[0]);
        // e31 = e3 e1 = -e13.
        let e31 = g3.blades.iter().find(|b| b.name == "e31").unwrap();
        assert_eq!((e31.mask, e31.sign, e31.grade), (0b101, -1.0, 2));
        // Vector * Vector: the scalar and the three bivectors, a Rotor.
        let table = &g3.table(|a, b| a.geometric(b));
        let v = g3.type_index("Vector");
        let mut needed: Vec<usize> = g3.type_blades[v]
            .iter()
            .flat_map(|&i| g3.type_blades[v].iter().flat_map(move |&j| table[i][j].clone()))
            .map(|(k, _)| k)
            .collect();
        needed.sort_unstable();
        needed.dedup();
        assert_eq!(g3.smallest_type(&needed), Some(g3.type_index("Rotor")));
        // A bivector alone is a Bivector, not the Rotor that also holds it; a scalar is `T`.
        assert_eq!(g3.smallest_type(&[4]), Some(g3.type_index("Bivector")));
        assert_eq!(g3.smallest_type(&[0]), None);
        assert_eq!(g3.smallest_type(&[1, 7]), Some(g3.type_index("Multivector")));
    }
}
