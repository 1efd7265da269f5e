//! Tracing an array of rays (`raycast`, and the `wedge` Python module): which rays are
//! misses by definition, the per-ray queries and how each hit is encoded as a row of `f64`.
//!
//! Both programs call [`trace_rays`], so that they give the same bits for the same rays.
//!
//! # Rays
//!
//! A ray is `stride` values, `stride` 6 or 8: origin x, y, z, direction x, y, z, and with 8,
//! `t_min` and `t_max` (only hits with `t_min <= t <= t_max` count; with 6, `0 < t`). Values
//! come as `f32` or `f64` and are rounded to the kernel's precision once ([`files`] reads a
//! file's rays straight into the kernel's precision, so that the trace reads no more bytes
//! per ray than the kernel takes, and [`kernel_ray`] rounds the same way). A ray with a NaN
//! or infinite origin or direction component after that rounding (a finite `f64` can
//! overflow `f32`), a zero direction, or a NaN `t_min` or `t_max`, is a miss
//! ([`kernel_ray`]).
//!
//! # Rows
//!
//! See [`Columns`]: the closest hit is `t, triangle, u, v`, then optionally the hit point and
//! the unit geometric normal; a miss is [`MISS`]. The any-hit query is `1` or `0`, then
//! optionally the index of a triangle hit (`-1` on a miss).

pub mod files;

use bvh::accel::Accel;
use intersect::{Intersector, Ray, Real};
use rayon::prelude::*;
use scene::Mesh;

/// Rays traced between two calls of the progress callback of [`trace_rays`].
pub const RAYS_PER_BLOCK: usize = 4096;

/// The columns of each ray's row, in order.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Columns {
    /// The any-hit query (`1` or `0`) instead of the closest hit (`t, triangle, u, v`).
    pub any_hit: bool,
    /// Closest hit: the hit point x, y, z, `(1 - u - v) a + u b + v c` from the triangle's
    /// vertices in `f64` (NaN on a miss).
    pub point: bool,
    /// Closest hit: the triangle's unit geometric normal `(b - a) x (c - a)`, normalised, in
    /// its winding (NaN on a miss).
    pub normal: bool,
    /// Any hit: the index of a triangle hit, the first found rather than the nearest (`-1`
    /// on a miss).
    pub prim: bool,
}

impl Columns {
    /// Values per row: `1 + prim` for the any-hit query, `4 + 3 point + 3 normal` for the
    /// closest hit (the fields that do not go with the query count for nothing).
    #[must_use]
    pub const fn count(self) -> usize {
        if self.any_hit {
            1 + self.prim as usize
        } else {
            4 + 3 * self.point as usize + 3 * self.normal as usize
        }
    }
}

/// A closest-hit miss's row, as long as the longest row: `+inf, -1`, then NaN.
pub const MISS: [f64; 10] = {
    let mut row = [f64::NAN; 10];
    row[0] = f64::INFINITY;
    row[1] = -1.0;
    row
};

/// A ray in a kernel's precision with its `t_min` and `t_max`.
pub type Segment<T> = (Ray<T>, T, T);

/// The ray `r` (`stride` values in `f32` or `f64`, see the [module documentation](self)) in
/// precision `T` with its segment `t_min, t_max`, or `None` for a ray that is a miss by
/// definition.
///
/// # Panics
///
/// If `r` has fewer than 6 values, or fewer than 8 with `stride` 8.
#[must_use]
// Always inlined: called out of line, its answer went through memory in pieces and was read
// back whole, a store-forwarding stall that cost `raycast` more per ray than a missed ray's
// whole traversal (`results/README.md`, "raycast's per-ray cost").
#[inline(always)]
pub fn kernel_ray<T: Real, V: Real>(r: &[V], stride: usize) -> Option<Segment<T>> {
    let ray: Ray<T> = Ray::new([r[0], r[1], r[2]], [r[3], r[4], r[5]]).cast();
    let bound = |x: V| T::from_f64(x.to_f64());
    let (t_min, t_max) =
        if stride == 8 { (bound(r[6]), bound(r[7])) } else { (T::ZERO, T::INFINITY) };
    // Rounding to f32 can overflow a finite f64 to infinity: check after the cast.
    let finite = ray.origin.iter().chain(&ray.dir).all(|x| x.is_finite());
    let segment = !t_min.is_nan() && !t_max.is_nan();
    (finite && segment && ray.dir != [T::ZERO; 3]).then_some((ray, t_min, t_max))
}

/// Traces `rays` (`stride` values each, see the [module documentation](self)) through
/// `accel`, writing each ray's row of `columns` into `out` in ray order, in parallel blocks
/// of [`RAYS_PER_BLOCK`] rays on the current rayon pool; `progress` is called after each
/// block with the number of rays it held.
///
/// `accel` must have been built from `mesh`'s triangles in mesh order (the hit points and
/// normals are computed from `mesh` in `f64`).
///
/// # Panics
///
/// If `stride` is not 6 or 8, `rays.len()` is not a multiple of it, or `out` does not hold
/// `columns.count()` values per ray.
pub fn trace_rays<I: Intersector, V: Real>(
    accel: &Accel<I>,
    mesh: &Mesh,
    rays: &[V],
    stride: usize,
    columns: Columns,
    out: &mut [f64],
    progress: &(impl Fn(usize) + Sync),
) {
    assert!(stride == 6 || stride == 8, "a ray is 6 or 8 values, not {stride}");
    assert!(rays.len().is_multiple_of(stride), "the rays are not whole rows of {stride}");
    let width = columns.count();
    assert_eq!(out.len(), rays.len() / stride * width, "the output is not one row per ray");
    // Tasks of at most four blocks (`with_max_len`), so that uneven blocks (the rays of a
    // camera where the mesh covers a few rows) are shared out in small pieces, as
    // `render_frame` shares its bands.
    let blocks = rays.par_chunks(stride * RAYS_PER_BLOCK);
    let blocks = blocks.zip(out.par_chunks_mut(width * RAYS_PER_BLOCK)).with_max_len(4);
    blocks.for_each(|(rays, out)| {
        let (ahead, row_ahead) = (rays.as_ptr(), out.as_ptr());
        for (k, (r, h)) in rays.chunks_exact(stride).zip(out.chunks_exact_mut(width)).enumerate() {
            prefetch::<false>(ahead.wrapping_add((k + PREFETCH_AHEAD) * stride).cast());
            prefetch::<true>(row_ahead.wrapping_add((k + PREFETCH_AHEAD) * width).cast());
            let ray = kernel_ray::<I::Real, V>(r, stride);
            if columns.any_hit {
                any_hit_row(accel, ray, columns, h);
            } else {
                closest_hit_row(accel, mesh, ray, columns, h);
            }
        }
        progress(out.len() / width);
    });
}

/// Rays ahead of the one traced whose values and row [`trace_rays`] asks the cache for.
///
/// The rays and rows stream through memory once, a few cache lines per 4 KiB page, and the
/// hardware prefetcher, which stops at page boundaries, left the loads of each page's first
/// rays and the stores of their rows waiting on memory: on rays that miss the mesh, about
/// as long as their trace (`results/README.md`, "`raycast`'s per-ray cost, again"). 64 rays
/// is 2-4 KiB ahead, a page or so.
const PREFETCH_AHEAD: usize = 64;

/// A hint to bring the cache line of `p` into the nearest cache, to be written if `WRITE`.
#[inline(always)]
fn prefetch<const WRITE: bool>(p: *const u8) {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::x86_64::{_MM_HINT_ET0, _MM_HINT_T0, _mm_prefetch};
        // SAFETY: a prefetch reads and writes nothing and never faults, whatever the
        // address (Intel SDM, PREFETCHh and PREFETCHW); SSE is part of x86-64.
        unsafe {
            if WRITE {
                _mm_prefetch::<_MM_HINT_ET0>(p.cast());
            } else {
                _mm_prefetch::<_MM_HINT_T0>(p.cast());
            }
        }
    }
    #[cfg(not(target_arch = "x86_64"))]
    let _ = p;
}

/// The any-hit row of one ray.
fn any_hit_row<I: Intersector>(
    accel: &Accel<I>,
    ray: Option<Segment<I::Real>>,
    columns: Columns,
    h: &mut [f64],
) {
    let found = match ray {
        Some((ray, t_min, t_max)) if columns.prim => accel.any_hit_triangle(&ray, t_min, t_max),
        Some((ray, t_min, t_max)) => accel.any_hit_between(&ray, t_min, t_max).then_some(0),
        None => None,
    };
    h[0] = f64::from(u8::from(found.is_some()));
    if columns.prim {
        h[1] = found.map_or(-1.0, f64::from);
    }
}

/// The closest-hit row of one ray.
fn closest_hit_row<I: Intersector>(
    accel: &Accel<I>,
    mesh: &Mesh,
    ray: Option<Segment<I::Real>>,
    columns: Columns,
    h: &mut [f64],
) {
    let hit = ray.and_then(|(ray, t_min, t_max)| accel.closest_hit_between(&ray, t_min, t_max));
    let Some(hit) = hit else {
        // The first four values as a fixed-size copy: a copy of `h.len()` values is a call
        // to `memcpy` per missing ray, which cost rays that miss the mesh 10% of their rate.
        h[..4].copy_from_slice(&MISS[..4]);
        let width = h.len();
        if width > 4 {
            h[4..].copy_from_slice(&MISS[4..width]);
        }
        return;
    };
    let (u, v) = (hit.u.to_f64(), hit.v.to_f64());
    h[..4].copy_from_slice(&[hit.t.to_f64(), f64::from(hit.prim), u, v]);
    if !(columns.point || columns.normal) {
        return;
    }
    let mut rest = &mut h[4..];
    let [a, b, c] = mesh.triangle::<f64>(hit.prim as usize).vertices();
    if columns.point {
        let w = 1.0 - u - v;
        for k in 0..3 {
            rest[k] = w * a[k] + u * b[k] + v * c[k];
        }
        rest = &mut rest[3..];
    }
    if columns.normal {
        rest[..3].copy_from_slice(&unit_normal(a, b, c));
    }
}

/// `(b - a) x (c - a)`, normalised (NaN for a degenerate triangle, which no ray hits).
#[must_use]
pub fn unit_normal(a: [f64; 3], b: [f64; 3], c: [f64; 3]) -> [f64; 3] {
    let (e1, e2) = (intersect::vec3::sub(b, a), intersect::vec3::sub(c, a));
    let n = intersect::vec3::cross(e1, e2);
    let len = intersect::vec3::dot(n, n).sqrt();
    n.map(|x| x / len)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn row_widths() {
        let c = |any_hit, point, normal, prim| Columns { any_hit, point, normal, prim };
        assert_eq!(c(false, false, false, false).count(), 4);
        assert_eq!(c(false, true, false, false).count(), 7);
        assert_eq!(c(false, true, true, false).count(), 10);
        assert_eq!(c(true, false, false, false).count(), 1);
        assert_eq!(c(true, false, false, true).count(), 2);
    }

    #[test]
    fn misses_by_definition() {
        let ok = [0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.5, 2.0];
        assert!(kernel_ray::<f32, f64>(&ok, 8).is_some());
        let (_, t_min, t_max) = kernel_ray::<f64, f64>(&ok, 6).unwrap();
        assert_eq!((t_min, t_max), (0.0, f64::INFINITY));
        for (k, bad) in [(5, 0.0), (0, f64::NAN), (3, f64::INFINITY), (6, f64::NAN), (7, f64::NAN)]
        {
            let mut r = ok;
            r[k] = bad;
            if k == 5 {
                r[3..6].fill(0.0);
            }
            assert!(kernel_ray::<f64, f64>(&r, 8).is_none(), "component {k} = {bad}");
        }
        // Finite in f64, infinite in f32.
        let mut r = ok;
        r[0] = 1e300;
        assert!(kernel_ray::<f64, f64>(&r, 6).is_some());
        assert!(kernel_ray::<f32, f64>(&r, 6).is_none());
    }
}
