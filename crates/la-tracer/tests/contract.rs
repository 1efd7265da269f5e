//! The seam's contract, checked on every kernel and precision: `0 < t <= t_max`, degenerate
//! triangles never hit, NaN and infinity give a miss and no panic.

mod common;

use common::{label, prev_down, ray_towards, reference, rng, triangle};
use intersect::{Intersector, Ray, Real, Triangle};
use la_tracer::is_degenerate;
use rand::Rng;

fn cast_tri<T: Real>(a: [f64; 3], b: [f64; 3], c: [f64; 3]) -> Triangle<T> {
    Triangle::new(a, b, c).cast()
}

fn cast_ray<T: Real>(origin: [f64; 3], dir: [f64; 3]) -> Ray<T> {
    Ray::new(origin, dir).cast()
}

fn hit<I: Intersector>(k: &I, tri: &Triangle<I::Real>, ray: &Ray<I::Real>, t_max: f64) -> bool {
    let t_max = I::Real::from_f64(t_max);
    let got = k.intersect(&k.prepare(tri), ray, &k.prepare_ray(ray), t_max);
    if let Some(h) = got {
        assert!(h.t > I::Real::ZERO && h.t <= t_max, "{}: t = {} out of range", label::<I>(), h.t);
        assert!(h.t.is_finite() && h.u.is_finite() && h.v.is_finite(), "{}: {h:?}", label::<I>());
    }
    got.is_some()
}

/// Exactly representable case: the plane z = 2, a ray from z = -1 along +z, so t = 3 exactly.
fn t_max_is_inclusive<I: Intersector + Default>() {
    let name = label::<I>();
    let k = I::default();
    let tri = cast_tri::<I::Real>([0.0, 0.0, 2.0], [1.0, 0.0, 2.0], [0.0, 1.0, 2.0]);
    let ray = cast_ray::<I::Real>([0.25, 0.25, -1.0], [0.0, 0.0, 1.0]);
    let rd = k.prepare_ray(&ray);
    let h = k.intersect(&k.prepare(&tri), &ray, &rd, I::Real::INFINITY).expect(&name);
    assert_eq!(h.t.to_f64(), 3.0, "{name}");
    assert_eq!((h.u.to_f64(), h.v.to_f64()), (0.25, 0.25), "{name}");
    assert!(hit(&k, &tri, &ray, 3.0), "{name}: a hit at exactly t_max counts");
    assert!(!hit(&k, &tri, &ray, prev_down(I::Real::from_f64(3.0)).to_f64()), "{name}");
    assert!(!hit(&k, &tri, &ray, 0.0), "{name}: t_max = 0");
    assert!(!hit(&k, &tri, &ray, -1.0), "{name}: negative t_max");
    assert!(!hit(&k, &tri, &ray, f64::NAN), "{name}: NaN t_max");
    // Behind the origin: the same ray turned around.
    let back = cast_ray::<I::Real>([0.25, 0.25, -1.0], [0.0, 0.0, -1.0]);
    assert!(!hit(&k, &tri, &back, f64::INFINITY), "{name}: hit behind the origin");
    // Starting on the triangle: t = 0 is not a hit, in either direction.
    for dz in [1.0, -1.0] {
        let on = cast_ray::<I::Real>([0.25, 0.25, 2.0], [0.5, 0.25, dz]);
        assert!(!hit(&k, &tri, &on, f64::INFINITY), "{name}: hit at t = 0");
    }
}

/// Random hits: each one's own `t` as `t_max` still hits, the float below does not, and the
/// reversed ray never hits.
fn t_max_and_behind_on_random_rays<I: Intersector + Default>() {
    let name = label::<I>();
    let k = I::default();
    let mut rng = rng(0x5eed_0002);
    let mut checked = 0;
    for _ in 0..5_000 {
        let tri: Triangle<I::Real> = triangle(&mut rng).cast();
        let ray: Ray<I::Real> = ray_towards(&mut rng, &tri.cast()).cast();
        let prim = k.prepare(&tri);
        let rd = k.prepare_ray(&ray);
        if let Some(h) = k.intersect(&prim, &ray, &rd, I::Real::INFINITY) {
            checked += 1;
            assert_eq!(k.intersect(&prim, &ray, &rd, h.t), Some(h), "{name}: t_max = own t");
            assert!(k.intersect(&prim, &ray, &rd, prev_down(h.t)).is_none(), "{name}");
        }
        let back = Ray::new(ray.origin, ray.dir.map(|x| -x));
        if reference(&tri, &back).is_some_and(|r| r.t < -1e-3) {
            assert!(!hit(&k, &tri, &back, f64::INFINITY), "{name}: behind {tri:?} {back:?}");
        }
    }
    assert!(checked > 1_000, "{name}: only {checked} hits");
}

/// Collinear, repeated and coincident vertices on an integer lattice (exactly degenerate in
/// every precision), and rays aimed at points of their segment: never a hit. `is_degenerate`
/// is checked against an exact integer cross product.
fn degenerate_triangles_never_hit<I: Intersector + Default>() {
    let name = label::<I>();
    let k = I::default();
    let mut rng = rng(0x5eed_0003);
    let lattice = |rng: &mut rand_pcg::Pcg64| [0; 3].map(|_| rng.random_range(-64i64..=64));
    let mut degenerate = 0;
    for _ in 0..5_000 {
        let a = lattice(&mut rng);
        let step = lattice(&mut rng);
        let (i, j) = (rng.random_range(-3i64..=3), rng.random_range(-3i64..=3));
        let b = core::array::from_fn(|n| a[n] + i * step[n]);
        let c = core::array::from_fn(|n| a[n] + j * step[n]);
        // Vertex order shuffled so that every position gets the repeated vertex.
        let mut v = [a, b, c];
        v.rotate_left(rng.random_range(0..3));
        let cross = exact_cross(v);
        let as_f64 = |p: [i64; 3]| p.map(|x| x as f64);
        let tri: Triangle<I::Real> = cast_tri(as_f64(v[0]), as_f64(v[1]), as_f64(v[2]));
        assert_eq!(is_degenerate(&tri), cross == [0; 3], "{tri:?}");
        assert_eq!(cross, [0; 3], "collinear by construction");
        degenerate += 1;
        // Aim at a point of the segment, halfway between two lattice points (exact).
        let s = rng.random_range(-4i64..=4);
        let target: [f64; 3] = core::array::from_fn(|n| (2 * a[n] + s * step[n]) as f64 / 2.0);
        let origin = common::point(&mut rng, 100.0);
        let dir = core::array::from_fn(|n| target[n] - origin[n]);
        let ray: Ray<I::Real> = cast_ray(origin, dir);
        assert!(!hit(&k, &tri, &ray, f64::INFINITY), "{name}: degenerate {tri:?} hit by {ray:?}");
        // And a ray along the segment's own line.
        let along: Ray<I::Real> = cast_ray(
            core::array::from_fn(|n| target[n] - 3.0 * step[n] as f64),
            step.map(|x| x as f64),
        );
        assert!(!hit(&k, &tri, &along, f64::INFINITY), "{name}: {tri:?} hit by {along:?}");
    }
    assert_eq!(degenerate, 5_000);
}

fn exact_cross([a, b, c]: [[i64; 3]; 3]) -> [i64; 3] {
    let (e, f): ([i64; 3], [i64; 3]) =
        (core::array::from_fn(|n| b[n] - a[n]), core::array::from_fn(|n| c[n] - a[n]));
    [e[1] * f[2] - e[2] * f[1], e[2] * f[0] - e[0] * f[2], e[0] * f[1] - e[1] * f[0]]
}

/// Lattice triangles that are not degenerate are reported as such (the other half of the
/// exact test, so `is_degenerate` cannot pass by saying "yes" to everything).
#[test]
fn is_degenerate_matches_an_exact_integer_cross_product() {
    let mut rng = rng(0x5eed_0004);
    let mut flat = 0;
    for _ in 0..20_000 {
        // Small range so that exactly collinear triples happen by chance too.
        let v = [0; 3].map(|_| [0; 3].map(|_| rng.random_range(-2i64..=2)));
        let expect = exact_cross(v) == [0; 3];
        flat += u32::from(expect);
        // Scaled by a power of two, so the coordinates stay exact.
        let [a, b, c] = v.map(|p| p.map(|x| x as f64 * 0.125));
        assert_eq!(is_degenerate(&Triangle::new(a, b, c)), expect, "{v:?}");
        let t32: Triangle<f32> = Triangle::new(a, b, c).cast();
        assert_eq!(is_degenerate(&t32), expect, "{v:?}");
    }
    assert!(flat > 500 && flat < 19_000, "{flat} degenerate of 20000");
}

/// Each coordinate of the origin, the direction and the vertices in turn is replaced by NaN,
/// +inf and -inf in rays that otherwise hit: always a miss, never a panic.
fn non_finite_input_is_a_miss<I: Intersector + Default>() {
    let name = label::<I>();
    let k = I::default();
    let mut rng = rng(0x5eed_0005);
    let mut cases = 0;
    while cases < 200 {
        let tri = triangle(&mut rng);
        let ray = ray_towards(&mut rng, &tri);
        if !hit(&k, &tri.cast::<I::Real>(), &ray.cast(), f64::INFINITY) {
            continue;
        }
        cases += 1;
        for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
            for slot in 0..15 {
                let (mut tri, mut ray) = (tri, ray);
                match slot {
                    0..3 => ray.origin[slot] = bad,
                    3..6 => ray.dir[slot - 3] = bad,
                    6..9 => tri.a[slot - 6] = bad,
                    9..12 => tri.b[slot - 9] = bad,
                    _ => tri.c[slot - 12] = bad,
                }
                let (tri, ray) = (tri.cast::<I::Real>(), ray.cast::<I::Real>());
                assert!(!hit(&k, &tri, &ray, f64::INFINITY), "{name}: {tri:?} {ray:?}");
            }
        }
        // A zero direction is no ray.
        let still = Ray::new(ray.origin, [0.0; 3]).cast::<I::Real>();
        assert!(!hit(&k, &tri.cast(), &still, f64::INFINITY), "{name}: zero direction");
    }
}

/// Rays along each axis, both ways, with direction components exactly zero, against a
/// triangle across that axis: `t`, `u`, `v` are exact.
fn axis_aligned_rays<I: Intersector + Default>() {
    let name = label::<I>();
    let k = I::default();
    for axis in 0..3 {
        for sign in [1.0, -1.0] {
            // The triangle lies in the plane x[axis] = 2 sign; the other two coordinates are
            // the corners (0, 0), (4, 1), (-1, 3) in cyclic order.
            let corner = |p: [f64; 2]| {
                let mut q = [0.0; 3];
                q[axis] = 2.0 * sign;
                q[(axis + 1) % 3] = p[0];
                q[(axis + 2) % 3] = p[1];
                q
            };
            let tri =
                cast_tri::<I::Real>(corner([0.0, 0.0]), corner([4.0, 1.0]), corner([-1.0, 3.0]));
            // Aim at u = 1/4, v = 1/2: (4, 1)/4 + (-1, 3)/2 = (0.5, 1.75).
            let mut origin = corner([0.5, 1.75]);
            origin[axis] = 0.0;
            for scale in [0.5, 1.0, 8.0] {
                let mut dir = [0.0; 3];
                dir[axis] = sign * scale;
                let ray = cast_ray::<I::Real>(origin, dir);
                let h =
                    k.intersect(&k.prepare(&tri), &ray, &k.prepare_ray(&ray), I::Real::INFINITY);
                let h = h.unwrap_or_else(|| panic!("{name}: axis {axis} sign {sign} missed"));
                assert_eq!(h.t.to_f64(), 2.0 / scale, "{name}");
                assert_eq!((h.u.to_f64(), h.v.to_f64()), (0.25, 0.5), "{name}");
                // The other way: behind.
                let back = cast_ray::<I::Real>(origin, dir.map(|x| -x));
                assert!(!hit(&k, &tri, &back, f64::INFINITY), "{name}");
            }
        }
    }
}

#[test]
fn axis_aligned_rays_hit_exactly() {
    for_each_kernel!(axis_aligned_rays);
}

#[test]
fn t_max_is_inclusive_and_t_must_be_positive() {
    for_each_kernel!(t_max_is_inclusive);
}

#[test]
fn random_hits_respect_t_max_and_direction() {
    for_each_kernel!(t_max_and_behind_on_random_rays);
}

#[test]
fn degenerate_triangles_are_never_hit() {
    for_each_kernel!(degenerate_triangles_never_hit);
}

#[test]
fn nan_and_infinity_are_misses() {
    for_each_kernel!(non_finite_input_is_a_miss);
}
