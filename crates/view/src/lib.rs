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
        },
        RayLayer {
            name: "rays that missed".into(),
            colour: MISS_COLOUR,
            kind: SegmentKind::Miss,
            segments: misses,
        },
    ]
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
}
