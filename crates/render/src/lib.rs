//! Camera, render loop and outputs, generic over the [`Intersector`](intersect::Intersector)
//! seam. Meshes come from the `scene` crate, the ray queries from `bvh`'s `Accel`.
//!
//! # Modules
//!
//! - [`camera`]: a pinhole camera and the exact pixel-to-ray mapping.
//! - [`frame`]: per-pixel results of a render.
//! - [`trace`]: the render loop, [`trace::render_frame`].
//! - [`output`]: image and data writers.
//! - [`compare`]: several back ends' renders of the same rays, compared pixel by pixel.
//! - [`cast`]: arrays of rays traced, each hit encoded as a row (`raycast`, the Python module).

#![deny(missing_docs)]

pub mod camera;
pub mod cast;
pub mod compare;
pub mod frame;
pub mod output;
pub mod trace;
