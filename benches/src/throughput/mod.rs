//! Shared code of the `throughput`, `kernels` and `build` benches: the scenes, the ray sets,
//! the tracing loops, the CSV rows and the SVG plot.
//!
//! ```
//! use wedge_benches::throughput::rays::{RaySet, incoherent_rays};
//! use scene::Mesh;
//!
//! let mesh = Mesh::from_obj_str("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "tri").unwrap();
//! let rays = incoherent_rays(&mesh, 100, 1);
//! assert_eq!(rays.len(), 100);
//! // Unit directions, origins in the mesh's box.
//! assert!(rays.iter().all(|r| (r.dir.iter().map(|d| d * d).sum::<f64>() - 1.0).abs() < 1e-12));
//! assert!(rays.iter().all(|r| r.origin[2] == 0.0 && r.origin[0] <= 1.0));
//! assert_eq!(RaySet::ALL.map(RaySet::name)[1], "primary_any");
//! ```

pub mod plot;
pub mod rays;
pub mod rows;
pub mod scenes;
pub mod trace;
