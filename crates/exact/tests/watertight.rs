//! The tie rule on meshes: rays exactly through shared edges and vertices hit exactly one
//! triangle, counted by brute force over every triangle of the mesh.

mod common;

use common::q;
use exact::{Exact, Sign};
use intersect::{Intersector, Ray, Triangle, TriangleHit};
use rand::{Rng, SeedableRng};
use rand_pcg::Pcg64;

/// 8 x 8 unit squares at `offset`, in the plane z = offset.z, two triangles each, all
/// counter-clockwise seen from +z; the diagonals alternate so interior vertices have 4 or 8
/// triangles around them.
fn grid(offset: [f64; 3]) -> Vec<Triangle<f64>> {
    let v = |i: i32, j: i32| [offset[0] + f64::from(i), offset[1] + f64::from(j), offset[2]];
    let mut tris = Vec::new();
    for i in 0..8 {
        for j in 0..8 {
            let (p00, p10, p11, p01) = (v(i, j), v(i + 1, j), v(i + 1, j + 1), v(i, j + 1));
            if (i + j) % 2 == 0 {
                tris.push(Triangle::new(p00, p10, p11));
                tris.push(Triangle::new(p00, p11, p01));
            } else {
                tris.push(Triangle::new(p00, p10, p01));
                tris.push(Triangle::new(p10, p11, p01));
            }
        }
    }
    tris
}

/// Points of the grid (relative to its corner) that lie on shared edges or are shared
/// vertices: interior vertices, eighths along interior horizontal and vertical edges, and
/// eighths along every diagonal.
fn shared_points() -> Vec<[f64; 2]> {
    let mut points = Vec::new();
    for i in 0..8 {
        for j in 0..8 {
            let (x, y) = (f64::from(i), f64::from(j));
            if i > 0 && j > 0 {
                points.push([x, y]);
            }
            for k in 1..8 {
                let s = f64::from(k) / 8.0;
                if j > 0 {
                    points.push([x + s, y]); // horizontal edge
                }
                if i > 0 {
                    points.push([x, y + s]); // vertical edge
                }
                if (i + j) % 2 == 0 {
                    points.push([x + s, y + s]);
                } else {
                    points.push([x + 1.0 - s, y + s]);
                }
            }
        }
    }
    points
}

fn all_hits(mesh: &[Triangle<f64>], ray: &Ray<f64>, t_max: f64) -> Vec<(usize, TriangleHit<f64>)> {
    let exact = Exact;
    let hits: Vec<_> = mesh
        .iter()
        .enumerate()
        .filter_map(|(i, tri)| {
            exact.intersect(&exact.prepare(tri), ray, &(), t_max).map(|h| (i, h))
        })
        .collect();
    let occluders =
        mesh.iter().filter(|tri| exact.occludes(&exact.prepare(tri), ray, &(), t_max)).count();
    assert_eq!(occluders, hits.len(), "occludes disagrees with intersect for {ray:?}");
    hits
}

/// A multiple of `2^-20` in `[lo, hi)`: differences with grid points stay exact.
fn lattice(rng: &mut Pcg64, lo: f64, hi: f64) -> f64 {
    (rng.random_range(lo..hi) * 1_048_576.0).round() / 1_048_576.0
}

/// The ray from `origin` with direction exactly `target - origin`, checked to be exact.
fn exact_ray(origin: [f64; 3], target: [f64; 3]) -> Ray<f64> {
    let dir: [f64; 3] = core::array::from_fn(|k| target[k] - origin[k]);
    for k in 0..3 {
        assert_eq!(q(origin[k]) + q(dir[k]), q(target[k]), "inexact test ray");
    }
    Ray::new(origin, dir)
}

const OFFSETS: [[f64; 3]; 3] = [[0.0, 0.0, 0.0], [1e3, -1e3, 1e3], [1e4, 1e4, -1e4]];

#[test]
fn rays_exactly_through_shared_edges_and_vertices_hit_exactly_one_triangle() {
    let mut rng = Pcg64::seed_from_u64(10);
    for offset in OFFSETS {
        let mesh = grid(offset);
        for (n, [x, y]) in shared_points().into_iter().enumerate() {
            // Every other point (there are ~1,300 per grid), alternating from above and below.
            if n % 2 == 1 {
                continue;
            }
            let target = [offset[0] + x, offset[1] + y, offset[2]];
            let height = lattice(&mut rng, 0.5, 16.0) * if n % 4 == 0 { 1.0 } else { -1.0 };
            let origin = [
                offset[0] + lattice(&mut rng, -8.0, 16.0),
                offset[1] + lattice(&mut rng, -8.0, 16.0),
                offset[2] + height,
            ];
            let ray = exact_ray(origin, target);
            let hits = all_hits(&mesh, &ray, f64::INFINITY);
            assert_eq!(hits.len(), 1, "{ray:?} through {target:?}: {hits:?}");
            let (i, hit) = hits[0];
            // The exact hit is at t = 1 and at the target; both are representable, so the
            // correctly rounded answer is exact.
            assert_eq!(hit.t, 1.0);
            assert_eq!(mesh[i].point(hit.u, hit.v), target, "{hit:?}");
            // t_max is tested exactly too: t = 1 is inside (0, 1], outside (0, 1 - ulp].
            assert_eq!(all_hits(&mesh, &ray, 1.0).len(), 1);
            assert_eq!(all_hits(&mesh, &ray, f64::next_down(1.0)).len(), 0);
        }
    }
}

#[test]
fn rays_near_shared_edges_from_arbitrary_origins_hit_exactly_one_triangle() {
    // Arbitrary f64 origins: target - origin rounds, so the rays pass within an ulp or so of
    // the edges and vertices, which is where inexact kernels crack.
    let mut rng = Pcg64::seed_from_u64(11);
    for offset in OFFSETS {
        let mesh = grid(offset);
        for (n, [x, y]) in shared_points().into_iter().enumerate().filter(|(n, _)| n % 3 == 0) {
            let target = [offset[0] + x, offset[1] + y, offset[2]];
            let side = if n % 2 == 0 { 1.0 } else { -1.0 };
            let origin = [
                offset[0] + rng.random_range(-8.0..16.0),
                offset[1] + rng.random_range(-8.0..16.0),
                offset[2] + side * rng.random_range(0.01..16.0),
            ];
            let dir: [f64; 3] = core::array::from_fn(|k| target[k] - origin[k]);
            let ray = Ray::new(origin, dir);
            assert_eq!(all_hits(&mesh, &ray, f64::INFINITY).len(), 1, "{ray:?}");
        }
    }
}

#[test]
fn rays_at_interior_points_hit_exactly_one_triangle() {
    let mut rng = Pcg64::seed_from_u64(12);
    for offset in OFFSETS {
        let mesh = grid(offset);
        for _ in 0..200 {
            let target = [
                offset[0] + rng.random_range(0.001..7.999),
                offset[1] + rng.random_range(0.001..7.999),
                offset[2],
            ];
            let origin = [
                offset[0] + rng.random_range(-8.0..16.0),
                offset[1] + rng.random_range(-8.0..16.0),
                offset[2] + rng.random_range(-16.0..16.0),
            ];
            let dir: [f64; 3] = core::array::from_fn(|k| target[k] - origin[k]);
            assert_eq!(all_hits(&mesh, &Ray::new(origin, dir), f64::INFINITY).len(), 1);
        }
    }
}

/// The cube `[-1, 1]^3 + offset`, 12 triangles, all counter-clockwise seen from outside.
fn cube(offset: [f64; 3]) -> Vec<Triangle<f64>> {
    let v = |x: f64, y: f64, z: f64| [offset[0] + x, offset[1] + y, offset[2] + z];
    let mut tris = Vec::new();
    for axis in 0..3 {
        for side in [-1.0, 1.0] {
            // Corners of the face in counter-clockwise order seen from outside.
            let corner = |s: f64, t: f64| {
                let mut p = [0.0; 3];
                p[axis] = side;
                p[(axis + 1) % 3] = s;
                p[(axis + 2) % 3] = t * side;
                v(p[0], p[1], p[2])
            };
            let [p0, p1, p2, p3] =
                [corner(-1.0, -1.0), corner(1.0, -1.0), corner(1.0, 1.0), corner(-1.0, 1.0)];
            tris.push(Triangle::new(p0, p1, p2));
            tris.push(Triangle::new(p0, p2, p3));
        }
    }
    tris
}

/// The octahedron with vertices `offset +- e_k`, counter-clockwise seen from outside.
fn octahedron(offset: [f64; 3]) -> Vec<Triangle<f64>> {
    let mut tris = Vec::new();
    for sx in [-1.0, 1.0] {
        for sy in [-1.0, 1.0] {
            for sz in [-1.0, 1.0] {
                let (a, b, c) = ([sx, 0.0, 0.0], [0.0, sy, 0.0], [0.0, 0.0, sz]);
                let at = |p: [f64; 3]| core::array::from_fn(|k| offset[k] + p[k]);
                // (a, b, c) is counter-clockwise from outside when sx sy sz > 0.
                if sx * sy * sz > 0.0 {
                    tris.push(Triangle::new(at(a), at(b), at(c)));
                } else {
                    tris.push(Triangle::new(at(a), at(c), at(b)));
                }
            }
        }
    }
    tris
}

/// Checks the orientation claim of the mesh builders: every face normal points away from the
/// centre (the fan tests below do not depend on it, but a wrong mesh would be a wrong test).
fn assert_outward(mesh: &[Triangle<f64>], centre: [f64; 3]) {
    for tri in mesh {
        let inside = Ray::new(centre, [0.0; 3]);
        let side = exact::predicates::orient3d(inside.origin, tri.a, tri.b, tri.c);
        assert_eq!(side, Some(Sign::Positive), "{tri:?}");
    }
}

/// Points on the surface: vertices, eighths along edges, points inside faces.
fn surface_points(mesh: &[Triangle<f64>]) -> Vec<[f64; 3]> {
    let mut points = Vec::new();
    for tri in mesh {
        let [a, b, c] = tri.vertices();
        for k in 0..8 {
            let s = f64::from(k) / 8.0;
            points.push(core::array::from_fn(|i| a[i] + s * (b[i] - a[i])));
        }
        points.push(tri.point(0.25, 0.5));
        points.push(tri.point(0.125, 0.25));
        points.push(c);
    }
    points
}

#[test]
fn rays_from_inside_closed_meshes_hit_exactly_one_triangle() {
    let mut rng = Pcg64::seed_from_u64(13);
    for offset in [[0.0; 3], [1e3, 1e3, -1e3], [-1e4, 1e4, 1e4]] {
        for mesh in [cube(offset), octahedron(offset)] {
            assert_outward(&mesh, offset);
            for target in surface_points(&mesh) {
                // From the exact centre, from a lattice point (exact ray), and from an
                // arbitrary interior point with a rounded direction.
                let lattice_origin = offset.map(|c| c + lattice(&mut rng, -0.3, 0.3));
                let arbitrary: [f64; 3] = offset.map(|c| c + rng.random_range(-0.3..0.3));
                let rounded =
                    Ray::new(arbitrary, core::array::from_fn(|k| target[k] - arbitrary[k]));
                for ray in [exact_ray(offset, target), exact_ray(lattice_origin, target), rounded] {
                    let hits = all_hits(&mesh, &ray, f64::INFINITY);
                    assert_eq!(hits.len(), 1, "{ray:?} towards {target:?}: {hits:?}");
                }
            }
            for _ in 0..300 {
                let dir = [
                    rng.random_range(-1.0..1.0),
                    rng.random_range(-1.0..1.0),
                    rng.random_range(-1.0..1.0),
                ];
                let origin = offset.map(|c| c + rng.random_range(-0.3..0.3));
                assert_eq!(all_hits(&mesh, &Ray::new(origin, dir), f64::INFINITY).len(), 1);
            }
        }
    }
}

/// The documented winner of a tie: the triangle on the +x side of the edge as seen along the
/// ray, or on the +y side when the edge runs along x.
#[test]
fn ties_go_to_the_documented_side() {
    let exact = Exact;
    let hit = |tri: &Triangle<f64>, ray: &Ray<f64>| {
        exact.intersect(&exact.prepare(tri), ray, &(), f64::INFINITY).is_some()
    };
    for dir in [[0.0, 0.0, -1.0], [0.0, 0.0, 1.0]] {
        let origin = [0.0, 0.0, -dir[2]];
        let ray = Ray::new(origin, dir);
        // Edge along y through the origin: the +x triangle wins.
        let (p, r) = ([0.0, -1.0, 0.0], [0.0, 1.0, 0.0]);
        let (east, west) =
            (Triangle::new(p, [1.0, 0.0, 0.0], r), Triangle::new(r, [-1.0, 0.0, 0.0], p));
        assert!(hit(&east, &ray) && !hit(&west, &ray), "{dir:?}");
        // Edge along x: the +y triangle wins.
        let (p, r) = ([-1.0, 0.0, 0.0], [1.0, 0.0, 0.0]);
        let (north, south) =
            (Triangle::new(r, [0.0, 1.0, 0.0], p), Triangle::new(p, [0.0, -1.0, 0.0], r));
        assert!(hit(&north, &ray) && !hit(&south, &ray), "{dir:?}");
    }
}
