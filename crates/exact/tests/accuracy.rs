//! Hit decisions, t, u and v against independent references: a plain f64 Moller-Trumbore
//! away from edges, and exact rationals (the plane formula and Cramer's rule, not the crate's
//! Plucker formulas) everywhere, near-grazing and near-edge rays included.

mod common;

use common::{Q, Q3, cross, dot, is_nearest, q, q3, sign, sub};
use exact::{Exact, Sign};
use intersect::{Intersector, Ray, Triangle, TriangleHit};
use num_traits::{Signed, Zero};
use rand::{Rng, SeedableRng};
use rand_pcg::Pcg64;

fn intersect(tri: &Triangle<f64>, ray: &Ray<f64>, t_max: f64) -> Option<TriangleHit<f64>> {
    let hit = Exact.intersect(&Exact.prepare(tri), ray, &(), t_max);
    assert_eq!(Exact.occludes(&Exact.prepare(tri), ray, &(), t_max), hit.is_some());
    hit
}

/// Plain f64 Moller-Trumbore: `(t, u, v)` of the line and the triangle's plane.
fn moller_trumbore(tri: &Triangle<f64>, ray: &Ray<f64>) -> (f64, f64, f64) {
    let s = |p: [f64; 3], r: [f64; 3]| [p[0] - r[0], p[1] - r[1], p[2] - r[2]];
    let x = |p: [f64; 3], r: [f64; 3]| {
        [p[1] * r[2] - p[2] * r[1], p[2] * r[0] - p[0] * r[2], p[0] * r[1] - p[1] * r[0]]
    };
    let d = |p: [f64; 3], r: [f64; 3]| p[0] * r[0] + p[1] * r[1] + p[2] * r[2];
    let (e1, e2) = (s(tri.b, tri.a), s(tri.c, tri.a));
    let p = x(ray.dir, e2);
    let inv = 1.0 / d(e1, p);
    let t0 = s(ray.origin, tri.a);
    let qv = x(t0, e1);
    (d(e2, qv) * inv, d(t0, p) * inv, d(ray.dir, qv) * inv)
}

/// The exact `t`, `u`, `v` of the line and the plane (independent formulas), or `None` if the
/// line is parallel to the plane or the triangle is degenerate.
fn exact_tuv(tri: &Triangle<f64>, ray: &Ray<f64>) -> Option<(Q, Q, Q)> {
    let (a, b, c, o, d) = (q3(tri.a), q3(tri.b), q3(tri.c), q3(ray.origin), q3(ray.dir));
    let (e1, e2) = (sub(&b, &a), sub(&c, &a));
    let n = cross(&e1, &e2);
    let nd = dot(&n, &d);
    let nn = dot(&n, &n);
    if nd.is_zero() || nn.is_zero() {
        return None;
    }
    let t = dot(&n, &sub(&a, &o)) / &nd;
    let p: Q3 = core::array::from_fn(|k| &o[k] + &t * &d[k]);
    let pa = sub(&p, &a);
    let u = dot(&cross(&pa, &e2), &n) / &nn;
    let v = dot(&cross(&e1, &pa), &n) / &nn;
    Some((t, u, v))
}

fn point(rng: &mut Pcg64, scale: f64, offset: f64) -> [f64; 3] {
    core::array::from_fn(|_| offset + rng.random_range(-scale..scale))
}

#[test]
fn away_from_edges_t_u_v_agree_with_f64_moller_trumbore() {
    let mut rng = Pcg64::seed_from_u64(20);
    for offset in [0.0, 1e3] {
        for _ in 0..2000 {
            let tri = Triangle::new(
                point(&mut rng, 1.0, offset),
                point(&mut rng, 1.0, offset),
                point(&mut rng, 1.0, offset),
            );
            let (u, v) = (rng.random_range(0.1..0.8), rng.random_range(0.1..0.8));
            if u + v > 0.9 {
                continue;
            }
            let target = tri.point(u, v);
            let origin = point(&mut rng, 5.0, offset);
            let ray = Ray::new(origin, core::array::from_fn(|k| target[k] - origin[k]));
            let (t_ref, u_ref, v_ref) = moller_trumbore(&tri, &ray);
            // Skip the nearly grazing rays, where f64 Moller-Trumbore itself is inaccurate.
            if !(u_ref > 0.05 && v_ref > 0.05 && u_ref + v_ref < 0.95 && (t_ref - 1.0).abs() < 1e-6)
            {
                continue;
            }
            let hit = intersect(&tri, &ray, f64::INFINITY).expect("interior hit");
            assert!((hit.t - t_ref).abs() <= 1e-9 * t_ref, "{hit:?} vs {t_ref}");
            assert!((hit.u - u_ref).abs() <= 1e-9 && (hit.v - v_ref).abs() <= 1e-9, "{hit:?}");
        }
    }
}

/// Random rays near the triangle's edges and vertices and near grazing: the decision must
/// match the exact closed-triangle test wherever the exact hit point is not on the boundary
/// (where the tie rule decides), `t` must match `t_max` exactly, and `t`, `u`, `v` must be
/// the exact values correctly rounded.
#[test]
fn decisions_and_values_match_exact_rationals() {
    let mut rng = Pcg64::seed_from_u64(21);
    let (mut hits, mut misses, mut boundary) = (0, 0, 0);
    for offset in [0.0, 1e4] {
        for case in 0..1200 {
            let tri = Triangle::new(
                point(&mut rng, 1.0, offset),
                point(&mut rng, 1.0, offset),
                point(&mut rng, 1.0, offset),
            );
            // Aim at a point on an edge (or vertex), just off it, or anywhere.
            let (mut u, mut v) = match case % 4 {
                0 => (rng.random_range(0.0..1.0), 0.0),
                1 => (0.0, f64::from(rng.random_range(0..=1))),
                2 => {
                    let u: f64 = rng.random_range(0.0..1.0);
                    (u, 1.0 - u)
                }
                _ => (rng.random_range(-0.2..1.0), rng.random_range(-0.2..1.0)),
            };
            if rng.random_bool(0.5) {
                u += rng.random_range(-1e-12..1e-12);
                v += rng.random_range(-1e-12..1e-12);
            }
            let target = tri.point(u, v);
            // Some origins almost in the plane of the triangle: nearly grazing rays.
            let origin = if case % 5 == 0 {
                let off = rng.random_range(-1e-9..1e-9);
                let p = tri.point(rng.random_range(-3.0..3.0), rng.random_range(-3.0..3.0));
                [p[0] + off, p[1] - off, p[2] + off]
            } else {
                point(&mut rng, 5.0, offset)
            };
            let mut dir: [f64; 3] = core::array::from_fn(|k| target[k] - origin[k]);
            if rng.random_bool(0.5) {
                let i = rng.random_range(0..3);
                dir[i] = f64::next_up(dir[i]);
            }
            let ray = Ray::new(origin, dir);
            let Some((t, u, v)) = exact_tuv(&tri, &ray) else {
                assert!(intersect(&tri, &ray, f64::INFINITY).is_none());
                continue;
            };
            let w = Q::from_integer(1.into()) - &u - &v;
            if u.is_zero() || v.is_zero() || w.is_zero() {
                boundary += 1;
                continue;
            }
            let inside = u.is_positive() && v.is_positive() && w.is_positive() && t.is_positive();
            let Some(hit) = intersect(&tri, &ray, f64::INFINITY) else {
                assert!(!inside, "missed {tri:?} {ray:?}");
                misses += 1;
                continue;
            };
            assert!(inside, "false hit {tri:?} {ray:?}");
            hits += 1;
            assert!(is_nearest(hit.t, &t), "t {} vs {t}", hit.t);
            assert!(is_nearest(hit.u, &u), "u {} vs {u}", hit.u);
            assert!(is_nearest(hit.v, &v), "v {} vs {v}", hit.v);
            // t_max is compared exactly: the nearest doubles around the exact t.
            for t_max in [hit.t, f64::next_up(hit.t), f64::next_down(hit.t)] {
                let expected = t <= q(t_max);
                assert_eq!(intersect(&tri, &ray, t_max).is_some(), expected, "t_max {t_max}");
            }
            // Front or back: the crossing sign is the sign of n . d.
            let n = cross(&sub(&q3(tri.b), &q3(tri.a)), &sub(&q3(tri.c), &q3(tri.a)));
            let nd = sign(&dot(&n, &q3(ray.dir)));
            assert_eq!(Exact.crossing(&tri, &ray, f64::INFINITY), Some(nd));
            assert_ne!(nd, Sign::Zero);
        }
    }
    assert!(
        hits > 400 && misses > 400 && boundary > 50,
        "{hits} hits, {misses} misses, {boundary} boundary"
    );
}

/// A ray whose origin lies exactly on the triangle's plane has t = 0 there: a miss, while the
/// same ray from just behind the plane hits.
#[test]
fn origin_on_the_plane_misses() {
    let tri = Triangle::new([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
    let on = Ray::new([0.25, 0.25, 0.0], [0.0, 0.0, 1.0]);
    assert!(intersect(&tri, &on, f64::INFINITY).is_none());
    let behind = Ray::new([0.25, 0.25, -f64::from_bits(1)], [0.0, 0.0, 1.0]);
    let hit = intersect(&tri, &behind, f64::INFINITY).expect("hit from a subnormal distance");
    assert_eq!(hit.t, f64::from_bits(1));
    assert_eq!((hit.u, hit.v), (0.25, 0.25));
}
