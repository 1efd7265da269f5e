//! The tie rule on two triangles sharing an edge and on a fan around a vertex, and safety at
//! coordinates near `f32::MAX`.

use super::label;
use crate::{Intersector, Ray, Real, Triangle};

/// How many of `tris` the ray from `origin` along `dir` hits, and which (indices).
fn owners<I: Intersector + Default>(
    tris: &[[[f64; 3]; 3]],
    origin: [f64; 3],
    dir: [f64; 3],
) -> Vec<usize> {
    let k = I::default();
    let ray: Ray<I::Real> = Ray::new(origin, dir).cast();
    let rd = k.prepare_ray(&ray);
    let hit = |tri: &[[f64; 3]; 3]| {
        let [a, b, c] = *tri;
        k.intersect(&k.prepare(&Triangle::new(a, b, c).cast()), &ray, &rd, I::Real::INFINITY)
    };
    (0..tris.len()).filter(|&i| hit(&tris[i]).is_some()).collect()
}

/// Steep directions with small dyadic components (exact in `f32`), downwards and upwards,
/// including the axis itself (where edges along the other axes need the rule's second term).
fn steep_directions() -> Vec<[f64; 3]> {
    let mut dirs = Vec::new();
    for dx in [-0.25, -0.125, 0.0, 0.0625, 0.25] {
        for dy in [-0.25, 0.0, 0.125, 0.1875] {
            dirs.extend([[dx, dy, -1.0], [dx, dy, 1.0]]);
        }
    }
    dirs
}

/// `p - 2 d`: exact for the dyadic points and directions used below.
fn behind(p: [f64; 3], d: [f64; 3]) -> [f64; 3] {
    core::array::from_fn(|n| p[n] - 2.0 * d[n])
}

/// The tie rule on two triangles sharing the edge from `(2, 0, 0)` to `(0, 2, 0)`: a ray
/// exactly through a point of it hits exactly one, whichever is listed first and wherever
/// each triangle's vertex list starts, and the same one in both cases.
pub fn shared_edge_has_one_owner<I: Intersector + Default>() {
    let lower = [[0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [0.0, 2.0, 0.0]];
    let upper = [[2.0, 0.0, 0.0], [2.0, 2.0, 0.0], [0.0, 2.0, 0.0]];
    let rotated = |t: [[f64; 3]; 3]| [t[1], t[2], t[0]];
    let flipped = |t: [[f64; 3]; 3]| [t[0], t[2], t[1]];
    for point in [[1.0, 1.0, 0.0], [0.5, 1.5, 0.0], [1.75, 0.25, 0.0]] {
        for dir in steep_directions() {
            let origin = behind(point, dir);
            let first = owners::<I>(&[lower, upper], origin, dir);
            assert_eq!(first.len(), 1, "{}: {point:?} {dir:?}: {first:?}", label::<I>());
            let swapped = owners::<I>(&[upper, lower], origin, dir);
            assert_eq!(swapped, [1 - first[0]], "{}: {point:?} {dir:?}", label::<I>());
            let turned = owners::<I>(&[rotated(lower), rotated(rotated(upper))], origin, dir);
            assert_eq!(turned, first, "{}: {point:?} {dir:?}", label::<I>());
            // Both wound the other way: still exactly one owner.
            let other = owners::<I>(&[flipped(lower), flipped(upper)], origin, dir);
            assert_eq!(other.len(), 1, "{}: {point:?} {dir:?}", label::<I>());
        }
    }
}

/// A ray exactly through the centre of a fan of triangles (a closed, non-planar ring with
/// edges along the axes) hits exactly one of them, for every steep direction.
pub fn fan_vertex_has_one_owner<I: Intersector + Default>() {
    let ring = [
        [1.0, 0.0, 0.25],
        [1.0, 1.0, 0.0],
        [0.0, 1.0, -0.25],
        [-1.0, 0.5, 0.5],
        [-1.0, 0.0, 0.0],
        [-0.5, -1.0, 0.125],
        [0.0, -1.0, 0.0],
        [0.75, -0.5, -0.25],
    ];
    let centre = [0.0, 0.0, 0.0];
    let fan: Vec<[[f64; 3]; 3]> =
        (0..ring.len()).map(|i| [centre, ring[i], ring[(i + 1) % ring.len()]]).collect();
    for dir in steep_directions() {
        let hits = owners::<I>(&fan, behind(centre, dir), dir);
        assert_eq!(hits.len(), 1, "{}: {dir:?}: {hits:?}", label::<I>());
    }
}

/// Coordinates at `±f32::MAX` overflow the kernel's intermediates: the result is a miss or a
/// finite hit, never NaN.
pub fn huge_coordinates_give_no_nan<I: Intersector + Default>() {
    let m = f64::from(f32::MAX);
    let tris = [
        [[-m, -m, 0.0], [m, -m, 0.0], [0.0, m, 0.0]],
        [[-m, -m, -m], [m, -m, m], [-m, m, m]],
        [[m, m, m], [-m, m, -m], [m, -m, -m]],
        [[0.0, 0.0, 0.0], [m, 0.0, 0.0], [0.0, m, 0.0]],
    ];
    let k = I::default();
    for tri in tris {
        let prim = k.prepare(&Triangle::new(tri[0], tri[1], tri[2]).cast());
        for origin in [[0.0, 0.0, 1.0], [1e30, -1e30, m], [-m, m, m], [0.5, 0.25, -m]] {
            for dir in steep_directions().into_iter().chain([[1.0, 1.0, 1.0], [m, -m, 1.0]]) {
                let ray: Ray<I::Real> = Ray::new(origin, dir).cast();
                if let Some(h) = k.intersect(&prim, &ray, &k.prepare_ray(&ray), I::Real::INFINITY) {
                    let finite = [h.t, h.u, h.v].iter().all(|x| x.is_finite());
                    assert!(finite, "{}: {tri:?} {origin:?} {dir:?}: {h:?}", label::<I>());
                }
            }
        }
    }
}
