//! The full geometric product of `Multivector` written lane by lane for AVX2 and FMA.
//!
//! Number the blades by bitmask, split into block bits and lane bits (3 lane bits for f32, 2
//! for f64: one 256-bit register holds a block). The product of blades is
//! `e_i e_j = f(i, j) e_(i XOR j)`, so output lane `l` of output block `B` collects, for each
//! `i`, `a_i b_j` with `j = (B XOR block(i), l XOR lane(i))`: a broadcast of `a_i` times block
//! `B XOR block(i)` of `b` with its lanes permuted by `l ↦ l XOR lane(i)`. The permuted block
//! for a given `(block of b, lane(i))` serves every output block, so each is formed once.
//!
//! The signs `f(i, j)` must then split into a per-lane pattern of the permuted block (one XOR,
//! shared) times one sign per output block (the choice of `fmadd` or `fnmadd`). They do when
//! the blades are ordered with the block generators first: for a blade product the sign is
//! `(-1)^(i^T U j)` with `U` the strictly triangular "moves past" relation plus the negative
//! squares on its diagonal, and with the block generators first, a lane generator of `j` moves
//! past lane generators of `i` only. A generator squaring to 0 is made a block bit, so its
//! zero products are whole skipped blocks. The generator checks the split on every term and
//! panics if it fails.
//!
//! The storage order is the documented basis with its orientations; the relabelling (a lane
//! gather and a sign per blade) is folded into the loads, the patterns and the output
//! gather. Every output coefficient is the sum of the same products as the term-by-term
//! expansion's, in another order.

use std::fmt::Write as _;

use ga_reference::blade_from_factors;

use crate::model::{Resolved, Storage};

/// A precision and its register width.
#[derive(Clone, Copy)]
enum Precision {
    F32,
    F64,
}

impl Precision {
    fn lane_bits(self) -> usize {
        match self {
            Self::F32 => 3,
            Self::F64 => 2,
        }
    }
    fn ty(self) -> &'static str {
        match self {
            Self::F32 => "f32",
            Self::F64 => "f64",
        }
    }
    fn sfx(self) -> &'static str {
        match self {
            Self::F32 => "ps",
            Self::F64 => "pd",
        }
    }
}

/// The split of an algebra's blades into blocks and lanes.
struct Layout {
    /// Lanes per block.
    width: usize,
    /// Blocks.
    blocks: usize,
    /// For internal index `block * width + lane`: the storage slot of the blade there.
    slot_at: Vec<usize>,
    /// For internal index `k`: `documented blade = rel[k] * internal blade`.
    rel: Vec<f64>,
    /// `f(i, j)` for internal indices, the product landing on `i XOR j`.
    sign: Vec<Vec<f64>>,
}

impl Layout {
    fn new(alg: &Resolved<'_>, p: Precision) -> Self {
        let gens = alg.spec.generators;
        let n = alg.blades.len();
        // The first lane-bit-many non-degenerate generators are the lane bits; the others,
        // every degenerate one among them, the block bits.
        let lane_gens: Vec<usize> =
            (0..gens.len()).filter(|&g| gens[g].1 != 0.0).take(p.lane_bits()).collect();
        assert_eq!(lane_gens.len(), p.lane_bits(), "{}: too few generators", alg.spec.name);
        let block_gens: Vec<usize> = (0..gens.len()).filter(|g| !lane_gens.contains(g)).collect();
        let width = 1 << p.lane_bits();
        let mask_of = |k: usize| {
            let (block, lane) = (k / width, k % width);
            let mut m = 0;
            for (t, &g) in lane_gens.iter().enumerate() {
                m |= ((lane >> t) & 1) << g;
            }
            for (t, &g) in block_gens.iter().enumerate() {
                m |= ((block >> t) & 1) << g;
            }
            m
        };
        // The internal blade: its block generators, then its lane generators, in order.
        let internal_sign = |k: usize| {
            let m = mask_of(k);
            let factors: Vec<usize> = block_gens
                .iter()
                .chain(&lane_gens)
                .copied()
                .filter(|g| m & (1 << g) != 0)
                .collect();
            blade_from_factors(&factors).1
        };
        let multivector = alg.type_index("Multivector");
        let type_blades = &alg.type_blades[multivector];
        let slot_of = |blade: usize| {
            let k = type_blades.iter().position(|&b| b == blade).expect("a full multivector");
            match alg.spec.types[multivector].storage {
                Storage::Fields => k,
                Storage::Array(slots) => slots[k],
            }
        };
        let blade_at: Vec<usize> = (0..n)
            .map(|k| alg.blades.iter().position(|b| b.mask == mask_of(k)).expect("every blade"))
            .collect();
        let slot_at = blade_at.iter().map(|&b| slot_of(b)).collect();
        let rel = (0..n).map(|k| alg.blades[blade_at[k]].sign * internal_sign(k)).collect();
        let sign = (0..n)
            .map(|i| {
                (0..n)
                    .map(|j| {
                        let (f, m) = alg.reference.blade_product(mask_of(i), mask_of(j));
                        assert_eq!(m, mask_of(i ^ j));
                        f * internal_sign(i) * internal_sign(j) * internal_sign(i ^ j)
                    })
                    .collect()
            })
            .collect();
        Self { width, blocks: n / width, slot_at, rel, sign }
    }
}

/// One permuted block of `b` and the products it enters.
struct Group {
    /// Block of `b`.
    jb: usize,
    /// The lane permutation `l ↦ l XOR x`.
    x: usize,
    /// The lane signs applied after the permutation (`true`: negate).
    mask: Vec<bool>,
    /// `(output block, storage slot of a_i, negate)` for each product it enters.
    terms: Vec<(usize, usize, bool)>,
}

fn groups(l: &Layout) -> Vec<Group> {
    let w = l.width;
    let mut out = Vec::new();
    for jb in 0..l.blocks {
        for x in 0..w {
            let mut pattern: Option<Vec<f64>> = None;
            let mut terms = Vec::new();
            for block in 0..l.blocks {
                let i = (block ^ jb) * w + x;
                // The sign of the term in each output lane, b's relabelling included.
                let g: Vec<f64> = (0..w)
                    .map(|lane| {
                        let j = jb * w + (lane ^ x);
                        l.sign[i][j] * l.rel[j]
                    })
                    .collect();
                if g.iter().all(|&v| v == 0.0) {
                    continue;
                }
                assert!(g.iter().all(|&v| v != 0.0), "a zero product inside a block");
                let p = pattern.get_or_insert_with(|| g.clone());
                let e = g[0] / p[0];
                assert!(g.iter().zip(p.iter()).all(|(a, b)| *a == e * b), "signs do not split");
                terms.push((block, l.slot_at[i], e * l.rel[i] < 0.0));
            }
            let Some(mut p) = pattern else { continue };
            if p.iter().all(|&v| v < 0.0) {
                p.iter_mut().for_each(|v| *v = -*v);
                terms.iter_mut().for_each(|t| t.2 = !t.2);
            }
            out.push(Group { jb, x, mask: p.iter().map(|&v| v < 0.0).collect(), terms });
        }
    }
    out
}

/// `_mm256_setr_ps(0.0, -0.0, ...)` for a sign mask.
fn sign_vector(p: Precision, negate: &[bool]) -> String {
    let lanes: Vec<&str> = negate.iter().map(|&n| if n { "-0.0" } else { "0.0" }).collect();
    format!("_mm256_setr_{}({})", p.sfx(), lanes.join(", "))
}

/// The immediate of a four-lane permutation taking lane `l` from lane `idx[l]`
/// (`_mm256_permute_ps` within each half, `_mm256_permute4x64_pd`).
fn imm4(idx: impl Iterator<Item = usize>) -> usize {
    idx.enumerate().map(|(l, s)| s << (2 * l)).sum()
}

/// `v` with lane `l` taken from lane `idx[l]`, as an expression.
fn permute(p: Precision, v: &str, idx: &[usize]) -> String {
    if idx.iter().enumerate().all(|(l, &s)| l == s) {
        return v.to_owned();
    }
    match p {
        Precision::F32 => {
            let list: Vec<String> = idx.iter().map(ToString::to_string).collect();
            format!("_mm256_permutevar8x32_ps({v}, _mm256_setr_epi32({}))", list.join(", "))
        }
        Precision::F64 => {
            format!("_mm256_permute4x64_pd::<{:#010b}>({v})", imm4(idx.iter().copied()))
        }
    }
}

/// The blocks `dest` of width `w` gathered from the blocks `src`: `from[d][l]` is the
/// `(source block, lane)` of lane `l` of destination `d`. Emits `let {dest}{d} = ...;`.
fn gather(p: Precision, s: &mut String, src: &str, dest: &str, from: &[Vec<(usize, usize)>]) {
    let w = from[0].len();
    for (d, lanes) in from.iter().enumerate() {
        let mut sources: Vec<usize> = lanes.iter().map(|x| x.0).collect();
        sources.sort_unstable();
        sources.dedup();
        let mut expr = String::new();
        for (n, &t) in sources.iter().enumerate() {
            let idx: Vec<usize> =
                (0..w).map(|l| if lanes[l].0 == t { lanes[l].1 } else { l }).collect();
            let part = permute(p, &format!("{src}{t}"), &idx);
            if n == 0 {
                expr = part;
            } else {
                let m: usize = (0..w).filter(|&l| lanes[l].0 == t).map(|l| 1 << l).sum();
                expr = format!("_mm256_blend_{}::<{m:#b}>({expr}, {part})", p.sfx());
            }
        }
        writeln!(s, "    let {dest}{d} = {expr};").expect("w");
    }
}

/// The lane permutation `l ↦ l XOR x` of block `v`, using the half-swapped `h` for f32.
fn xor_permute(p: Precision, v: &str, h: &str, x: usize) -> String {
    match p {
        Precision::F32 => {
            let base = if x >= 4 { h } else { v };
            let x = x & 3;
            if x == 0 {
                return base.to_owned();
            }
            format!("_mm256_permute_ps::<{:#010b}>({base})", imm4((0..4).map(|u| u ^ x)))
        }
        // Within pairs the cheaper in-lane permute; across pairs the general one.
        Precision::F64 if x == 1 => format!("_mm256_permute_pd::<0b0101>({v})"),
        Precision::F64 => permute(p, v, &(0..4).map(|u| u ^ x).collect::<Vec<_>>()),
    }
}

/// The AVX2 kernel of one precision.
fn kernel(alg: &Resolved<'_>, p: Precision) -> String {
    let l = Layout::new(alg, p);
    let (ty, sfx, w, n) = (p.ty(), p.sfx(), l.width, l.slot_at.len());
    let mut s = String::new();
    let groups = groups(&l);
    let terms: usize = groups.iter().map(|g| g.terms.len()).sum();
    writeln!(
        s,
        "/// `a b` for {ty} multivectors in storage order: {terms} fused multiply-adds of {w} \
         lanes, {} lane permutations.\n///\n/// Inlined into the caller, so that `a` and `b` \
         are read where they lie: behind a call, the\n/// caller's fresh scalar copies of them \
         stall the vector loads (store forwarding fails).\n/// No `#[target_feature]`: the \
         module is compiled only where the build enables AVX2 and FMA.\n#[inline(always)]\n\
         #[allow(clippy::too_many_lines)]\npub(crate) fn geometric_{ty}(a: &[{ty}; {n}], b: \
         &[{ty}; {n}]) -> [{ty}; {n}] {{\n    // SAFETY: the intrinsics need AVX2 and FMA, \
         which the build enables wherever this module\n    // is compiled; the stores write \
         the {w}-lane blocks of `out`, which has {n} lanes.\n    unsafe {{",
        groups.iter().filter(|g| g.x != 0).count()
    )
    .expect("w");
    // b's storage blocks, then its blocks in the internal order.
    for t in 0..l.blocks {
        let lanes: Vec<String> = (0..w).map(|u| format!("b[{}]", t * w + u)).collect();
        writeln!(s, "    let s{t} = _mm256_setr_{sfx}({});", lanes.join(", ")).expect("w");
    }
    let from: Vec<Vec<(usize, usize)>> = (0..l.blocks)
        .map(|d| (0..w).map(|u| (l.slot_at[d * w + u] / w, l.slot_at[d * w + u] % w)).collect())
        .collect();
    gather(p, &mut s, "s", "b", &from);
    if matches!(p, Precision::F32) {
        for jb in 0..l.blocks {
            writeln!(s, "    let h{jb} = _mm256_permute2f128_ps::<0x01>(b{jb}, b{jb});")
                .expect("w");
        }
    }
    let mut slots: Vec<usize> = groups.iter().flat_map(|g| g.terms.iter().map(|t| t.1)).collect();
    slots.sort_unstable();
    slots.dedup();
    for k in slots {
        writeln!(s, "    let a{k} = _mm256_set1_{sfx}(a[{k}]);").expect("w");
    }
    // Four accumulators per output block: measured against one chain per two blocks, two and
    // eight per block (results/README.md), four was best or level in each algebra and precision.
    let chains = 4;
    for b in 0..l.blocks {
        for r in 0..chains {
            writeln!(s, "    let mut c{b}_{r} = _mm256_setzero_{sfx}();").expect("w");
        }
    }
    let mut used = vec![0; l.blocks];
    for g in &groups {
        let (jb, x) = (g.jb, g.x);
        let mut v = xor_permute(p, &format!("b{jb}"), &format!("h{jb}"), x);
        if g.mask.iter().any(|&m| m) {
            v = format!("_mm256_xor_{sfx}({v}, {})", sign_vector(p, &g.mask));
        }
        writeln!(s, "    let v = {v};").expect("w");
        for &(block, slot, negate) in &g.terms {
            let r = used[block] % chains;
            used[block] += 1;
            let f = if negate { "fnmadd" } else { "fmadd" };
            writeln!(s, "    c{block}_{r} = _mm256_{f}_{sfx}(a{slot}, v, c{block}_{r});")
                .expect("w");
        }
    }
    for b in 0..l.blocks {
        let mut sum = format!("c{b}_0");
        for r in 1..chains {
            sum = format!("_mm256_add_{sfx}({sum}, c{b}_{r})");
        }
        writeln!(s, "    let c{b} = {sum};").expect("w");
    }
    // Back to storage order, with the relabelling signs.
    let mut place = vec![0; n];
    for (k, &slot) in l.slot_at.iter().enumerate() {
        place[slot] = k;
    }
    let to: Vec<Vec<(usize, usize)>> = (0..l.blocks)
        .map(|t| (0..w).map(|u| (place[t * w + u] / w, place[t * w + u] % w)).collect())
        .collect();
    gather(p, &mut s, "c", "o", &to);
    writeln!(s, "    let mut out = [0.0; {n}];").expect("w");
    for t in 0..l.blocks {
        let negate: Vec<bool> = (0..w).map(|u| l.rel[place[t * w + u]] < 0.0).collect();
        let v = if negate.iter().any(|&x| x) {
            format!("_mm256_xor_{sfx}(o{t}, {})", sign_vector(p, &negate))
        } else {
            format!("o{t}")
        };
        writeln!(s, "    _mm256_storeu_{sfx}(out.as_mut_ptr().add({}), {v});", t * w).expect("w");
    }
    s.push_str("    out\n    }\n}\n");
    s
}

/// `lanes.rs` of an algebra: both precisions' kernels.
#[must_use]
pub fn lanes_file(alg: &Resolved<'_>) -> String {
    let title = alg.spec.title;
    format!(
        "//! The geometric product of two `Multivector`s of {title} lane by lane, for x86-64 \
         with AVX2 and\n//! FMA (compiled only where the build enables both).\n//!\n//! The \
         blades are numbered by bitmask and split into blocks of one register; output block \
         `B`\n//! gains, for each blade `e_i` of `a`, `a_i` times block `B XOR block(i)` of `b` \
         with its lanes\n//! permuted by `l ↦ l XOR lane(i)` and signed. Each permuted block of \
         `b` is formed once, with one\n//! sign pattern, and serves every output block (how the \
         signs split that way, and the layout,\n//! are derived in \
         `crates/ga-codegen/src/lanes.rs`).\n\nuse core::arch::x86_64::*;\n\n{}\n{}",
        kernel(alg, Precision::F32),
        kernel(alg, Precision::F64)
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebras;

    /// In every algebra (G3 too) and precision the signs split, and each non-zero term of the
    /// Cayley table is one lane of one fused multiply-add: no lane is wasted on a zero product.
    #[test]
    fn every_non_zero_term_is_one_lane_of_one_fma() {
        for spec in algebras::all() {
            let alg = Resolved::new(&spec);
            let n = alg.blades.len();
            let masks: Vec<usize> = alg.blades.iter().map(|b| b.mask).collect();
            let pairs = (0..n).flat_map(|i| (0..n).map(move |j| (i, j)));
            let non_zero = pairs
                .filter(|&(i, j)| alg.reference.blade_product(masks[i], masks[j]).0 != 0.0)
                .count();
            for p in [Precision::F32, Precision::F64] {
                let layout = Layout::new(&alg, p);
                let fmas: usize = groups(&layout).iter().map(|g| g.terms.len()).sum();
                assert_eq!(fmas * layout.width, non_zero, "{}", spec.name);
            }
        }
    }
}
