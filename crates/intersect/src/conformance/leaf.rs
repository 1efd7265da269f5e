//! [`Intersector::intersect_leaf`] and [`Intersector::occludes_leaf`] against the loop over a
//! leaf's triangles one by one: the same calls of `found`, in the same order, with the same
//! hits bit for bit and limits lowered between triangles as a closest-hit search lowers them;
//! the same any-hit answer. The leaves sit in a scene as a BVH lays them out for the kernel's
//! blocks: each starts at a multiple of [`Intersector::BLOCK`], with degenerate triangles as
//! padding between them. Kernels with blocks are held to it; for the others it checks the
//! defaults.

use rand::Rng;

use super::group::{bits, rays, triangles};
use super::label;
use super::reference::{rng, triangle};
use crate::{Intersector, Ray, Real, Triangle};

/// One call of `found`: the triangle's position in the leaf and the hit's `(t, u, v)` bits.
type Event = (usize, [u64; 3]);

/// Leaves of 1 to 8 triangles (random ones, the halves of a lattice square whose diagonal
/// rays meet exactly, repeated triangles), laid out as a BVH lays them out for `I`'s blocks,
/// each ray of a random set traced through each leaf: `intersect_leaf` makes the calls of the
/// one-by-one loop, bit for bit, with limits lowered or not, and `occludes_leaf` answers what
/// `occludes` says of the leaf's triangles.
///
/// # Panics
///
/// At the first leaf and ray where they differ.
pub fn leaf_agrees_with_one_by_one<I: Intersector + Default>() {
    let name = label::<I>();
    let k = I::default();
    let mut rng = rng(0x1eaf_0018);
    for case in 0..400 {
        // The scene: up to three leaves, each at a multiple of the block, padded between.
        let mut scene: Vec<Triangle<f64>> = Vec::new();
        let mut leaves = Vec::new();
        for _ in 0..rng.random_range(1..=3) {
            let mut tris = triangles(&mut rng);
            tris.truncate(8);
            if rng.random_bool(0.2) {
                let again = tris[rng.random_range(0..tris.len())];
                tris.push(again);
                tris.truncate(8);
            }
            while !scene.len().is_multiple_of(I::BLOCK) {
                scene.push(Triangle::default());
            }
            leaves.push(scene.len()..scene.len() + tris.len());
            scene.extend(tris);
        }
        let prims: Vec<I::Prim> = scene.iter().map(|t| k.prepare(&t.cast())).collect();
        let blocks = k.prepare_blocks(&prims);
        let aims: Vec<Triangle<f64>> =
            scene.iter().copied().filter(|t| *t != Triangle::default()).collect();
        let aims = if aims.is_empty() { vec![triangle(&mut rng)] } else { aims };
        let lower = case % 2 == 0;
        for ray in rays(&mut rng, &aims) {
            let ray: Ray<I::Real> = ray.cast();
            let data = k.prepare_ray(&ray);
            let start = match rng.random_range(0..3) {
                0 => I::Real::INFINITY,
                _ => I::Real::from_f64(rng.random_range(0.5..6.0)),
            };
            for leaf in &leaves {
                let prims = &prims[leaf.clone()];
                let (mut want, mut want_limit) = (Vec::<Event>::new(), start);
                for (p, prim) in prims.iter().enumerate() {
                    if let Some(h) = k.intersect(prim, &ray, &data, want_limit) {
                        want.push((p, bits(h)));
                        if lower {
                            want_limit = h.t;
                        }
                    }
                }
                let blocks = blocks.get(leaf.start / I::BLOCK..).unwrap_or_default();
                let (mut got, mut got_limit) = (Vec::<Event>::new(), start);
                k.intersect_leaf(prims, blocks, &ray, &data, &mut got_limit, &mut |p, h, limit| {
                    got.push((p, bits(h)));
                    if lower {
                        *limit = h.t;
                    }
                });
                assert_eq!(got, want, "{name}: case {case}, leaf {leaf:?}, {ray:?}: hits");
                assert_eq!(
                    got_limit.to_f64().to_bits(),
                    want_limit.to_f64().to_bits(),
                    "{name}: case {case}, leaf {leaf:?}, {ray:?}: limit"
                );
                let any = prims.iter().any(|p| k.occludes(p, &ray, &data, start));
                assert_eq!(
                    k.occludes_leaf(prims, blocks, &ray, &data, start),
                    any,
                    "{name}: case {case}, leaf {leaf:?}, {ray:?}: any hit"
                );
            }
        }
    }
}
