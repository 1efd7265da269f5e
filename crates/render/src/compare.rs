//! Where back ends disagree: the same camera's rays traced by several back ends, compared
//! pixel by pixel.
//!
//! Each back end's render is a [`Hits`]: per pixel, the closest hit's triangle and distance
//! `t`, or a miss ([`trace_hits`], one [`Accel::closest_hit`] per pixel, whatever the image
//! mode). [`compare`] takes the renders of the same rays, in the order the back ends were
//! asked for, and gives a [`Comparison`]:
//!
//! - per pair `(a, b)` (`a` before `b` in that order), a [`PairStats`]: pixels where `a` hits
//!   and `b` misses, where `b` hits and `a` misses, where both hit different triangles
//!   (together the *differing* pixels), and, where both hit the same triangle, how many
//!   distances differ and the largest absolute and relative difference;
//! - the [`Disagreement`]s: every pixel on which any two back ends differ (hit against miss,
//!   or different triangles; a distance alone is not a disagreement), with the ray through it
//!   and every back end's answer, for drawing the rays where back ends disagree.
//!
//! [`diff_image`] draws one pair's differences in the manner of pbrt's `imgtool diff`:
//! black where the pair agrees exactly, [`A_ONLY`] red where only `a` hits, [`B_ONLY`] green
//! where only `b` hits, [`TRIANGLE`] yellow where both hit different triangles, and blue where
//! both hit the same triangle at different distances, from [`DEPTH_MIN_BLUE`] for the
//! smallest difference to 255 for the pair's largest (linear in the difference).
//!
//! Nothing here knows a back end: the caller renders with each and passes the results in.

use core::fmt::Write as _;

use image::RgbImage;
use intersect::{Intersector, Real};

use crate::camera::Camera;
use crate::frame::{FrameError, filled, pixel_count};
use bvh::accel::Accel;

/// One pixel's closest hit.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct PixelHit {
    /// Index of the hit triangle in the mesh.
    pub prim: u32,
    /// Distance along the unit ray (in the back end's precision, widened to `f64`).
    pub t: f64,
}

/// A back end's closest hits for every pixel of a frame, row by row from the top
/// (`index = j * width + i`, as in [`Frame`](crate::frame::Frame)).
#[derive(Clone, Debug, PartialEq)]
pub struct Hits {
    width: u32,
    height: u32,
    pixels: Vec<Option<PixelHit>>,
}

impl Hits {
    /// Hits made of existing values (`width * height` of them).
    ///
    /// # Errors
    ///
    /// As [`Frame::new`](crate::frame::Frame::new) for the size;
    /// [`FrameError::Length`] when the number of values is not `width * height`.
    pub fn from_pixels(
        width: u32,
        height: u32,
        pixels: Vec<Option<PixelHit>>,
    ) -> Result<Self, FrameError> {
        let n = pixel_count(width, height)?;
        if pixels.len() != n {
            return Err(FrameError::Length { width, height, expected: n, found: pixels.len() });
        }
        Ok(Self { width, height, pixels })
    }

    /// Width in pixels.
    #[must_use]
    pub const fn width(&self) -> u32 {
        self.width
    }

    /// Height in pixels.
    #[must_use]
    pub const fn height(&self) -> u32 {
        self.height
    }

    /// The hits in pixel order.
    #[must_use]
    pub fn pixels(&self) -> &[Option<PixelHit>] {
        &self.pixels
    }
}

/// Traces the closest hit of `camera`'s ray through every pixel of a `width x height` frame,
/// in parallel tiles like [`render_frame`](crate::trace::render_frame) (same rays, same
/// `progress` calls, adding up to `width * height`).
///
/// # Errors
///
/// The size errors of [`Frame::new`](crate::frame::Frame::new), or
/// [`FrameError::OutOfMemory`].
pub fn trace_hits<I: Intersector>(
    accel: &Accel<I>,
    camera: &Camera,
    width: u32,
    height: u32,
    progress: &(impl Fn(usize) + Sync),
) -> Result<Hits, FrameError> {
    let n = pixel_count(width, height)?;
    let mut pixels = filled(n, None, width, height, "hit buffer")?;
    crate::trace::fill(&mut pixels, width, height, progress, |i, j| {
        accel
            .closest_hit(&camera.ray::<I::Real>(i, j, width, height))
            .map(|hit| PixelHit { prim: hit.prim, t: hit.t.to_f64() })
    });
    Ok(Hits { width, height, pixels })
}

/// How one pixel compares between two back ends.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PixelDiff {
    /// Both missed, or both hit the same triangle at the same distance.
    Equal,
    /// Only the first back end hit.
    AOnly,
    /// Only the second back end hit.
    BOnly,
    /// Both hit, different triangles.
    Triangle,
    /// Both hit the same triangle, at distances this far apart (`> 0`).
    Depth(f64),
}

impl PixelDiff {
    /// The comparison of `a`'s and `b`'s answers for one pixel.
    #[must_use]
    pub fn of(a: Option<PixelHit>, b: Option<PixelHit>) -> Self {
        match (a, b) {
            (None, None) => PixelDiff::Equal,
            (Some(_), None) => PixelDiff::AOnly,
            (None, Some(_)) => PixelDiff::BOnly,
            (Some(a), Some(b)) if a.prim != b.prim => PixelDiff::Triangle,
            (Some(a), Some(b)) if a.t == b.t => PixelDiff::Equal,
            (Some(a), Some(b)) => PixelDiff::Depth((a.t - b.t).abs()),
        }
    }

    /// Whether the two back ends disagree on what the ray hit (not merely on its distance).
    #[must_use]
    pub const fn disagrees(self) -> bool {
        matches!(self, PixelDiff::AOnly | PixelDiff::BOnly | PixelDiff::Triangle)
    }
}

/// The figures for one pair of back ends (the JSON keys are the field names).
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct PairStats {
    /// The first back end's name.
    pub a: String,
    /// The second back end's name.
    pub b: String,
    /// Pixels where the two disagree: `a_only + b_only + triangle`.
    pub differing: u64,
    /// Pixels `a` hits and `b` misses.
    pub a_only: u64,
    /// Pixels `b` hits and `a` misses.
    pub b_only: u64,
    /// Pixels both hit, on different triangles.
    pub triangle: u64,
    /// Pixels both hit on the same triangle at different distances.
    pub depth_differs: u64,
    /// The largest `|t_a - t_b|` where both hit the same triangle (0 if none differ).
    pub max_depth_diff: f64,
    /// The largest `|t_a - t_b| / max(t_a, t_b)` where both hit the same triangle.
    pub max_rel_depth_diff: f64,
}

impl PairStats {
    /// The figures for `a` against `b`, named `a_name` and `b_name`.
    ///
    /// # Panics
    ///
    /// If the two are not the same size.
    #[must_use]
    pub fn of(a_name: &str, a: &Hits, b_name: &str, b: &Hits) -> Self {
        assert_eq!((a.width, a.height), (b.width, b.height), "hits of different frames");
        let mut s = PairStats {
            a: a_name.to_owned(),
            b: b_name.to_owned(),
            differing: 0,
            a_only: 0,
            b_only: 0,
            triangle: 0,
            depth_differs: 0,
            max_depth_diff: 0.0,
            max_rel_depth_diff: 0.0,
        };
        for (&pa, &pb) in a.pixels.iter().zip(&b.pixels) {
            match PixelDiff::of(pa, pb) {
                PixelDiff::Equal => {}
                PixelDiff::AOnly => s.a_only += 1,
                PixelDiff::BOnly => s.b_only += 1,
                PixelDiff::Triangle => s.triangle += 1,
                PixelDiff::Depth(d) => {
                    s.depth_differs += 1;
                    s.max_depth_diff = s.max_depth_diff.max(d);
                    let (ta, tb) = (pa.map_or(0.0, |h| h.t), pb.map_or(0.0, |h| h.t));
                    s.max_rel_depth_diff = s.max_rel_depth_diff.max(d / ta.max(tb));
                }
            }
        }
        s.differing = s.a_only + s.b_only + s.triangle;
        s
    }
}

/// A pixel on which back ends disagree, with everything needed to draw its ray.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Disagreement {
    /// Column `i` and row `j` (from the top) of the pixel.
    pub pixel: [u32; 2],
    /// The ray's origin (the camera's eye), in the mesh's coordinates, in `f64` (an `f32`
    /// back end traced this rounded to `f32`).
    pub origin: [f64; 3],
    /// The ray's unit direction, in `f64` (rounded likewise).
    pub direction: [f64; 3],
    /// Each back end's answer, in the order of [`Comparison::backends`]: `None` for a miss.
    pub hits: Vec<Option<PixelHit>>,
}

impl Disagreement {
    /// The hit point of back end `k`'s answer, `origin + t * direction`, if it hit.
    #[must_use]
    pub fn hit_point(&self, k: usize) -> Option<[f64; 3]> {
        let hit = self.hits.get(k).copied().flatten()?;
        Some(core::array::from_fn(|c| self.origin[c] + hit.t * self.direction[c]))
    }
}

/// Several back ends' renders of the same rays, compared (see the
/// [module documentation](self)).
#[derive(Clone, Debug, PartialEq)]
pub struct Comparison {
    /// Frame width in pixels.
    pub width: u32,
    /// Frame height in pixels.
    pub height: u32,
    /// The back ends' names, in the order given.
    pub backends: Vec<String>,
    /// Every pair `(a, b)` with `a` before `b`: `(0, 1), (0, 2), ..., (1, 2), ...`.
    pub pairs: Vec<PairStats>,
    /// Every pixel on which some two back ends disagree, in pixel order.
    pub disagreements: Vec<Disagreement>,
}

/// Compares `runs`, each a back end's name and its [`Hits`] for `camera`'s rays (see the
/// [module documentation](self)).
///
/// # Panics
///
/// If the hits are not all the same size.
#[must_use]
pub fn compare(runs: &[(&str, &Hits)], camera: &Camera) -> Comparison {
    let (width, height) = runs.first().map_or((0, 0), |(_, h)| (h.width, h.height));
    assert!(
        runs.iter().all(|(_, h)| (h.width, h.height) == (width, height)),
        "hits of different frames"
    );
    let mut pairs = Vec::new();
    for (k, &(a_name, a)) in runs.iter().enumerate() {
        for &(b_name, b) in &runs[k + 1..] {
            pairs.push(PairStats::of(a_name, a, b_name, b));
        }
    }
    let mut disagreements = Vec::new();
    let n = width as usize * height as usize;
    for p in 0..n {
        let answers: Vec<Option<PixelHit>> = runs.iter().map(|(_, h)| h.pixels[p]).collect();
        let first = answers[0].map(|h| h.prim);
        if answers.iter().all(|h| h.map(|h| h.prim) == first) {
            continue;
        }
        let (i, j) = ((p % width as usize) as u32, (p / width as usize) as u32);
        let ray = camera.ray::<f64>(i, j, width, height);
        disagreements.push(Disagreement {
            pixel: [i, j],
            origin: ray.origin,
            direction: ray.dir,
            hits: answers,
        });
    }
    Comparison {
        width,
        height,
        backends: runs.iter().map(|(name, _)| (*name).to_owned()).collect(),
        pairs,
        disagreements,
    }
}

/// Where only the first back end of a pair hit: red.
pub const A_ONLY: [u8; 3] = [255, 0, 0];
/// Where only the second back end hit: green.
pub const B_ONLY: [u8; 3] = [0, 255, 0];
/// Where both hit different triangles: yellow.
pub const TRIANGLE: [u8; 3] = [255, 255, 0];
/// Where the pair agrees exactly: black.
pub const EQUAL: [u8; 3] = [0, 0, 0];
/// The blue of the smallest distance difference; the pair's largest is 255.
pub const DEPTH_MIN_BLUE: u8 = 64;

/// The diff image of `a` against `b` (colours in the [module documentation](self)).
///
/// # Errors
///
/// [`FrameError::OutOfMemory`] if the image cannot be allocated.
///
/// # Panics
///
/// If the two are not the same size.
pub fn diff_image(a: &Hits, b: &Hits) -> Result<RgbImage, FrameError> {
    assert_eq!((a.width, a.height), (b.width, b.height), "hits of different frames");
    let (w, h) = (a.width, a.height);
    let diffs: Vec<PixelDiff> =
        a.pixels.iter().zip(&b.pixels).map(|(&pa, &pb)| PixelDiff::of(pa, pb)).collect();
    let max =
        diffs.iter().fold(0.0_f64, |m, d| if let PixelDiff::Depth(x) = d { m.max(*x) } else { m });
    let mut buf: Vec<u8> =
        crate::frame::reserve(diffs.len().saturating_mul(3), w, h, "diff image")?;
    for d in diffs {
        buf.extend_from_slice(&match d {
            PixelDiff::Equal => EQUAL,
            PixelDiff::AOnly => A_ONLY,
            PixelDiff::BOnly => B_ONLY,
            PixelDiff::Triangle => TRIANGLE,
            PixelDiff::Depth(x) => {
                let span = f64::from(255 - DEPTH_MIN_BLUE);
                // `as` saturates; x <= max, and max > 0 whenever a Depth exists.
                [0, 0, DEPTH_MIN_BLUE + (span * x / max).round() as u8]
            }
        });
    }
    Ok(RgbImage::from_raw(w, h, buf).expect("the buffer holds width * height pixels"))
}

/// The column headings of [`table`], in order.
pub const TABLE_COLUMNS: [&str; 9] = [
    "a",
    "b",
    "differing",
    "a only",
    "b only",
    "triangle",
    "depth differs",
    "max |dt|",
    "max rel dt",
];

/// The comparison's per-pair figures as a plain-text table, one line per pair under a line of
/// [`TABLE_COLUMNS`], each line ending in a newline. Distances are printed with 3 significant
/// digits (`0` when none differ).
#[must_use]
pub fn table(comparison: &Comparison) -> String {
    let rows: Vec<[String; 9]> = comparison
        .pairs
        .iter()
        .map(|p| {
            [
                p.a.clone(),
                p.b.clone(),
                p.differing.to_string(),
                p.a_only.to_string(),
                p.b_only.to_string(),
                p.triangle.to_string(),
                p.depth_differs.to_string(),
                sci(p.max_depth_diff),
                sci(p.max_rel_depth_diff),
            ]
        })
        .collect();
    let mut widths = TABLE_COLUMNS.map(str::len);
    for row in &rows {
        for (w, cell) in widths.iter_mut().zip(row) {
            *w = (*w).max(cell.len());
        }
    }
    let mut out = String::new();
    let mut line = |cells: [&str; 9]| {
        for (k, (cell, w)) in cells.iter().zip(widths).enumerate() {
            let sep = if k == 0 { "" } else { "  " };
            // Names left-aligned, figures right-aligned.
            if k < 2 {
                let _ = write!(out, "{sep}{cell:<w$}");
            } else {
                let _ = write!(out, "{sep}{cell:>w$}");
            }
        }
        let trimmed = out.trim_end().len();
        out.truncate(trimmed);
        out.push('\n');
    };
    line(TABLE_COLUMNS);
    for row in &rows {
        line(row.each_ref().map(String::as_str));
    }
    out
}

/// `x` with 3 significant digits in scientific notation, `0` for zero.
fn sci(x: f64) -> String {
    if x == 0.0 { "0".to_owned() } else { format!("{x:.2e}") }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn hit(prim: u32, t: f64) -> Option<PixelHit> {
        Some(PixelHit { prim, t })
    }

    /// A 3 x 2 frame: row 0 a miss, a hit, a hit; row 1 hits on triangles 1, 2, 2.
    fn base() -> Hits {
        let px = vec![None, hit(0, 2.0), hit(0, 3.0), hit(1, 4.0), hit(2, 5.0), hit(2, 6.0)];
        Hits::from_pixels(3, 2, px).unwrap()
    }

    /// `base` with one of every kind of difference: pixel 0 hit (b only), pixel 1 missed
    /// (a only), pixel 3 on another triangle, pixels 4 and 5 farther by 0.5 and 0.25.
    fn other() -> Hits {
        let px = vec![hit(7, 1.0), None, hit(0, 3.0), hit(9, 4.0), hit(2, 5.5), hit(2, 6.25)];
        Hits::from_pixels(3, 2, px).unwrap()
    }

    #[test]
    fn sizes_are_checked() {
        assert!(matches!(Hits::from_pixels(2, 2, vec![None; 3]), Err(FrameError::Length { .. })));
        assert!(matches!(Hits::from_pixels(0, 2, vec![]), Err(FrameError::Empty { .. })));
    }

    #[test]
    fn pair_figures_count_each_kind() {
        let s = PairStats::of("x", &base(), "y", &other());
        assert_eq!((s.a.as_str(), s.b.as_str()), ("x", "y"));
        assert_eq!((s.a_only, s.b_only, s.triangle, s.differing), (1, 1, 1, 3));
        assert_eq!(s.depth_differs, 2);
        assert_eq!(s.max_depth_diff, 0.5);
        assert_eq!(s.max_rel_depth_diff, 0.5 / 5.5);
        let same = PairStats::of("x", &base(), "x2", &base());
        assert_eq!((same.differing, same.depth_differs, same.max_depth_diff), (0, 0, 0.0));
    }

    #[test]
    fn diff_image_pixel_by_pixel() {
        let img = diff_image(&base(), &other()).unwrap();
        assert_eq!(img.dimensions(), (3, 2));
        let px = |i, j| img.get_pixel(i, j).0;
        assert_eq!(px(0, 0), B_ONLY);
        assert_eq!(px(1, 0), A_ONLY);
        assert_eq!(px(2, 0), EQUAL);
        assert_eq!(px(0, 1), TRIANGLE);
        assert_eq!(px(1, 1), [0, 0, 255], "the largest depth difference is full blue");
        // 0.25 of 0.5: 64 + 191 / 2 = 159.5, rounded to 160.
        assert_eq!(px(2, 1), [0, 0, 160]);
        let same = diff_image(&base(), &base()).unwrap();
        assert!(same.pixels().all(|p| p.0 == EQUAL));
    }

    #[test]
    fn disagreements_list_every_back_end_and_the_ray() {
        let camera = Camera::origin();
        let (a, b, c) = (base(), other(), base());
        let cmp = compare(&[("a", &a), ("b", &b), ("c", &c)], &camera);
        assert_eq!(cmp.backends, ["a", "b", "c"]);
        let names: Vec<_> = cmp.pairs.iter().map(|p| (p.a.as_str(), p.b.as_str())).collect();
        assert_eq!(names, [("a", "b"), ("a", "c"), ("b", "c")]);
        assert_eq!(cmp.pairs[1].differing, 0);
        // Pixels 0, 1 and 3 disagree; the depth-only pixels 4 and 5 do not.
        let pixels: Vec<[u32; 2]> = cmp.disagreements.iter().map(|d| d.pixel).collect();
        assert_eq!(pixels, [[0, 0], [1, 0], [0, 1]]);
        let d = &cmp.disagreements[2];
        assert_eq!(d.hits, [hit(1, 4.0), hit(9, 4.0), hit(1, 4.0)]);
        let ray = camera.ray::<f64>(0, 1, 3, 2);
        assert_eq!((d.origin, d.direction), (ray.origin, ray.dir));
        let p = d.hit_point(1).unwrap();
        assert!((0..3).all(|k| (p[k] - 4.0 * ray.dir[k]).abs() < 1e-12));
        assert_eq!(cmp.disagreements[1].hit_point(1), None, "b missed pixel 1");
    }

    #[test]
    fn the_table_has_a_line_per_pair() {
        let (a, b) = (base(), other());
        let text = table(&compare(&[("la", &a), ("la-mt", &b)], &Camera::origin()));
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines.len(), 2);
        assert!(lines[0].starts_with("a   b      differing  a only"), "{text}");
        let cells: Vec<&str> = lines[1].split_whitespace().collect();
        assert_eq!(cells, ["la", "la-mt", "3", "1", "1", "1", "2", "5.00e-1", "9.09e-2"]);
    }
}
