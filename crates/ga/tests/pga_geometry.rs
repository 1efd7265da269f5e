//! `ga::pga` geometry against independent answers: glam's affine maps for rigid motions,
//! textbook vector formulas for incidences, distances and projections, power series for the
//! exponential, exact zeros for integer inputs. Random inputs come from fixed seeds.

use std::f64::consts::PI;

use ga::pga::{Line, Motor, Plane, Point, Rotor, Translator};
use glam::{DAffine3, DQuat, DVec3};
use rand::{Rng, SeedableRng};
use rand_pcg::Pcg64;

const CASES: usize = 200;
const TOL: f64 = 1e-12;

/// A seed per test (FNV-1a of its name), so adding a test changes no other test's inputs.
fn rng(name: &str) -> Pcg64 {
    let seed = name
        .bytes()
        .fold(0xcbf2_9ce4_8422_2325_u64, |h, b| (h ^ u64::from(b)).wrapping_mul(0x100_0000_01b3));
    Pcg64::seed_from_u64(seed)
}

fn vec3(rng: &mut Pcg64, r: f64) -> [f64; 3] {
    [rng.random_range(-r..r), rng.random_range(-r..r), rng.random_range(-r..r)]
}

fn int3(rng: &mut Pcg64) -> [f64; 3] {
    [-5, -5, -5].map(|lo: i32| f64::from(rng.random_range(lo..=5)))
}

fn dv(a: [f64; 3]) -> DVec3 {
    DVec3::from_array(a)
}

fn pt(v: DVec3) -> Point<f64> {
    Point::from_xyz(v.x, v.y, v.z)
}

fn close(a: &[f64], b: &[f64], tol: f64) -> bool {
    a.len() == b.len() && a.iter().zip(b).all(|(x, y)| (x - y).abs() <= tol)
}

#[track_caller]
fn assert_close(a: &[f64], b: &[f64], tol: f64) {
    assert!(close(a, b, tol), "{a:?} != {b:?} (tolerance {tol:e})");
}

/// `a` and `b` are the same projective element: `a = k b` for some `k != 0`.
#[track_caller]
fn assert_proportional(a: &[f64], b: &[f64], tol: f64) {
    let i = (0..b.len()).max_by(|&i, &j| b[i].abs().total_cmp(&b[j].abs())).unwrap();
    assert!(b[i] != 0.0, "zero element {b:?}");
    let k = a[i] / b[i];
    assert!(k != 0.0, "{a:?} is not a multiple of {b:?}");
    let scaled: Vec<f64> = b.iter().map(|x| x * k).collect();
    assert_close(a, &scaled, tol * k.abs().max(1.0));
}

fn random_motor(rng: &mut Pcg64) -> (Motor<f64>, DAffine3) {
    let axis = vec3(rng, 1.0);
    let angle = rng.random_range(-PI..PI);
    let t = vec3(rng, 5.0);
    let m = Motor::from_rotation_translation(Rotor::from_axis_angle(axis, angle), t);
    let a = DAffine3::from_rotation_translation(
        DQuat::from_axis_angle(dv(axis).normalize(), angle),
        dv(t),
    );
    (m, a)
}

fn moved(m: Motor<f64>, p: [f64; 3]) -> [f64; 3] {
    m.transform_point(Point::from_xyz_array(p)).to_xyz().unwrap()
}

#[test]
fn points_round_trip_and_ideal_points_have_no_position() {
    let p = Point::from_xyz(1.5, -2.0, 3.25);
    assert_eq!(p.to_array(), [3.25, -2.0, 1.5, 1.0]);
    assert_eq!(p.to_xyz(), Some([1.5, -2.0, 3.25]));
    assert_eq!((p * 4.0).to_xyz(), Some([1.5, -2.0, 3.25]));
    assert_eq!((p * -2.0).normalized(), p);
    let d = Point::direction(1.0, 2.0, 3.0);
    assert!(d.is_ideal());
    assert_eq!(d.to_xyz(), None);
    assert_eq!(d.xyz_weighted(), [1.0, 2.0, 3.0]);
    // A translation leaves a direction where it is, a rotation turns it.
    let t = Translator::from_translation([4.0, 5.0, 6.0]);
    assert_eq!(t.sandwich(d), d);
    assert_eq!(t.translation(), [4.0, 5.0, 6.0]);
}

#[test]
fn meet_of_two_planes_is_the_join_of_two_points_on_both() {
    // x + y + z = 3 and x = y meet in the line through (1, 1, 1) and (0, 0, 3).
    let a = Plane::from_normal_offset([1.0, 1.0, 1.0], 3.0);
    let b = Plane::from_normal_offset([1.0, -1.0, 0.0], 0.0);
    let (p, q) = (Point::from_xyz(1.0, 1.0, 1.0), Point::from_xyz(0.0, 0.0, 3.0));
    assert!(a.contains(p) && a.contains(q) && b.contains(p) && b.contains(q));
    let meet = Line::meet(a, b);
    let join = Line::through(p, q);
    assert_proportional(&meet.to_array(), &join.to_array(), 0.0);
    assert!(meet.contains(p) && meet.contains(q));
    // Parallel planes meet in an ideal line, the line at infinity of planes with their normal.
    let ideal = Line::meet(a, Plane::from_normal_offset([2.0, 2.0, 2.0], -1.0));
    assert!(ideal.is_ideal());
    assert_proportional(&ideal.moment(), &[1.0, 1.0, 1.0], 0.0);

    // Random planes: two points on both from the textbook construction (a point on the
    // line solving the two plane equations, plus the cross product of the normals).
    let mut rng = rng("meet_join");
    for _ in 0..CASES {
        let (na, nb) = (vec3(&mut rng, 1.0), vec3(&mut rng, 1.0));
        let (da, db) = (rng.random_range(-2.0..2.0), rng.random_range(-2.0..2.0));
        let (a, b) = (Plane::from_normal_offset(na, da), Plane::from_normal_offset(nb, db));
        let (na, nb) = (dv(na), dv(nb));
        let dir = na.cross(nb);
        // p = (da (nb × dir) + db (dir × na)) / |dir|² satisfies na·p = da, nb·p = db.
        let p = (da * nb.cross(dir) + db * dir.cross(na)) / dir.length_squared();
        assert!((na.dot(p) - da).abs() < 1e-9 && (nb.dot(p) - db).abs() < 1e-9);
        let q = p + dir;
        let join = Line::through(pt(p), pt(q));
        assert_proportional(&Line::meet(a, b).to_array(), &join.to_array(), 1e-9);
        assert_close(&Line::meet(a, b).direction(), &dir.to_array(), 1e-15);
    }
}

#[test]
fn join_and_plane_through_three_points_match_cross_products_exactly() {
    let mut rng = rng("join");
    for _ in 0..CASES {
        let (p, q, r) = (int3(&mut rng), int3(&mut rng), int3(&mut rng));
        let (vp, vq, vr) = (dv(p), dv(q), dv(r));
        let (pp, pq, pr) =
            (Point::from_xyz_array(p), Point::from_xyz_array(q), Point::from_xyz_array(r));
        let line = Line::through(pp, pq);
        assert_eq!(line.direction(), (vq - vp).to_array());
        assert_eq!(line.moment(), vp.cross(vq).to_array());
        assert_eq!(line, Line::from_point_direction(p, (vq - vp).to_array()));
        // The foot of the perpendicular from the origin: on the line, orthogonal to it.
        if let Some(c) = line.closest_point_to_origin() {
            assert!(line.distance_to_point(Point::from_xyz_array(c)) < 1e-14);
            assert!(dv(c).dot(vq - vp).abs() < 1e-13);
        }
        let plane = Plane::through(pp, pq, pr);
        let n = (vq - vp).cross(vr - vp);
        assert_eq!(plane.normal(), n.to_array());
        assert_eq!(plane, Plane::from_normal_point(n.to_array(), p));
        // Exact zeros: every point on its plane and line.
        assert!(plane.contains(pp) && plane.contains(pq) && plane.contains(pr));
        assert!(line.contains(pp) && line.contains(pq));
        assert_eq!(plane.signed_distance(pr), 0.0);
        assert_eq!(line.distance_to_point(pq), 0.0);
    }
}

#[test]
fn line_plane_meet_matches_the_ray_plane_formula() {
    let mut rng = rng("line_plane");
    for _ in 0..CASES {
        let (o, d) = (vec3(&mut rng, 3.0), vec3(&mut rng, 1.0));
        let (n, off) = (vec3(&mut rng, 1.0), rng.random_range(-2.0..2.0));
        let (vo, vd, vn) = (dv(o), dv(d), dv(n));
        // Ray o + t d meets n · x = off at t = (off - n · o) / (n · d).
        let t = (off - vn.dot(vo)) / vn.dot(vd);
        let want = vo + t * vd;
        let got = Line::from_point_direction(o, d)
            .meet_plane(Plane::from_normal_offset(n, off))
            .to_xyz()
            .unwrap();
        assert_close(&got, &want.to_array(), 1e-9 * want.length().max(1.0));
    }
    // Parallel: the ideal point of the line's direction, exactly.
    let line = Line::from_point_direction([0.0, 0.0, 1.0], [1.0, 2.0, 0.0]);
    let meet = line.meet_plane(Plane::from_normal_offset([0.0, 0.0, 1.0], 0.0));
    assert!(meet.is_ideal());
    assert_proportional(&meet.xyz_weighted(), &[1.0, 2.0, 0.0], 0.0);
}

#[test]
fn distances_and_angles_match_closed_forms() {
    let mut rng = rng("distances");
    for _ in 0..CASES {
        let (p, q) = (vec3(&mut rng, 4.0), vec3(&mut rng, 4.0));
        let (vp, vq) = (dv(p), dv(q));
        let (pp, pq) = (Point::from_xyz_array(p) * 3.0, Point::from_xyz_array(q) * -0.5);
        assert!((pp.distance(pq) - vp.distance(vq)).abs() < TOL * 10.0);

        let (n, off) = (vec3(&mut rng, 2.0), rng.random_range(-2.0..2.0));
        let plane = Plane::from_normal_offset(n, off);
        let want = (dv(n).dot(vp) - off) / dv(n).length();
        assert!((plane.signed_distance(pp) - want).abs() < TOL * 10.0);
        assert!((plane.normalized().normal()[0] - dv(n).normalize().x).abs() < TOL);

        let (a, d) = (vec3(&mut rng, 3.0), vec3(&mut rng, 1.0));
        let line = Line::from_point_direction(a, d) * 2.5;
        let want = (vp - dv(a)).cross(dv(d)).length() / dv(d).length();
        assert!((line.distance_to_point(pp) - want).abs() < 1e-11);

        let (b, e) = (vec3(&mut rng, 3.0), vec3(&mut rng, 1.0));
        let other = Line::from_point_direction(b, e);
        let c = dv(d).cross(dv(e));
        let want = (dv(b) - dv(a)).dot(c).abs() / c.length();
        assert!((line.distance_to_line(other) - want).abs() < 1e-10);
        let want = dv(d).angle_between(dv(e));
        assert!((line.angle(other) - want).abs() < 1e-12);

        let m = vec3(&mut rng, 1.0);
        let (pa, pb) = (Plane::from_normal_offset(n, 1.0), Plane::from_normal_offset(m, -3.0));
        assert!((pa.angle(pb) - dv(n).angle_between(dv(m))).abs() < 1e-12);
    }
    // Exact cases: parallel lines 5 apart (a 3-4-5 offset), intersecting lines, a plane angle.
    let l1 = Line::from_point_direction([1.0, 0.0, 0.0], [0.0, 0.0, 1.0]);
    let l2 = Line::from_point_direction([4.0, 4.0, 7.0], [0.0, 0.0, -2.0]);
    assert_eq!(l1.distance_to_line(l2), 5.0);
    let l3 = Line::from_point_direction([1.0, 2.0, 3.0], [1.0, 1.0, 0.0]);
    let l4 = Line::from_point_direction([1.0, 2.0, 3.0], [0.0, -1.0, 5.0]);
    assert_eq!(l3.distance_to_line(l4), 0.0);
    assert_eq!(l1.angle(l2), PI);
    let (x, y) = (Plane::new(0.0, 1.0, 0.0, 0.0), Plane::new(7.0, 0.0, 2.0, 0.0));
    assert_eq!(x.angle(y), PI / 2.0);
    assert_eq!(Point::from_xyz(1.0, 2.0, 3.0).distance(Point::from_xyz(4.0, 6.0, 3.0)), 5.0);
}

#[test]
fn projections_match_closed_forms() {
    let mut rng = rng("projections");
    for _ in 0..CASES {
        let p = dv(vec3(&mut rng, 4.0));
        let (n, off) = (dv(vec3(&mut rng, 2.0)), rng.random_range(-2.0..2.0));
        let plane = Plane::from_normal_offset(n.to_array(), off);
        let want = p - (n.dot(p) - off) / n.length_squared() * n;
        let got = pt(p).project_onto_plane(plane).to_xyz().unwrap();
        assert_close(&got, &want.to_array(), 1e-11);

        let (a, d) = (dv(vec3(&mut rng, 3.0)), dv(vec3(&mut rng, 1.0)));
        let line = Line::from_point_direction(a.to_array(), d.to_array());
        let want = a + (p - a).dot(d) / d.length_squared() * d;
        let got = pt(p).project_onto_line(line).to_xyz().unwrap();
        assert_close(&got, &want.to_array(), 1e-11);

        // The projected line: direction d minus its normal component, through the projection
        // of a (oriented like d).
        let projected = line.project_onto_plane(plane);
        let dir = d - d.dot(n) / n.length_squared() * n;
        assert_proportional(&projected.direction(), &dir.to_array(), 1e-11);
        assert!(dv(projected.direction()).dot(dir) > 0.0);
        let foot = a - (n.dot(a) - off) / n.length_squared() * n;
        assert!(projected.distance_to_point(pt(foot)) < 1e-10);
        assert!(
            plane.signed_distance(projected.meet_plane(Plane::new(1.0, 0.3, -0.2, 0.9))).abs()
                < 1e-9
        );
    }
    // Exact: (3, 4, 5) onto z = 2 is (3, 4, 2), onto the x axis (3, 0, 0).
    let p = Point::from_xyz(3.0, 4.0, 5.0);
    let z2 = Plane::from_normal_offset([0.0, 0.0, 1.0], 2.0);
    assert_eq!(p.project_onto_plane(z2).to_xyz(), Some([3.0, 4.0, 2.0]));
    let x_axis = Line::from_point_direction([0.0, 0.0, 0.0], [1.0, 0.0, 0.0]);
    assert_eq!(p.project_onto_line(x_axis).to_xyz(), Some([3.0, 0.0, 0.0]));
}

#[test]
fn motors_move_points_like_glam_affine_maps() {
    let mut rng = rng("motor_glam");
    for _ in 0..CASES {
        let (m, a) = random_motor(&mut rng);
        let p = vec3(&mut rng, 10.0);
        assert_close(&moved(m, p), &a.transform_point3(dv(p)).to_array(), TOL * 10.0);
        // In single precision, like glam's Affine3A.
        let m32 = Motor::<f32>::from_array(m.to_array().map(|x| x as f32));
        let a32 = glam::Affine3A::from_mat4(glam::DMat4::from(a).as_mat4());
        let p32 = glam::Vec3::from_array(p.map(|x| x as f32));
        let got = m32.transform_point(Point::from_xyz(p32.x, p32.y, p32.z)).to_xyz().unwrap();
        let want = a32.transform_point3(p32);
        assert!(glam::Vec3::from_array(got).abs_diff_eq(want, 2e-5 * want.length().max(1.0)));
        // Directions (ideal points) turn but do not move.
        let d = vec3(&mut rng, 1.0);
        let got = m.transform_point(Point::direction(d[0], d[1], d[2]));
        assert!(got.is_ideal());
        assert_close(&got.xyz_weighted(), &a.transform_vector3(dv(d)).to_array(), TOL);

        // Composition: a * b applies b first, like glam's product.
        let (n, b) = random_motor(&mut rng);
        assert_close(&moved(m * n, p), &(a * b).transform_point3(dv(p)).to_array(), 1e-11);
        // The inverse undoes the motion; the matrix is glam's.
        assert_close(&moved(m.inverse(), moved(m, p)), &p, 1e-11);
        let r = m.to_matrix();
        let want = a.to_cols_array_2d();
        for (i, row) in r.iter().enumerate() {
            for (j, x) in row.iter().enumerate() {
                assert!((x - want[j][i]).abs() < TOL, "matrix {r:?} != glam {want:?}");
            }
        }
    }
}

#[test]
fn transform_point_and_transform_points_are_the_sandwich() {
    let mut rng = rng("transform_points");
    for case in 0..CASES {
        // Unit motors, and scaled ones (the map then scales the weight, like the sandwich).
        let (m, _) = random_motor(&mut rng);
        let m = if case % 2 == 0 { m } else { m * rng.random_range(0.5..2.0) };
        let mut points: Vec<Point<f64>> = (0..5)
            .map(|_| Point::from_array([0; 4].map(|_| rng.random_range(-10.0..10.0))))
            .collect();
        // An ideal point (a direction) and a Euclidean one with weight 1.
        points.push(Point::direction(1.0, -2.0, 0.5));
        points.push(Point::from_xyz_array(vec3(&mut rng, 10.0)));
        // The generated sandwich, term by term, is the reference of both.
        let want: Vec<[f64; 4]> = points.iter().map(|&p| m.sandwich(p).to_array()).collect();
        let one_by_one: Vec<Point<f64>> = points.iter().map(|&p| m.transform_point(p)).collect();
        m.transform_points(&mut points);
        for ((got, single), want) in points.iter().zip(&one_by_one).zip(&want) {
            let scale = want.iter().fold(1.0_f64, |a, x| a.max(x.abs()));
            let unit = |p: &Point<f64>| p.to_array().map(|x| x / scale);
            assert_close(&unit(got), &want.map(|x| x / scale), 1e-13);
            assert_close(&unit(single), &want.map(|x| x / scale), 1e-13);
        }
    }
    // f32 takes the same path.
    let m = Motor::<f32>::from_rotation_translation(
        Rotor::from_axis_angle([0.0, 0.0, 1.0], core::f32::consts::FRAC_PI_2),
        [1.0, 2.0, 3.0],
    );
    let mut p = [Point::<f32>::from_xyz(1.0, 0.0, 0.0)];
    m.transform_points(&mut p);
    let xyz = p[0].to_xyz().unwrap();
    assert!(xyz.iter().zip([1.0, 3.0, 3.0]).all(|(a, b)| (a - b).abs() < 1e-6), "{xyz:?}");
}

#[test]
fn rotation_about_an_arbitrary_line_matches_glam() {
    let mut rng = rng("line_rotation");
    for _ in 0..CASES {
        let (c, axis) = (vec3(&mut rng, 5.0), vec3(&mut rng, 1.0));
        let angle = rng.random_range(-PI..PI);
        let line = Line::from_point_direction(c, axis) * rng.random_range(0.1..3.0);
        let m = Motor::from_line_angle(line, angle);
        let a = DAffine3::from_translation(dv(c))
            * DAffine3::from_axis_angle(dv(axis).normalize(), angle)
            * DAffine3::from_translation(-dv(c));
        let p = vec3(&mut rng, 10.0);
        assert_close(&moved(m, p), &a.transform_point3(dv(p)).to_array(), 1e-11);
        // The axis is fixed, point for point; the motor is unit.
        let on = (dv(c) + 2.0 * dv(axis)).to_array();
        assert_close(&moved(m, on), &on, 1e-11);
        let (s, i) = m.study_norm_squared();
        assert!((s - 1.0).abs() < TOL && i.abs() < TOL);
    }
    // An ideal line: a translation by the angle along its unit moment.
    let m = Motor::from_line_angle(Line::ideal([0.0, 0.0, 2.0]), 3.0);
    assert_eq!(moved(m, [1.0, 1.0, 1.0]), [1.0, 1.0, 4.0]);
}

#[test]
fn motors_act_on_planes_lines_and_motors_consistently_with_points() {
    let mut rng = rng("motor_types");
    for _ in 0..CASES {
        let (m, _) = random_motor(&mut rng);
        let (p, q, r) = (vec3(&mut rng, 3.0), vec3(&mut rng, 3.0), vec3(&mut rng, 3.0));
        let (pp, pq, pr) =
            (Point::from_xyz_array(p), Point::from_xyz_array(q), Point::from_xyz_array(r));
        let (mp, mq, mr) = (m.transform_point(pp), m.transform_point(pq), m.transform_point(pr));
        // Joins commute with rigid motions: M (P & Q) M~ = (M P M~) & (M Q M~).
        assert_close(&m.transform_line(pp & pq).to_array(), &(mp & mq).to_array(), 1e-11);
        let plane = Plane::through(pp, pq, pr);
        assert_close(
            &m.transform_plane(plane).to_array(),
            &Plane::through(mp, mq, mr).to_array(),
            1e-10,
        );
        // A motor conjugated by M moves M P as it moved P.
        let (n, _) = random_motor(&mut rng);
        let conj = m.transform_motor(n);
        assert_close(&moved(conj, moved(m, p)), &moved(m, moved(n, p)), 1e-10);
        // ... and is the product M N M~ of the generated geometric product.
        assert_close(&conj.to_array(), &(m * n * m.reverse()).to_array(), 1e-12);
    }
}

/// `exp` by its power series `sum B^k / k!`, with the generated geometric product.
fn exp_series(b: Line<f64>) -> Motor<f64> {
    let mut term = Motor::ONE;
    let mut sum = Motor::ONE;
    for k in 1..60 {
        term = term * b / f64::from(k);
        sum += term;
    }
    sum
}

fn random_line(rng: &mut Pcg64, max_angle: f64) -> Line<f64> {
    let d = dv(vec3(rng, 1.0)).normalize() * rng.random_range(0.0..max_angle);
    let m = vec3(rng, 3.0);
    Line::from_direction_moment(d.to_array(), m)
}

#[test]
fn exp_matches_its_power_series() {
    let mut rng = rng("exp_series");
    for _ in 0..CASES {
        // General bivectors (d · m != 0: screws), up to the principal range.
        let b = random_line(&mut rng, 3.0);
        assert_close(&b.exp().to_array(), &exp_series(b).to_array(), 1e-12);
        // Tiny rotations take the series branch.
        let tiny = random_line(&mut rng, 1e-5);
        assert_close(&tiny.exp().to_array(), &exp_series(tiny).to_array(), 1e-15);
    }
    // A pure translation is exactly 1 + B.
    let b = Line::ideal([1.0, -2.0, 0.5]);
    assert_eq!(b.exp().to_array(), [1.0, 1.0, -2.0, 0.5, 0.0, 0.0, 0.0, 0.0]);
}

#[test]
fn exp_and_log_are_inverse() {
    let mut rng = rng("exp_log");
    for _ in 0..CASES {
        let b = random_line(&mut rng, 3.0);
        assert_close(&b.exp().log().to_array(), &b.to_array(), 1e-10);
        let small = random_line(&mut rng, 1e-6);
        assert_close(&small.exp().log().to_array(), &small.to_array(), 1e-14);
        let (m, _) = random_motor(&mut rng);
        assert_close(&m.log().exp().to_array(), &m.to_array(), 1e-12);
        // The logarithm is the screw: exp(log(M) / 2) twice is M.
        let half = (m.log() * 0.5).exp();
        assert_close(&(half * half).to_array(), &m.to_array(), 1e-12);
    }
    // Pure translation (sin a = 0, s = 1).
    let t: Motor<f64> = Translator::from_translation([2.0, -4.0, 6.0]).into();
    assert_eq!(t.log(), Line::ideal([-1.0, 2.0, -3.0]));
    assert_eq!(t.log().exp(), t);
    // Rotation by π (s = 0) through the point (1, 0, 0) about z, and a half-angle π, where
    // M = -1 + F (sin a = 0, s = -1): the same motion as 1 - F.
    let half_turn =
        Motor::from_line_angle(Line::from_point_direction([1.0, 0.0, 0.0], [0.0, 0.0, 1.0]), PI);
    assert_close(&half_turn.log().exp().to_array(), &half_turn.to_array(), 1e-15);
    for f in [[0.0, 0.0, 0.0], [0.5, -1.0, 2.0]] {
        let m = Motor::new(-1.0, f[0], f[1], f[2], 0.0, 0.0, 0.0, 0.0);
        let l = m.log();
        assert!((l.norm() - PI).abs() < 1e-15);
        assert_close(&l.exp().to_array(), &m.to_array(), 1e-15);
    }
}

#[test]
fn normalisation_gives_unit_motors_of_the_same_motion() {
    let mut rng = rng("normalise");
    for _ in 0..CASES {
        // A unit motor scaled and perturbed off the Study condition.
        let (m, a) = random_motor(&mut rng);
        let k = rng.random_range(0.2..5.0);
        let mut c = (m * k).to_array();
        for x in &mut c[1..4] {
            *x += rng.random_range(-1e-3..1e-3);
        }
        let off = Motor::from_array(c);
        let n = off.normalized();
        let one = n * n.reverse();
        assert_close(&one.to_array(), &Motor::<f64>::ONE.to_array(), 1e-14);
        let (s, i) = n.study_norm_squared();
        assert!((s - 1.0).abs() < 1e-14 && i.abs() < 1e-14);
        // A scaled unit motor comes back as itself and moves points as before.
        assert_close(&(m * k).normalized().to_array(), &m.to_array(), 1e-14);
        let p = vec3(&mut rng, 5.0);
        assert_close(&moved(n, p), &a.transform_point3(dv(p)).to_array(), 1e-2);
    }
}

#[cfg(feature = "glam")]
#[test]
fn glam_conversions_agree() {
    use glam::{Affine3A, Quat, Vec3};
    let mut rng = rng("glam_conversions");
    for _ in 0..CASES {
        let (m, a) = random_motor(&mut rng);
        let got = DAffine3::from(m);
        assert!(got.abs_diff_eq(a, TOL), "{got:?} != {a:?}");
        let axis = dv(vec3(&mut rng, 1.0)).normalize();
        let angle = rng.random_range(-PI..PI);
        let q = DQuat::from_axis_angle(axis, angle);
        let r = Rotor::from_axis_angle(axis.to_array(), angle);
        assert_close(&Rotor::from(q).to_array(), &r.to_array(), TOL);
        assert!(DQuat::from(r).abs_diff_eq(q, TOL));
        let m32 = Motor::<f32>::from_rotation_translation(
            Rotor::from_axis_angle(axis.as_vec3().to_array(), angle as f32),
            [1.0, 2.0, 3.0],
        );
        let a32 = Affine3A::from_rotation_translation(
            Quat::from_axis_angle(axis.as_vec3(), angle as f32),
            Vec3::new(1.0, 2.0, 3.0),
        );
        assert!(Affine3A::from(m32).abs_diff_eq(a32, 1e-5));
    }
}

#[test]
fn the_matrix_of_any_motor_is_its_sandwich_on_points() {
    let mut rng = rng("matrix");
    for _ in 0..CASES {
        // Arbitrary even elements, not unit and off the Study condition: the sandwich is still
        // an affine map of the points, divided by the weight.
        let c: [f64; 8] = core::array::from_fn(|_| rng.random_range(-2.0..2.0));
        let m = Motor::from_array(c);
        let r = m.to_matrix();
        let p = vec3(&mut rng, 5.0);
        let want = moved(m, p);
        let got: Vec<f64> =
            r.iter().map(|row| row[0] * p[0] + row[1] * p[1] + row[2] * p[2] + row[3]).collect();
        assert_close(&got, &want, 1e-11 * want.iter().fold(1.0_f64, |a, x| a.max(x.abs())));
    }
}

#[test]
fn single_precision_agrees_with_double() {
    let mut rng = rng("f32");
    for _ in 0..CASES {
        let b = random_line(&mut rng, 3.0);
        let b32 = Line::<f32>::from_array(b.to_array().map(|x| x as f32));
        let m = b.exp();
        let m32 = b32.exp();
        let widened = m32.to_array().map(f64::from);
        assert_close(&widened, &m.to_array(), 1e-5);
        let back = m32.log().to_array().map(f64::from);
        assert_close(&back, &b.to_array(), 1e-4);
        let tiny = random_line(&mut rng, 1e-3);
        let tiny32 = Line::<f32>::from_array(tiny.to_array().map(|x| x as f32));
        let got = tiny32.exp().to_array().map(f64::from);
        assert_close(&got, &tiny.exp().to_array(), 1e-6);
        let back = tiny32.exp().log().to_array().map(f64::from);
        assert_close(&back, &tiny.to_array(), 1e-6);
    }
}
