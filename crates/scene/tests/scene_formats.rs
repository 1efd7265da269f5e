//! PLY, STL, glTF/GLB and gzip loading: each format against an OBJ of the same mesh written
//! independently here, the documented triangle orders, and the refusals (malformed,
//! truncated, absurd counts, gzip bombs), each one line naming the file.

use std::io::Write as _;
use std::path::Path;

use scene::{Mesh, MeshFormat, SceneError};

/// A small test mesh: a unit square (two triangles) and a pentagon lifted to z = 1, with
/// coordinates exact in f32, and a normal per vertex.
struct Shape {
    positions: Vec<[f32; 3]>,
    normals: Vec<[f32; 3]>,
    /// Faces as polygons (fanned by every format but STL and glTF, which get triangles).
    faces: Vec<Vec<u32>>,
}

fn shape() -> Shape {
    let positions = vec![
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [1.0, 1.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.5, 0.25, 1.0],
        [2.0, 0.5, 1.0],
        [1.5, 2.0, 1.0],
        [0.25, 1.75, 1.0],
        [-0.5, 1.0, 1.0],
    ];
    let normals =
        (0..positions.len()).map(|i| if i < 4 { [0.0, 0.0, 1.0] } else { [0.0, 1.0, 0.0] });
    Shape {
        positions,
        normals: normals.collect(),
        faces: vec![vec![0, 1, 2, 3], vec![4, 5, 6, 7, 8], vec![2, 1, 0]],
    }
}

impl Shape {
    /// The faces fanned from their first vertex.
    fn triangles(&self) -> Vec<[u32; 3]> {
        let mut t = Vec::new();
        for f in &self.faces {
            for k in 1..f.len() - 1 {
                t.push([f[0], f[k], f[k + 1]]);
            }
        }
        t
    }

    fn obj(&self, normals: bool) -> String {
        let mut s = String::new();
        for p in &self.positions {
            s += &format!("v {} {} {}\n", p[0], p[1], p[2]);
        }
        if normals {
            for n in &self.normals {
                s += &format!("vn {} {} {}\n", n[0], n[1], n[2]);
            }
        }
        for f in &self.faces {
            s += "f";
            for v in f {
                if normals {
                    s += &format!(" {}//{}", v + 1, v + 1);
                } else {
                    s += &format!(" {}", v + 1);
                }
            }
            s += "\n";
        }
        s
    }

    fn ply_header(&self, format: &str, index_type: &str) -> String {
        format!(
            "ply\nformat {format} 1.0\ncomment made by the test\nelement vertex {}\n\
             property float x\nproperty float y\nproperty float z\nproperty float nx\n\
             property float ny\nproperty float nz\nproperty uchar red\n\
             element face {}\nproperty list uchar {index_type} vertex_indices\n\
             element edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n",
            self.positions.len(),
            self.faces.len()
        )
    }

    fn ply_ascii(&self) -> Vec<u8> {
        let mut s = self.ply_header("ascii", "int");
        for (p, n) in self.positions.iter().zip(&self.normals) {
            s += &format!("{} {} {} {} {} {} 255\n", p[0], p[1], p[2], n[0], n[1], n[2]);
        }
        for f in &self.faces {
            s += &f.len().to_string();
            for v in f {
                s += &format!(" {v}");
            }
            s += "\n";
        }
        s += "0 1\n";
        s.into_bytes()
    }

    /// Binary PLY with `index_type` (`uchar`, `ushort`, `uint`, `int`) indices.
    fn ply_binary(&self, big_endian: bool, index_type: &str) -> Vec<u8> {
        let format = if big_endian { "binary_big_endian" } else { "binary_little_endian" };
        let mut out = self.ply_header(format, index_type).into_bytes();
        let f32b = |x: f32| if big_endian { x.to_be_bytes() } else { x.to_le_bytes() };
        for (p, n) in self.positions.iter().zip(&self.normals) {
            for x in p.iter().chain(n) {
                out.extend(f32b(*x));
            }
            out.push(255);
        }
        for f in &self.faces {
            out.push(f.len() as u8);
            for &v in f {
                match index_type {
                    "uchar" => out.push(v as u8),
                    "ushort" if big_endian => out.extend((v as u16).to_be_bytes()),
                    "ushort" => out.extend((v as u16).to_le_bytes()),
                    _ if big_endian => out.extend(v.to_be_bytes()),
                    _ => out.extend(v.to_le_bytes()),
                }
            }
        }
        let i32b = |x: i32| if big_endian { x.to_be_bytes() } else { x.to_le_bytes() };
        out.extend(i32b(0));
        out.extend(i32b(1));
        out
    }

    fn stl_ascii(&self) -> Vec<u8> {
        let mut s = "solid test\n".to_owned();
        for t in self.triangles() {
            s += "  facet normal 0 0 0\n    outer loop\n";
            for v in t {
                let p = self.positions[v as usize];
                s += &format!("      vertex {} {} {}\n", p[0], p[1], p[2]);
            }
            s += "    endloop\n  endfacet\n";
        }
        s += "endsolid test\n";
        s.into_bytes()
    }

    /// Binary STL; the header starts with `header` (e.g. `solid` to trick a sniffer).
    fn stl_binary(&self, header: &[u8]) -> Vec<u8> {
        let mut out = vec![b' '; 80];
        out[..header.len()].copy_from_slice(header);
        let t = self.triangles();
        out.extend((t.len() as u32).to_le_bytes());
        for t in t {
            out.extend([0u8; 12]);
            for v in t {
                for x in self.positions[v as usize] {
                    out.extend(x.to_le_bytes());
                }
            }
            out.extend([0u8; 2]);
        }
        out
    }
}

/// Corner coordinates of every triangle, in order.
fn corners(mesh: &Mesh) -> Vec<[[f64; 3]; 3]> {
    (0..mesh.len()).map(|i| mesh.triangle::<f64>(i).vertices()).collect()
}

/// Writes `bytes` to `name` in a fresh directory and loads it.
fn load_bytes(name: &str, bytes: &[u8]) -> (Result<Mesh, SceneError>, tempfile::TempDir) {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join(name);
    std::fs::write(&path, bytes).unwrap();
    (Mesh::load(&path), dir)
}

/// Loads `bytes` as `name`, expecting an error: checks it is one line naming the file and
/// returns the message.
fn error_of(name: &str, bytes: &[u8]) -> String {
    let (result, dir) = load_bytes(name, bytes);
    let msg = result.expect_err("should not load").to_string();
    let path = dir.path().join(name).display().to_string();
    assert!(msg.starts_with(&format!("{path}:")), "`{msg}` does not name {path}");
    assert!(!msg.contains('\n'), "not one line: {msg:?}");
    msg[path.len()..].to_owned()
}

fn gzip(bytes: &[u8]) -> Vec<u8> {
    let mut gz = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::default());
    gz.write_all(bytes).unwrap();
    gz.finish().unwrap()
}

#[test]
fn formats_come_from_the_extension_in_any_case() {
    let cases = [
        ("a.obj", MeshFormat::Obj, false),
        ("dir.x/B.OBJ", MeshFormat::Obj, false),
        ("scan.Ply", MeshFormat::Ply, false),
        ("part.STL", MeshFormat::Stl, false),
        ("scene.gltf", MeshFormat::Gltf, false),
        ("scene.GLB", MeshFormat::Glb, false),
        ("a.obj.gz", MeshFormat::Obj, true),
        ("bun.PLY.GZ", MeshFormat::Ply, true),
    ];
    for (name, format, gz) in cases {
        assert_eq!(MeshFormat::from_path(Path::new(name)).unwrap(), (format, gz), "{name}");
    }
    for name in ["a.off", "a.stl.gz", "obj", ".obj", "a.gz", "a.obj.zip", "a"] {
        let e = MeshFormat::from_path(Path::new(name)).unwrap_err().to_string();
        assert_eq!(
            e,
            format!(
                "{name}: unsupported mesh format (supported: .obj, .ply, .stl, .gltf, .glb, \
                 .obj.gz, .ply.gz)"
            )
        );
    }
    assert_eq!(MeshFormat::ALL.len(), 5);
    let names: Vec<&str> = MeshFormat::ALL.iter().map(|f| f.name()).collect();
    assert_eq!(names, ["OBJ", "PLY", "STL", "glTF", "GLB"]);
    // An existing file with another extension is refused by name too.
    let msg = error_of("mesh.off", b"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    assert!(msg.ends_with(
        "unsupported mesh format (supported: .obj, .ply, .stl, .gltf, .glb, .obj.gz, .ply.gz)"
    ));
}

#[test]
fn ply_ascii_and_binary_match_the_obj() {
    let s = shape();
    let obj = Mesh::from_obj_str(&s.obj(true), "s.obj").unwrap();
    let mut files = vec![("ascii", s.ply_ascii())];
    for index in ["uchar", "ushort", "int", "uint"] {
        files.push(("little", s.ply_binary(false, index)));
        files.push(("big", s.ply_binary(true, index)));
    }
    for (what, bytes) in files {
        let mesh = Mesh::from_bytes(&bytes, MeshFormat::Ply, "s.ply").unwrap();
        assert_eq!(corners(&mesh), corners(&obj), "{what}");
        assert_eq!(mesh.normals, obj.normals, "{what}");
        assert_eq!(mesh.triangles, s.triangles(), "{what}: file vertex order kept");
        let (loaded, _dir) = load_bytes("s.ply", &bytes);
        assert_eq!(loaded.unwrap().triangles, mesh.triangles);
    }
    // Without nx ny nz there are no normals.
    let text = "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\n\
                property double z\nelement face 1\nproperty list uchar uint vertex_index\n\
                end_header\n0 0 0\n1 0 0.1\n0 1 0\n3 0 1 2\n";
    let mesh = Mesh::from_bytes(text.as_bytes(), MeshFormat::Ply, "t.ply").unwrap();
    assert_eq!(mesh.normals, None);
    assert_eq!(mesh.triangle::<f64>(0).b, [1.0, 0.0, 0.1]);
}

#[test]
fn ply_refusals_name_the_file() {
    let s = shape();
    let good = s.ply_binary(false, "int");
    // Truncated anywhere in the payload.
    let header_len = s.ply_header("binary_little_endian", "int").len();
    for cut in [header_len, header_len + 5, header_len + 100, good.len() - 1] {
        let msg = error_of("t.ply", &good[..cut]);
        assert!(msg.contains("invalid PLY"), "cut at {cut}: {msg}");
    }
    // A count the file cannot hold is refused before reading (and allocating).
    let absurd = "ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\n\
                  property float x\nproperty float y\nproperty float z\nend_header\n\
                  \0\0\0\0";
    let msg = error_of("a.ply", absurd.as_bytes());
    assert!(msg.contains("announces 4000000000 `vertex` entries"), "{msg}");
    // Zero-size entries cannot make a count free.
    let empty = "ply\nformat binary_little_endian 1.0\nelement junk 4000000000\nend_header\n";
    assert!(error_of("e.ply", empty.as_bytes()).contains("4000000000 `junk` entries"));
    // Index out of range, negative index, face of two vertices, bad number, not PLY.
    let with = |faces: &str| {
        format!(
            "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n\
             property float z\nelement face 1\nproperty list uchar int vertex_indices\n\
             end_header\n0 0 0\n1 0 0\n0 1 0\n{faces}\n"
        )
    };
    let msg = error_of("r.ply", with("3 0 1 7").as_bytes());
    assert!(msg.contains("triangle 0 refers to vertex [0, 1, 7], but there are 3 vertices"));
    assert!(
        error_of("n.ply", with("3 0 -1 2").as_bytes()).contains("face 0 has the vertex index -1")
    );
    assert!(error_of("2.ply", with("2 0 1").as_bytes()).contains("face 0 has 2 vertices"));
    let msg = error_of("x.ply", with("3 0 1 x").as_bytes());
    assert!(msg.starts_with(":13: invalid PLY in element `face`: "), "{msg}");
    assert!(error_of("o.ply", b"solid x\n").contains("invalid PLY"));
    let nan = with("3 0 1 2").replace("1 0 0\n", "nan 0 0\n");
    assert!(
        error_of("nan.ply", nan.as_bytes()).starts_with(":11: invalid PLY in element `vertex`")
    );
    let mut nan = shape();
    nan.positions[1][0] = f32::NAN;
    let msg = error_of("nan.ply", &nan.ply_binary(false, "int"));
    assert_eq!(msg, ": vertex 1 has a coordinate that is not finite: [NaN, 0.0, 0.0]");
    let none = with("3 0 1 2").replace("element face 1", "element face 0");
    let none = none.replace("3 0 1 2\n", "");
    assert_eq!(error_of("none.ply", none.as_bytes()), ": the mesh has no faces");
}

#[test]
fn stl_ascii_and_binary_match_the_obj() {
    let s = shape();
    let obj = Mesh::from_obj_str(&s.obj(false), "s.obj").unwrap();
    for (what, bytes) in [
        ("ascii", s.stl_ascii()),
        ("binary", s.stl_binary(b"binary header")),
        // A binary file whose header starts like ASCII STL is still binary: its size says so.
        ("binary solid", s.stl_binary(b"solid looks like text")),
    ] {
        let mesh = Mesh::from_bytes(&bytes, MeshFormat::Stl, "s.stl").unwrap();
        assert_eq!(corners(&mesh), corners(&obj), "{what}");
        assert_eq!(mesh.normals, None);
        assert_eq!(mesh.positions.len(), 3 * mesh.len(), "{what}: STL shares no vertex");
    }
    // ASCII keeps decimals in f64; keywords in any case; several solids.
    let text = "solid a\nFACET NORMAL 0 0 1\nouter loop\nvertex 0.1 0 0\nvertex 1 0 0\n\
                vertex 0 1 0\nendloop\nendfacet\nendsolid a\nsolid b\nendsolid b\n";
    let mesh = Mesh::from_bytes(text.as_bytes(), MeshFormat::Stl, "d.stl").unwrap();
    assert_eq!(mesh.triangle::<f64>(0).a, [0.1, 0.0, 0.0]);
}

#[test]
fn stl_refusals_name_the_file() {
    let s = shape();
    let good = s.stl_binary(b"bin");
    // Truncated: the count announces more facets than the bytes hold.
    let msg = error_of("t.stl", &good[..good.len() - 1]);
    assert!(msg.contains("the header announces 6 facets (384 bytes), the file has 383"), "{msg}");
    // An absurd count in a short file, at once.
    let mut absurd = vec![0u8; 84];
    absurd[80..].copy_from_slice(&u32::MAX.to_le_bytes());
    assert!(error_of("a.stl", &absurd).contains("announces 4294967295 facets"));
    assert!(error_of("s.stl", b"abc").contains("too short for binary STL"));
    let text = String::from_utf8(s.stl_ascii()).unwrap();
    let msg = error_of("x.stl", text.replacen("vertex 1 0 0", "vertex 1 x 0", 1).as_bytes());
    assert_eq!(msg, ":5: `x` is not a number");
    let cut: String = text.split_inclusive('\n').take(6).collect();
    let msg = error_of("c.stl", cut.as_bytes());
    assert!(msg.contains("the file ends inside a facet"), "{msg}");
    let msg = error_of("k.stl", text.replacen("outer loop", "outer space", 1).as_bytes());
    assert_eq!(msg, ":3: expected `outer loop`");
    assert_eq!(error_of("e.stl", b"solid empty\nendsolid empty\n"), ": the mesh has no faces");
}

#[test]
fn gzip_obj_and_ply_load_like_the_plain_files() {
    let s = shape();
    let obj = Mesh::from_obj_str(&s.obj(true), "s.obj").unwrap();
    let (plain, _d) = load_bytes("s.obj.gz", &gzip(s.obj(true).as_bytes()));
    assert_eq!(corners(&plain.unwrap()), corners(&obj));
    let (ply, _d) = load_bytes("s.ply.gz", &gzip(&s.ply_binary(true, "int")));
    let ply = ply.unwrap();
    assert_eq!(corners(&ply), corners(&obj));
    assert_eq!(ply.normals, obj.normals);
    // Concatenated members read as one stream, as gzip -d does.
    let text = s.obj(false);
    let (a, b) = text.split_at(text.len() / 2);
    let mut two = gzip(a.as_bytes());
    two.extend(gzip(b.as_bytes()));
    let (joined, _d) = load_bytes("two.OBJ.GZ", &two);
    assert_eq!(corners(&joined.unwrap()), corners(&obj));
}

#[test]
fn gzip_refusals_corrupt_truncated_and_bombs() {
    let s = shape();
    let gz = gzip(s.obj(false).as_bytes());
    assert!(error_of("t.obj.gz", &gz[..gz.len() / 2]).contains("corrupt gzip data"));
    assert!(error_of("p.obj.gz", s.obj(false).as_bytes()).contains("not gzip data"));
    // A NUL byte in the decompressed text is refused like in a plain OBJ.
    let msg = error_of("z.obj.gz", &gzip(b"v 0 0 0\nv 1 0 0\n\0\0"));
    assert_eq!(msg, ": not a text file (NUL byte at line 3)");
    // A bomb: 1 GB of spaces from about 1 MB, refused at a small limit without decompressing
    // it all (the bound, not the memory available, stops it).
    let mut enc = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::best());
    let block = vec![b' '; 1 << 20];
    for _ in 0..1024 {
        enc.write_all(&block).unwrap();
    }
    let bomb = enc.finish().unwrap();
    assert!(bomb.len() < 2 << 20, "{}", bomb.len());
    let start = std::time::Instant::now();
    let e = scene::gz::gunzip(&bomb, 64 << 20, "bomb.obj.gz").unwrap_err();
    assert!(matches!(e, SceneError::OutOfMemory { .. }), "{e}");
    let msg = e.to_string();
    assert!(msg.starts_with("bomb.obj.gz: too large for memory: needs about 1.1 GB"), "{msg}");
    // Generous bound for a loaded machine; decompressing 64 MB takes well under a second.
    assert!(start.elapsed().as_secs() < 30);
}

/// A glTF document writer for tests: buffers, views, accessors, meshes, nodes and scenes
/// as JSON text, with the binary data in one buffer.
#[derive(Default)]
struct Gltf {
    bin: Vec<u8>,
    views: Vec<String>,
    accessors: Vec<String>,
    meshes: Vec<String>,
    nodes: Vec<String>,
}

impl Gltf {
    /// Adds `data` as a buffer view and an accessor; returns the accessor's index.
    fn accessor(&mut self, data: &[u8], count: usize, ty: &str, component: u32) -> usize {
        while !self.bin.len().is_multiple_of(4) {
            self.bin.push(0);
        }
        let offset = self.bin.len();
        self.bin.extend(data);
        self.views
            .push(format!(r#"{{"buffer":0,"byteOffset":{offset},"byteLength":{}}}"#, data.len()));
        self.accessors.push(format!(
            r#"{{"bufferView":{},"componentType":{component},"count":{count},"type":"{ty}"}}"#,
            self.views.len() - 1
        ));
        self.accessors.len() - 1
    }

    fn vec3(&mut self, v: &[[f32; 3]]) -> usize {
        let bytes: Vec<u8> = v.iter().flatten().flat_map(|x| x.to_le_bytes()).collect();
        self.accessor(&bytes, v.len(), "VEC3", 5126)
    }

    fn indices_u16(&mut self, i: &[u32]) -> usize {
        let bytes: Vec<u8> = i.iter().flat_map(|&x| (x as u16).to_le_bytes()).collect();
        self.accessor(&bytes, i.len(), "SCALAR", 5123)
    }

    /// Adds a mesh of primitives, each `(attributes JSON, indices accessor, mode)`.
    fn mesh(&mut self, primitives: &[(String, Option<usize>, u32)]) -> usize {
        let p: Vec<String> = primitives
            .iter()
            .map(|(attributes, indices, mode)| {
                let indices = indices.map(|i| format!(r#","indices":{i}"#)).unwrap_or_default();
                format!(r#"{{"attributes":{attributes}{indices},"mode":{mode}}}"#)
            })
            .collect();
        self.meshes.push(format!(r#"{{"primitives":[{}]}}"#, p.join(",")));
        self.meshes.len() - 1
    }

    fn node(&mut self, json: &str) -> usize {
        self.nodes.push(json.to_owned());
        self.nodes.len() - 1
    }

    fn json(&self, uri: Option<&str>, scenes: &str) -> String {
        let uri = uri.map(|u| format!(r#","uri":"{u}""#)).unwrap_or_default();
        format!(
            r#"{{"asset":{{"version":"2.0"}},{scenes}"nodes":[{}],"meshes":[{}],
            "accessors":[{}],"bufferViews":[{}],"buffers":[{{"byteLength":{}{uri}}}]}}"#,
            self.nodes.join(","),
            self.meshes.join(","),
            self.accessors.join(","),
            self.views.join(","),
            self.bin.len()
        )
    }

    fn glb(&self, scenes: &str) -> Vec<u8> {
        let mut json = self.json(None, scenes).into_bytes();
        while !json.len().is_multiple_of(4) {
            json.push(b' ');
        }
        let mut bin = self.bin.clone();
        while !bin.len().is_multiple_of(4) {
            bin.push(0);
        }
        let total = 12 + 8 + json.len() + 8 + bin.len();
        let mut out = b"glTF".to_vec();
        out.extend(2u32.to_le_bytes());
        out.extend((total as u32).to_le_bytes());
        out.extend((json.len() as u32).to_le_bytes());
        out.extend(b"JSON");
        out.extend(json);
        out.extend((bin.len() as u32).to_le_bytes());
        out.extend(b"BIN\0");
        out.extend(bin);
        out
    }
}

/// A node's transform of a point, for the expected results.
type Transform = dyn Fn([f32; 3]) -> [f64; 3];

/// An OBJ of the expected glTF result, written from the transformed points.
fn obj_of(points: &[[f64; 3]], triangles: &[[usize; 3]]) -> Mesh {
    let mut s = String::new();
    for p in points {
        s += &format!("v {:?} {:?} {:?}\n", p[0], p[1], p[2]);
    }
    for t in triangles {
        s += &format!("f {} {} {}\n", t[0] + 1, t[1] + 1, t[2] + 1);
    }
    Mesh::from_obj_str(&s, "expected.obj").unwrap()
}

/// The test scene: a root node translated by (10, 0, 0) with a child scaled by 2 and
/// rotated 180 degrees about z, a mirrored sibling (scale -1 in x, by a matrix); the meshes: a
/// quad as TRIANGLES (u16 indices) plus a strip primitive and a fan primitive without
/// indices, and a points primitive that must be ignored.
fn scene() -> (Gltf, String, Mesh) {
    let mut g = Gltf::default();
    let quad = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]];
    let normals = [[0.0, 0.0, 1.0]; 4];
    let p = g.vec3(&quad);
    let n = g.vec3(&normals);
    let i = g.indices_u16(&[0, 1, 2, 0, 2, 3]);
    // Counter-clockwise seen from +z, every triangle of it (the odd one by the strip rule).
    let strip_pts =
        [[0.0, 0.0, 1.0], [1.0, 0.0, 1.0], [0.0, 1.0, 1.0], [1.0, 1.0, 1.0], [0.0, 2.0, 1.0]];
    let sp = g.vec3(&strip_pts);
    let sn = g.vec3(&[[0.0, 0.0, 1.0]; 5]);
    let fan_pts = [[0.0, 0.0, 2.0], [1.0, 0.0, 2.0], [1.0, 1.0, 2.0], [0.0, 1.0, 2.0]];
    let fp = g.vec3(&fan_pts);
    let fnn = g.vec3(&[[0.0, 0.0, 1.0]; 4]);
    let attrs = |p: usize, n: usize| format!(r#"{{"POSITION":{p},"NORMAL":{n}}}"#);
    let mesh = g.mesh(&[
        (attrs(p, n), Some(i), 4),
        (attrs(sp, sn), None, 5),
        (format!(r#"{{"POSITION":{p}}}"#), None, 0),
        (attrs(fp, fnn), None, 6),
    ]);
    // Node order in the file differs from the traversal order on purpose.
    let child = g.node(&format!(r#"{{"mesh":{mesh},"scale":[2,2,2],"rotation":[0,0,1,0]}}"#));
    let mirror =
        g.node(&format!(r#"{{"mesh":{mesh},"matrix":[-1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,-5,1]}}"#));
    let root = g.node(&format!(
        r#"{{"mesh":{mesh},"translation":[10,0,0],"children":[{child},{mirror}]}}"#
    ));
    let scenes = format!(r#""scene":1,"scenes":[{{"nodes":[]}},{{"nodes":[{root}]}}],"#);

    // Expected, built independently: per node, all points transformed, then the triangles.
    let mut points = Vec::new();
    let mut tris = Vec::new();
    let local = [[0, 1, 2], [0, 2, 3]];
    let strip = [[0, 1, 2], [1, 3, 2], [2, 3, 4]];
    let fan = [[0, 1, 2], [0, 2, 3]];
    let transforms: [(&Transform, bool); 3] = [
        (&|q: [f32; 3]| [q[0] as f64 + 10.0, q[1] as f64, q[2] as f64], false),
        // Child: translate(10) * rotate180z * scale2: (x, y) -> (-2x, -2y), then + 10.
        (&|q: [f32; 3]| [10.0 - 2.0 * q[0] as f64, -2.0 * q[1] as f64, 2.0 * q[2] as f64], false),
        // Mirror: translate(10) * (x -> -x, z -> z - 5).
        (&|q: [f32; 3]| [10.0 - q[0] as f64, q[1] as f64, q[2] as f64 - 5.0], true),
    ];
    for (f, mirrored) in transforms {
        for (pts, order) in
            [(&quad[..], &local[..]), (&strip_pts[..], &strip[..]), (&fan_pts[..], &fan[..])]
        {
            let base = points.len();
            points.extend(pts.iter().map(|&q| f(q)));
            for t in order {
                let t = t.map(|k| base + k);
                tris.push(if mirrored { [t[0], t[2], t[1]] } else { t });
            }
        }
    }
    (g, scenes, obj_of(&points, &tris))
}

#[test]
fn glb_and_gltf_with_a_node_hierarchy_match_the_obj() {
    let (g, scenes, expected) = scene();
    let glb = g.glb(&scenes);
    let mesh = Mesh::from_bytes(&glb, MeshFormat::Glb, "s.glb").unwrap();
    assert_eq!(corners(&mesh), corners(&expected));
    // Normals: +z, turned by the rotation (still +z), scaled (renormalised), and mirrored in
    // x (still +z, with the winding swapped the normal keeps pointing to the front).
    let normals = mesh.normals.as_ref().expect("every triangle primitive has normals");
    assert_eq!(normals.len(), mesh.len());
    for n in normals.iter().flatten() {
        assert!((n[2] - 1.0).abs() < 1e-6 && n[0].abs() < 1e-6 && n[1].abs() < 1e-6, "{n:?}");
    }
    // Each triangle faces its normal (counter-clockwise seen from the front).
    for (i, n) in normals.iter().enumerate() {
        let t = mesh.triangle::<f64>(i);
        let (u, v) = ((0..3).map(|k| t.b[k] - t.a[k]), (0..3).map(|k| t.c[k] - t.a[k]));
        let (u, v): (Vec<f64>, Vec<f64>) = (u.collect(), v.collect());
        let cross_z = u[0] * v[1] - u[1] * v[0];
        assert!(cross_z * n[0][2] as f64 > 0.0, "triangle {i} faces away from its normal");
    }

    // The same scene as .gltf with the buffer in a data: URI and in an external file.
    use base64::Engine as _;
    let data = base64::engine::general_purpose::STANDARD.encode(&g.bin);
    let uri = format!("data:application/octet-stream;base64,{data}");
    let embedded = g.json(Some(&uri), &scenes);
    let mesh = Mesh::from_bytes(embedded.as_bytes(), MeshFormat::Gltf, "e.gltf").unwrap();
    assert_eq!(corners(&mesh), corners(&expected));

    let dir = tempfile::tempdir().unwrap();
    std::fs::create_dir(dir.path().join("sub dir")).unwrap();
    std::fs::write(dir.path().join("sub dir/the data.bin"), &g.bin).unwrap();
    let path = dir.path().join("x.gltf");
    std::fs::write(&path, g.json(Some("sub%20dir/the%20data.bin"), &scenes)).unwrap();
    let mesh = Mesh::load(&path).unwrap();
    assert_eq!(corners(&mesh), corners(&expected));
    // from_bytes does not read files.
    let json = std::fs::read(&path).unwrap();
    let msg = Mesh::from_bytes(&json, MeshFormat::Gltf, "x.gltf").unwrap_err().to_string();
    assert!(msg.starts_with("x.gltf: invalid glTF: buffer 0: refers to the external file"));
    // A missing external file is named.
    std::fs::remove_file(dir.path().join("sub dir/the data.bin")).unwrap();
    let msg = Mesh::load(&path).unwrap_err().to_string();
    assert!(msg.ends_with("the data.bin: file not found"), "{msg}");
}

#[test]
fn gltf_without_a_default_scene_takes_every_scene_then_root_nodes() {
    let mut g = Gltf::default();
    let p = g.vec3(&[[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]);
    let mesh = g.mesh(&[(format!(r#"{{"POSITION":{p}}}"#), None, 4)]);
    let a = g.node(&format!(r#"{{"mesh":{mesh},"translation":[0,0,1]}}"#));
    let b = g.node(&format!(r#"{{"mesh":{mesh},"translation":[0,0,2]}}"#));
    let z = |m: &Mesh| (0..m.len()).map(|i| m.triangle::<f64>(i).a[2]).collect::<Vec<_>>();
    let two = format!(r#""scenes":[{{"nodes":[{b}]}},{{"nodes":[{a}]}}],"#);
    let m = Mesh::from_bytes(&g.glb(&two), MeshFormat::Glb, "s.glb").unwrap();
    assert_eq!(z(&m), [2.0, 1.0]);
    assert_eq!(m.normals, None);
    let m = Mesh::from_bytes(&g.glb(""), MeshFormat::Glb, "n.glb").unwrap();
    assert_eq!(z(&m), [1.0, 2.0]);
    // Application-specific attributes (`_NAME`, allowed by the specification) are ignored.
    let mut g = Gltf::default();
    let p = g.vec3(&[[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]);
    let mesh = g.mesh(&[(format!(r#"{{"POSITION":{p},"_BATCHID":{p}}}"#), None, 4)]);
    g.node(&format!(r#"{{"mesh":{mesh}}}"#));
    let m = Mesh::from_bytes(&g.glb(""), MeshFormat::Glb, "x.glb").unwrap();
    assert_eq!(m.len(), 1);
}

#[test]
fn gltf_refusals_name_the_file() {
    let (g, scenes, _) = scene();
    let glb = g.glb(&scenes);
    // Truncated anywhere.
    for cut in [0, 3, 11, 12, 19, 40, glb.len() / 2, glb.len() - 1] {
        let msg = Mesh::from_bytes(&glb[..cut], MeshFormat::Glb, "t.glb").unwrap_err().to_string();
        assert!(msg.starts_with("t.glb: invalid GLB: "), "cut {cut}: {msg}");
    }
    // A header length below the header's own size (a subtraction that underflows in the
    // gltf crate) is refused here.
    let mut short = glb.clone();
    short[8..12].copy_from_slice(&4u32.to_le_bytes());
    assert!(Mesh::from_bytes(&short, MeshFormat::Glb, "h.glb").is_err());
    // An accessor count beyond its view, before anything is read.
    let json = g.json(Some("data:application/octet-stream;base64,AAAA"), &scenes);
    let huge = json.replacen(r#""count":4"#, r#""count":4000000000"#, 1);
    let msg = Mesh::from_bytes(huge.as_bytes(), MeshFormat::Gltf, "c.gltf").unwrap_err();
    let msg = msg.to_string();
    assert!(msg.starts_with("c.gltf: invalid glTF: "), "{msg}");
    assert!(!msg.contains('\n'));
    // 64-bit counts and offsets at their largest: no overflow, an error.
    for (field, value) in [("count", "4"), ("byteOffset", "0"), ("byteLength", "48")] {
        let from = format!(r#""{field}":{value}"#);
        assert!(json.contains(&from), "{field}");
        let huge = json.replacen(&from, &format!(r#""{field}":18446744073709551615"#), 1);
        let e = Mesh::from_bytes(huge.as_bytes(), MeshFormat::Gltf, "u.gltf").unwrap_err();
        assert!(e.to_string().starts_with("u.gltf: invalid glTF: "), "{field}: {e}");
    }
    // Not JSON, not valid glTF, a cycle in the hierarchy.
    for (bytes, what) in [
        (&b"{"[..], "EOF"),
        (br#"{"asset":{"version":"2.0"},"nodes":[{"mesh":3}]}"#, "mesh"),
        (
            br#"{"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],
               "nodes":[{"children":[1]},{"children":[0]}]}"#,
            "reached twice",
        ),
    ] {
        let msg = Mesh::from_bytes(bytes, MeshFormat::Gltf, "b.gltf").unwrap_err().to_string();
        assert!(msg.starts_with("b.gltf: invalid glTF: ") && msg.contains(what), "{msg}");
        assert!(!msg.contains('\n'));
    }
    // Instancing beyond the output bound: one node chain of 3000 instances of a mesh.
    let mut big = Gltf::default();
    let pts = vec![[0.0f32, 0.0, 0.0]; 3000];
    let p = big.vec3(&pts);
    let mesh = big.mesh(&[(format!(r#"{{"POSITION":{p}}}"#), None, 4)]);
    for _ in 0..3000 {
        big.node(&format!(r#"{{"mesh":{mesh}}}"#));
    }
    let msg = Mesh::from_bytes(&big.glb(""), MeshFormat::Glb, "i.glb").unwrap_err().to_string();
    assert!(msg.contains("too much instancing"), "{msg}");
    // No triangle primitive at all.
    let mut pts_only = Gltf::default();
    let p = pts_only.vec3(&[[0.0, 0.0, 0.0]]);
    let mesh = pts_only.mesh(&[(format!(r#"{{"POSITION":{p}}}"#), None, 0)]);
    pts_only.node(&format!(r#"{{"mesh":{mesh}}}"#));
    let msg = Mesh::from_bytes(&pts_only.glb(""), MeshFormat::Glb, "p.glb").unwrap_err();
    assert_eq!(msg.to_string(), "p.glb: the mesh has no faces");
}

/// Random damage to valid files of every format (flipped, inserted and deleted bytes,
/// truncation, absurd 32-bit words) must give a result or an error, never a panic; and
/// every error is one line naming the source.
#[test]
fn damaged_files_never_panic() {
    use rand::{Rng as _, SeedableRng as _};
    let s = shape();
    let (g, scenes, _) = scene();
    let inputs = [
        (MeshFormat::Obj, s.obj(true).into_bytes()),
        (MeshFormat::Ply, s.ply_ascii()),
        (MeshFormat::Ply, s.ply_binary(false, "uchar")),
        (MeshFormat::Ply, s.ply_binary(true, "int")),
        (MeshFormat::Stl, s.stl_ascii()),
        (MeshFormat::Stl, s.stl_binary(b"solid")),
        (MeshFormat::Glb, g.glb(&scenes)),
        (
            MeshFormat::Gltf,
            g.json(Some("data:application/octet-stream;base64,AAAA"), &scenes).into_bytes(),
        ),
    ];
    let mut rng = rand_pcg::Pcg64::seed_from_u64(13);
    for (format, good) in inputs {
        for _ in 0..400 {
            let mut bytes = good.clone();
            for _ in 0..rng.random_range(1..4) {
                if bytes.is_empty() {
                    break;
                }
                let at = rng.random_range(0..bytes.len());
                match rng.random_range(0..5) {
                    0 => bytes[at] ^= 1 << rng.random_range(0..8),
                    1 => bytes.insert(at, rng.random()),
                    2 => {
                        bytes.remove(at);
                    }
                    3 => bytes.truncate(at.max(1)),
                    _ => {
                        let word: u32 = if rng.random() { u32::MAX } else { rng.random() };
                        let end = (at + 4).min(bytes.len());
                        let len = end - at;
                        bytes[at..end].copy_from_slice(&word.to_le_bytes()[..len]);
                    }
                }
            }
            if let Err(e) = Mesh::from_bytes(&bytes, format, "d.mesh") {
                let msg = e.to_string();
                assert!(msg.starts_with("d.mesh:") && !msg.contains('\n'), "{format:?}: {msg}");
            }
        }
    }
}
