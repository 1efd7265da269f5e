//! What a run looked like, for eyes and for other tools: the self-contained HTML viewer page
//! ([`page`]) and the glTF 2.0 binary export ([`glb`]).
//!
//! Both take a [`Run`]: plain data (the mesh, the camera and its image when there is one, any
//! number of named ray layers, the run's figures), filled in by the command-line programs.
//! Nothing here traces a ray: the programs hand over the segments they traced.
//!
//! # The ray sample
//!
//! [`sample_pixels`] picks a deterministic grid of pixels (the same for every run of the same
//! size), so that a page or a `.glb` shows the same rays from one run to the next and two back
//! ends can be compared ray by ray.

#![deny(missing_docs)]

pub mod glb;
pub mod page;

use render::camera::Camera;
use render::compare::Comparison;
use scene::Mesh;

/// What a ray of a layer did.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SegmentKind {
    /// The segment ends at the ray's hit point.
    Hit,
    /// The ray missed: the segment has a fixed length ([`miss_length`]).
    Miss,
}

/// One named set of ray segments, drawn in one colour with a toggle of its own in the page.
#[derive(Clone, Debug, PartialEq)]
pub struct RayLayer {
    /// The name shown beside the layer's toggle.
    pub name: String,
    /// sRGB colour, each channel in `0..=1`.
    pub colour: [f32; 3],
    /// Whether the layer's rays hit or missed: the page draws misses faint, the `.glb` writes
    /// hit points for hits only.
    pub kind: SegmentKind,
    /// Origin and end of each segment, in the mesh's coordinates.
    pub segments: Vec<[[f64; 3]; 2]>,
    /// Whether the page draws the layer faint (the many misses of a ray sample), not solid.
    pub faint: bool,
    /// Whether the page shows the layer when it opens (its toggle starts ticked); the `.glb`
    /// writes every layer.
    pub shown: bool,
}

/// The camera of a run that rendered an image.
#[derive(Clone, Debug, PartialEq)]
pub struct RunCamera {
    /// The camera the rays came from.
    pub camera: Camera,
    /// The point the camera looks at (the orbit's centre in the page).
    pub look_at: [f64; 3],
    /// Image width in pixels.
    pub width: u32,
    /// Image height in pixels.
    pub height: u32,
    /// The rendered image as a PNG file, shown on the camera's image plane.
    pub png: Vec<u8>,
}

/// Everything the page and the `.glb` show of one run.
#[derive(Clone, Debug)]
pub struct Run<'a> {
    /// The mesh as loaded (triangle order as in the file).
    pub mesh: &'a Mesh,
    /// The camera, for `raytrace`; `None` for `raycast` (its rays come from anywhere).
    pub camera: Option<RunCamera>,
    /// The ray layers, drawn in order.
    pub layers: Vec<RayLayer>,
    /// The run's figures as (name, value), shown in the page's panel.
    pub figures: Vec<(String, String)>,
}

/// The default number of rays in a `--view` or `--scene` sample.
pub const DEFAULT_SAMPLE: usize = 2_000;

/// The colour of rays that hit (orange).
pub const HIT_COLOUR: [f32; 3] = [1.0, 0.55, 0.1];

/// The colour of rays that missed (grey-blue; the page also draws them faint).
pub const MISS_COLOUR: [f32; 3] = [0.55, 0.65, 0.8];

/// About `n` pixels of a `width x height` image on a regular grid: the centre pixel of each
/// cell of a grid of square cells, row by row from the top. Every pixel when `n` is at least
/// the pixel count; none when `n` is 0.
#[must_use]
pub fn sample_pixels(width: u32, height: u32, n: usize) -> Vec<(u32, u32)> {
    let pixels = u64::from(width) * u64::from(height);
    if n == 0 || pixels == 0 {
        return Vec::new();
    }
    // The cell side s with (W / s) (H / s) close to n.
    #[allow(clippy::cast_precision_loss)]
    let side = ((pixels as f64 / n as f64).sqrt()).max(1.0);
    let steps = |len: u32| {
        #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
        let cells = ((f64::from(len) / side).round() as u32).clamp(1, len);
        (0..cells).map(move |k| {
            #[allow(clippy::cast_possible_truncation)]
            let p = ((2 * u64::from(k) + 1) * u64::from(len) / (2 * u64::from(cells))) as u32;
            p
        })
    };
    steps(height).flat_map(|j| steps(width).map(move |i| (i, j))).collect()
}

/// About `n` indices of `0..count`, evenly spaced (all of them when `n >= count`).
#[must_use]
pub fn sample_indices(count: usize, n: usize) -> Vec<usize> {
    if n >= count {
        return (0..count).collect();
    }
    (0..n).map(|k| k * count / n).collect()
}

/// The length drawn for a ray that missed: short, the distance from `from` to the near side
/// of the mesh's bounding sphere `(centre, radius)`, so that misses show where they went
/// without hiding the mesh (the sphere's radius when `from` is inside it).
#[must_use]
pub fn miss_length((c, r): ([f64; 3], f64), from: [f64; 3]) -> f64 {
    let d = (0..3).map(|k| (c[k] - from[k]).powi(2)).sum::<f64>().sqrt();
    let len = if d > 2.0 * r { d - r } else { r };
    if len > 0.0 && len.is_finite() { len } else { 1.0 }
}

/// Splits traced rays into a "hits" and a "misses" layer: each ray is its origin, its unit
/// direction and the distance to its hit (`None` for a miss).
#[must_use]
pub fn hit_and_miss_layers(
    mesh: &Mesh,
    rays: impl IntoIterator<Item = ([f64; 3], [f64; 3], Option<f64>)>,
) -> Vec<RayLayer> {
    let sphere = mesh.bounding_sphere();
    let mut hits = Vec::new();
    let mut misses = Vec::new();
    for (o, d, t) in rays {
        let at = |t: f64| [o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2]];
        match t {
            Some(t) => hits.push([o, at(t)]),
            None => misses.push([o, at(miss_length(sphere, o))]),
        }
    }
    vec![
        RayLayer {
            name: "rays that hit".into(),
            colour: HIT_COLOUR,
            kind: SegmentKind::Hit,
            segments: hits,
            faint: false,
            shown: true,
        },
        RayLayer {
            name: "rays that missed".into(),
            colour: MISS_COLOUR,
            kind: SegmentKind::Miss,
            segments: misses,
            faint: true,
            shown: true,
        },
    ]
}

/// The colour of back end `k` of `n` in a comparison's layers: hues evenly spaced around the
/// colour wheel from red (HSV with saturation 0.7 and value 1), so that neighbours in the list
/// differ most when there are few.
#[must_use]
pub fn palette(k: usize, n: usize) -> [f32; 3] {
    #[allow(clippy::cast_precision_loss)]
    let hue = 6.0 * k as f32 / n.max(1) as f32;
    let s = 0.7;
    // HSV to RGB: each channel's distance around the wheel from its own primary.
    let channel = |offset: f32| {
        let d = (hue - offset).rem_euclid(6.0);
        let d = d.min(6.0 - d);
        1.0 - s * (d - 1.0).clamp(0.0, 1.0)
    };
    [channel(0.0), channel(2.0), channel(4.0)]
}

/// How far past the farthest hit among the other back ends a "missed" ray of
/// [`disagreement_layers`] is drawn, as a factor of that distance: far enough to show that the
/// ray passes through the surface where the others stop.
pub const MISS_OVERSHOOT: f64 = 1.25;

/// The layers of a `--compare` run: the rays where back ends disagree, coloured by which back
/// end hit what.
///
/// Of the comparison's disagreeing pixels (about `n` of them, evenly spaced in pixel order,
/// all when there are fewer), each back end gets up to two layers in its [`palette`] colour:
/// "NAME hit", the rays it hit, drawn to its own hit point, and "NAME missed", the rays it
/// missed, drawn (solid: they are few, and the point) through the surface to
/// [`MISS_OVERSHOOT`] times the farthest hit the others found. A crack of a non-watertight
/// kernel is a "missed" ray of that back end passing through the mesh beside another's "hit";
/// two back ends that hit different triangles at an edge show two segments ending at the same
/// place. Empty layers are left out.
#[must_use]
pub fn disagreement_layers(comparison: &Comparison, n: usize) -> Vec<RayLayer> {
    let names = &comparison.backends;
    let mut hits = vec![Vec::new(); names.len()];
    let mut misses = vec![Vec::new(); names.len()];
    let all = &comparison.disagreements;
    for d in sample_indices(all.len(), n).into_iter().map(|k| &all[k]) {
        let farthest = d.hits.iter().flatten().map(|h| h.t).fold(0.0, f64::max);
        let through = farthest * MISS_OVERSHOOT;
        let end = core::array::from_fn(|c| d.origin[c] + through * d.direction[c]);
        for k in 0..names.len() {
            match d.hit_point(k) {
                Some(p) => hits[k].push([d.origin, p]),
                None => misses[k].push([d.origin, end]),
            }
        }
    }
    let mut layers = Vec::new();
    for (k, (hit, miss)) in hits.into_iter().zip(misses).enumerate() {
        let colour = palette(k, names.len());
        for (segments, kind, what) in
            [(hit, SegmentKind::Hit, "hit"), (miss, SegmentKind::Miss, "missed")]
        {
            if !segments.is_empty() {
                let name = format!("{} {what}", names[k]);
                let layer = RayLayer { name, colour, kind, segments, faint: false, shown: true };
                layers.push(layer);
            }
        }
    }
    layers
}

/// The image as PNG bytes, for [`RunCamera::png`].
///
/// # Errors
///
/// If the frame cannot be shown as an 8-bit image or the encoder fails.
pub fn png_of(frame: &render::frame::Frame) -> Result<Vec<u8>, image::ImageError> {
    let img = frame.to_display().map_err(|e| {
        image::ImageError::Parameter(image::error::ParameterError::from_kind(
            image::error::ParameterErrorKind::Generic(e.to_string()),
        ))
    })?;
    let mut png = Vec::new();
    img.write_to(&mut std::io::Cursor::new(&mut png), image::ImageFormat::Png)?;
    Ok(png)
}

/// The mesh's positions as `f32` (the page's and glTF's precision).
pub(crate) fn positions_f32(mesh: &Mesh) -> Vec<[f32; 3]> {
    #[allow(clippy::cast_possible_truncation)]
    mesh.positions.iter().map(|p| p.map(|x| x as f32)).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pixel_samples_are_a_grid_inside_the_image() {
        let s = sample_pixels(640, 480, 2000);
        assert!((1500..2500).contains(&s.len()), "{}", s.len());
        assert!(s.iter().all(|&(i, j)| i < 640 && j < 480));
        assert_eq!(s, sample_pixels(640, 480, 2000));
        assert_eq!(sample_pixels(3, 2, 100).len(), 6);
        assert!(sample_pixels(3, 2, 0).is_empty());
        assert_eq!(sample_pixels(1, 1, 5), vec![(0, 0)]);
        assert_eq!(sample_indices(10, 4), vec![0, 2, 5, 7]);
        assert_eq!(sample_indices(3, 4), vec![0, 1, 2]);
    }

    #[test]
    fn palette_spreads_hues_and_stays_in_range() {
        assert_eq!(palette(0, 3), [1.0, 0.3, 0.3]);
        assert_eq!(palette(1, 3), [0.3, 1.0, 0.3]);
        assert_eq!(palette(2, 3), [0.3, 0.3, 1.0]);
        for k in 0..22 {
            let c = palette(k, 22);
            assert!(c.iter().all(|x| (0.3..=1.0).contains(x)), "{c:?}");
            assert_ne!(c, palette((k + 1) % 22, 22));
        }
    }

    #[test]
    fn disagreement_layers_show_who_hit_what() {
        use render::compare::{Disagreement, PixelHit};
        let ray = |hits: Vec<Option<PixelHit>>| Disagreement {
            pixel: [0, 0],
            origin: [0.0, 0.0, -4.0],
            direction: [0.0, 0.0, 1.0],
            hits,
        };
        let hit = |prim, t| Some(PixelHit { prim, t });
        let comparison = Comparison {
            width: 2,
            height: 1,
            backends: vec!["a".into(), "b".into()],
            pairs: Vec::new(),
            disagreements: vec![
                // A crack of b: a hits at t = 2, b passes through.
                ray(vec![hit(7, 2.0), None]),
                // An edge: both hit at t = 3, different triangles.
                ray(vec![hit(1, 3.0), hit(2, 3.0)]),
            ],
        };
        let layers = disagreement_layers(&comparison, 10);
        let names: Vec<_> = layers.iter().map(|l| l.name.as_str()).collect();
        assert_eq!(names, ["a hit", "b hit", "b missed"]);
        let o = [0.0, 0.0, -4.0];
        assert_eq!(layers[0].segments, [[o, [0.0, 0.0, -2.0]], [o, [0.0, 0.0, -1.0]]]);
        assert_eq!(layers[1].segments, [[o, [0.0, 0.0, -1.0]]]);
        assert_eq!(layers[2].segments, [[o, [0.0, 0.0, -1.5]]]);
        assert_eq!(layers[2].kind, SegmentKind::Miss);
        assert_ne!(layers[0].colour, layers[1].colour);
        assert_eq!(layers[1].colour, layers[2].colour);
        // A sample of one ray keeps the first disagreement only.
        assert_eq!(disagreement_layers(&comparison, 1).len(), 2);
        assert!(disagreement_layers(&comparison, 0).is_empty());
    }
}
