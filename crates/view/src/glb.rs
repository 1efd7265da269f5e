//! The run as a glTF 2.0 binary (`.glb`), written by this small writer: one JSON chunk
//! (`serde_json`) and one binary chunk.
//!
//! Node 0 holds the mesh: its triangles (positions as `f32`, in the file's triangle order;
//! indexed when the mesh has no normals, else three vertices per triangle with the file's
//! corner normals), then per ray layer a `LINES` primitive, and the hit points of hit layers as
//! `POINTS`. Everything is in the mesh's coordinates (the scene has no transform).
//!
//! # The camera
//!
//! Node 1 (for `raytrace`) is a perspective camera with the run's `yfov`, `aspectRatio` (width
//! / height), and `znear`/`zfar` bracketing the mesh's bounding sphere. glTF's camera looks down
//! its local -z with +y up and +x to the right, right-handed; ours (`render::camera`) has
//! `right = up x forward`, so that +x of the image is the world's `right` in a left-handed
//! frame. The node's rotation maps local (x, y, z) to (-right, up', -forward): the glTF camera
//! stands at the eye and looks where ours looks, with the same up, and therefore sees the
//! rendered image mirrored left to right (a rotation cannot undo a change of handedness; the
//! alternative, a negative scale on the node, is not allowed on camera nodes by the spec).

use std::io::{self, Write};

use serde_json::{Value, json};

use crate::{Run, SegmentKind};

/// glTF's component type for `f32`.
const FLOAT: u32 = 5126;
/// glTF's component type for `u32`.
const UNSIGNED_INT: u32 = 5125;
/// `bufferView.target` for vertex attributes.
const ARRAY_BUFFER: u32 = 34962;
/// `bufferView.target` for indices.
const ELEMENT_ARRAY_BUFFER: u32 = 34963;

/// The binary chunk and the JSON objects that describe it.
#[derive(Default)]
struct Builder {
    bin: Vec<u8>,
    views: Vec<Value>,
    accessors: Vec<Value>,
}

impl Builder {
    /// Adds `data` as a buffer view and an accessor; returns the accessor's index.
    fn vec3(&mut self, data: &[[f32; 3]]) -> usize {
        let mut min = [f32::INFINITY; 3];
        let mut max = [f32::NEG_INFINITY; 3];
        for p in data {
            for k in 0..3 {
                min[k] = min[k].min(p[k]);
                max[k] = max[k].max(p[k]);
            }
        }
        let bytes: Vec<u8> = data.iter().flatten().flat_map(|x| x.to_le_bytes()).collect();
        let view = self.view(&bytes, ARRAY_BUFFER);
        self.accessor(json!({
            "bufferView": view, "componentType": FLOAT, "count": data.len(), "type": "VEC3",
            "min": min, "max": max,
        }))
    }

    /// Adds `data` (without bounds: only POSITION accessors need them).
    fn vec3_unbounded(&mut self, data: &[[f32; 3]]) -> usize {
        let bytes: Vec<u8> = data.iter().flatten().flat_map(|x| x.to_le_bytes()).collect();
        let view = self.view(&bytes, ARRAY_BUFFER);
        self.accessor(json!({
            "bufferView": view, "componentType": FLOAT, "count": data.len(), "type": "VEC3",
        }))
    }

    fn indices(&mut self, data: &[u32]) -> usize {
        let bytes: Vec<u8> = data.iter().flat_map(|x| x.to_le_bytes()).collect();
        let view = self.view(&bytes, ELEMENT_ARRAY_BUFFER);
        self.accessor(json!({
            "bufferView": view, "componentType": UNSIGNED_INT, "count": data.len(),
            "type": "SCALAR",
        }))
    }

    fn view(&mut self, bytes: &[u8], target: u32) -> usize {
        // Every element is 4 bytes long, so every view stays 4-byte aligned.
        self.views.push(json!({
            "buffer": 0, "byteOffset": self.bin.len(), "byteLength": bytes.len(), "target": target,
        }));
        self.bin.extend_from_slice(bytes);
        self.views.len() - 1
    }

    fn accessor(&mut self, a: Value) -> usize {
        self.accessors.push(a);
        self.accessors.len() - 1
    }
}

/// The quaternion `[x, y, z, w]` of the rotation whose matrix has columns `x`, `y`, `z`
/// (orthonormal, right-handed).
fn quaternion(x: [f64; 3], y: [f64; 3], z: [f64; 3]) -> [f64; 4] {
    // m[row][col]
    let m = [[x[0], y[0], z[0]], [x[1], y[1], z[1]], [x[2], y[2], z[2]]];
    let trace = m[0][0] + m[1][1] + m[2][2];
    let q = if trace > 0.0 {
        let s = (trace + 1.0).sqrt() * 2.0;
        [(m[2][1] - m[1][2]) / s, (m[0][2] - m[2][0]) / s, (m[1][0] - m[0][1]) / s, s / 4.0]
    } else if m[0][0] > m[1][1] && m[0][0] > m[2][2] {
        let s = (1.0 + m[0][0] - m[1][1] - m[2][2]).sqrt() * 2.0;
        [s / 4.0, (m[0][1] + m[1][0]) / s, (m[0][2] + m[2][0]) / s, (m[2][1] - m[1][2]) / s]
    } else if m[1][1] > m[2][2] {
        let s = (1.0 + m[1][1] - m[0][0] - m[2][2]).sqrt() * 2.0;
        [(m[0][1] + m[1][0]) / s, s / 4.0, (m[1][2] + m[2][1]) / s, (m[0][2] - m[2][0]) / s]
    } else {
        let s = (1.0 + m[2][2] - m[0][0] - m[1][1]).sqrt() * 2.0;
        [(m[0][2] + m[2][0]) / s, (m[1][2] + m[2][1]) / s, s / 4.0, (m[1][0] - m[0][1]) / s]
    };
    // Exactly unit length, as the validator checks.
    let n = q.iter().map(|c| c * c).sum::<f64>().sqrt();
    q.map(|c| c / n)
}

#[allow(clippy::cast_possible_truncation)]
fn f32s(p: [f64; 3]) -> [f32; 3] {
    p.map(|x| x as f32)
}

/// The `.glb` file's bytes for `run`.
#[must_use]
pub fn to_bytes(run: &Run<'_>) -> Vec<u8> {
    let mesh = run.mesh;
    let mut b = Builder::default();
    let mut primitives = Vec::new();
    let materials = vec![
        json!({"name": "mesh", "pbrMetallicRoughness": {"baseColorFactor": [0.86, 0.85, 0.8, 1.0],
            "metallicFactor": 0.0}, "doubleSided": true}),
    ];
    let mut materials = materials;
    if !mesh.triangles.is_empty() {
        let prim = if let Some(normals) = &mesh.normals {
            // Corner normals: three vertices per triangle, in triangle order.
            let pos: Vec<[f32; 3]> = mesh
                .triangles
                .iter()
                .flatten()
                .map(|&v| f32s(mesh.positions[v as usize]))
                .collect();
            let nrm: Vec<[f32; 3]> = normals.iter().flatten().copied().collect();
            let p = b.vec3(&pos);
            let n = b.vec3_unbounded(&nrm);
            json!({"attributes": {"POSITION": p, "NORMAL": n}, "mode": 4, "material": 0})
        } else {
            let p = b.vec3(&crate::positions_f32(mesh));
            let idx: Vec<u32> = mesh.triangles.iter().flatten().copied().collect();
            let i = b.indices(&idx);
            json!({"attributes": {"POSITION": p}, "indices": i, "mode": 4, "material": 0})
        };
        primitives.push(prim);
    }
    for layer in run.layers.iter().filter(|l| !l.segments.is_empty()) {
        materials.push(json!({"name": layer.name, "pbrMetallicRoughness": {
            "baseColorFactor": [layer.colour[0], layer.colour[1], layer.colour[2], 1.0],
            "metallicFactor": 0.0}}));
        let material = materials.len() - 1;
        let ends: Vec<[f32; 3]> = layer.segments.iter().flatten().map(|&p| f32s(p)).collect();
        let p = b.vec3(&ends);
        primitives.push(json!({"attributes": {"POSITION": p}, "mode": 1, "material": material}));
        if layer.kind == SegmentKind::Hit {
            let hits: Vec<[f32; 3]> = layer.segments.iter().map(|s| f32s(s[1])).collect();
            let p = b.vec3(&hits);
            primitives
                .push(json!({"attributes": {"POSITION": p}, "mode": 0, "material": material}));
        }
    }
    let mut nodes = Vec::new();
    let mut meshes = Vec::new();
    if !primitives.is_empty() {
        meshes.push(json!({"name": mesh.name, "primitives": primitives}));
        nodes.push(json!({"name": mesh.name, "mesh": 0}));
    }
    let mut cameras = Vec::new();
    if let Some(c) = &run.camera {
        let cam = &c.camera;
        let (centre, radius) = mesh.bounding_sphere();
        let eye = cam.eye();
        let dist = (0..3).map(|k| (centre[k] - eye[k]).powi(2)).sum::<f64>().sqrt();
        let zfar = (dist + 2.0 * radius).max(1e-6);
        let znear = (dist - 2.0 * radius).max(zfar * 1e-4);
        cameras.push(json!({"type": "perspective", "perspective": {
            "yfov": cam.fov_deg().to_radians(),
            "aspectRatio": f64::from(c.width) / f64::from(c.height),
            "znear": znear, "zfar": zfar}}));
        let neg = |v: [f64; 3]| v.map(|x| -x);
        let rotation = quaternion(neg(cam.right()), cam.up(), neg(cam.forward()));
        nodes.push(json!({"name": "camera", "camera": 0, "translation": eye,
            "rotation": rotation}));
    }
    let mut root = json!({
        "asset": {"version": "2.0", "generator": "wedge (crates/view)"},
        "scene": 0,
        "scenes": [{"nodes": (0..nodes.len()).collect::<Vec<_>>()}],
        "nodes": nodes,
    });
    let obj = root.as_object_mut().expect("an object");
    if !meshes.is_empty() {
        obj.insert("meshes".into(), meshes.into());
        obj.insert("materials".into(), materials.into());
    }
    if !cameras.is_empty() {
        obj.insert("cameras".into(), cameras.into());
    }
    if !b.bin.is_empty() {
        obj.insert("buffers".into(), json!([{"byteLength": b.bin.len()}]));
        obj.insert("bufferViews".into(), b.views.into());
        obj.insert("accessors".into(), b.accessors.into());
    }
    container(&root.to_string(), b.bin)
}

/// The GLB container: header, JSON chunk padded with spaces, BIN chunk padded with zeros.
fn container(json: &str, mut bin: Vec<u8>) -> Vec<u8> {
    let mut text = json.as_bytes().to_vec();
    while !text.len().is_multiple_of(4) {
        text.push(b' ');
    }
    while !bin.len().is_multiple_of(4) {
        bin.push(0);
    }
    let bin_chunk = if bin.is_empty() { 0 } else { 8 + bin.len() };
    let total = 12 + 8 + text.len() + bin_chunk;
    let u32le = |n: usize| u32::try_from(n).expect("a .glb is under 4 GiB").to_le_bytes();
    let mut out = Vec::with_capacity(total);
    out.extend_from_slice(b"glTF");
    out.extend_from_slice(&2u32.to_le_bytes());
    out.extend_from_slice(&u32le(total));
    out.extend_from_slice(&u32le(text.len()));
    out.extend_from_slice(b"JSON");
    out.extend_from_slice(&text);
    if !bin.is_empty() {
        out.extend_from_slice(&u32le(bin.len()));
        out.extend_from_slice(b"BIN\0");
        out.extend_from_slice(&bin);
    }
    out
}

/// Writes [`to_bytes`] into `w`.
///
/// # Errors
///
/// If writing fails.
pub fn write(run: &Run<'_>, w: &mut impl Write) -> io::Result<()> {
    w.write_all(&to_bytes(run))
}
