//! The `.glb` read back with the `gltf` crate: counts, bounds, the camera's pose and
//! projection, and the page's data.

use render::camera::Camera;
use scene::Mesh;
use view::{Run, RunCamera};

fn tetrahedron() -> Mesh {
    let obj = "v 0 0 5\nv 1 0 5\nv 0 1 5\nv 0 0 6\nf 1 2 3\nf 1 2 4\nf 1 3 4\nf 2 3 4\n";
    Mesh::from_obj_str(obj, "tetra").unwrap()
}

fn run(mesh: &Mesh) -> Run<'_> {
    let camera = Camera::look_at([0.2, 0.2, 0.0], [0.2, 0.2, 5.0], [0.0, 1.0, 0.0], 40.0).unwrap();
    let rays = vec![
        ([0.2, 0.2, 0.0], [0.0, 0.0, 1.0], Some(5.0)),
        ([0.2, 0.2, 0.0], [0.0, 0.6, 0.8], None),
    ];
    Run {
        mesh,
        camera: Some(RunCamera {
            camera,
            look_at: [0.2, 0.2, 5.0],
            width: 40,
            height: 20,
            png: vec![0x89, b'P', b'N', b'G'],
        }),
        layers: view::hit_and_miss_layers(mesh, rays),
        figures: vec![("backend".into(), "la".into())],
    }
}

/// The document and its binary chunk.
fn open(bytes: &[u8]) -> (gltf::Document, Vec<u8>) {
    let g = gltf::Gltf::from_slice(bytes).unwrap();
    let bin = g.blob.clone().unwrap_or_default();
    (g.document, bin)
}

#[test]
fn the_glb_reads_back() {
    let mesh = tetrahedron();
    let bytes = view::glb::to_bytes(&run(&mesh));
    let (doc, bin) = open(&bytes);
    let prims: Vec<_> = doc.meshes().next().unwrap().primitives().collect();
    // Triangles, hit lines, hit points, miss lines.
    let modes: Vec<_> = prims.iter().map(gltf::Primitive::mode).collect();
    use gltf::mesh::Mode;
    assert_eq!(modes, [Mode::Triangles, Mode::Lines, Mode::Points, Mode::Lines]);
    let tri = &prims[0];
    let reader = tri.reader(|_| Some(&bin[..]));
    let idx: Vec<u32> = reader.read_indices().unwrap().into_u32().collect();
    let want: Vec<u32> = mesh.triangles.iter().flatten().copied().collect();
    assert_eq!(idx, want, "triangle order kept");
    let bb = tri.bounding_box();
    assert_eq!((bb.min, bb.max), ([0.0, 0.0, 5.0], [1.0, 1.0, 6.0]));
    let hit_points: Vec<[f32; 3]> =
        prims[2].reader(|_| Some(&bin[..])).read_positions().unwrap().collect();
    assert_eq!(hit_points, [[0.2, 0.2, 5.0]]);
    assert_eq!(prims[3].get(&gltf::Semantic::Positions).unwrap().count(), 2);

    let node = doc.nodes().find(|n| n.camera().is_some()).unwrap();
    let camera = node.camera().unwrap();
    let gltf::camera::Projection::Perspective(p) = camera.projection() else {
        panic!("not a perspective camera");
    };
    assert!((p.yfov() - 40f32.to_radians()).abs() < 1e-6);
    assert_eq!(p.aspect_ratio(), Some(2.0));
    let (znear, zfar) = (p.znear(), p.zfar().unwrap());
    assert!(znear > 0.0 && znear < 5.0 && zfar > 6.0, "{znear} {zfar}");
    let (t, r, s) = node.transform().decomposed();
    assert_eq!(t, [0.2, 0.2, 0.0]);
    assert_eq!(s, [1.0; 3]);
    // The camera looks down its local -z: here along world +z; its +y is world +y; its +x
    // is our camera's left (world +x is our right: see glb's documentation).
    let rot = |v: [f32; 3]| {
        let [x, y, z, w] = r;
        let q = [x, y, z];
        let cross = |a: [f32; 3], b: [f32; 3]| {
            [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
        };
        let t = cross(q, v).map(|c| 2.0 * c);
        let u = cross(q, t);
        [0, 1, 2].map(|k| v[k] + w * t[k] + u[k])
    };
    let close = |a: [f32; 3], b: [f32; 3]| a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-6);
    assert!(close(rot([0.0, 0.0, -1.0]), [0.0, 0.0, 1.0]), "{:?}", rot([0.0, 0.0, -1.0]));
    assert!(close(rot([0.0, 1.0, 0.0]), [0.0, 1.0, 0.0]));
    assert!(close(rot([1.0, 0.0, 0.0]), [-1.0, 0.0, 0.0]));
}

#[test]
fn corner_normals_unindex_the_mesh() {
    let obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\n";
    let mesh = Mesh::from_obj_str(obj, "n").unwrap();
    let run = Run { mesh: &mesh, camera: None, layers: Vec::new(), figures: Vec::new() };
    let (doc, bin) = open(&view::glb::to_bytes(&run));
    assert_eq!(doc.cameras().count(), 0);
    let prim = doc.meshes().next().unwrap().primitives().next().unwrap();
    let reader = prim.reader(|_| Some(&bin[..]));
    let n: Vec<[f32; 3]> = reader.read_normals().unwrap().collect();
    assert_eq!(n, [[0.0, 0.0, 1.0]; 3]);
    assert!(prim.indices().is_none());
}

#[test]
fn the_page_holds_its_data_and_no_early_script_end() {
    let mut mesh = tetrahedron();
    mesh.name = "a</script>b".into();
    let page = view::page::to_string(&run(&mesh));
    assert!(page.starts_with("<!DOCTYPE html>"));
    assert_eq!(page.matches("</script>").count(), page.matches("<script").count());
    assert!(page.contains(r#"id="positions""#) && page.contains(r#"id="layer1""#));
    assert!(page.contains(r#""triangles":4"#) && page.contains(r#"["backend","la"]"#));
    assert!(!page.contains("http://") && !page.contains("https://"), "no network fetch");
}
