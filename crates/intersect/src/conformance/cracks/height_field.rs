//! Rays aimed exactly at shared edges and vertices of a triangle mesh without holes (a
//! height field), counting the rays that slip through (hit none of the triangles that meet
//! there) and those counted twice.
//!
//! The vertices are random `f32` values (24 significant bits, so the kernels' arithmetic
//! rounds as it would on a scanned mesh). A point on an edge, `p + s (q - p)` with
//! `s = k / 256`, is exact in `f64` though not in `f32`; the ray to it starts at `o`, the
//! point rounded to `f32` after a short step back, and its direction is `d = x - o`, which is
//! small enough to be exact in `f32`. So `o + 1 * d` is exactly the point on the edge, in
//! both precisions, near the origin and 1024 extents away from it: any miss is the
//! kernel's doing. Every ray is tested against every triangle of the mesh.

use rand::Rng;
use rand_pcg::Pcg64;

use crate::conformance::label;
use crate::conformance::reference::{rng, tolerance};
use crate::{Intersector, Ray, Real, Triangle};

/// Grid cells per side.
const N: usize = 16;

/// A height field over an `N x N` grid, spacing 1 with vertices jittered by up to 0.2,
/// heights in `[16, 17]`, each cell split along a random diagonal, all triangles
/// counter-clockwise seen from above. Coordinates are `f32` values in `[16, 32]`, so they
/// all have the same resolution (2^-19) and a point on an edge is never much finer.
struct Mesh {
    vertices: Vec<[f64; 3]>,
    triangles: Vec<[usize; 3]>,
}

impl Mesh {
    fn height_field(rng: &mut Pcg64) -> Self {
        let id = |i: usize, j: usize| i * (N + 1) + j;
        let mut vertices = Vec::new();
        for i in 0..=N {
            for j in 0..=N {
                let (x, y) = (16.0 + i as f64 + jitter(rng, i), 16.0 + j as f64 + jitter(rng, j));
                vertices.push(round32([x, y, 16.0 + rng.random::<f64>()]));
            }
        }
        let mut triangles = Vec::new();
        for i in 0..N {
            for j in 0..N {
                let [p00, p10, p11, p01] = [id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)];
                if rng.random_bool(0.5) {
                    triangles.extend([[p00, p10, p11], [p00, p11, p01]]);
                } else {
                    triangles.extend([[p00, p10, p01], [p10, p11, p01]]);
                }
            }
        }
        Self { vertices, triangles }
    }

    /// Edges shared by two triangles, with those two triangles' indices.
    fn shared_edges(&self) -> Vec<([usize; 2], [usize; 2])> {
        let mut edges: Vec<([usize; 2], usize)> = Vec::new();
        for (t, tri) in self.triangles.iter().enumerate() {
            for k in 0..3 {
                let (p, q) = (tri[k], tri[(k + 1) % 3]);
                edges.push(([p.min(q), p.max(q)], t));
            }
        }
        edges.sort_unstable();
        edges.windows(2).filter(|w| w[0].0 == w[1].0).map(|w| (w[0].0, [w[0].1, w[1].1])).collect()
    }

    /// Interior vertices (not on the border of the grid), with the triangles around each.
    fn shared_vertices(&self) -> Vec<(usize, Vec<usize>)> {
        let border =
            |i: usize| i.is_multiple_of(N + 1) || i % (N + 1) == N || i <= N || i >= N * (N + 1);
        (0..self.vertices.len())
            .filter(|&v| !border(v))
            .map(|v| {
                let around = (0..self.triangles.len()).filter(|&t| self.triangles[t].contains(&v));
                (v, around.collect())
            })
            .collect()
    }
}

/// Grid jitter: none on the border, so that the grid stays a square.
fn jitter(rng: &mut Pcg64, i: usize) -> f64 {
    if i == 0 || i == N { 0.0 } else { rng.random_range(-0.2..0.2) }
}

/// Rounds to the nearest `f32`.
fn round32(p: [f64; 3]) -> [f64; 3] {
    p.map(|x| f64::from(x as f32))
}

/// A signed permutation of the axes, applied to every point: exact, and it makes the ray's
/// dominant axis (and its sign) vary, which exercises the watertight kernel's axis choice
/// and winding swap.
#[derive(Clone, Copy)]
struct Frame {
    perm: [usize; 3],
    sign: [f64; 3],
    offset: [f64; 3],
}

impl Frame {
    fn random(rng: &mut Pcg64, distance: f64) -> Self {
        const PERMS: [[usize; 3]; 6] =
            [[0, 1, 2], [0, 2, 1], [1, 0, 2], [1, 2, 0], [2, 0, 1], [2, 1, 0]];
        let sign = [0; 3].map(|_| if rng.random_bool(0.5) { 1.0 } else { -1.0 });
        let offset = [0; 3].map(|_| distance * if rng.random_bool(0.5) { 1.0 } else { -1.0 });
        Self { perm: PERMS[rng.random_range(0..6)], sign, offset }
    }

    fn point(&self, p: [f64; 3]) -> [f64; 3] {
        core::array::from_fn(|k| self.sign[k] * p[self.perm[k]] + self.offset[k])
    }

    fn vector(&self, v: [f64; 3]) -> [f64; 3] {
        core::array::from_fn(|k| self.sign[k] * v[self.perm[k]])
    }
}

/// Rays through exact points of shared edges and through shared vertices.
#[derive(Clone, Copy, Default, Debug, PartialEq, Eq)]
pub struct Count {
    /// Rays shot.
    pub rays: u32,
    /// No triangle at the edge or vertex was hit.
    pub cracks: u32,
    /// More than one was hit.
    pub multiple: u32,
}

/// One ray through `target` (exact, in the frame's coordinates), tested against all the
/// triangles of the mesh (`mesh`, already in the frame's coordinates): the ray is steeper
/// than any of them, so it meets the surface once.
fn shoot<I: Intersector + Default>(
    rng: &mut Pcg64,
    frame: &Frame,
    target: [f64; 3],
    mesh: &[[[f64; 3]; 3]],
    count: &mut Count,
) {
    let k = I::default();
    // Mostly downwards in the mesh's own frame: horizontal components up to a quarter of the
    // vertical one make the ray steeper than any triangle (slopes below 1.7), so it meets
    // the surface once and the triangles around a point cover it.
    let mut tries = 0;
    let ray = loop {
        tries += 1;
        assert!(tries < 1_000, "no exact ray to {target:?}");
        let step = [rng.random_range(-0.25..0.25), rng.random_range(-0.25..0.25), -1.0];
        let step = frame.vector(step.map(|x| x / 32.0));
        let origin = round32(core::array::from_fn(|n| target[n] - step[n]));
        let dir: [f64; 3] = core::array::from_fn(|n| target[n] - origin[n]);
        let exact = round32(dir) == dir && (0..3).all(|n| origin[n] + dir[n] == target[n]);
        if exact {
            break Ray::new(origin, dir).cast::<I::Real>();
        }
    };
    let rd = k.prepare_ray(&ray);
    let mut hits = 0;
    for &[a, b, c] in mesh {
        let tri: Triangle<I::Real> = Triangle::new(a, b, c).cast();
        if let Some(h) = k.intersect(&k.prepare(&tri), &ray, &rd, I::Real::INFINITY) {
            hits += 1;
            // t = 1 exactly; the ray is short, so allow the conditioning of a 1/32 step.
            let err = (h.t.to_f64() - 1.0).abs();
            assert!(err <= tolerance::<I::Real>() * 100.0, "{}: t = {}", label::<I>(), h.t);
        }
    }
    count.rays += 1;
    count.cracks += u32::from(hits == 0);
    count.multiple += u32::from(hits > 1);
}

/// Every shared edge at 4 random points, every interior vertex, each with a random frame,
/// the mesh `distance` away from the world origin on every axis.
pub fn count_cracks<I: Intersector + Default>(distance: f64) -> Count {
    let mut rng = rng(0x5eed_0010);
    let mut count = Count::default();
    for _ in 0..4 {
        let mesh = Mesh::height_field(&mut rng);
        let framed = |frame: &Frame| -> Vec<[[f64; 3]; 3]> {
            let vertex = |v: usize| round32(frame.point(mesh.vertices[v]));
            mesh.triangles.iter().map(|t| t.map(vertex)).collect()
        };
        for ([p, q], _) in mesh.shared_edges() {
            for _ in 0..4 {
                let frame = Frame::random(&mut rng, distance);
                let [p, q] = [p, q].map(|v| round32(frame.point(mesh.vertices[v])));
                // p + (q - p) * s, exact in f64: at most 24 + 1 + 8 significant bits.
                let s = f64::from(rng.random_range(1..256u32)) / 256.0;
                let target = core::array::from_fn(|n| p[n] + (q[n] - p[n]) * s);
                shoot::<I>(&mut rng, &frame, target, &framed(&frame), &mut count);
            }
        }
        for (v, _) in mesh.shared_vertices() {
            let frame = Frame::random(&mut rng, distance);
            let target = round32(frame.point(mesh.vertices[v]));
            shoot::<I>(&mut rng, &frame, target, &framed(&frame), &mut count);
        }
    }
    count
}

/// The mesh near the origin, then 1024 extents (16384 units) away on every axis.
pub const DISTANCES: [f64; 2] = [0.0, 1024.0 * N as f64];

/// [`count_cracks`] at both [`DISTANCES`], printed (run the tests with `--nocapture`).
pub fn report<I: Intersector + Default>() -> [Count; 2] {
    DISTANCES.map(|d| {
        let c = count_cracks::<I>(d);
        eprintln!("{} at distance {d}: {c:?}", label::<I>());
        c
    })
}
