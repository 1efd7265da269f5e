//! Ray generators, one per family of the suite. Every generator is a pure function of its
//! mesh, its sizes and a seed ([`SplitMix64`]), so every run judges the same rays.

use intersect::Ray;
use render::camera::Camera;

use super::fp::{
    add, cross, dot, exact_add3, exact_scale3, exact_sub3, is_f32_3, length, normalize, round32_3,
    scale, sub,
};
use super::mesh::TriMesh;
use super::runner::Pair;
use crate::SplitMix64;

/// How exactly an aimed ray passes through its target point.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Aim {
    /// Origin and direction are `f32` values and `origin + 1 * dir` is exactly the target:
    /// the `f32` and the `f64` back ends both see a ray exactly through the edge or vertex.
    Exact,
    /// The ray passes exactly through the target in `f64`; its `f32` rounding (what an `f32`
    /// back end sees) generally passes near it.
    F64,
}

impl Aim {
    /// `exact` or `f64`.
    #[must_use]
    pub const fn name(self) -> &'static str {
        match self {
            Aim::Exact => "exact",
            Aim::F64 => "f64",
        }
    }
}

/// A ray aimed at a point of a shared edge or at a shared vertex, with the triangles that
/// meet there.
#[derive(Clone, Debug, PartialEq)]
pub struct AimedRay {
    /// The ray; `ray.at(1)` is the target point.
    pub ray: Ray<f64>,
    /// Indices of the triangles at the edge (2) or around the vertex (the ring).
    pub around: Vec<u32>,
}

/// Rays aimed at shared edges, or at shared vertices, of one mesh.
#[derive(Clone, Debug, PartialEq)]
pub struct AimedSet {
    /// The mesh (its coordinates are `f32` values).
    pub mesh: TriMesh,
    /// `edges` or `vertices`.
    pub target: &'static str,
    /// How exactly the rays pass through their targets.
    pub aim: Aim,
    /// The rays.
    pub rays: Vec<AimedRay>,
}

/// `count` rays at points of shared edges: edge `i % edges` for ray `i` when there are at
/// least as many rays as edges (every edge is covered), else random edges. The point is
/// `p + s (q - p)` with `s = k / 16`, `0 < k < 16`, kept only when that is exact in `f64`
/// (so the point is exactly on the edge). The ray comes from a random side, within 45 degrees
/// or so of the mean normal of the two triangles, from about two edge lengths away.
///
/// The mesh is first rounded to `f32` ([`TriMesh::rounded_to_f32`]).
#[must_use]
pub fn edge_rays(mesh: &TriMesh, count: usize, aim: Aim, seed: u64) -> AimedSet {
    let mesh = mesh.rounded_to_f32();
    let edges = mesh.shared_edges();
    let mut rng = SplitMix64::new(seed);
    let mut rays = Vec::with_capacity(count);
    if edges.is_empty() {
        return AimedSet { mesh, target: "edges", aim, rays };
    }
    for i in 0..count {
        let pick =
            if count >= edges.len() { i % edges.len() } else { below(&mut rng, edges.len()) };
        let edge = edges[pick];
        let [p, q] = edge.ends.map(|v| mesh.positions[v as usize]);
        let normal =
            add(unit_normal(&mesh, edge.triangles[0]), unit_normal(&mesh, edge.triangles[1]));
        let step = 2.0 * length(sub(q, p));
        for _ in 0..8 {
            let s = (1 + below(&mut rng, 15)) as f64 / 16.0;
            let target =
                exact_sub3(q, p).and_then(|e| exact_scale3(e, s)).and_then(|d| exact_add3(p, d));
            if let Some(ray) = target.and_then(|t| aim_at(t, normal, step, aim, &mut rng)) {
                rays.push(AimedRay { ray, around: edge.triangles.to_vec() });
                break;
            }
        }
    }
    AimedSet { mesh, target: "edges", aim, rays }
}

/// `count` rays at vertices with closed rings of triangles ([`TriMesh::fans`]), covering
/// every such vertex in turn when there are enough rays, else random ones, from a random side
/// within about 45 degrees of the ring's mean normal, from about two edge lengths away.
///
/// The mesh is first rounded to `f32`, so the vertex itself is an `f32` value.
#[must_use]
pub fn vertex_rays(mesh: &TriMesh, count: usize, aim: Aim, seed: u64) -> AimedSet {
    let mesh = mesh.rounded_to_f32();
    let fans = mesh.fans();
    let mut rng = SplitMix64::new(seed);
    let mut rays = Vec::with_capacity(count);
    if fans.is_empty() {
        return AimedSet { mesh, target: "vertices", aim, rays };
    }
    for i in 0..count {
        let fan =
            &fans[if count >= fans.len() { i % fans.len() } else { below(&mut rng, fans.len()) }];
        let target = mesh.positions[fan.vertex as usize];
        let normal = fan.triangles.iter().fold([0.0; 3], |n, &t| add(n, unit_normal(&mesh, t)));
        let step = 2.0 * mesh.mean_edge_length(fan.triangles[0]);
        if let Some(ray) = aim_at(target, normal, step, aim, &mut rng) {
            rays.push(AimedRay { ray, around: fan.triangles.clone() });
        }
    }
    AimedSet { mesh, target: "vertices", aim, rays }
}

/// A ray through `target` (exactly, see [`Aim`]) from a random side of the surface with
/// normal `normal`, starting about `step` away. `None` when no such ray is found.
fn aim_at(
    target: [f64; 3],
    normal: [f64; 3],
    step: f64,
    aim: Aim,
    rng: &mut SplitMix64,
) -> Option<Ray<f64>> {
    let normal = normalize(normal)?;
    let side = if rng.next_u64() & 1 == 0 { 1.0 } else { -1.0 };
    // Jitter of up to about 45 degrees, staying well on the chosen side.
    let dir = (0..16).find_map(|_| {
        let dir = normalize(add(scale(normal, -side), scale(rng.array::<3>(), 0.6)))?;
        (dot(dir, normal) * side < -0.2).then_some(dir)
    })?;
    let mut step = step;
    // Shorter steps leave fewer significant bits in target - origin, until it fits an f32.
    for _ in 0..64 {
        let origin = sub(target, scale(dir, step));
        let origin = match aim {
            Aim::Exact => round32_3(origin),
            Aim::F64 => origin,
        };
        if let Some(d) = exact_sub3(target, origin) {
            let usable = d != [0.0; 3] && (aim == Aim::F64 || is_f32_3(d));
            if usable {
                return Some(Ray::new(origin, d));
            }
        }
        step *= 0.5;
    }
    None
}

/// The unit normal of triangle `t` (zero for a degenerate one).
fn unit_normal(mesh: &TriMesh, t: u32) -> [f64; 3] {
    let [a, b, c] = mesh.triangle(t).vertices();
    normalize(cross(sub(b, a), sub(c, a))).unwrap_or([0.0; 3])
}

/// `count` ordinary rays: from uniformly random points of the sphere of twice the bounding
/// box's half-diagonal around its centre, towards uniformly random points of the box
/// (directions of unit length). About half of them hit the bunny.
#[must_use]
pub fn random_rays(mesh: &TriMesh, count: usize, seed: u64) -> Vec<Ray<f64>> {
    let (lo, hi) = mesh.bounds();
    let centre: [f64; 3] = core::array::from_fn(|k| 0.5 * (lo[k] + hi[k]));
    let radius = length(sub(hi, lo));
    let mut rng = SplitMix64::new(seed);
    (0..count)
        .map(|_| {
            let on_sphere = loop {
                let v = rng.array::<3>();
                let l = length(v);
                if l > 0.1 && l <= 1.0 {
                    break scale(v, radius / l);
                }
            };
            let origin = add(centre, on_sphere);
            let target: [f64; 3] = core::array::from_fn(|k| rng.range(lo[k], hi[k]));
            Ray::new(origin, normalize(sub(target, origin)).expect("origin is off the box"))
        })
        .collect()
}

/// The primary rays of a `width x height` image of the mesh, framed by
/// [`Camera::auto`] (45 degree field of view): the rays of the images compared in
/// `SUMMARY.md`.
#[must_use]
pub fn camera_rays(mesh: &TriMesh, width: u32, height: u32) -> Vec<Ray<f64>> {
    let (lo, hi) = mesh.bounds();
    let centre: [f64; 3] = core::array::from_fn(|k| 0.5 * (lo[k] + hi[k]));
    let radius = 0.5 * length(sub(hi, lo));
    let camera = Camera::auto(centre, radius, 45.0, f64::from(width) / f64::from(height))
        .expect("a finite mesh gives a valid camera");
    let mut rays = Vec::with_capacity(width as usize * height as usize);
    for j in 0..height {
        for i in 0..width {
            rays.push(Ray::new(camera.eye(), camera.direction(i, j, width, height)));
        }
    }
    rays
}

/// `count` rays with zero direction components (infinite inverse directions for the BVH's
/// slab test): along an axis (two zeros) or in a coordinate plane (one zero), from random
/// `f32` points of the box around the mesh grown by a quarter of its largest side on each
/// side. Every value is an `f32`.
#[must_use]
pub fn axis_aligned_rays(mesh: &TriMesh, count: usize, seed: u64) -> Vec<Ray<f64>> {
    let (lo, hi) = mesh.bounds();
    // Padded by a quarter of the largest side on every axis, so that a flat mesh (the tile
    // grid) is not met only by rays in its plane.
    let pad = 0.25 * mesh.extent();
    let mut rng = SplitMix64::new(seed);
    (0..count)
        .map(|_| {
            let origin = round32_3(core::array::from_fn(|k| rng.range(lo[k] - pad, hi[k] + pad)));
            let axis = below(&mut rng, 3);
            let mut dir = [0.0; 3];
            dir[axis] = if rng.next_u64() & 1 == 0 { 1.0 } else { -1.0 };
            if rng.next_u64() & 1 == 0 {
                // One zero only: a second component in the coordinate plane.
                dir[(axis + 1) % 3] = round32_3([rng.range(-1.0, 1.0); 3])[0];
            }
            Ray::new(origin, dir)
        })
        .collect()
}

/// Rays in, or nearly in, the plane of a triangle, every value an `f32`:
/// - `along-edge`: from `2a - b` along `b - a`, exactly along the line of an edge (in the
///   planes of both triangles at it);
/// - `in-plane`: from `2a - m` towards `m`, the midpoint of `bc` (exactly in the plane,
///   through the triangle from a vertex to the opposite side);
/// - `near-plane`: the `in-plane` direction tilted out of the plane by about `2^-20`.
///
/// Each ray comes paired with its triangle (the reference never reports a hit for a ray in
/// the triangle's plane). Rays whose construction is not exact are skipped, so there may be
/// fewer than `count`.
#[must_use]
pub fn grazing_rays(mesh: &TriMesh, count: usize, seed: u64) -> Vec<(&'static str, Pair)> {
    let mesh = mesh.rounded_to_f32();
    let mut rng = SplitMix64::new(seed);
    let mut out = Vec::with_capacity(count);
    for i in 0..count * 4 {
        if out.len() == count || mesh.is_empty() {
            break;
        }
        let t = below(&mut rng, mesh.len()) as u32;
        let [a, b, c] = rotate(mesh.triangle(t).vertices(), below(&mut rng, 3));
        let n = cross(sub(b, a), sub(c, a));
        let ray = match i % 3 {
            0 => exact_sub3(a, b)
                .and_then(|back| Some(Ray::new(exact_add3(a, back)?, exact_sub3(b, a)?)))
                .map(|r| ("along-edge", r)),
            k => exact_add3(b, c)
                .and_then(|sum| exact_scale3(sum, 0.5))
                .and_then(|m| {
                    let back = exact_sub3(a, m)?;
                    Some(Ray::new(exact_add3(a, back)?, exact_sub3(m, a)?))
                })
                .and_then(|r| {
                    if k == 1 {
                        return Some(("in-plane", r));
                    }
                    let tilt = scale(normalize(n)?, length(r.dir) * 2f64.powi(-20));
                    let tilt = if rng.next_u64() & 1 == 0 { tilt } else { scale(tilt, -1.0) };
                    Some(("near-plane", Ray::new(r.origin, round32_3(add(r.dir, tilt)))))
                }),
        };
        if let Some((kind, r)) = ray
            && r.dir != [0.0; 3]
            && is_f32_3(r.origin)
            && is_f32_3(r.dir)
            && n != [0.0; 3]
        {
            out.push((kind, Pair { ray: r, tri: mesh.triangle(t), t_max: f64::INFINITY }));
        }
    }
    out
}

fn rotate<T: Copy>(v: [T; 3], k: usize) -> [T; 3] {
    core::array::from_fn(|i| v[(i + k) % 3])
}

/// `count` rays starting exactly on the surface, at the targets of [`edge_rays`] and
/// [`vertex_rays`] (alternately), in uniformly random directions rounded to `f32`, each
/// paired with every triangle that contains its origin (two at an edge point, the ring at a
/// vertex). The reference never reports those hits: the ray meets each such triangle's plane
/// at `t = 0` only.
#[must_use]
pub fn surface_rays(mesh: &TriMesh, count: usize, seed: u64) -> Vec<Pair> {
    let edges = edge_rays(mesh, count.div_ceil(2), Aim::Exact, seed);
    let vertices = vertex_rays(mesh, count / 2, Aim::Exact, seed ^ 0x5151);
    let mut rng = SplitMix64::new(seed ^ 0xface);
    let mut out = Vec::with_capacity(count * 3);
    for (set, aimed) in
        edges.rays.iter().map(|a| (&edges, a)).chain(vertices.rays.iter().map(|a| (&vertices, a)))
    {
        let origin = aimed.ray.at(1.0);
        if !is_f32_3(origin) {
            continue;
        }
        let dir = loop {
            let v = rng.array::<3>();
            if length(v) > 0.1 {
                break round32_3(v);
            }
        };
        for &t in &aimed.around {
            let tri = set.mesh.triangle(t);
            out.push(Pair { ray: Ray::new(origin, dir), tri, t_max: f64::INFINITY });
        }
    }
    out
}

/// A uniform index in `0..n` (`n > 0`).
pub(crate) fn below(rng: &mut SplitMix64, n: usize) -> usize {
    // Multiply-shift: unbiased enough for picking test cases, and deterministic.
    ((u128::from(rng.next_u64()) * n as u128) >> 64) as usize
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exact_edge_rays_pass_exactly_through_edge_points() {
        let tiles = TriMesh::tiles();
        let set = edge_rays(&tiles, 200, Aim::Exact, 1);
        assert_eq!(set.rays.len(), 200);
        for r in &set.rays {
            assert!(is_f32_3(r.ray.origin) && is_f32_3(r.ray.dir));
            let x = r.ray.at(1.0);
            // On the grid: z = 0 and on the line of a shared edge of both triangles.
            assert_eq!(x[2], 0.0);
            let [t0, t1] = [r.around[0], r.around[1]].map(|t| set.mesh.triangles[t as usize]);
            let shared: Vec<u32> = t0.iter().copied().filter(|v| t1.contains(v)).collect();
            let [p, q] = [shared[0], shared[1]].map(|v| set.mesh.positions[v as usize]);
            assert_eq!(cross(sub(q, p), sub(x, p)), [0.0; 3], "{x:?} off {p:?}-{q:?}");
        }
    }

    #[test]
    fn vertex_rays_hit_their_vertex() {
        let tiles = TriMesh::tiles();
        let set = vertex_rays(&tiles, 225, Aim::F64, 2);
        assert_eq!(set.rays.len(), 225);
        for r in &set.rays {
            let x = r.ray.at(1.0);
            assert!(set.mesh.positions.contains(&x));
        }
    }

    #[test]
    fn grazing_rays_on_the_grid_stay_in_its_plane() {
        let rays = grazing_rays(&TriMesh::tiles(), 60, 3);
        assert_eq!(rays.len(), 60);
        for (kind, pair) in rays {
            let r = pair.ray;
            let in_plane = r.origin[2] == 0.0 && r.dir[2] == 0.0;
            assert_eq!(in_plane, kind != "near-plane", "{kind}: {r:?}");
        }
    }
}
