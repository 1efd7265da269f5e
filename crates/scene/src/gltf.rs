//! glTF 2.0, as JSON (`.gltf`) or binary (`.glb`).
//!
//! # What is read
//!
//! Every triangle primitive of every mesh instanced by a node of the default scene (or, if
//! the file names none, of every scene in order; if it has no scene, of every node that is
//! no other node's child). Each node's transform (a matrix, or translation, rotation and
//! scale) is composed down the hierarchy in `f64` and applied to the positions; normals,
//! when every triangle primitive has them, are transformed by the inverse transpose
//! (computed as the cofactor matrix, so a singular transform needs no inverse) and
//! renormalised. A node whose transform has a negative determinant mirrors its meshes; glTF
//! then takes clockwise triangles as front faces, so the last two corners of each of its
//! triangles are swapped to keep every triangle counter-clockwise seen from its front.
//!
//! `POINTS` and `LINES`-type primitives are ignored. Positions and normals must be
//! `VEC3` of `FLOAT`, indices `UNSIGNED_BYTE`, `UNSIGNED_SHORT` or `UNSIGNED_INT`; a
//! primitive without indices uses its vertices in order. Sparse accessors, quantised
//! positions and accessors without a buffer view are refused with a message. Buffers come
//! from the GLB binary chunk, from `data:` URIs (base64) or, for [`Mesh::load`], from files
//! named relative to the glTF file.
//!
//! # Triangle order
//!
//! 1. Nodes in depth-first order: a scene's root nodes in order, each node before its
//!    children, children in order. A mesh used by several nodes appears once per node.
//! 2. A node's mesh's primitives in order.
//! 3. A primitive's triangles in the order of its indices: `TRIANGLES` takes them three at a
//!    time; `TRIANGLE_STRIP` gives triangle `i` as `(v[i], v[i+1], v[i+2])` for even `i` and
//!    `(v[i], v[i+2], v[i+1])` for odd `i` (the glTF rule: every triangle keeps the
//!    primitive's orientation); `TRIANGLE_FAN` gives `(v[0], v[i+1], v[i+2])`, the fan from the
//!    first vertex, as in OBJ (glTF writes it `(v[i+1], v[i+2], v[0])`, the same triangle
//!    and orientation).
//!
//! Each primitive instance adds all its vertices to [`Mesh::positions`], in accessor order.
//!
//! # Bounds
//!
//! Every accessor's extent (offset, stride and count) is checked against its buffer view and
//! the view against its buffer before anything is read. Instancing can make the output far
//! larger than the file; the output is refused when it would exceed
//! [`FROM_BYTES_MULTIPLE`](super::memory::FROM_BYTES_MULTIPLE)` / 2` times the input's bytes
//! (file and buffers), which leaves 20 instances of a mesh with 16-bit indices room.

use std::borrow::Cow;
use std::path::Path;

use base64::Engine as _;
use gltf::accessor::{DataType, Dimensions};
use gltf::mesh::Mode;

use super::{IndexedMesh, Mesh, SceneError, memory};

/// A column-major 4x4 matrix, as glTF stores them.
type Mat4 = [[f64; 4]; 4];

const IDENTITY: Mat4 =
    [[1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], [0.0, 0.0, 0.0, 1.0]];

/// Parses a `.glb` container: the 12-byte header, the JSON chunk and an optional `BIN` chunk.
pub(crate) fn from_glb_bytes(bytes: &[u8], name: &str) -> Result<Mesh, SceneError> {
    let bad = |problem: String| SceneError::invalid(name, format!("invalid GLB: {problem}"));
    let word = |at: usize| {
        bytes.get(at..at + 4).map(|w| u32::from_le_bytes([w[0], w[1], w[2], w[3]]) as usize)
    };
    if !bytes.starts_with(b"glTF") {
        return Err(bad("the file does not start with `glTF`".to_owned()));
    }
    let (Some(version), Some(length)) = (word(4), word(8)) else {
        return Err(bad(format!("{} bytes is too short for the header", bytes.len())));
    };
    if version != 2 {
        return Err(bad(format!("version {version}, only 2 is supported")));
    }
    if length > bytes.len() || length < 12 {
        return Err(bad(format!(
            "the header gives a length of {length} bytes, the file has {}",
            bytes.len()
        )));
    }
    let bytes = &bytes[..length];
    // Chunks: length, type, data; the first is JSON, a `BIN` chunk may follow.
    let mut at = 12;
    let mut json = None;
    let mut blob = None;
    while at < length {
        let (Some(len), Some(kind)) = (word(at), bytes.get(at + 4..at + 8)) else {
            return Err(bad(format!("the chunk header at byte {at} is cut off")));
        };
        let data = at
            .checked_add(8)
            .and_then(|start| Some(start..start.checked_add(len)?))
            .and_then(|range| bytes.get(range))
            .ok_or_else(|| bad(format!("the chunk at byte {at} ({len} bytes) is cut off")))?;
        match kind {
            b"JSON" if json.is_none() => json = Some(data),
            b"BIN\0" if json.is_some() && blob.is_none() => blob = Some(data),
            _ if json.is_none() => return Err(bad("the first chunk is not JSON".to_owned())),
            // Unknown chunks are skipped, as the specification asks.
            _ => {}
        }
        // Chunks are 4-byte aligned.
        at += 8 + len.next_multiple_of(4);
    }
    let json = json.ok_or_else(|| bad("no JSON chunk".to_owned()))?;
    build(json, blob, name, None, bytes.len())
}

/// Parses a `.gltf` file's JSON; external buffers are read relative to `path` if given
/// (and refused otherwise).
pub(crate) fn from_gltf_bytes(
    bytes: &[u8],
    name: &str,
    path: Option<&Path>,
) -> Result<Mesh, SceneError> {
    if bytes.starts_with(b"glTF") {
        // A binary glTF under a `.gltf` name: read it as what it is.
        return from_glb_bytes(bytes, name);
    }
    build(bytes, None, name, path, bytes.len())
}

/// Joins an error's text onto one line.
fn one_line(text: &str) -> String {
    text.split_whitespace().collect::<Vec<_>>().join(" ")
}

/// The validated document of the glTF JSON `json`, or the problem. The specification's
/// requirement of `min` and `max` on `POSITION` accessors is not enforced (they are not
/// used here, and some exporters omit them); every other check of the `gltf` crate is, and
/// the crate's accessors rely on them (valid indices between objects).
fn document(json: &[u8]) -> Result<gltf::Document, String> {
    use gltf::json::validation::{Error, Validate as _};
    let root = gltf::json::Root::from_slice(json).map_err(|e| one_line(&e.to_string()))?;
    // The crate's validation indexes the accessors with each POSITION attribute unchecked
    // (gltf-json 1.4.1 panics on one out of range): check those first.
    let position = gltf::json::validation::Checked::Valid(gltf::json::mesh::Semantic::Positions);
    for (m, mesh) in root.meshes.iter().enumerate() {
        for (p, primitive) in mesh.primitives.iter().enumerate() {
            if let Some(i) = primitive.attributes.get(&position)
                && i.value() >= root.accessors.len()
            {
                return Err(format!(
                    "meshes[{m}].primitives[{p}].attributes[\"POSITION\"]: accessor {} \
                         does not exist",
                    i.value()
                ));
            }
        }
    }
    let mut errors = Vec::new();
    root.validate(&root, gltf::json::Path::new, &mut |path, error| errors.push((path(), error)));
    errors.retain(|(path, error)| {
        let bound = path.as_str().ends_with(".min") || path.as_str().ends_with(".max");
        !(bound && matches!(error, Error::Missing))
    });
    match errors.first() {
        None => Ok(gltf::Document::from_json_without_validation(root)),
        Some((path, error)) => Err(format!(
            "{path}: {error}{}",
            match errors.len() {
                1 => String::new(),
                n => format!(" (and {} more problems)", n - 1),
            }
        )),
    }
}

/// The mesh of the glTF document `json`, with the GLB binary chunk `blob` if any.
fn build(
    json: &[u8],
    blob: Option<&[u8]>,
    name: &str,
    path: Option<&Path>,
    input_len: usize,
) -> Result<Mesh, SceneError> {
    let bad = |problem: String| SceneError::invalid(name, format!("invalid glTF: {problem}"));
    let doc = document(json).map_err(bad)?;
    let buffers = load_buffers(&doc, blob, name, path)?;
    let input: u64 = input_len as u64 + buffers.iter().map(|b| b.len() as u64).sum::<u64>();
    let budget = input.saturating_mul(memory::FROM_BYTES_MULTIPLE / 2).max(1 << 16);

    // The root nodes, grouped by scene: the hierarchy below each group must be a tree.
    let groups: Vec<Vec<usize>> = if let Some(scene) = doc.default_scene() {
        vec![scene.nodes().map(|n| n.index()).collect()]
    } else if doc.scenes().len() > 0 {
        doc.scenes().map(|s| s.nodes().map(|n| n.index()).collect()).collect()
    } else {
        let mut child = vec![false; doc.nodes().len()];
        for node in doc.nodes() {
            for c in node.children() {
                child[c.index()] = true;
            }
        }
        vec![(0..child.len()).filter(|&i| !child[i]).collect()]
    };
    let nodes: Vec<gltf::Node> = doc.nodes().collect();
    let mut out = Output { mesh: IndexedMesh::default(), all_normals: true, bytes: 0, budget };
    for roots in groups {
        let mut seen = vec![false; nodes.len()];
        // Depth-first with an explicit stack (a deep hierarchy cannot overflow the call
        // stack); children are pushed in reverse so that they come off in order.
        let mut stack: Vec<(usize, Mat4)> = roots.iter().rev().map(|&r| (r, IDENTITY)).collect();
        while let Some((index, parent)) = stack.pop() {
            if std::mem::replace(&mut seen[index], true) {
                return Err(bad(format!(
                    "node {index} is reached twice: the node hierarchy is not a tree"
                )));
            }
            let node = &nodes[index];
            let world = multiply(&parent, &local_matrix(node));
            if let Some(mesh) = node.mesh() {
                for primitive in mesh.primitives() {
                    let at = format!("mesh {} primitive {}", mesh.index(), primitive.index());
                    out.add(&primitive, &world, &buffers)
                        .map_err(|problem| bad(format!("{at}: {problem}")))?;
                }
            }
            let children: Vec<usize> = node.children().map(|c| c.index()).collect();
            stack.extend(children.into_iter().rev().map(|c| (c, world)));
        }
    }
    let mut mesh = out.mesh;
    if !out.all_normals {
        mesh.normals = Vec::new();
    }
    mesh.finish(name)
}

/// The data of every buffer of `doc`.
fn load_buffers<'a>(
    doc: &gltf::Document,
    blob: Option<&'a [u8]>,
    name: &str,
    path: Option<&Path>,
) -> Result<Vec<Cow<'a, [u8]>>, SceneError> {
    let bad = |i: usize, problem: String| {
        SceneError::invalid(name, format!("invalid glTF: buffer {i}: {problem}"))
    };
    // External files first checked for size, all together, before any is read.
    let mut external = 0u64;
    for buffer in doc.buffers() {
        if let (gltf::buffer::Source::Uri(uri), Some(path)) = (buffer.source(), path)
            && !uri.starts_with("data:")
        {
            let file = external_path(path, uri).map_err(|p| bad(buffer.index(), p))?;
            external += crate::input::regular_file_size(&file)?;
        }
    }
    if external > 0 {
        memory::check_fits(name, memory::peak_estimate(super::MeshFormat::Gltf, external))?;
    }
    let mut out = Vec::new();
    for buffer in doc.buffers() {
        let i = buffer.index();
        let data: Cow<[u8]> =
            match buffer.source() {
                gltf::buffer::Source::Bin => Cow::Borrowed(blob.ok_or_else(|| {
                    bad(i, "refers to a GLB binary chunk, which is absent".into())
                })?),
                gltf::buffer::Source::Uri(uri) if uri.starts_with("data:") => {
                    let (_, payload) = uri
                        .split_once(";base64,")
                        .ok_or_else(|| bad(i, "a data: URI without `;base64,`".to_owned()))?;
                    // Decoded data is 3/4 of the text: bounded by the input.
                    let data = base64::engine::general_purpose::STANDARD
                        .decode(payload)
                        .map_err(|e| bad(i, format!("bad base64 in its data: URI: {e}")))?;
                    Cow::Owned(data)
                }
                gltf::buffer::Source::Uri(uri) => {
                    let Some(path) = path else {
                        return Err(bad(
                            i,
                            format!("refers to the external file `{uri}`, which needs the path"),
                        ));
                    };
                    let file = external_path(path, uri).map_err(|p| bad(i, p))?;
                    Cow::Owned(crate::input::read_file(&file)?)
                }
            };
        if data.len() < buffer.length() {
            return Err(bad(
                i,
                format!(
                    "its byteLength is {} but its data has {} bytes",
                    buffer.length(),
                    data.len()
                ),
            ));
        }
        out.push(data);
    }
    Ok(out)
}

/// The file a relative buffer URI names, beside the glTF file at `gltf`.
fn external_path(gltf: &Path, uri: &str) -> Result<std::path::PathBuf, String> {
    if uri.contains("://") || uri.starts_with('/') {
        return Err(format!("`{uri}`: only relative file names and data: URIs are supported"));
    }
    // URIs escape bytes as %XX (a space is %20).
    let mut bytes = Vec::with_capacity(uri.len());
    let mut rest = uri.as_bytes();
    while let Some((&b, tail)) = rest.split_first() {
        let hex = |d: u8| (d as char).to_digit(16).map(|x| x as u8);
        match (b, tail) {
            (b'%', [h, l, more @ ..]) if hex(*h).is_some() && hex(*l).is_some() => {
                bytes.push(hex(*h).unwrap_or(0) * 16 + hex(*l).unwrap_or(0));
                rest = more;
            }
            _ => {
                bytes.push(b);
                rest = tail;
            }
        }
    }
    let relative = String::from_utf8(bytes).map_err(|_| format!("`{uri}` is not UTF-8"))?;
    Ok(gltf.parent().unwrap_or(Path::new("")).join(relative))
}

/// The triangles gathered so far and the output budget.
struct Output {
    mesh: IndexedMesh,
    /// Whether every triangle primitive so far had normals.
    all_normals: bool,
    /// Bytes the output will take (positions, normals, triangles, corner normals).
    bytes: u64,
    budget: u64,
}

impl Output {
    /// Adds one primitive instanced with the transform `world`.
    fn add(
        &mut self,
        primitive: &gltf::Primitive,
        world: &Mat4,
        buffers: &[Cow<[u8]>],
    ) -> Result<(), String> {
        let mode = primitive.mode();
        if !matches!(mode, Mode::Triangles | Mode::TriangleStrip | Mode::TriangleFan) {
            return Ok(());
        }
        let positions = primitive
            .get(&gltf::Semantic::Positions)
            .ok_or_else(|| "a triangle primitive without POSITION".to_owned())?;
        let vertex_count = positions.count();
        let index_count = primitive.indices().map_or(vertex_count, |a: gltf::Accessor| a.count());
        let triangle_count = match mode {
            Mode::Triangles if !index_count.is_multiple_of(3) => {
                return Err(format!("TRIANGLES with {index_count} indices (not a multiple of 3)"));
            }
            Mode::Triangles => index_count / 3,
            _ => index_count.saturating_sub(2),
        };
        self.bytes = self
            .bytes
            .saturating_add((vertex_count as u64).saturating_mul(24 + 12))
            .saturating_add((triangle_count as u64).saturating_mul(12 + 36));
        if self.bytes > self.budget {
            return Err(format!(
                "the instanced meshes add up to more than {} bytes of output, over {}x the \
                 input's size (too much instancing for this loader)",
                self.budget,
                memory::FROM_BYTES_MULTIPLE / 2
            ));
        }
        let points = read_vec3(&positions, buffers).map_err(|e| format!("POSITION: {e}"))?;
        let normals = match primitive.get(&gltf::Semantic::Normals) {
            Some(n) if self.all_normals => {
                let normals = read_vec3(&n, buffers).map_err(|e| format!("NORMAL: {e}"))?;
                if normals.len() != points.len() {
                    return Err(format!(
                        "{} normals for {} positions",
                        normals.len(),
                        points.len()
                    ));
                }
                Some(normals)
            }
            _ => None,
        };
        let indices: Vec<u32> = match primitive.indices() {
            Some(a) => read_indices(&a, buffers).map_err(|e| format!("indices: {e}"))?,
            None => (0..u32::try_from(vertex_count).map_err(|_| "too many vertices")?).collect(),
        };
        if let Some(&i) = indices.iter().find(|&&i| i as usize >= points.len()) {
            return Err(format!("index {i} is out of range ({} vertices)", points.len()));
        }
        let m = self.mesh.positions.len();
        let base = u32::try_from(m)
            .ok()
            .filter(|_| (m + points.len()) as u64 <= u32::MAX.into())
            .ok_or_else(|| "more than 4294967295 vertices in all".to_owned())?;
        self.mesh.positions.try_reserve(points.len()).map_err(|_| "out of memory")?;
        self.mesh.positions.extend(points.iter().map(|p| transform_point(world, p)));
        if normals.is_none() && self.all_normals {
            self.all_normals = false;
            self.mesh.normals = Vec::new();
        }
        if let Some(normals) = &normals {
            // The inverse transpose is the cofactor matrix over the determinant; only the
            // sign of the determinant matters before renormalising.
            let sign = if determinant3(world) < 0.0 { -1.0 } else { 1.0 };
            let cof = cofactor(world).map(|row| row.map(|x| x * sign));
            debug_assert_eq!(self.mesh.normals.len(), m);
            self.mesh.normals.try_reserve(normals.len()).map_err(|_| "out of memory")?;
            self.mesh.normals.extend(normals.iter().map(|n| transform_normal(&cof, n)));
        }
        let mirrored = determinant3(world) < 0.0;
        let corner = |t: [u32; 3]| {
            let t = t.map(|i| base + i);
            if mirrored { [t[0], t[2], t[1]] } else { t }
        };
        self.mesh.triangles.try_reserve(triangle_count).map_err(|_| "out of memory")?;
        let v = &indices;
        match mode {
            Mode::Triangles => {
                self.mesh.triangles.extend(v.chunks_exact(3).map(|t| corner([t[0], t[1], t[2]])));
            }
            Mode::TriangleStrip => self.mesh.triangles.extend((0..triangle_count).map(|i| {
                if i % 2 == 0 {
                    corner([v[i], v[i + 1], v[i + 2]])
                } else {
                    corner([v[i], v[i + 2], v[i + 1]])
                }
            })),
            _ => self
                .mesh
                .triangles
                .extend((0..triangle_count).map(|i| corner([v[0], v[i + 1], v[i + 2]]))),
        }
        Ok(())
    }
}

/// The bytes of `accessor`'s elements: the slice starting at its first element, the stride,
/// with the extent checked against the view and the view against the buffer.
fn accessor_bytes<'b>(
    accessor: &gltf::Accessor,
    buffers: &'b [Cow<[u8]>],
) -> Result<(&'b [u8], usize), String> {
    let index = accessor.index();
    if accessor.sparse().is_some() {
        return Err(format!("accessor {index} is sparse (not supported)"));
    }
    let view = accessor
        .view()
        .ok_or_else(|| format!("accessor {index} has no buffer view (not supported)"))?;
    let data = &buffers[view.buffer().index()];
    // Counts and offsets are 64-bit in the JSON: all arithmetic on them saturates, and any
    // sum past the data is refused.
    let (start, len) = (view.offset() as u64, view.length() as u64);
    let view_end = start.saturating_add(len);
    if view_end > data.len() as u64 {
        return Err(format!(
            "buffer view {} (bytes {start}..{view_end}) runs past its buffer's {} bytes",
            view.index(),
            data.len()
        ));
    }
    let view_bytes = &data[start as usize..view_end as usize];
    let element = accessor.size();
    let stride = view.stride().unwrap_or(element);
    if stride < element {
        return Err(format!("buffer view {} has a stride below the element size", view.index()));
    }
    let count = accessor.count() as u64;
    let offset = accessor.offset() as u64;
    let end = match count {
        0 => offset,
        _ => offset
            .saturating_add((count - 1).saturating_mul(stride as u64))
            .saturating_add(element as u64),
    };
    if end > len {
        return Err(format!(
            "accessor {index} ({count} elements) needs {end} bytes of buffer view {}, which \
             has {len}",
            view.index()
        ));
    }
    Ok((&view_bytes[offset as usize..end as usize], stride))
}

/// A `VEC3` of `FLOAT` accessor's elements.
fn read_vec3(accessor: &gltf::Accessor, buffers: &[Cow<[u8]>]) -> Result<Vec<[f32; 3]>, String> {
    if accessor.dimensions() != Dimensions::Vec3 || accessor.data_type() != DataType::F32 {
        return Err(format!(
            "accessor {} is {:?} of {:?}, only VEC3 of FLOAT is supported",
            accessor.index(),
            accessor.dimensions(),
            accessor.data_type()
        ));
    }
    let (bytes, stride) = accessor_bytes(accessor, buffers)?;
    let f =
        |at: usize| f32::from_le_bytes([bytes[at], bytes[at + 1], bytes[at + 2], bytes[at + 3]]);
    Ok((0..accessor.count())
        .map(|i| [f(i * stride), f(i * stride + 4), f(i * stride + 8)])
        .collect())
}

/// A `SCALAR` accessor of unsigned integers, as `u32`.
fn read_indices(accessor: &gltf::Accessor, buffers: &[Cow<[u8]>]) -> Result<Vec<u32>, String> {
    let size = match (accessor.dimensions(), accessor.data_type()) {
        (Dimensions::Scalar, DataType::U8) => 1,
        (Dimensions::Scalar, DataType::U16) => 2,
        (Dimensions::Scalar, DataType::U32) => 4,
        (d, t) => {
            return Err(format!(
                "accessor {} is {d:?} of {t:?}, not an unsigned integer SCALAR",
                accessor.index()
            ));
        }
    };
    let (bytes, stride) = accessor_bytes(accessor, buffers)?;
    Ok((0..accessor.count())
        .map(|i| {
            let b = &bytes[i * stride..i * stride + size];
            match size {
                1 => b[0].into(),
                2 => u16::from_le_bytes([b[0], b[1]]).into(),
                _ => u32::from_le_bytes([b[0], b[1], b[2], b[3]]),
            }
        })
        .collect())
}

/// A node's local transform in `f64`: its matrix, or `T * R * S`.
fn local_matrix(node: &gltf::Node) -> Mat4 {
    match node.transform() {
        gltf::scene::Transform::Matrix { matrix } => matrix.map(|c| c.map(f64::from)),
        gltf::scene::Transform::Decomposed { translation: t, rotation: q, scale: s } => {
            let [x, y, z, w] = q.map(f64::from);
            // Normalised here: the file's quaternion is unit only to f32 precision. A zero
            // quaternion (invalid) is taken as no rotation.
            let norm = (x * x + y * y + z * z + w * w).sqrt();
            let (x, y, z, w) = if norm > 0.0 {
                (x / norm, y / norm, z / norm, w / norm)
            } else {
                (0.0, 0.0, 0.0, 1.0)
            };
            let r = [
                [1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y + z * w), 2.0 * (x * z - y * w)],
                [2.0 * (x * y - z * w), 1.0 - 2.0 * (x * x + z * z), 2.0 * (y * z + x * w)],
                [2.0 * (x * z + y * w), 2.0 * (y * z - x * w), 1.0 - 2.0 * (x * x + y * y)],
            ];
            let s = s.map(f64::from);
            let mut m = IDENTITY;
            for c in 0..3 {
                for k in 0..3 {
                    m[c][k] = r[c][k] * s[c];
                }
                m[3][c] = f64::from(t[c]);
            }
            m
        }
    }
}

/// `a * b` for column-major matrices.
fn multiply(a: &Mat4, b: &Mat4) -> Mat4 {
    let mut m = [[0.0; 4]; 4];
    for (c, col) in m.iter_mut().enumerate() {
        for (r, x) in col.iter_mut().enumerate() {
            *x = (0..4).map(|k| a[k][r] * b[c][k]).sum();
        }
    }
    m
}

/// The affine transform of a point (the projective row is ignored, as glTF requires it to
/// be `0 0 0 1`).
fn transform_point(m: &Mat4, p: &[f32; 3]) -> [f64; 3] {
    let p = p.map(f64::from);
    std::array::from_fn(|r| m[0][r] * p[0] + m[1][r] * p[1] + m[2][r] * p[2] + m[3][r])
}

/// Entry `(row, column)` of the upper 3x3 block.
fn at(m: &Mat4, r: usize, c: usize) -> f64 {
    m[c][r]
}

/// The determinant of the upper 3x3 block.
fn determinant3(m: &Mat4) -> f64 {
    let c = cofactor(m);
    (0..3).map(|k| at(m, 0, k) * c[0][k]).sum()
}

/// The cofactor matrix of the upper 3x3 block (row-major): `det * inverse-transpose`, the
/// normal transform up to a positive or negative factor.
fn cofactor(m: &Mat4) -> [[f64; 3]; 3] {
    std::array::from_fn(|r| {
        std::array::from_fn(|c| {
            let (r1, r2) = ((r + 1) % 3, (r + 2) % 3);
            let (c1, c2) = ((c + 1) % 3, (c + 2) % 3);
            at(m, r1, c1) * at(m, r2, c2) - at(m, r1, c2) * at(m, r2, c1)
        })
    })
}

/// A normal under the transform whose (sign-corrected) cofactor matrix is `cof`,
/// renormalised; a normal the transform collapses to zero is kept as it was.
fn transform_normal(cof: &[[f64; 3]; 3], n: &[f32; 3]) -> [f32; 3] {
    let n = n.map(f64::from);
    let v: [f64; 3] = std::array::from_fn(|r| (0..3).map(|c| cof[r][c] * n[c]).sum());
    let len = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    if len > 0.0 && len.is_finite() { v.map(|x| (x / len) as f32) } else { n.map(|x| x as f32) }
}
