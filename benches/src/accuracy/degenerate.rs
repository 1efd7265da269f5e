//! Degenerate and hostile input: zero-area, collinear and needle triangles, repeated
//! vertices, huge triangles beside tiny ones, NaN and infinite vertices and rays, odd `t_max`.

use intersect::{Ray, Triangle};

use super::rays::below;
use super::runner::Pair;
use crate::SplitMix64;

/// Triangles and rays to be tested pair by pair (no BVH: a BVH may rightly skip a triangle
/// with NaN coordinates, and here every kernel must see every pair).
#[derive(Clone, Debug, PartialEq)]
pub struct Soup {
    /// Each triangle with the name of its kind.
    pub triangles: Vec<(&'static str, Triangle<f64>)>,
    /// Each ray with the name of its kind.
    pub rays: Vec<(&'static str, Ray<f64>)>,
    /// The `t_max` values every pair is tested with.
    pub t_maxes: Vec<f64>,
}

/// The kinds of triangle in a [`Soup`], each placed `copies` times at random lattice
/// positions (integer multiples of `2^-4`, so the constructions below stay exact), and rays:
/// `rays_per_triangle` aimed at each triangle's centroid from random points, plus rays with
/// NaN, infinite, zero, subnormal and huge components.
///
/// Triangle kinds (`*` marks the degenerate ones, which must never be hit):
/// `point*` (three equal vertices), `repeated-vertex*` (two equal), `collinear*` (the middle
/// vertex the exact midpoint), `collinear-far*` (`c = a + 3 (b - a)`), `needle` (height
/// `2^-30` of its length), `needle-f32` (height one `f32` ulp of its length), `huge`
/// (coordinates up to `1e18`), `tiny` (size `2^-60`, about `1e-18`, beside the huge one),
/// `subnormal-f32` (size `1e-40`: subnormal in `f32`), `f32-max` (coordinates near `f32::MAX`),
/// `nan-vertex*`, `inf-vertex*` (the reference counts non-finite triangles as degenerate).
#[must_use]
pub fn soup(copies: usize, rays_per_triangle: usize, seed: u64) -> Soup {
    let mut rng = SplitMix64::new(seed);
    let mut triangles = Vec::new();
    for _ in 0..copies {
        let lattice = |rng: &mut SplitMix64| -> [f64; 3] {
            core::array::from_fn(|_| (below(rng, 64) as f64 - 32.0) / 16.0)
        };
        let (a, b) = (lattice(&mut rng), lattice(&mut rng));
        let mut c = lattice(&mut rng);
        if a == b {
            continue;
        }
        if c == a || c == b {
            c = [a[0] + 1.0, a[1] - 0.5, a[2] + 0.25];
        }
        let mid: [f64; 3] = core::array::from_fn(|k| 0.5 * (a[k] + c[k]));
        let far: [f64; 3] = core::array::from_fn(|k| a[k] + 3.0 * (b[k] - a[k]));
        let len = 1.0 + below(&mut rng, 4) as f64;
        let z = (below(&mut rng, 16) as f64) / 4.0;
        let huge = 1e18 * (1.0 + below(&mut rng, 4) as f64);
        // 2^-50 + 2^-60 is exact in f32 and f64: a triangle of size 1e-18 that stays one.
        let (t0, tiny) = (2f64.powi(-50), 2f64.powi(-60));
        triangles.extend([
            ("point", Triangle::new(a, a, a)),
            ("repeated-vertex", Triangle::new(a, b, a)),
            ("collinear", Triangle::new(a, mid, c)),
            ("collinear-far", Triangle::new(a, b, far)),
            ("needle", Triangle::new([0.0, 0.0, z], [len, 0.0, z], [0.5, 2f64.powi(-30), z])),
            (
                "needle-f32",
                Triangle::new(
                    [0.0, z, 0.0],
                    [len, z, 0.0],
                    [0.25, z, len * f64::from(f32::EPSILON)],
                ),
            ),
            ("huge", Triangle::new([-huge, -huge, z], [huge, -huge, z], [0.0, huge, z])),
            ("tiny", Triangle::new([t0, t0, z], [t0 + tiny, t0, z], [t0, t0 + tiny, z])),
            ("subnormal-f32", Triangle::new([0.0, 0.0, z], [1e-40, 0.0, z], [0.0, 1e-40, z])),
            ("f32-max", Triangle::new([-3e38, -3e38, z], [3e38, -3e38, z], [0.0, 3e38, z])),
            ("nan-vertex", Triangle::new(a, b, [c[0], f64::NAN, c[2]])),
            ("inf-vertex", Triangle::new(a, [f64::INFINITY, b[1], b[2]], c)),
        ]);
    }
    let mut rays = Vec::new();
    for (_, tri) in &triangles {
        let [a, b, c] = tri.vertices();
        let centroid: [f64; 3] = core::array::from_fn(|k| (a[k] + b[k] + c[k]) / 3.0);
        for _ in 0..rays_per_triangle {
            let origin: [f64; 3] = core::array::from_fn(|k| centroid[k] + rng.range(-4.0, 4.0));
            let dir: [f64; 3] = core::array::from_fn(|k| centroid[k] - origin[k]);
            rays.push(("aimed", Ray::new(origin, dir)));
        }
    }
    let (o, d) = ([0.25, 0.25, -1.0], [0.0, 0.0, 1.0]);
    rays.extend([
        ("nan-origin", Ray::new([f64::NAN, 0.25, -1.0], d)),
        ("inf-origin", Ray::new([0.25, f64::INFINITY, -1.0], d)),
        ("nan-dir", Ray::new(o, [0.0, f64::NAN, 1.0])),
        ("inf-dir", Ray::new(o, [0.0, 0.0, f64::INFINITY])),
        ("zero-dir", Ray::new(o, [0.0; 3])),
        ("subnormal-dir", Ray::new(o, [0.0, 0.0, 1e-310])),
        ("huge-dir", Ray::new(o, [1e-3, 0.0, 1e300])),
        ("huge-origin", Ray::new([1e300, 0.25, -1.0], [-1.0, 0.0, 1e-300])),
    ]);
    let t_maxes = vec![f64::INFINITY, 1e10, 2.0, 0.0, -1.0, f64::NAN];
    Soup { triangles, rays, t_maxes }
}

impl Soup {
    /// Every (triangle, ray, `t_max`) combination, in that nesting order, with the name of
    /// the triangle's kind.
    #[must_use]
    pub fn pairs(&self) -> Vec<(&'static str, Pair)> {
        let mut out = Vec::new();
        for (kind, tri) in &self.triangles {
            for (_, ray) in &self.rays {
                for &t_max in &self.t_maxes {
                    out.push((*kind, Pair { ray: *ray, tri: *tri, t_max }));
                }
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use exact::Exact;
    use intersect::Intersector;

    #[test]
    fn the_reference_agrees_on_which_kinds_are_degenerate() {
        let soup = soup(4, 1, 9);
        for (kind, tri) in &soup.triangles {
            let hittable = Exact.prepare(tri).is_hittable();
            let degenerate =
                matches!(*kind, "point" | "repeated-vertex" | "collinear" | "collinear-far")
                    || kind.ends_with("-vertex") && *kind != "repeated-vertex";
            assert_eq!(hittable, !degenerate, "{kind}: {tri:?}");
        }
    }
}
