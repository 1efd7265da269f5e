//! `ga::cga::geometry` against independent answers: Euclidean formulas (distances, the
//! textbook line-plane intersection, reflection and inversion formulas), glam's affine maps
//! for rigid motions, and exact zeros for incidences with integer coordinates.

use core::f64::consts::PI;

use ga::cga::{Bivector, Motor, Pseudoscalar, Quadvector, Rotor, Trivector, Vector};
use ga::g3;
use glam::{Affine3A, DAffine3, DQuat, DVec3, Quat, Vec3};
use rand::{Rng, SeedableRng};
use rand_pcg::Pcg64;

type V3 = g3::Vector<f64>;

fn v3(x: f64, y: f64, z: f64) -> V3 {
    V3::new(x, y, z)
}

fn up(x: V3) -> Vector<f64> {
    Vector::up(x)
}

fn dot(a: V3, b: V3) -> f64 {
    a.e1 * b.e1 + a.e2 * b.e2 + a.e3 * b.e3
}

fn cross(a: V3, b: V3) -> V3 {
    v3(a.e2 * b.e3 - a.e3 * b.e2, a.e3 * b.e1 - a.e1 * b.e3, a.e1 * b.e2 - a.e2 * b.e1)
}

fn random_v3(rng: &mut Pcg64, r: f64) -> V3 {
    v3(rng.random_range(-r..r), rng.random_range(-r..r), rng.random_range(-r..r))
}

fn random_int_v3(rng: &mut Pcg64, r: i32) -> V3 {
    let mut c = || f64::from(rng.random_range(-r..=r));
    v3(c(), c(), c())
}

fn random_unit(rng: &mut Pcg64) -> V3 {
    loop {
        let v = random_v3(rng, 1.0);
        let n = v.norm();
        if n > 0.1 {
            return v / n;
        }
    }
}

/// A half-width for random coordinates: small, unit-sized or large.
fn random_scale(rng: &mut Pcg64) -> f64 {
    [0.5, 2.0, 10.0][rng.random_range(0..3)]
}

/// The relative tolerance for coordinates of size `m`: a point stores `½|x|²` in both `e4`
/// and `e5` and its weight is their difference, so rounding grows like `ε m²` (module docs of
/// `ga::cga::geometry`, "Precision"). 1e-12 up to `m = 3`.
fn tol(m: f64) -> f64 {
    1e-13 * (1.0 + m * m)
}

fn to_dvec3(v: V3) -> DVec3 {
    DVec3::new(v.e1, v.e2, v.e3)
}

/// `|a - b| <= tol max(1, |b|)`.
fn assert_close(a: V3, b: V3, tol: f64, what: &str) {
    let err = (a - b).norm();
    assert!(err <= tol * b.norm().max(1.0), "{what}: {a:?} vs {b:?} (error {err:e})");
}

/// Every coefficient within `tol max(1, max |b|)`.
fn assert_close_slices(a: &[f64], b: &[f64], tol: f64, what: &str) {
    let scale = b.iter().fold(1.0_f64, |m, x| m.max(x.abs()));
    for (i, (x, y)) in a.iter().zip(b).enumerate() {
        assert!((x - y).abs() <= tol * scale, "{what}: coefficient {i}: {a:?} vs {b:?}");
    }
}

#[test]
fn null_basis() {
    let (o, inf) = (Vector::<f64>::E_O, Vector::<f64>::E_INF);
    assert_eq!((o | o, inf | inf, o | inf, inf | o), (0.0, 0.0, -1.0, -1.0));
    assert_eq!(o, up(V3::ZERO));
    // eₒ ∧ e∞ = -e45, which squares to +1 (the generator of dilations).
    assert_eq!(o ^ inf, Bivector::E45 * -1.0);
    assert_eq!((o ^ inf).scalar_product(o ^ inf), 1.0);
    assert_eq!((inf.weight(), o.weight(), up(v3(3.0, -4.0, 12.0)).weight()), (0.0, 1.0, 1.0));
}

#[test]
fn up_down_round_trips() {
    let mut rng = Pcg64::seed_from_u64(0xC6A_0001);
    for _ in 0..2000 {
        let x = random_v3(&mut rng, 100.0);
        let p = up(x);
        assert_close(p.down(), x, tol(100.0), "down(up(x))");
        assert_eq!(p.to_xyz(), p.down().to_array());
        assert!((p.weight() - 1.0).abs() <= 1e-15 * x.norm_squared().max(1.0));
        // Any non-zero multiple is the same point.
        let lambda = rng.random_range(0.01..100.0) * if rng.random_bool(0.5) { 1.0 } else { -1.0 };
        assert_close((p * lambda).down(), x, tol(100.0), "down(λ up(x))");
        // And so is the dual sphere of radius zero, whose centre is down.
        let centre = Vector::dual_sphere(x, 0.0).down();
        assert_close(centre, x, tol(100.0), "centre of a radius-0 sphere");
        // Near the origin the round trip is as good as the brief asks (1e-12).
        let y = random_v3(&mut rng, 2.0);
        assert_close(up(y).down(), y, 1e-12, "down(up(y)), |y| < 4");
    }
    // f32.
    for _ in 0..200 {
        let x = random_v3(&mut rng, 10.0);
        let y = Vector::<f32>::point(x.e1 as f32, x.e2 as f32, x.e3 as f32).down();
        let back = v3(f64::from(y.e1), f64::from(y.e2), f64::from(y.e3));
        assert_close(back, x, 1e-5, "f32 down(up(x))");
    }
}

#[test]
fn inner_product_of_points_is_minus_half_squared_distance() {
    let mut rng = Pcg64::seed_from_u64(0xC6A_0002);
    // Exact with integer coordinates: the products and sums are exact in f64.
    for _ in 0..1000 {
        let (x, y) = (random_int_v3(&mut rng, 20), random_int_v3(&mut rng, 20));
        assert_eq!(up(x) | up(x), 0.0);
        assert_eq!(up(x) | up(y), -0.5 * (x - y).norm_squared());
        assert_eq!(up(x) | up(y), up(y) | up(x));
    }
    for _ in 0..1000 {
        let (x, y) = (random_v3(&mut rng, 10.0), random_v3(&mut rng, 10.0));
        let scale = x.norm_squared() + y.norm_squared() + 1.0;
        assert!((up(x) | up(x)).abs() <= 1e-14 * scale);
        let err = (up(x) | up(y)) + 0.5 * (x - y).norm_squared();
        assert!(err.abs() <= 1e-13 * scale, "{x:?} {y:?}: {err:e}");
    }
}

/// Integer offsets of length 3 (points on a sphere of radius 3), the first four not coplanar.
const ON_SPHERE: [[f64; 3]; 10] = [
    [3.0, 0.0, 0.0],
    [0.0, 3.0, 0.0],
    [0.0, 0.0, 3.0],
    [-3.0, 0.0, 0.0],
    [0.0, -3.0, 0.0],
    [0.0, 0.0, -3.0],
    [2.0, 2.0, 1.0],
    [-2.0, 1.0, -2.0],
    [1.0, -2.0, 2.0],
    [-1.0, -2.0, -2.0],
];

#[test]
fn points_lie_exactly_on_the_sphere_through_them() {
    let mut rng = Pcg64::seed_from_u64(0xC6A_0003);
    for _ in 0..200 {
        let c = random_int_v3(&mut rng, 5);
        let on: Vec<Vector<f64>> = ON_SPHERE.iter().map(|&o| up(c + V3::from_array(o))).collect();
        let sphere = Quadvector::sphere(on[0], on[1], on[2], on[3]);
        let dual = Vector::dual_sphere(c, 3.0);
        for &p in &on {
            assert_eq!(sphere ^ p, Pseudoscalar::ZERO);
            assert_eq!(sphere.dual() | p, 0.0);
            assert_eq!(dual | p, 0.0);
        }
        // Off the sphere: up(x) · σ = ½(r² - |x - c|²), inside positive.
        assert_eq!(dual | up(c + v3(3.0, 1.0, 0.0)), -0.5);
        assert_eq!(dual | up(c + v3(1.0, 1.0, 0.0)), 3.5);
        assert_ne!(sphere ^ up(c + v3(3.0, 1.0, 0.0)), Pseudoscalar::ZERO);
        // The direct sphere's dual is a multiple of the dual sphere (exactly: every 2x2 minor
        // is zero), and both read back the centre and the radius.
        assert_eq!(sphere.dual() ^ dual, Bivector::ZERO);
        assert_eq!((dual.down(), dual.radius_squared()), (c, 9.0));
        assert_close(sphere.centre(), c, 1e-14, "centre of the sphere through four points");
        assert!((sphere.radius_squared() - 9.0).abs() <= 1e-13);
    }
}

#[test]
fn points_lie_exactly_on_the_circle_through_them() {
    // Six points on the circle of radius √2 about c in the plane through c normal to (1,1,1).
    let offsets = [
        [1.0, -1.0, 0.0],
        [0.0, 1.0, -1.0],
        [-1.0, 0.0, 1.0],
        [-1.0, 1.0, 0.0],
        [1.0, 0.0, -1.0],
        [0.0, -1.0, 1.0],
    ];
    let mut rng = Pcg64::seed_from_u64(0xC6A_0004);
    for _ in 0..200 {
        let c = random_int_v3(&mut rng, 6);
        let on: Vec<Vector<f64>> = offsets.iter().map(|&o| up(c + V3::from_array(o))).collect();
        let circle = Trivector::circle(on[0], on[1], on[2]);
        for &p in &on {
            assert_eq!(circle ^ p, Quadvector::ZERO);
        }
        // In the plane but off the circle, and on the sphere |x - c|² = 2 but off the plane.
        assert_ne!(circle ^ up(c + v3(1.0, 1.0, -2.0)), Quadvector::ZERO);
        assert_ne!(circle ^ up(c + v3(1.0, 1.0, 0.0)), Quadvector::ZERO);
    }
}

#[test]
fn points_lie_exactly_on_lines_and_planes_through_them() {
    let mut rng = Pcg64::seed_from_u64(0xC6A_0005);
    let mut planes = 0;
    while planes < 200 {
        let (a, b, c) =
            (random_int_v3(&mut rng, 5), random_int_v3(&mut rng, 5), random_int_v3(&mut rng, 5));
        let n = cross(b - a, c - a);
        if n == V3::ZERO {
            continue;
        }
        planes += 1;
        // The line through a and b holds every a + k (b - a), and not c.
        let line = Trivector::line(up(a), up(b));
        for k in -3..=3 {
            assert_eq!(line ^ up(a + (b - a) * f64::from(k)), Quadvector::ZERO);
        }
        assert_ne!(line ^ up(c), Quadvector::ZERO);
        // The plane through a, b, c holds a + i (b - a) + j (c - a); so does the dual plane
        // n · x = n · a, and the direct plane's dual is a multiple of it.
        let plane = Quadvector::plane(up(a), up(b), up(c));
        let dual = Vector::dual_plane(n, dot(n, a));
        for i in -2..=2 {
            for j in -2..=2 {
                let x = up(a + (b - a) * f64::from(i) + (c - a) * f64::from(j));
                assert_eq!(plane ^ x, Pseudoscalar::ZERO);
                assert_eq!(plane.dual() | x, 0.0);
                assert_eq!(dual | x, 0.0);
            }
        }
        assert_eq!(dual | up(a + n), n.norm_squared());
        assert_ne!(plane ^ up(a + n), Pseudoscalar::ZERO);
        assert_eq!(plane.dual() ^ dual, Bivector::ZERO);
        // Every line passes through infinity, and a flat point reads back its position.
        assert_eq!(line ^ Vector::E_INF, Quadvector::ZERO);
        assert_eq!(Bivector::flat_point(a).flat_point_position(), a);
    }
}

#[test]
fn the_closed_form_line_is_the_outer_product() {
    // Exact on integer coordinates (every product and sum is), close on any vectors, points
    // or not (the closed form does not assume weight 1).
    let mut rng = Pcg64::seed_from_u64(0xC6A_0011);
    for _ in 0..500 {
        let (a, b) = (random_int_v3(&mut rng, 20), random_int_v3(&mut rng, 20));
        let (p, q) = (up(a), up(b));
        assert_eq!(Trivector::line(p, q), p ^ q ^ Vector::E_INF);
        let g = |rng: &mut Pcg64| {
            Vector::from_array(core::array::from_fn(|_| rng.random_range(-5.0..5.0)))
        };
        let (p, q) = (g(&mut rng), g(&mut rng));
        let generic = (p ^ q ^ Vector::E_INF).to_array();
        assert_close_slices(&Trivector::line(p, q).to_array(), &generic, 1e-12, "line");
    }
}

#[test]
fn a_line_meets_a_plane_at_the_textbook_intersection() {
    // Exact: the line through the origin and (1,1,1) meets z = 2 at (2,2,2), whether the plane
    // is spanned by three points, given dual, or met through the contraction.
    let line = Trivector::line(up(V3::ZERO), up(v3(1.0, 1.0, 1.0)));
    let plane =
        Quadvector::plane(up(v3(0.0, 0.0, 2.0)), up(v3(1.0, 0.0, 2.0)), up(v3(5.0, 3.0, 2.0)));
    let dual = Vector::dual_plane(V3::E3, 2.0);
    assert_eq!((line & plane).flat_point_position(), v3(2.0, 2.0, 2.0));
    assert_eq!((line & dual.undual()).flat_point_position(), v3(2.0, 2.0, 2.0));
    assert_eq!((dual | line).flat_point_position(), v3(2.0, 2.0, 2.0));
    assert_eq!(line.meet_plane_position(dual), v3(2.0, 2.0, 2.0));
    assert!(
        !Trivector::line(up(V3::ZERO), up(v3(1.0, 1.0, 0.0)))
            .meet_plane_position(dual)
            .e1
            .is_finite()
    );
    // Parallel: the flat point has weight zero.
    let parallel = Trivector::line(up(V3::ZERO), up(v3(1.0, 1.0, 0.0)));
    assert_eq!((parallel & plane).e45, 0.0);
    assert!(!(parallel & plane).flat_point_position().e1.is_finite());

    let mut rng = Pcg64::seed_from_u64(0xC6A_0006);
    let mut tested = 0;
    while tested < 2000 {
        let (p, q) = (random_v3(&mut rng, 10.0), random_v3(&mut rng, 10.0));
        let (n, d) = (random_unit(&mut rng), rng.random_range(-10.0..10.0));
        let dir = q - p;
        let along = dot(n, dir);
        if along.abs() < 0.2 * dir.norm() {
            continue;
        }
        tested += 1;
        let expected = p + dir * ((d - dot(n, p)) / along);
        let line = Trivector::line(up(p), up(q));
        let dual = Vector::dual_plane(n, d);
        let meet = line & dual.undual();
        assert_close(meet.flat_point_position(), expected, 1e-10, "line & plane");
        assert_close((dual | line).flat_point_position(), expected, 1e-10, "π ⌋ line");
        assert_close(line.meet_plane_position(dual), expected, 1e-10, "meet_plane_position");
        // The meet is a flat point: up(x) ∧ e∞ up to scale.
        let unit = meet * (-1.0 / meet.e45);
        let flat = Bivector::flat_point(expected).to_array();
        assert_close_slices(&unit.to_array(), &flat, 1e-10, "flat point");
    }
}

#[test]
fn motors_move_points_like_glam_affine_maps() {
    let mut rng = Pcg64::seed_from_u64(0xC6A_0007);
    let random_motion = |rng: &mut Pcg64, m: f64| {
        let (axis, angle, t) = (random_unit(rng), rng.random_range(-PI..PI), random_v3(rng, m));
        let motor = Motor::translator(t) * Motor::from(Rotor::from_axis_angle(axis, angle));
        let affine = DAffine3::from_rotation_translation(
            DQuat::from_axis_angle(to_dvec3(axis), angle),
            to_dvec3(t),
        );
        // The rotor is G3's, re-labelled.
        let g3_rotor = g3::Rotor::from_angle_plane(angle, axis.undual());
        let from_g3 = Rotor::from(g3_rotor).to_array();
        let direct = Rotor::from_axis_angle(axis, angle).to_array();
        assert_close_slices(&from_g3, &direct, 1e-15, "Rotor::from(g3::Rotor)");
        (motor, affine)
    };
    let image = |a: &DAffine3, x: V3| {
        let y = a.transform_point3(to_dvec3(x));
        v3(y.x, y.y, y.z)
    };
    for _ in 0..3000 {
        let m = random_scale(&mut rng);
        let (m1, a1) = random_motion(&mut rng, m);
        let (m2, a2) = random_motion(&mut rng, m);
        let x = random_v3(&mut rng, m);
        assert_close(m1.transform_point(x), image(&a1, x), tol(m), "motor vs DAffine3");
        // Rigid motions keep the weight 1.
        assert!((m1.sandwich(up(x)).weight() - 1.0).abs() <= tol(2.0 * m));
        let composed = (m1 * m2).transform_point(x);
        assert_close(composed, image(&(a1 * a2), x), tol(3.0 * m), "composition");
    }
    // f32 against Affine3A, with the same growth of the rounding error in m² (f32's ε is
    // 2^29 times f64's: three correct digits at m = 10).
    for _ in 0..600 {
        let m = random_scale(&mut rng);
        let (axis, angle, t) =
            (random_unit(&mut rng), rng.random_range(-PI..PI), random_v3(&mut rng, m));
        let x = random_v3(&mut rng, m);
        let f = |v: V3| g3::Vector::new(v.e1 as f32, v.e2 as f32, v.e3 as f32);
        let to_vec3 = |v: V3| Vec3::new(v.e1 as f32, v.e2 as f32, v.e3 as f32);
        let motor =
            Motor::translator(f(t)) * Motor::from(Rotor::from_axis_angle(f(axis), angle as f32));
        let affine = Affine3A::from_rotation_translation(
            Quat::from_axis_angle(to_vec3(axis), angle as f32),
            to_vec3(t),
        );
        let (y, z) = (motor.transform_point(f(x)), affine.transform_point3(to_vec3(x)));
        let back = v3(f64::from(y.e1), f64::from(y.e2), f64::from(y.e3));
        let expected = v3(f64::from(z.x), f64::from(z.y), f64::from(z.z));
        assert_close(back, expected, 1e-13 * 2f64.powi(29) * (1.0 + 4.0 * m * m), "f32");
    }
}

#[test]
fn transform_points_is_transform_point_for_every_even_versor() {
    // Rigid motions, motions with a dilation, and the product of two sphere inversions (an
    // even versor that moves e∞: the weight of an image depends on the point).
    let mut rng = Pcg64::seed_from_u64(0xC6A_0012);
    for case in 0..300 {
        let m = random_scale(&mut rng);
        let (axis, angle, t) =
            (random_unit(&mut rng), rng.random_range(-PI..PI), random_v3(&mut rng, m));
        let rigid = Motor::translator(t) * Motor::from(Rotor::from_axis_angle(axis, angle));
        let motor = match case % 3 {
            0 => rigid,
            1 => Motor::dilator(rng.random_range(0.25..4.0)) * rigid,
            _ => {
                let s1 = Vector::dual_sphere(random_v3(&mut rng, m), m);
                let s2 = Vector::dual_sphere(random_v3(&mut rng, m), 2.0 * m);
                Motor::from_array((s1 * s2).to_array().map(|c| c / (m * m)))
            }
        };
        let mut points: Vec<V3> = (0..9).map(|_| random_v3(&mut rng, m)).collect();
        let expected: Vec<V3> = points.iter().map(|&x| motor.transform_point(x)).collect();
        motor.transform_points(&mut points);
        for (got, want) in points.iter().zip(&expected) {
            let scale = want.norm().max(m);
            assert_close(*got, *want, 1e-9 * scale, "transform_points");
        }
    }
    // The map itself is the sandwich, on vectors that are not points too.
    for _ in 0..300 {
        let g = |rng: &mut Pcg64, n: usize| -> Vec<f64> {
            (0..n).map(|_| rng.random_range(-2.0..2.0)).collect()
        };
        let motor = Motor::from_array(g(&mut rng, 16).try_into().expect("16"));
        let x = Vector::from_array(g(&mut rng, 5).try_into().expect("5"));
        let m = motor.vector_map();
        let mapped: Vec<f64> =
            m.iter().map(|row| row.iter().zip(x.to_array()).map(|(a, b)| a * b).sum()).collect();
        assert_close_slices(&mapped, &motor.sandwich(x).to_array(), 1e-12, "vector_map");
    }
    let mut none: [V3; 0] = [];
    Motor::<f64>::ONE.transform_points(&mut none);
}

#[test]
fn reflection_in_a_plane_matches_the_formula() {
    // Exact: x = 1 reflects (3, 2, 5) to (-1, 2, 5), and the image is a normalised point.
    let plane = Vector::dual_plane(V3::E1, 1.0);
    assert_eq!(plane.reflect(up(v3(3.0, 2.0, 5.0))), up(v3(-1.0, 2.0, 5.0)));
    let mut rng = Pcg64::seed_from_u64(0xC6A_0008);
    for _ in 0..3000 {
        let m = random_scale(&mut rng);
        let (n, d, x) = (random_unit(&mut rng), rng.random_range(-m..m), random_v3(&mut rng, m));
        let expected = x - n * (2.0 * (dot(n, x) - d));
        let image = Vector::dual_plane(n, d).reflect(up(x));
        assert_close(image.down(), expected, tol(3.0 * m), "reflection in a plane");
        assert!((image.weight() - 1.0).abs() <= tol(3.0 * m), "weight {}", image.weight());
        // Null: terms of size (3m)⁴ cancel.
        let null = image | image;
        assert!(null.abs() <= tol(3.0 * m) * (1.0 + 9.0 * m * m), "{null:e} at scale {m}");
    }
}

#[test]
fn inversion_in_a_sphere_matches_the_formula() {
    // Exact: the unit sphere inverts (2, 0, 0) to (1/2, 0, 0) and fixes its own points.
    let unit = Vector::dual_sphere(V3::ZERO, 1.0);
    assert_eq!(unit.reflect(up(v3(2.0, 0.0, 0.0))).down(), v3(0.5, 0.0, 0.0));
    assert_eq!(unit.reflect(up(v3(0.0, 1.0, 0.0))).down(), v3(0.0, 1.0, 0.0));
    let mut rng = Pcg64::seed_from_u64(0xC6A_0009);
    let mut tested = 0;
    while tested < 3000 {
        let m = random_scale(&mut rng);
        let (c, r, x) =
            (random_v3(&mut rng, m), rng.random_range(0.2..1.0) * m, random_v3(&mut rng, m));
        let off = x - c;
        if off.norm() < 0.2 * m {
            continue;
        }
        tested += 1;
        let expected = c + off * (r * r / off.norm_squared());
        let image = Vector::dual_sphere(c, r).reflect(up(x));
        assert_close(image.down(), expected, tol(3.0 * m), "inversion in a sphere");
        let scale = image.weight().powi(2) * expected.norm_squared().max(1.0).powi(2);
        assert!((image | image).abs() <= 1e-13 * scale, "not null: {image:?}");
    }
}

/// `-½ t e∞ = -½ t ∧ e∞`, the generator of the translation by `t`.
fn translation_generator(t: V3) -> Bivector<f64> {
    (Vector::new(t.e1, t.e2, t.e3, 0.0, 0.0) ^ Vector::E_INF) * -0.5
}

#[test]
fn translators_are_exact_with_integer_coordinates() {
    let mut rng = Pcg64::seed_from_u64(0xC6A_000A);
    for _ in 0..1000 {
        let (t, x) = (random_int_v3(&mut rng, 20), random_int_v3(&mut rng, 20));
        let tr = Motor::translator(t);
        assert_eq!(tr.sandwich(up(x)), up(x + t));
        assert_eq!(tr.transform_point(x), x + t);
        assert_eq!(translation_generator(t).exp_blade(), tr);
        assert_eq!(tr.log_blade(), translation_generator(t));
        assert_eq!(tr.inverse(), Some(Motor::translator(-t)));
        assert_eq!(tr * Motor::translator(x), Motor::translator(t + x));
    }
}

#[test]
fn dilators_scale_about_the_origin() {
    let e = Vector::<f64>::E_O ^ Vector::E_INF;
    let mut rng = Pcg64::seed_from_u64(0xC6A_000B);
    for _ in 0..3000 {
        let m = random_scale(&mut rng);
        let (s, s2, x) =
            (rng.random_range(0.1..10.0), rng.random_range(0.1..10.0), random_v3(&mut rng, m));
        let d = Motor::dilator(s);
        assert_close(d.transform_point(x), x * s, tol(2.0 * m * s.max(1.0)), "dilation");
        assert!((d.norm_squared() - 1.0).abs() <= 1e-14);
        let generator = e * (0.5 * s.ln());
        assert_close_slices(&generator.exp_blade().to_array(), &d.to_array(), 1e-14, "exp");
        assert_close_slices(&d.log_blade().to_array(), &generator.to_array(), 1e-13, "log");
        assert_close_slices(&(-d).log_blade().to_array(), &generator.to_array(), 1e-13, "log -D");
        let product = (d * Motor::dilator(s2)).to_array();
        assert_close_slices(&product, &Motor::dilator(s * s2).to_array(), 1e-14, "D(a) D(b)");
    }
    // Near the identity the logarithm keeps its relative accuracy (ln_1p, exp_m1).
    for k in 4..15 {
        // 1 + eps rounds; (1 + eps) - 1 is exact (Sterbenz), so compare with what was built.
        let s = 1.0 + 10f64.powi(-k);
        let eps = s - 1.0;
        let log = Motor::dilator(s).log_blade();
        let expected = -0.5 * eps.ln_1p();
        assert!((log.e45 - expected).abs() <= 1e-12 * expected.abs(), "{eps}: {log:?}");
        let back = (e * (0.5 * eps)).exp_blade();
        assert!((back.e45 + (0.5 * eps).sinh()).abs() <= 1e-15 * eps, "{eps}: {back:?}");
    }
}

#[test]
fn rotor_exp_and_log_in_closed_form() {
    let mut rng = Pcg64::seed_from_u64(0xC6A_000C);
    for _ in 0..3000 {
        let m = random_scale(&mut rng);
        let (n, angle) = (random_unit(&mut rng), rng.random_range(-3.1..3.1));
        // -θ/2 (n I₃), n I₃ = n1 e23 - n2 e13 + n3 e12.
        let mut generator = Bivector::ZERO;
        (generator.e12, generator.e13, generator.e23) = (n.e3, -n.e2, n.e1);
        generator *= -0.5 * angle;
        let rotor = Motor::from(Rotor::from_axis_angle(n, angle));
        assert_close_slices(&generator.exp_blade().to_array(), &rotor.to_array(), 1e-15, "exp");
        assert_close_slices(&rotor.log_blade().to_array(), &generator.to_array(), 1e-13, "log");

        // About an axis through p: the generator moved by the translator, T B T̃, is still a
        // blade, and its exponential is the rotation about the moved axis.
        let p = random_v3(&mut rng, m);
        let moved = Motor::translator(p).sandwich(generator);
        let about_p = moved.exp_blade();
        let affine = DAffine3::from_translation(to_dvec3(p))
            * DAffine3::from_axis_angle(to_dvec3(n), angle)
            * DAffine3::from_translation(-to_dvec3(p));
        let x = random_v3(&mut rng, m);
        let y = affine.transform_point3(to_dvec3(x));
        let rotated = about_p.transform_point(x);
        assert_close(rotated, v3(y.x, y.y, y.z), tol(3.0 * m), "rotation about p");
        let log = about_p.log_blade().to_array();
        assert_close_slices(&log, &moved.to_array(), tol(2.0 * m), "log");
    }
}

#[test]
fn versor_inverses() {
    let mut rng = Pcg64::seed_from_u64(0xC6A_000D);
    for _ in 0..3000 {
        let m = random_scale(&mut rng);
        let (axis, angle) = (random_unit(&mut rng), rng.random_range(-PI..PI));
        let (t, s) = (random_v3(&mut rng, m), rng.random_range(0.25..4.0));
        let rotor = Rotor::from_axis_angle(axis, angle) * 3.0;
        let motor = Motor::translator(t) * Motor::from(rotor) * Motor::dilator(s);
        let one = (motor * motor.inverse().unwrap()).to_array();
        assert_close_slices(&one, &Motor::ONE.to_array(), tol(2.0 * m), "M M⁻¹");
        let one = (rotor * rotor.inverse().unwrap()).to_array();
        assert_close_slices(&one, &Rotor::ONE.to_array(), 1e-15, "R R⁻¹");
        // σ² = r² is what is left of the cancellation of terms of size |t|⁴.
        let r = rng.random_range(0.2..1.0) * m;
        let sphere = Vector::dual_sphere(t, r);
        let one = (sphere * sphere.inverse().unwrap()).to_array();
        assert_close_slices(&one, &Motor::ONE.to_array(), tol(2.0 * m), "σ σ⁻¹");
    }
    // Null vectors (points, e∞) and zero have no inverse.
    assert_eq!(Vector::point(1.0, 2.0, 3.0).inverse(), None);
    assert_eq!(Vector::<f64>::E_INF.inverse(), None);
    assert_eq!(Motor::<f64>::ZERO.inverse(), None);
    assert_eq!(Rotor::<f64>::ZERO.inverse(), None);
}

#[test]
fn meets_of_planes_and_spheres_hold_the_common_points() {
    let mut rng = Pcg64::seed_from_u64(0xC6A_000E);
    for _ in 0..200 {
        let c = random_int_v3(&mut rng, 4);
        let p = |x: f64, y: f64, z: f64| up(c + v3(x, y, z));
        // The planes x = c1 and y = c2 meet in the vertical line through c.
        let px = Quadvector::plane(p(0.0, 0.0, 0.0), p(0.0, 1.0, 0.0), p(0.0, 0.0, 1.0));
        let py = Quadvector::plane(p(0.0, 0.0, 0.0), p(1.0, 0.0, 0.0), p(0.0, 0.0, 1.0));
        let line = px & py;
        for k in -3..=3 {
            assert_eq!(line ^ p(0.0, 0.0, f64::from(k)), Quadvector::ZERO);
        }
        assert_ne!(line ^ p(1.0, 0.0, 0.0), Quadvector::ZERO);
        // The sphere of radius 3 about c meets the plane z = c3 in the circle of radius 3.
        let sphere = Quadvector::sphere(
            p(3.0, 0.0, 0.0),
            p(0.0, 3.0, 0.0),
            p(0.0, 0.0, 3.0),
            p(-3.0, 0.0, 0.0),
        );
        let pz = Quadvector::plane(p(0.0, 0.0, 0.0), p(1.0, 0.0, 0.0), p(0.0, 1.0, 0.0));
        let circle = sphere & pz;
        for q in [p(0.0, -3.0, 0.0), p(3.0, 0.0, 0.0), p(-3.0, 0.0, 0.0), p(0.0, 3.0, 0.0)] {
            assert_eq!(circle ^ q, Quadvector::ZERO);
        }
        // On the sphere but off the plane, on the plane but off the sphere.
        assert_ne!(circle ^ p(2.0, 2.0, 1.0), Quadvector::ZERO);
        assert_ne!(circle ^ p(2.0, 2.0, 0.0), Quadvector::ZERO);
        // Three planes meet in the flat point c.
        assert_eq!((line & pz).flat_point_position(), c);
    }
}

#[test]
fn a_reflected_line_holds_the_reflected_points() {
    // The sandwich maps every blade; its sign and scale do not matter for incidence.
    let mut rng = Pcg64::seed_from_u64(0xC6A_000F);
    for _ in 0..200 {
        let (a, b) = (random_int_v3(&mut rng, 4), random_int_v3(&mut rng, 4));
        if a == b {
            continue;
        }
        let n = [V3::E1, V3::E2, V3::E3][rng.random_range(0..3)];
        let plane = Vector::dual_plane(n, f64::from(rng.random_range(-3..=3)));
        let image = plane.sandwich(Trivector::line(up(a), up(b)));
        for k in -2..=2 {
            let x = a + (b - a) * f64::from(k);
            assert_eq!(image ^ plane.reflect(up(x)), Quadvector::ZERO);
        }
        let off = [cross(b - a, V3::E1), cross(b - a, V3::E2)].into_iter().find(|o| *o != V3::ZERO);
        assert_ne!(image ^ plane.reflect(up(a + off.unwrap())), Quadvector::ZERO);
    }
}
