//! The readers under test: one row of [`TARGETS`] each.
//!
//! A target runs one reader on the input and checks what comes back, panicking when an answer
//! breaks the reader's contract, so that a wrong answer is caught like a crash:
//! - an error message is one line (no line break);
//! - an accepted `.npy` array has `rows * 6` values, and writing it and reading it back gives
//!   the same bits (`f32` files: every value is exactly an `f32`);
//! - an accepted `.npz` rays file (read from a file, as `raycast` reads it, a chunk at a time)
//!   gives exactly the values its shape calls for;
//! - an accepted mesh has a triangle, every index names a vertex, every coordinate and normal
//!   component is finite, and there is one normal triple per triangle.

use render::output::npy;
use scene::MeshFormat::{self, Glb, Gltf, Obj, Ply, Stl};
use scene::memory::FROM_BYTES_MULTIPLE;
use scene::{Mesh, SceneError, gz};

/// What a reader made of one input: `Ok` with a short description of what it read (without
/// numbers, so that it can tell kinds of answer apart), or its error message.
pub type Outcome = Result<String, String>;

/// One reader to fuzz.
pub struct Target {
    /// The name on the command line, and of the folders `corpus/NAME` and `crashes/NAME`.
    pub name: &'static str,
    /// Runs the reader on the input and checks its answer (panics when the answer is wrong).
    pub run: fn(&[u8]) -> Outcome,
    /// Keywords and fragments of the format for the mutator to insert.
    pub tokens: &'static [&'static [u8]],
    /// Memory the reader may hold at once per input byte, beyond [`crate::MEMORY_BASE`]: a
    /// file can only hold so much, and a reader that reserves what a header claims instead of
    /// what the file holds goes far beyond this.
    pub memory_per_byte: usize,
}

/// What `Mesh::from_bytes` promises to allocate at most per input byte.
const MESH: usize = FROM_BYTES_MULTIPLE as usize;

/// The most a deflate stream expands (1032 to 1), so the most a gzip target's input can hold.
const GZ: usize = 1032;

/// Every target. Adding a reader is one row here and a folder of seeds in `fuzz/corpus/`.
pub const TARGETS: &[Target] = &[
    Target { name: "npy", run: npy_rays, tokens: NPY_TOKENS, memory_per_byte: 64 },
    Target { name: "npz", run: npz_rays, tokens: NPZ_TOKENS, memory_per_byte: 64 },
    Target { name: "obj", run: |b| mesh(Obj, b), tokens: OBJ_TOKENS, memory_per_byte: MESH },
    Target { name: "ply", run: |b| mesh(Ply, b), tokens: PLY_TOKENS, memory_per_byte: MESH },
    Target { name: "stl", run: |b| mesh(Stl, b), tokens: STL_TOKENS, memory_per_byte: MESH },
    Target { name: "gltf", run: |b| mesh(Gltf, b), tokens: GLTF_TOKENS, memory_per_byte: MESH },
    Target { name: "glb", run: |b| mesh(Glb, b), tokens: GLTF_TOKENS, memory_per_byte: MESH },
    Target { name: "obj.gz", run: |b| gz(Obj, b), tokens: GZ_TOKENS, memory_per_byte: GZ * MESH },
    Target { name: "ply.gz", run: |b| gz(Ply, b), tokens: GZ_TOKENS, memory_per_byte: GZ * MESH },
];

/// The target called `name`.
#[must_use]
pub fn find(name: &str) -> Option<&'static Target> {
    TARGETS.iter().find(|t| t.name == name)
}

/// The name the readers give the input in their messages.
pub const INPUT_NAME: &str = "fuzz-input";

const NPY_TOKENS: &[&[u8]] = &[
    b"\x93NUMPY\x01\x00",
    b"\x93NUMPY\x02\x00",
    b"\x93NUMPY\x03\x00",
    b"{'descr': '<f8', 'fortran_order': False, 'shape': (1, 6), }",
    b"'descr': ",
    b"'fortran_order': ",
    b"'shape': ",
    b"'<f4'",
    b"'<f8'",
    b"'>f8'",
    b"'|u1'",
    b"\"<f8\"",
    b"True",
    b"False",
    b"(4294967295, 6)",
    b"(3074457345618258602, 6)",
    b"(18446744073709551615, 6)",
    b"(0, 6)",
    b"(6,)",
    b"()",
    b", ",
    b": ",
    b"{",
    b"}",
    b"(",
    b")",
    b"'",
    b"\n",
    b"\xff\xff",
];

const OBJ_TOKENS: &[&[u8]] = &[
    b"v ",
    b"vt ",
    b"vn ",
    b"vp ",
    b"f ",
    b"l ",
    b"p ",
    b"o ",
    b"g ",
    b"s off",
    b"usemtl ",
    b"mtllib ",
    b"/",
    b"//",
    b" ",
    b"\t",
    b"\n",
    b"\r\n",
    b"\\\n",
    b"#",
    b"-",
    b"v 0 0 0\n",
    b"v 1e300 -1e300 1e-300 1e-300\n",
    b"v 1 2 3 0.5 0.5 0.5\n",
    b"vn 0 0 1\n",
    b"vt 0 0\n",
    b"f 1 2 3\n",
    b"f 1/1/1 2/2/2 3/3/3\n",
    b"f 1//1 2//1 3//1\n",
    b"f 1/1 2/1 3/1\n",
    b"f -1 -2 -3\n",
    b"f 1 2 3 4 5 6 7 8\n",
    b"\xef\xbb\xbf",
    b"\0",
];

const PLY_TOKENS: &[&[u8]] = &[
    b"ply\n",
    b"format ascii 1.0\n",
    b"format binary_little_endian 1.0\n",
    b"format binary_big_endian 1.0\n",
    b"comment x\n",
    b"element vertex ",
    b"element face ",
    b"element vertex 4294967295\n",
    b"element face 18446744073709551615\n",
    b"property float x\n",
    b"property double y\n",
    b"property uchar red\n",
    b"property list uchar int vertex_indices\n",
    b"property list uint uint vertex_index\n",
    b"property list uchar uchar vertex_indices\n",
    b"end_header\n",
    b"\n",
    b" ",
    b"\r\n",
    b"255 ",
    b"3 0 1 2\n",
];

const STL_TOKENS: &[&[u8]] = &[
    b"solid ",
    b"facet normal 0 0 1\n",
    b"outer loop\n",
    b"vertex 0 0 0\n",
    b"vertex ",
    b"endloop\n",
    b"endfacet\n",
    b"endsolid\n",
    b"\xff\xff\xff\xff",
    b"\x01\x00\x00\x00",
    b"\n",
    b" ",
];

const GLTF_TOKENS: &[&[u8]] = &[
    b"glTF",
    b"JSON",
    b"BIN\0",
    b"\"accessors\"",
    b"\"bufferView\":",
    b"\"bufferViews\"",
    b"\"buffers\"",
    b"\"byteOffset\":",
    b"\"byteLength\":",
    b"\"byteStride\":",
    b"\"count\":",
    b"\"componentType\":5126",
    b"5125",
    b"5123",
    b"5121",
    b"\"type\":\"VEC3\"",
    b"\"SCALAR\"",
    b"\"indices\":",
    b"\"mode\":",
    b"\"matrix\":[0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0]",
    b"\"scale\":[1e39,1,1]",
    b"\"children\":[0]",
    b"\"nodes\":[0,0]",
    b"\"sparse\":{\"count\":1}",
    b"\"uri\":\"data:application/octet-stream;base64,AAAA\"",
    b"\"uri\":\"x.bin\"",
    b"null",
    b"[",
    b"]",
    b"{",
    b"}",
    b",",
    b":",
    b"\"",
];

/// Zip records (local header, central directory, end of directory, ZIP64 end) and `.npy`
/// headers, for `.npz` archives.
const NPZ_TOKENS: &[&[u8]] = &[
    b"PK\x03\x04",
    b"PK\x01\x02",
    b"PK\x05\x06",
    b"PK\x06\x06",
    b"PK\x06\x07",
    b"rays.npy",
    b"\x93NUMPY\x01\x00",
    b"{'descr': '<f4', 'fortran_order': False, 'shape': (2, 8), }",
    b"\x00\x00\x00\x00",
    b"\xff\xff\xff\xff",
];

/// Bytes that make gzip headers and deflate blocks (the readers' own tokens are in the
/// compressed stream only by chance: the plain targets fuzz the text inside).
const GZ_TOKENS: &[&[u8]] = &[
    b"\x1f\x8b\x08\x00\x00\x00\x00\x00\x00\xff",
    b"\x1f\x8b\x08\x08",
    b"\x03\x00",
    b"\x00\x00\xff\xff",
    b"\xff\xff\xff\xff",
];

/// `.npy` rays as `raycast` reads them: an `(N, 6)` array.
fn npy_rays(bytes: &[u8]) -> Outcome {
    let m = match npy::read_f64_matrix(bytes, 6) {
        Ok(m) => m,
        Err(e) => return Err(one_line(&e)),
    };
    assert_eq!(m.columns, 6, "read_f64_matrix(_, 6) returned {} columns", m.columns);
    assert_eq!(m.values.len(), m.rows * 6, "{} values for {} rows", m.values.len(), m.rows);
    let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
    let mut again = Vec::new();
    if m.was_f32 {
        let narrow: Vec<f32> = m.values.iter().map(|&x| x as f32).collect();
        let wide: Vec<f64> = narrow.iter().map(|&x| f64::from(x)).collect();
        assert_eq!(bits(&wide), bits(&m.values), "an f32 file gave values that are not f32");
        npy::write(&mut again, &[m.rows, 6], narrow).expect("writing to memory");
    } else {
        npy::write(&mut again, &[m.rows, 6], m.values.iter().copied()).expect("writing to memory");
    }
    let back = npy::read_f64_matrix(&again, 6).expect("reading back what was written");
    assert_eq!((back.rows, back.was_f32), (m.rows, m.was_f32), "read back differently");
    assert_eq!(bits(&back.values), bits(&m.values), "values changed when read back");
    Ok(format!("{} array", if m.was_f32 { "f32" } else { "f64" }))
}

/// `.npz` rays as `raycast` reads them: written to a file (the reader seeks), opened, and
/// read in chunks of 1000 rays (each input in a file of its own: the tests run targets on
/// several threads at once).
fn npz_rays(bytes: &[u8]) -> Outcome {
    use render::cast::files::RaysFile;
    use std::sync::atomic::{AtomicU64, Ordering};
    static INPUTS: AtomicU64 = AtomicU64::new(0);
    let n = INPUTS.fetch_add(1, Ordering::Relaxed);
    let name = format!("wedge-fuzz-{}-{n}.npz", std::process::id());
    let path = std::env::temp_dir().join(name);
    std::fs::write(&path, bytes).expect("writing the input to a temporary file");
    let opened = RaysFile::open(&path, None);
    // Open files outlive their name (Linux): leave nothing in the temporary directory.
    std::fs::remove_file(&path).expect("removing the temporary file");
    let mut file = match opened {
        Ok(file) => file,
        Err(e) => return Err(one_line(&e)),
    };
    let (rows, columns, was_f32) = (file.rows(), file.columns(), file.was_f32());
    assert!(columns == 6 || columns == 8, "{columns} columns accepted");
    let mut reader = match file.rows_reader() {
        Ok(reader) => reader,
        Err(e) => return Err(one_line(&e)),
    };
    let (mut values, mut read) = (Vec::<f64>::new(), 0);
    loop {
        match reader.next_rows(1000, &mut values) {
            Ok(0) => break,
            Ok(n) => {
                assert_eq!(values.len(), n * columns, "{} values for {n} rows", values.len());
                read += n;
            }
            Err(e) => return Err(one_line(&e)),
        }
    }
    assert_eq!(read, rows, "{read} rows read of {rows}");
    Ok(format!("{} npz array", if was_f32 { "f32" } else { "f64" }))
}

/// A mesh file as `Mesh::load` reads one of `format` (without a glTF's external buffers).
fn mesh(format: MeshFormat, bytes: &[u8]) -> Outcome {
    check_mesh(Mesh::from_bytes(bytes, format, INPUT_NAME))
}

/// The largest decompressed size the gzip targets accept: enough for any mutation of the
/// seeds, small enough that a bomb is refused quickly.
const GZ_LIMIT: u64 = 4 << 20;

/// A gzip-compressed file of `format` as `Mesh::load` reads one.
fn gz(format: MeshFormat, bytes: &[u8]) -> Outcome {
    match gz::gunzip(bytes, GZ_LIMIT, INPUT_NAME) {
        Ok(plain) => check_mesh(Mesh::from_bytes(&plain, format, INPUT_NAME)),
        Err(e) => Err(one_line(&e)),
    }
}

/// Checks a mesh reader's answer.
fn check_mesh(result: Result<Mesh, SceneError>) -> Outcome {
    let mesh = match result {
        Ok(mesh) => mesh,
        Err(e) => return Err(one_line(&e)),
    };
    assert!(!mesh.triangles.is_empty(), "a mesh without triangles was accepted");
    let n = mesh.positions.len();
    for (i, p) in mesh.positions.iter().enumerate() {
        assert!(p.iter().all(|x| x.is_finite()), "vertex {i} is {p:?}");
    }
    for (i, t) in mesh.triangles.iter().enumerate() {
        assert!(t.iter().all(|&v| (v as usize) < n), "triangle {i} is {t:?} with {n} vertices");
    }
    if let Some(normals) = &mesh.normals {
        assert_eq!(normals.len(), mesh.triangles.len(), "normals and triangles differ in count");
        for (i, corners) in normals.iter().enumerate() {
            let finite = corners.iter().flatten().all(|x| x.is_finite());
            assert!(finite, "triangle {i} has the normals {corners:?}");
        }
    }
    Ok(format!("mesh{}", if mesh.normals.is_some() { " with normals" } else { "" }))
}

/// The error's message, checked to be one line: no character that breaks a line in a terminal
/// or an editor. (Other control characters quoted from a file are a lesser fault, left to the
/// readers' own tests, so that they do not stop a run before it finds worse.)
fn one_line(e: &dyn std::error::Error) -> String {
    let text = e.to_string();
    let breaks = ['\n', '\r', '\u{b}', '\u{c}', '\u{85}', '\u{2028}', '\u{2029}'];
    let bad = text.chars().find(|c| breaks.contains(c));
    assert!(bad.is_none(), "the error message holds {bad:?}: {text:?}");
    text
}
