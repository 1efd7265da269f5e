//! How much of our tree and of tinybvh's a ray must visit: a diagnostic of issue 18, not a
//! timing. For each ray, its closest hit `t` (from `la`) is found first; then every box of
//! each tree that the ray enters at or before `t` is counted, as an ideal front-to-back
//! traversal would visit it whatever its order: interior nodes, leaves, and the triangles
//! in those leaves. Both trees are walked by the same code (an `f64` slab test), so only
//! their shapes differ: ours ([`bvh::Bvh`], 8 wide) and tinybvh's `MBVH<8>` built as the
//! `versus` bench builds the `BVH8_CPU` it times (binned SAH, leaves split to 4 triangles).
//!
//! Run: `cargo run --release -p wedge-benches --example tree_visits` (about a minute).

use bvh::accel::Accel;
use bvh::{Bvh, Child};
use intersect::Ray;
use intersect::vec3::sub;
use render::camera::{Camera, DEFAULT_FOV_DEG};
use scene::Mesh;
use tinybvh_rs::{bvh as tiny, mbvh};
use wedge_benches::throughput::rays::{INCOHERENT_SEED, camera_rays, incoherent_rays};
use wedge_benches::throughput::scenes::{bunny, subdivided};

/// Camera rays per side, and incoherent rays.
const SIDE: u32 = 512;
const INCOHERENT: usize = 200_000;

/// The `versus` bench's front view at `scale` times the automatic distance (0.7: `fill`,
/// 3.0: `small`).
fn camera(mesh: &Mesh, scale: f64) -> Camera {
    let (center, radius) = mesh.bounding_sphere();
    let auto = Camera::auto(center, radius, DEFAULT_FOV_DEG, 1.0).expect("finite bounds");
    let back = sub(auto.eye(), center);
    let eye = core::array::from_fn(|k| center[k] + scale * back[k]);
    Camera::look_at(eye, center, [0.0, 1.0, 0.0], DEFAULT_FOV_DEG).expect("a valid camera")
}

/// Whether the ray `o + s d` (`inv = 1 / d`) enters the box within `[0, t]`.
fn enters(lo: [f32; 3], hi: [f32; 3], o: [f64; 3], inv: [f64; 3], t: f64) -> bool {
    let (mut near, mut far) = (0.0f64, t);
    for k in 0..3 {
        let a = (f64::from(lo[k]) - o[k]) * inv[k];
        let b = (f64::from(hi[k]) - o[k]) * inv[k];
        near = near.max(a.min(b));
        far = far.min(a.max(b));
    }
    near <= far
}

/// Visits summed over rays.
#[derive(Default)]
struct Visits {
    nodes: u64,
    leaves: u64,
    triangles: u64,
}

/// The ray `(o, inv)` within `t` in our tree, from node `i`.
fn ours(tree: &Bvh<f32>, i: usize, o: [f64; 3], inv: [f64; 3], t: f64, v: &mut Visits) {
    v.nodes += 1;
    for child in tree.children(i) {
        let b = child.bounds();
        if !enters(b.min, b.max, o, inv, t) {
            continue;
        }
        match child {
            Child::Leaf { slots, .. } => {
                v.leaves += 1;
                v.triangles += slots.len() as u64;
            }
            Child::Node { index, .. } => ours(tree, index, o, inv, t, v),
        }
    }
}

/// The same in tinybvh's `MBVH<8>`.
fn theirs(nodes: &[mbvh::Node], i: usize, o: [f64; 3], inv: [f64; 3], t: f64, v: &mut Visits) {
    let node = &nodes[i];
    v.nodes += 1;
    for &c in &node.child[..node.child_count as usize] {
        let child = &nodes[c as usize];
        if !enters(child.aabb_min, child.aabb_max, o, inv, t) {
            continue;
        }
        if child.is_leaf() {
            v.leaves += 1;
            v.triangles += u64::from(child.tri_count);
        } else {
            theirs(nodes, c as usize, o, inv, t, v);
        }
    }
}

fn main() {
    for (name, mesh) in [("bunny", bunny()), ("bunny-sub2", subdivided(&bunny(), 2))] {
        let triangles = mesh.triangles::<f32>();
        let accel = Accel::build(kernels_la::Watertight::<f32>::new(), &triangles);
        let positions: Vec<[f32; 4]> =
            triangles.iter().flat_map(|t| t.vertices().map(|[x, y, z]| [x, y, z, 0.0])).collect();
        let mut wald = tiny::BVH::new(positions.as_slice().into()).expect("whole triangles");
        wald.split_leaves(4);
        let wide = mbvh::BVH::new(&wald);
        let tree = accel.bvh();
        println!(
            "{name}: ours {} interior nodes and {} leaves; tinybvh {} nodes (leaves included)",
            tree.node_count(),
            tree.leaf_count(),
            wide.nodes().len()
        );
        println!("  per ray: interior nodes, leaves, triangles (ours | tinybvh)");
        for (view, rays) in [
            ("fill", camera_rays(&camera(&mesh, 0.7), SIDE, SIDE)),
            ("small", camera_rays(&camera(&mesh, 3.0), SIDE, SIDE)),
            ("incoherent", incoherent_rays(&mesh, INCOHERENT, INCOHERENT_SEED)),
        ] {
            let (mut a, mut b) = (Visits::default(), Visits::default());
            for r in &rays {
                let ray: Ray<f32> = r.cast();
                let t = accel.closest_hit(&ray).map_or(f64::INFINITY, |h| f64::from(h.t));
                let inv = r.dir.map(|d| 1.0 / d);
                ours(tree, 0, r.origin, inv, t, &mut a);
                theirs(wide.nodes(), 0, r.origin, inv, t, &mut b);
            }
            let per = |x: u64| x as f64 / rays.len() as f64;
            println!(
                "  {view}: {:.2} {:.2} {:.2} | {:.2} {:.2} {:.2}",
                per(a.nodes),
                per(a.leaves),
                per(a.triangles),
                per(b.nodes),
                per(b.leaves),
                per(b.triangles)
            );
        }
    }
}
