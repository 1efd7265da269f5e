//! Degenerate triangles, non-finite inputs and extreme magnitudes: never a false hit, never
//! a panic, and scaling a scene by a power of two (exact) never changes an answer, even where
//! every product underflows or overflows.

use exact::Exact;
use intersect::{Intersector, Ray, Triangle, TriangleHit};
use rand::{Rng, SeedableRng};
use rand_pcg::Pcg64;

fn intersect(tri: &Triangle<f64>, ray: &Ray<f64>, t_max: f64) -> Option<TriangleHit<f64>> {
    let prim = Exact.prepare(tri);
    let hit = Exact.intersect(&prim, ray, &(), t_max);
    assert_eq!(Exact.occludes(&prim, ray, &(), t_max), hit.is_some());
    hit
}

#[test]
fn degenerate_triangles_are_never_hit() {
    let mut rng = Pcg64::seed_from_u64(30);
    for offset in [0.0, 1e4] {
        for _ in 0..500 {
            let a: [f64; 3] =
                core::array::from_fn(|_| offset + f64::from(rng.random_range(-64..64)) / 16.0);
            let e: [f64; 3] = core::array::from_fn(|_| f64::from(rng.random_range(-8..8)) / 4.0);
            let (s, t) = (f64::from(rng.random_range(-4..5)), f64::from(rng.random_range(-4..5)));
            let b: [f64; 3] = core::array::from_fn(|k| a[k] + s * e[k]);
            let c: [f64; 3] = core::array::from_fn(|k| a[k] + t * e[k]);
            for tri in [Triangle::new(a, b, c), Triangle::new(a, a, c), Triangle::new(a, a, a)] {
                assert!(!Exact.prepare(&tri).is_hittable(), "{tri:?}");
                // Rays through points of the segment, from everywhere.
                let target: [f64; 3] = core::array::from_fn(|k| a[k] + 0.5 * (b[k] - a[k]));
                let origin: [f64; 3] =
                    core::array::from_fn(|_| offset + rng.random_range(-8.0..8.0));
                let ray = Ray::new(origin, core::array::from_fn(|k| target[k] - origin[k]));
                assert!(intersect(&tri, &ray, f64::INFINITY).is_none());
                assert!(Exact.crossing(&tri, &ray, f64::INFINITY).is_none());
            }
        }
    }
}

#[test]
fn non_finite_inputs_and_bad_t_max_never_hit() {
    let tri = Triangle::new([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
    let ray = Ray::new([0.25, 0.25, -1.0], [0.0, 0.0, 1.0]);
    assert!(intersect(&tri, &ray, f64::INFINITY).is_some());
    for bad in [f64::NAN, -f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        for which in 0..9 {
            let mut v = tri.vertices();
            v[which / 3][which % 3] = bad;
            let t = Triangle::new(v[0], v[1], v[2]);
            assert!(!Exact.prepare(&t).is_hittable());
            assert!(intersect(&t, &ray, f64::INFINITY).is_none(), "{t:?}");
            assert!(Exact.crossing(&t, &ray, f64::INFINITY).is_none(), "{t:?}");
        }
        for which in 0..6 {
            let mut r = ray;
            if which < 3 {
                r.origin[which] = bad;
            } else {
                r.dir[which - 3] = bad;
            }
            assert!(intersect(&tri, &r, f64::INFINITY).is_none(), "{r:?}");
            assert!(intersect(&tri, &r, 10.0).is_none(), "{r:?}");
        }
    }
    for t_max in [f64::NAN, 0.0, -0.0, -1.0, f64::NEG_INFINITY, 0.5] {
        assert!(intersect(&tri, &ray, t_max).is_none(), "{t_max}");
    }
    assert!(intersect(&tri, &Ray::new(ray.origin, [0.0; 3]), f64::INFINITY).is_none());
}

/// A small scene of rays exactly through shared vertices, edge points and interior points of a
/// 4 x 4 grid, scaled by `2^k` (exact). Answers: hit triangle, t, u, v, per ray.
fn scaled_answers(k: i32) -> Vec<Option<(usize, TriangleHit<f64>)>> {
    let s = 2f64.powi(k.clamp(-1000, 1000)) * 2f64.powi(k - k.clamp(-1000, 1000));
    let v = |i: i32, j: i32| [f64::from(i) * s, f64::from(j) * s, 0.0];
    let mut mesh = Vec::new();
    for i in 0..4 {
        for j in 0..4 {
            mesh.push(Triangle::new(v(i, j), v(i + 1, j), v(i + 1, j + 1)));
            mesh.push(Triangle::new(v(i, j), v(i + 1, j + 1), v(i, j + 1)));
        }
    }
    let mut rng = Pcg64::seed_from_u64(31);
    (0..400)
        .map(|_| {
            // Targets on a 1/4 lattice, origins on a 1/16 lattice: exact differences at any scale.
            let target = [
                f64::from(rng.random_range(1..16)) / 4.0,
                f64::from(rng.random_range(1..16)) / 4.0,
                0.0,
            ];
            let origin: [f64; 3] = [
                f64::from(rng.random_range(-64..128)) / 16.0,
                f64::from(rng.random_range(-64..128)) / 16.0,
                f64::from(rng.random_range(1..64)) / 16.0,
            ];
            let (target, origin) = (target.map(|x| x * s), origin.map(|x| x * s));
            let ray = Ray::new(origin, core::array::from_fn(|k| target[k] - origin[k]));
            let hits: Vec<_> = mesh
                .iter()
                .enumerate()
                .filter_map(|(i, tri)| intersect(tri, &ray, f64::INFINITY).map(|h| (i, h)))
                .collect();
            assert!(hits.len() <= 1, "scale 2^{k}: {hits:?}");
            hits.first().copied()
        })
        .collect()
}

#[test]
fn power_of_two_scaling_changes_nothing_even_under_underflow_and_overflow() {
    let reference = scaled_answers(0);
    assert!(reference.iter().all(Option::is_some), "every ray aims inside the grid");
    // 2^-1060: every coordinate is subnormal or nearly, every product underflows to zero in
    // f64, so only the exact path can answer. 2^1000: every product overflows.
    for k in [-1060, -700, -300, 300, 700, 1000] {
        assert_eq!(scaled_answers(k), reference, "scale 2^{k}");
    }
}
