//! One test per erratum listed in `ga::errata`: each computes what the report writes and what
//! is right, and asserts that they differ the way the erratum says.

mod common;

use common::{Embed, report};
use ga::g3::geometry::{Line, Plane, point_in_triangle};
use ga::g3::{Bivector, Multivector, Rotor, Trivector, Vector};

fn v(x: f64, y: f64, z: f64) -> Vector<f64> {
    Vector::new(x, y, z)
}

/// The report's line-plane intersection (3.2), `p = a - ((a ^ B)* - d) u / (u ^ B)*`, with the
/// plane exactly as the report builds it (3.1): `B = b' ^ c'` unnormalised, `d = |a_perp|`.
fn report_intersection(
    line: &Line<f64>,
    a: Vector<f64>,
    b: Vector<f64>,
    c: Vector<f64>,
) -> Vector<f64> {
    let bivector = (b - a) ^ (c - a);
    let distance = a.reject(bivector).norm();
    let numerator = (line.point ^ bivector).dual() - distance;
    line.point - line.dir * (numerator / (line.dir ^ bivector).dual())
}

/// E1: the tables print `column * row` (the full 192-entry check is in `report_tables.rs`).
#[test]
fn e1_tables_are_transposed() {
    // Figure 2.5, row e1, column e2, reads -e12; equation 2.11 says e1 e2 = +e12.
    let printed = -Multivector::<f64>::E12;
    assert_eq!(Multivector::<f64>::E1 * Multivector::E2, Multivector::E12);
    assert_ne!(Multivector::<f64>::E1 * Multivector::E2, printed);
    assert_eq!(Multivector::<f64>::E2 * Multivector::E1, printed);
    // Figure 2.7, row e1, column e12, reads -e2: that is e12 | e1, not e1 | e12.
    assert_eq!(Vector::<f64>::E1 | Bivector::E12, Vector::E2);
    assert_eq!(Bivector::<f64>::E12 | Vector::E1, -Vector::E2);
}

/// E2: `B = a' ^ c'` is zero because `a' = a - a = 0`; `b' ^ c'` is meant.
#[test]
fn e2_plane_bivector_from_a_prime_is_zero() {
    let (a, b, c) = (v(1.0, 2.0, 3.0), v(4.0, 0.0, 1.0), v(-1.0, 5.0, 2.0));
    let (a1, b1, c1) = (a - a, b - a, c - a);
    assert_eq!(a1 ^ c1, Bivector::ZERO, "the report's formula");
    let meant = b1 ^ c1;
    assert_ne!(meant, Bivector::ZERO);
    // The meant bivector is the triangle's plane: every edge lies in it.
    for edge in [b - a, c - b, a - c] {
        assert!((edge ^ meant).e123.abs() < 1e-12);
    }
}

/// E3: `d = |a_perp|` loses the sign, so a plane with the origin on its positive side is
/// mirrored through the origin.
#[test]
fn e3_unsigned_offset_puts_the_plane_on_the_wrong_side() {
    // The plane z = -2, normal +e3 (counter-clockwise seen from +z), unit bivector e12 (the
    // triangle has area 1/2, so E4 does not interfere).
    let (a, b, c) = (v(0.0, 0.0, -2.0), v(1.0, 0.0, -2.0), v(0.0, 1.0, -2.0));
    let line = Line::new(v(0.2, 0.2, 0.0), v(0.0, 0.0, -1.0));
    assert_eq!(((b - a) ^ (c - a)).norm(), 1.0);
    // The report: |a_perp| = 2, and the ray meets the mirror plane z = +2, behind it.
    let wrong = report_intersection(&line, a, b, c);
    assert!(wrong.abs_diff_eq(v(0.2, 0.2, 2.0), 1e-15), "{wrong:?}");
    // Signed offset: d = a . n = -2, and the hit is at z = -2, two units along the ray.
    let plane = Plane::from_triangle(a, b, c);
    assert_eq!(plane.offset, -2.0);
    let (t, hit) = plane.intersect_line(&line).expect("not parallel");
    assert_eq!(t, 2.0);
    assert!(hit.abs_diff_eq(v(0.2, 0.2, -2.0), 1e-15), "{hit:?}");
    assert!(point_in_triangle(hit, a, b, c));
}

/// E4: the intersection formula needs `|B| = 1`, and `b' ^ c'` is twice the triangle's area.
#[test]
fn e4_intersection_needs_a_unit_bivector() {
    // Plane z = 2 on its positive side (so the unsigned offset of E3 is right here); |B| = 16.
    let (a, b, c) = (v(0.0, 0.0, 2.0), v(4.0, 0.0, 2.0), v(0.0, 4.0, 2.0));
    let line = Line::new(Vector::ZERO, Vector::E3);
    assert_eq!(((b - a) ^ (c - a)).norm(), 16.0);
    let wrong = report_intersection(&line, a, b, c);
    assert!(wrong.abs_diff_eq(v(0.0, 0.0, 2.0 / 16.0), 1e-15), "{wrong:?}");
    // Normalising B (or scaling d by |B|) gives the right point.
    let (_, hit) = Plane::from_triangle(a, b, c).intersect_line(&line).expect("not parallel");
    assert!(hit.abs_diff_eq(v(0.0, 0.0, 2.0), 1e-15), "{hit:?}");
    let big = (b - a) ^ (c - a);
    let scaled_offset = (a ^ big).dual();
    let t = -((line.point ^ big).dual() - scaled_offset) / (line.dir ^ big).dual();
    assert_eq!(line.at(t), v(0.0, 0.0, 2.0));
}

/// E5: `A† A` is not a scalar in general, so `A† / (A† A)` is the inverse of versors only.
#[test]
fn e5_reverse_product_is_not_scalar_in_general() {
    // 1 + e1: A† A = 2 + 2 e1, and A has no inverse at all ((1 + e1)(1 - e1) = 0).
    let a = Multivector::<f64>::ONE + Multivector::E1;
    assert_eq!((a.reverse() * a).to_array(), [2.0, 2.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]);
    assert_eq!(a * a.conjugate(), Multivector::ZERO);
    assert!(a.inverse().is_none());
    // 2 + e1 is not a versor (even and odd grades) yet is invertible: (2 - e1) / 3.
    let a = Multivector::<f64>::scalar(2.0) + Multivector::E1;
    assert_eq!((a.reverse() * a).to_array(), [5.0, 4.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]);
    let inverse = a.inverse().expect("2 + e1 is invertible");
    assert!(inverse.abs_diff_eq((Multivector::scalar(2.0) - Multivector::E1) / 3.0, 1e-15));
    assert!((a * inverse).abs_diff_eq(Multivector::ONE, 1e-15));
    // The report's formula with the sum of squares, A† / |A|^2, is not an inverse here.
    let report_inverse = a.versor_inverse().expect("non-zero");
    assert!(!(a * report_inverse).abs_diff_eq(Multivector::ONE, 0.1), "{}", a * report_inverse);
    // The scalar part of A† A is still the sum of squares, for any A.
    let m = Multivector::from_array([1.0, -2.0, 0.5, 3.0, -1.0, 2.0, 0.25, -4.0]);
    assert_eq!((m.reverse() * m).s(), m.to_array().iter().map(|x| x * x).sum::<f64>());
}

/// E6: for a versor, `A† A` is the sum of the *squared* coefficients, not their sum.
#[test]
fn e6_reverse_product_of_a_versor_is_the_sum_of_squares() {
    let versor = Multivector::from(v(1.0, 2.0, 0.0) * v(0.0, 1.0, 3.0));
    let coefficients = versor.to_array();
    let product = versor.reverse() * versor;
    let squares: f64 = coefficients.iter().map(|x| x * x).sum();
    let sum: f64 = coefficients.iter().sum();
    assert_eq!(product, Multivector::scalar(squares));
    assert_ne!(squares, sum, "the printed formula sum(a_k) would give {sum}");
}

/// E7: with the report's inner product, bivectors of the same orientation give `s < 0`, so the
/// report's rule (all three `s > 0`) accepts no point at all.
#[test]
fn e7_report_sign_rule_accepts_no_point() {
    let (a, b, c) = (v(0.0, 0.0, 0.0), v(1.0, 0.0, 0.0), v(0.0, 1.0, 0.0));
    // Same orientation, negative inner product: e12 | e12 = -1.
    assert_eq!(Bivector::<f64>::E12 | Bivector::E12, -1.0);
    let report_rule = |p: Vector<f64>| {
        let edge = |start: Vector<f64>, end: Vector<f64>, other: Vector<f64>| {
            let s = ((end - start) ^ (p - start)) | ((end - start) ^ (other - start));
            s > 0.0
        };
        edge(a, b, c) && edge(b, c, a) && edge(a, c, b)
    };
    let mut inside = 0;
    for i in -10..=20 {
        for j in -10..=20 {
            let p = v(f64::from(i) * 0.1 + 0.01, f64::from(j) * 0.1 + 0.01, 0.0);
            assert!(!report_rule(p), "the report's rule accepted {p:?}");
            let barycentric_inside = p.e1 >= 0.0 && p.e2 >= 0.0 && p.e1 + p.e2 <= 1.0;
            assert_eq!(point_in_triangle(p, a, b, c), barycentric_inside, "{p:?}");
            inside += usize::from(barycentric_inside);
        }
    }
    assert!(inside > 0, "the grid must contain inside points for the test to mean anything");
}

/// E8: parallel vectors have inner product `|a| |b|`, not 1.
#[test]
fn e8_parallel_vectors_dot_to_the_product_of_lengths() {
    let (a, b) = (v(2.0, 0.0, 0.0), v(3.0, 0.0, 0.0));
    assert_eq!(a | b, 6.0);
    assert_eq!(a | -b, -6.0);
    assert_eq!(Vector::<f64>::E1 | Vector::E1, 1.0, "only unit vectors give 1");
}

/// E9: for `b` in the plane of `A`, `|A . b| = |A| |b|`, not `|b|`.
#[test]
fn e9_bivector_vector_inner_product_scales_with_the_bivector() {
    let (big, b) = (Bivector::<f64>::E12 * 2.0, Vector::<f64>::E1);
    let c = big | b;
    assert_eq!(c.norm(), 2.0);
    assert_ne!(c.norm(), b.norm());
    assert_eq!(c | b, 0.0, "c is perpendicular to b, as the report says");
}

/// E10: the text says scalar . scalar is the product; figure 2.7 (followed by `|`) says 0.
#[test]
fn e10_scalar_inner_scalar_is_zero_in_the_table() {
    let (two, three) = (Multivector::<f64>::scalar(2.0), Multivector::scalar(3.0));
    assert_eq!(two | three, Multivector::ZERO, "figure 2.7, row s");
    assert_eq!(two | Multivector::E1, Multivector::ZERO);
    assert_eq!(two.scalar_product(three), 6.0);
    assert_eq!(two.left_contraction(three), Multivector::scalar(6.0));
}

/// E11: `I . B` is the negative normal; the dual `B I^-1` is the normal (2.3.3 is right).
#[test]
fn e11_trivector_inner_bivector_is_the_negative_normal() {
    let normal = Vector::<f64>::E1.cross(Vector::E2);
    assert_eq!(normal, Vector::E3);
    assert_eq!(Trivector::<f64>::I | Bivector::E12, -normal);
    assert_eq!(Bivector::<f64>::E12.dual(), normal);
    let plane = v(1.0, 2.0, 0.5) ^ v(-1.0, 0.0, 3.0);
    assert!((Trivector::I | plane).abs_diff_eq(-plane.dual(), 1e-15));
}

/// E12: sharing a basis vector does not make the inner product non-zero (nor equal to 1).
#[test]
fn e12_shared_components_do_not_decide_the_inner_product() {
    // e12 and e23 share e2, yet their inner product is 0: e12 e23 = e13 has grade 2, not 0.
    assert_eq!(Bivector::<f64>::E12 | Bivector::E23, 0.0);
    let product = Multivector::<f64>::E12 * Multivector::E23;
    assert_eq!(product, -Multivector::E31);
    assert_eq!(Bivector::<f64>::E12 | Bivector::E12, -1.0, "not 1");
    // The grade rule reproduces the table: the grade |r - s| part of the geometric product.
    let (a, b) = (Multivector::<f64>::E1, Multivector::E12);
    assert_eq!(a | b, (a * b).grade(1));
}

/// E13: linearly *dependent* vectors span no volume.
#[test]
fn e13_dependent_vectors_span_no_volume() {
    let (a, b) = (v(1.0, 2.0, 3.0), v(-2.0, 0.5, 1.0));
    assert_eq!((a ^ b ^ (a * 2.0 - b)).e123, 0.0);
    assert_ne!((a ^ b ^ Vector::E1).e123, 0.0);
}

/// E14: the trivector is the *outer* product `(a ^ b) ^ c`, the signed volume `det[a b c]`.
#[test]
fn e14_trivector_is_the_outer_product_with_c() {
    let (a, b, c) = (v(1.0, 2.0, 3.0), v(-2.0, 0.5, 1.0), v(0.0, 4.0, -1.0));
    // det by cofactor expansion along the first row, in plain arithmetic.
    let det = a.e1 * (b.e2 * c.e3 - b.e3 * c.e2) - a.e2 * (b.e1 * c.e3 - b.e3 * c.e1)
        + a.e3 * (b.e1 * c.e2 - b.e2 * c.e1);
    assert_eq!((a ^ b) ^ c, Trivector::new(det));
    // The reference algebra agrees, with c outer-multiplied onto the bivector.
    let want = report(&a.to_reference().outer(&b.to_reference()).outer(&c.to_reference()));
    assert_eq!(want[7], det);
}

/// E15: the second formula of 2.3.4 is the rejection, and it is right.
#[test]
fn e15_projection_and_rejection_split_a_vector() {
    let (a, plane) = (v(1.0, -2.0, 3.0), v(0.5, 1.0, 0.0) ^ v(-1.0, 1.0, 2.0));
    let (parallel, perpendicular) = (a.project(plane), a.reject(plane));
    assert!((parallel + perpendicular).abs_diff_eq(a, 1e-14));
    assert!((perpendicular | plane).max_abs() < 1e-14, "a_perp . B = 0 (2.14)");
    assert!((parallel ^ plane).e123.abs() < 1e-14, "a_par ^ B = 0 (2.13)");
    // (a ^ B) B^-1 with general products gives the same vector.
    let general =
        Multivector::from(a ^ plane) * Multivector::from(plane).inverse().expect("B != 0");
    assert!(general.abs_diff_eq(Multivector::from(perpendicular), 1e-14));
    // Rotating the whole configuration keeps the split (a sanity check on both formulas).
    let r = Rotor::from_angle_plane(0.7, Bivector::E23);
    assert!(
        r.rotate(a).reject(r.rotate_bivector(plane)).abs_diff_eq(r.rotate(perpendicular), 1e-14)
    );
}
