//! PLY (the Stanford polygon format), ASCII and binary in either byte order.
//!
//! # Triangle order
//!
//! Faces in the order of the `face` element; a face with `n >= 3` vertex indices
//! `(v0, ..., v(n-1))` becomes the fan `(v0, v1, v2), (v0, v2, v3), ..., (v0, v(n-2),
//! v(n-1))`, as in OBJ. Vertices keep their file order, so [`Mesh::positions`]`[i]` is the
//! file's vertex `i`.
//!
//! # What the loader accepts
//!
//! Parsing is done by [`ply_rs_bw`]. The `vertex` element's `x`, `y`, `z` (any scalar type,
//! read into `f64`) are the positions; `nx`, `ny`, `nz`, when all three are declared, are
//! vertex normals and become [`Mesh::normals`]. The `face` element's `vertex_indices` (or
//! `vertex_index`) list, of any integer type, gives the faces. Other elements and properties
//! (colours, texture coordinates, `edge`, `material`, ...) are read past and ignored.
//!
//! Each element's count is checked against the bytes after the header before any is read:
//! an element needs at least its scalar properties' sizes and its lists' count sizes per entry
//! in a binary file, and at least one byte (its line end) in an ASCII file, so a header
//! announcing four billion vertices in a short file is refused at once.

use ply_rs_bw::parser::{Parser, Reader};
use ply_rs_bw::ply::{
    ElementDef, Encoding, Header, Property, PropertyAccess, PropertyAccessResult, PropertyType,
    ScalarType,
};

use super::{IndexedMesh, Mesh, SceneError, try_vec};

/// Parses PLY bytes (see the [module documentation](self)).
pub(crate) fn from_ply_bytes(bytes: &[u8], name: &str) -> Result<Mesh, SceneError> {
    let mut reader = Reader::new(bytes);
    let header = Parser::<Skip>::new()
        .read_header(&mut reader)
        .map_err(|e| ply_error(name, &e, "the header", true))?;
    check_counts(&header, reader.get_ref().len(), name)?;
    let vertex = header.elements.get("vertex");
    let has_normals =
        vertex.is_some_and(|v| ["nx", "ny", "nz"].iter().all(|p| v.properties.contains_key(*p)));
    let mut mesh = IndexedMesh::default();
    let mut faces: Vec<Face> = Vec::new();
    for element in header.elements.values() {
        let ascii = header.encoding == Encoding::Ascii;
        let fail = |e: ply_rs_bw::parser::ParseError| {
            ply_error(name, &e, &format!("element `{}`", element.name), ascii)
        };
        match element.name.as_str() {
            "vertex" => {
                let vertices = Parser::<Vertex>::new()
                    .read_payload_for_element(&mut reader, element, &header)
                    .map_err(fail)?;
                mesh.positions = try_vec(vertices.len(), name)?;
                mesh.positions.extend(vertices.iter().map(|v| v.position));
                if has_normals {
                    mesh.normals = try_vec(vertices.len(), name)?;
                    mesh.normals.extend(vertices.iter().map(|v| v.normal));
                }
            }
            "face" => {
                faces = Parser::<Face>::new()
                    .read_payload_for_element(&mut reader, element, &header)
                    .map_err(fail)?;
            }
            _ => {
                Parser::<Skip>::new()
                    .read_payload_for_element(&mut reader, element, &header)
                    .map_err(fail)?;
            }
        }
    }
    let count: usize = faces.iter().map(|f| f.indices.len().saturating_sub(2)).sum();
    mesh.triangles = try_vec(count, name)?;
    for (i, face) in faces.iter().enumerate() {
        if let Some(bad) = face.bad {
            return Err(SceneError::invalid(
                name,
                format!("invalid PLY: face {i} has the vertex index {bad}"),
            ));
        }
        let v = &face.indices;
        if v.len() < 3 {
            return Err(SceneError::invalid(
                name,
                format!("invalid PLY: face {i} has {} vertices (at least 3 needed)", v.len()),
            ));
        }
        mesh.triangles.extend((1..v.len() - 1).map(|k| [v[0], v[k], v[k + 1]]));
    }
    mesh.finish(name)
}

/// The one-line error for a `ply_rs_bw` failure while reading `what`; the crate's line
/// number is kept where it means something (the header, an ASCII payload).
fn ply_error(
    name: &str,
    e: &ply_rs_bw::parser::ParseError,
    what: &str,
    text_lines: bool,
) -> SceneError {
    let text = e.to_string();
    let text = match e.line() {
        Some(line) => text.strip_prefix(&format!("Line {line}: ")).unwrap_or(&text).to_owned(),
        None => text,
    };
    // The crate's messages span lines (`Parse error.\n\tValue: ...`): one line here.
    let problem = text.split_whitespace().collect::<Vec<_>>().join(" ");
    // Header errors end in the grammar's own state (` Error: ParseError { location: ...,
    // expected: ExpectedSet { ... } }`), which tells a user nothing the first part does not.
    let problem = problem.split(" Error: ParseError").next().unwrap_or(&problem);
    let problem = format!("invalid PLY in {what}: {problem}");
    match e.line() {
        Some(line) if text_lines => SceneError::Malformed { file: name.to_owned(), line, problem },
        _ => SceneError::invalid(name, problem),
    }
}

/// Bytes of a binary scalar.
fn scalar_size(t: &ScalarType) -> u64 {
    match t {
        ScalarType::Char | ScalarType::UChar => 1,
        ScalarType::Short | ScalarType::UShort => 2,
        ScalarType::Int | ScalarType::UInt | ScalarType::Float => 4,
        ScalarType::Double => 8,
    }
}

/// Least bytes one entry of `element` takes in the payload.
fn min_entry_size(element: &ElementDef, encoding: Encoding) -> u64 {
    if encoding == Encoding::Ascii {
        return 1;
    }
    let size: u64 = element
        .properties
        .values()
        .map(|p| match &p.data_type {
            PropertyType::Scalar(t) => scalar_size(t),
            // An empty list still has its count.
            PropertyType::List(count, _) => scalar_size(count),
        })
        .sum();
    // An entry of no property takes no byte, but no real file has a count of them: treat it
    // as one byte so that the count is still bounded by the file.
    size.max(1)
}

/// Refuses an element count that the `payload` bytes after the header cannot hold.
fn check_counts(header: &Header, payload: usize, name: &str) -> Result<(), SceneError> {
    let mut needed = 0u64;
    for element in header.elements.values() {
        let size = min_entry_size(element, header.encoding);
        needed = needed.saturating_add((element.count as u64).saturating_mul(size));
        if needed > payload as u64 {
            return Err(SceneError::invalid(
                name,
                format!(
                    "invalid PLY: the header announces {} `{}` entries (at least {size} bytes \
                     each), more than the {payload} bytes after the header can hold",
                    element.count, element.name
                ),
            ));
        }
    }
    Ok(())
}

/// A scalar property as `f64`.
fn scalar(p: &Property) -> Option<f64> {
    Some(match *p {
        Property::Char(x) => x.into(),
        Property::UChar(x) => x.into(),
        Property::Short(x) => x.into(),
        Property::UShort(x) => x.into(),
        Property::Int(x) => x.into(),
        Property::UInt(x) => x.into(),
        Property::Float(x) => x.into(),
        Property::Double(x) => x,
        _ => return None,
    })
}

/// An entry of the `vertex` element.
struct Vertex {
    position: [f64; 3],
    normal: [f32; 3],
}

impl PropertyAccess for Vertex {
    fn new() -> Self {
        Vertex { position: [0.0; 3], normal: [0.0; 3] }
    }

    fn set_property(&mut self, name: &str, property: Property) -> PropertyAccessResult {
        let Some(x) = scalar(&property) else { return PropertyAccessResult::Ignored };
        match name {
            "x" => self.position[0] = x,
            "y" => self.position[1] = x,
            "z" => self.position[2] = x,
            "nx" => self.normal[0] = x as f32,
            "ny" => self.normal[1] = x as f32,
            "nz" => self.normal[2] = x as f32,
            _ => return PropertyAccessResult::Ignored,
        }
        PropertyAccessResult::Set
    }
}

/// An entry of the `face` element: its vertex indices, or the first negative one.
struct Face {
    indices: Vec<u32>,
    bad: Option<i64>,
}

impl Face {
    /// Keeps `list` as the indices, noting the first that is negative.
    fn set<T: Copy + Into<i64>>(&mut self, list: &[T]) {
        self.indices = Vec::with_capacity(list.len());
        for &x in list {
            match u32::try_from(x.into()) {
                Ok(v) => self.indices.push(v),
                Err(_) => {
                    self.bad.get_or_insert(x.into());
                }
            }
        }
    }
}

impl PropertyAccess for Face {
    fn new() -> Self {
        Face { indices: Vec::new(), bad: None }
    }

    fn set_property(&mut self, name: &str, property: Property) -> PropertyAccessResult {
        if name != "vertex_indices" && name != "vertex_index" {
            return PropertyAccessResult::Ignored;
        }
        match property {
            Property::ListChar(l) => self.set(&l),
            Property::ListUChar(l) => self.set(&l),
            Property::ListShort(l) => self.set(&l),
            Property::ListUShort(l) => self.set(&l),
            Property::ListInt(l) => self.set(&l),
            Property::ListUInt(l) => self.set(&l),
            _ => return PropertyAccessResult::UnsupportedType,
        }
        PropertyAccessResult::Set
    }
}

/// An entry of an element this loader does not use.
struct Skip;

impl PropertyAccess for Skip {
    fn new() -> Self {
        Skip
    }
}
