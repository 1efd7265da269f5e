//! [`Intersector::intersect_group`] against [`Intersector::intersect`]: the hits a group of
//! rays gets from the group call are, ray by ray, the hits of the single-ray loop over the
//! same triangles, bit for bit, with limits lowered between triangles as a closest-hit search
//! lowers them. The kernels that override the default (several rays at once) are held to it;
//! for the others it checks the default.

use rand::Rng;
use rand::seq::SliceRandom;
use rand_pcg::Pcg64;

use super::label;
use super::reference::{point, ray_towards, ray_with_zero_components, rng, triangle};
use crate::vec3::sub;
use crate::{Intersector, Ray, Real, Triangle, TriangleHit};

/// One call of `found`: ray, triangle position, and the hit's `(t, u, v)` as `f64` bits.
type Event = (usize, usize, [u64; 3]);

/// A scene of a few triangles: random ones, or the two halves of a lattice square (whose
/// shared diagonal rays can meet exactly, so that the exact fallback and the tie rule run).
pub(super) fn triangles(rng: &mut Pcg64) -> Vec<Triangle<f64>> {
    if rng.random_bool(0.5) {
        let z = f64::from(rng.random_range(-2..=2));
        let (a, b, c, d) = ([0.0, 0.0, z], [2.0, 0.0, z], [2.0, 2.0, z], [0.0, 2.0, z]);
        let mut tris = vec![Triangle::new(a, b, c), Triangle::new(a, c, d)];
        tris.extend((0..rng.random_range(0..3)).map(|_| triangle(rng)));
        tris
    } else {
        (0..rng.random_range(1..=6)).map(|_| triangle(rng)).collect()
    }
}

/// A group of rays at `tris`: most from one origin (coherent, as a packet's), some towards
/// the lattice square's edges and corners from integer origins (exact zeros), some with zero
/// direction components, and now and then a NaN.
pub(super) fn rays(rng: &mut Pcg64, tris: &[Triangle<f64>]) -> Vec<Ray<f64>> {
    let origin = point(rng, 3.0);
    (0..rng.random_range(1..=70))
        .map(|_| {
            let tri = &tris[rng.random_range(0..tris.len())];
            match rng.random_range(0..10) {
                0..=4 => {
                    let aim = ray_towards(rng, tri);
                    Ray::new(origin, sub(aim.at(1.0), origin))
                }
                5 | 6 => {
                    let o = [0, 1, 2].map(|_| f64::from(rng.random_range(-3..=3)));
                    let target = [0, 1, 2].map(|_| f64::from(rng.random_range(0..=2)));
                    let target = [target[0], target[1], tri.a[2]];
                    Ray::new(o, sub(target, o))
                }
                7 => ray_with_zero_components(rng, tri),
                8 => ray_towards(rng, tri),
                _ => Ray::new(origin, [f64::NAN, 1.0, 0.5]),
            }
        })
        .collect()
}

/// The single-ray loop: each triangle in turn, each ray in turn, with `lower` deciding
/// whether a hit lowers the ray's limit.
fn expected<I: Intersector>(
    k: &I,
    prims: &[I::Prim],
    rays: &[Ray<I::Real>],
    data: &[I::RayData],
    members: &[usize],
    limits: &mut [I::Real],
    lower: bool,
) -> Vec<Event> {
    let mut events = Vec::new();
    for (p, prim) in prims.iter().enumerate() {
        for &r in members {
            if let Some(h) = k.intersect(prim, &rays[r], &data[r], limits[r]) {
                events.push((r, p, bits(h)));
                if lower {
                    limits[r] = h.t;
                }
            }
        }
    }
    events
}

pub(super) fn bits<T: Real>(h: TriangleHit<T>) -> [u64; 3] {
    [h.t, h.u, h.v].map(|x| x.to_f64().to_bits())
}

/// `intersect_group` gives every ray of random groups (1 to 70 rays, coherent and not, exact
/// ties included) the hits and the final limit of the single-ray loop, bit for bit.
///
/// # Panics
///
/// At the first group where they differ.
pub fn group_agrees_with_single_rays<I: Intersector + Default>() {
    let name = label::<I>();
    let k = I::default();
    let mut rng = rng(0x6a_0010);
    for case in 0..600 {
        let tris = triangles(&mut rng);
        let rays: Vec<Ray<I::Real>> = rays(&mut rng, &tris).iter().map(Ray::cast).collect();
        let prims: Vec<I::Prim> = tris.iter().map(|t| k.prepare(&t.cast())).collect();
        let data: Vec<I::RayData> = rays.iter().map(|r| k.prepare_ray(r)).collect();
        let start: Vec<I::Real> = rays
            .iter()
            .map(|_| match rng.random_range(0..3) {
                0 => I::Real::INFINITY,
                _ => I::Real::from_f64(rng.random_range(0.5..6.0)),
            })
            .collect();
        let lower = case % 2 == 0;
        // Every ray, or (one case in three) a subset in a random order, as a packet hands a
        // leaf the rays that reach it: the others must see no call.
        let mut members: Vec<usize> = (0..rays.len()).collect();
        if case % 3 == 1 {
            members.shuffle(&mut rng);
            members.truncate(rng.random_range(1..=rays.len()));
        }
        let mut want_limits = start.clone();
        let mut want = expected(&k, &prims, &rays, &data, &members, &mut want_limits, lower);
        let mut got_limits = start;
        let mut got = Vec::new();
        let mut record = |r, p, h, limit: &mut I::Real| {
            got.push((r, p, bits(h)));
            if lower {
                *limit = h.t;
            }
        };
        k.intersect_group(&prims, &rays, &data, &members, &mut got_limits, &mut record);
        // Per ray in order of triangles; across rays the order is the kernel's.
        want.sort_by_key(|e| (e.0, e.1));
        got.sort_by_key(|e| (e.0, e.1));
        assert_eq!(got, want, "{name}: case {case}: the group's hits");
        let limit_bits = |l: &[I::Real]| l.iter().map(|x| x.to_f64().to_bits()).collect::<Vec<_>>();
        assert_eq!(
            limit_bits(&got_limits),
            limit_bits(&want_limits),
            "{name}: case {case}: limits"
        );
    }
}
