//! Scene loading, BVH, camera, render loop and outputs, generic over the
//! [`Intersector`](intersect::Intersector) seam.
//!
//! ```
//! use intersect::{Algebra, Guarantees, Intersector, Method, Ray, Triangle, TriangleHit};
//! use render::accel::Accel;
//!
//! /// A toy back end for rays along +z: the triangle's plane must be z = const.
//! struct Flat;
//!
//! impl Intersector for Flat {
//!     type Real = f64;
//!     type Prim = Triangle<f64>;
//!     type RayData = ();
//!     const NAME: &'static str = "flat";
//!     const ALGEBRA: Algebra = Algebra::La;
//!     const METHOD: Method = Method::Report;
//!     const GUARANTEES: Guarantees = Guarantees { watertight: false, exact: false };
//!
//!     fn prepare(&self, tri: &Triangle<f64>) -> Triangle<f64> {
//!         *tri
//!     }
//!     fn prepare_ray(&self, _ray: &Ray<f64>) {}
//!     fn intersect(&self, p: &Triangle<f64>, ray: &Ray<f64>, _: &(), t_max: f64)
//!         -> Option<TriangleHit<f64>>
//!     {
//!         let t = (p.a[2] - ray.origin[2]) / ray.dir[2];
//!         // Barycentrics of the right triangle a, a + (1, 0, 0), a + (0, 1, 0).
//!         let (u, v) = (ray.origin[0] - p.a[0], ray.origin[1] - p.a[1]);
//!         (t > 0.0 && t <= t_max && u >= 0.0 && v >= 0.0 && u + v <= 1.0)
//!             .then_some(TriangleHit { t, u, v })
//!     }
//! }
//!
//! let near = Triangle::new([0.0, 0.0, 2.0], [1.0, 0.0, 2.0], [0.0, 1.0, 2.0]);
//! let far = Triangle::new([0.0, 0.0, 5.0], [1.0, 0.0, 5.0], [0.0, 1.0, 5.0]);
//! let scene = Accel::build(Flat, &[far, near]);
//!
//! let ray = Ray::new([0.25, 0.25, 0.0], [0.0, 0.0, 1.0]);
//! let hit = scene.closest_hit(&ray).unwrap();
//! assert_eq!((hit.prim, hit.t), (1, 2.0)); // `near`, index 1 in the slice given to build
//! assert_eq!(scene.closest_hit_brute_force(&ray), Some(hit));
//! assert!(scene.any_hit(&ray, 10.0) && !scene.any_hit(&ray, 1.0));
//! ```
//!
//! # Modules
//!
//! - [`scene`]: triangle meshes from OBJ, PLY, STL and glTF files, optionally gzip-compressed
//!   ([`scene::Mesh`]), with a documented triangle order and one-line errors naming file and
//!   line.
//! - [`bvh`]: a bounding volume hierarchy over boxes (binned SAH, robust traversal).
//! - [`accel`]: [`accel::Accel`], a back end's prepared triangles in BVH order with closest-hit
//!   and any-hit queries and their brute-force references.
//! - [`camera`]: a pinhole camera and the exact pixel-to-ray mapping.
//! - [`frame`]: per-pixel results of a render.
//! - [`input`]: reading input files: regular files only, bounded, without aborting.
//! - [`render`](mod@render): the render loop.
//! - [`output`]: image and data writers.

#![deny(missing_docs)]

pub mod accel;
pub mod bvh;
pub mod camera;
pub mod frame;
pub mod input;
pub mod output;
pub mod render;
pub mod scene;
