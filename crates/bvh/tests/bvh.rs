//! The BVH must change nothing but speed: closest-hit and any-hit queries equal a plain loop
//! over the triangles, in f32 and f64, on random soups, on scenes full of exact ties, on
//! inputs that defeat the SAH, and on the real meshes; and the tree's invariants hold.

use std::marker::PhantomData;
use std::path::Path;

use bvh::accel::Accel;
use bvh::{Aabb, Child, MAX_DEPTH, MAX_LEAF, WIDTH};
use intersect::{Algebra, Guarantees, Hit, Intersector, Method, Ray, Real, Triangle, TriangleHit};
use rand::{Rng, SeedableRng};
use rand_pcg::Pcg64;
use scene::Mesh;

/// Plain Moller-Trumbore in precision `T`, written for these tests only.
struct Mt<T>(PhantomData<T>);

fn mt<T>() -> Mt<T> {
    Mt(PhantomData)
}

fn sub<T: Real>(a: [T; 3], b: [T; 3]) -> [T; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
fn dot<T: Real>(a: [T; 3], b: [T; 3]) -> T {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
fn cross<T: Real>(a: [T; 3], b: [T; 3]) -> [T; 3] {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

/// Moller-Trumbore; degenerate triangles are never hit (for them the determinant is rounding
/// noise, and so would be `t`).
fn moller_trumbore<T: Real>(p: &Triangle<T>, ray: &Ray<T>, t_max: T) -> Option<TriangleHit<T>> {
    if intersect::is_degenerate(p) {
        return None;
    }
    let (e1, e2) = (sub(p.b, p.a), sub(p.c, p.a));
    let pv = cross(ray.dir, e2);
    let det = dot(e1, pv);
    if det == T::ZERO || !det.is_finite() {
        return None;
    }
    let inv = T::ONE / det;
    let s = sub(ray.origin, p.a);
    let u = dot(s, pv) * inv;
    // Written so that NaN fails every test.
    if !(u >= T::ZERO && u <= T::ONE) {
        return None;
    }
    let q = cross(s, e1);
    let v = dot(ray.dir, q) * inv;
    if !(v >= T::ZERO && u + v <= T::ONE) {
        return None;
    }
    let t = dot(e2, q) * inv;
    (t > T::ZERO && t <= t_max).then_some(TriangleHit { t, u, v })
}

impl<T: Real> Intersector for Mt<T> {
    type Real = T;
    type Prim = Triangle<T>;
    type RayData = ();
    type Block = ();
    const NAME: &'static str = "test-mt";
    const ALGEBRA: Algebra = Algebra::La;
    const METHOD: Method = Method::MollerTrumbore;
    const GUARANTEES: Guarantees = Guarantees { watertight: false, exact: false };
    const VARIANT: Option<&'static str> = None;

    fn prepare(&self, tri: &Triangle<T>) -> Triangle<T> {
        *tri
    }
    fn prepare_ray(&self, _ray: &Ray<T>) {}
    fn intersect(&self, p: &Triangle<T>, ray: &Ray<T>, _: &(), t_max: T) -> Option<TriangleHit<T>> {
        moller_trumbore(p, ray, t_max)
    }
}

/// The oracle: every triangle of the original slice, in order, nearest kept, ties to the
/// lower index. Independent of the Accel's storage.
fn reference<T: Real>(tris: &[Triangle<T>], ray: &Ray<T>) -> Option<Hit<T>> {
    reference_between(tris, ray, T::ZERO, T::INFINITY)
}

/// The oracle of the segment `t_min <= t <= t_max`.
fn reference_between<T: Real>(
    tris: &[Triangle<T>],
    ray: &Ray<T>,
    t_min: T,
    t_max: T,
) -> Option<Hit<T>> {
    let mut best: Option<Hit<T>> = None;
    for (i, tri) in tris.iter().enumerate() {
        if let Some(h) = moller_trumbore(tri, ray, t_max).filter(|h| h.t >= t_min) {
            let hit = Hit::new(i as u32, h);
            if best.is_none_or(|b| hit.t < b.t) {
                best = Some(hit);
            }
        }
    }
    best
}

/// Checks every query on `ray` against the oracle; returns whether the ray hit something.
fn check_ray<T: Real>(accel: &Accel<Mt<T>>, tris: &[Triangle<T>], ray: &Ray<T>) -> bool {
    let expected = reference(tris, ray);
    let got = accel.closest_hit(ray);
    assert_eq!(got, expected, "closest hit differs from the oracle for {ray:?}");
    assert_eq!(accel.closest_hit_brute_force(ray), expected, "brute force, {ray:?}");
    let inf = T::INFINITY;
    assert_eq!(accel.any_hit(ray, inf), expected.is_some(), "any hit, {ray:?}");
    assert_eq!(accel.any_hit_brute_force(ray, inf), expected.is_some());
    if let Some(h) = expected {
        // The limit exactly at the hit includes it; just below excludes the nearest hit (and
        // every other one unless some other triangle is hit at the same distance).
        assert!(accel.any_hit(ray, h.t), "any hit at t_max = t, {ray:?}");
        assert_eq!(accel.closest_hit_within(ray, h.t), Some(h));
        let below = h.t * T::from_f64(0.999);
        assert_eq!(accel.any_hit(ray, below), accel.any_hit_brute_force(ray, below));
        assert!(!accel.any_hit(ray, below), "{ray:?}");
        assert_eq!(accel.closest_hit_within(ray, below), None);
        let beyond = h.t * T::from_f64(1.5);
        assert_eq!(accel.closest_hit_within(ray, beyond), Some(h));
        // Segments: from the hit on includes it; from just past it, the next hit (the first
        // of a ray that goes on through the mesh), as the oracle finds it.
        assert_eq!(accel.closest_hit_between(ray, h.t, inf), Some(h), "{ray:?}");
        assert!(accel.any_hit_between(ray, h.t, inf));
        let past = h.t * T::from_f64(1.0001);
        let next = reference_between(tris, ray, past, inf);
        assert_eq!(accel.closest_hit_between(ray, past, inf), next, "{ray:?}");
        assert_eq!(accel.any_hit_between(ray, past, inf), next.is_some(), "{ray:?}");
        // The triangle any-hit names is one the ray hits within the segment.
        let found = accel.any_hit_triangle(ray, past, inf);
        assert_eq!(found.is_some(), next.is_some(), "{ray:?}");
        if let Some(i) = found {
            let h = moller_trumbore(&tris[i as usize], ray, inf).expect("a hit triangle");
            assert!(h.t >= past, "{ray:?}");
        }
        assert!(accel.any_hit_triangle(ray, T::ZERO, inf).is_some());
        if let Some(n) = next {
            // A segment that ends before the next hit holds nothing.
            let short = past + (n.t - past) * T::from_f64(0.5);
            assert_eq!(accel.closest_hit_between(ray, past, short), None);
            assert!(!accel.any_hit_between(ray, past, short));
        }
        // An empty or NaN segment holds nothing; t_min <= 0 is the plain query.
        assert_eq!(accel.closest_hit_between(ray, beyond, h.t), None);
        assert!(!accel.any_hit_between(ray, T::from_f64(f64::NAN), inf));
        assert_eq!(accel.closest_hit_between(ray, -T::ONE, inf), Some(h));
    }
    expected.is_some()
}

/// Tree invariants: slots form a permutation covered by exactly one leaf each, every
/// triangle's box lies in its leaf's box, every node's children lie in the box its parent holds
/// for it, every node is reached once from the root, depth and leaf size bounds.
fn check_invariants<T: Real>(accel: &Accel<Mt<T>>, tris: &[Triangle<T>]) {
    let bvh = accel.bvh();
    let n = tris.len();
    let mut sorted = bvh.order().to_vec();
    sorted.sort_unstable();
    assert_eq!(sorted, (0..n as u32).collect::<Vec<_>>(), "order is a permutation");
    if n == 0 {
        assert_eq!(bvh.node_count(), 0);
        return;
    }
    let mut covered = vec![0u32; n];
    let mut reached = vec![0u32; bvh.node_count()];
    let mut leaves = 0;
    let mut max_depth = 0;
    // (node, depth, the box its parent holds for it)
    let mut stack = vec![(0usize, 1usize, bvh.node_bounds(0))];
    while let Some((i, depth, parent_box)) = stack.pop() {
        reached[i] += 1;
        max_depth = max_depth.max(depth);
        let children = bvh.children(i);
        assert!((1..=WIDTH).contains(&children.len()));
        assert!(parent_box.contains(&bvh.node_bounds(i)), "node outside its parent's box");
        for child in children {
            match child {
                Child::Leaf { slots, bounds } => {
                    leaves += 1;
                    assert!(!slots.is_empty() && slots.len() <= MAX_LEAF);
                    for slot in slots {
                        covered[slot] += 1;
                        let tri = &tris[bvh.order()[slot] as usize];
                        assert!(bounds.contains(&Aabb::of_triangle(tri)), "triangle outside leaf");
                    }
                }
                Child::Node { index, bounds } => {
                    assert!(index > i, "depth-first layout: children after their parent");
                    stack.push((index, depth + 1, bounds));
                }
            }
        }
    }
    assert!(covered.iter().all(|&c| c == 1), "each slot in exactly one leaf");
    assert!(reached.iter().all(|&c| c == 1), "every node reached once from the root");
    assert_eq!(bvh.leaf_count(), leaves);
    assert_eq!(bvh.depth(), max_depth);
    assert!(max_depth <= MAX_DEPTH);
    let stats = accel.stats();
    assert_eq!((stats.triangles, stats.nodes, stats.leaves), (n, bvh.node_count(), leaves));
    assert!(stats.bytes_per_triangle() > 0.0);
}

fn point(rng: &mut Pcg64, lo: f64, hi: f64) -> [f64; 3] {
    [rng.random_range(lo..hi), rng.random_range(lo..hi), rng.random_range(lo..hi)]
}

/// A soup: small and large triangles, slivers, degenerate ones (repeated vertex, collinear),
/// exact duplicates and axis-aligned ones.
fn soup(rng: &mut Pcg64, n: usize) -> Vec<Triangle<f64>> {
    let mut tris = Vec::with_capacity(n);
    while tris.len() < n {
        let c = point(rng, -1.0, 1.0);
        let s = if rng.random_bool(0.05) { 1.0 } else { 0.08 };
        let mut corner = || core::array::from_fn(|k| c[k] + rng.random_range(-s..s));
        let (a, b, mut cc) = (corner(), corner(), corner());
        // On a 1/16 grid, so that collinear stays exactly collinear in f32.
        let g = |x: f64| (x * 16.0).round() / 16.0;
        match rng.random_range(0..10) {
            0 => cc = b, // repeated vertex
            1 => {
                let (a, b) = (a.map(g), b.map(g));
                let c = core::array::from_fn(|k| 2.0 * b[k] - a[k]);
                tris.push(Triangle::new(a, b, c)); // collinear
                continue;
            }
            2 => {
                // In the plane x = a.x, on the grid: exact coordinates, shared planes.
                let (a, b, cc) = (a.map(g), b.map(g), cc.map(g));
                tris.push(Triangle::new(a, [a[0], b[1], b[2]], [a[0], cc[1], cc[2]]));
                continue;
            }
            _ => {}
        }
        tris.push(Triangle::new(a, b, cc));
        if rng.random_bool(0.05) {
            tris.push(Triangle::new(a, b, cc)); // exact duplicate: a tie on every hit
        }
    }
    tris.truncate(n);
    tris
}

/// Rays from outside and inside, aimed at the soup, some along axes (zero direction
/// components, origins on grid planes).
fn rays(rng: &mut Pcg64, count: usize, tris: &[Triangle<f64>]) -> Vec<Ray<f64>> {
    let bounds = bounds_of(tris);
    (0..count)
        .map(|i| {
            // Half the targets inside a triangle, half anywhere in the soup's box.
            let target: [f64; 3] = if i % 2 == 0 {
                let t = &tris[rng.random_range(0..tris.len())];
                let (u, v) = (rng.random_range(0.0..1.0), rng.random_range(0.0..1.0));
                let (u, v) = if u + v > 1.0 { (1.0 - u, 1.0 - v) } else { (u, v) };
                t.point(u, v)
            } else {
                core::array::from_fn(|k| rng.random_range(bounds.min[k]..=bounds.max[k]))
            };
            match i % 5 {
                0 | 1 => {
                    let o = point(rng, -4.0, 4.0);
                    Ray::new(o, sub(target, o))
                }
                2 => {
                    let o = point(rng, -0.5, 0.5);
                    Ray::new(o, sub(target, o))
                }
                3 => {
                    // Axis-aligned from far away, origin on the 1/16 grid.
                    let axis = rng.random_range(0..3);
                    let sign = if rng.random_bool(0.5) { 1.0 } else { -1.0 };
                    let mut o = target.map(|x| (x * 16.0).round() / 16.0);
                    o[axis] = -4.0 * sign;
                    let mut d = [0.0; 3];
                    d[axis] = sign;
                    Ray::new(o, d)
                }
                _ => {
                    // One zero component, in a plane of the grid.
                    let o = point(rng, -4.0, 4.0);
                    let mut d = sub(target, o);
                    let axis = rng.random_range(0..3);
                    d[axis] = if rng.random_bool(0.5) { 0.0 } else { -0.0 };
                    let mut o = o;
                    o[axis] = (target[axis] * 16.0).round() / 16.0;
                    Ray::new(o, d)
                }
            }
        })
        .collect()
}

fn bounds_of(tris: &[Triangle<f64>]) -> Aabb<f64> {
    tris.iter().fold(Aabb::empty(), |b, t| b.union(&Aabb::of_triangle(t)))
}

fn check_soup<T: Real>(tris64: &[Triangle<f64>], rays64: &[Ray<f64>]) -> usize {
    let tris: Vec<Triangle<T>> = tris64.iter().map(Triangle::cast).collect();
    let accel = Accel::build(mt::<T>(), &tris);
    check_invariants(&accel, &tris);
    rays64.iter().filter(|r| check_ray(&accel, &tris, &r.cast())).count()
}

#[test]
fn random_soups_match_the_oracle_in_f64_and_f32() {
    let mut rng = Pcg64::seed_from_u64(7);
    for (n, ray_count) in [(1, 200), (2, 200), (9, 300), (100, 500), (3000, 1500)] {
        let tris = soup(&mut rng, n);
        let rays = rays(&mut rng, ray_count, &tris);
        let hits64 = check_soup::<f64>(&tris, &rays);
        let hits32 = check_soup::<f32>(&tris, &rays);
        // The test must be able to fail: many rays are aimed at triangles.
        eprintln!("{n} triangles: {hits64} and {hits32} hits of {ray_count} rays");
        assert!(hits64 > ray_count / 10 && hits32 > ray_count / 10, "{hits64} {hits32}");
    }
}

/// The closed surface of a box of `nx x ny x nz` unit cells on the integer grid, each face of
/// a cell split into two triangles.
fn grid_box(nx: i32, ny: i32, nz: i32) -> Vec<Triangle<f64>> {
    let mut tris = Vec::new();
    let mut quad = |p: [f64; 3], u: [f64; 3], v: [f64; 3]| {
        let at = |a: f64, b: f64| core::array::from_fn(|k| p[k] + a * u[k] + b * v[k]);
        tris.push(Triangle::new(at(0.0, 0.0), at(1.0, 0.0), at(1.0, 1.0)));
        tris.push(Triangle::new(at(0.0, 0.0), at(1.0, 1.0), at(0.0, 1.0)));
    };
    for i in 0..nx {
        for j in 0..ny {
            for z in [0.0, f64::from(nz)] {
                quad([f64::from(i), f64::from(j), z], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
            }
        }
        for k in 0..nz {
            for y in [0.0, f64::from(ny)] {
                quad([f64::from(i), y, f64::from(k)], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]);
            }
        }
    }
    for j in 0..ny {
        for k in 0..nz {
            for x in [0.0, f64::from(nx)] {
                quad([x, f64::from(j), f64::from(k)], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]);
            }
        }
    }
    tris
}

/// A closed surface on an integer grid (a box of 8 x 6 x 4 unit cells) hit exactly at
/// vertices and edges: every hit there is a tie.
#[test]
fn exact_ties_on_shared_edges_and_vertices() {
    let (nx, ny, nz) = (8, 6, 4);
    let tris = grid_box(nx, ny, nz);
    let accel = Accel::build(mt::<f64>(), &tris);
    check_invariants(&accel, &tris);
    let accel32 = Accel::build(mt::<f32>(), &tris.iter().map(Triangle::cast).collect::<Vec<_>>());
    let tris32: Vec<Triangle<f32>> = tris.iter().map(Triangle::cast).collect();
    let mut rng = Pcg64::seed_from_u64(11);
    let mut hits = 0;
    for _ in 0..3000 {
        // Targets on grid vertices and half-grid edge points, origins anywhere or on grid.
        let target = [
            f64::from(rng.random_range(0..=2 * nx)) * 0.5,
            f64::from(rng.random_range(0..=2 * ny)) * 0.5,
            f64::from(rng.random_range(0..=2 * nz)) * 0.5,
        ];
        let origin = if rng.random_bool(0.5) {
            point(&mut rng, -10.0, 20.0)
        } else {
            [rng.random_range(-3..12), rng.random_range(-3..10), rng.random_range(-3..8)]
                .map(f64::from)
        };
        let ray = Ray::new(origin, sub(target, origin));
        if ray.dir == [0.0; 3] {
            continue;
        }
        hits += usize::from(check_ray(&accel, &tris, &ray));
        check_ray(&accel32, &tris32, &ray.cast());
    }
    assert!(hits > 2000, "{hits}");
}

#[test]
fn identical_triangles_report_the_lowest_index() {
    let t = Triangle::new([0.0, 0.0, 1.0], [1.0, 0.0, 1.0], [0.0, 1.0, 1.0]);
    let other = Triangle::new([5.0, 5.0, 5.0], [6.0, 5.0, 5.0], [5.0, 6.0, 5.0]);
    let mut tris = vec![other; 37];
    tris.extend(vec![t; 1000]);
    let accel = Accel::build(mt::<f64>(), &tris);
    check_invariants(&accel, &tris);
    let hit = accel.closest_hit(&Ray::new([0.25, 0.25, 0.0], [0.0, 0.0, 1.0])).unwrap();
    assert_eq!((hit.prim, hit.t), (37, 1.0));
}

/// Triangles whose centroids form a geometric progression: SAH bins on a uniform grid would
/// peel them off one or two at a time, a tree as deep as the input is long. The depth guard
/// must keep the depth under MAX_DEPTH, and queries must stay exact.
#[test]
fn depth_stays_bounded_when_sah_degenerates() {
    let tris: Vec<Triangle<f64>> = (0..1500)
        .map(|k| {
            let x = 1.2f64.powi(k);
            Triangle::new([x, 0.0, 0.0], [x * 1.1, 0.0, 0.0], [x, x * 0.1, 1.0])
        })
        .collect();
    let accel = Accel::build(mt::<f64>(), &tris);
    check_invariants(&accel, &tris);
    eprintln!("depth {}", accel.stats().depth);
    assert!(accel.stats().depth <= MAX_DEPTH);
    let mut rng = Pcg64::seed_from_u64(3);
    let mut hits = 0;
    for k in (0..1500).step_by(7) {
        let x = 1.2f64.powi(k);
        let target = [x * rng.random_range(1.0..1.05), x * 0.01, 0.1];
        let origin = [target[0], target[1], -1.0];
        hits += usize::from(check_ray(&accel, &tris, &Ray::new(origin, [0.0, 0.0, 1.0])));
    }
    assert_eq!(hits, 215, "every ray is aimed inside a triangle");
}

#[test]
fn empty_scene_never_hits() {
    let accel = Accel::build(mt::<f64>(), &[]);
    check_invariants(&accel, &[]);
    let ray = Ray::new([0.0; 3], [0.0, 0.0, 1.0]);
    assert_eq!(accel.closest_hit(&ray), None);
    assert!(!accel.any_hit(&ray, f64::INFINITY));
    assert!(accel.is_empty());
}

/// The shared test meshes, beside the repository (see `/work/shared/meshes/README.md`).
fn shared_mesh(name: &str) -> Mesh {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../shared/meshes");
    assert!(
        dir.is_dir(),
        "the shared test meshes are missing: expected the folder {} (shared/meshes beside the \
         repository); these tests need it",
        dir.display()
    );
    Mesh::load(&dir.join(name)).unwrap()
}

/// Rays from a sphere around the mesh towards random points of its bounding box.
fn rays_around(mesh: &Mesh, rng: &mut Pcg64, count: usize) -> Vec<Ray<f64>> {
    let (c, r) = mesh.bounding_sphere();
    let b = mesh.bounds();
    (0..count)
        .map(|_| {
            let d = point(rng, -1.0, 1.0);
            let len = dot(d, d).sqrt().max(1e-3);
            let o = core::array::from_fn(|k| c[k] + 2.0 * r * d[k] / len);
            let target: [f64; 3] = core::array::from_fn(|k| rng.random_range(b.min[k]..=b.max[k]));
            Ray::new(o, sub(target, o))
        })
        .collect()
}

#[test]
fn real_meshes_match_the_oracle() {
    let mut rng = Pcg64::seed_from_u64(5);
    for (name, ray_count) in
        [("stanford-bunny.obj", 150), ("teapot.obj", 600), ("suzanne.obj", 1000), ("cow.obj", 600)]
    {
        let mesh = shared_mesh(name);
        let rays = rays_around(&mesh, &mut rng, ray_count);
        let tris = mesh.triangles::<f64>();
        let accel = Accel::build(mt::<f64>(), &mesh.triangles());
        check_invariants(&accel, &tris);
        let hits = rays.iter().filter(|r| check_ray(&accel, &tris, r)).count();
        let tris32 = mesh.triangles::<f32>();
        let accel32 = Accel::build(mt::<f32>(), &mesh.triangles());
        check_invariants(&accel32, &tris32);
        let hits32 = rays.iter().filter(|r| check_ray(&accel32, &tris32, &r.cast())).count();
        assert!(hits > ray_count / 5 && hits32 > ray_count / 5, "{name}: {hits} {hits32}");
    }
}

/// The tree, node for node, does not depend on how many threads build it (subtrees built in
/// parallel are appended in the order the sequential build writes them).
#[test]
fn build_does_not_depend_on_the_thread_count() {
    let mesh = shared_mesh("stanford-bunny.obj");
    fn same<T: Real>(tris: &[Triangle<T>]) {
        let pool = |n| rayon::ThreadPoolBuilder::new().num_threads(n).build().unwrap();
        let one = pool(1).install(|| bvh::Bvh::from_triangles(tris));
        let four = pool(4).install(|| bvh::Bvh::from_triangles(tris));
        assert_eq!(one.order(), four.order());
        assert_eq!(one.node_count(), four.node_count());
        for i in 0..one.node_count() {
            assert_eq!(one.children(i), four.children(i), "node {i}");
        }
        assert_eq!((one.depth(), one.leaf_count()), (four.depth(), four.leaf_count()));
    }
    same(&mesh.triangles::<f32>());
    same(&mesh.triangles::<f64>());
}

/// Rays with a non-finite coordinate, and a NaN limit, meet nothing (and do not panic).
#[test]
fn non_finite_rays_meet_nothing() {
    let t = Triangle::new([0.0, 0.0, 1.0], [1.0, 0.0, 1.0], [0.0, 1.0, 1.0]);
    let accel = Accel::build(mt::<f64>(), &[t; 20]);
    let nan = f64::NAN;
    for ray in [
        Ray::new([nan, 0.25, 0.0], [0.0, 0.0, 1.0]),
        Ray::new([0.25, 0.25, 0.0], [0.0, nan, 1.0]),
        Ray::new([0.25, 0.25, f64::NEG_INFINITY], [0.0, 0.0, 1.0]),
        Ray::new([0.25, 0.25, 0.0], [0.0, 0.0, f64::INFINITY]),
    ] {
        assert_eq!(accel.closest_hit(&ray), None, "{ray:?}");
        assert!(!accel.any_hit(&ray, f64::INFINITY), "{ray:?}");
    }
    let ray = Ray::new([0.25, 0.25, 0.0], [0.0, 0.0, 1.0]);
    assert!(accel.closest_hit(&ray).is_some());
    assert_eq!(accel.closest_hit_within(&ray, nan), None);
    assert!(!accel.any_hit(&ray, nan));
}

/// What one traversal did: every leaf visited with the limit it was given, and the nearest
/// hit found (`Hit` in slot order: the test compares paths, not triangle indices).
type Visit<T> = (Vec<(usize, usize, T)>, Option<(T, usize)>);

fn closest_visit<T: Real>(
    bvh: &bvh::Bvh<T>,
    isa: bvh::Isa,
    tris: &[Triangle<T>],
    ray: &Ray<T>,
) -> Visit<T> {
    let (mut leaves, mut best) = (Vec::new(), None);
    bvh.closest_with(isa, ray, T::INFINITY, |slots, limit| {
        leaves.push((slots.start, slots.len(), *limit));
        for slot in slots {
            let tri = &tris[bvh.order()[slot] as usize];
            if let Some(h) = moller_trumbore(tri, ray, *limit) {
                if best.is_none_or(|(t, _)| h.t < t) {
                    best = Some((h.t, slot));
                }
                *limit = h.t;
            }
        }
    });
    (leaves, best)
}

fn any_visit<T: Real>(
    bvh: &bvh::Bvh<T>,
    isa: bvh::Isa,
    tris: &[Triangle<T>],
    ray: &Ray<T>,
) -> (Vec<usize>, bool) {
    let mut leaves = Vec::new();
    let hit = bvh.any_with(isa, ray, T::INFINITY, |slots| {
        leaves.push(slots.start);
        slots
            .into_iter()
            .any(|s| moller_trumbore(&tris[bvh.order()[s] as usize], ray, T::INFINITY).is_some())
    });
    (leaves, hit)
}

/// Every node test gives the same answers bit for bit: on the same trees and rays, the
/// AVX-512 traversal visits the same leaves in the same order with the same limits, and finds
/// the same hits, as the baseline's (AVX2 on the workspace's build), in f32 and f64.
#[test]
fn every_instruction_set_visits_the_same_leaves() {
    use bvh::Isa;
    if Isa::detected() != Isa::Avx512 {
        println!("note: this CPU has no AVX-512 (F and VL): only the baseline node test runs here");
        return;
    }
    fn same<T: Real>(name: &str, tris64: &[Triangle<f64>], rays: &[Ray<f64>]) {
        let tris: Vec<Triangle<T>> = tris64.iter().map(Triangle::cast).collect();
        let bvh = bvh::Bvh::from_triangles(&tris);
        let (mut visits, mut hits) = (0, 0);
        for ray in rays {
            let ray: Ray<T> = ray.cast();
            let base = closest_visit(&bvh, Isa::Baseline, &tris, &ray);
            let wide = closest_visit(&bvh, Isa::Avx512, &tris, &ray);
            assert!(base == wide, "{name}: closest {ray:?}");
            let base_any = any_visit(&bvh, Isa::Baseline, &tris, &ray);
            assert_eq!(base_any, any_visit(&bvh, Isa::Avx512, &tris, &ray), "{name}: any {ray:?}");
            visits += base.0.len();
            hits += usize::from(base.1.is_some());
        }
        // Not vacuous: the rays reach leaves and hit.
        assert!(visits > rays.len() && hits > rays.len() / 10, "{name}: {visits} {hits}");
    }
    let mut rng = Pcg64::seed_from_u64(18);
    for name in ["stanford-bunny.obj", "teapot.obj"] {
        let mesh = shared_mesh(name);
        let rays = rays_around(&mesh, &mut rng, 3000);
        same::<f32>(name, &mesh.triangles(), &rays);
        same::<f64>(name, &mesh.triangles(), &rays);
    }
    // The soup's rays along axes, with zero and negative-zero components and origins in the
    // boxes' planes (the NaN slabs).
    let tris = soup(&mut rng, 3000);
    let rays = rays(&mut rng, 3000, &tris);
    same::<f32>("soup", &tris, &rays);
    same::<f64>("soup", &tris, &rays);
}

/// The packet queries against the single-ray ones (which `check_ray` holds to the oracle), ray
/// by ray, bit for bit: closest hit within `t_max` and any hit, for no limit and for a limit
/// that cuts through the scene (the median distance of the hits). Returns the hits.
fn check_packets<T: Real>(accel: &Accel<Mt<T>>, rays: &[Ray<T>]) -> usize {
    let single: Vec<_> = rays.iter().map(|r| accel.closest_hit(r)).collect();
    let mut ts: Vec<T> = single.iter().flatten().map(|h| h.t).collect();
    ts.sort_by(|a, b| a.partial_cmp(b).unwrap());
    let median = ts.get(ts.len() / 2).copied().unwrap_or(T::ONE);
    let mut closest = vec![None; rays.len()];
    let mut any = vec![false; rays.len()];
    for t_max in [T::INFINITY, median, T::from_f64(f64::NAN)] {
        accel.closest_hits_packet(rays, t_max, &mut closest);
        accel.any_hits_packet(rays, t_max, &mut any);
        for (i, ray) in rays.iter().enumerate() {
            let want = accel.closest_hit_within(ray, t_max);
            assert_eq!(closest[i], want, "ray {i} {ray:?}, t_max {t_max:?}");
            assert_eq!(any[i], accel.any_hit(ray, t_max), "ray {i} {ray:?}, t_max {t_max:?}");
        }
    }
    ts.len()
}

/// A pinhole camera's rays from `eye` through a `side x side` grid of points `at + x u + y v`
/// (`x`, `y` in `[-1, 1]`), in 8 x 8 blocks as a renderer sends them.
fn pinhole(eye: [f64; 3], at: [f64; 3], u: [f64; 3], v: [f64; 3], side: u32) -> Vec<Ray<f64>> {
    let mut rays = Vec::new();
    let coord = |i: u32| 2.0 * (f64::from(i) + 0.5) / f64::from(side) - 1.0;
    for bj in (0..side).step_by(8) {
        for bi in (0..side).step_by(8) {
            for j in bj..(bj + 8).min(side) {
                for i in bi..(bi + 8).min(side) {
                    let (x, y) = (coord(i), coord(j));
                    let p: [f64; 3] = core::array::from_fn(|k| at[k] + x * u[k] + y * v[k]);
                    rays.push(Ray::new(eye, sub(p, eye)));
                }
            }
        }
    }
    rays
}

#[test]
fn packets_match_single_rays_on_soups() {
    let mut rng = Pcg64::seed_from_u64(17);
    let mut hits = 0;
    for n in [1, 9, 100, 3000] {
        let tris64 = soup(&mut rng, n);
        // Incoherent rays (every octant in every chunk: wide intervals, small groups), then a
        // camera looking at the soup from each side, with non-finite rays in its packets.
        let mut sets = vec![rays(&mut rng, 700, &tris64)];
        for eye in [[0.1, 0.2, -5.0], [4.0, -3.0, 0.5], [0.0, 6.0, 0.0]] {
            let mut cam = pinhole(eye, [0.0; 3], [1.2, 0.0, 0.0], [0.0, 0.0, 1.2], 24);
            cam[5].dir[0] = f64::NAN;
            cam[70].origin[2] = f64::INFINITY;
            cam[71].dir = [0.0; 3];
            sets.push(cam);
        }
        for rays in &sets {
            let tris: Vec<Triangle<f32>> = tris64.iter().map(Triangle::cast).collect();
            hits += check_packets(&Accel::build(mt::<f64>(), &tris64), rays);
            let rays32: Vec<Ray<f32>> = rays.iter().map(Ray::cast).collect();
            hits += check_packets(&Accel::build(mt::<f32>(), &tris), &rays32);
        }
    }
    assert!(hits > 2000, "{hits} hits");
}

/// The closed box of `exact_ties_on_shared_edges_and_vertices` seen by cameras whose rays pass
/// exactly through its grid's vertices and edge midpoints: ties in every packet.
#[test]
fn packets_keep_exact_ties() {
    let (nx, ny, nz) = (8, 6, 4);
    let tris = grid_box(nx, ny, nz);
    let tris32: Vec<Triangle<f32>> = tris.iter().map(Triangle::cast).collect();
    let (a64, a32) = (Accel::build(mt::<f64>(), &tris), Accel::build(mt::<f32>(), &tris32));
    let mut hits = 0;
    for eye in [[3.0, 2.0, -5.0], [-4.0, 3.0, 1.0], [11.0, -1.0, 9.0], [4.0, 3.0, 2.0]] {
        // Every half-integer point of the z = 0 and x = 0 faces, from one eye: exact
        // directions, on the shared edges and vertices of the triangles.
        let mut rays = Vec::new();
        for (a, b) in (0..=2 * nx).flat_map(|a| (0..=2 * ny).map(move |b| (a, b))) {
            rays.push([f64::from(a) * 0.5, f64::from(b) * 0.5, 0.0]);
        }
        for (b, c) in (0..=2 * ny).flat_map(|b| (0..=2 * nz).map(move |c| (b, c))) {
            rays.push([0.0, f64::from(b) * 0.5, f64::from(c) * 0.5]);
        }
        let rays: Vec<Ray<f64>> = rays.into_iter().map(|p| Ray::new(eye, sub(p, eye))).collect();
        for ray in &rays {
            hits += usize::from(check_ray(&a64, &tris, ray));
        }
        hits += check_packets(&a64, &rays);
        check_packets(&a32, &rays.iter().map(Ray::cast).collect::<Vec<_>>());
    }
    assert!(hits > 1000, "{hits}");
}

#[test]
fn packets_match_single_rays_on_real_meshes() {
    for name in ["stanford-bunny.obj", "teapot.obj"] {
        let mesh = shared_mesh(name);
        let (c, r) = mesh.bounding_sphere();
        let mut hits = 0;
        // Front, side and grazing views, a frame of 32 x 32 rays each.
        for (dir, up) in [([0.0, 0.0, -1.0], [0.0, 1.0, 0.0]), ([1.0, 0.0, 0.0], [0.0, 0.0, 1.0])] {
            let eye = core::array::from_fn(|k| c[k] + 2.5 * r * dir[k]);
            let side = cross(dir, up);
            let u = side.map(|x| x * r);
            let v = up.map(|x| x * r);
            let rays = pinhole(eye, c, u, v, 32);
            hits += check_packets(&Accel::build(mt::<f64>(), &mesh.triangles()), &rays);
            let rays32: Vec<Ray<f32>> = rays.iter().map(Ray::cast).collect();
            hits += check_packets(&Accel::build(mt::<f32>(), &mesh.triangles()), &rays32);
        }
        assert!(hits > 500, "{name}: {hits}");
    }
}

/// A tree with its leaves aligned to blocks is the same tree: the same nodes, boxes and
/// children, each leaf holding the same triangles from a slot that is a multiple of the
/// block, padding only between leaves; and closest-hit traversals find the same triangles.
#[test]
fn aligned_leaves_keep_the_tree() {
    let mut rng = Pcg64::seed_from_u64(0xa119);
    let mesh = shared_mesh("teapot.obj");
    for (name, tris64) in [("soup", soup(&mut rng, 2000)), ("teapot", mesh.triangles())] {
        let tris: Vec<Triangle<f32>> = tris64.iter().map(Triangle::cast).collect();
        let plain = bvh::Bvh::from_triangles(&tris);
        for align in [1, 3, 4, 8] {
            let aligned = plain.clone().with_leaves_aligned(align);
            assert_eq!(aligned.len(), tris.len(), "{name}");
            assert_eq!(aligned.node_count(), plain.node_count(), "{name}");
            assert_eq!(aligned.order().len() % align, 0, "{name}");
            let mut in_leaves = 0;
            for i in 0..plain.node_count() {
                for (a, b) in plain.children(i).into_iter().zip(aligned.children(i)) {
                    assert_eq!(a.bounds(), b.bounds(), "{name}: node {i}");
                    match (a, b) {
                        (Child::Leaf { slots: s, .. }, Child::Leaf { slots: t, .. }) => {
                            assert_eq!(t.start % align, 0, "{name}: leaf at {t:?}");
                            assert_eq!(plain.order()[s], aligned.order()[t.clone()], "{name}");
                            in_leaves += t.len();
                        }
                        (Child::Node { index: i, .. }, Child::Node { index: j, .. }) => {
                            assert_eq!(i, j, "{name}");
                        }
                        _ => panic!("{name}: node {i}: a leaf became a node or back"),
                    }
                }
            }
            let padding = aligned.order().iter().filter(|&&p| p == bvh::PADDING).count();
            assert_eq!(in_leaves + padding, aligned.order().len(), "{name}: padding only");
            let mut hits = 0;
            for ray in rays(&mut rng, 300, &tris64) {
                let ray: Ray<f32> = ray.cast();
                let hit = |bvh: &bvh::Bvh<f32>| {
                    let found = closest_visit(bvh, bvh::Isa::current(), &tris, &ray).1;
                    found.map(|(t, slot)| (t, bvh.order()[slot]))
                };
                assert_eq!(hit(&plain), hit(&aligned), "{name}: align {align}: {ray:?}");
                hits += usize::from(hit(&plain).is_some());
            }
            assert!(hits > 30, "{name}: {hits} of 300 rays hit");
        }
    }
}
