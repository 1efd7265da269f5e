//! Algebraic laws of `ga::g3`, as properties over random inputs (proptest, fixed seeds).
//!
//! Each property runs a modest number of cases from a fixed seed, so the file is deterministic
//! and runs in well under a second; raise `PROPTEST_CASES` locally to search harder.

mod common;

use std::f64::consts::PI;

use common::{Embed, report};
use ga::g3::{Bivector, Multivector, Rotor, Trivector, Vector};
use proptest::prelude::*;
use proptest::test_runner::{Config, RngSeed};

const TOLERANCE: f64 = 1e-12;

/// Cases per property: 256, or `PROPTEST_CASES` when it is set (to search harder locally).
fn cases(env: Option<&str>) -> u32 {
    env.map_or(256, |s| s.trim().parse().unwrap_or_else(|_| panic!("PROPTEST_CASES={s:?}")))
}

fn config(seed: u64) -> Config {
    Config {
        cases: cases(std::env::var("PROPTEST_CASES").ok().as_deref()),
        rng_seed: RngSeed::Fixed(seed),
        // No regression files: the seed already makes every failure reproducible.
        failure_persistence: None,
        ..Config::default()
    }
}

fn coefficient() -> impl Strategy<Value = f64> {
    -10.0..10.0_f64
}

fn multivector() -> impl Strategy<Value = Multivector<f64>> {
    prop::array::uniform8(coefficient()).prop_map(Multivector::from_array)
}

fn vector() -> impl Strategy<Value = Vector<f64>> {
    prop::array::uniform3(coefficient()).prop_map(Vector::from_array)
}

fn bivector() -> impl Strategy<Value = Bivector<f64>> {
    prop::array::uniform3(coefficient()).prop_map(Bivector::from_array)
}

/// A non-degenerate vector (length at least 0.1).
fn nonzero_vector() -> impl Strategy<Value = Vector<f64>> {
    vector().prop_filter("length >= 0.1", |v| v.norm() >= 0.1)
}

/// A unit rotor: an angle in `[-2 pi, 2 pi]` in a random plane.
fn unit_rotor() -> impl Strategy<Value = Rotor<f64>> {
    (-2.0 * PI..2.0 * PI, nonzero_vector())
        .prop_map(|(angle, n)| Rotor::from_angle_plane(angle, n.undual()))
}

fn close<E: Embed>(got: E, want: E, scale: f64) -> bool {
    let (g, w) = (got.to_report(), want.to_report());
    g.iter().zip(&w).all(|(a, b)| (a - b).abs() <= TOLERANCE * scale.max(1.0))
}

/// The same rotation: a rotor and its negative act identically.
fn same_rotation(a: Rotor<f64>, b: Rotor<f64>, tolerance: f64) -> bool {
    let d = (a - b).max_abs().min((a + b).max_abs());
    d <= tolerance
}

proptest! {
    #![proptest_config(config(1))]

    #[test]
    fn geometric_product_is_associative(
        a in multivector(),
        b in multivector(),
        c in multivector(),
    ) {
        let scale = a.norm() * b.norm() * c.norm();
        prop_assert!(close((a * b) * c, a * (b * c), scale));
    }

    #[test]
    fn mixed_products_are_associative(
        a in vector(),
        b in bivector(),
        c in bivector(),
        r in unit_rotor(),
    ) {
        // Across grade types, through the specialised kernels: odd results are multivectors,
        // even ones rotors.
        let scale = a.norm() * b.norm();
        prop_assert!(close((a * b) * r, a * (b * r), scale));
        prop_assert!(close((b * r) * c, b * (r * c), scale * c.norm()));
    }

    #[test]
    fn geometric_product_distributes(a in multivector(), b in multivector(), c in multivector()) {
        let scale = a.norm() * (b.norm() + c.norm());
        prop_assert!(close(a * (b + c), a * b + a * c, scale));
        prop_assert!(close((b + c) * a, b * a + c * a, scale));
    }
}

proptest! {
    #![proptest_config(config(2))]

    #[test]
    fn outer_product_of_vectors_is_antisymmetric(a in vector(), b in vector()) {
        prop_assert_eq!(a ^ b, -(b ^ a));
        prop_assert_eq!(a ^ a, Bivector::ZERO);
    }

    /// a b = a | b + a ^ b (report equation 2.6).
    #[test]
    fn vector_product_is_inner_plus_outer(a in vector(), b in vector()) {
        let split = Rotor::from_scalar_bivector(a | b, a ^ b);
        prop_assert!(close(a * b, split, a.norm() * b.norm()));
    }

    #[test]
    fn reverse_of_a_product_reverses_the_order(
        a in multivector(),
        b in multivector(),
        c in multivector(),
    ) {
        let scale = a.norm() * b.norm() * c.norm();
        let want = c.reverse() * b.reverse() * a.reverse();
        prop_assert!(close((a * b * c).reverse(), want, scale));
    }

    #[test]
    fn dual_and_undual_are_inverse(
        m in multivector(),
        v in vector(),
        b in bivector(),
        t in coefficient(),
    ) {
        prop_assert_eq!(m.dual().undual(), m);
        prop_assert_eq!(m.undual().dual(), m);
        prop_assert_eq!(v.dual().undual(), v);
        prop_assert_eq!(b.dual().undual(), b);
        prop_assert_eq!(Trivector::new(t).dual(), t);
        prop_assert_eq!(Trivector::from_dual(Trivector::new(t).dual()), Trivector::new(t));
        // The typed duals agree with the general one.
        prop_assert_eq!(Multivector::from(v).dual(), Multivector::from(v.dual()));
        prop_assert_eq!(Multivector::from(b).dual(), Multivector::from(b.dual()));
    }
}

/// A zero divisor with exact integer coefficients: `(p + q e_i + r e_j)` with
/// `p^2 = q^2 + r^2` (a Pythagorean triple), so that `(p + v)(p - v) = p^2 - |v|^2 = 0`.
fn zero_divisor() -> impl Strategy<Value = Multivector<f64>> {
    let triples = prop::sample::select(vec![(1.0, 1.0, 0.0), (5.0, 3.0, 4.0), (13.0, 5.0, 12.0)]);
    (triples, 0..3usize, any::<bool>()).prop_map(|((p, q, r), axis, flip)| {
        let mut c = [0.0; 8];
        c[0] = p;
        c[1 + axis] = if flip { -q } else { q };
        c[1 + (axis + 1) % 3] = r;
        Multivector::from_array(c)
    })
}

/// A multivector with small integer coefficients: its products are exact in f64.
fn integer_multivector() -> impl Strategy<Value = Multivector<f64>> {
    prop::array::uniform8(-3..=3i32).prop_map(|c| Multivector::from_array(c.map(f64::from)))
}

/// `A Ā`, which lies in the centre `{1, I}`: returned as `(alpha, beta)`.
fn central_norm(a: Multivector<f64>) -> (f64, f64) {
    let z = a.to_reference().geometric(&a.to_reference().conjugate());
    let c = report(&z);
    assert!(c[1..7].iter().all(|&x| x.abs() <= 1e-9 * a.norm_squared()), "A Ā not central: {c:?}");
    (c[0], c[7])
}

proptest! {
    #![proptest_config(config(3))]

    #[test]
    fn inverse_is_two_sided(a in multivector()) {
        let (alpha, beta) = central_norm(a);
        // Well away from singular, the inverse must exist and be accurate.
        prop_assume!(alpha.hypot(beta) > 1e-3 * a.norm_squared());
        let inverse = a.inverse().expect("invertible");
        let scale = a.norm() * inverse.norm();
        prop_assert!(close(a * inverse, Multivector::ONE, scale));
        prop_assert!(close(inverse * a, Multivector::ONE, scale));
    }

    /// With exact (small integer) coefficients, `inverse()` is `None` exactly when
    /// `A Ā = 0`.
    #[test]
    fn inverse_is_none_exactly_when_the_central_norm_vanishes(
        x in integer_multivector(),
        d in zero_divisor(),
        make_singular in any::<bool>(),
    ) {
        let a = if make_singular { d * x } else { x };
        let (alpha, beta) = central_norm(a);
        let singular = alpha == 0.0 && beta == 0.0;
        prop_assert_eq!(a.inverse().is_none(), singular, "A = {}, A Ā = {} + {} I", a, alpha, beta);
        if let Some(inverse) = a.inverse() {
            prop_assert!(close(a * inverse, Multivector::ONE, a.norm() * inverse.norm()));
        }
    }

    #[test]
    fn typed_inverses(
        v in nonzero_vector(),
        b in bivector(),
        r in unit_rotor(),
        t in coefficient(),
    ) {
        prop_assert!(close(Multivector::from(v * v.inverse().unwrap()), Multivector::ONE, 1.0));
        if let Some(bi) = b.inverse() {
            prop_assert!(close(b * bi, Rotor::IDENTITY, b.norm() * bi.norm()));
        }
        prop_assert!(close(r * r.inverse().unwrap(), Rotor::IDENTITY, 1.0));
        if let Some(ti) = Trivector::new(t).inverse() {
            prop_assert!(((Trivector::new(t) * ti) - 1.0).abs() <= TOLERANCE);
        }
    }
}

proptest! {
    #![proptest_config(config(4))]

    /// Rotations keep lengths and angles and map a right-handed frame to a right-handed one.
    #[test]
    fn rotors_preserve_lengths_and_orientation(r in unit_rotor(), a in vector(), b in vector()) {
        let (ra, rb) = (r.rotate(a), r.rotate(b));
        prop_assert!((ra.norm() - a.norm()).abs() <= TOLERANCE * a.norm().max(1.0));
        prop_assert!(((ra | rb) - (a | b)).abs() <= TOLERANCE * (a.norm() * b.norm()).max(1.0));
        let frame = r.rotate(Vector::E1) ^ r.rotate(Vector::E2) ^ r.rotate(Vector::E3);
        prop_assert!((frame.e123 - 1.0).abs() <= TOLERANCE, "det = {}", frame.e123);
    }

    #[test]
    fn exp_undoes_log(r in unit_rotor()) {
        prop_assert!(close(r.log().exp(), r, 1.0));
    }

    #[test]
    fn composing_rotors_composes_rotations(r in unit_rotor(), s in unit_rotor(), v in vector()) {
        // (S R) v (S R)~ = S (R v R~) S~: apply R first.
        let want = s.rotate(r.rotate(v));
        prop_assert!(close((s * r).rotate(v), want, v.norm()));
    }

    /// from_vectors takes the first direction to the second, including at 0 and 180 degrees.
    #[test]
    fn from_vectors_handles_equal_and_opposite_directions(
        a in nonzero_vector(),
        b in nonzero_vector(),
        k in 0.1..10.0_f64,
    ) {
        let unit = |v: Vector<f64>| v / v.norm();
        for to in [b, a * k, a * -k] {
            let r = Rotor::from_vectors(a, to);
            prop_assert!((r.norm() - 1.0).abs() <= TOLERANCE, "not unit: {:?}", r);
            prop_assert!(close(r.rotate(unit(a)), unit(to), 1.0), "{:?} -> {:?}", a, to);
        }
        // Equal directions: no rotation at all.
        prop_assert!(same_rotation(Rotor::from_vectors(a, a * k), Rotor::IDENTITY, TOLERANCE));
        // Opposite directions: a half turn (scalar part zero) in a plane containing a.
        let half = Rotor::from_vectors(a, -a);
        prop_assert!(half.s.abs() <= TOLERANCE);
        prop_assert!((a ^ half.bivector()).e123.abs() <= TOLERANCE * a.norm());
    }

    #[test]
    fn slerp_hits_its_endpoints(r0 in unit_rotor(), r1 in unit_rotor()) {
        prop_assert!(same_rotation(r0.slerp(r1, 0.0), r0, 1e-12));
        prop_assert!(same_rotation(r0.slerp(r1, 1.0), r1, 1e-12));
        prop_assert!(same_rotation(r0.slerp(r0, 0.5), r0, 1e-12));
        // Halfway, the remaining turn to r1 equals the turn already made.
        let mid = r0.slerp(r1, 0.5);
        prop_assert!(same_rotation(mid * r0.reverse(), r1 * mid.reverse(), 1e-9));
    }

    #[test]
    fn zero_half_and_full_turns(n in nonzero_vector(), v in vector()) {
        let plane = n.undual();
        prop_assert!(same_rotation(Rotor::from_angle_plane(0.0, plane), Rotor::IDENTITY, 0.0));
        // A full turn is the rotor -1: the same rotation as the identity.
        let full = Rotor::from_angle_plane(2.0 * PI, plane);
        prop_assert!(close(full, -Rotor::IDENTITY, 1.0));
        // A half turn negates the in-plane part of v and keeps the normal part.
        let half = Rotor::from_angle_plane(PI, plane);
        let (inside, normal) = (v.project(plane), v.reject(plane));
        prop_assert!(close(half.rotate(v), normal - inside, v.norm()));
    }
}

/// The case count is 256 by default and follows `PROPTEST_CASES` when it is set, as the
/// module docs promise.
#[test]
fn case_count_follows_proptest_cases() {
    assert_eq!(cases(None), 256);
    assert_eq!(cases(Some("5000")), 5000);
    assert_eq!(cases(Some(" 12\n")), 12);
    assert!(std::panic::catch_unwind(|| cases(Some("many"))).is_err());
    let env = std::env::var("PROPTEST_CASES").ok();
    assert_eq!(config(1).cases, cases(env.as_deref()));
}
