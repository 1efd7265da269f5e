//! The ray sets: primary rays of a camera framing the mesh, and incoherent rays (origins
//! uniform in the mesh's bounding box, directions uniform on the sphere, fixed seed).
//!
//! Rays are made in `f64` and rounded once to each back end's precision, so every back end of
//! a precision traces the very same rays.

use intersect::Ray;
use render::camera::{Camera, DEFAULT_FOV_DEG};
use scene::Mesh;

use crate::SplitMix64;

/// The seed of the incoherent rays.
pub const INCOHERENT_SEED: u64 = 0x7772_6179_7331;

/// What is asked of the rays of a set.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Query {
    /// The nearest hit, with its triangle and barycentrics (`Accel::closest_hit`).
    Closest,
    /// Whether there is any hit; stops at the first (`Accel::any_hit`, the alpha mode).
    Any,
}

/// A set of rays and the query made with them: the three columns of the table.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RaySet {
    /// Primary rays, closest hit.
    PrimaryClosest,
    /// Primary rays, any hit.
    PrimaryAny,
    /// Incoherent rays, closest hit.
    IncoherentClosest,
    /// Primary rays of a 1920 x 1080 image, any hit: the alpha frame of the 1.1M mesh
    /// (traced on the large scenes only).
    AlphaFullHd,
}

impl RaySet {
    /// The three sets of the table, in its order.
    pub const ALL: [RaySet; 3] =
        [RaySet::PrimaryClosest, RaySet::PrimaryAny, RaySet::IncoherentClosest];

    /// The name in CSV rows and bench ids.
    #[must_use]
    pub const fn name(self) -> &'static str {
        match self {
            RaySet::PrimaryClosest => "primary_closest",
            RaySet::PrimaryAny => "primary_any",
            RaySet::IncoherentClosest => "incoherent_closest",
            RaySet::AlphaFullHd => "alpha_1920x1080",
        }
    }

    /// The query.
    #[must_use]
    pub const fn query(self) -> Query {
        match self {
            RaySet::PrimaryClosest | RaySet::IncoherentClosest => Query::Closest,
            RaySet::PrimaryAny | RaySet::AlphaFullHd => Query::Any,
        }
    }

    /// Whether the set is made of primary rays.
    #[must_use]
    pub const fn is_primary(self) -> bool {
        !matches!(self, RaySet::IncoherentClosest)
    }
}

/// One ray per pixel of a `width x height` image, row by row from the top left, through pixel
/// centres, from [`Camera::auto`] framing the mesh's bounding sphere (45 degree field of view).
///
/// # Panics
///
/// If the mesh's bounds are not finite.
#[must_use]
pub fn primary_rays(mesh: &Mesh, width: u32, height: u32) -> Vec<Ray<f64>> {
    let (center, radius) = mesh.bounding_sphere();
    let aspect = f64::from(width) / f64::from(height);
    let camera = Camera::auto(center, radius, DEFAULT_FOV_DEG, aspect)
        .expect("a loaded mesh has finite bounds");
    camera_rays(&camera, width, height)
}

/// One ray per pixel of a `width x height` image seen by `camera`, row by row from the top
/// left, through pixel centres (`Camera::direction`, in `f64`).
#[must_use]
pub fn camera_rays(camera: &Camera, width: u32, height: u32) -> Vec<Ray<f64>> {
    (0..height)
        .flat_map(|j| (0..width).map(move |i| (i, j)))
        .map(|(i, j)| Ray::new(camera.eye(), camera.direction(i, j, width, height)))
        .collect()
}

/// `count` rays with origins uniform in the mesh's bounding box and unit directions uniform on
/// the sphere, from a fixed seed.
#[must_use]
pub fn incoherent_rays(mesh: &Mesh, count: usize, seed: u64) -> Vec<Ray<f64>> {
    let bounds = mesh.bounds();
    let mut rng = SplitMix64::new(seed);
    (0..count)
        .map(|_| {
            let origin = core::array::from_fn(|k| rng.range(bounds.min[k], bounds.max[k]));
            // Archimedes: z uniform in [-1, 1] and a uniform angle give a uniform direction.
            let z = rng.range(-1.0, 1.0);
            let phi = rng.range(0.0, core::f64::consts::TAU);
            let r = (1.0 - z * z).max(0.0).sqrt();
            Ray::new(origin, [r * phi.cos(), r * phi.sin(), z])
        })
        .collect()
}
