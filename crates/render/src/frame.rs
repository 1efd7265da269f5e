//! [`Frame`]: a rendered image's raw values, one kind per [`Mode`], and their conversion to
//! displayable images.
//!
//! | mode | raw value per pixel ([`FrameData`]) | miss | 8-bit display ([`Frame::to_display`]) |
//! |---|---|---|---|
//! | `alpha` | `u8`: 1 hit, 0 miss | 0 | grey: 255 hit, 0 miss |
//! | `depth` | `f32`: hit distance `t` along the unit ray | `+inf` | grey: nearest hit 255 (white), farthest 0, miss 0 (black) |
//! | `normal` | `[f32; 3]`: the hit triangle's unit geometric normal, as wound | `[0, 0, 0]` | RGB `0.5 n + 0.5`, miss black |
//! | `shade` | `[f32; 3]`: linear radiance in `0..=1` | `[0, 0, 0]` | RGB, sRGB-encoded |
//! | `prim` | `u32`: index of the hit triangle | `u32::MAX` | RGB false colour from a hash of the index, miss black |
//!
//! Pixels are stored row by row from the top, `width` per row (`index = j * width + i`).
//! [`Frame::to_float`] gives the floating-point image written to OpenEXR files.

use core::fmt;
use core::str::FromStr;

use image::{DynamicImage, GrayImage, RgbImage, Rgba32FImage};

/// The largest width or height of a frame. It keeps every pixel index within `u32`, and is
/// also the largest size a JPEG file can record.
pub const MAX_SIDE: u32 = 65_535;

/// What a render computes per pixel. See the [module documentation](self) for the values.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Mode {
    /// Hit or miss (the report's image): any-hit queries only.
    #[default]
    Alpha,
    /// Distance to the nearest hit.
    Depth,
    /// Geometric normal of the nearest hit's triangle.
    Normal,
    /// Lambert shading with one directional light.
    Shade,
    /// Index of the nearest hit's triangle.
    Prim,
}

impl Mode {
    /// Every mode, in documentation order.
    pub const ALL: [Mode; 5] = [Mode::Alpha, Mode::Depth, Mode::Normal, Mode::Shade, Mode::Prim];

    /// The mode's name on command lines: `alpha`, `depth`, `normal`, `shade`, `prim`.
    #[must_use]
    pub const fn name(self) -> &'static str {
        match self {
            Mode::Alpha => "alpha",
            Mode::Depth => "depth",
            Mode::Normal => "normal",
            Mode::Shade => "shade",
            Mode::Prim => "prim",
        }
    }
}

impl fmt::Display for Mode {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Mode {
    type Err = String;

    fn from_str(s: &str) -> Result<Self, String> {
        Mode::ALL.into_iter().find(|m| m.name() == s).ok_or_else(|| {
            format!("unknown mode '{s}' (expected alpha, depth, normal, shade or prim)")
        })
    }
}

/// Why a frame could not be made.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum FrameError {
    /// Width or height is 0.
    #[error("image size {width}x{height} is empty: width and height must be at least 1")]
    Empty {
        /// Requested width.
        width: u32,
        /// Requested height.
        height: u32,
    },
    /// Width or height exceeds [`MAX_SIDE`].
    #[error("image size {width}x{height} is too large: width and height are at most {MAX_SIDE}")]
    TooLarge {
        /// Requested width.
        width: u32,
        /// Requested height.
        height: u32,
    },
    /// [`Frame::from_data`] was given a number of values other than `width * height`.
    #[error("{found} pixel values for a {width}x{height} image ({expected} expected)")]
    Length {
        /// Requested width.
        width: u32,
        /// Requested height.
        height: u32,
        /// `width * height`.
        expected: usize,
        /// Values given.
        found: usize,
    },
    /// The memory for the image could not be reserved.
    #[error("cannot allocate {bytes} bytes for a {width}x{height} {what}")]
    OutOfMemory {
        /// Requested width.
        width: u32,
        /// Requested height.
        height: u32,
        /// Bytes asked for (saturated at `usize::MAX` when the product overflows).
        bytes: usize,
        /// Which buffer: `"alpha frame"`, `"8-bit image"`, ...
        what: &'static str,
    },
}

/// A frame's pixels, one variant per [`Mode`] (see the [module documentation](self)).
#[derive(Clone, Debug, PartialEq)]
pub enum FrameData {
    /// 1 where a ray hit, 0 elsewhere.
    Alpha(Vec<u8>),
    /// Hit distance, `+inf` for a miss.
    Depth(Vec<f32>),
    /// Unit geometric normal, `[0, 0, 0]` for a miss.
    Normal(Vec<[f32; 3]>),
    /// Linear RGB radiance, `[0, 0, 0]` for a miss.
    Shade(Vec<[f32; 3]>),
    /// Triangle index, `u32::MAX` for a miss.
    Prim(Vec<u32>),
}

/// A rendered image: its size and its raw per-pixel values.
#[derive(Clone, Debug, PartialEq)]
pub struct Frame {
    width: u32,
    height: u32,
    data: FrameData,
}

impl Frame {
    /// A frame of `width x height` pixels for `mode`, every pixel set to the mode's miss value.
    ///
    /// The size is checked and the memory reserved without aborting on failure, so a size too
    /// large for the machine is an error, not a crash.
    ///
    /// # Errors
    ///
    /// [`FrameError::Empty`] for a zero side, [`FrameError::TooLarge`] for a side over
    /// [`MAX_SIDE`], [`FrameError::OutOfMemory`] if the pixels cannot be allocated.
    pub fn new(mode: Mode, width: u32, height: u32) -> Result<Self, FrameError> {
        let n = pixel_count(width, height)?;
        let data = match mode {
            Mode::Alpha => FrameData::Alpha(filled(n, 0, width, height, "alpha frame")?),
            Mode::Depth => {
                FrameData::Depth(filled(n, f32::INFINITY, width, height, "depth frame")?)
            }
            Mode::Normal => FrameData::Normal(filled(n, [0.0; 3], width, height, "normal frame")?),
            Mode::Shade => FrameData::Shade(filled(n, [0.0; 3], width, height, "shade frame")?),
            Mode::Prim => FrameData::Prim(filled(n, u32::MAX, width, height, "prim frame")?),
        };
        Ok(Self { width, height, data })
    }

    /// A frame made of existing pixel values.
    ///
    /// # Errors
    ///
    /// As [`Frame::new`] for the size; [`FrameError::Length`] when the number of values is
    /// not `width * height`.
    pub fn from_data(width: u32, height: u32, data: FrameData) -> Result<Self, FrameError> {
        let n = pixel_count(width, height)?;
        let len = match &data {
            FrameData::Alpha(v) => v.len(),
            FrameData::Depth(v) => v.len(),
            FrameData::Normal(v) | FrameData::Shade(v) => v.len(),
            FrameData::Prim(v) => v.len(),
        };
        if len != n {
            return Err(FrameError::Length { width, height, expected: n, found: len });
        }
        Ok(Self { width, height, data })
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

    /// The mode the values belong to.
    #[must_use]
    pub const fn mode(&self) -> Mode {
        match self.data {
            FrameData::Alpha(_) => Mode::Alpha,
            FrameData::Depth(_) => Mode::Depth,
            FrameData::Normal(_) => Mode::Normal,
            FrameData::Shade(_) => Mode::Shade,
            FrameData::Prim(_) => Mode::Prim,
        }
    }

    /// The raw values.
    #[must_use]
    pub const fn data(&self) -> &FrameData {
        &self.data
    }

    /// The raw values, for the render loop to fill.
    pub fn data_mut(&mut self) -> &mut FrameData {
        &mut self.data
    }

    /// The frame as an 8-bit image for PNG and JPEG: greyscale for `alpha` and `depth`, RGB
    /// otherwise (see the [module documentation](self) for each mapping).
    ///
    /// # Errors
    ///
    /// [`FrameError::OutOfMemory`] if the image cannot be allocated.
    pub fn to_display(&self) -> Result<DynamicImage, FrameError> {
        let (w, h) = (self.width, self.height);
        Ok(match &self.data {
            FrameData::Alpha(v) => gray(w, h, v.iter().map(|&a| if a != 0 { 255 } else { 0 }))?,
            FrameData::Depth(v) => {
                let (near, far) = depth_range(v);
                gray(w, h, v.iter().map(|&t| depth_to_u8(t, near, far)))?
            }
            FrameData::Normal(v) => rgb(w, h, v.iter().map(|n| normal_to_u8(*n)))?,
            FrameData::Shade(v) => rgb(w, h, v.iter().map(|c| c.map(linear_to_srgb8)))?,
            FrameData::Prim(v) => rgb(w, h, v.iter().map(|&p| prim_colour(p)))?,
        })
    }

    /// The frame as a floating-point RGBA image for OpenEXR: RGB holds the raw value (`alpha`
    /// 0 or 1, `depth` `t` in all three channels with `+inf` for a miss, `normal` the raw
    /// normal, `shade` the linear radiance, `prim` the false colour of the 8-bit image in
    /// `0..=1`, since an index above 2^24 does not fit an `f32`), A is 1 on a hit and 0 on a
    /// miss.
    ///
    /// # Errors
    ///
    /// [`FrameError::OutOfMemory`] if the image cannot be allocated.
    pub fn to_float(&self) -> Result<Rgba32FImage, FrameError> {
        let (w, h) = (self.width, self.height);
        let n = self.width as usize * self.height as usize;
        let mut out: Vec<f32> = reserve(n.saturating_mul(4), w, h, "float image")?;
        let mut push = |rgb: [f32; 3], hit: bool| {
            out.extend_from_slice(&rgb);
            out.push(if hit { 1.0 } else { 0.0 });
        };
        match &self.data {
            FrameData::Alpha(v) => v.iter().for_each(|&a| push([f32::from(a); 3], a != 0)),
            FrameData::Depth(v) => v.iter().for_each(|&t| push([t; 3], t.is_finite())),
            FrameData::Normal(v) | FrameData::Shade(v) => {
                let hits = self.hit_mask();
                v.iter().zip(hits).for_each(|(c, hit)| push(*c, hit));
            }
            FrameData::Prim(v) => v
                .iter()
                .for_each(|&p| push(prim_colour(p).map(|c| f32::from(c) / 255.0), p != u32::MAX)),
        }
        Ok(Rgba32FImage::from_raw(w, h, out).expect("the buffer holds width * height pixels"))
    }

    /// Whether each pixel's ray hit something, in pixel order. `normal` and `shade` misses are
    /// the all-zero value, which no hit produces (a unit normal is never zero; shading adds an
    /// ambient term to every hit).
    #[must_use]
    pub fn hit_mask(&self) -> Vec<bool> {
        match &self.data {
            FrameData::Alpha(v) => v.iter().map(|&a| a != 0).collect(),
            FrameData::Depth(v) => v.iter().map(|t| t.is_finite()).collect(),
            FrameData::Normal(v) | FrameData::Shade(v) => {
                v.iter().map(|c| *c != [0.0; 3]).collect()
            }
            FrameData::Prim(v) => v.iter().map(|&p| p != u32::MAX).collect(),
        }
    }
}

/// `width * height`, checked against the limits.
pub(crate) fn pixel_count(width: u32, height: u32) -> Result<usize, FrameError> {
    if width == 0 || height == 0 {
        return Err(FrameError::Empty { width, height });
    }
    if width > MAX_SIDE || height > MAX_SIDE {
        return Err(FrameError::TooLarge { width, height });
    }
    usize::try_from(u64::from(width) * u64::from(height))
        .map_err(|_| FrameError::TooLarge { width, height })
}

/// An empty vector with room for `n` values, or an error instead of an abort.
pub(crate) fn reserve<T>(
    n: usize,
    width: u32,
    height: u32,
    what: &'static str,
) -> Result<Vec<T>, FrameError> {
    let mut v = Vec::new();
    v.try_reserve_exact(n).map_err(|_| FrameError::OutOfMemory {
        width,
        height,
        bytes: n.saturating_mul(size_of::<T>()),
        what,
    })?;
    Ok(v)
}

pub(crate) fn filled<T: Clone>(
    n: usize,
    value: T,
    width: u32,
    height: u32,
    what: &'static str,
) -> Result<Vec<T>, FrameError> {
    let mut v = reserve(n, width, height, what)?;
    v.resize(n, value);
    Ok(v)
}

fn gray(w: u32, h: u32, px: impl Iterator<Item = u8>) -> Result<DynamicImage, FrameError> {
    let mut buf = reserve(w as usize * h as usize, w, h, "8-bit image")?;
    buf.extend(px);
    Ok(GrayImage::from_raw(w, h, buf).expect("the buffer holds width * height pixels").into())
}

fn rgb(w: u32, h: u32, px: impl Iterator<Item = [u8; 3]>) -> Result<DynamicImage, FrameError> {
    let mut buf = reserve((w as usize * h as usize).saturating_mul(3), w, h, "8-bit image")?;
    px.for_each(|p| buf.extend_from_slice(&p));
    Ok(RgbImage::from_raw(w, h, buf).expect("the buffer holds width * height pixels").into())
}

/// The nearest and farthest finite depths (`(inf, -inf)` when nothing was hit).
fn depth_range(depths: &[f32]) -> (f32, f32) {
    depths
        .iter()
        .filter(|t| t.is_finite())
        .fold((f32::INFINITY, f32::NEG_INFINITY), |(lo, hi), &t| (lo.min(t), hi.max(t)))
}

/// Nearest hit white, farthest black (a single depth is white), miss black.
fn depth_to_u8(t: f32, near: f32, far: f32) -> u8 {
    if !t.is_finite() {
        return 0;
    }
    let s = if far > near { (far - t) / (far - near) } else { 1.0 };
    unit_to_u8(s)
}

fn normal_to_u8(n: [f32; 3]) -> [u8; 3] {
    if n == [0.0; 3] { [0; 3] } else { n.map(|c| unit_to_u8(0.5 * c + 0.5)) }
}

/// `0..=1` to `0..=255`, rounding to nearest, clamping outside values.
fn unit_to_u8(x: f32) -> u8 {
    // `as` saturates, and maps NaN to 0.
    (x.clamp(0.0, 1.0) * 255.0).round() as u8
}

/// The sRGB transfer function (IEC 61966-2-1) on a linear value in `0..=1`.
fn linear_to_srgb8(c: f32) -> u8 {
    let c = c.clamp(0.0, 1.0);
    let s = if c <= 0.003_130_8 { 12.92 * c } else { 1.055 * c.powf(1.0 / 2.4) - 0.055 };
    unit_to_u8(s)
}

/// A false colour for a triangle index: Fibonacci hashing (multiplication by 2^32 / golden
/// ratio, Knuth) with xor-shifts so that neighbouring indices get unrelated colours, spread
/// over RGB and lifted away from black so that no hit looks like a miss. A miss
/// (`u32::MAX`) is black.
#[must_use]
pub fn prim_colour(index: u32) -> [u8; 3] {
    if index == u32::MAX {
        return [0; 3];
    }
    let mut x = index.wrapping_mul(0x9e37_79b9);
    x ^= x >> 16;
    x = x.wrapping_mul(0x9e37_79b9);
    x ^= x >> 13;
    let [_, r, g, b] = x.to_le_bytes();
    // 48 + c * 207 / 255: every channel at least 48.
    [r, g, b].map(|c| (48 + u32::from(c) * 207 / 255) as u8)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_are_checked() {
        assert_eq!(Frame::new(Mode::Alpha, 0, 5), Err(FrameError::Empty { width: 0, height: 5 }));
        assert_eq!(Frame::new(Mode::Depth, 5, 0), Err(FrameError::Empty { width: 5, height: 0 }));
        assert_eq!(
            Frame::new(Mode::Shade, 100_000, 100_000),
            Err(FrameError::TooLarge { width: 100_000, height: 100_000 })
        );
        let f = Frame::new(Mode::Prim, 3, 2).unwrap();
        assert_eq!((f.width(), f.height(), f.mode()), (3, 2, Mode::Prim));
        assert_eq!(f.data(), &FrameData::Prim(vec![u32::MAX; 6]));
        assert_eq!(
            Frame::from_data(3, 2, FrameData::Alpha(vec![0; 5])),
            Err(FrameError::Length { width: 3, height: 2, expected: 6, found: 5 })
        );
    }

    #[test]
    fn modes_round_trip_through_their_names() {
        for m in Mode::ALL {
            assert_eq!(m.name().parse::<Mode>(), Ok(m));
            assert_eq!(m.to_string(), m.name());
        }
        assert!("colour".parse::<Mode>().unwrap_err().contains("colour"));
    }

    #[test]
    fn depth_display_maps_near_to_white_and_far_to_black() {
        let inf = f32::INFINITY;
        let f = Frame::from_data(4, 1, FrameData::Depth(vec![2.0, 4.0, 3.0, inf])).unwrap();
        let img = f.to_display().unwrap().into_luma8();
        assert_eq!(img.into_raw(), vec![255, 0, 128, 0]);
        let single = Frame::from_data(2, 1, FrameData::Depth(vec![7.0, inf])).unwrap();
        assert_eq!(single.to_display().unwrap().into_luma8().into_raw(), vec![255, 0]);
        let fl = f.to_float().unwrap();
        assert_eq!(fl.get_pixel(1, 0).0, [4.0, 4.0, 4.0, 1.0]);
        assert_eq!(fl.get_pixel(3, 0).0, [inf, inf, inf, 0.0]);
    }

    #[test]
    fn normal_shade_alpha_and_prim_displays() {
        let n =
            Frame::from_data(2, 1, FrameData::Normal(vec![[0.0, 0.0, -1.0], [0.0; 3]])).unwrap();
        assert_eq!(n.to_display().unwrap().into_rgb8().into_raw(), vec![128, 128, 0, 0, 0, 0]);
        assert_eq!(n.hit_mask(), vec![true, false]);
        // sRGB: linear 0.5 encodes to 0.7354 -> 188; 0.002 is on the linear segment -> 7.
        let s = Frame::from_data(1, 1, FrameData::Shade(vec![[0.5, 1.0, 0.002]])).unwrap();
        assert_eq!(s.to_display().unwrap().into_rgb8().into_raw(), vec![188, 255, 7]);
        let a = Frame::from_data(2, 1, FrameData::Alpha(vec![1, 0])).unwrap();
        assert_eq!(a.to_display().unwrap().into_luma8().into_raw(), vec![255, 0]);
        assert_eq!(a.to_float().unwrap().get_pixel(0, 0).0, [1.0, 1.0, 1.0, 1.0]);
        let p = Frame::from_data(2, 1, FrameData::Prim(vec![5, u32::MAX])).unwrap();
        let raw = p.to_display().unwrap().into_rgb8().into_raw();
        assert_eq!(&raw[..3], &prim_colour(5));
        assert_eq!(&raw[3..], &[0, 0, 0]);
    }

    #[test]
    fn prim_colours_differ_and_are_never_black() {
        let colours: std::collections::HashSet<[u8; 3]> = (0..1000).map(prim_colour).collect();
        assert!(colours.len() > 990);
        assert!(colours.iter().all(|c| c.iter().all(|&x| x >= 48)));
        assert_eq!(prim_colour(u32::MAX), [0, 0, 0]);
    }
}
