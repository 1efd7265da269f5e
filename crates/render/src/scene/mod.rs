//! Triangle meshes loaded from Wavefront OBJ files.
//!
//! # Triangle order
//!
//! Hit reports name triangles by index, so the order is part of the interface:
//!
//! 1. Faces are taken in the order of their `f` lines in the file, across every object (`o`),
//!    group (`g`) and material (`usemtl`) section: all sections are merged into one mesh.
//! 2. A face with `n >= 3` vertices `(v0, v1, ..., v(n-1))` becomes the `n - 2` triangles of
//!    the fan from its first vertex, in this order: `(v0, v1, v2), (v0, v2, v3), ...,
//!    (v0, v(n-2), v(n-1))`. A quad `(a, b, c, d)` gives `(a, b, c), (a, c, d)`.
//! 3. Triangle `i` of the mesh is the `i`-th triangle of that sequence, counting from 0.
//!
//! Degenerate (zero-area) faces are kept in this order: the kernels never report hits on
//! them, and dropping them would shift every later index.
//!
//! # What the loader accepts
//!
//! Parsing is done by [`tobj`] (with `f64` coordinates). Polylines (`l`), texture coordinates,
//! vertex colours (`v x y z r g b`) and materials are ignored; a vertex weight
//! (`v x y z w`) divides the coordinates. Face indices may be negative (relative to the vertices read so
//! far) and may point to a vertex that appears later in the file. Vertex normals are kept
//! when every face vertex of the file has one (`v//vn` or `v/vt/vn`).
//!
//! Errors ([`SceneError`]) are one line naming the file and, for a problem in the text, the
//! line: `scene.obj:17: face index 9 is out of range (the file has 8 vertices)`. `tobj`
//! reports no line numbers, so when it fails (or accepts something this loader rejects: a
//! face of one or two vertices, a NaN or infinite number) a second pass over the text finds
//! the offending line; a file that loads cleanly pays only for checks over the loaded data.

mod check;

use std::borrow::Cow;
use std::path::Path;

use intersect::{Real, Triangle};

use crate::bvh::Aabb;

/// Why a scene could not be loaded. Each message is one line naming the file.
#[derive(Debug, thiserror::Error)]
pub enum SceneError {
    /// The file is missing, not a regular file, unreadable or too large for memory.
    #[error(transparent)]
    Input(#[from] crate::input::InputError),
    /// A line of the file is not valid OBJ (or not something this loader accepts).
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
    /// Loads an OBJ file.
    ///
    /// # Errors
    ///
    /// [`SceneError`]: the file is missing or unreadable, a line is malformed (bad number,
    /// face index zero or out of range, face with fewer than 3 vertices), a coordinate is NaN
    /// or infinite, or the file has no face.
    pub fn load(path: &Path) -> Result<Mesh, SceneError> {
        let bytes = crate::input::read_file(path)?;
        // Tolerate stray non-UTF-8 bytes (comments in Latin-1 are common); a number spoilt by
        // one is reported as a bad number on its line.
        let text = String::from_utf8_lossy(&bytes);
        Self::from_obj_str(&text, &path.display().to_string())
    }

    /// Parses OBJ text; `name` names the source in error messages and becomes
    /// [`Mesh::name`].
    ///
    /// # Errors
    ///
    /// As [`Mesh::load`], except for file access.
    pub fn from_obj_str(text: &str, name: &str) -> Result<Mesh, SceneError> {
        // tobj reads `l` (polyline) statements as faces; blank them, keeping line numbers.
        let text = blank_polylines(text);
        // The struct update covers fields that exist only with some tobj features, which
        // another crate of a build may switch on.
        #[allow(clippy::needless_update)]
        let options = tobj::LoadOptions {
            single_index: true,
            // The fan is built here, so that faces of 1 or 2 vertices stay visible as errors.
            triangulate: false,
            ignore_points: false,
            ignore_lines: false,
            ..Default::default()
        };
        let parse = |text: &str| {
            tobj::load_obj_buf(&mut text.as_bytes(), &options, |_| {
                // Materials are not used; do not read .mtl files.
                Err(tobj::LoadError::GenericFailure)
            })
        };
        let loaded = match parse(&text) {
            // tobj fails when some vertices have colours (`v x y z r g b`) and others not;
            // colours are not used, so drop them and parse again.
            Err(tobj::LoadError::FaceColorOutOfBounds) => parse(&strip_vertex_colours(&text)),
            other => other,
        };
        let models = match loaded {
            Ok((models, _materials)) => models,
            Err(e) => return Err(locate(&text, name, || e.to_string())),
        };
        let mesh = assemble(&models, name)?;
        match mesh {
            Some(mesh) if mesh.triangles.is_empty() => {
                Err(SceneError::NoFaces { file: name.to_owned() })
            }
            Some(mesh) => Ok(mesh),
            // Something tobj accepted that this loader rejects: find the line.
            None => Err(locate(&text, name, || "unsupported content".to_owned())),
        }
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

/// Replaces each `l` statement with an empty comment so that tobj does not read it as a face.
fn blank_polylines(text: &str) -> Cow<'_, str> {
    let is_polyline = |line: &str| line.split_whitespace().next() == Some("l");
    // A substring search first: most files have no `l` statement and skip the line scan.
    let maybe = text.contains("l ") || text.contains("l\t");
    if !maybe || !text.lines().any(is_polyline) {
        return Cow::Borrowed(text);
    }
    let mut out = String::with_capacity(text.len());
    for line in text.split_inclusive('\n') {
        if is_polyline(line) {
            out.push('#');
            // Keep the line ending (and so the line count).
            out.push_str(line.strip_prefix(line.trim_end_matches(['\n', '\r'])).unwrap_or(""));
        } else {
            out.push_str(line);
        }
    }
    Cow::Owned(out)
}

/// The text with every `v x y z r g b` statement cut to `v x y z`; line numbers unchanged.
fn strip_vertex_colours(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for line in text.split_inclusive('\n') {
        let words: Vec<&str> = line.split_whitespace().collect();
        if words.len() == 7 && words[0] == "v" {
            out.push_str(&words[..4].join(" "));
            out.push('\n');
        } else {
            out.push_str(line);
        }
    }
    out
}

/// The error for a text that failed: the first bad line if the check finds one, else a
/// file-level error with `fallback`'s message.
fn locate(text: &str, name: &str, fallback: impl FnOnce() -> String) -> SceneError {
    check::first_problem(text, name)
        .unwrap_or_else(|| SceneError::Obj { file: name.to_owned(), message: fallback() })
}

/// Merges tobj's models into one mesh in file order. `Ok(None)` if the data holds something
/// this loader rejects (a face of fewer than 3 vertices, a non-finite number), to be located
/// in the text by the caller.
fn assemble(models: &[tobj::Model], name: &str) -> Result<Option<Mesh>, SceneError> {
    let vertex_count: usize = models.iter().map(|m| m.mesh.positions.len() / 3).sum();
    if u32::try_from(vertex_count).is_err() {
        return Err(SceneError::TooLarge {
            file: name.to_owned(),
            count: vertex_count,
            what: "vertices",
        });
    }
    // Normals only if every model has one per vertex (with a single index, tobj stores a
    // normal for a vertex exactly when its face vertex had one).
    // Models without faces (tobj ends the file with one after a trailing `o`) do not count.
    let with_normals = models
        .iter()
        .filter(|m| !m.mesh.indices.is_empty())
        .all(|m| !m.mesh.normals.is_empty() && m.mesh.normals.len() == m.mesh.positions.len());

    let mut mesh = Mesh { name: name.to_owned(), ..Mesh::default() };
    let mut corner_normals = Vec::new();
    for model in models {
        let m = &model.mesh;
        let base = mesh.positions.len() as u32;
        for p in m.positions.chunks_exact(3) {
            if !p.iter().all(|x| x.is_finite()) {
                return Ok(None);
            }
            mesh.positions.push([p[0], p[1], p[2]]);
        }
        let normal = |v: u32| -> [f32; 3] {
            let i = 3 * v as usize;
            [m.normals[i] as f32, m.normals[i + 1] as f32, m.normals[i + 2] as f32]
        };
        if with_normals && !m.normals.iter().all(|x: &f64| x.is_finite()) {
            return Ok(None);
        }
        let mut first = 0usize;
        // With no arities, every face is a triangle.
        let arities = m.face_arities.iter().copied().chain(core::iter::repeat(3));
        for arity in arities {
            if first >= m.indices.len() {
                break;
            }
            let arity = arity as usize;
            if arity < 3 {
                return Ok(None);
            }
            let face = &m.indices[first..first + arity];
            for k in 1..arity - 1 {
                let tri = [face[0], face[k], face[k + 1]];
                mesh.triangles.push(tri.map(|v| base + v));
                if with_normals {
                    corner_normals.push(tri.map(normal));
                }
            }
            first += arity;
        }
    }
    if u32::try_from(mesh.triangles.len()).is_err() {
        return Err(SceneError::TooLarge {
            file: name.to_owned(),
            count: mesh.triangles.len(),
            what: "triangles",
        });
    }
    if with_normals && !models.is_empty() {
        mesh.normals = Some(corner_normals);
    }
    Ok(Some(mesh))
}
