//! A pinhole camera and the exact mapping from pixels to rays.
//!
//! # The contract
//!
//! Given an eye, a point to look at, an up hint and a vertical field of view `fov` (degrees):
//!
//! ```text
//! fwd   = normalize(look_at - eye)
//! right = normalize(cross(up, fwd))
//! up'   = cross(fwd, right)
//! ```
//!
//! Pixel `(i, j)` of a `W x H` image, `i` counted from the left and `j` from the top, is traced
//! through its centre:
//!
//! ```text
//! x   = (2 (i + 0.5) / W - 1) tan(fov / 2) W / H
//! y   = (1 - 2 (j + 0.5) / H) tan(fov / 2)
//! dir = normalize(fwd + x right + y up')
//! ```
//!
//! from origin `eye`. Everything is computed in `f64`; [`Camera::ray`] rounds the result to the
//! tracer's precision at the very end, so an `f32` and an `f64` render shoot the same rays up
//! to one rounding.
//!
//! # Handedness
//!
//! `right x up' = fwd`: the camera's axes (right, up', forward) are ordered like the world's
//! (x, y, z). The [origin camera](Camera::origin) looks along +z with +y up, so +x is on the
//! **right** of the image and +y at the top, as in POV-Ray and Direct3D (a "left-handed"
//! view). A right-handed, OpenGL-style viewer standing at the same place and looking the same
//! way would see +x on the left, that is, this image flipped left to right. Looking along -z
//! (from the +z side, where modelling tools show a model's front), +x is on the left of the
//! image. Concretely: a mesh vertex at `(1, 0, 5)` appears right of the centre
//! of the origin camera's image, and one at `(0, 1, 5)` above it.

use core::ops::Range;

use intersect::vec3::{cross, length, sub};
use intersect::{Ray, Real};

/// The default vertical field of view, in degrees.
pub const DEFAULT_FOV_DEG: f64 = 45.0;

/// How far outside the tightest distance [`Camera::auto`] puts the eye (5 % margin).
pub const AUTO_MARGIN: f64 = 1.05;

/// Why a camera could not be made.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum CameraError {
    /// A coordinate, the field of view, the radius or the aspect ratio is NaN or infinite.
    #[error("camera parameters must be finite numbers")]
    NotFinite,
    /// The eye and the point looked at coincide, so there is no viewing direction.
    #[error("the camera's eye and look-at point coincide")]
    EyeAtLookAt,
    /// The up vector is zero or parallel to the viewing direction.
    #[error("the camera's up vector is zero or parallel to the viewing direction")]
    UpAlongView,
    /// The field of view is not strictly between 0 and 180 degrees.
    #[error("field of view {0} degrees is not strictly between 0 and 180")]
    BadFov(f64),
    /// The aspect ratio (width / height) is not positive.
    #[error("aspect ratio {0} is not positive")]
    BadAspect(f64),
}

/// A pinhole camera: an eye, an orthonormal frame and a vertical field of view.
///
/// ```
/// use render::camera::Camera;
///
/// let cam = Camera::origin();
/// // The centre of an odd-sized image looks straight ahead, along +z.
/// let d = cam.direction(50, 50, 101, 101);
/// assert!((d[2] - 1.0).abs() < 1e-15 && d[0].abs() < 1e-15 && d[1].abs() < 1e-15);
/// // A pixel right of the centre looks towards +x.
/// assert!(cam.direction(90, 50, 101, 101)[0] > 0.0);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera {
    eye: [f64; 3],
    fwd: [f64; 3],
    right: [f64; 3],
    up: [f64; 3],
    fov_deg: f64,
    tan_half: f64,
}

impl Camera {
    /// A camera at `eye` looking at `look_at`, with `up` as the up hint (it need not be
    /// perpendicular to the view, nor unit length) and vertical field of view `fov_deg` degrees.
    ///
    /// # Errors
    ///
    /// [`CameraError`] if a value is not finite, the eye is the look-at point, `up` is zero or
    /// parallel to the view, or the field of view is not strictly between 0 and 180 degrees.
    pub fn look_at(
        eye: [f64; 3],
        look_at: [f64; 3],
        up: [f64; 3],
        fov_deg: f64,
    ) -> Result<Self, CameraError> {
        let all = eye.iter().chain(&look_at).chain(&up).chain(core::iter::once(&fov_deg));
        if !all.copied().all(f64::is_finite) {
            return Err(CameraError::NotFinite);
        }
        if !(fov_deg > 0.0 && fov_deg < 180.0) {
            return Err(CameraError::BadFov(fov_deg));
        }
        let fwd = normalize(sub(look_at, eye)).ok_or(CameraError::EyeAtLookAt)?;
        let right = normalize(cross(up, fwd)).ok_or(CameraError::UpAlongView)?;
        // fwd and right are orthonormal, so their cross product is already unit length.
        let up = cross(fwd, right);
        let tan_half = (fov_deg.to_radians() / 2.0).tan();
        Ok(Self { eye, fwd, right, up, fov_deg, tan_half })
    }

    /// The report's camera: eye at the origin, looking along +z, +y up, 45 degree vertical field
    /// of view.
    #[must_use]
    pub fn origin() -> Self {
        Self::look_at([0.0; 3], [0.0, 0.0, 1.0], [0.0, 1.0, 0.0], DEFAULT_FOV_DEG)
            .expect("the origin camera's parameters are valid")
    }

    /// A camera that frames a bounding sphere (`center`, `radius`) from its -z side, for an
    /// image of the given `aspect` ratio (width / height).
    ///
    /// Placement, exactly: with half-angle `a = min(vfov, hfov) / 2`, where
    /// `tan(hfov / 2) = tan(vfov / 2) * aspect`, the eye is at
    /// `center - (0, 0, dist)` with `dist = AUTO_MARGIN * radius / sin(a)`, looking at
    /// `center` with +y up. At that distance the sphere's silhouette cone has half-angle
    /// `asin(1 / AUTO_MARGIN)` of `a`, so the whole sphere fits the narrower side of the
    /// image with a margin, and the eye is outside the sphere, so every point of the mesh is
    /// in front of it. A radius that is not positive (a mesh collapsed to a point) counts as 1.
    ///
    /// # Errors
    ///
    /// [`CameraError`] if a value is not finite, the field of view is not strictly between 0
    /// and 180 degrees, or the aspect ratio is not positive.
    pub fn auto(
        center: [f64; 3],
        radius: f64,
        fov_deg: f64,
        aspect: f64,
    ) -> Result<Self, CameraError> {
        if !(radius.is_finite() && aspect.is_finite() && fov_deg.is_finite()) {
            return Err(CameraError::NotFinite);
        }
        if !(fov_deg > 0.0 && fov_deg < 180.0) {
            return Err(CameraError::BadFov(fov_deg));
        }
        if aspect <= 0.0 {
            return Err(CameraError::BadAspect(aspect));
        }
        let radius = if radius > 0.0 { radius } else { 1.0 };
        let tan_v = (fov_deg.to_radians() / 2.0).tan();
        let half = tan_v.min(tan_v * aspect).atan();
        let dist = AUTO_MARGIN * radius / half.sin();
        let eye = [center[0], center[1], center[2] - dist];
        Self::look_at(eye, center, [0.0, 1.0, 0.0], fov_deg)
    }

    /// The eye (every ray's origin).
    #[must_use]
    pub const fn eye(&self) -> [f64; 3] {
        self.eye
    }

    /// The unit viewing direction `fwd`.
    #[must_use]
    pub const fn forward(&self) -> [f64; 3] {
        self.fwd
    }

    /// The unit vector pointing to the right of the image.
    #[must_use]
    pub const fn right(&self) -> [f64; 3] {
        self.right
    }

    /// The unit vector pointing to the top of the image (`up'`, perpendicular to `fwd`).
    #[must_use]
    pub const fn up(&self) -> [f64; 3] {
        self.up
    }

    /// The vertical field of view in degrees.
    #[must_use]
    pub const fn fov_deg(&self) -> f64 {
        self.fov_deg
    }

    /// The unit direction of the ray through the centre of pixel `(i, j)` of a
    /// `width x height` image (`i` from the left, `j` from the top), in `f64`.
    ///
    /// Pixels outside the image are allowed: the formula simply extends past the edges.
    ///
    /// # Panics
    ///
    /// Does not panic; a zero `width` or `height` gives NaN components.
    #[must_use]
    pub fn direction(&self, i: u32, j: u32, width: u32, height: u32) -> [f64; 3] {
        let column = self.column(i, width, height);
        unit(core::array::from_fn(|k| column[k] + self.row(j, height)[k]))
    }

    /// The ray through the centre of pixel `(i, j)`, rounded to precision `T` (see
    /// [`Camera::direction`]).
    #[must_use]
    pub fn ray<T: Real>(&self, i: u32, j: u32, width: u32, height: u32) -> Ray<T> {
        Ray::new(self.eye, self.direction(i, j, width, height)).cast()
    }

    /// The rays of every pixel of a `width x height` image, with the work that depends on the
    /// column or the row alone done once (see [`PixelRays`]).
    #[must_use]
    pub fn pixel_rays(&self, width: u32, height: u32) -> PixelRays {
        PixelRays {
            eye: self.eye,
            columns: (0..width).map(|i| self.column(i, width, height)).collect(),
            rows: (0..height).map(|j| self.row(j, height)).collect(),
        }
    }

    /// `fwd + x right` of column `i`: the first two terms of the sum, as `direction` adds them
    /// (`fwd + x right + y up'` is `(fwd + x right) + y up'` in Rust's order).
    #[inline]
    fn column(&self, i: u32, width: u32, height: u32) -> [f64; 3] {
        let (w, h) = (f64::from(width), f64::from(height));
        let x = (2.0 * (f64::from(i) + 0.5) / w - 1.0) * self.tan_half * w / h;
        core::array::from_fn(|k| self.fwd[k] + x * self.right[k])
    }

    /// `y up'` of row `j`.
    #[inline]
    fn row(&self, j: u32, height: u32) -> [f64; 3] {
        let y = (1.0 - 2.0 * (f64::from(j) + 0.5) / f64::from(height)) * self.tan_half;
        self.up.map(|u| y * u)
    }
}

/// The camera rays of one image, made cheaply and exactly: [`PixelRays::direction`] is
/// [`Camera::direction`] bit for bit, with `fwd + x right` computed once per column and
/// `y up'` once per row, so that a pixel costs one addition per component and the
/// normalisation. The same `f64` operations in the same order as the formula's (it is the code
/// `Camera::direction` itself runs), so every image stays the same.
///
/// ```
/// use render::camera::Camera;
///
/// let cam = Camera::origin();
/// let rays = cam.pixel_rays(64, 48);
/// assert_eq!(rays.direction(10, 20), cam.direction(10, 20, 64, 48));
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct PixelRays {
    eye: [f64; 3],
    columns: Vec<[f64; 3]>,
    rows: Vec<[f64; 3]>,
}

impl PixelRays {
    /// [`Camera::direction`] of pixel `(i, j)` of this image.
    ///
    /// # Panics
    ///
    /// If the pixel is outside the image.
    #[must_use]
    #[inline]
    pub fn direction(&self, i: u32, j: u32) -> [f64; 3] {
        let (column, row) = (self.columns[i as usize], self.rows[j as usize]);
        unit(core::array::from_fn(|k| column[k] + row[k]))
    }

    /// [`Camera::ray`] of pixel `(i, j)` of this image.
    ///
    /// # Panics
    ///
    /// If the pixel is outside the image.
    #[must_use]
    #[inline]
    pub fn ray<T: Real>(&self, i: u32, j: u32) -> Ray<T> {
        Ray::new(self.eye, self.direction(i, j)).cast()
    }

    /// [`PixelRays::ray`] of pixels `(i, j)` for `i` in `columns`, written to the start of
    /// `out`, the same bits, [`SEGMENT`] pixels at a time: each component of the sum, the
    /// squared length, its square root and the divisions run lane by lane over the segment
    /// (vector instructions, one pixel per lane), with no branch inside.
    ///
    /// # Panics
    ///
    /// If a pixel is outside the image or `out` is shorter than `columns`.
    #[inline]
    pub fn row_into<T: Real>(&self, j: u32, columns: Range<u32>, out: &mut [Ray<T>]) {
        let row = self.rows[j as usize];
        let first = columns.start as usize;
        let n = columns.len();
        let out = &mut out[..n];
        let origin = self.eye.map(T::from_f64);
        for (start, out) in (first..first + n).step_by(SEGMENT).zip(out.chunks_mut(SEGMENT)) {
            let columns = &self.columns[start..start + out.len()];
            // The direction, squared length and largest component, per lane: the operations of
            // `normalize`, in its order.
            let mut d = [[0.0f64; SEGMENT]; 3];
            let mut len = [0.0f64; SEGMENT];
            let mut ok = true;
            for (lane, c) in columns.iter().enumerate() {
                let v: [f64; 3] = core::array::from_fn(|k| c[k] + row[k]);
                let l = length(v);
                let scale = v.iter().fold(0.0f64, |m, x| m.max(x.abs()));
                ok &= l > 0.0 && l.is_finite() && l > scale * 1e-12;
                for k in 0..3 {
                    d[k][lane] = v[k];
                }
                len[lane] = l;
            }
            assert!(ok, "a pixel direction has length at least 1");
            for (lane, ray) in out.iter_mut().enumerate() {
                let dir = core::array::from_fn(|k| T::from_f64(d[k][lane] / len[lane]));
                *ray = Ray { origin, dir };
            }
        }
    }
}

/// Pixels per step of [`PixelRays::row_into`]: the width of a tile, so that one step makes a
/// tile's row of rays.
pub const SEGMENT: usize = 16;

/// A pixel's `fwd + x right + y up'` normalised: `|d| >= 1` because `fwd` is a unit vector
/// perpendicular to `right` and `up'`.
#[inline]
fn unit(d: [f64; 3]) -> [f64; 3] {
    normalize(d).expect("a pixel direction has length at least 1")
}

/// `v / |v|`, or `None` when `v` is too short to have a direction.
fn normalize(v: [f64; 3]) -> Option<[f64; 3]> {
    let len = length(v);
    // Relative to the largest component: a tiny but well-formed vector still normalises.
    let scale = v.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    (len > 0.0 && len.is_finite() && len > scale * 1e-12).then(|| v.map(|x| x / len))
}

/// Where the camera of a render goes: a base placement, then the values given on top of it
/// (`raytrace`'s `--camera`, `--eye`, `--look-at`, `--up` and `--fov`; the Python module's
/// `Scene.render`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Placement {
    /// The base: [`Camera::auto`] framing the mesh's bounding sphere (`true`), or the
    /// [origin camera](Camera::origin)'s eye and look-at point (`false`).
    pub auto: bool,
    /// The eye, instead of the base's.
    pub eye: Option<[f64; 3]>,
    /// The point looked at, instead of the base's (the sphere's centre, or `(0, 0, 1)`).
    pub look_at: Option<[f64; 3]>,
    /// The up hint, instead of `(0, 1, 0)`.
    pub up: Option<[f64; 3]>,
    /// The vertical field of view in degrees.
    pub fov_deg: f64,
}

/// Why a [`Placement`] gave no camera.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum PlacementError {
    /// The automatic placement failed (a bad field of view or aspect ratio).
    #[error("camera auto: {0}")]
    Auto(CameraError),
    /// The camera from the eye, look-at point, up hint and field of view is not valid.
    #[error("bad camera: {0}")]
    Camera(CameraError),
}

impl Placement {
    /// The camera for a mesh with bounding sphere `sphere` (centre, radius) and an image of
    /// `aspect` ratio (width / height), with the look-at point and up hint it uses.
    ///
    /// # Errors
    ///
    /// [`PlacementError`], with the [`CameraError`] inside.
    pub fn camera(
        &self,
        sphere: ([f64; 3], f64),
        aspect: f64,
    ) -> Result<(Camera, [f64; 3], [f64; 3]), PlacementError> {
        let (center, radius) = sphere;
        let base_eye = if self.auto {
            Camera::auto(center, radius, self.fov_deg, aspect).map_err(PlacementError::Auto)?.eye()
        } else {
            [0.0; 3]
        };
        let eye = self.eye.unwrap_or(base_eye);
        let up = self.up.unwrap_or([0.0, 1.0, 0.0]);
        let look_at = self.look_at.unwrap_or(if self.auto { center } else { [0.0, 0.0, 1.0] });
        let camera =
            Camera::look_at(eye, look_at, up, self.fov_deg).map_err(PlacementError::Camera)?;
        Ok((camera, look_at, up))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The formula of the module documentation, written out once more in the order it is
    /// printed there: the reference `PixelRays` and `Camera::direction` must equal bit for bit.
    fn formula(c: &Camera, i: u32, j: u32, width: u32, height: u32) -> [f64; 3] {
        let (w, h) = (f64::from(width), f64::from(height));
        let x = (2.0 * (f64::from(i) + 0.5) / w - 1.0) * c.tan_half * w / h;
        let y = (1.0 - 2.0 * (f64::from(j) + 0.5) / h) * c.tan_half;
        let d: [f64; 3] = core::array::from_fn(|k| c.fwd[k] + x * c.right[k] + y * c.up[k]);
        let len = length(d);
        d.map(|v| v / len)
    }

    fn test_cameras() -> [Camera; 4] {
        [
            Camera::origin(),
            Camera::look_at([0.3, -1.0, 2.0], [1.0, 1.0, 1.0], [0.2, 0.9, 0.1], 33.0).unwrap(),
            Camera::look_at([1e3, 2e3, -5e2], [0.0; 3], [0.0, 0.0, 1.0], 170.0).unwrap(),
            Camera::auto([0.1, -0.2, 0.3], 0.07, 45.0, 640.0 / 480.0).unwrap(),
        ]
    }

    /// Row segments, whole rows and segments that start and end anywhere (not on a multiple of
    /// `SEGMENT`), in both precisions, against the formula, every pixel of each image.
    #[test]
    fn row_segments_are_the_formula_bit_for_bit() {
        fn check<T: Real>(c: &Camera, n: usize, w: u32, h: u32) {
            let rays = c.pixel_rays(w, h);
            let mut out = vec![Ray::<T>::new([T::ZERO; 3], [T::ZERO; 3]); w as usize + 1];
            for j in 0..h {
                let start = j % w.min(21);
                for columns in [0..w, start..w, start..(start + 17).min(w)] {
                    rays.row_into(j, columns.clone(), &mut out);
                    for (ray, i) in out.iter().zip(columns) {
                        let want = Ray::new(c.eye(), formula(c, i, j, w, h)).cast::<T>();
                        let bits = |r: &Ray<T>| {
                            r.origin
                                .iter()
                                .chain(&r.dir)
                                .map(|x| x.to_f64().to_bits())
                                .collect::<Vec<_>>()
                        };
                        assert_eq!(bits(ray), bits(&want), "camera {n}, {w}x{h}, pixel ({i}, {j})");
                    }
                }
            }
        }
        for (n, c) in test_cameras().iter().enumerate() {
            for (w, h) in [(1, 1), (37, 23), (640, 480), (1024, 1024), (3, 1000)] {
                check::<f64>(c, n, w, h);
                check::<f32>(c, n, w, h);
            }
        }
    }

    /// Exhaustive over whole images: every pixel of each size and camera, every bit.
    #[test]
    fn pixel_rays_are_the_formula_bit_for_bit() {
        for (n, c) in test_cameras().iter().enumerate() {
            for (w, h) in [(1, 1), (37, 23), (640, 480), (1024, 1024), (3, 1000)] {
                let rays = c.pixel_rays(w, h);
                for j in 0..h {
                    for i in 0..w {
                        let want = formula(c, i, j, w, h).map(f64::to_bits);
                        let got = rays.direction(i, j).map(f64::to_bits);
                        assert_eq!(got, want, "camera {n}, {w}x{h}, pixel ({i}, {j})");
                        if (i + j) % 97 == 0 {
                            assert_eq!(c.direction(i, j, w, h).map(f64::to_bits), want);
                            let (a, b) = (rays.ray::<f32>(i, j), c.ray::<f32>(i, j, w, h));
                            assert_eq!((a.origin, a.dir), (b.origin, b.dir));
                        }
                    }
                }
            }
        }
    }

    use intersect::vec3::dot;

    fn close(a: [f64; 3], b: [f64; 3], tol: f64) -> bool {
        (0..3).all(|k| (a[k] - b[k]).abs() <= tol)
    }

    #[test]
    fn origin_camera_axes_are_the_world_axes() {
        let c = Camera::origin();
        assert_eq!(c.eye(), [0.0; 3]);
        assert_eq!(c.forward(), [0.0, 0.0, 1.0]);
        assert_eq!(c.right(), [1.0, 0.0, 0.0]);
        assert_eq!(c.up(), [0.0, 1.0, 0.0]);
        assert_eq!(c.fov_deg(), 45.0);
    }

    #[test]
    fn centre_pixel_looks_forward() {
        let c = Camera::look_at([1.0, 2.0, 3.0], [4.0, -2.0, 3.0], [0.0, 0.0, 1.0], 60.0).unwrap();
        let d = c.direction(100, 40, 201, 81);
        assert!(close(d, [0.6, -0.8, 0.0], 1e-15), "{d:?}");
    }

    #[test]
    fn corner_pixels_follow_the_formula() {
        // Independent reference: the angle from the axis of the ray through the image corner
        // (pixel edge, not centre) is given by tan = tan(fov/2) * sqrt(aspect^2 + 1).
        let (w, h) = (400u32, 200u32);
        let c = Camera::origin();
        let t = (22.5f64).to_radians().tan();
        for (i, j, sx, sy) in [(0, 0, -1.0, 1.0), (w - 1, 0, 1.0, 1.0), (0, h - 1, -1.0, -1.0)] {
            let d = c.direction(i, j, w, h);
            // Pixel centre offsets, written out by hand for this size.
            let x = sx * (1.0 - 1.0 / f64::from(w)) * t * 2.0;
            let y = sy * (1.0 - 1.0 / f64::from(h)) * t;
            let n = (1.0 + x * x + y * y).sqrt();
            assert!(close(d, [x / n, y / n, 1.0 / n], 1e-15), "{i},{j}: {d:?}");
        }
    }

    #[test]
    fn fov_spans_the_image_height_and_aspect_the_width() {
        // Pixel edges: a 2-pixel-high image's rows straddle the centre; extrapolating the
        // centre formula to i = -0.5 is the image edge. Check with a 1-pixel-wide column of
        // very many rows: the first row's angle tends to fov/2.
        let c = Camera::look_at([0.0; 3], [0.0, 0.0, 1.0], [0.0, 1.0, 0.0], 90.0).unwrap();
        let h = 1_000_000;
        let top = c.direction(0, 0, 1, h);
        let angle = top[1].atan2(top[2]).to_degrees();
        assert!((angle - 45.0).abs() < 1e-3, "{angle}");
        // Width 3x height: the horizontal half-angle has tangent 3 * tan(45) = 3.
        let h = 1_000_001;
        let left = c.direction(0, h / 2, 3 * h, h);
        assert!((-left[0] / left[2] - 3.0).abs() < 1e-5, "{left:?}");
        assert!(left[1].abs() < 1e-15);
    }

    #[test]
    fn every_direction_is_unit_and_frame_is_orthonormal() {
        let c = Camera::look_at([0.3, -1.0, 2.0], [1.0, 1.0, 1.0], [0.2, 0.9, 0.1], 33.0).unwrap();
        let (f, r, u) = (c.forward(), c.right(), c.up());
        for (a, b) in [(f, r), (f, u), (r, u)] {
            assert!(dot(a, b).abs() < 1e-15);
        }
        for v in [f, r, u] {
            assert!((dot(v, v) - 1.0).abs() < 1e-15);
        }
        // right x up' = fwd: the documented handedness.
        assert!(close(cross(r, u), f, 1e-15));
        for (i, j) in [(0, 0), (7, 3), (63, 47)] {
            let d = c.direction(i, j, 64, 48);
            assert!((dot(d, d) - 1.0).abs() < 1e-15);
        }
    }

    #[test]
    fn world_x_is_image_right_and_world_y_is_image_top() {
        let c = Camera::origin();
        let (w, h) = (64, 64);
        // Project a point to the pixel whose ray passes nearest to it: search all pixels.
        let nearest = |p: [f64; 3]| {
            let n = normalize(p).unwrap();
            let mut best = (0, 0, -2.0);
            for j in 0..h {
                for i in 0..w {
                    let d = dot(c.direction(i, j, w, h), n);
                    if d > best.2 {
                        best = (i, j, d);
                    }
                }
            }
            (best.0, best.1)
        };
        let (i, j) = nearest([1.0, 0.0, 5.0]);
        assert!(i > w / 2 && (j == h / 2 || j == h / 2 - 1), "{i},{j}");
        let (i, j) = nearest([0.0, 1.0, 5.0]);
        assert!(j < h / 2 && (i == w / 2 || i == w / 2 - 1), "{i},{j}");
    }

    #[test]
    fn auto_frames_the_sphere_with_a_margin() {
        for (aspect, fov) in [(1.0, 45.0), (2.0, 30.0), (0.5, 60.0)] {
            let (center, r) = ([1.0, -2.0, 3.0], 2.5);
            let c = Camera::auto(center, r, fov, aspect).unwrap();
            assert_eq!(c.forward(), [0.0, 0.0, 1.0]);
            let dist = center[2] - c.eye()[2];
            assert_eq!(c.eye()[0], center[0]);
            assert_eq!(c.eye()[1], center[1]);
            // The silhouette's half-angle is asin(r / dist); it must be within the narrower
            // half field of view, and the margin means strictly within.
            let sil = (r / dist).asin().to_degrees();
            let vhalf = fov / 2.0;
            let hhalf = (vhalf.to_radians().tan() * aspect).atan().to_degrees();
            let narrow = vhalf.min(hhalf);
            assert!(sil < narrow && sil > narrow * 0.9, "{sil} vs {narrow}");
            assert!(dist > r);
        }
        let c = Camera::auto([0.0; 3], 0.0, 45.0, 1.0).unwrap();
        assert!(c.eye()[2] < -1.0);
    }

    #[test]
    fn bad_cameras_are_errors() {
        let z = [0.0; 3];
        let (fwd, up) = ([0.0, 0.0, 1.0], [0.0, 1.0, 0.0]);
        assert_eq!(Camera::look_at(z, z, up, 45.0), Err(CameraError::EyeAtLookAt));
        assert_eq!(Camera::look_at(z, fwd, fwd, 45.0), Err(CameraError::UpAlongView));
        assert_eq!(Camera::look_at(z, fwd, z, 45.0), Err(CameraError::UpAlongView));
        assert_eq!(Camera::look_at(z, fwd, up, 180.0), Err(CameraError::BadFov(180.0)));
        assert_eq!(Camera::look_at(z, fwd, up, 0.0), Err(CameraError::BadFov(0.0)));
        assert_eq!(Camera::look_at([f64::NAN; 3], fwd, up, 45.0), Err(CameraError::NotFinite));
        assert_eq!(Camera::auto(z, f64::INFINITY, 45.0, 1.0), Err(CameraError::NotFinite));
        assert_eq!(Camera::auto(z, 1.0, 45.0, 0.0), Err(CameraError::BadAspect(0.0)));
    }

    #[test]
    fn f32_rays_round_the_f64_ray() {
        let c = Camera::origin();
        let r64: Ray<f64> = c.ray(3, 4, 10, 10);
        let r32: Ray<f32> = c.ray(3, 4, 10, 10);
        for k in 0..3 {
            assert_eq!(r32.dir[k], r64.dir[k] as f32);
        }
    }
}
