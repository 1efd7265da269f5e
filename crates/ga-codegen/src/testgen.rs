//! The test that checks every generated kernel against the reference algebra, written from the
//! same table (so a new type or algebra is tested without another line written by hand).

use std::fmt::Write as _;

use crate::emit::Impl;
use crate::model::{Dual, Inner, Regressive, Resolved, Storage};

/// Where the test goes, relative to the workspace root.
pub const PATH: &str = "crates/ga/tests/generated_kernels.rs";

/// The helpers every algebra's checks share.
const PRELUDE: &str = r#"//! Every generated kernel of every algebra in the table of
//! `crates/ga-codegen` against the reference algebra (`ga-reference`): random f64 inputs from
//! fixed seeds, every coefficient within a relative error of 1e-12 of the product of the
//! inputs' norms, and every blade the result type drops zero in the reference. Then algebra
//! laws as properties: associativity of `*`, the reverse of a product, and `a ^ b` as the
//! grade `r + s` part of `a * b`.

use ga_reference::{Algebra, Multivector as Reference, from_basis, grade_of, to_basis};
use rand::{Rng, SeedableRng};
use rand_pcg::Pcg64;

const CASES: usize = 64;
const TOLERANCE: f64 = 1e-12;

/// An algebra as the checks see it: the reference algebra and each documented basis blade as
/// `(canonical bitmask, sign)`.
struct Basis {
    algebra: Algebra,
    blades: &'static [(usize, f64)],
}

/// A type as the blades (indices into the documented basis) it holds.
trait Blades: Copy {
    const BLADES: &'static [usize];
    fn coefficients(self) -> Vec<f64>;
    fn from_coefficients(c: &[f64]) -> Self;
}

impl Blades for f64 {
    const BLADES: &'static [usize] = &[0];
    fn coefficients(self) -> Vec<f64> {
        vec![self]
    }
    fn from_coefficients(c: &[f64]) -> Self {
        c[0]
    }
}

/// A seed per check (FNV-1a of its name), so adding a check changes no other check's inputs.
fn seed(name: &str) -> u64 {
    name.bytes()
        .fold(0xcbf2_9ce4_8422_2325, |h, b| (h ^ u64::from(b)).wrapping_mul(0x100_0000_01b3))
}

fn random<A: Blades>(rng: &mut Pcg64) -> A {
    let c: Vec<f64> = A::BLADES.iter().map(|_| rng.random_range(-1.0..1.0)).collect();
    A::from_coefficients(&c)
}

fn to_reference<A: Blades>(basis: &Basis, x: A) -> Reference {
    let blades: Vec<(usize, f64)> = A::BLADES.iter().map(|&k| basis.blades[k]).collect();
    from_basis(basis.algebra, &blades, &x.coefficients())
}

fn norm<A: Blades>(x: A) -> f64 {
    x.coefficients().iter().map(|c| c * c).sum::<f64>().sqrt()
}

/// `got` against the reference value on every blade of the algebra.
#[track_caller]
fn compare<C: Blades>(
    basis: &Basis,
    name: &str,
    case: usize,
    got: C,
    want: &Reference,
    scale: f64,
) {
    let got_c = got.coefficients();
    for (k, w) in to_basis(want, basis.blades).into_iter().enumerate() {
        let g = C::BLADES.iter().position(|&b| b == k).map_or(0.0, |p| got_c[p]);
        assert!(
            (g - w).abs() <= TOLERANCE * scale.max(1.0),
            "{name}, case {case}: blade {k}: got {g}, want {w}"
        );
    }
}

fn binary<A: Blades, B: Blades, C: Blades>(
    basis: &Basis,
    name: &str,
    op: impl Fn(A, B) -> C,
    reference: impl Fn(&Reference, &Reference) -> Reference,
) {
    let mut rng = Pcg64::seed_from_u64(seed(name));
    for case in 0..CASES {
        let (a, b) = (random::<A>(&mut rng), random::<B>(&mut rng));
        let want = reference(&to_reference(basis, a), &to_reference(basis, b));
        compare(basis, name, case, op(a, b), &want, norm(a) * norm(b));
    }
}

/// `v x ṽ` against the reference, keeping the grades of `X`.
fn sandwich<V: Blades, X: Blades, C: Blades>(basis: &Basis, name: &str, op: impl Fn(V, X) -> C) {
    let mut rng = Pcg64::seed_from_u64(seed(name));
    let grades: Vec<usize> = X::BLADES.iter().map(|&k| grade_of(basis.blades[k].0)).collect();
    for case in 0..CASES {
        let (v, x) = (random::<V>(&mut rng), random::<X>(&mut rng));
        let rv = to_reference(basis, v);
        let full = rv.geometric(&to_reference(basis, x)).geometric(&rv.reverse());
        let want = full.map(|blade, c| if grades.contains(&grade_of(blade)) { c } else { 0.0 });
        compare(basis, name, case, op(v, x), &want, norm(v) * norm(v) * norm(x));
    }
}

/// `a ^ b` is the grade `grade` part of `a * b`, within rounding (both generated).
fn outer_is_graded_geometric<A: Blades, B: Blades, C: Blades, D: Blades>(
    basis: &Basis,
    name: &str,
    grade: usize,
    outer: impl Fn(A, B) -> C,
    geometric: impl Fn(A, B) -> D,
) {
    let mut rng = Pcg64::seed_from_u64(seed(name));
    for case in 0..CASES {
        let (a, b) = (random::<A>(&mut rng), random::<B>(&mut rng));
        let g = geometric(a, b);
        let kept: Vec<(usize, f64)> = D::BLADES
            .iter()
            .zip(g.coefficients())
            .filter(|&(&k, _)| grade_of(basis.blades[k].0) == grade)
            .map(|(&k, c)| (basis.blades[k].0, basis.blades[k].1 * c))
            .collect();
        let mut want = basis.algebra.zero();
        for (blade, c) in kept {
            want = &want + &basis.algebra.blade(blade, c);
        }
        compare(basis, name, case, outer(a, b), &want, norm(a) * norm(b));
    }
}

/// Associativity of `*` and `(a b)~ = b~ a~`, on random multivectors.
fn laws<M: Blades>(basis: &Basis, name: &str, mul: impl Fn(M, M) -> M, reverse: impl Fn(M) -> M) {
    let mut rng = Pcg64::seed_from_u64(seed(name));
    for case in 0..CASES {
        let (a, b, c) = (random::<M>(&mut rng), random::<M>(&mut rng), random::<M>(&mut rng));
        let left = to_reference(basis, mul(mul(a, b), c));
        compare(basis, name, case, mul(a, mul(b, c)), &left, norm(a) * norm(b) * norm(c));
        let reversed = to_reference(basis, reverse(mul(a, b)));
        compare(basis, name, case, mul(reverse(b), reverse(a)), &reversed, norm(a) * norm(b));
    }
}
"#;

/// The check of the unary operations, for algebras whose types are generated.
const UNARY: &str = r#"
fn unary<A: Blades, C: Blades>(
    basis: &Basis,
    name: &str,
    op: impl Fn(A) -> C,
    reference: impl Fn(&Reference) -> Reference,
) {
    let mut rng = Pcg64::seed_from_u64(seed(name));
    for case in 0..CASES {
        let a = random::<A>(&mut rng);
        compare(basis, name, case, op(a), &reference(&to_reference(basis, a)), norm(a));
    }
}
"#;

/// The reference expression for product `key` in `alg`'s conventions.
fn reference(alg: &Resolved<'_>, key: &str) -> &'static str {
    match key {
        "geometric" => "|a, b| a.geometric(b)",
        "outer" => "|a, b| a.outer(b)",
        "inner" => match alg.spec.inner {
            Inner::Hestenes => "|a, b| a.inner(b)",
            Inner::FatDot => "|a, b| a.fat_dot(b)",
            Inner::LeftContraction => "|a, b| a.left_contraction(b)",
        },
        "regressive" => match alg.spec.regressive {
            Regressive::ViaDual => "|a, b| a.dual().unwrap().outer(&b.dual().unwrap()).undual()",
            Regressive::Complement => "|a, b| a.regressive(b)",
        },
        "left_contraction" => "|a, b| a.left_contraction(b)",
        "right_contraction" => "|a, b| a.right_contraction(b)",
        "scalar_product" => "|a, b| a.algebra().scalar(a.scalar_product(b))",
        "commutator" => "|a, b| a.commutator(b)",
        _ => unreachable!("no product {key}"),
    }
}

/// The Rust expression applying product `key` to `a` and `b`.
fn apply(key: &str) -> String {
    match key {
        "geometric" => "|a, b| a * b".to_owned(),
        "outer" => "|a, b| a ^ b".to_owned(),
        "inner" => "|a, b| a | b".to_owned(),
        "regressive" => "|a, b| a & b".to_owned(),
        method => format!("|a, b| a.{method}(b)"),
    }
}

/// The whole test file (before rustfmt).
#[must_use]
pub fn oracle_test(algebras: &[Resolved<'_>], impls: &[Vec<Impl>]) -> String {
    let mut out = PRELUDE.to_owned();
    if algebras.iter().any(|a| a.spec.emit_types) {
        out.push_str(UNARY);
    }
    for (alg, impls) in algebras.iter().zip(impls) {
        assert_eq!(alg.blades[0].grade, 0, "{}: the scalar comes first", alg.spec.name);
        let name = alg.spec.name;
        let types: Vec<&str> = alg.spec.types.iter().map(|t| t.name).collect();
        let blades: Vec<String> =
            alg.blades.iter().map(|b| format!("({:#b}, {:.1})", b.mask, b.sign)).collect();
        let metric: Vec<String> =
            alg.spec.generators.iter().map(|g| format!("{:.1}", g.1)).collect();
        write!(
            out,
            "\nmod {name} {{\n    use super::*;\n    use ga::{name}::{{{}}};\n\n    \
             const BLADES: [(usize, f64); {}] = [{}];\n\n    \
             fn basis() -> Basis {{\n\
             Basis {{ algebra: Algebra::from_metric(&[{}]), blades: &BLADES }}\n    }}\n\n",
            types.join(", "),
            blades.len(),
            blades.join(", "),
            metric.join(", ")
        )
        .expect("w");
        for (t, spec) in alg.spec.types.iter().enumerate() {
            let idx: Vec<String> = alg.type_blades[t].iter().map(ToString::to_string).collect();
            let n = idx.len();
            let (get, make) = match spec.storage {
                Storage::Fields => {
                    let fields: Vec<&str> =
                        alg.type_blades[t].iter().map(|&k| alg.blades[k].field.as_str()).collect();
                    let get: Vec<String> = fields.iter().map(|f| format!("self.{f}")).collect();
                    let make: Vec<String> =
                        fields.iter().enumerate().map(|(i, f)| format!("{f}: c[{i}]")).collect();
                    (format!("vec![{}]", get.join(", ")), format!("Self {{ {} }}", make.join(", ")))
                }
                Storage::Array(_) => (
                    "self.to_array().to_vec()".to_owned(),
                    format!("Self::from_array(core::array::from_fn::<_, {n}, _>(|k| c[k]))"),
                ),
            };
            write!(
                out,
                "    impl Blades for {ty}<f64> {{\n\
                    const BLADES: &'static [usize] = &[{}];\n        \
                 fn coefficients(self) -> Vec<f64> {{\n            {get}\n        }}\n        \
                 fn from_coefficients(c: &[f64]) -> Self {{\n            {make}\n        }}\n\
                 }}\n\n",
                idx.join(", "),
                ty = spec.name
            )
            .expect("w");
        }
        let ty = |t: Option<usize>| t.map_or("f64".to_owned(), |t| format!("{}<f64>", types[t]));
        let mut by_product: Vec<(&str, Vec<&Impl>)> = Vec::new();
        for i in impls {
            match by_product.iter_mut().find(|(k, _)| *k == i.product) {
                Some((_, v)) => v.push(i),
                None => by_product.push((i.product, vec![i])),
            }
        }
        for (product, list) in &by_product {
            writeln!(
                out,
                "    #[test]\n    fn {product}_against_reference() {{\n        let basis = basis();"
            )
            .expect("w");
            for i in list {
                let label = format!("{name} {} {product} {}", types[i.left], types[i.right]);
                if *product == "sandwich" {
                    writeln!(
                        out,
                        "        sandwich::<{}, {}, {}>(&basis, \"{label}\", |v, x| \
                            v.sandwich(x));",
                        ty(Some(i.left)),
                        ty(Some(i.right)),
                        ty(i.result)
                    )
                    .expect("w");
                } else {
                    writeln!(
                        out,
                        "        binary::<{}, {}, _>(&basis, \"{label}\", {}, {});",
                        ty(Some(i.left)),
                        ty(Some(i.right)),
                        apply(product),
                        reference(alg, product)
                    )
                    .expect("w");
                }
            }
            out.push_str("    }\n\n");
        }
        // Laws.
        let mv = alg.type_index("Multivector");
        writeln!(
            out,
            "    #[test]\n    fn algebra_laws() {{\n        let basis = basis();\n        \
             laws::<{m}>(&basis, \"{name} laws\", |a, b| a * b, |a| a.reverse());",
            m = ty(Some(mv))
        )
        .expect("w");
        let homogeneous = |t: usize| {
            let g: Vec<usize> = alg.type_blades[t].iter().map(|&k| alg.blades[k].grade).collect();
            g.iter().all(|&x| x == g[0]).then_some(g[0])
        };
        for i in impls.iter().filter(|i| i.product == "outer") {
            let (Some(r), Some(s)) = (homogeneous(i.left), homogeneous(i.right)) else { continue };
            let has_geometric = impls
                .iter()
                .any(|g| g.product == "geometric" && g.left == i.left && g.right == i.right);
            if !has_geometric {
                continue;
            }
            writeln!(
                out,
                "        outer_is_graded_geometric::<{}, {}, _, _>(&basis, \"{name} {} ^ {}\", \
                    {}, |a, b| a ^ b, |a, b| a * b);",
                ty(Some(i.left)),
                ty(Some(i.right)),
                types[i.left],
                types[i.right],
                r + s
            )
            .expect("w");
        }
        out.push_str("    }\n");
        if alg.spec.emit_types {
            writeln!(
                out,
                "\n    #[test]\n    fn unary_against_reference() {{\n        let basis = basis();"
            )
            .expect("w");
            let (dual, undual) = match alg.spec.dual {
                Dual::InversePseudoscalar => ("|a| a.dual().unwrap()", "|a| a.undual()"),
                Dual::Complement => ("|a| a.right_complement()", "|a| a.left_complement()"),
            };
            for t in &types {
                for (method, reference) in [
                    ("reverse", "|a| a.reverse()"),
                    ("grade_involution", "|a| a.grade_involution()"),
                    ("conjugate", "|a| a.conjugate()"),
                    ("dual", dual),
                    ("undual", undual),
                    ("norm_squared", "|a| a.algebra().scalar(a.norm_squared())"),
                ] {
                    writeln!(
                        out,
                        "        unary::<{t}<f64>, _>(&basis, \"{name} {t}::{method}\", |a| \
                            a.{method}(), {reference});"
                    )
                    .expect("w");
                }
            }
            out.push_str("    }\n");
        }
        out.push_str("}\n");
    }
    out
}
