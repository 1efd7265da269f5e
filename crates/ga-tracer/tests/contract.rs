//! The seam's contract, checked on every kernel and precision: `0 < t <= t_max` (a hit at
//! exactly `t_max` counts), nothing behind the origin, both faces, degenerate triangles never
//! hit, NaN and infinity give a miss and no panic, `occludes` agrees with `intersect`.

mod common;

use common::{
    cast_ray, cast_tri, label, prev_down, ray_towards, reference, rng, run, tolerance, triangle,
};
use intersect::{Intersector, Ray, Real, Triangle};
use rand::Rng;

fn hits<I: Intersector>(k: &I, tri: &Triangle<I::Real>, ray: &Ray<I::Real>, t_max: f64) -> bool {
    run(k, tri, ray, I::Real::from_f64(t_max)).is_some()
}

/// The plane z = 2, a ray from z = -1 along +z: `t = 3` exactly, in either precision.
fn t_max_is_inclusive<I: Intersector + Default>() {
    let name = label::<I>();
    let k = I::default();
    let tri = cast_tri::<I::Real>([0.0, 0.0, 2.0], [1.0, 0.0, 2.0], [0.0, 1.0, 2.0]);
    let ray = cast_ray::<I::Real>([0.25, 0.5, -1.0], [0.0, 0.0, 1.0]);
    let h = run(&k, &tri, &ray, I::Real::INFINITY).expect(&name);
    assert_eq!((h.t.to_f64(), h.u.to_f64(), h.v.to_f64()), (3.0, 0.25, 0.5), "{name}");
    assert!(hits(&k, &tri, &ray, 3.0), "{name}: a hit at exactly t_max counts");
    assert!(!hits(&k, &tri, &ray, prev_down(I::Real::from_f64(3.0)).to_f64()), "{name}");
    assert!(!hits(&k, &tri, &ray, 0.0), "{name}: t_max = 0");
    assert!(!hits(&k, &tri, &ray, -1.0), "{name}: negative t_max");
    assert!(!hits(&k, &tri, &ray, f64::NAN), "{name}: NaN t_max");
    // The same ray turned around: the triangle is behind it.
    let back = cast_ray::<I::Real>([0.25, 0.5, -1.0], [0.0, 0.0, -1.0]);
    assert!(!hits(&k, &tri, &back, f64::INFINITY), "{name}: hit behind the origin");
    // Starting on the triangle: t = 0 is not a hit, in either direction.
    for dz in [1.0, -1.0] {
        let on = cast_ray::<I::Real>([0.25, 0.25, 2.0], [0.5, 0.25, dz]);
        assert!(!hits(&k, &tri, &on, f64::INFINITY), "{name}: hit at t = 0");
    }
    // In the plane of the triangle (parallel): never a hit, even aimed across it.
    let along = cast_ray::<I::Real>([-1.0, 0.25, 2.0], [1.0, 0.0, 0.0]);
    assert!(!hits(&k, &tri, &along, f64::INFINITY), "{name}: ray in the plane");
}

/// Random hits: the hit's own `t` as `t_max` still hits with the same answer, the float below
/// does not, and a reversed ray (triangle clearly behind) never hits.
fn t_max_and_behind_on_random_rays<I: Intersector + Default>() {
    let name = label::<I>();
    let k = I::default();
    let mut rng = rng(0x6a_0001);
    let mut checked = 0;
    for _ in 0..4_000 {
        let tri: Triangle<I::Real> = triangle(&mut rng).cast();
        let ray: Ray<I::Real> = ray_towards(&mut rng, &tri.cast()).cast();
        if let Some(h) = run(&k, &tri, &ray, I::Real::INFINITY) {
            checked += 1;
            assert_eq!(run(&k, &tri, &ray, h.t), Some(h), "{name}: t_max = own t");
            assert!(run(&k, &tri, &ray, prev_down(h.t)).is_none(), "{name}: t_max below t");
        }
        let back = Ray::new(ray.origin, ray.dir.map(|x| -x));
        if reference(&tri, &back).is_some_and(|r| r.t < -1e-3) {
            assert!(!hits(&k, &tri, &back, f64::INFINITY), "{name}: behind {tri:?} {back:?}");
        }
    }
    assert!(checked > 1_000, "{name}: only {checked} hits");
}

/// Collinear, repeated and coincident vertices on an integer lattice (exactly degenerate in
/// every precision), with rays aimed at points of their segment and along it: never a hit.
/// [`ga_tracer::is_degenerate`] is checked against an exact integer cross product, on these
/// and on random (non-degenerate) lattice triangles.
fn degenerate_triangles_never_hit<I: Intersector + Default>() {
    let name = label::<I>();
    let k = I::default();
    let mut rng = rng(0x6a_0002);
    let lattice = |rng: &mut rand_pcg::Pcg64| [0; 3].map(|_| rng.random_range(-64i64..=64));
    let as_f64 = |p: [i64; 3]| p.map(|x| x as f64);
    for _ in 0..3_000 {
        let a = lattice(&mut rng);
        let step = lattice(&mut rng);
        let (i, j) = (rng.random_range(-3i64..=3), rng.random_range(-3i64..=3));
        let b = core::array::from_fn(|n| a[n] + i * step[n]);
        let c = core::array::from_fn(|n| a[n] + j * step[n]);
        let mut v = [a, b, c];
        v.rotate_left(rng.random_range(0..3));
        assert_eq!(exact_cross(v), [0; 3], "collinear by construction");
        let tri: Triangle<I::Real> = cast_tri(as_f64(v[0]), as_f64(v[1]), as_f64(v[2]));
        assert!(ga_tracer::is_degenerate(&tri), "{tri:?}");
        // Aim at a point of the segment, halfway between two lattice points (exact).
        let s = rng.random_range(-4i64..=4);
        let target: [f64; 3] = core::array::from_fn(|n| (2 * a[n] + s * step[n]) as f64 / 2.0);
        let origin = common::point(&mut rng, 100.0);
        let ray = cast_ray::<I::Real>(origin, common::sub(target, origin));
        assert!(!hits(&k, &tri, &ray, f64::INFINITY), "{name}: degenerate {tri:?} hit by {ray:?}");
        let along = cast_ray::<I::Real>(
            core::array::from_fn(|n| target[n] - 3.0 * step[n] as f64),
            as_f64(step),
        );
        assert!(!hits(&k, &tri, &along, f64::INFINITY), "{name}: {tri:?} hit by {along:?}");
        // A general lattice triangle: degenerate exactly when its cross product is zero.
        let w = [lattice(&mut rng), lattice(&mut rng), lattice(&mut rng)];
        let tri: Triangle<I::Real> = cast_tri(as_f64(w[0]), as_f64(w[1]), as_f64(w[2]));
        assert_eq!(ga_tracer::is_degenerate(&tri), exact_cross(w) == [0; 3], "{tri:?}");
    }
    // Collinear but not on a lattice: a, a + h e, a + 2 h e with e a power of two times an
    // integer vector keeps the points exactly collinear after rounding.
    for _ in 0..1_000 {
        let a = common::point(&mut rng, 1.0).map(|x| I::Real::from_f64(x).to_f64());
        let e = lattice(&mut rng).map(|x| x as f64 / 64.0);
        let tri: Triangle<I::Real> = cast_tri(a, core::array::from_fn(|n| a[n] + e[n]), a);
        let ray = cast_ray::<I::Real>(
            [0.0, 0.0, 5.0],
            common::sub(tri.cast().point(0.5, 0.0), [0.0, 0.0, 5.0]),
        );
        assert!(!hits(&k, &tri, &ray, f64::INFINITY), "{name}: repeated vertex {tri:?}");
    }
}

/// `(b - a) x (c - a)` in integers.
fn exact_cross([a, b, c]: [[i64; 3]; 3]) -> [i64; 3] {
    let (e, f) = ([b[0] - a[0], b[1] - a[1], b[2] - a[2]], [c[0] - a[0], c[1] - a[1], c[2] - a[2]]);
    [e[1] * f[2] - e[2] * f[1], e[2] * f[0] - e[0] * f[2], e[0] * f[1] - e[1] * f[0]]
}

/// NaN or infinity in any single coordinate of a vertex, the origin or the direction, and in
/// `t_max`: a miss (or, for an infinite `t_max`, whatever the finite case gives), never a
/// panic or a NaN.
fn non_finite_input_misses<I: Intersector + Default>() {
    let name = label::<I>();
    let k = I::default();
    let tri = [[0.0, 0.0, 2.0], [1.0, 0.0, 2.0], [0.0, 1.0, 2.0]];
    let ray = [[0.25, 0.25, -1.0], [0.0, 0.0, 1.0]];
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        for slot in 0..9 {
            let mut v = tri;
            v[slot / 3][slot % 3] = bad;
            let t: Triangle<I::Real> = cast_tri(v[0], v[1], v[2]);
            let r = cast_ray::<I::Real>(ray[0], ray[1]);
            assert!(!hits(&k, &t, &r, f64::INFINITY), "{name}: vertex {v:?}");
        }
        for slot in 0..6 {
            let mut r = ray;
            r[slot / 3][slot % 3] = bad;
            let t: Triangle<I::Real> = cast_tri(tri[0], tri[1], tri[2]);
            let r = cast_ray::<I::Real>(r[0], r[1]);
            assert!(!hits(&k, &t, &r, f64::INFINITY), "{name}: ray {r:?}");
        }
    }
    // Every coordinate NaN at once, and a NaN t_max with a valid hit.
    let nan = [f64::NAN; 3];
    let t: Triangle<I::Real> = cast_tri(nan, nan, nan);
    assert!(!hits(&k, &t, &cast_ray::<I::Real>(nan, nan), f64::NAN), "{name}: all NaN");
}

/// `occludes` agrees with `intersect` for random rays and every `t_max` around the hit
/// (checked inside `run`), including `t_max` exactly at and just below the hit.
fn occludes_agrees_with_intersect<I: Intersector + Default>() {
    let k = I::default();
    let mut rng = rng(0x6a_0003);
    for _ in 0..2_000 {
        let tri: Triangle<I::Real> = triangle(&mut rng).cast();
        let ray: Ray<I::Real> = ray_towards(&mut rng, &tri.cast()).cast();
        let t_max = I::Real::from_f64(rng.random_range(0.0..3.0));
        let _ = run(&k, &tri, &ray, t_max);
        if let Some(h) = run(&k, &tri, &ray, I::Real::INFINITY) {
            let _ = run(&k, &tri, &ray, h.t);
            let _ = run(&k, &tri, &ray, prev_down(h.t));
        }
    }
}

/// Both windings are hit (no backface culling) at the same `t`, with `u` and `v` swapped.
fn both_windings_hit<I: Intersector + Default>() {
    let name = label::<I>();
    let k = I::default();
    let mut rng = rng(0x6a_0004);
    let tol = tolerance::<I::Real>() * 10.0;
    let mut both = 0;
    for _ in 0..4_000 {
        let f = triangle(&mut rng);
        let ray: Ray<I::Real> = ray_towards(&mut rng, &f).cast();
        let (front, back) = (f.cast::<I::Real>(), Triangle::new(f.a, f.c, f.b).cast::<I::Real>());
        let Some(r) = reference(&front, &ray) else { continue };
        if r.margin() < 1e-3 || r.t <= 0.0 || r.cos < 0.05 {
            continue;
        }
        let h1 =
            run(&k, &front, &ray, I::Real::INFINITY).unwrap_or_else(|| panic!("{name}: {r:?}"));
        let h2 = run(&k, &back, &ray, I::Real::INFINITY).unwrap_or_else(|| panic!("{name}: {r:?}"));
        let close =
            |x: I::Real, y: I::Real, scale: f64| (x.to_f64() - y.to_f64()).abs() <= tol * scale;
        assert!(close(h1.t, h2.t, h1.t.to_f64()), "{name}: {h1:?} {h2:?}");
        assert!(close(h1.u, h2.v, 1.0) && close(h1.v, h2.u, 1.0), "{name}: {h1:?} {h2:?}");
        both += 1;
    }
    assert!(both > 500, "{name}: only {both} cases");
}

/// Rays along each axis, both directions, with the triangle in front: `t` is the exact
/// distance (every quantity is a small dyadic rational) and the barycentrics are exact.
fn axis_aligned_rays<I: Intersector + Default>() {
    let name = label::<I>();
    let k = I::default();
    for axis in 0..3 {
        for sign in [1.0, -1.0] {
            // The triangle in the plane x[axis] = 4 sign, spanning the other two axes.
            let (i, j) = ((axis + 1) % 3, (axis + 2) % 3);
            let vertex = |p: f64, q: f64| {
                let mut v = [0.0; 3];
                v[axis] = 4.0 * sign;
                v[i] = p;
                v[j] = q;
                v
            };
            let tri: Triangle<I::Real> =
                cast_tri(vertex(0.0, 0.0), vertex(2.0, 0.0), vertex(0.0, 2.0));
            let mut origin = vertex(0.5, 0.25);
            origin[axis] = -sign;
            let mut dir = [0.0; 3];
            dir[axis] = 2.0 * sign;
            let ray = cast_ray::<I::Real>(origin, dir);
            let h = run(&k, &tri, &ray, I::Real::INFINITY)
                .unwrap_or_else(|| panic!("{name}: axis {axis} sign {sign}"));
            assert_eq!(
                (h.t.to_f64(), h.u.to_f64(), h.v.to_f64()),
                (2.5, 0.25, 0.125),
                "{name}: axis {axis} sign {sign}"
            );
            // Pointing the other way along the axis: behind.
            let back = cast_ray::<I::Real>(origin, dir.map(|x| -x));
            assert!(!hits(&k, &tri, &back, f64::INFINITY), "{name}: axis {axis}");
        }
    }
}

/// Erratum E3 (unsigned plane offset): planes on either side of the world origin, with the
/// normal pointing either way and the ray origin on either side of the plane. The report's
/// `d = |a⊥|` would mirror half of these planes through the origin.
fn planes_on_both_sides_of_the_origin<I: Intersector + Default>() {
    let name = label::<I>();
    let k = I::default();
    for z in [-6.0, -2.0, 2.0, 6.0] {
        for flip in [false, true] {
            let (a, mut b, mut c) = ([-1.0, -1.0, z], [3.0, -1.0, z], [-1.0, 3.0, z]);
            if flip {
                core::mem::swap(&mut b, &mut c);
            }
            let tri: Triangle<I::Real> = cast_tri(a, b, c);
            for (oz, dz) in [(z - 3.0, 1.0), (z + 3.0, -1.0), (0.0, z.signum())] {
                let ray = cast_ray::<I::Real>([0.0, 0.0, oz], [0.0, 0.0, dz]);
                let h = run(&k, &tri, &ray, I::Real::INFINITY)
                    .unwrap_or_else(|| panic!("{name}: plane z = {z}, ray from {oz}"));
                assert_eq!(h.t.to_f64(), (z - oz).abs(), "{name}: plane z = {z}, ray from {oz}");
                // The mirror image of the plane through the origin is not hit.
                let mirror = cast_ray::<I::Real>([0.0, 0.0, -oz], [0.0, 0.0, -dz]);
                if oz == 0.0 {
                    assert!(!hits(&k, &tri, &mirror, f64::INFINITY), "{name}: z = {z} mirrored");
                }
            }
        }
    }
}

#[test]
fn t_max_is_inclusive_on_every_kernel() {
    for_each_kernel!(t_max_is_inclusive);
}

#[test]
fn t_max_and_behind_on_random_rays_on_every_kernel() {
    for_each_kernel!(t_max_and_behind_on_random_rays);
}

#[test]
fn degenerate_triangles_never_hit_on_every_kernel() {
    for_each_kernel!(degenerate_triangles_never_hit);
}

#[test]
fn non_finite_input_misses_on_every_kernel() {
    for_each_kernel!(non_finite_input_misses);
}

#[test]
fn occludes_agrees_with_intersect_on_every_kernel() {
    for_each_kernel!(occludes_agrees_with_intersect);
}

#[test]
fn both_windings_hit_on_every_kernel() {
    for_each_kernel!(both_windings_hit);
}

#[test]
fn axis_aligned_rays_on_every_kernel() {
    for_each_kernel!(axis_aligned_rays);
}

#[test]
fn planes_on_both_sides_of_the_origin_on_every_kernel() {
    for_each_kernel!(planes_on_both_sides_of_the_origin);
}
