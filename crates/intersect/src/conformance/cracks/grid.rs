//! A tile grid: a height field of `N x N` jittered cells, each split into two triangles along
//! a random diagonal, wound consistently (or, on request, at random), with the vertices
//! stored once and shared by index (so neighbours see identical numbers, as in an indexed
//! mesh). Rays start at random points above the grid and aim at random points of interior
//! edges, or exactly at interior vertices; each such ray passes through the grid's interior,
//! so it must hit some triangle, and only one at the aimed point.

use rand::Rng;

use crate::conformance::reference::rng;
use crate::vec3::sub;
use crate::{Intersector, Ray, Real, Triangle};

/// Grid cells per side.
const N: usize = 8;

/// The grid's vertices (rounded to the kernel's precision) and triangles (index triples).
struct Grid {
    vertices: Vec<[f64; 3]>,
    triangles: Vec<[usize; 3]>,
}

impl Grid {
    /// With `mixed_winding`, half of the triangles (at random) are wound the other way.
    fn new<T: Real>(rng: &mut rand_pcg::Pcg64, offset: f64, mixed_winding: bool) -> Self {
        let index = |i: usize, j: usize| i * (N + 1) + j;
        let mut vertices = Vec::new();
        for i in 0..=N {
            for j in 0..=N {
                // Jitter interior vertices so that coordinates are not small dyadic numbers.
                let jitter = |rng: &mut rand_pcg::Pcg64| {
                    if i == 0 || j == 0 || i == N || j == N {
                        0.0
                    } else {
                        rng.random_range(-0.3..0.3)
                    }
                };
                let p = [
                    offset + i as f64 + jitter(rng),
                    offset + j as f64 + jitter(rng),
                    offset + rng.random_range(-0.1..0.1),
                ];
                vertices.push(p.map(|x| T::from_f64(x).to_f64()));
            }
        }
        let mut triangles = Vec::new();
        for i in 0..N {
            for j in 0..N {
                let (a, b, c, d) =
                    (index(i, j), index(i + 1, j), index(i + 1, j + 1), index(i, j + 1));
                if rng.random_bool(0.5) {
                    triangles.extend([[a, b, c], [a, c, d]]);
                } else {
                    triangles.extend([[a, b, d], [b, c, d]]);
                }
            }
        }
        if mixed_winding {
            for t in &mut triangles {
                if rng.random_bool(0.5) {
                    t.swap(1, 2);
                }
            }
        }
        Self { vertices, triangles }
    }

    fn triangle<T: Real>(&self, t: [usize; 3]) -> Triangle<T> {
        Triangle::new(self.vertices[t[0]], self.vertices[t[1]], self.vertices[t[2]]).cast()
    }

    /// Edges shared by two triangles, as vertex index pairs (smaller index first).
    fn interior_edges(&self) -> Vec<(usize, usize)> {
        let mut all: Vec<(usize, usize)> = self
            .triangles
            .iter()
            .flat_map(|t| [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])])
            .map(|(p, q)| (p.min(q), p.max(q)))
            .collect();
        all.sort_unstable();
        all.windows(2).filter(|w| w[0] == w[1]).map(|w| w[0]).collect()
    }

    /// The largest `|grad z|` of a triangle: `|n_xy| / |n_z|` for its normal `n`.
    fn max_slope(&self) -> f64 {
        let slope = |t: &[usize; 3]| {
            let [a, b, c] = t.map(|v| self.vertices[v]);
            let (e, f) = (sub(b, a), sub(c, a));
            let n =
                [e[1] * f[2] - e[2] * f[1], e[2] * f[0] - e[0] * f[2], e[0] * f[1] - e[1] * f[0]];
            n[0].hypot(n[1]) / n[2].abs()
        };
        self.triangles.iter().map(slope).fold(0.0, f64::max)
    }

    fn interior_vertices(&self) -> Vec<usize> {
        (1..N).flat_map(|i| (1..N).map(move |j| i * (N + 1) + j)).collect()
    }
}

/// `rays / 2` rays aimed at shared edges and as many at vertices; returns how many of each hit
/// no triangle, and how many of each hit more than one.
///
/// Every triangle is tested (brute force), and a hit counts when its `t` is within `1e-2` of
/// the aimed point's `t = 1`: the grid is not steep enough for a ray to meet it twice that
/// close together, but it can meet it again farther on.
pub fn cracks_and_doubles<I: Intersector + Default>(
    seed: u64,
    offset: f64,
    mixed_winding: bool,
    rays: usize,
) -> [[usize; 2]; 2] {
    let k = I::default();
    let mut rng = rng(seed);
    let grid = Grid::new::<I::Real>(&mut rng, offset, mixed_winding);
    let prims: Vec<I::Prim> =
        grid.triangles.iter().map(|&t| k.prepare(&grid.triangle(t))).collect();
    assert!(grid.max_slope() < 2f64.sqrt(), "{}", grid.max_slope());
    let (edges, vertices) = (grid.interior_edges(), grid.interior_vertices());
    assert_eq!(edges.len(), 3 * N * N - 2 * N, "interior edges of an N x N split grid");
    let (mut missed, mut doubled) = ([0; 2], [0; 2]);
    for n in 0..rays {
        let target = if n % 2 == 0 {
            let (p, q) = edges[rng.random_range(0..edges.len())];
            // Not too close to the ends: an edge may end on the grid's border.
            let s = rng.random_range(0.05..0.95);
            let (p, q) = (grid.vertices[p], grid.vertices[q]);
            core::array::from_fn(|m| p[m] + s * (q[m] - p[m]))
        } else {
            grid.vertices[vertices[rng.random_range(0..vertices.len())]]
        };
        // From above, at most 35 degrees off vertical (slope below 1 / sqrt(2)), steeper than
        // every triangle (`max_slope` below): seen along the ray the grid does not fold, so
        // the triangles around the aimed point cover it once. The origin is rounded first, so the
        // only error in the aim is the rounding of the direction: the ray passes within about
        // 1e-7 of the target in f32 even where coordinates are 1e4 and their spacing 1e-3.
        let origin = [
            target[0] + rng.random_range(-1.5..1.5),
            target[1] + rng.random_range(-1.5..1.5),
            target[2] + rng.random_range(3.0..6.0),
        ]
        .map(|x| I::Real::from_f64(x).to_f64());
        let ray: Ray<I::Real> = Ray::new(origin, sub(target, origin)).cast();
        let rd = k.prepare_ray(&ray);
        let at_target = |p: &I::Prim| {
            let hit = k.intersect(p, &ray, &rd, I::Real::INFINITY);
            hit.is_some_and(|h| (h.t.to_f64() - 1.0).abs() <= 1e-2)
        };
        match prims.iter().filter(|&p| at_target(p)).count() {
            0 => missed[n % 2] += 1,
            1 => {}
            _ => doubled[n % 2] += 1,
        }
    }
    [missed, doubled]
}

/// How many rays hit no triangle, through shared edges and through shared vertices.
pub fn cracks<I: Intersector + Default>(
    seed: u64,
    offset: f64,
    mixed_winding: bool,
    rays: usize,
) -> [usize; 2] {
    cracks_and_doubles::<I>(seed, offset, mixed_winding, rays)[0]
}
