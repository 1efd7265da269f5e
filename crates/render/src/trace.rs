//! The render loop: one primary ray per pixel, traced in parallel tiles, generic over the back
//! end.
//!
//! [`render_frame`] fills a [`Frame`] for its [`Mode`](crate::frame::Mode):
//!
//! - `alpha`: [`Accel::any_hit`] with `t_max = inf` (the report's image). No hit point is
//!   computed at all.
//! - `depth`: [`Accel::closest_hit`]'s `t`. Camera rays have unit direction (rounded to the
//!   back end's precision), so `t` is the distance from the eye.
//! - `normal`: the unit geometric normal `(b - a) x (c - a)` of the hit triangle, computed in
//!   `f64` from the mesh, **as wound** (not flipped towards the viewer), so inside-out faces
//!   show.
//! - `shade`: Lambert shading, white surface, one directional light and no shadows:
//!   `AMBIENT + (1 - AMBIENT) * max(0, n . l)` in all three channels (see [`AMBIENT`],
//!   [`light_direction`]). `n` is the geometric normal flipped to face the viewer, or, when the
//!   mesh has vertex normals, the barycentric interpolation of the hit triangle's corner
//!   normals (normalised, flipped to the viewer's side of the triangle).
//! - `prim`: the hit triangle's index.
//!
//! Only the nearest hit's triangle is looked up for normals; traversal computes nothing but
//! `t` and barycentrics.
//!
//! # Packets
//!
//! Each tile's rays are traced together, in packets of 8 x 8 pixels
//! ([`Accel::closest_hits_packet`], [`Accel::any_hits_packet`]): the rays of a tile leave one
//! eye in nearly the same direction, so a packet tests each node of the tree once where single
//! rays test it once each. The answers are those of [`Accel::closest_hit`] and
//! [`Accel::any_hit`] per pixel, bit for bit, ties included; only the speed differs.
//!
//! A block whose pixels all lie outside the projection of the BVH's root box, by a margin
//! that covers every rounding (`Footprint`), is a miss without a ray being made: most of a
//! frame where the mesh is small.
//!
//! # Parallelism and progress
//!
//! The image is cut into bands of at most [`TILE`] rows, each traced as a row of
//! `TILE x TILE` tiles (neighbouring rays visit the same BVH nodes, which keeps them in
//! cache). Bands are shared among the threads of the current rayon pool: the caller picks the
//! thread count by running [`render_frame`] inside `ThreadPool::install`. After each tile,
//! `progress` is called with the number of pixels just finished (from any thread), so a
//! caller can drive a progress bar; the calls add up to `width * height`.

use intersect::vec3::{cross, dot, sub};
use intersect::{Hit, Intersector, Ray, Real};
use rayon::prelude::*;
use std::ops::Range;

use crate::camera::{Camera, PixelRays};
use crate::frame::{Frame, FrameData};
use bvh::accel::Accel;
use scene::Mesh;

/// Side of the square tiles traced together, in pixels.
pub const TILE: u32 = 16;

/// The ambient term of `shade`: the brightness of a surface facing away from the light.
pub const AMBIENT: f32 = 0.1;

/// The direction towards the light in `shade` mode, for `camera`: from the upper left and
/// behind the camera, `normalize(-right + up' - fwd)`. A surface facing the camera receives
/// `1 / sqrt(3) = 58 %` of the full light, which leaves room to see the shape.
#[must_use]
pub fn light_direction(camera: &Camera) -> [f64; 3] {
    let (r, u, f) = (camera.right(), camera.up(), camera.forward());
    let l: [f64; 3] = core::array::from_fn(|k| -r[k] + u[k] - f[k]);
    let len = dot(l, l).sqrt();
    l.map(|x| x / len)
}

/// Renders `mesh` as seen by `camera` into `frame`, in `frame`'s mode and size. See the
/// [module documentation](self).
///
/// `accel` must have been built from `mesh`'s triangles in mesh order
/// (`Accel::build(intersector, &mesh.triangles())`): hits name triangles by mesh index.
///
/// # Panics
///
/// If `accel` and `mesh` have different numbers of triangles.
pub fn render_frame<I: Intersector>(
    accel: &Accel<I>,
    mesh: &Mesh,
    camera: &Camera,
    frame: &mut Frame,
    progress: &(impl Fn(usize) + Sync),
) {
    let footprint = Footprint::new(accel, camera, frame.width(), frame.height());
    render_within(accel, mesh, camera, frame, progress, &footprint);
}

/// [`render_frame`] with every block outside `footprint` a miss.
fn render_within<I: Intersector>(
    accel: &Accel<I>,
    mesh: &Mesh,
    camera: &Camera,
    frame: &mut Frame,
    progress: &(impl Fn(usize) + Sync),
    footprint: &Footprint,
) {
    assert_eq!(accel.len(), mesh.len(), "the accelerator was not built from this mesh");
    let (w, h) = (frame.width(), frame.height());
    let inf = <I::Real as Real>::INFINITY;
    // The same rays as `camera.ray(i, j, w, h)`, bit for bit, at a fraction of the cost.
    let rays = camera.pixel_rays(w, h);
    let light = light_direction(camera);
    // Every mode traces its tiles in packets (the rays of a tile leave one eye: coherent);
    // the answers are those of single rays, bit for bit.
    let closest = |rays: &[Ray<I::Real>], out: &mut [Option<Hit<I::Real>>]| {
        accel.closest_hits_packet(rays, inf, out);
    };
    match frame.data_mut() {
        FrameData::Alpha(px) => {
            let any =
                |rays: &[Ray<I::Real>], out: &mut [bool]| accel.any_hits_packet(rays, inf, out);
            fill_traced(px, w, h, progress, (&rays, footprint), any, |_, _, hit| u8::from(hit));
        }
        FrameData::Depth(px) => {
            fill_traced(px, w, h, progress, (&rays, footprint), closest, |_, _, hit| {
                hit.map_or(f32::INFINITY, |hit| hit.t.to_f64() as f32)
            })
        }
        FrameData::Normal(px) => {
            fill_traced(px, w, h, progress, (&rays, footprint), closest, |_, _, hit| {
                hit.map_or([0.0; 3], |hit| {
                    geometric_normal(mesh, hit.prim as usize)
                        .map_or([0.0; 3], |n| n.map(|c| c as f32))
                })
            })
        }
        FrameData::Shade(px) => {
            fill_traced(px, w, h, progress, (&rays, footprint), closest, |i, j, hit| {
                hit.map_or([0.0; 3], |hit| {
                    let dir = rays.direction(i, j);
                    let (u, v) = (hit.u.to_f64(), hit.v.to_f64());
                    let n = shading_normal(mesh, hit.prim as usize, u, v, dir);
                    let lambert = dot(n, light).max(0.0) as f32;
                    [AMBIENT + (1.0 - AMBIENT) * lambert; 3]
                })
            })
        }
        FrameData::Prim(px) => {
            fill_traced(px, w, h, progress, (&rays, footprint), closest, |_, _, hit| {
                hit.map_or(u32::MAX, |hit| hit.prim)
            })
        }
    }
}

/// Side of the square blocks of pixels whose rays are traced as one packet (the packet size
/// of `bvh`, [`bvh::PACKET`], is 8 x 8).
const BLOCK: u32 = 8;

/// Computes every pixel of a `w x h` row-major buffer with `pixel(i, j)`, in parallel bands
/// of tiles, reporting finished pixels to `progress`.
pub(crate) fn fill<P: Send>(
    px: &mut [P],
    w: u32,
    h: u32,
    progress: &(impl Fn(usize) + Sync),
    pixel: impl Fn(u32, u32) -> P + Sync,
) {
    tiles(px, w, h, progress, |rows, (i0, i1), (j0, rows_here)| {
        for dj in 0..rows_here {
            let row = &mut rows[(dj * w) as usize..][..w as usize];
            for i in i0..i1 {
                row[i as usize] = pixel(i, j0 + dj);
            }
        }
    });
}

/// [`fill`] by whole tiles: the camera rays of each tile ([`PixelRays::row_into`], the same
/// rays as `Camera::ray`, a row of a block at a time) are handed to `trace` at once, in
/// [`BLOCK`] x [`BLOCK`] blocks, and each pixel is `pixel(i, j, its answer)`.
fn fill_traced<P: Send, T: Real, Q: Copy + Default>(
    px: &mut [P],
    w: u32,
    h: u32,
    progress: &(impl Fn(usize) + Sync),
    (rays, footprint): (&PixelRays, &Footprint),
    trace: impl Fn(&[Ray<T>], &mut [Q]) + Sync,
    pixel: impl Fn(u32, u32, Q) -> P + Sync,
) {
    tiles(px, w, h, progress, |rows, (i0, i1), (j0, rows_here)| {
        let mut at = Vec::with_capacity((TILE * TILE) as usize);
        let mut tile_rays = Vec::with_capacity((TILE * TILE) as usize);
        let mut segment = [Ray::new([T::ZERO; 3], [T::ZERO; 3]); BLOCK as usize];
        for bj in (0..rows_here).step_by(BLOCK as usize) {
            for bi in (i0..i1).step_by(BLOCK as usize) {
                let columns = bi..(bi + BLOCK).min(i1);
                let n = columns.len();
                let block_rows = j0 + bj..j0 + (bj + BLOCK).min(rows_here);
                if !footprint.may_hit(columns.clone(), block_rows) {
                    for dj in bj..(bj + BLOCK).min(rows_here) {
                        for i in columns.clone() {
                            rows[(dj * w + i) as usize] = pixel(i, j0 + dj, Q::default());
                        }
                    }
                    continue;
                }
                for dj in bj..(bj + BLOCK).min(rows_here) {
                    rays.row_into(j0 + dj, columns.clone(), &mut segment[..n]);
                    tile_rays.extend_from_slice(&segment[..n]);
                    at.extend(columns.clone().map(|i| (i, dj)));
                }
            }
        }
        let mut answers = vec![Q::default(); tile_rays.len()];
        trace(&tile_rays, &mut answers);
        for (&(i, dj), &answer) in at.iter().zip(&answers) {
            rows[(dj * w + i) as usize] = pixel(i, j0 + dj, answer);
        }
    });
}

/// Where in an image the rays may hit the mesh: the projection of the BVH's root box, as a
/// rectangle of pixel coordinates grown by a margin, or the whole image.
///
/// A ray whose pixel centre lies outside the rectangle passes the box at some distance, so the
/// traversal's first box test rejects it: its answer is a miss, found without the ray. The
/// margin, in image-plane units (at unit depth), is 4 pixels plus `1e-5 (1 + scale / z)`,
/// `scale` the largest coordinate of the eye and the box and `z` the box's nearest depth.
/// Rounding the eye to `f32` moves it by at most `1e-7 scale`, which moves an image-plane
/// point by at most `(1 + |x|) 1e-7 scale / z`, under `5e-7 scale / z` with `|x|, |y| < 4`;
/// rounding the direction and the box test's own rounding (relative `6e-8` each) stay under
/// `1e-6`: the margin is 20 times what it must cover. Views where the bound does not hold
/// keep the whole image: a corner of the box not in front of the eye, an image wider or
/// taller than `tan = 4` (about 152 degrees), values not finite.
#[derive(Clone, Copy, Debug)]
struct Footprint {
    /// Pixel coordinates (`i + 0.5` is pixel `i`'s centre) of the rectangle: `x0, x1, y0, y1`.
    rect: [f64; 4],
}

impl Footprint {
    /// The whole image.
    const WHOLE: Self =
        Self { rect: [f64::NEG_INFINITY, f64::INFINITY, f64::NEG_INFINITY, f64::INFINITY] };

    fn new<I: Intersector>(accel: &Accel<I>, camera: &Camera, w: u32, h: u32) -> Self {
        let whole = Self::WHOLE;
        if accel.is_empty() || w == 0 || h == 0 {
            return whole;
        }
        let b = accel.bvh().node_bounds(0);
        let (lo, hi) = (b.min.map(Real::to_f64), b.max.map(Real::to_f64));
        let (eye, fwd, right, up) = (camera.eye(), camera.forward(), camera.right(), camera.up());
        let (fw, fh) = (f64::from(w), f64::from(h));
        let tan_y = (camera.fov_deg().to_radians() / 2.0).tan();
        let tan_x = tan_y * fw / fh;
        if !(tan_x < 4.0 && tan_y < 4.0) {
            return whole;
        }
        let mut scale = eye.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        let (mut x0, mut x1, mut y0, mut y1) =
            (f64::INFINITY, f64::NEG_INFINITY, f64::INFINITY, f64::NEG_INFINITY);
        let mut z_min = f64::INFINITY;
        for corner in 0..8 {
            let p: [f64; 3] =
                core::array::from_fn(|k| if corner >> k & 1 == 0 { lo[k] } else { hi[k] });
            scale = p.iter().fold(scale, |m, x| m.max(x.abs()));
            let d = sub(p, eye);
            let z = dot(d, fwd);
            // Image-plane coordinates: `x` right and `y` up at unit distance.
            let (x, y) = (dot(d, right) / z, dot(d, up) / z);
            if z <= 0.0 || ![x, y, z].iter().all(|v| v.is_finite()) {
                return whole;
            }
            (x0, x1, y0, y1) = (x0.min(x), x1.max(x), y0.min(y), y1.max(y));
            z_min = z_min.min(z);
        }
        if !scale.is_finite() {
            return whole;
        }
        let pixel = 2.0 * tan_y / fh;
        let margin = 4.0 * pixel + 1e-5 * (1.0 + scale / z_min);
        let (x0, x1, y0, y1) = (x0 - margin, x1 + margin, y0 - margin, y1 + margin);
        // Inverting `Camera::direction`'s `x = (2 (i + 0.5) / w - 1) tan_x` and
        // `y = (1 - 2 (j + 0.5) / h) tan_y`; `y` grows downwards in pixels.
        let px = |x: f64| (x / tan_x + 1.0) * fw / 2.0;
        let py = |y: f64| (1.0 - y / tan_y) * fh / 2.0;
        Self { rect: [px(x0), px(x1), py(y1), py(y0)] }
    }

    /// Whether a ray through some pixel of `columns x rows` may hit.
    fn may_hit(&self, columns: Range<u32>, rows: Range<u32>) -> bool {
        let [x0, x1, y0, y1] = self.rect;
        let centre = |k: u32| f64::from(k) + 0.5;
        let (i0, i1) = (centre(columns.start), centre(columns.end - 1));
        let (j0, j1) = (centre(rows.start), centre(rows.end - 1));
        i1 >= x0 && i0 <= x1 && j1 >= y0 && j0 <= y1
    }
}

/// Cuts a `w x h` row-major buffer into bands of tiles shared among the threads; `tile` fills
/// one tile of its band (`rows`, the band's rows): columns `i0..i1`, the band's `rows_here`
/// rows from image row `j0`. Reports each finished tile to `progress`.
fn tiles<P: Send>(
    px: &mut [P],
    w: u32,
    h: u32,
    progress: &(impl Fn(usize) + Sync),
    tile: impl Fn(&mut [P], (u32, u32), (u32, u32)) + Sync,
) {
    debug_assert_eq!(px.len(), w as usize * h as usize);
    // Short bands for short images, so that every thread gets a few to balance the load.
    let threads = rayon::current_num_threads() as u32;
    let band_rows = h.div_ceil(4 * threads).clamp(1, TILE);
    // Tasks of at most four bands (`with_max_len`): where the mesh covers a few bands,
    // rayon's default halving hands them out in two large pieces and one thread finishes
    // late (1.65-1.81x on two threads, `results/README.md`); single bands cost the threads
    // the locality of neighbouring bands (1.88-1.91x on the bunny's `fill` frames).
    let bands = px.par_chunks_mut(band_rows as usize * w as usize).with_max_len(4);
    bands.enumerate().for_each(|(band, rows)| {
        let j0 = band as u32 * band_rows;
        let rows_here = rows.len() as u32 / w;
        for i0 in (0..w).step_by(TILE as usize) {
            let i1 = (i0 + TILE).min(w);
            tile(rows, (i0, i1), (j0, rows_here));
            progress(((i1 - i0) * rows_here) as usize);
        }
    });
}

/// The unit normal `(b - a) x (c - a)` of triangle `index`, or `None` if it has no area.
#[must_use]
fn geometric_normal(mesh: &Mesh, index: usize) -> Option<[f64; 3]> {
    let [a, b, c] = mesh.triangles[index].map(|v| mesh.positions[v as usize]);
    normalize(cross(sub(b, a), sub(c, a)))
}

/// The normal used for shading at barycentrics `(u, v)` of triangle `index`, seen along
/// `dir`: facing the viewer (`n . dir < 0`).
fn shading_normal(mesh: &Mesh, index: usize, u: f64, v: f64, dir: [f64; 3]) -> [f64; 3] {
    // A triangle the kernel hit has area in the back end's precision; should it have none in
    // f64 (cannot happen for f64 back ends), light it as if it faced the viewer.
    let geo = geometric_normal(mesh, index).unwrap_or(dir.map(|x| -x));
    let facing = if dot(geo, dir) > 0.0 { geo.map(|x| -x) } else { geo };
    let Some(normals) = &mesh.normals else { return facing };
    let [na, nb, nc] = normals[index].map(|n| n.map(f64::from));
    let w = 1.0 - u - v;
    let smooth: [f64; 3] = core::array::from_fn(|k| w * na[k] + u * nb[k] + v * nc[k]);
    match normalize(smooth) {
        // Vertex normals may be wound either way: put them on the viewer's side.
        Some(n) if dot(n, facing) < 0.0 => n.map(|x| -x),
        Some(n) => n,
        None => facing,
    }
}

fn normalize(v: [f64; 3]) -> Option<[f64; 3]> {
    let len = dot(v, v).sqrt();
    (len > 0.0 && len.is_finite()).then(|| v.map(|x| x / len))
}

#[cfg(test)]
mod tests {
    use std::sync::atomic::{AtomicUsize, Ordering};

    use intersect::{Algebra, Guarantees, Method, Triangle, TriangleHit};

    use super::*;
    use crate::frame::Mode;

    /// A plain f64 ray-triangle test (Cramer's rule on the 3x3 system), independent of the
    /// back ends: enough for scenes whose answers are known analytically.
    struct Reference;

    impl Intersector for Reference {
        type Real = f64;
        type Prim = Triangle<f64>;
        type RayData = ();
        type Block = ();
        const NAME: &'static str = "reference";
        const ALGEBRA: Algebra = Algebra::La;
        const METHOD: Method = Method::MollerTrumbore;
        const GUARANTEES: Guarantees = Guarantees { watertight: false, exact: false };
        const VARIANT: Option<&'static str> = None;

        fn prepare(&self, tri: &Triangle<f64>) -> Triangle<f64> {
            *tri
        }
        fn prepare_ray(&self, _: &Ray<f64>) {}
        fn intersect(
            &self,
            p: &Triangle<f64>,
            ray: &Ray<f64>,
            _: &(),
            t_max: f64,
        ) -> Option<TriangleHit<f64>> {
            let (e1, e2) = (sub(p.b, p.a), sub(p.c, p.a));
            let s = sub(ray.origin, p.a);
            let m = [e1, e2, ray.dir.map(|x| -x)];
            let det = dot(m[0], cross(m[1], m[2]));
            if det == 0.0 {
                return None;
            }
            let u = dot(s, cross(m[1], m[2])) / det;
            let v = dot(m[0], cross(s, m[2])) / det;
            let t = dot(m[0], cross(m[1], s)) / det;
            (u >= 0.0 && v >= 0.0 && u + v <= 1.0 && t > 0.0 && t <= t_max).then_some(TriangleHit {
                t,
                u,
                v,
            })
        }
    }

    /// A square `[-1, 1]^2` at `z = 4`, two triangles wound towards -z (facing the origin
    /// camera), with optional vertex normals tilted towards +x on the right edge.
    fn square(normals: bool) -> Mesh {
        let obj = if normals {
            "v -1 -1 4\nv 1 -1 4\nv 1 1 4\nv -1 1 4\n\
             vn 0 0 -1\nvn 0.6 0 -0.8\n\
             f 1//1 4//1 3//2\nf 1//1 3//2 2//2\n"
        } else {
            "v -1 -1 4\nv 1 -1 4\nv 1 1 4\nv -1 1 4\nf 1 4 3\nf 1 3 2\n"
        };
        Mesh::from_obj_str(obj, "square.obj").unwrap()
    }

    fn run(mesh: &Mesh, mode: Mode, w: u32, h: u32) -> Frame {
        let accel = Accel::build(Reference, &mesh.triangles());
        let mut frame = Frame::new(mode, w, h).unwrap();
        let done = AtomicUsize::new(0);
        render_frame(&accel, mesh, &Camera::origin(), &mut frame, &|n| {
            done.fetch_add(n, Ordering::Relaxed);
        });
        assert_eq!(done.into_inner(), (w * h) as usize, "progress adds up to the pixel count");
        frame
    }

    /// Whether the origin camera's ray through pixel (i, j) meets the square: it crosses
    /// z = 4 at 4 * (x, y) / z of its direction.
    fn in_square(i: u32, j: u32, w: u32, h: u32) -> bool {
        let d = Camera::origin().direction(i, j, w, h);
        let (x, y) = (4.0 * d[0] / d[2], 4.0 * d[1] / d[2]);
        x.abs() <= 1.0 && y.abs() <= 1.0
    }

    #[test]
    fn alpha_matches_the_analytic_square() {
        // 37 x 23: odd sizes, bands and tiles that do not divide the image.
        let (w, h) = (37, 23);
        let f = run(&square(false), Mode::Alpha, w, h);
        let FrameData::Alpha(px) = f.data() else { panic!() };
        let mut hits = 0;
        for j in 0..h {
            for i in 0..w {
                assert_eq!(px[(j * w + i) as usize] == 1, in_square(i, j, w, h), "({i},{j})");
                hits += u32::from(px[(j * w + i) as usize]);
            }
        }
        assert!(hits > 50 && hits < w * h);
    }

    #[test]
    fn depth_is_the_distance_to_the_plane() {
        let (w, h) = (20, 20);
        let f = run(&square(false), Mode::Depth, w, h);
        let FrameData::Depth(px) = f.data() else { panic!() };
        for j in 0..h {
            for i in 0..w {
                let d = Camera::origin().direction(i, j, w, h);
                let t = px[(j * w + i) as usize];
                if in_square(i, j, w, h) {
                    let expect = 4.0 / d[2];
                    assert!((f64::from(t) - expect).abs() < 1e-5, "({i},{j}) {t} vs {expect}");
                } else {
                    assert_eq!(t, f32::INFINITY);
                }
            }
        }
    }

    #[test]
    fn normal_prim_and_shade_of_a_flat_square() {
        let (w, h) = (16, 16);
        let mesh = square(false);
        let centre = (8 * w + 8) as usize;
        let corner = 0usize;
        assert!(in_square(8, 8, w, h));
        let n = run(&mesh, Mode::Normal, w, h);
        let FrameData::Normal(px) = n.data() else { panic!() };
        assert_eq!(px[centre], [0.0, 0.0, -1.0]);
        assert_eq!(px[corner] == [0.0; 3], !in_square(0, 0, w, h));

        let p = run(&mesh, Mode::Prim, w, h);
        let FrameData::Prim(px) = p.data() else { panic!() };
        // Triangle 0 is (1, 4, 3): the upper-left half (x < y); triangle 1 the lower right.
        assert_eq!(px[(4 * w + 6) as usize], 0, "upper left, above the diagonal");
        assert_eq!(px[(11 * w + 9) as usize], 1, "lower right, below the diagonal");

        let s = run(&mesh, Mode::Shade, w, h);
        let FrameData::Shade(px) = s.data() else { panic!() };
        let expect = AMBIENT + (1.0 - AMBIENT) / 3f32.sqrt();
        assert!((px[centre][0] - expect).abs() < 1e-6, "{:?} vs {expect}", px[centre]);
        assert_eq!(px[centre][0], px[centre][2]);
    }

    #[test]
    fn shade_interpolates_vertex_normals() {
        let (w, h) = (32, 32);
        let s = run(&square(true), Mode::Shade, w, h);
        let FrameData::Shade(px) = s.data() else { panic!() };
        let light = light_direction(&Camera::origin());
        // On each pixel, rebuild the expected value from the analytic hit point.
        for j in 0..h {
            for i in 0..w {
                if !in_square(i, j, w, h) {
                    continue;
                }
                let d = Camera::origin().direction(i, j, w, h);
                let x = 4.0 * d[0] / d[2];
                // Normals are (0,0,-1) at x = -1 and (0.6,0,-0.8) at x = 1, linear in x.
                let s = (x + 1.0) / 2.0;
                let n = normalize([0.6 * s, 0.0, -1.0 + 0.2 * s]).unwrap();
                let expect = AMBIENT + (1.0 - AMBIENT) * dot(n, light).max(0.0) as f32;
                let got = px[(j * w + i) as usize][1];
                assert!((got - expect).abs() < 1e-5, "({i},{j}): {got} vs {expect}");
            }
        }
    }

    #[test]
    fn thread_count_does_not_change_the_image() {
        let mesh = square(true);
        let one = rayon::ThreadPoolBuilder::new().num_threads(1).build().unwrap();
        let three = rayon::ThreadPoolBuilder::new().num_threads(3).build().unwrap();
        for mode in Mode::ALL {
            let a = one.install(|| run(&mesh, mode, 29, 41));
            let b = three.install(|| run(&mesh, mode, 29, 41));
            assert_eq!(a, b, "{mode}");
        }
    }

    /// `n x n` squares of two triangles each tiling `[-s, s]^2` around `(cx, cy)` at depth
    /// `z`, every vertex nudged off the grid so that edges are not all aligned.
    fn grid(n: usize, s: f64, [cx, cy, z]: [f64; 3]) -> Mesh {
        let mut obj = String::new();
        for j in 0..=n {
            for i in 0..=n {
                let nudge = ((i * 7 + j * 13) % 5) as f64 * 0.03 / n as f64;
                let x = cx + s * (2.0 * i as f64 / n as f64 - 1.0 + nudge);
                let y = cy + s * (2.0 * j as f64 / n as f64 - 1.0 - nudge);
                obj.push_str(&format!("v {x} {y} {}\n", z + s * nudge));
            }
        }
        for j in 0..n {
            for i in 0..n {
                let v = |i: usize, j: usize| j * (n + 1) + i + 1;
                let (a, b, c, d) = (v(i, j), v(i + 1, j), v(i + 1, j + 1), v(i, j + 1));
                obj.push_str(&format!("f {a} {d} {c}\nf {a} {c} {b}\n"));
            }
        }
        Mesh::from_obj_str(&obj, "grid.obj").unwrap()
    }

    #[test]
    fn blocks_outside_the_footprint_are_the_misses_they_would_be() {
        let camera = Camera::origin();
        // Small in the frame, off centre, and reaching past the frame's edge; each drawn with
        // and without the footprint.
        let views = [
            (grid(6, 0.3, [0.4, -0.2, 4.0]), camera, 64, 48),
            (grid(6, 0.5, [1.7, 0.9, 4.0]), camera, 40, 40),
            // Far from the origin: the rounding of the eye to f32 matters most here.
            (
                grid(4, 1.0, [1e5, 2e5, 3e5 + 40.0]),
                Camera::look_at([1e5, 2e5, 3e5], [1e5, 2e5, 3e5 + 1.0], [0.0, 1.0, 0.0], 30.0)
                    .unwrap(),
                64,
                64,
            ),
        ];
        for (mesh, camera, w, h) in views {
            let accel = Accel::build(Reference, &mesh.triangles());
            let footprint = Footprint::new(&accel, &camera, w, h);
            assert!(footprint.rect[0].is_finite(), "the footprint is in use");
            let outside = (0..w)
                .step_by(8)
                .flat_map(|i| (0..h).step_by(8).map(move |j| (i, j)))
                .filter(|&(i, j)| !footprint.may_hit(i..(i + 8).min(w), j..(j + 8).min(h)))
                .count();
            assert!(outside > 0, "some block is culled: {:?}", footprint.rect);
            for mode in Mode::ALL {
                let draw = |footprint: &Footprint| {
                    let mut frame = Frame::new(mode, w, h).unwrap();
                    render_within(&accel, &mesh, &camera, &mut frame, &|_| {}, footprint);
                    frame
                };
                let (culled, whole) = (draw(&footprint), draw(&Footprint::WHOLE));
                if let FrameData::Alpha(px) = whole.data() {
                    let hits = px.iter().filter(|&&a| a != 0).count();
                    assert!(hits > 8 && hits < px.len() / 2, "{hits} hits: a view to test");
                }
                assert_eq!(culled, whole, "{mode}");
            }
        }
        // The eye inside the box, or the box behind it: the whole image.
        let mesh = grid(2, 1.0, [0.0, 0.0, 0.0]);
        let accel = Accel::build(Reference, &mesh.triangles());
        let inside = Footprint::new(&accel, &Camera::origin(), 16, 16);
        assert!(inside.rect[0].is_infinite());
    }

    #[test]
    fn light_is_upper_left_and_behind() {
        let l = light_direction(&Camera::origin());
        let k = 1.0 / 3f64.sqrt();
        assert!((l[0] + k).abs() < 1e-15 && (l[1] - k).abs() < 1e-15);
        assert!((l[2] + k).abs() < 1e-15);
    }
}
