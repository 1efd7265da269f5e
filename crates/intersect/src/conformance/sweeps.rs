//! Agreement with the independent reference on random rays, and the same rays after the
//! scene is scaled by powers of two and translated far from the world origin.

use super::reference::{is_f32, ray_towards, reference, rng, tolerance, triangle};
use super::{Guarantees, contract::run, label};
use crate::{Intersector, Ray, Real, Triangle};

/// The widest band around the edges, in barycentric units (for rays at least 10% off
/// grazing; it widens as `1 / cos` below that), in which any kernel of the workspace may
/// decide otherwise than the exact answer. An exact kernel may disagree only where the
/// reference's own rounding can (`1e-12`).
fn edge_band<T: Real>(g: &Guarantees) -> f64 {
    if g.exact {
        1e-12
    } else if is_f32::<T>() {
        1e-3
    } else {
        1e-9
    }
}

/// The largest deviations of a kernel from [`reference()`] on random rays, measured by
/// [`deviation`].
#[derive(Clone, Copy, Debug, Default)]
pub struct Deviation {
    /// The widest band around an edge (barycentric units, divided by the conditioning) in
    /// which the kernel decided otherwise than the reference.
    pub band: f64,
    /// The largest relative error of `t`, divided by the conditioning.
    pub t: f64,
    /// The largest error of `u` or `v`, divided by the conditioning.
    pub uv: f64,
    /// Rays decided otherwise than the reference.
    pub disagreements: usize,
    /// Hits (among rays the reference can judge).
    pub hits: usize,
    /// Misses (likewise).
    pub misses: usize,
}

/// `cases` random triangles and rays (seed `0x6a_1001`, [`ray_towards`]) against
/// [`reference()`], rays within 0.01 of grazing left out. Errors grow as the ray grazes the
/// plane: each is divided by the conditioning `max(1, 0.1 / cos)`. A decision otherwise than
/// the reference counts by its distance to the nearest edge, or to the plane for a ray that
/// starts on it.
///
/// # Panics
///
/// If the kernel hits where the reference finds the ray parallel or the triangle degenerate,
/// or fails [`run`]'s checks.
pub fn deviation<I: Intersector + Default>(cases: usize) -> Deviation {
    let name = label::<I>();
    let k = I::default();
    let mut rng = rng(0x6a_1001);
    let mut worst = Deviation::default();
    for _ in 0..cases {
        let tri: Triangle<I::Real> = triangle(&mut rng).cast();
        let ray: Ray<I::Real> = ray_towards(&mut rng, &tri.cast()).cast();
        let got = run(&k, &tri, &ray, I::Real::INFINITY);
        let Some(r) = reference(&tri, &ray) else {
            assert!(got.is_none(), "{name}: hit where the reference has none");
            continue;
        };
        if r.cos < 0.01 {
            continue;
        }
        let conditioning = (0.1 / r.cos).max(1.0);
        if got.is_some() != r.is_hit(f64::INFINITY) {
            let near = r.margin().abs().min(r.t.abs() / r.t.abs().max(1.0)) / conditioning;
            worst.band = worst.band.max(near);
            worst.disagreements += 1;
        }
        let Some(h) = got else {
            worst.misses += 1;
            continue;
        };
        worst.hits += 1;
        let t_err = (h.t.to_f64() - r.t).abs() / r.t.abs() / conditioning;
        let uv_err = (h.u.to_f64() - r.u).abs().max((h.v.to_f64() - r.v).abs()) / conditioning;
        worst.t = worst.t.max(t_err);
        worst.uv = worst.uv.max(uv_err);
    }
    worst
}

/// Random triangles and rays against [`reference()`] ([`deviation`]): the hit/miss decision
/// agrees except within a band of an edge (`1e-3` in `f32`, `1e-9` in `f64`, `1e-12` for an
/// exact kernel), `t` is accurate to ten times [`tolerance`] (thin triangles magnify a
/// kernel's rounding, by different amounts in each) and the barycentrics to ten times the
/// band. A floor every back end meets; a back end's own tests hold it to tighter bounds.
pub fn agrees_with_reference<I: Intersector + Default>(g: &Guarantees) {
    let name = label::<I>();
    let (band, tol) = (edge_band::<I::Real>(g), tolerance::<I::Real>() * 10.0);
    let d = deviation::<I>(20_000);
    assert!(d.hits > 5_000 && d.misses > 5_000, "{name}: {d:?}");
    assert!(d.band <= band, "{name}: decided otherwise {d:?}");
    assert!(d.t <= tol, "{name}: t error {d:?}");
    assert!(d.uv <= band.max(tol) * 10.0, "{name}: (u, v) error {d:?}");
}

/// Scaling the whole scene (vertices, ray origin and direction) by a power of two is exact
/// and changes nothing a kernel should depend on: the answer keeps its bits (`t`, `u`, `v`
/// are ratios of homogeneous expressions), for scales far enough from the precision's
/// overflow and underflow.
pub fn scale_sweep<I: Intersector + Default>() {
    let name = label::<I>();
    let k = I::default();
    let mut rng = rng(0x6a_1004);
    let exponents: &[i32] =
        if is_f32::<I::Real>() { &[-16, -6, -1, 1, 6, 16] } else { &[-120, -30, -1, 1, 30, 120] };
    let mut hits = 0;
    for _ in 0..3_000 {
        let tri: Triangle<I::Real> = triangle(&mut rng).cast();
        let ray: Ray<I::Real> = ray_towards(&mut rng, &tri.cast()).cast();
        let want = run(&k, &tri, &ray, I::Real::INFINITY);
        hits += usize::from(want.is_some());
        for &e in exponents {
            let s = I::Real::from_f64(2f64.powi(e));
            let scale = |p: [I::Real; 3]| p.map(|x| x * s);
            let big = Triangle::new(scale(tri.a), scale(tri.b), scale(tri.c));
            let far = Ray::new(scale(ray.origin), scale(ray.dir));
            let got = run(&k, &big, &far, I::Real::INFINITY);
            assert_eq!(got, want, "{name}: scaled by 2^{e}: {tri:?} {ray:?}");
        }
    }
    assert!(hits > 1_000, "{name}: only {hits} hits");
}

/// The scene and the rays translated by `10^k` scene sizes (`k` = 1 to 3) on every axis:
/// the decision agrees with the reference away from the edges (1% of the triangle, divided by
/// the cosine of the ray's angle to the normal) and from
/// the plane, and `t` stays accurate to a thousand times [`tolerance`] (a kernel measuring
/// from the world origin loses about three digits there; one measuring from a vertex or the
/// ray's origin keeps them, as its own tests say).
pub fn translation_sweep<I: Intersector + Default>() {
    let name = label::<I>();
    let k = I::default();
    let mut rng = rng(0x6a_1003);
    let tol = tolerance::<I::Real>() * 1e3;
    for shift in [2e1, 2e2, 2e3] {
        let mut hits = 0;
        for _ in 0..5_000 {
            let t0 = triangle(&mut rng);
            let r0 = ray_towards(&mut rng, &t0);
            let moved = |p: [f64; 3]| p.map(|x| x + shift);
            let tri: Triangle<I::Real> =
                Triangle::new(moved(t0.a), moved(t0.b), moved(t0.c)).cast();
            let ray: Ray<I::Real> = Ray::new(moved(r0.origin), r0.dir).cast();
            let Some(r) = reference(&tri, &ray) else { continue };
            // Away from the edges relative to the conditioning: grazing rays magnify the
            // rounding of coordinates that are 10^3 times the triangle's size.
            if r.cos < 0.05 || r.margin().abs() * r.cos < 1e-2 || r.t.abs() < 1e-2 {
                continue;
            }
            let got = run(&k, &tri, &ray, I::Real::INFINITY);
            assert_eq!(got.is_some(), r.is_hit(f64::INFINITY), "{name}: at {shift}, {r:?}");
            if let Some(h) = got {
                let err = (h.t.to_f64() - r.t).abs() / r.t;
                assert!(err <= tol, "{name}: t error {err:e} at {shift}, {r:?} got {h:?}");
                hits += 1;
            }
        }
        assert!(hits > 500, "{name}: only {hits} hits at {shift}");
    }
}
