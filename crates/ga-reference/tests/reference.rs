//! Tests of the oracle itself (the `ga-reference` crate), on Euclidean, projective, conformal and
//! spacetime signatures.
//!
//! A bilinear product is the Clifford product of a metric exactly when (1) it is associative,
//! (2) each generator squares to its metric entry, (3) distinct generators anticommute and (4) the
//! canonical blade `e_{i<j<...}` is the product of its generators in increasing order. These four
//! tests therefore pin the geometric product down completely; the other products are then checked
//! against their textbook formulas in terms of the geometric product.

use ga_reference::{
    Algebra, G3_REPORT_BASIS, Multivector, blade_name, from_g3_report, grade_of, to_g3_report,
};
use rand::{Rng, SeedableRng};
use rand_pcg::Pcg64;

const TOLERANCE: f64 = 1e-12;

/// Every algebra the oracle has to serve, with a name for messages.
fn algebras() -> Vec<(&'static str, Algebra)> {
    vec![
        ("G(3,0,0)", Algebra::new(3, 0, 0)),
        ("PGA R(3,0,1)", Algebra::new(3, 0, 1)),
        ("PGA e0 first", Algebra::from_metric(&[0.0, 1.0, 1.0, 1.0])),
        ("CGA R(4,1)", Algebra::new(4, 1, 0)),
        ("STA R(1,3)", Algebra::new(1, 3, 0)),
        ("R(2,2,2)", Algebra::new(2, 2, 2)),
    ]
}

fn random(algebra: Algebra, rng: &mut Pcg64) -> Multivector {
    let coefficients: Vec<f64> =
        (0..algebra.blade_count()).map(|_| rng.random_range(-1.0..1.0)).collect();
    algebra.from_coefficients(&coefficients)
}

fn random_grade(algebra: Algebra, k: usize, rng: &mut Pcg64) -> Multivector {
    random(algebra, rng).grade(k)
}

#[track_caller]
fn assert_close(what: &str, got: &Multivector, want: &Multivector) {
    let scale = want.max_abs().max(1.0);
    let error = (got - want).max_abs();
    assert!(error <= TOLERANCE * scale, "{what}: got {got:?}, want {want:?} (error {error:e})");
}

#[test]
fn generators_square_to_the_metric() {
    for (name, algebra) in algebras() {
        for (i, &square) in algebra.metric().iter().enumerate() {
            let e = algebra.generator(i);
            assert_close(&format!("{name} e{}^2", i + 1), &(&e * &e), &algebra.scalar(square));
        }
    }
}

#[test]
fn distinct_generators_anticommute() {
    for (name, algebra) in algebras() {
        for i in 0..algebra.dimension() {
            for j in 0..algebra.dimension() {
                if i == j {
                    continue;
                }
                let (ei, ej) = (algebra.generator(i), algebra.generator(j));
                assert_close(&format!("{name} e{i}e{j}"), &(&ei * &ej), &-&(&ej * &ei));
            }
        }
    }
}

#[test]
fn blades_are_products_of_their_generators_in_increasing_order() {
    for (name, algebra) in algebras() {
        for blade in 0..algebra.blade_count() {
            let product = (0..algebra.dimension())
                .filter(|i| blade & (1 << i) != 0)
                .fold(algebra.scalar(1.0), |acc, i| &acc * &algebra.generator(i));
            assert_close(
                &format!("{name} {}", blade_name(blade)),
                &product,
                &algebra.blade(blade, 1.0),
            );
        }
    }
}

#[test]
fn geometric_product_is_associative() {
    let mut rng = Pcg64::seed_from_u64(1);
    for (name, algebra) in algebras() {
        for _ in 0..50 {
            let (a, b, c) =
                (random(algebra, &mut rng), random(algebra, &mut rng), random(algebra, &mut rng));
            assert_close(name, &(&(&a * &b) * &c), &(&a * &(&b * &c)));
        }
    }
}

#[test]
fn signature_specific_squares() {
    // PGA: e0 (the fourth generator) is null, e1..e3 are unit.
    let pga = Algebra::new(3, 0, 1);
    assert_eq!(pga.metric(), &[1.0, 1.0, 1.0, 0.0]);
    let e0 = pga.generator(3);
    assert_eq!((&e0 * &e0).max_abs(), 0.0);
    // A PGA plane-point incidence needs e0 e1 to survive: e0 is null but not zero.
    let e01 = &e0 * &pga.generator(0);
    assert_eq!(e01.coefficient(0b1001), -1.0);
    // CGA: e+ squares to 1, e- to -1, so e+ + e- is a null vector and e+ e- squares to +1.
    let cga = Algebra::new(4, 1, 0);
    let (ep, em) = (cga.generator(3), cga.generator(4));
    assert_eq!((&ep * &ep).scalar_part(), 1.0);
    assert_eq!((&em * &em).scalar_part(), -1.0);
    let null = &ep + &em;
    assert_eq!((&null * &null).max_abs(), 0.0);
    let e_plus_minus = &ep * &em;
    assert_close("(e+e-)^2", &(&e_plus_minus * &e_plus_minus), &cga.scalar(1.0));
}

/// `a1 ^ ... ^ ak` for vectors is the antisymmetrised geometric product, in every metric.
#[test]
fn outer_product_of_vectors_is_the_antisymmetrised_geometric_product() {
    let mut rng = Pcg64::seed_from_u64(2);
    for (name, algebra) in algebras() {
        for _ in 0..20 {
            let [a, b, c] = [(); 3].map(|()| random_grade(algebra, 1, &mut rng));
            let ab = (&(&a * &b) - &(&b * &a)).scale(0.5);
            assert_close(name, &(&a ^ &b), &ab);
            let permutations = [
                (&a, &b, &c, 1.0),
                (&b, &c, &a, 1.0),
                (&c, &a, &b, 1.0),
                (&b, &a, &c, -1.0),
                (&a, &c, &b, -1.0),
                (&c, &b, &a, -1.0),
            ];
            let sum = permutations.iter().fold(algebra.zero(), |acc, (x, y, z, s)| {
                &acc + &(&(*x * *y) * *z).scale(*s / 6.0)
            });
            assert_close(name, &(&(&a ^ &b) ^ &c), &sum);
        }
    }
}

#[test]
fn outer_product_is_associative_and_grade_additive() {
    let mut rng = Pcg64::seed_from_u64(3);
    for (name, algebra) in algebras() {
        for _ in 0..30 {
            let (a, b, c) =
                (random(algebra, &mut rng), random(algebra, &mut rng), random(algebra, &mut rng));
            assert_close(name, &(&(&a ^ &b) ^ &c), &(&a ^ &(&b ^ &c)));
        }
        for r in 0..=algebra.dimension() {
            for s in 0..=algebra.dimension() {
                let a = random_grade(algebra, r, &mut rng);
                let b = random_grade(algebra, s, &mut rng);
                let wedge = &a ^ &b;
                assert_close(name, &wedge, &(&a * &b).grade(r + s));
            }
        }
    }
}

/// For a vector `a` and any `B`: `a _| B = (a B - B^ a) / 2` and `B |_ a = (B a - a B^) / 2`.
#[test]
fn contractions_by_a_vector_match_their_formulas() {
    let mut rng = Pcg64::seed_from_u64(4);
    for (name, algebra) in algebras() {
        for _ in 0..30 {
            let a = random_grade(algebra, 1, &mut rng);
            let b = random(algebra, &mut rng);
            let b_hat = b.grade_involution();
            let left = (&(&a * &b) - &(&b_hat * &a)).scale(0.5);
            assert_close(name, &a.left_contraction(&b), &left);
            let right = (&(&b * &a) - &(&a * &b_hat)).scale(0.5);
            assert_close(name, &b.right_contraction(&a), &right);
        }
    }
}

/// `(A ^ B) _| C = A _| (B _| C)` and its reverse, `C |_ (A ^ B) = (C |_ A) |_ B`.
#[test]
fn contractions_compose_with_the_outer_product() {
    let mut rng = Pcg64::seed_from_u64(5);
    for (name, algebra) in algebras() {
        for _ in 0..30 {
            let (a, b, c) =
                (random(algebra, &mut rng), random(algebra, &mut rng), random(algebra, &mut rng));
            assert_close(
                name,
                &(&a ^ &b).left_contraction(&c),
                &a.left_contraction(&b.left_contraction(&c)),
            );
            assert_close(
                name,
                &c.right_contraction(&(&a ^ &b)),
                &c.right_contraction(&a).right_contraction(&b),
            );
        }
    }
}

/// The report's inner product is the contraction from the lower grade into the higher one, and
/// vanishes when either side is a scalar.
#[test]
fn report_inner_product_is_the_contraction_of_the_lower_grade() {
    let mut rng = Pcg64::seed_from_u64(6);
    for (name, algebra) in algebras() {
        for r in 0..=algebra.dimension() {
            for s in 0..=algebra.dimension() {
                let a = random_grade(algebra, r, &mut rng);
                let b = random_grade(algebra, s, &mut rng);
                let want = if r == 0 || s == 0 {
                    algebra.zero()
                } else if r <= s {
                    a.left_contraction(&b)
                } else {
                    a.right_contraction(&b)
                };
                assert_close(&format!("{name} grades {r},{s}"), &a.inner(&b), &want);
            }
        }
        let (a, b) = (random_grade(algebra, 1, &mut rng), random_grade(algebra, 1, &mut rng));
        assert_close(name, &a.inner(&b), &(&(&a * &b) + &(&b * &a)).scale(0.5));
    }
}

/// The "fat dot" is the contraction of the lower grade onto the higher, scalars included: a
/// scalar on either side scales.
#[test]
fn fat_dot_is_the_contraction_of_the_lower_grade_scalars_included() {
    let mut rng = Pcg64::seed_from_u64(16);
    for (name, algebra) in algebras() {
        for r in 0..=algebra.dimension() {
            for s in 0..=algebra.dimension() {
                let a = random_grade(algebra, r, &mut rng);
                let b = random_grade(algebra, s, &mut rng);
                let want = if r <= s { a.left_contraction(&b) } else { a.right_contraction(&b) };
                assert_close(&format!("{name} grades {r},{s}"), &a.fat_dot(&b), &want);
            }
        }
    }
}

#[test]
fn scalar_product_norm_and_commutator() {
    let mut rng = Pcg64::seed_from_u64(7);
    for (name, algebra) in algebras() {
        let (a, b) = (random(algebra, &mut rng), random(algebra, &mut rng));
        let want = (&a * &b).scalar_part();
        assert!((a.scalar_product(&b) - want).abs() <= TOLERANCE, "{name}");
        let commutator = (&(&a * &b) - &(&b * &a)).scale(0.5);
        assert_close(name, &a.commutator(&b), &commutator);
    }
    // In a Euclidean algebra <A ~A>_0 is the sum of squared coefficients.
    let g3 = Algebra::new(3, 0, 0);
    let a = random(g3, &mut rng);
    let sum: f64 = a.coefficients().iter().map(|c| c * c).sum();
    assert!((a.norm_squared() - sum).abs() <= TOLERANCE);
    assert!((a.norm() - sum.sqrt()).abs() <= TOLERANCE);
}

#[test]
fn reverse_and_involution_are_anti_and_automorphisms() {
    let mut rng = Pcg64::seed_from_u64(8);
    for (name, algebra) in algebras() {
        for _ in 0..20 {
            let (a, b) = (random(algebra, &mut rng), random(algebra, &mut rng));
            let ab = &a * &b;
            assert_close(name, &ab.reverse(), &(&b.reverse() * &a.reverse()));
            assert_close(
                name,
                &ab.grade_involution(),
                &(&a.grade_involution() * &b.grade_involution()),
            );
            assert_close(name, &ab.conjugate(), &(&b.conjugate() * &a.conjugate()));
        }
        // On vectors: reverse is the identity, involution and conjugate negate.
        let v = random_grade(algebra, 1, &mut rng);
        assert_close(name, &v.reverse(), &v);
        assert_close(name, &v.grade_involution(), &-&v);
        assert_close(name, &v.conjugate(), &-&v);
    }
}

#[test]
fn grade_parts_sum_to_the_whole() {
    let mut rng = Pcg64::seed_from_u64(9);
    for (name, algebra) in algebras() {
        let a = random(algebra, &mut rng);
        let sum = (0..=algebra.dimension()).fold(algebra.zero(), |acc, k| &acc + &a.grade(k));
        assert_close(name, &sum, &a);
        for k in 0..=algebra.dimension() {
            let part = a.grade(k);
            for blade in 0..algebra.blade_count() {
                if grade_of(blade) != k {
                    assert_eq!(part.coefficient(blade), 0.0, "{name}");
                }
            }
        }
    }
}

#[test]
fn dual_and_undual() {
    let mut rng = Pcg64::seed_from_u64(10);
    let g3 = Algebra::new(3, 0, 0);
    // In G3, I^-1 = -e123, so e1* = e1 (-e123) = -e23 and e12* = e3.
    assert_close("e1*", &g3.generator(0).dual().unwrap(), &g3.blade(0b110, -1.0));
    assert_close("e12*", &g3.blade(0b011, 1.0).dual().unwrap(), &g3.generator(2));
    for (name, algebra) in algebras() {
        let a = random(algebra, &mut rng);
        match a.dual() {
            Some(dual) => {
                assert_close(name, &dual.undual(), &a);
                assert_close(name, &dual, &(&a * &algebra.pseudoscalar().inverse().unwrap()));
            }
            None => assert!(algebra.metric().contains(&0.0), "{name}: dual missing"),
        }
    }
}

#[test]
fn complements_and_regressive_product() {
    let mut rng = Pcg64::seed_from_u64(11);
    for (name, algebra) in algebras() {
        let pseudoscalar = algebra.pseudoscalar();
        for blade in 0..algebra.blade_count() {
            let e = algebra.blade(blade, 1.0);
            assert_close(name, &(&e ^ &e.right_complement()), &pseudoscalar);
            assert_close(name, &(&e.left_complement() ^ &e), &pseudoscalar);
        }
        let (a, b, c) =
            (random(algebra, &mut rng), random(algebra, &mut rng), random(algebra, &mut rng));
        assert_close(name, &a.right_complement().left_complement(), &a);
        // The pseudoscalar is the unit of the regressive product, which is associative.
        assert_close(name, &pseudoscalar.regressive(&a), &a);
        assert_close(name, &a.regressive(&pseudoscalar), &a);
        assert_close(name, &a.regressive(&b).regressive(&c), &a.regressive(&b.regressive(&c)));
    }
    // G3: the planes e12 and e23 meet in the e2 axis.
    let g3 = Algebra::new(3, 0, 0);
    let meet = g3.blade(0b011, 1.0).regressive(&g3.blade(0b110, 1.0));
    assert_close("e12 v e23", &meet, &g3.generator(1));
}

#[test]
fn inverse_is_two_sided_or_absent() {
    let mut rng = Pcg64::seed_from_u64(12);
    for (name, algebra) in algebras() {
        let one = algebra.scalar(1.0);
        for _ in 0..20 {
            let a = random(algebra, &mut rng);
            let Some(inverse) = a.inverse() else {
                panic!("{name}: random multivector {a:?} has no inverse");
            };
            let scale = a.max_abs() * inverse.max_abs();
            let error =
                (&(&a * &inverse) - &one).max_abs().max((&(&inverse * &a) - &one).max_abs());
            assert!(error <= 1e-10 * scale, "{name}: error {error:e}");
        }
    }
    let g3 = Algebra::new(3, 0, 0);
    // 1 + e1 is a zero divisor: (1 + e1)(1 - e1) = 0.
    assert!((&g3.scalar(1.0) + &g3.generator(0)).inverse().is_none());
    assert!(g3.zero().inverse().is_none());
    let v = &g3.generator(0).scale(3.0) + &g3.generator(1).scale(4.0);
    assert_close("vector inverse", &v.inverse().unwrap(), &v.scale(1.0 / 25.0));
    let pga = Algebra::new(3, 0, 1);
    assert!(pga.generator(3).inverse().is_none(), "e0 is null");
    let cga = Algebra::new(4, 1, 0);
    assert!((&cga.generator(3) + &cga.generator(4)).inverse().is_none(), "e+ + e- is null");
}

#[test]
fn exponentials_match_closed_forms() {
    let g3 = Algebra::new(3, 0, 0);
    for theta in [0.0, 0.3, -1.2, 3.0, 10.0] {
        // e12^2 = -1: a rotation, cos + sin e12.
        let got = g3.blade(0b011, theta).exp();
        let mut want = g3.scalar(theta.cos());
        want = &want + &g3.blade(0b011, theta.sin());
        assert_close("exp(t e12)", &got, &want);
    }
    // PGA: e01 is null, so exp(t e01) = 1 + t e01 (a translator).
    let pga = Algebra::new(3, 0, 1);
    let got = pga.blade(0b1001, 2.5).exp();
    assert_close("exp(t e01)", &got, &(&pga.scalar(1.0) + &pga.blade(0b1001, 2.5)));
    // CGA: (e+ e-)^2 = 1, a boost: cosh + sinh e+-.
    let cga = Algebra::new(4, 1, 0);
    let t = 1.7_f64;
    let got = cga.blade(0b11000, t).exp();
    assert_close("exp(t e45)", &got, &(&cga.scalar(t.cosh()) + &cga.blade(0b11000, t.sinh())));
}

#[test]
fn report_basis_mapping() {
    let g3 = Algebra::new(3, 0, 0);
    let [e1, e2, e3] = [0, 1, 2].map(|i| g3.generator(i));
    // The report's blades, built as products of generators.
    let report_blades = [
        g3.scalar(1.0),
        e1.clone(),
        e2.clone(),
        e3.clone(),
        &e1 * &e2,
        &e2 * &e3,
        &e3 * &e1,
        &(&e1 * &e2) * &e3,
    ];
    for (k, blade) in report_blades.iter().enumerate() {
        let mut unit = [0.0; 8];
        unit[k] = 1.0;
        assert_close(&format!("report blade {k}"), &from_g3_report(unit), blade);
        assert_eq!(to_g3_report(blade), unit);
    }
    assert_eq!(G3_REPORT_BASIS[6], (0b101, -1.0));
    let mut rng = Pcg64::seed_from_u64(13);
    let values: [f64; 8] = std::array::from_fn(|_| rng.random_range(-1.0..1.0));
    assert_eq!(to_g3_report(&from_g3_report(values)), values);
}

#[test]
fn debug_prints_nonzero_terms() {
    let g3 = Algebra::new(3, 0, 0);
    let m = &(&g3.scalar(1.0) + &g3.generator(0).scale(-2.0)) + &g3.blade(0b101, 0.5);
    assert_eq!(format!("{m:?}"), "1 - 2 e1 + 0.5 e13");
    assert_eq!(format!("{:?}", g3.zero()), "0");
    assert_eq!(format!("{:?}", g3.blade(0b111, 3.0)), "3 e123");
}
