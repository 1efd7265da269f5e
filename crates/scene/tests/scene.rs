//! OBJ loading: triangle order, normals, every error kind, and the real meshes against an
//! independent minimal parser.

use std::path::{Path, PathBuf};

use scene::input::InputError;
use scene::{Mesh, SceneError};

/// Writes `text` to `name` in a fresh temporary directory and loads it.
fn load_text(name: &str, text: &str) -> (Result<Mesh, SceneError>, tempfile::TempDir) {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join(name);
    std::fs::write(&path, text).unwrap();
    (Mesh::load(&path), dir)
}

/// The error message for `text`, checked to be one line starting with `<path>:<line>: `.
fn error_at(text: &str, line: usize) -> String {
    let (result, dir) = load_text("scene.obj", text);
    let err = result.expect_err("the text should not load");
    let msg = err.to_string();
    let path = dir.path().join("scene.obj");
    let prefix = format!("{}:{line}: ", path.display());
    assert!(msg.starts_with(&prefix), "expected `{prefix}...`, got `{msg}`");
    assert!(!msg.contains('\n'), "not one line: {msg:?}");
    msg[prefix.len()..].to_owned()
}

const SQUARE: &str = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";

#[test]
fn polygons_become_fans_from_the_first_vertex_in_file_order() {
    let text = format!("{SQUARE}v 0.5 2 0\nf 1 2 3\nf 1 2 3 4\nf 1 2 3 5 4\nf 4 3 2\n");
    let mesh = Mesh::from_obj_str(&text, "fan.obj").unwrap();
    let corners: Vec<[[f64; 3]; 3]> =
        mesh.triangles.iter().map(|t| t.map(|v| mesh.positions[v as usize])).collect();
    let p = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0], [0.5, 2.0, 0.0]];
    let expected = vec![
        [p[0], p[1], p[2]],
        // quad 1 2 3 4
        [p[0], p[1], p[2]],
        [p[0], p[2], p[3]],
        // pentagon 1 2 3 5 4
        [p[0], p[1], p[2]],
        [p[0], p[2], p[4]],
        [p[0], p[4], p[3]],
        [p[3], p[2], p[1]],
    ];
    assert_eq!(corners, expected);
    assert_eq!(mesh.len(), 7);
    assert_eq!(mesh.normals, None);
    assert_eq!(mesh.name, "fan.obj");
}

#[test]
fn objects_groups_and_materials_merge_in_file_order() {
    // Vertex z encodes the face number, so the order can be read back from the triangles.
    let mut text = String::new();
    for k in 0..6 {
        text += &format!("v 0 0 {k}\nv 1 0 {k}\nv 0 1 {k}\n");
    }
    text += "o first\nf 1 2 3\nusemtl red\nf 4 5 6\ng second\nf 7 8 9\nusemtl blue\n";
    text += "f 10 11 12\no third\nf 13 14 15\nusemtl red\nf 16 17 18\no empty\n";
    let mesh = Mesh::from_obj_str(&text, "order.obj").unwrap();
    let z: Vec<f64> = (0..mesh.len()).map(|i| mesh.triangle::<f64>(i).a[2]).collect();
    assert_eq!(z, [0.0, 1.0, 2.0, 3.0, 4.0, 5.0]);
}

#[test]
fn relative_indices_crlf_polylines_materials_colours_and_weights() {
    let text = "# comment\r\nmtllib absent.mtl\r\nv 0 0 0 1 0 0\r\nv 4 0 0 2\r\nv 0 2 0\r\n\
                l 1 2 3\r\ns off\r\nusemtl absent\r\nvt 0 0\r\nf -3 -2 -1\r\nl 1 2\r\n";
    let mesh = Mesh::from_obj_str(text, "rel.obj").unwrap();
    assert_eq!(mesh.len(), 1);
    let t = mesh.triangle::<f32>(0);
    assert_eq!((t.a, t.b, t.c), ([0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [0.0, 2.0, 0.0]));
}

#[test]
fn normals_are_kept_per_corner_only_when_every_face_has_them() {
    let text =
        format!("{SQUARE}vn 0 0 1\nvn 0 1 0\nvn 1 0 0\nf 1//1 2//2 3//3 4//1\nf 1//3 3//3 4//2\n");
    let mesh = Mesh::from_obj_str(&text, "n.obj").unwrap();
    let (x, y, z) = ([1.0f32, 0.0, 0.0], [0.0f32, 1.0, 0.0], [0.0f32, 0.0, 1.0]);
    assert_eq!(mesh.normals, Some(vec![[z, y, x], [z, x, z], [x, x, y]]));

    let partial = format!("{SQUARE}vn 0 0 1\nf 1//1 2//1 3//1\nf 1 3 4\n");
    assert_eq!(Mesh::from_obj_str(&partial, "p.obj").unwrap().normals, None);
}

#[test]
fn degenerate_faces_are_kept_in_place() {
    let text = format!("{SQUARE}f 1 2 3\nf 1 1 1\nf 1 2 2\nf 1 3 4\n");
    let mesh = Mesh::from_obj_str(&text, "d.obj").unwrap();
    assert_eq!(mesh.len(), 4);
    assert_eq!(mesh.triangle::<f64>(3).c, [0.0, 1.0, 0.0]);
}

#[test]
fn positions_keep_double_precision() {
    let text = "v 0.1 0.2 0.30000000000000004\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    let mesh = Mesh::from_obj_str(text, "p.obj").unwrap();
    assert_eq!(mesh.triangle::<f64>(0).a, [0.1, 0.2, 0.30000000000000004]);
    assert_eq!(mesh.triangle::<f32>(0).a, [0.1f32, 0.2, 0.3]);
}

#[test]
fn bounds_and_bounding_sphere() {
    let text = "v -1 0 0\nv 3 0 0\nv 1 4 -2\nv 100 100 100\nf 1 2 3\n";
    let mesh = Mesh::from_obj_str(text, "b.obj").unwrap();
    let b = mesh.bounds();
    // The unused vertex 4 does not count.
    assert_eq!((b.min, b.max), ([-1.0, 0.0, -2.0], [3.0, 4.0, 0.0]));
    let (c, r) = mesh.bounding_sphere();
    assert_eq!(c, [1.0, 2.0, -1.0]);
    // Farthest corner from the centre: (3,0,0) or (-1,0,0): sqrt(4 + 4 + 1) = 3; (1,4,-2): sqrt(5).
    assert_eq!(r, 3.0);
}

#[test]
fn missing_and_unreadable_files() {
    let dir = tempfile::tempdir().unwrap();
    let missing = dir.path().join("nope.obj");
    let err = Mesh::load(&missing).unwrap_err();
    assert!(matches!(err, SceneError::Input(InputError::NotFound { .. })));
    assert_eq!(err.to_string(), format!("{}: file not found", missing.display()));

    // A directory cannot be read as a file.
    let err = Mesh::load(dir.path()).unwrap_err();
    assert!(matches!(err, SceneError::Input(InputError::NotAFile { .. })), "{err:?}");
    let msg = err.to_string();
    assert_eq!(msg, format!("{}: is a directory, not a file", dir.path().display()));
    assert!(!msg.contains('\n'));
}

#[test]
fn bad_numbers() {
    assert_eq!(error_at("v 0 0 0\nv 1 x 0\nv 0 1 0\nf 1 2 3\n", 2), "`x` is not a number");
    assert_eq!(error_at("v 0 0 0\nv 1 0\nf 1 2 2\n", 2), "a vertex needs 3 numbers, found 2");
    assert_eq!(
        error_at(&format!("{SQUARE}vn 0 0\nf 1 2 3\n"), 5),
        "a normal needs 3 numbers, found 2"
    );
    assert_eq!(
        error_at(&format!("{SQUARE}f 1 2 a\n"), 5),
        "`a` in face vertex `a` is not an index"
    );
    assert_eq!(
        error_at(&format!("{SQUARE}f 1 2 3.5\n"), 5),
        "`3.5` in face vertex `3.5` is not an index"
    );
    assert_eq!(
        error_at(&format!("{SQUARE}f 1 2 3/1/1/1\n"), 5),
        "face vertex `3/1/1/1` has more than 3 indices (v/vt/vn)"
    );
    assert_eq!(error_at("v 0 0 0 0\nf 1 1 1\n", 1), "vertex weight w is 0");
}

#[test]
fn indices_out_of_range_or_zero() {
    let text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 2 0 0\nv 2 1 0\nv 3 0 0\nv 3 1 0\n\
                f 1 2 3\nf 2 4 3\n# fine so far\n\n\n\n\nf 5 6 7\nf 7 8 9\n";
    assert_eq!(error_at(text, 17), "face index 9 is out of range (the file has 8 vertices)");
    assert_eq!(
        error_at(&format!("{SQUARE}f 0 1 2\n"), 5),
        "face index 0 is invalid (OBJ indices start at 1)"
    );
    assert_eq!(
        error_at(&format!("{SQUARE}f -1 -2 -5\n"), 5),
        "relative face index -5 is out of range (4 vertices before this line)"
    );
    assert_eq!(
        error_at(&format!("{SQUARE}vn 0 0 1\nf 1//1 2//1 3//2\n"), 6),
        "normal index 2 is out of range (the file has 1 normals)"
    );
}

#[test]
fn faces_with_fewer_than_three_vertices() {
    assert_eq!(
        error_at(&format!("{SQUARE}f 1 2 3\nf 1 2\n"), 6),
        "a face needs at least 3 vertices, found 2"
    );
    assert_eq!(
        error_at(&format!("{SQUARE}f 4\nf 1 2 3\n"), 5),
        "a face needs at least 3 vertices, found 1"
    );
}

#[test]
fn non_finite_coordinates() {
    assert_eq!(
        error_at("v 0 0 0\nv 1 0 0\nv 0 NaN 0\nf 1 2 3\n", 3),
        "vertex coordinate NaN is not finite"
    );
    assert_eq!(
        error_at("v 0 0 0\nv 1e400 0 0\nv 0 1 0\nf 1 2 3\n", 2),
        "vertex coordinate 1e400 is not finite"
    );
    assert_eq!(
        error_at("v 0 0 0\nv 1 0 0\nv 0 1 -inf\nf 1 2 3\n", 3),
        "vertex coordinate -inf is not finite"
    );
    assert_eq!(
        error_at("v 0 0 0\nv 1e300 0 0 1e-300\nv 0 1 0\nf 1 2 3\n", 2),
        "vertex coordinate 1e300 / 1e-300 is not finite"
    );
    assert_eq!(
        error_at(&format!("{SQUARE}vn 0 inf 1\nf 1//1 2//1 3//1\n"), 5),
        "normal component inf is not finite"
    );
}

#[test]
fn a_file_without_faces() {
    for text in ["", "# nothing\n", "v 0 0 0\nv 1 0 0\nv 0 1 0\n", "v 0 0 0\nl 1 1\n"] {
        let (result, dir) = load_text("empty.obj", text);
        let err = result.unwrap_err();
        assert!(matches!(err, SceneError::NoFaces { .. }), "{text:?}: {err:?}");
        let path = dir.path().join("empty.obj");
        assert_eq!(err.to_string(), format!("{}: the mesh has no faces", path.display()));
    }
}

/// The shared test meshes, beside the repository (see `/work/shared/meshes/README.md`).
fn shared_mesh(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../shared/meshes");
    assert!(
        dir.is_dir(),
        "the shared test meshes are missing: expected the folder {} (shared/meshes beside the \
         repository); these tests need it",
        dir.display()
    );
    dir.join(name)
}

/// An independent reading of a simple OBJ (v and f lines with positive `v[/vt][/vn]`
/// indices): each face as a fan, as a list of corner coordinates.
fn naive_triangles(text: &str) -> Vec<[[f64; 3]; 3]> {
    let mut v = Vec::new();
    let mut tris = Vec::new();
    for line in text.lines() {
        let w: Vec<&str> = line.split_whitespace().collect();
        match w.first() {
            Some(&"v") => v.push([w[1], w[2], w[3]].map(|x| x.parse::<f64>().unwrap())),
            Some(&"f") => {
                let idx: Vec<usize> = w[1..]
                    .iter()
                    .map(|c| c.split('/').next().unwrap().parse::<usize>().unwrap() - 1)
                    .collect();
                for k in 1..idx.len() - 1 {
                    tris.push([v[idx[0]], v[idx[k]], v[idx[k + 1]]]);
                }
            }
            _ => {}
        }
    }
    tris
}

#[test]
fn real_meshes_match_an_independent_reading() {
    for (name, triangles, normals) in [
        ("stanford-bunny.obj", 69_451, false),
        ("teapot.obj", 6_320, false),
        // 468 quads and 32 triangles.
        ("suzanne.obj", 468 * 2 + 32, true),
        ("spot.obj", 5_856, false),
        ("cow.obj", 5_804, false),
    ] {
        let path = shared_mesh(name);
        let mesh = Mesh::load(&path).unwrap();
        assert_eq!(mesh.len(), triangles, "{name}");
        assert_eq!(mesh.normals.is_some(), normals, "{name}");
        if let Some(n) = &mesh.normals {
            assert_eq!(n.len(), mesh.len());
        }
        let expected = naive_triangles(&std::fs::read_to_string(&path).unwrap());
        assert_eq!(expected.len(), triangles);
        for (i, e) in expected.iter().enumerate() {
            assert_eq!(mesh.triangle::<f64>(i).vertices(), *e, "{name} triangle {i}");
        }
    }
}

#[test]
fn a_byte_order_mark_is_skipped() {
    let text = format!("\u{feff}{SQUARE}f 1 2 3 4\n");
    let (mesh, _dir) = load_text("bom.obj", &text);
    let mesh = mesh.unwrap();
    assert_eq!(mesh.len(), 2);
    assert_eq!(mesh.triangle::<f64>(0).a, [0.0, 0.0, 0.0]);
    assert_eq!(
        Mesh::from_obj_str(&text, "bom.obj").unwrap(),
        Mesh { name: "bom.obj".into(), ..mesh }
    );
}

#[test]
fn texture_and_normal_references_must_exist() {
    // No vt at all: tobj skips the reference; it is an error here.
    assert_eq!(
        error_at(&format!("{SQUARE}f 1 2 3\nf 1/2/3 2 3\n"), 6),
        "texture coordinate index 2 is out of range (the file has no texture coordinates)"
    );
    assert_eq!(
        error_at(&format!("{SQUARE}vt 0 0\nf 1//9 2//1 3//1\n"), 6),
        "normal index 9 is out of range (the file has no normals)"
    );
    // With one vn, index 9 is out of range too (tobj reports it, the check names the line).
    assert_eq!(
        error_at(&format!("{SQUARE}vn 0 0 1\nf 1//9 2//1 3//1\n"), 6),
        "normal index 9 is out of range (the file has 1 normals)"
    );
    // Indices too large for any file (the fuzzer's finds: tobj overflowed on them) are named
    // like any other out-of-range index.
    assert_eq!(
        error_at(&format!("{SQUARE}vn 0 0 1\nf 1//6148914691236517206 2//1 3//1\n"), 6),
        "normal index 6148914691236517206 is out of range (the file has 1 normals)"
    );
    assert_eq!(
        error_at(&format!("{SQUARE}vt 0 0\nf 1/1 2/1 3/-9223372036854775808\n"), 6),
        "relative texture coordinate index -9223372036854775808 is out of range \
         (1 texture coordinates before this line)"
    );
    // A small relative index reaching before the first texture coordinate overflowed too.
    assert_eq!(
        error_at(&format!("{SQUARE}vt 0 0\nf 1/1 2/1 3/-9\n"), 6),
        "relative texture coordinate index -9 is out of range (1 texture coordinates before \
         this line)"
    );
    // Existing references are fine, with or without the other kind.
    let ok = format!("{SQUARE}vt 0 0\nvn 0 0 1\nf 1/1 2/1 3/1\nf 1//1 3//1 4//1\n");
    assert_eq!(Mesh::from_obj_str(&ok, "ok.obj").unwrap().len(), 2);
}

#[test]
fn nul_bytes_mean_not_a_text_file() {
    let (result, dir) = load_text("bin.obj", &format!("{SQUARE}\0f 1 2 3\n"));
    let msg = result.unwrap_err().to_string();
    let path = dir.path().join("bin.obj");
    assert_eq!(msg, format!("{}: not a text file (NUL byte at line 5)", path.display()));
    let e = Mesh::from_obj_str("\0", "x.obj").unwrap_err().to_string();
    assert_eq!(e, "x.obj: not a text file (NUL byte at line 1)");
}

#[test]
fn coordinates_beyond_a_limit_are_found_among_used_vertices() {
    let text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 -4e38\nv 5e38 0 0\nf 1 2 3\nf 1 4 2\nf 5 1 2\n";
    let mesh = Mesh::from_obj_str(text, "big.obj").unwrap();
    let limit = f64::from(f32::MAX);
    assert_eq!(mesh.first_coordinate_beyond(limit), Some((3, -4e38)));
    assert_eq!(mesh.first_coordinate_beyond(4.5e38), Some((4, 5e38)));
    assert_eq!(mesh.first_coordinate_beyond(1e39), None);
    let small = Mesh::from_obj_str("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1e39 0 0\nf 1 2 3\n", "s.obj");
    assert_eq!(small.unwrap().first_coordinate_beyond(limit), None);
}

#[test]
fn a_mesh_too_large_for_memory_is_refused_before_reading() {
    if scene::memory::available().is_none() {
        return; // no MemAvailable on this system: nothing is refused up front
    }
    // A sparse 4 TB file: no disk space used, and far beyond any machine's memory.
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("huge.obj");
    let file = std::fs::File::create(&path).unwrap();
    if file.set_len(1 << 42).is_err() {
        return; // the file system cannot hold such a file, even sparse
    }
    let start = std::time::Instant::now();
    let msg = Mesh::load(&path).unwrap_err().to_string();
    let prefix = format!("{}: too large for memory: needs about ", path.display());
    assert!(msg.starts_with(&prefix), "{msg}");
    assert!(msg.ends_with(" GB available") && !msg.contains('\n'), "{msg}");
    // Refused from the size alone: reading 4 TB would take hours.
    assert!(start.elapsed().as_secs() < 10);
}

#[test]
fn normals_beyond_f32_keep_their_direction() {
    // A component beyond f32's range would round to infinity: the normal is scaled first.
    let text = format!("{SQUARE}vn 0 3e38 1e39\nf 1//1 2//1 3//1\n");
    let mesh = Mesh::from_obj_str(&text, "big.obj").unwrap();
    let n = mesh.normals.unwrap()[0][0];
    assert_eq!(n, [0.0, 0.3, 1.0]);
}
