//! STL, ASCII and binary.
//!
//! # Triangle order
//!
//! Facets in file order, one triangle each, corners in the order of their `vertex` lines (or
//! of the three binary vertices). Each facet has its own three vertices in
//! [`Mesh::positions`]: STL shares none, and the kernels are watertight on edges whose
//! coordinates agree, which is what STL stores. The facet normals are not used (they are often
//! zero or stale, and a facet normal is no per-corner normal), so [`Mesh::normals`] is `None`.
//!
//! # Binary or ASCII
//!
//! A binary STL is an 80-byte header, a 32-bit little-endian facet count `n` and `n` records
//! of 50 bytes (normal, three vertices, attribute count). Some exporters write binary files
//! whose header starts with `solid`, the keyword of ASCII STL, so the size decides: a file of
//! exactly `84 + 50 n` bytes is binary whatever its first bytes; otherwise a file starting with
//! `solid` is ASCII, and any other file is binary and must hold at least the `n` records
//! its count announces (later bytes are ignored). The count is checked against the size
//! before anything is allocated.
//!
//! The parser is this module's own: the binary layout is fixed and short, and the ASCII
//! reader gives line numbers and keeps decimal coordinates in `f64` (binary STL is `f32`,
//! read exactly).

use super::{IndexedMesh, Mesh, SceneError, try_vec};

/// Bytes before the first binary record.
const HEADER: usize = 84;
/// Bytes of one binary record.
const RECORD: usize = 50;

/// Parses STL bytes, binary or ASCII (see the [module documentation](self)).
pub(crate) fn from_stl_bytes(bytes: &[u8], name: &str) -> Result<Mesh, SceneError> {
    let count = bytes.get(80..HEADER).map(|c| u32::from_le_bytes([c[0], c[1], c[2], c[3]]));
    let exact_binary =
        count.is_some_and(|n| (n as u64) * RECORD as u64 + HEADER as u64 == bytes.len() as u64);
    let ascii = trim_start(bytes).starts_with(b"solid");
    if exact_binary || !ascii {
        let Some(n) = count else {
            return Err(SceneError::invalid(
                name,
                format!(
                    "invalid STL: {} bytes is too short for binary STL (84-byte header) and the \
                     file does not start with `solid`",
                    bytes.len()
                ),
            ));
        };
        return binary(bytes, n as usize, name);
    }
    ascii_stl(bytes, name)
}

/// `bytes` without leading ASCII white space.
fn trim_start(bytes: &[u8]) -> &[u8] {
    let at = bytes.iter().position(|b| !b.is_ascii_whitespace()).unwrap_or(bytes.len());
    &bytes[at..]
}

/// The `n` records of a binary STL.
fn binary(bytes: &[u8], n: usize, name: &str) -> Result<Mesh, SceneError> {
    let needed = (n as u64) * RECORD as u64 + HEADER as u64;
    if needed > bytes.len() as u64 {
        return Err(SceneError::invalid(
            name,
            format!(
                "invalid binary STL: the header announces {n} facets ({needed} bytes), the file \
                 has {} bytes",
                bytes.len()
            ),
        ));
    }
    if 3 * n > u32::MAX as usize {
        return Err(SceneError::TooLarge { file: name.to_owned(), count: 3 * n, what: "vertices" });
    }
    let mut mesh = IndexedMesh {
        positions: try_vec(3 * n, name)?,
        triangles: try_vec(n, name)?,
        ..IndexedMesh::default()
    };
    for (i, record) in bytes[HEADER..].chunks_exact(RECORD).take(n).enumerate() {
        let f = |k: usize| {
            let at = 12 + 4 * k;
            f64::from(f32::from_le_bytes([
                record[at],
                record[at + 1],
                record[at + 2],
                record[at + 3],
            ]))
        };
        for v in 0..3 {
            mesh.positions.push([f(3 * v), f(3 * v + 1), f(3 * v + 2)]);
        }
        // 3 n fits in u32 (checked above).
        let base = (3 * i) as u32;
        mesh.triangles.push([base, base + 1, base + 2]);
    }
    mesh.finish(name)
}

/// What the ASCII reader expects next.
#[derive(Clone, Copy, PartialEq)]
enum Expect {
    /// `solid` (at the start, or after `endsolid`).
    Solid,
    /// `facet` or `endsolid`.
    Facet,
    /// `outer loop`.
    OuterLoop,
    /// Vertex `k` (0, 1, 2) of the loop.
    Vertex(usize),
    /// `endloop`.
    EndLoop,
    /// `endfacet`.
    EndFacet,
}

/// Parses ASCII STL: `solid [name]`, then facets `facet normal nx ny nz`, `outer loop`, three
/// `vertex x y z`, `endloop`, `endfacet`, then `endsolid [name]`; several solids may follow
/// each other. Keywords are case-insensitive.
fn ascii_stl(bytes: &[u8], name: &str) -> Result<Mesh, SceneError> {
    let text = String::from_utf8_lossy(bytes);
    let mut mesh = IndexedMesh::default();
    let mut expect = Expect::Solid;
    let mut line_no = 0;
    for (i, text_line) in text.lines().enumerate() {
        let line = i + 1;
        line_no = line;
        let bad = |problem: String| SceneError::Malformed { file: name.to_owned(), line, problem };
        let words: Vec<&str> = text_line.split_whitespace().collect();
        let Some(keyword) = words.first() else { continue };
        let keyword = keyword.to_ascii_lowercase();
        let wanted = match expect {
            Expect::Solid => "solid",
            Expect::Facet if keyword == "endsolid" => {
                expect = Expect::Solid;
                continue;
            }
            Expect::Facet => "facet",
            Expect::OuterLoop => "outer",
            Expect::Vertex(_) => "vertex",
            Expect::EndLoop => "endloop",
            Expect::EndFacet => "endfacet",
        };
        if keyword != wanted {
            let wanted = if expect == Expect::Facet { "`facet` or `endsolid`" } else { wanted };
            return Err(bad(format!("expected {wanted}, found `{}`", words[0])));
        }
        expect = match expect {
            Expect::Solid => Expect::Facet,
            Expect::Facet => {
                if words.len() != 5 || !words[1].eq_ignore_ascii_case("normal") {
                    return Err(bad("expected `facet normal nx ny nz`".to_owned()));
                }
                numbers(&words[2..], &bad)?;
                Expect::OuterLoop
            }
            Expect::OuterLoop => {
                if words.len() != 2 || !words[1].eq_ignore_ascii_case("loop") {
                    return Err(bad("expected `outer loop`".to_owned()));
                }
                Expect::Vertex(0)
            }
            Expect::Vertex(k) => {
                if words.len() != 4 {
                    return Err(bad(format!(
                        "a vertex needs 3 numbers, found {}",
                        words.len() - 1
                    )));
                }
                let p = numbers(&words[1..], &bad)?;
                if let Some(x) = p.iter().find(|x| !x.is_finite()) {
                    return Err(SceneError::NotFinite {
                        file: name.to_owned(),
                        line,
                        what: "vertex coordinate",
                        value: x.to_string(),
                    });
                }
                mesh.positions.try_reserve(1).map_err(|_| oom(name, &mesh))?;
                mesh.positions.push(p);
                if k == 2 { Expect::EndLoop } else { Expect::Vertex(k + 1) }
            }
            Expect::EndLoop => Expect::EndFacet,
            Expect::EndFacet => {
                let base =
                    u32::try_from(mesh.positions.len() - 3).map_err(|_| SceneError::TooLarge {
                        file: name.to_owned(),
                        count: mesh.positions.len(),
                        what: "vertices",
                    })?;
                mesh.triangles.try_reserve(1).map_err(|_| oom(name, &mesh))?;
                mesh.triangles.push([base, base + 1, base + 2]);
                Expect::Facet
            }
        };
    }
    if !matches!(expect, Expect::Solid | Expect::Facet) {
        return Err(SceneError::invalid(
            name,
            format!("invalid STL: the file ends inside a facet (line {line_no})"),
        ));
    }
    mesh.finish(name)
}

/// Three numbers, or the error for the first word that is not one.
fn numbers(words: &[&str], bad: &dyn Fn(String) -> SceneError) -> Result<[f64; 3], SceneError> {
    let mut p = [0.0; 3];
    for (x, w) in p.iter_mut().zip(words) {
        *x = w.parse().map_err(|_| bad(format!("`{w}` is not a number")))?;
    }
    Ok(p)
}

/// The error for an allocator refusal while growing `mesh`.
fn oom(name: &str, mesh: &IndexedMesh) -> SceneError {
    SceneError::OutOfMemory {
        file: name.to_owned(),
        needed: (mesh.positions.len() as u64 + 1) * 24 + mesh.triangles.len() as u64 * 12,
        available: super::memory::available().unwrap_or(0),
    }
}
