//! The seam's contract ([`Intersector`]), checked on one kernel: `0 < t <= t_max` (a hit at
//! exactly `t_max` counts), nothing behind the origin, nothing at `t = 0`, nothing in the
//! triangle's plane, both faces, degenerate triangles never hit, NaN and infinity give a miss
//! and no panic, `occludes` agrees with `intersect` everywhere.

use rand::Rng;
use rand_pcg::Pcg64;

use super::reference::{
    cast_ray, cast_tri, is_f32, point, prev_down, ray_towards, ray_with_zero_components, reference,
    rng, tolerance, triangle,
};
use super::{Guarantees, label};
use crate::vec3::sub;
use crate::{Intersector, Ray, Real, Triangle, TriangleHit, is_degenerate};

/// The kernel's whole pipeline for one ray and triangle: `prepare`, `prepare_ray`,
/// `intersect`, checking on the way that `occludes` agrees and that a hit is in range and
/// finite.
///
/// # Panics
///
/// If `occludes` disagrees with `intersect`, or a hit is out of `(0, t_max]` or not finite.
pub fn run<I: Intersector>(
    k: &I,
    tri: &Triangle<I::Real>,
    ray: &Ray<I::Real>,
    t_max: I::Real,
) -> Option<TriangleHit<I::Real>> {
    let prim = k.prepare(tri);
    let rd = k.prepare_ray(ray);
    let got = k.intersect(&prim, ray, &rd, t_max);
    assert_eq!(k.occludes(&prim, ray, &rd, t_max), got.is_some(), "{}: occludes", label::<I>());
    if let Some(h) = got {
        let name = label::<I>();
        assert!(h.t > I::Real::ZERO && h.t <= t_max, "{name}: t = {} not in (0, {t_max}]", h.t);
        let finite = h.t.is_finite() && h.u.is_finite() && h.v.is_finite();
        assert!(finite, "{name}: {h:?} not finite");
    }
    got
}

fn hits<I: Intersector>(k: &I, tri: &Triangle<I::Real>, ray: &Ray<I::Real>, t_max: f64) -> bool {
    run(k, tri, ray, I::Real::from_f64(t_max)).is_some()
}

/// The plane z = 2, a ray from z = -1 along +z: `t = 3` exactly, in either precision; then
/// `t_max` at, below and around it, the ray turned around, rays starting on the triangle and
/// a ray in its plane.
pub fn t_max_is_inclusive<I: Intersector + Default>() {
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
    for dir in [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [1.0, 1.0, 0.0]] {
        let along = cast_ray::<I::Real>([-1.0, -1.0, 2.0], dir);
        assert!(!hits(&k, &tri, &along, f64::INFINITY), "{name}: ray in the plane {dir:?}");
    }
}

/// Random hits: the hit's own `t` as `t_max` still hits with the same answer, the float below
/// does not, and a reversed ray (triangle clearly behind) never hits. Both generators of
/// rays: aimed near edges, and with zero direction components.
///
/// An exact kernel compares its exact `t` with `t_max` and reports `t` rounded to nearest,
/// so with its own `t` as `t_max` it may miss (when the exact `t` is the larger); the float
/// above its `t` always hits, the float below never.
pub fn t_max_and_behind_on_random_rays<I: Intersector + Default>(g: &Guarantees) {
    let name = label::<I>();
    let k = I::default();
    let mut rng = rng(0x6a_0001);
    let mut checked = 0;
    for n in 0..8_000 {
        let tri: Triangle<I::Real> = triangle(&mut rng).cast();
        let aim = if n % 2 == 0 { ray_towards } else { ray_with_zero_components };
        let ray: Ray<I::Real> = aim(&mut rng, &tri.cast()).cast();
        if let Some(h) = run(&k, &tri, &ray, I::Real::INFINITY) {
            checked += 1;
            let at_own_t = run(&k, &tri, &ray, h.t);
            if g.exact {
                assert!(at_own_t.is_none_or(|a| a == h), "{name}: t_max = own t");
                let above = next_up_in(h.t);
                assert_eq!(run(&k, &tri, &ray, above), Some(h), "{name}: t_max above t");
            } else {
                assert_eq!(at_own_t, Some(h), "{name}: t_max = own t");
            }
            assert!(run(&k, &tri, &ray, prev_down(h.t)).is_none(), "{name}: t_max below t");
        }
        let back = Ray::new(ray.origin, ray.dir.map(|x| -x));
        if reference(&tri, &back).is_some_and(|r| r.t < -1e-3) {
            assert!(!hits(&k, &tri, &back, f64::INFINITY), "{name}: behind {tri:?} {back:?}");
        }
    }
    assert!(checked > 2_000, "{name}: only {checked} hits");
}

/// The next representable value of `T` above a positive finite `x`.
fn next_up_in<T: Real>(x: T) -> T {
    if is_f32::<T>() {
        T::from_f64(f64::from((x.to_f64() as f32).next_up()))
    } else {
        T::from_f64(x.to_f64().next_up())
    }
}

/// `(b - a) x (c - a)` in integers.
fn exact_cross([a, b, c]: [[i64; 3]; 3]) -> [i64; 3] {
    let (e, f) = ([b[0] - a[0], b[1] - a[1], b[2] - a[2]], [c[0] - a[0], c[1] - a[1], c[2] - a[2]]);
    [e[1] * f[2] - e[2] * f[1], e[2] * f[0] - e[0] * f[2], e[0] * f[1] - e[1] * f[0]]
}

fn lattice(rng: &mut Pcg64) -> [i64; 3] {
    [0; 3].map(|_| rng.random_range(-64i64..=64))
}

/// Collinear, repeated and coincident vertices on an integer lattice (exactly degenerate in
/// every precision, as an exact integer cross product and [`is_degenerate`] agree), with rays
/// aimed at points of their segment and along it: never a hit. Then collinear triples off the
/// lattice, with a repeated vertex.
pub fn degenerate_triangles_never_hit<I: Intersector + Default>() {
    let name = label::<I>();
    let k = I::default();
    let mut rng = rng(0x6a_0002);
    let as_f64 = |p: [i64; 3]| p.map(|x| x as f64);
    for _ in 0..3_000 {
        let a = lattice(&mut rng);
        let step = lattice(&mut rng);
        let (i, j) = (rng.random_range(-3i64..=3), rng.random_range(-3i64..=3));
        let b = core::array::from_fn(|n| a[n] + i * step[n]);
        let c = core::array::from_fn(|n| a[n] + j * step[n]);
        // Vertex order shuffled so that every position gets the repeated vertex.
        let mut v = [a, b, c];
        v.rotate_left(rng.random_range(0..3));
        assert_eq!(exact_cross(v), [0; 3], "collinear by construction");
        let tri: Triangle<I::Real> = cast_tri(as_f64(v[0]), as_f64(v[1]), as_f64(v[2]));
        assert!(is_degenerate(&tri), "{tri:?}");
        // Aim at a point of the segment, halfway between two lattice points (exact).
        let s = rng.random_range(-4i64..=4);
        let target: [f64; 3] = core::array::from_fn(|n| (2 * a[n] + s * step[n]) as f64 / 2.0);
        let origin = point(&mut rng, 100.0);
        let ray = cast_ray::<I::Real>(origin, sub(target, origin));
        assert!(!hits(&k, &tri, &ray, f64::INFINITY), "{name}: degenerate {tri:?} hit by {ray:?}");
        // And a ray along the segment's own line.
        let along = cast_ray::<I::Real>(
            core::array::from_fn(|n| target[n] - 3.0 * step[n] as f64),
            as_f64(step),
        );
        assert!(!hits(&k, &tri, &along, f64::INFINITY), "{name}: {tri:?} hit by {along:?}");
    }
    // Collinear but not on a lattice: a, a + e, a with e a small dyadic vector keeps the
    // points exactly collinear after rounding.
    for _ in 0..1_000 {
        let a = point(&mut rng, 1.0).map(|x| I::Real::from_f64(x).to_f64());
        let e = lattice(&mut rng).map(|x| x as f64 / 64.0);
        let tri: Triangle<I::Real> = cast_tri(a, core::array::from_fn(|n| a[n] + e[n]), a);
        let ray =
            cast_ray::<I::Real>([0.0, 0.0, 5.0], sub(tri.cast().point(0.5, 0.0), [0.0, 0.0, 5.0]));
        assert!(!hits(&k, &tri, &ray, f64::INFINITY), "{name}: repeated vertex {tri:?}");
    }
}

/// NaN or infinity in any single coordinate of a vertex, the origin or the direction, of a
/// fixed case and of random rays that otherwise hit; every coordinate NaN at once; a zero
/// direction: a miss, never a panic or a NaN.
pub fn non_finite_input_misses<I: Intersector + Default>() {
    let name = label::<I>();
    let k = I::default();
    let tri = [[0.0, 0.0, 2.0], [1.0, 0.0, 2.0], [0.0, 1.0, 2.0]];
    let ray = [[0.25, 0.25, -1.0], [0.0, 0.0, 1.0]];
    let bad_values = [f64::NAN, f64::INFINITY, f64::NEG_INFINITY];
    for bad in bad_values {
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
    let nan = [f64::NAN; 3];
    let t: Triangle<I::Real> = cast_tri(nan, nan, nan);
    assert!(!hits(&k, &t, &cast_ray::<I::Real>(nan, nan), f64::NAN), "{name}: all NaN");
    let mut rng = rng(0x5eed_0005);
    let mut cases = 0;
    while cases < 200 {
        let tri = triangle(&mut rng);
        let ray = ray_with_zero_components(&mut rng, &tri);
        if !hits(&k, &tri.cast::<I::Real>(), &ray.cast(), f64::INFINITY) {
            continue;
        }
        cases += 1;
        for bad in bad_values {
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
                assert!(!hits(&k, &tri, &ray, f64::INFINITY), "{name}: {tri:?} {ray:?}");
            }
        }
        // A zero direction is no ray.
        let still = Ray::new(ray.origin, [0.0; 3]).cast::<I::Real>();
        assert!(!hits(&k, &tri.cast(), &still, f64::INFINITY), "{name}: zero direction");
    }
}

/// `occludes` agrees with `intersect` for random rays and `t_max` drawn at random, at the hit
/// and just below it (checked inside [`run`]).
pub fn occludes_agrees_with_intersect<I: Intersector + Default>() {
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
pub fn both_windings_hit<I: Intersector + Default>() {
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

/// The point of the plane `x[axis] = c` whose other two coordinates, in cyclic order
/// (`axis + 1`, `axis + 2`), are `p`.
fn across_axis(axis: usize, c: f64, p: [f64; 2]) -> [f64; 3] {
    let mut q = [0.0; 3];
    q[axis] = c;
    q[(axis + 1) % 3] = p[0];
    q[(axis + 2) % 3] = p[1];
    q
}

/// Plane offset, corners, aimed point, expected `(u, v)`, ray origin along the axis.
type AxisCase = (f64, [[f64; 2]; 3], [f64; 2], (f64, f64), f64);

/// A right triangle with legs along the other two axes: every back end's `t`, `u` and `v` are
/// exact on it.
const RIGHT: AxisCase =
    (4.0, [[0.0, 0.0], [2.0, 0.0], [0.0, 2.0]], [0.5, 0.25], (0.25, 0.125), -1.0);

/// A skewed triangle: `t` is exact, `u` and `v` are small dyadic rationals that a kernel
/// solving in the ray's own frame gets exactly, and one with a precomputed reciprocal frame
/// to its rounding.
const SKEWED: AxisCase =
    (2.0, [[0.0, 0.0], [4.0, 1.0], [-1.0, 3.0]], [0.5, 1.75], (0.25, 0.5), 0.0);

/// Rays along each axis, both ways, direction components exactly zero, against `case`'s
/// triangle across that axis, with directions of several lengths: `t` is exact, `u` and `v`
/// within `uv_error` of the exact values, and the ray turned around misses.
fn axis_aligned<I: Intersector + Default>(case: AxisCase, uv_error: f64) {
    let name = label::<I>();
    let k = I::default();
    let (offset, corners, aim, uv, start) = case;
    for axis in 0..3 {
        for sign in [1.0, -1.0] {
            let [a, b, c] = corners.map(|p| across_axis(axis, offset * sign, p));
            let tri = cast_tri::<I::Real>(a, b, c);
            let origin = across_axis(axis, start * sign, aim);
            for length in [0.5, 1.0, 2.0, 8.0] {
                let mut dir = [0.0; 3];
                dir[axis] = sign * length;
                let ray = cast_ray::<I::Real>(origin, dir);
                let h = run(&k, &tri, &ray, I::Real::INFINITY)
                    .unwrap_or_else(|| panic!("{name}: axis {axis} sign {sign} missed"));
                assert_eq!(h.t.to_f64(), (offset - start) / length, "{name}: axis {axis}");
                let (du, dv) = ((h.u.to_f64() - uv.0).abs(), (h.v.to_f64() - uv.1).abs());
                assert!(du.max(dv) <= uv_error, "{name}: axis {axis}: {h:?}, want {uv:?}");
                let back = cast_ray::<I::Real>(origin, dir.map(|x| -x));
                assert!(!hits(&k, &tri, &back, f64::INFINITY), "{name}: axis {axis} behind");
            }
        }
    }
}

/// Rays along each axis, both ways, direction components exactly zero, with directions of
/// several lengths, and the same rays turned around (a miss): exact `t`, `u`, `v` on a right
/// triangle; exact `t` and `u`, `v` to [`tolerance`] on a skewed one.
pub fn axis_aligned_rays<I: Intersector + Default>() {
    axis_aligned::<I>(RIGHT, 0.0);
    axis_aligned::<I>(SKEWED, tolerance::<I::Real>());
}

/// A stronger claim than [`axis_aligned_rays`], for kernels that solve in the ray's frame
/// (the `la` back ends): `u` and `v` exact on the skewed triangle too. Not part of
/// [`check_all`](super::check_all); such a back end's tests call it beside it.
pub fn axis_aligned_rays_are_exact_on_skewed_triangles<I: Intersector + Default>() {
    axis_aligned::<I>(SKEWED, 0.0);
}

/// Planes on either side of the world origin, the normal either way, the ray origin on either
/// side of the plane and at the world origin (erratum E3 of the GA report: an unsigned plane
/// offset mirrors half of these planes through the origin): exact `t`, and the mirror image
/// of the plane is not hit.
pub fn planes_on_both_sides_of_the_origin<I: Intersector + Default>() {
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
                if oz == 0.0 {
                    let mirror = cast_ray::<I::Real>([0.0; 3], [0.0, 0.0, -dz]);
                    assert!(!hits(&k, &tri, &mirror, f64::INFINITY), "{name}: z = {z} mirrored");
                }
            }
        }
    }
}
