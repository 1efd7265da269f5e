//! Rust source text for one algebra: the kernels, the types, and their docs.

use std::collections::BTreeMap;
use std::fmt::Write as _;

use crate::model::{Resolved, Storage, Table};
use crate::products::{PRODUCTS, Product, dual, evaluate};

/// A signed product of coefficients: `coef * text`.
struct Term {
    coef: i32,
    text: String,
}

/// `t1 + t2 - t3`: terms in the order given, except that a leading negative term gives way to
/// the first positive one (`b - a`, not `-a + b`), as the hand-written kernels had it. The
/// order is part of the arithmetic (f32 sums round differently in another order).
fn sum(mut terms: Vec<Term>) -> String {
    if terms.is_empty() {
        return "T::ZERO".to_owned();
    }
    if terms[0].coef < 0
        && let Some(p) = terms.iter().position(|t| t.coef > 0)
    {
        let t = terms.remove(p);
        terms.insert(0, t);
    }
    let mut out = String::new();
    for (n, t) in terms.iter().enumerate() {
        let m = t.coef.unsigned_abs() as usize;
        // Only `+`, `-` and `*`: a coefficient 2 is the term added to itself (exact).
        let body = if m == 1 {
            t.text.clone()
        } else {
            format!("({})", vec![t.text.as_str(); m].join(" + "))
        };
        match (n, t.coef < 0) {
            (0, true) => write!(out, "-{body}"),
            (0, false) => write!(out, "{body}"),
            (_, true) => write!(out, " - {body}"),
            (_, false) => write!(out, " + {body}"),
        }
        .expect("writing to a String");
    }
    out
}

/// Whether a grade-`g` blade changes sign under an involution.
type Negates = fn(usize) -> bool;

/// Whether the reverse negates grade `g`: `(-1)^(g(g-1)/2)`.
fn reverse_negates(g: usize) -> bool {
    !(g * g.saturating_sub(1) / 2).is_multiple_of(2)
}

/// A sandwich's collected triple sum: output blade to `(operand position, versor position,
/// versor position)` to coefficient (see `Resolved::sandwich_terms`).
type SandwichTerms = BTreeMap<usize, BTreeMap<(usize, usize, usize), i32>>;

/// The arithmetic operations a kernel body performs: its binary `*`, `+` and `-`.
fn operations(body: &str) -> usize {
    [" * ", " + ", " - "].iter().map(|op| body.matches(op).count()).sum()
}

/// Upper camel case to snake case: `Multivector` to `multivector`.
fn snake(name: &str) -> String {
    let mut out = String::new();
    for (i, c) in name.chars().enumerate() {
        if c.is_uppercase() && i > 0 {
            out.push('_');
        }
        out.push(c.to_ascii_lowercase());
    }
    out
}

impl Resolved<'_> {
    /// `var`'s coefficient of the `pos`-th blade of type `ty`.
    fn access(&self, var: &str, ty: usize, pos: usize) -> String {
        match self.spec.types[ty].storage {
            Storage::Fields => format!("{var}.{}", self.blades[self.type_blades[ty][pos]].field),
            Storage::Array(slots) => format!("{var}.c[{}]", slots[pos]),
        }
    }

    /// `Name<T>`, or `T` for the scalar.
    fn rust_type(&self, ty: Option<usize>) -> String {
        ty.map_or_else(|| "T".to_owned(), |t| format!("{}<T>", self.spec.types[t].name))
    }

    /// `Name`, or `scalar`, for docs.
    fn doc_type(&self, ty: Option<usize>) -> &str {
        ty.map_or("scalar", |t| self.spec.types[t].name)
    }

    /// A value of type `ty` from expressions per blade (blade index to expression); blades the
    /// map lacks are zero.
    fn construct(&self, ty: Option<usize>, exprs: &BTreeMap<usize, String>) -> String {
        let get = |k: usize| exprs.get(&k).cloned().unwrap_or_else(|| "T::ZERO".to_owned());
        let Some(t) = ty else {
            return get(0);
        };
        let spec = &self.spec.types[t];
        let blades = &self.type_blades[t];
        match spec.storage {
            Storage::Fields => {
                let fields: Vec<String> = blades
                    .iter()
                    .map(|&k| format!("{}: {}", self.blades[k].field, get(k)))
                    .collect();
                format!("{} {{ {} }}", spec.name, fields.join(", "))
            }
            Storage::Array(slots) => {
                let mut lanes = vec![String::new(); slots.len()];
                for (pos, &k) in blades.iter().enumerate() {
                    lanes[slots[pos]] = get(k);
                }
                format!("{} {{ c: [{}] }}", spec.name, lanes.join(", "))
            }
        }
    }

    /// The kernel body of `a op b` for types `ta`, `tb`, or `None` when it is identically
    /// zero: `(result type, expression)`.
    fn bilinear(&self, table: &Table, ta: usize, tb: usize) -> Option<(Option<usize>, String)> {
        let mut out: BTreeMap<usize, Vec<Term>> = BTreeMap::new();
        for (pa, &i) in self.type_blades[ta].iter().enumerate() {
            for (pb, &j) in self.type_blades[tb].iter().enumerate() {
                for &(k, coef) in &table[i][j] {
                    let text =
                        format!("{} * {}", self.access("a", ta, pa), self.access("b", tb, pb));
                    out.entry(k).or_default().push(Term { coef, text });
                }
            }
        }
        if out.is_empty() {
            return None;
        }
        let needed: Vec<usize> = out.keys().copied().collect();
        let ty = self.smallest_type(&needed);
        let exprs = out.into_iter().map(|(k, terms)| (k, sum(terms))).collect();
        Some((ty, self.construct(ty, &exprs)))
    }

    /// The geometric product's table `e_i e_j = c e_k` as `(k, c)` (`c` is 0 for null blades).
    fn geometric_table(&self) -> Vec<Vec<(usize, i32)>> {
        let t = self.table(|a, b| a.geometric(b));
        let n = self.blades.len();
        (0..n)
            .map(|i| {
                (0..n)
                    .map(|j| {
                        let k = self
                            .blades
                            .iter()
                            .position(|b| b.mask == self.blades[i].mask ^ self.blades[j].mask);
                        t[i][j].first().copied().unwrap_or((k.expect("a blade"), 0))
                    })
                    .collect()
            })
            .collect()
    }

    /// The sandwich `v x ṽ` for versor type `tv` and operand type `tx`, keeping the grades of
    /// `tx`: `(result type, statements and expression)`, in whichever of the collected form
    /// and the two-step form ([`Self::sandwich_in_two_steps`]) takes fewer operations.
    fn sandwich(
        &self,
        geo: &[Vec<(usize, i32)>],
        tv: usize,
        tx: usize,
    ) -> Option<(Option<usize>, String)> {
        let out = self.sandwich_terms(geo, tv, tx);
        if out.is_empty() {
            return None;
        }
        let mut used: Vec<(usize, usize)> = Vec::new();
        let mut exprs = BTreeMap::new();
        for (&m, terms) in &out {
            let mut by_x: BTreeMap<usize, Vec<Term>> = BTreeMap::new();
            for (&(px, pi, pk), &coef) in terms {
                used.push((pi, pk));
                by_x.entry(px).or_default().push(Term { coef, text: self.pair_name(tv, pi, pk) });
            }
            let outer: Vec<Term> = by_x
                .into_iter()
                .map(|(px, quad)| {
                    let x = self.access("x", tx, px);
                    if quad.len() == 1 && quad[0].coef.abs() == 1 {
                        Term { coef: quad[0].coef, text: format!("{} * {x}", quad[0].text) }
                    } else {
                        Term { coef: 1, text: format!("({}) * {x}", sum(quad)) }
                    }
                })
                .collect();
            exprs.insert(m, sum(outer));
        }
        let mut body = self.pair_products(tv, used);
        let needed: Vec<usize> = out.keys().copied().collect();
        let ty = self.smallest_type(&needed);
        body.push_str(&self.construct(ty, &exprs));
        let steps = self.sandwich_in_two_steps(geo, tv, tx, ty, &needed);
        Some((ty, if operations(&steps) < operations(&body) { steps } else { body }))
    }

    /// The name of the product `a_i a_k` of the coefficients at positions `pi` and `pk` of
    /// versor type `tv`, as the collected sandwich and the sandwich map write it.
    fn pair_name(&self, tv: usize, pi: usize, pk: usize) -> String {
        let field = |p: usize| &self.blades[self.type_blades[tv][p]].field;
        format!("{}_{}", field(pi), field(pk))
    }

    /// The statements forming each product `a_i a_k` of `pairs` once (repeats dropped), in
    /// position order.
    fn pair_products(&self, tv: usize, mut pairs: Vec<(usize, usize)>) -> String {
        pairs.sort_unstable();
        pairs.dedup();
        let mut body = String::new();
        for (pi, pk) in pairs {
            let (ai, ak) = (self.access("a", tv, pi), self.access("a", tv, pk));
            writeln!(body, "let {} = {ai} * {ak};", self.pair_name(tv, pi, pk))
                .expect("writing to a String");
        }
        body
    }

    /// The triple sum of the sandwich `v x ṽ` with its like terms collected, keeping the grades
    /// of `x`: `out[m][(px, pi, pk)]` (`pi <= pk`) is the coefficient of `a_i a_k x_j` on blade
    /// `m`; blades whose terms all cancel are left out.
    fn sandwich_terms(&self, geo: &[Vec<(usize, i32)>], tv: usize, tx: usize) -> SandwichTerms {
        let grades: Vec<usize> =
            self.type_blades[tx].iter().map(|&k| self.blades[k].grade).collect();
        let reverse_sign = |k: usize| if reverse_negates(self.blades[k].grade) { -1 } else { 1 };
        let mut out = SandwichTerms::new();
        let vb = &self.type_blades[tv];
        for (pi, &i) in vb.iter().enumerate() {
            for (px, &j) in self.type_blades[tx].iter().enumerate() {
                let (l, c1) = geo[i][j];
                if c1 == 0 {
                    continue;
                }
                for (pk, &k) in vb.iter().enumerate() {
                    let (m, c2) = geo[l][k];
                    if c2 == 0 || !grades.contains(&self.blades[m].grade) {
                        continue;
                    }
                    let key = (px, pi.min(pk), pi.max(pk));
                    *out.entry(m).or_default().entry(key).or_default() += c1 * c2 * reverse_sign(k);
                }
            }
        }
        for terms in out.values_mut() {
            terms.retain(|_, c| *c != 0);
        }
        out.retain(|_, terms| !terms.is_empty());
        out
    }

    /// The method `{operand}_map` of versor type `tv`: the sandwich on type `tx` as the matrix
    /// `m` with `(v x ṽ)_i = Σ_j m[i][j] x_j`, rows and columns in `tx`'s blade order, each
    /// entry the collected quadratic form of the triple sum.
    fn sandwich_map(&self, geo: &[Vec<(usize, i32)>], tv: usize, tx: usize) -> String {
        let out = self.sandwich_terms(geo, tv, tx);
        let xb = &self.type_blades[tx];
        assert!(
            out.keys().all(|m| xb.contains(m)),
            "a sandwich map needs an operand type that holds its image"
        );
        let mut pairs: Vec<(usize, usize)> = Vec::new();
        let mut rows = Vec::new();
        for m in xb {
            let mut entries: Vec<Vec<Term>> = (0..xb.len()).map(|_| Vec::new()).collect();
            for (&(px, pi, pk), &coef) in out.get(m).into_iter().flatten() {
                pairs.push((pi, pk));
                entries[px].push(Term { coef, text: self.pair_name(tv, pi, pk) });
            }
            let entries: Vec<String> = entries.into_iter().map(sum).collect();
            rows.push(format!("[{}]", entries.join(", ")));
        }
        let (n, v, x) = (xb.len(), self.spec.types[tv].name, self.spec.types[tx].name);
        let body = self.pair_products(tv, pairs);
        format!(
            "impl<T: Scalar> {v}<T> {{\n    \
             /// The sandwich `x ↦ v x ṽ` on a [`{x}`] as a matrix:\n    \
             /// `(v x ṽ)ᵢ = Σⱼ m[i][j] xⱼ`, rows and columns in the blade order of\n    \
             /// [`{x}`]. The map is linear in `x`, so worked out once it applies the\n    \
             /// versor to many operands.\n    \
             #[must_use]\n    pub fn {name}_map(self) -> [[T; {n}]; {n}] {{\n        \
             let a = self;\n{body}[{rows}]\n    }}\n}}\n\n",
            name = snake(x),
            rows = rows.join(", "),
        )
    }

    /// The sandwich as two products, `w = v x` and then the blades `needed` of `w ṽ`: fewer
    /// operations than the collected form when a versor has many coefficients and is applied
    /// once (CGA's motor on a vector: 160 multiply-adds against about 560 operations), more when
    /// the collected form's quadratic terms are few (each `a_i a_k` is formed once, however many
    /// outputs use it). Blades of `w ṽ` whose terms cancel in the collected form are not
    /// written: `needed` holds only those that do not.
    fn sandwich_in_two_steps(
        &self,
        geo: &[Vec<(usize, i32)>],
        tv: usize,
        tx: usize,
        ty: Option<usize>,
        needed: &[usize],
    ) -> String {
        let vb = &self.type_blades[tv];
        let mut w: BTreeMap<usize, Vec<Term>> = BTreeMap::new();
        for (pi, &i) in vb.iter().enumerate() {
            for (px, &j) in self.type_blades[tx].iter().enumerate() {
                let (l, c) = geo[i][j];
                if c != 0 {
                    let text =
                        format!("{} * {}", self.access("a", tv, pi), self.access("x", tx, px));
                    w.entry(l).or_default().push(Term { coef: c, text });
                }
            }
        }
        let mut out: BTreeMap<usize, Vec<Term>> = BTreeMap::new();
        let mut used = Vec::new();
        for &l in w.keys() {
            for (pk, &k) in vb.iter().enumerate() {
                let (m, c) = geo[l][k];
                if c != 0 && needed.contains(&m) {
                    let sign = if reverse_negates(self.blades[k].grade) { -c } else { c };
                    let text = format!("w_{} * {}", self.blades[l].field, self.access("a", tv, pk));
                    out.entry(m).or_default().push(Term { coef: sign, text });
                    if !used.contains(&l) {
                        used.push(l);
                    }
                }
            }
        }
        let mut body = String::new();
        for (l, terms) in w {
            if used.contains(&l) {
                let line = format!("let w_{} = {};", self.blades[l].field, sum(terms));
                writeln!(body, "{line}").expect("writing to a String");
            }
        }
        let exprs = out.into_iter().map(|(m, terms)| (m, sum(terms))).collect();
        body.push_str(&self.construct(ty, &exprs));
        body
    }

    fn is_hand_written(&self, p: &Product, ta: usize, tb: usize) -> bool {
        let (a, b) = (self.spec.types[ta].name, self.spec.types[tb].name);
        self.spec.hand_written.iter().any(|&(k, x, y)| k == p.key && x == a && y == b)
    }

    /// The file of product kernels for every product written to `file`, and the pairs that got
    /// an impl: `(product key, left, right, result)`.
    fn product_file(&self, file: &str, impls: &mut Vec<Impl>) -> String {
        let mut code = String::new();
        let n = self.spec.types.len();
        let mut traits: Vec<&str> = Vec::new();
        for p in PRODUCTS.iter().filter(|p| p.file == file) {
            let table = self.table(|a, b| evaluate(self.spec, p.key, a, b));
            for ta in 0..n {
                for tb in 0..n {
                    let Some((ty, expr)) = self.bilinear(&table, ta, tb) else { continue };
                    let (a, b, out) =
                        (self.rust_type(Some(ta)), self.rust_type(Some(tb)), self.rust_type(ty));
                    let doc = format!(
                        "{} `{} {} {} -> {}`.",
                        p.doc,
                        self.spec.types[ta].name,
                        p.symbol,
                        self.spec.types[tb].name,
                        self.doc_type(ty)
                    );
                    if self.is_hand_written(p, ta, tb) {
                        let name = format!(
                            "{}_{}_{}",
                            p.key,
                            snake(self.spec.types[ta].name),
                            snake(self.spec.types[tb].name)
                        );
                        write!(
                            code,
                            "/// {doc} The expansion the hand-written kernel is checked against.\n\
                             #[cfg_attr(not(test), allow(dead_code))]\n#[inline]\n\
                             pub(crate) fn {name}<T: Scalar>(a: {a}, b: {b}) -> {out} {{\n\
                             {expr}\n}}\n\n"
                        )
                        .expect("writing to a String");
                        impls.push(Impl { product: p.key, left: ta, right: tb, result: ty });
                        continue;
                    }
                    if !traits.contains(&p.trait_name) {
                        traits.push(p.trait_name);
                    }
                    write!(
                        code,
                        "/// {doc}\nimpl<T: Coefficient> {tr}<{b}> for {a} {{\n\
                            type Output = {out};\n    \
                         #[inline]\n    fn {m}(self, b: {b}) -> {out} {{\n\
                         let a = self;\n        {expr}\n    }}\n}}\n\n",
                        tr = p.trait_name,
                        m = p.method
                    )
                    .expect("writing to a String");
                    impls.push(Impl { product: p.key, left: ta, right: tb, result: ty });
                }
            }
        }
        let mut header = String::new();
        let ops: Vec<&str> = PRODUCTS
            .iter()
            .filter(|p| p.operator && traits.contains(&p.trait_name))
            .map(|p| p.trait_name)
            .collect();
        let methods: Vec<&str> = PRODUCTS
            .iter()
            .filter(|p| !p.operator && traits.contains(&p.trait_name))
            .map(|p| p.trait_name)
            .collect();
        if !ops.is_empty() {
            writeln!(header, "use core::ops::{{{}}};\n", ops.join(", ")).expect("writing");
        }
        if !methods.is_empty() {
            writeln!(header, "use crate::products::{{{}}};", methods.join(", ")).expect("writing");
        }
        header.push_str(&self.use_types(&code));
        header + &code
    }

    /// `use crate::Scalar;` and the algebra's types that `code` names.
    fn use_types(&self, code: &str) -> String {
        let names: Vec<&str> = self
            .spec
            .types
            .iter()
            .map(|t| t.name)
            .filter(|n| code.contains(&format!("{n}<")) || code.contains(&format!("{n} {{")))
            .collect();
        let bounds: Vec<&str> =
            [("crate::Coefficient", "T: Coefficient"), ("crate::Scalar", "T: Scalar")]
                .into_iter()
                .filter(|(_, bound)| code.contains(bound))
                .map(|(path, _)| path)
                .collect();
        let uses: String = bounds.iter().map(|path| format!("use {path};\n")).collect();
        format!("{uses}use {}::{{{}}};\n\n", self.spec.module, names.join(", "))
    }

    /// The sandwich kernels and the inherent methods forwarding to every method trait.
    fn sandwich_file(&self, impls: &mut Vec<Impl>) -> String {
        let geo = self.geometric_table();
        let mut code = String::new();
        for &v in self.spec.versors {
            for &x in self.spec.sandwiched {
                let (tv, tx) = (self.type_index(v), self.type_index(x));
                let Some((ty, body)) = self.sandwich(&geo, tv, tx) else { continue };
                let (vt, xt, out) =
                    (self.rust_type(Some(tv)), self.rust_type(Some(tx)), self.rust_type(ty));
                write!(
                    code,
                    "/// Sandwich `v x ṽ` of a {v} `v` and a {x} `x` -> {o}.\n\
                        impl<T: Scalar> Sandwich<{xt}> for {vt} {{\n    \
                     type Output = {out};\n    #[inline]\n\
                     fn sandwich(self, x: {xt}) -> {out} {{\n        let a = self;\n\
                     {body}\n    }}\n}}\n\n",
                    o = self.doc_type(ty)
                )
                .expect("writing to a String");
                impls.push(Impl { product: "sandwich", left: tv, right: tx, result: ty });
            }
        }
        for &(v, x) in self.spec.maps {
            code.push_str(&self.sandwich_map(&geo, self.type_index(v), self.type_index(x)));
        }
        format!("use crate::products::Sandwich;\n{}{code}", self.use_types(&code))
    }

    /// Inherent methods `a.left_contraction(b)` etc. for every type that has the trait.
    fn inherent_file(&self, impls: &[Impl]) -> String {
        let methods: [(&str, &str, &str); 5] = [
            ("LeftContraction", "left_contraction", "The left contraction `self ⌋ b`."),
            ("RightContraction", "right_contraction", "The right contraction `self ⌊ b`."),
            ("ScalarProduct", "scalar_product", "The scalar product `⟨self b⟩₀`."),
            ("Commutator", "commutator", "The commutator product `(self b - b self) / 2`."),
            ("Sandwich", "sandwich", "The sandwich `self b self̃` (the grades of `b` kept)."),
        ];
        let mut code = String::new();
        let mut used = Vec::new();
        for (t, spec) in self.spec.types.iter().enumerate() {
            let mut body = String::new();
            for (tr, method, doc) in methods {
                if !impls.iter().any(|i| i.left == t && i.product == method) {
                    continue;
                }
                if !used.contains(&tr) {
                    used.push(tr);
                }
                write!(
                    body,
                    "/// {doc}\n///\n\
                        /// Defined for the right-hand types that [`{tr}`] is implemented for, \
                        with the \
                     smallest result type; this inherent form needs no import of the trait.\n\
                     #[must_use]\n#[inline]\n\
                     pub fn {method}<B>(self, b: B) -> <Self as {tr}<B>>::Output where Self: \
                     {tr}<B> {{\n    {tr}::{method}(self, b)\n}}\n\n"
                )
                .expect("writing to a String");
            }
            if !body.is_empty() {
                write!(code, "impl<T: Scalar> {}<T> {{\n{body}}}\n\n", spec.name).expect("writing");
            }
        }
        format!("use crate::products::{{{}}};\n{}{code}", used.join(", "), self.use_types(&code))
    }

    /// The Cayley table of the geometric product, in markdown.
    fn cayley(&self) -> String {
        let geo = self.geometric_table();
        let names: Vec<&str> = self.blades.iter().map(|b| b.name.as_str()).collect();
        let mut out =
            format!("| · | {} |\n|---|{}\n", names.join(" | "), "---|".repeat(names.len()));
        for (i, row) in geo.iter().enumerate() {
            let cells: Vec<String> = row
                .iter()
                .map(|&(k, c)| match c {
                    0 => "0".to_owned(),
                    1 => names[k].to_owned(),
                    -1 => format!("-{}", names[k]),
                    _ => unreachable!("basis blades multiply to ±1 or 0"),
                })
                .collect();
            writeln!(out, "| **{}** | {} |", names[i], cells.join(" | ")).expect("writing");
        }
        out
    }

    /// `+`, `-`, negation, scaling by `T` (both sides for f32 and f64), division by `T`, and
    /// their assigning forms, component by component.
    fn linear_ops(&self, t: usize) -> String {
        let name = self.spec.types[t].name;
        let each = |f: &dyn Fn(String, String) -> String| -> String {
            let exprs = self.type_blades[t]
                .iter()
                .enumerate()
                .map(|(pos, &k)| (k, f(self.access("self", t, pos), self.access("b", t, pos))))
                .collect();
            self.construct(Some(t), &exprs)
        };
        format!(
            "impl<T: Coefficient> Add for {name}<T> {{\n    type Output = Self;\n    #[inline]\n\
                fn add(self, b: Self) -> Self {{\n        {add}\n    }}\n}}\n\n\
             impl<T: Coefficient> Sub for {name}<T> {{\n    type Output = Self;\n    #[inline]\n\
             fn sub(self, b: Self) -> Self {{\n        {sub}\n    }}\n}}\n\n\
             impl<T: Coefficient> Neg for {name}<T> {{\n    type Output = Self;\n    #[inline]\n\
             fn neg(self) -> Self {{\n        {neg}\n    }}\n}}\n\n\
             impl<T: Coefficient> Mul<T> for {name}<T> {{\n    type Output = Self;\n    #[inline]\n\
             fn mul(self, k: T) -> Self {{\n        {mul}\n    }}\n}}\n\n\
             impl<T: Scalar> Div<T> for {name}<T> {{\n    type Output = Self;\n\
             /// Divides every coefficient by `k` (correctly rounded, like glam's).\n\
             #[inline]\n    fn div(self, k: T) -> Self {{\n        {div}\n    }}\n}}\n\n\
             impl<T: Scalar> AddAssign for {name}<T> {{\n    #[inline]\n\
             fn add_assign(&mut self, b: Self) {{\n        *self = *self + b;\n    }}\n}}\n\n\
             impl<T: Scalar> SubAssign for {name}<T> {{\n    #[inline]\n\
             fn sub_assign(&mut self, b: Self) {{\n        *self = *self - b;\n    }}\n}}\n\n\
             impl<T: Scalar> MulAssign<T> for {name}<T> {{\n    #[inline]\n\
             fn mul_assign(&mut self, k: T) {{\n        *self = *self * k;\n    }}\n}}\n\n\
             impl<T: Scalar> DivAssign<T> for {name}<T> {{\n    #[inline]\n\
             fn div_assign(&mut self, k: T) {{\n        *self = *self / k;\n    }}\n}}\n\n\
             impl Mul<{name}<f32>> for f32 {{\n    type Output = {name}<f32>;\n    #[inline]\n\
             fn mul(self, x: {name}<f32>) -> {name}<f32> {{\n        x * self\n    }}\n}}\n\n\
             impl Mul<{name}<f64>> for f64 {{\n    type Output = {name}<f64>;\n    #[inline]\n\
             fn mul(self, x: {name}<f64>) -> {name}<f64> {{\n        x * self\n    }}\n}}\n\n",
            add = each(&|a, b| format!("{a} + {b}")),
            sub = each(&|a, b| format!("{a} - {b}")),
            neg = each(&|a, _| format!("-{a}")),
            mul = each(&|a, _| format!("{a} * k")),
            div = each(&|a, _| format!("{a} / k")),
        )
    }

    /// The linear operations of every type (for algebras whose types are written by hand).
    fn linear_file(&self) -> String {
        let mut code = String::new();
        for t in 0..self.spec.types.len() {
            code.push_str(&self.linear_ops(t));
        }
        format!(
            "use core::ops::{{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Sub, \
                SubAssign}};\n\n{}{code}",
            self.use_types(&code)
        )
    }

    /// The types themselves: structs, constants, constructors, arrays, linear operations,
    /// involutions, duals, norms and widening conversions.
    fn types_file(&self) -> String {
        let mut code = String::new();
        let geo = self.geometric_table();
        for (t, spec) in self.spec.types.iter().enumerate() {
            let blades = &self.type_blades[t];
            let name = spec.name;
            let fields: Vec<&str> = blades.iter().map(|&k| self.blades[k].field.as_str()).collect();
            let n = fields.len();
            let blade_list: Vec<String> =
                blades.iter().map(|&k| format!("`{}`", self.blades[k].name)).collect();
            write!(
                code,
                "/// {}\n///\n/// Blades {}, laid out in this order like `[T; {n}]` (`repr(C)`).\n\
                    #[derive(Clone, Copy, Debug, Default, PartialEq)]\n#[repr(C)]\npub struct \
                    {name}<T> {{\n",
                spec.doc,
                blade_list.join(", ")
            )
            .expect("writing");
            for &k in blades {
                let b = &self.blades[k];
                let what = if b.grade == 0 {
                    "The scalar part.".to_owned()
                } else {
                    format!("Coefficient of `{}`.", b.name)
                };
                write!(code, "    /// {what}\n    pub {}: T,\n", b.field).expect("writing");
            }
            code.push_str("}\n\n");
            let zeros = vec!["T::ZERO"; n].join(", ");
            let params: Vec<String> = fields.iter().map(|f| format!("{f}: T")).collect();
            let selfs: Vec<String> = fields.iter().map(|f| format!("self.{f}")).collect();
            let idx: Vec<String> = (0..n).map(|i| format!("a[{i}]")).collect();
            write!(
                code,
                "impl<T: Scalar> {name}<T> {{\n    /// Zero.\n\
                pub const ZERO: Self = Self::new({zeros});\n"
            )
            .expect("w");
            for (pos, &k) in blades.iter().enumerate() {
                let b = &self.blades[k];
                let args: Vec<&str> =
                    (0..n).map(|p| if p == pos { "T::ONE" } else { "T::ZERO" }).collect();
                let (cname, what) = if b.grade == 0 {
                    ("ONE".to_owned(), "The scalar 1.".to_owned())
                } else {
                    (b.name.to_uppercase(), format!("The basis blade `{}`.", b.name))
                };
                write!(
                    code,
                    "    /// {what}\n    pub const {cname}: Self = Self::new({});\n",
                    args.join(", ")
                )
                .expect("w");
            }
            let allow = if n > 7 { "    #[allow(clippy::too_many_arguments)]\n" } else { "" };
            write!(
                code,
                "\n    /// From the coefficients of {list}.\n{allow}    #[must_use]\n\
                    #[inline]\n    pub const fn new({p}) -> Self {{\n        Self {{ {f} }}\n\
                    }}\n\n\
                 \x20   /// From `[{fl}]`.\n    #[must_use]\n    #[inline]\n\
                 pub const fn from_array(a: [T; {n}]) -> Self {{\n        Self::new({i})\n\
                 }}\n\n\
                 \x20   /// As `[{fl}]`.\n    #[must_use]\n    #[inline]\n\
                 pub const fn to_array(self) -> [T; {n}] {{\n        [{s}]\n    }}\n\n\
                 \x20   /// The coefficients in place, as `[{fl}]` (no copy: the struct is \
                 `repr(C)` in that\n    /// order).\n    #[must_use]\n    #[inline]\n\
                 pub const fn as_array(&self) -> &[T; {n}] {{\n        const {{ \
                 assert!(size_of::<Self>() == size_of::<[T; {n}]>()) }};\n        // SAFETY: \
                 `Self` is `repr(C)` with {n} fields of type `T`, so it has the layout of\n        \
                 // `[T; {n}]` (sizes checked above).\n        unsafe {{ \
                 &*core::ptr::from_ref(self).cast::<[T; {n}]>() }}\n    }}\n\n",
                list = blade_list.join(", "),
                p = params.join(", "),
                f = fields.join(", "),
                fl = fields.join(", "),
                i = idx.join(", "),
                s = selfs.join(", ")
            )
            .expect("writing");
            // The involutions: a sign per grade.
            let involutions: [(&str, &str, Negates); 3] = [
                ("reverse", "The reverse: grade `k` times `(-1)^(k(k-1)/2)`.", reverse_negates),
                ("grade_involution", "The grade involution: grade `k` times `(-1)^k`.", |g| {
                    !g.is_multiple_of(2)
                }),
                ("conjugate", "The Clifford conjugate: grade `k` times `(-1)^(k(k+1)/2)`.", |g| {
                    !(g * (g + 1) / 2).is_multiple_of(2)
                }),
            ];
            for (method, doc, negates) in involutions {
                let parts: Vec<String> = blades
                    .iter()
                    .map(|&k| {
                        let f = &self.blades[k].field;
                        if negates(self.blades[k].grade) {
                            format!("{f}: -self.{f}")
                        } else {
                            format!("{f}: self.{f}")
                        }
                    })
                    .collect();
                write!(
                    code,
                    "    /// {doc}\n    #[must_use]\n    #[inline]\n\
                    pub fn {method}(self) -> Self {{\n        Self {{ {} }}\n    }}\n\n",
                    parts.join(", ")
                )
                .expect("w");
            }
            for (method, undual) in [("dual", false), ("undual", true)] {
                let mut exprs = BTreeMap::new();
                for (pos, &k) in blades.iter().enumerate() {
                    for (m, c) in self.declared(&dual(self.spec, &self.basis_blade(k), undual)) {
                        let a = self.access("self", t, pos);
                        exprs.insert(m, if c < 0 { format!("-{a}") } else { a });
                    }
                }
                let needed: Vec<usize> = exprs.keys().copied().collect();
                let ty = self.smallest_type(&needed);
                let doc = if undual { "The undual, the inverse of `dual`" } else { "The dual" };
                write!(
                    code,
                    "    /// {doc} (see the module docs for its definition).\n    #[must_use]\n\
                        #[inline]\n    pub fn {method}(self) -> {} {{\n        {}\n    }}\n\n",
                    self.rust_type(ty),
                    self.construct(ty, &exprs)
                )
                .expect("w");
            }
            let squares: Vec<Term> = blades
                .iter()
                .enumerate()
                .filter_map(|(pos, &k)| {
                    let (_, c) = geo[k][k];
                    let rev = if reverse_negates(self.blades[k].grade) { -1 } else { 1 };
                    let a = self.access("self", t, pos);
                    (c != 0).then(|| Term { coef: c * rev, text: format!("{a} * {a}") })
                })
                .collect();
            write!(
                code,
                "    /// `⟨A Ã⟩₀`, the squared norm (blades that square to zero do not count).\n\
                    #[must_use]\n    #[inline]\n    pub fn norm_squared(self) -> T {{\n\
                    {}\n    }}\n\n\
                 \x20   /// `sqrt(|⟨A Ã⟩₀|)`.\n    #[must_use]\n    #[inline]\n\
                 pub fn norm(self) -> T {{\n        self.norm_squared().abs().sqrt()\n    }}\n\
                 }}\n\n",
                sum(squares)
            )
            .expect("w");
            code.push_str(&self.linear_ops(t));
        }
        // Widening conversions: every type into every type holding all its blades.
        for (s, small) in self.type_blades.iter().enumerate() {
            for (b, big) in self.type_blades.iter().enumerate() {
                if s == b || !small.iter().all(|k| big.contains(k)) {
                    continue;
                }
                let exprs = small
                    .iter()
                    .enumerate()
                    .map(|(pos, &k)| (k, self.access("x", s, pos)))
                    .collect();
                let (sn, bn) = (self.spec.types[s].name, self.spec.types[b].name);
                write!(
                    code,
                    "/// Widening: the blades `{bn}` has and `{sn}` lacks are zero.\n\
                        impl<T: Scalar> From<{sn}<T>> for {bn}<T> {{\n    #[inline]\n\
                        fn from(x: {sn}<T>) -> Self {{\n        {}\n    }}\n}}\n\n",
                    self.construct(Some(b), &exprs)
                )
                .expect("w");
            }
        }
        format!(
            "use core::ops::{{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Sub, \
                SubAssign}};\n\nuse crate::{{Coefficient, Scalar}};\n\n{code}"
        )
    }
}

/// For each product, the table of result types: left operand down, right operand across, `T`
/// for a scalar, `—` where the product is identically zero (no impl).
fn result_types(alg: &Resolved<'_>, impls: &[Impl]) -> String {
    let names: Vec<&str> = alg.spec.types.iter().map(|t| t.name).collect();
    let mut out = String::new();
    let mut products: Vec<(&str, String)> =
        PRODUCTS.iter().map(|p| (p.key, format!("{} `a {} b`", p.doc, p.symbol))).collect();
    products.push(("sandwich", "Sandwich `a.sandwich(b)` (`a b ã`)".to_owned()));
    for (key, title) in products {
        let rows: Vec<usize> = (0..names.len())
            .filter(|&a| key != "sandwich" || alg.spec.versors.contains(&names[a]))
            .collect();
        let cols: Vec<usize> = (0..names.len())
            .filter(|&b| key != "sandwich" || alg.spec.sandwiched.contains(&names[b]))
            .collect();
        let header: Vec<&str> = cols.iter().map(|&b| names[b]).collect();
        write!(
            out,
            "{title}:\n\n| `a` \\ `b` | {} |\n|---|{}\n",
            header.join(" | "),
            "---|".repeat(cols.len())
        )
        .expect("w");
        for &a in &rows {
            let cells: Vec<String> = cols
                .iter()
                .map(|&b| {
                    impls
                        .iter()
                        .find(|i| i.product == key && i.left == a && i.right == b)
                        .map_or("—".to_owned(), |i| {
                            i.result.map_or("`T`".to_owned(), |r| names[r].to_owned())
                        })
                })
                .collect();
            writeln!(out, "| {} | {} |", names[a], cells.join(" | ")).expect("w");
        }
        out.push('\n');
    }
    out
}

/// One product impl: generated, or hand-written beside its generated expansion.
pub struct Impl {
    /// The product's key (`"sandwich"` for sandwiches).
    pub product: &'static str,
    /// Left type index.
    pub left: usize,
    /// Right type index.
    pub right: usize,
    /// Result type index, `None` for the scalar.
    pub result: Option<usize>,
}

/// The generated files of one algebra, `(file name, contents before rustfmt)`, and its impls.
#[must_use]
pub fn algebra_files(alg: &Resolved<'_>) -> (Vec<(String, String)>, Vec<Impl>) {
    let mut impls = Vec::new();
    let mut files = Vec::new();
    let lint = "// The operator traits name the product (`Mul`, `BitXor`, ...) but each kernel \
        is a sum of\n\
                // products of coefficients, which is what clippy's heuristic flags.\n\
                #![allow(clippy::suspicious_arithmetic_impl)]\n\n";
    let title = alg.spec.title;
    for (file, what) in [
        ("geometric", "The geometric product `*`"),
        ("outer", "The outer product `^`"),
        ("inner", "The inner product `|`"),
        ("regressive", "The regressive product `&`"),
        ("contractions", "The left and right contractions and the scalar product"),
        ("commutator", "The commutator product"),
    ] {
        let body = alg.product_file(file, &mut impls);
        files.push((
            format!("{file}.rs"),
            format!(
                "//! {what} of {title}, for every pair of types where it is not \
                identically zero.\n\n{lint}{body}"
            ),
        ));
    }
    let body = alg.sandwich_file(&mut impls);
    files.push((
        "sandwich.rs".to_owned(),
        format!(
            "//! The sandwich `v x ṽ` of {title}: each \
        versor type applied to each type, keeping only the\n//! grades of `x` (the other \
        grades cancel when `v` is a versor).\n\n{body}"
        ),
    ));
    let body = alg.inherent_file(&impls);
    files.push((
        "methods.rs".to_owned(),
        format!(
            "//! The product methods of {title} as \
        inherent methods generic over the right-hand side.\n\n{body}"
        ),
    ));
    let mut modules = vec![
        "commutator",
        "contractions",
        "geometric",
        "inner",
        "methods",
        "outer",
        "regressive",
        "sandwich",
    ];
    if !alg.spec.emit_types {
        files.push((
            "linear.rs".to_owned(),
            format!(
                "//! The linear operations of {title}'s types, component by component.\n\n{}",
                alg.linear_file()
            ),
        ));
        modules.push("linear");
        modules.sort_unstable();
    }
    if alg.spec.emit_types {
        files.push((
            "types.rs".to_owned(),
            format!(
                "//! The types of {title}, with their \
            linear operations, involutions, duals and norms.\n\n{}",
                alg.types_file()
            ),
        ));
        modules.push("types");
        modules.sort_unstable();
    }
    let mut m = format!(
        "//! The generated part of {title}: types and products (see `crates/ga-codegen`).\n\n"
    );
    for module in modules {
        writeln!(m, "mod {module};").expect("w");
    }
    if alg.spec.emit_types {
        let names: Vec<&str> = alg.spec.types.iter().map(|t| t.name).collect();
        writeln!(m, "\npub use types::{{{}}};", names.join(", ")).expect("w");
    }
    if alg.spec.lanes {
        files.push(("lanes.rs".to_owned(), crate::lanes::lanes_file(alg)));
        m.push_str(
            "\n#[cfg(all(target_arch = \"x86_64\", target_feature = \"avx2\", \
             target_feature = \"fma\"))]\npub(crate) mod lanes;\n",
        );
    }
    files.push(("mod.rs".to_owned(), m));
    let hand: Vec<String> = alg
        .spec
        .hand_written
        .iter()
        .map(|&(p, a, b)| format!("{p}_{}_{}", snake(a), snake(b)))
        .collect();
    if !hand.is_empty() {
        // The hand-written kernels' checks reach the generated forms through the module.
        let last = files.len() - 1;
        let uses: Vec<String> = alg
            .spec
            .hand_written
            .iter()
            .zip(&hand)
            .map(|(&(p, _, _), h)| {
                let file = PRODUCTS.iter().find(|x| x.key == p).expect("a product").file;
                format!(
                    "#[cfg_attr(not(test), allow(unused_imports))]\npub(crate) use {file}::{h};"
                )
            })
            .collect();
        files[last].1.push_str(&format!("\n{}\n", uses.join("\n")));
    }
    files.push(("cayley.md".to_owned(), alg.cayley()));
    files.push(("products.md".to_owned(), result_types(alg, &impls)));
    (files, impls)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn term(coef: i32, text: &str) -> Term {
        Term { coef, text: text.to_owned() }
    }

    #[test]
    fn a_leading_negative_term_gives_way_to_the_first_positive_one() {
        let terms = vec![term(-1, "x"), term(-1, "y"), term(1, "z"), term(1, "w")];
        assert_eq!(sum(terms), "z - x - y + w");
        assert_eq!(sum(vec![term(-1, "x"), term(-1, "y")]), "-x - y");
        assert_eq!(sum(vec![term(2, "x"), term(-2, "y")]), "(x + x) - (y + y)");
        assert_eq!(sum(Vec::new()), "T::ZERO");
        assert_eq!(snake("Multivector"), "multivector");
        assert_eq!(snake("PointPair"), "point_pair");
    }
}
