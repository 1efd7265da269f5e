//! The sign predicates against independent exact evaluations: `BigRational` (Sarrus' rule on
//! exact rationals), `i128` on small integers, and the `robust` crate's `orient3d`.

mod common;

use common::{det, perturbed_edge_sign, q3, sign, sub};
use exact::Sign;
use exact::predicates::{edge_sign, edge_sign_perturbed, is_degenerate, orient3d};
use intersect::Triangle;
use rand::{Rng, SeedableRng};
use rand_pcg::Pcg64;

fn exact_edge(o: [f64; 3], d: [f64; 3], p: [f64; 3], r: [f64; 3]) -> Sign {
    let o = q3(o);
    sign(&det(&sub(&q3(p), &o), &sub(&q3(r), &o), &q3(d)))
}

fn exact_orient(o: [f64; 3], a: [f64; 3], b: [f64; 3], c: [f64; 3]) -> Sign {
    let o = q3(o);
    sign(&det(&sub(&q3(a), &o), &sub(&q3(b), &o), &sub(&q3(c), &o)))
}

/// Checks all three predicates on one input against the exact references.
fn check(o: [f64; 3], d: [f64; 3], p: [f64; 3], r: [f64; 3]) {
    assert_eq!(edge_sign(o, d, p, r), Some(exact_edge(o, d, p, r)), "{o:?} {d:?} {p:?} {r:?}");
    assert_eq!(
        edge_sign_perturbed(o, d, p, r),
        Some(perturbed_edge_sign(o, d, p, r)),
        "perturbed {o:?} {d:?} {p:?} {r:?}"
    );
    assert_eq!(orient3d(o, d, p, r), Some(exact_orient(o, d, p, r)), "orient {o:?} {d:?} {p:?}");
}

/// A random coordinate of magnitude in `[2^-40, scale)` or zero, with either sign.
fn coordinate(rng: &mut Pcg64, scale: f64) -> f64 {
    match rng.random_range(0..10) {
        0 => 0.0,
        1 => {
            let tiny = rng.random_range(2f64.powi(-40)..1e-6);
            if rng.random_bool(0.5) { tiny } else { -tiny }
        }
        _ => rng.random_range(-scale..scale),
    }
}

fn point(rng: &mut Pcg64, scale: f64, offset: f64) -> [f64; 3] {
    core::array::from_fn(|_| offset + coordinate(rng, scale))
}

/// A dyadic coordinate `offset + m 2^-g`, `|m| < 2^12`: sums and differences of a few of them
/// stay exact in `f64`.
fn lattice(rng: &mut Pcg64, g: i32, offset: f64) -> [f64; 3] {
    core::array::from_fn(|_| offset + f64::from(rng.random_range(-4096..4096)) * 2f64.powi(-g))
}

#[test]
fn random_inputs_match_exact_rationals() {
    let mut rng = Pcg64::seed_from_u64(1);
    for offset in [0.0, 1e3, 1e4, -3.75e4] {
        for scale in [1.0, 10.0, 1e4] {
            for _ in 0..150 {
                let (o, d) = (point(&mut rng, scale, offset), point(&mut rng, scale, 0.0));
                check(o, d, point(&mut rng, scale, offset), point(&mut rng, scale, offset));
            }
        }
    }
}

/// Exactly-zero configurations (the ray through a point of the edge, through a vertex, or
/// parallel to the edge), then single-coordinate nudges by one ulp either way: the
/// hardest inputs for a filter, and the ones the tie rule is for.
#[test]
fn points_on_edges_and_one_ulp_nudges_match_exact_rationals() {
    let mut rng = Pcg64::seed_from_u64(2);
    let mut zeros = 0;
    for offset in [0.0, 1e3, 1e4, -1e4] {
        for g in [0, 10, 30] {
            for case in 0..40 {
                let (p, r) = (lattice(&mut rng, g, offset), lattice(&mut rng, g, offset));
                let k = f64::from(case % 9) / 8.0; // 0 and 1 are the vertices
                let target: [f64; 3] = core::array::from_fn(|i| p[i] + k * (r[i] - p[i]));
                let o = lattice(&mut rng, g, offset);
                let scale = 2f64.powi(rng.random_range(-3..4));
                let mut d: [f64; 3] = core::array::from_fn(|i| (target[i] - o[i]) * scale);
                if case % 10 == 9 {
                    d = core::array::from_fn(|i| r[i] - p[i]); // parallel to the edge
                }
                // The construction is exact only if these roundings were: check, don't assume.
                let exact_zero = exact_edge(o, d, p, r) == Sign::Zero;
                zeros += usize::from(exact_zero);
                check(o, d, p, r);
                // Eight of the 24 nudges, chosen at random (all of them would be slow).
                for _ in 0..8 {
                    let mut inputs = [o, d, p, r];
                    let which = rng.random_range(0..12);
                    let x = &mut inputs[which / 3][which % 3];
                    *x = if rng.random_bool(0.5) { f64::next_up(*x) } else { f64::next_down(*x) };
                    let [o, d, p, r] = inputs;
                    check(o, d, p, r);
                }
            }
        }
    }
    // Most constructions must really be exact zeros, or this test tests nothing special.
    assert!(zeros > 400, "only {zeros} exact zeros");
}

/// The tie rule's derivation, checked on the shapes it is for: an edge crossed exactly gets
/// opposite perturbed signs from its two directions, and only a parallel edge stays zero.
#[test]
fn perturbed_signs_are_antisymmetric_and_zero_only_when_parallel() {
    let mut rng = Pcg64::seed_from_u64(3);
    for _ in 0..2000 {
        let (p, r, o) =
            (lattice(&mut rng, 4, 0.0), lattice(&mut rng, 4, 0.0), lattice(&mut rng, 4, 0.0));
        let k = f64::from(rng.random_range(0..=4)) / 4.0;
        let d: [f64; 3] = core::array::from_fn(|i| p[i] + k * (r[i] - p[i]) - o[i]);
        let forward = edge_sign_perturbed(o, d, p, r).unwrap();
        let backward = edge_sign_perturbed(o, d, r, p).unwrap();
        let negated = match forward {
            Sign::Negative => Sign::Positive,
            Sign::Zero => Sign::Zero,
            Sign::Positive => Sign::Negative,
        };
        assert_eq!(backward, negated);
        let e = q3([r[0] - p[0], r[1] - p[1], r[2] - p[2]]);
        let parallel = common::cross(&e, &q3(d)).iter().all(num_traits::Zero::is_zero);
        assert_eq!(forward == Sign::Zero, parallel, "{o:?} {d:?} {p:?} {r:?}");
    }
}

#[test]
fn small_integers_match_i128() {
    let mut rng = Pcg64::seed_from_u64(4);
    let det = |p: [i128; 3], r: [i128; 3], s: [i128; 3]| {
        p[0] * (r[1] * s[2] - r[2] * s[1]) - p[1] * (r[0] * s[2] - r[2] * s[0])
            + p[2] * (r[0] * s[1] - r[1] * s[0])
    };
    let sign_of = |x: i128| match x.signum() {
        -1 => Sign::Negative,
        0 => Sign::Zero,
        _ => Sign::Positive,
    };
    for range in [3, 1 << 20] {
        for _ in 0..5000 {
            let v: [[i128; 3]; 4] = core::array::from_fn(|_| {
                core::array::from_fn(|_| rng.random_range(-range..=range))
            });
            let f = v.map(|p| p.map(|x| x as f64));
            let diff = |p: [i128; 3]| core::array::from_fn(|i| p[i] - v[0][i]);
            let e = det(diff(v[2]), diff(v[3]), v[1]);
            assert_eq!(edge_sign(f[0], f[1], f[2], f[3]), Some(sign_of(e)), "{v:?}");
            let n = det(diff(v[1]), diff(v[2]), diff(v[3]));
            assert_eq!(orient3d(f[0], f[1], f[2], f[3]), Some(sign_of(n)), "{v:?}");
        }
    }
}

#[test]
fn orient3d_matches_the_robust_crate() {
    let mut rng = Pcg64::seed_from_u64(5);
    let c = |p: [f64; 3]| robust::Coord3D { x: p[0], y: p[1], z: p[2] };
    for _ in 0..3000 {
        let (o, a, b) =
            (lattice(&mut rng, 20, 1e4), lattice(&mut rng, 20, 1e4), point(&mut rng, 1e4, 0.0));
        // A fourth point on the plane of the other three, then nudged by an ulp or not.
        let (s, t) = (rng.random_range(-2.0..2.0), rng.random_range(-2.0..2.0));
        let mut cc: [f64; 3] =
            core::array::from_fn(|i| o[i] + s * (a[i] - o[i]) + t * (b[i] - o[i]));
        if rng.random_bool(0.5) {
            let i = rng.random_range(0..3);
            cc[i] = f64::next_up(cc[i]);
        }
        // Shewchuk's orient3d(a, b, c, o) is det[a - o, b - o, c - o].
        let theirs = robust::orient3d(c(a), c(b), c(cc), c(o));
        let theirs = if theirs > 0.0 {
            Sign::Positive
        } else if theirs < 0.0 {
            Sign::Negative
        } else {
            Sign::Zero
        };
        assert_eq!(orient3d(o, a, b, cc), Some(theirs));
        assert_eq!(theirs, exact_orient(o, a, b, cc));
    }
}

#[test]
fn degeneracy_matches_exact_rationals() {
    let mut rng = Pcg64::seed_from_u64(6);
    let mut degenerate = 0;
    for offset in [0.0, 1e4] {
        for _ in 0..2000 {
            let a = lattice(&mut rng, 20, offset);
            let e = lattice(&mut rng, 8, 0.0);
            let (s, t) = (f64::from(rng.random_range(-8..8)), f64::from(rng.random_range(-8..8)));
            let mut b: [f64; 3] = core::array::from_fn(|i| a[i] + s * e[i]);
            let c: [f64; 3] = core::array::from_fn(|i| a[i] + t * e[i]);
            if rng.random_bool(0.5) {
                let i = rng.random_range(0..3);
                b[i] = if rng.random_bool(0.5) { b[i].next_up() } else { b[i].next_down() };
            }
            let tri = Triangle::new(a, b, c);
            let (a, b, c) = (q3(a), q3(b), q3(c));
            let n = common::cross(&sub(&b, &a), &sub(&c, &a));
            let exact = n.iter().all(num_traits::Zero::is_zero);
            degenerate += usize::from(exact);
            assert_eq!(is_degenerate(&tri), exact, "{tri:?}");
        }
    }
    assert!(degenerate > 1000, "only {degenerate} degenerate triangles");
}

#[test]
fn non_finite_inputs_give_none() {
    let good = [[0.5, 0.25, -1.0], [0.0, 0.0, 1.0], [0.0, 0.0, 0.0], [1.0, 0.0, 0.0]];
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        for which in 0..12 {
            let mut v = good;
            v[which / 3][which % 3] = bad;
            let [o, d, p, r] = v;
            assert_eq!(edge_sign(o, d, p, r), None, "{v:?}");
            assert_eq!(edge_sign_perturbed(o, d, p, r), None, "{v:?}");
            assert_eq!(orient3d(o, d, p, r), None, "{v:?}");
        }
    }
}
