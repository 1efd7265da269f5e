//! Triangle meshes loaded from Wavefront OBJ, PLY, STL and glTF 2.0 files, optionally
//! gzip-compressed (`.obj.gz`, `.ply.gz`).
//!
//! # Triangle order
//!
//! Hit reports name triangles by index, so the order is part of the interface. Each format's
//! module documents its order; in short:
//!
//! - [OBJ](obj): faces in the order of their `f` lines, all objects and groups merged; a face
//!   `(v0, v1, ..., v(n-1))` becomes the fan `(v0, v1, v2), (v0, v2, v3), ...,
//!   (v0, v(n-2), v(n-1))`.
//! - [PLY](ply): faces in the order of the `face` element, each fanned as in OBJ.
//! - [STL](stl): facets in file order, one triangle each.
//! - [glTF](gltf): nodes in depth-first order of the scene, primitives in the order of their
//!   mesh, triangles in the order of their indices; strips and fans as documented there.
//!
//! Triangle `i` of the mesh is the `i`-th triangle of that sequence, counting from 0.
//! Degenerate (zero-area) faces are kept in this order: the kernels never report hits on
//! them, and dropping them would shift every later index.
//!
//! # Formats
//!
//! The format comes from the file name's extension, in any case ([`MeshFormat::from_path`]):
//! `.obj`, `.ply`, `.stl`, `.gltf`, `.glb`, and `.obj.gz` or `.ply.gz` for gzip-compressed
//! OBJ or PLY. [`Mesh::from_bytes`] parses bytes already in memory.
//!
//! # Errors and resources
//!
//! Errors ([`SceneError`]) are one line naming the file and, for a problem in a text
//! format, the line: `scene.obj:17: face index 9 is out of range (the file has 8 vertices)`.
//! Counts in binary headers (PLY element counts, the STL facet count, glTF accessor counts)
//! are checked against the bytes present before anything is allocated for them, so a
//! truncated file or an absurd count is an error, never a large allocation. See
//! [`Mesh::from_bytes`] for the memory bound and [`Mesh::load`] for the check against the
//! memory available.
//!
//! # Other modules
//!
//! - [`input`]: reading input files: regular files only, bounded, without aborting (the
//!   readers' file access, also used by the programs for their other inputs).
//! - [`generators`]: the project's own small test scenes (the `obj/` folder) and midpoint
//!   [`subdivide`](generators::subdivide) for the benches' large meshes.

#![deny(missing_docs)]

mod check;
pub mod generators;
pub mod gltf;
pub mod gz;
pub mod input;
pub mod memory;
pub mod obj;
pub mod ply;
pub mod stl;

use std::path::Path;

use intersect::{Real, Triangle};

use bvh::Aabb;

/// Why a scene could not be loaded. Each message is one line naming the file.
#[derive(Debug, thiserror::Error)]
pub enum SceneError {
    /// The file is missing, not a regular file, unreadable or too large for memory.
    #[error(transparent)]
    Input(#[from] crate::input::InputError),
    /// A line of a text file is not valid (or not something this loader accepts).
    #[error("{file}:{line}: {problem}")]
    Malformed {
        /// The file name as given.
        file: String,
        /// Line number, counting from 1.
        line: usize,
        /// What is wrong with the line.
        problem: String,
    },
    /// A coordinate (of a vertex or a normal) is NaN or infinite.
    #[error("{file}:{line}: {what} {value} is not finite")]
    NotFinite {
        /// The file name as given.
        file: String,
        /// Line number, counting from 1.
        line: usize,
        /// `"vertex coordinate"` or `"normal component"`.
        what: &'static str,
        /// The number as written in the file.
        value: String,
    },
    /// The file parses but holds no face.
    #[error("{file}: the mesh has no faces")]
    NoFaces {
        /// The file name as given.
        file: String,
    },
    /// `tobj` rejected the file and the line-by-line check found no reason (a case it does not
    /// know); the message is `tobj`'s.
    #[error("{file}: invalid OBJ: {message}")]
    Obj {
        /// The file name as given.
        file: String,
        /// `tobj`'s description.
        message: String,
    },
    /// The file is not valid in its format (a binary file, or a problem with no line).
    #[error("{file}: {problem}")]
    Invalid {
        /// The file name as given.
        file: String,
        /// What is wrong, e.g. `invalid PLY: the file ends inside element vertex 3`.
        problem: String,
    },
    /// A text format holds a NUL byte: the file is not text (or is corrupt).
    #[error("{file}: not a text file (NUL byte at line {line})")]
    NotText {
        /// The file name as given.
        file: String,
        /// Line of the first NUL byte, counting from 1.
        line: usize,
    },
    /// The file name's extension names no supported format.
    #[error(
        "{file}: unsupported mesh format (supported: .obj, .ply, .stl, .gltf, .glb, .obj.gz, \
         .ply.gz)"
    )]
    Unsupported {
        /// The file name as given.
        file: String,
    },
    /// Loading the mesh would need more memory than the machine has available.
    #[error(
        "{file}: too large for memory: needs about {} GB, {} GB available",
        gigabytes(*needed),
        gigabytes(*available)
    )]
    OutOfMemory {
        /// The file name as given.
        file: String,
        /// Estimated bytes needed.
        needed: u64,
        /// Bytes available (`MemAvailable`, or what the allocator refused).
        available: u64,
    },
    /// The mesh is too large for 32-bit triangle or vertex indices.
    #[error("{file}: too large: {count} {what} (at most 4294967295)")]
    TooLarge {
        /// The file name as given.
        file: String,
        /// How many there are.
        count: usize,
        /// `"vertices"` or `"triangles"`.
        what: &'static str,
    },
}

/// Bytes as gigabytes with one decimal (at least 0.1 so that a refusal never reads "0.0").
fn gigabytes(bytes: u64) -> String {
    format!("{:.1}", (bytes as f64 / 1e9).max(0.1))
}

impl SceneError {
    /// A [`SceneError::Invalid`] for `file`.
    pub(crate) fn invalid(file: &str, problem: impl Into<String>) -> SceneError {
        SceneError::Invalid { file: file.to_owned(), problem: problem.into() }
    }
}

/// A mesh file format, chosen by the file name's extension.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum MeshFormat {
    /// Wavefront OBJ (text).
    Obj,
    /// PLY, the Stanford polygon format (ASCII or binary, either endianness).
    Ply,
    /// STL (ASCII or binary).
    Stl,
    /// glTF 2.0 JSON (`.gltf`), with buffers in external files or `data:` URIs.
    Gltf,
    /// glTF 2.0 binary container (`.glb`).
    Glb,
}

impl MeshFormat {
    /// Every format, in the order of the supported-formats message.
    pub const ALL: [MeshFormat; 5] =
        [MeshFormat::Obj, MeshFormat::Ply, MeshFormat::Stl, MeshFormat::Gltf, MeshFormat::Glb];

    /// The format's usual name (`"OBJ"`, `"PLY"`, `"STL"`, `"glTF"`, `"GLB"`).
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            MeshFormat::Obj => "OBJ",
            MeshFormat::Ply => "PLY",
            MeshFormat::Stl => "STL",
            MeshFormat::Gltf => "glTF",
            MeshFormat::Glb => "GLB",
        }
    }

    /// The lower-case extension without the dot (`"obj"`, ...).
    #[must_use]
    pub fn extension(self) -> &'static str {
        match self {
            MeshFormat::Obj => "obj",
            MeshFormat::Ply => "ply",
            MeshFormat::Stl => "stl",
            MeshFormat::Gltf => "gltf",
            MeshFormat::Glb => "glb",
        }
    }

    /// The format of `path` from its extension, in any case, and whether the file is
    /// gzip-compressed (`.obj.gz`, `.ply.gz`).
    ///
    /// ```
    /// use scene::MeshFormat;
    /// use std::path::Path;
    /// assert_eq!(MeshFormat::from_path(Path::new("a/Bunny.PLY.gz"))?, (MeshFormat::Ply, true));
    /// assert_eq!(MeshFormat::from_path(Path::new("x.glb"))?, (MeshFormat::Glb, false));
    /// assert!(MeshFormat::from_path(Path::new("x.stl.gz")).is_err());
    /// # Ok::<(), scene::SceneError>(())
    /// ```
    ///
    /// # Errors
    ///
    /// [`SceneError::Unsupported`] for any other name.
    pub fn from_path(path: &Path) -> Result<(MeshFormat, bool), SceneError> {
        let unsupported = || SceneError::Unsupported { file: path.display().to_string() };
        let name = path.file_name().ok_or_else(unsupported)?.to_string_lossy().to_lowercase();
        let (stem, gzip) = match name.strip_suffix(".gz") {
            Some(stem) => (stem, true),
            None => (name.as_str(), false),
        };
        let format = MeshFormat::ALL
            .into_iter()
            .find(|f| {
                stem.strip_suffix(f.extension()).is_some_and(|s| s.ends_with('.') && s.len() > 1)
            })
            .ok_or_else(unsupported)?;
        if gzip && !matches!(format, MeshFormat::Obj | MeshFormat::Ply) {
            return Err(unsupported());
        }
        Ok((format, gzip))
    }
}

/// A triangle mesh: shared vertex positions and triangles indexing them.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Mesh {
    /// Name for messages (the file name as given).
    pub name: String,
    /// Vertex positions. A file vertex used with different normals or texture coordinates, or
    /// in several objects, may appear more than once, always with the same coordinates.
    pub positions: Vec<[f64; 3]>,
    /// Triangles as indices into `positions`, in the order documented in the
    /// [module documentation](self).
    pub triangles: Vec<[u32; 3]>,
    /// Per-triangle corner normals (for corners `a`, `b`, `c`), present when the file gives a
    /// normal for every face vertex.
    pub normals: Option<Vec<[[f32; 3]; 3]>>,
}

impl Mesh {
    /// Loads a mesh file in the format its name gives ([`MeshFormat::from_path`]); a glTF
    /// file's external buffers are read from beside it.
    ///
    /// Before reading, the memory the load and a render need is estimated from the file size
    /// ([`memory::peak_estimate`]) and compared with the memory available; a gzip stream is
    /// decompressed only up to what that memory can hold.
    ///
    /// # Errors
    ///
    /// [`SceneError`]: unsupported extension; the file is missing or unreadable; too large
    /// for memory; malformed (bad number, index out of range, face with fewer than 3
    /// vertices, truncated binary data, NUL byte in a text format, ...); a coordinate is NaN or
    /// infinite; the file has no face.
    pub fn load(path: &Path) -> Result<Mesh, SceneError> {
        // A missing file or a directory is named as such, whatever its name.
        let size = crate::input::regular_file_size(path)?;
        let (format, gzip) = MeshFormat::from_path(path)?;
        let name = path.display().to_string();
        if !gzip {
            memory::check_fits(&name, memory::peak_estimate(format, size))?;
        }
        let bytes = crate::input::read_file(path)?;
        let bytes = if gzip {
            let limit = memory::decompression_limit(format);
            let text = gz::gunzip(&bytes, limit, &name)?;
            drop(bytes);
            memory::check_fits(&name, memory::peak_estimate(format, text.len() as u64))?;
            text
        } else {
            bytes
        };
        match format {
            MeshFormat::Gltf => gltf::from_gltf_bytes(&bytes, &name, Some(path)),
            _ => Self::from_bytes(&bytes, format, &name),
        }
    }

    /// Parses a mesh held in memory; `name` names the source in error messages and becomes
    /// [`Mesh::name`]. For [`MeshFormat::Gltf`] only buffers in `data:` URIs are resolved (a
    /// reference to an external file is an error; [`Mesh::load`] reads those).
    ///
    /// On any input this returns (never panics, never loops without bound), and the memory it
    /// allocates is bounded by [`memory::FROM_BYTES_MULTIPLE`] times `bytes.len()` plus a
    /// constant: every count is checked against the bytes present before anything is
    /// reserved for it.
    ///
    /// # Errors
    ///
    /// As [`Mesh::load`], except for file access.
    pub fn from_bytes(bytes: &[u8], format: MeshFormat, name: &str) -> Result<Mesh, SceneError> {
        match format {
            MeshFormat::Obj => obj::from_obj_bytes(bytes, name),
            MeshFormat::Ply => ply::from_ply_bytes(bytes, name),
            MeshFormat::Stl => stl::from_stl_bytes(bytes, name),
            MeshFormat::Gltf => gltf::from_gltf_bytes(bytes, name, None),
            MeshFormat::Glb => gltf::from_glb_bytes(bytes, name),
        }
    }

    /// Parses OBJ text; `name` names the source in error messages and becomes
    /// [`Mesh::name`].
    ///
    /// # Errors
    ///
    /// As [`Mesh::load`], except for file access.
    pub fn from_obj_str(text: &str, name: &str) -> Result<Mesh, SceneError> {
        obj::from_obj_str(text, name)
    }

    /// Number of triangles.
    #[must_use]
    pub fn len(&self) -> usize {
        self.triangles.len()
    }

    /// Whether the mesh has no triangle.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.triangles.is_empty()
    }

    /// Triangle `i` in precision `T` (vertex coordinates rounded to nearest).
    ///
    /// # Panics
    ///
    /// If `i >= self.len()`.
    #[must_use]
    pub fn triangle<T: Real>(&self, i: usize) -> Triangle<T> {
        let [a, b, c] = self.triangles[i].map(|v| self.positions[v as usize].map(T::from_f64));
        Triangle::new(a, b, c)
    }

    /// All triangles in precision `T`, in mesh order.
    #[must_use]
    pub fn triangles<T: Real>(&self) -> Vec<Triangle<T>> {
        (0..self.len()).map(|i| self.triangle(i)).collect()
    }

    /// The first vertex used by a triangle (in triangle order, corners `a`, `b`, `c`) with a
    /// coordinate of magnitude above `limit`, as its index into [`Mesh::positions`] and the
    /// coordinate; `None` if there is none. With `limit = f32::MAX as f64` this finds the
    /// vertices that `f32` cannot hold (they would round to infinity).
    ///
    /// ```
    /// let text = "v 0 0 0\nv 1e39 0 0\nv 0 1 0\nv 0 0 -1e40\nf 1 2 3\n";
    /// let mesh = scene::Mesh::from_obj_str(text, "big.obj")?;
    /// // Vertex 3 (-1e40) is not used by a triangle.
    /// assert_eq!(mesh.first_coordinate_beyond(f32::MAX.into()), Some((1, 1e39)));
    /// assert_eq!(mesh.first_coordinate_beyond(1e40), None);
    /// # Ok::<(), scene::SceneError>(())
    /// ```
    #[must_use]
    pub fn first_coordinate_beyond(&self, limit: f64) -> Option<(usize, f64)> {
        self.triangles.iter().flatten().find_map(|&v| {
            let p = self.positions[v as usize];
            p.into_iter().find(|x| x.abs() > limit).map(|x| (v as usize, x))
        })
    }

    /// The box of the vertices used by triangles (empty for an empty mesh).
    #[must_use]
    pub fn bounds(&self) -> Aabb<f64> {
        let mut b = Aabb::empty();
        for t in &self.triangles {
            for &v in t {
                b.grow_point(self.positions[v as usize]);
            }
        }
        b
    }

    /// A sphere holding every vertex used by triangles: the centre of [`Mesh::bounds`] and the
    /// largest distance from it (not the smallest such sphere, but within a factor
    /// `sqrt(3)` of it). `([0; 3], 0)` for an empty mesh.
    #[must_use]
    pub fn bounding_sphere(&self) -> ([f64; 3], f64) {
        if self.is_empty() {
            return ([0.0; 3], 0.0);
        }
        let center = self.bounds().center();
        let mut r2 = 0.0f64;
        for t in &self.triangles {
            for &v in t {
                let p = self.positions[v as usize];
                let d2: f64 = (0..3).map(|k| (p[k] - center[k]) * (p[k] - center[k])).sum();
                r2 = r2.max(d2);
            }
        }
        (center, r2.sqrt())
    }
}

/// An indexed mesh as the binary formats give it: positions, optional per-vertex normals and
/// triangles, turned into a [`Mesh`] by [`IndexedMesh::finish`].
#[derive(Default)]
pub(crate) struct IndexedMesh {
    pub(crate) positions: Vec<[f64; 3]>,
    /// One normal per position, or empty.
    pub(crate) normals: Vec<[f32; 3]>,
    pub(crate) triangles: Vec<[u32; 3]>,
}

impl IndexedMesh {
    /// Checks the data (finite positions and normals, indices in range, 32-bit counts, at
    /// least one triangle) and builds the mesh, with corner normals if every vertex has one.
    pub(crate) fn finish(self, name: &str) -> Result<Mesh, SceneError> {
        let IndexedMesh { positions, normals, triangles } = self;
        for (what, count) in [("vertices", positions.len()), ("triangles", triangles.len())] {
            if u32::try_from(count).is_err() {
                return Err(SceneError::TooLarge { file: name.to_owned(), count, what });
            }
        }
        if triangles.is_empty() {
            return Err(SceneError::NoFaces { file: name.to_owned() });
        }
        if let Some((i, p)) = positions.iter().enumerate().find(|(_, p)| !all_finite(p)) {
            return Err(SceneError::invalid(
                name,
                format!("vertex {i} has a coordinate that is not finite: {p:?}"),
            ));
        }
        if let Some((i, n)) = normals.iter().enumerate().find(|(_, n)| !all_finite(n)) {
            return Err(SceneError::invalid(
                name,
                format!("the normal of vertex {i} has a component that is not finite: {n:?}"),
            ));
        }
        let count = positions.len();
        if let Some((i, t)) =
            triangles.iter().enumerate().find(|(_, t)| t.iter().any(|&v| v as usize >= count))
        {
            return Err(SceneError::invalid(
                name,
                format!("triangle {i} refers to vertex {t:?}, but there are {count} vertices"),
            ));
        }
        let normals = if !normals.is_empty() && normals.len() == count {
            let mut corners = try_vec(triangles.len(), name)?;
            corners.extend(triangles.iter().map(|t| t.map(|v| normals[v as usize])));
            Some(corners)
        } else {
            None
        };
        Ok(Mesh { name: name.to_owned(), positions, triangles, normals })
    }
}

/// Whether every component is finite.
fn all_finite<T: Into<f64> + Copy>(v: &[T; 3]) -> bool {
    v.iter().all(|&x| x.into().is_finite())
}

/// An empty vector with room for `n` elements, or [`SceneError::OutOfMemory`] if the
/// allocator refuses.
pub(crate) fn try_vec<T>(n: usize, name: &str) -> Result<Vec<T>, SceneError> {
    let mut v = Vec::new();
    v.try_reserve_exact(n).map_err(|_| SceneError::OutOfMemory {
        file: name.to_owned(),
        needed: (n as u64).saturating_mul(size_of::<T>() as u64),
        available: memory::available().unwrap_or(0),
    })?;
    Ok(v)
}
