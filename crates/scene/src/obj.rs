//! Wavefront OBJ.
//!
//! # Triangle order
//!
//! 1. Faces are taken in the order of their `f` lines in the file, across every object (`o`),
//!    group (`g`) and material (`usemtl`) section: all sections are merged into one mesh.
//! 2. A face with `n >= 3` vertices `(v0, v1, ..., v(n-1))` becomes the `n - 2` triangles of
//!    the fan from its first vertex, in this order: `(v0, v1, v2), (v0, v2, v3), ...,
//!    (v0, v(n-2), v(n-1))`. A quad `(a, b, c, d)` gives `(a, b, c), (a, c, d)`.
//! 3. Triangle `i` of the mesh is the `i`-th triangle of that sequence, counting from 0.
//!
//! # What the loader accepts
//!
//! Parsing is done by [`tobj`] (with `f64` coordinates). Polylines (`l`), texture coordinates,
//! vertex colours (`v x y z r g b`) and materials are ignored; a vertex weight
//! (`v x y z w`) divides the coordinates. Face indices may be negative (relative to the
//! vertices read so far) and may point to a vertex that appears later in the file. Vertex
//! normals are kept when every face vertex of the file has one (`v//vn` or `v/vt/vn`).
//! A UTF-8 byte-order mark at the start is skipped; stray non-UTF-8 bytes (comments in
//! Latin-1) are tolerated, and a number spoilt by one is reported as a bad number on its line.
//! A NUL byte anywhere means the file is not text: it is refused before parsing, naming the
//! line.
//!
//! Errors name the line: `scene.obj:17: face index 9 is out of range (the file has 8
//! vertices)`. `tobj` reports no line numbers, so when it fails (or accepts something this
//! loader rejects: a face of one or two vertices, a NaN or infinite number, a reference to a
//! texture coordinate or normal in a file that has none) a second pass over the text finds
//! the offending line; a file that loads cleanly pays only for checks over the loaded data
//! (and, if a face uses `/` while the file lacks texture coordinates or normals, one scan for
//! references to them).

use std::borrow::Cow;

use super::{Mesh, SceneError, check, try_vec};

/// Parses OBJ bytes: refuses NUL bytes, then reads the text as UTF-8, replacing invalid
/// sequences.
pub(crate) fn from_obj_bytes(bytes: &[u8], name: &str) -> Result<Mesh, SceneError> {
    if let Some(err) = nul_byte(bytes, name) {
        return Err(err);
    }
    from_obj_str(&String::from_utf8_lossy(bytes), name)
}

/// [`SceneError::NotText`] if `bytes` holds a NUL byte.
fn nul_byte(bytes: &[u8], name: &str) -> Option<SceneError> {
    let at = bytes.iter().position(|&b| b == 0)?;
    let line = 1 + bytes[..at].iter().filter(|&&b| b == b'\n').count();
    Some(SceneError::NotText { file: name.to_owned(), line })
}

/// See [`Mesh::from_obj_str`].
pub(crate) fn from_obj_str(text: &str, name: &str) -> Result<Mesh, SceneError> {
    if let Some(err) = nul_byte(text.as_bytes(), name) {
        return Err(err);
    }
    // A byte-order mark would otherwise make the first statement unrecognisable.
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
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
    // tobj computes with face indices unchecked (`3 * index`, `len + index`): an index
    // larger than any count the file could hold overflows inside it. No count exceeds the
    // number of bytes, so such an index is out of range whatever the file holds: find its line.
    if has_impossible_index(&text) {
        return Err(locate(&text, name, || "face index out of range".to_owned()));
    }
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
    // tobj skips texture and normal indices when the file has no `vt` (or no `vn`) at all;
    // such a reference is as wrong as a bad vertex index. Only a face with a `/` can hold one.
    let lacks = |empty: fn(&tobj::Mesh) -> bool| models.iter().all(|m| empty(&m.mesh));
    if (lacks(|m| m.texcoords.is_empty()) || lacks(|m| m.normals.is_empty()))
        && text.contains('/')
        && let Some(err) = check::dangling_reference(&text, name)
    {
        return Err(err);
    }
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

/// Whether a face holds an index that overflows tobj's arithmetic: a relative (negative)
/// index reaching before the first vertex, texture coordinate or normal read so far, or an
/// absolute one whose magnitude exceeds the length of the text (and so every count of the
/// file). One pass; tobj refuses the other out-of-range indices itself.
fn has_impossible_index(text: &str) -> bool {
    let limit = text.len() as u64;
    // Vertices, texture coordinates and normals read so far.
    let mut so_far = [0u64; 3];
    text.lines().any(|line| {
        let mut words = line.split_whitespace();
        let kind = match words.next() {
            Some("v") => 0,
            Some("vt") => 1,
            Some("vn") => 2,
            Some("f") => 3,
            _ => return false,
        };
        if kind < 3 {
            so_far[kind] += 1;
            return false;
        }
        words.any(|word| {
            word.split('/').enumerate().any(|(k, index)| {
                let (negative, digits) = match index.strip_prefix('-') {
                    Some(d) => (true, d),
                    None => (false, index),
                };
                // Too many digits for u64 is impossible too; a non-number is for tobj.
                let bound = if negative { so_far[k.min(2)] } else { limit };
                digits.bytes().all(|b| b.is_ascii_digit())
                    && digits.parse::<u64>().map_or(!digits.is_empty(), |n| n > bound)
            })
        })
    })
}

/// A normal in f32: as written when it fits, else scaled down in f64 first (the direction is
/// what matters, and a component beyond f32's range would become infinite).
fn narrow_normal(n: [f64; 3]) -> [f32; 3] {
    let largest = n.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let n = if largest > f64::from(f32::MAX) { n.map(|x| x / largest) } else { n };
    n.map(|x| x as f32)
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

    // Reserved up front so that a refusal by the allocator is an error, not an abort.
    let triangle_count: usize = models
        .iter()
        .map(|m| match m.mesh.face_arities.as_slice() {
            [] => m.mesh.indices.len() / 3,
            arities => arities.iter().map(|&n| (n as usize).saturating_sub(2)).sum(),
        })
        .sum();
    let mut mesh = Mesh {
        name: name.to_owned(),
        positions: try_vec(vertex_count, name)?,
        triangles: try_vec(triangle_count, name)?,
        normals: None,
    };
    let mut corner_normals = try_vec(if with_normals { triangle_count } else { 0 }, name)?;
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
            narrow_normal([m.normals[i], m.normals[i + 1], m.normals[i + 2]])
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
