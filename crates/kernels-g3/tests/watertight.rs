//! What is true of each kernel on the conformance kit's tile grid (rays aimed exactly at
//! shared edges and vertices; see `intersect::conformance::cracks::grid`): `ga-plucker` lets
//! no ray through (asserted again here beside the others, and with double hits and mixed
//! winding in its conformance run, `tests/conformance.rs`), and `ga` and `ga-report`, which
//! are not watertight, leave cracks at shared edges in both precisions near the origin, and
//! (but for `ga` built without FMA) at shared vertices and far from it. The counts are
//! printed with `--nocapture`.

use intersect::Intersector;
use intersect::conformance::cracks::grid::cracks;
use intersect::conformance::label;

const RAYS: usize = 20_000;

/// The grid at the origin and `1e3` grid sizes away.
const OFFSETS: [f64; 2] = [0.0, 8e3];

/// Rays that hit no triangle `[through edges, through vertices]` at each offset, printed.
fn report<I: Intersector + Default>() -> [[usize; 2]; 2] {
    OFFSETS.map(|offset| {
        let [edges, vertices] = cracks::<I>(0x6a_2001, offset, false, RAYS);
        let (name, half) = (label::<I>(), RAYS / 2);
        eprintln!("{name}, offset {offset}: rays missed: {edges} of {half} through shared edges,");
        eprintln!("    {vertices} of {half} through shared vertices");
        [edges, vertices]
    })
}

/// A kernel that is not watertight cracks at shared edges near the origin; at shared
/// vertices there too, and somewhere far from it, where `vertices` and `far` say so.
fn leaves_cracks<I: Intersector + Default>(vertices: bool, far: bool) {
    let [[edges, near_vertices], [far_edges, far_vertices]] = report::<I>();
    let name = label::<I>();
    assert!(edges > 0, "{name}: no crack at a shared edge");
    assert!(near_vertices > 0 || !vertices, "{name}: no crack at a shared vertex");
    assert!(far_edges + far_vertices > 0 || !far, "{name}: no crack far from the origin");
}

#[test]
fn ga_plucker_has_no_cracks() {
    assert_eq!(report::<kernels_g3::G3Watertight<f32>>(), [[0, 0]; 2]);
    assert_eq!(report::<kernels_g3::G3Watertight<f64>>(), [[0, 0]; 2]);
}

#[test]
fn g3_watertight_has_no_cracks() {
    assert_eq!(report::<kernels_g3::G3WatertightCell<f32>>(), [[0, 0]; 2]);
    assert_eq!(report::<kernels_g3::G3WatertightCell<f64>>(), [[0, 0]; 2]);
}

/// Built without FMA, `ga` rounds differently: its cracks are all at edges, and in `f64` far
/// from the origin it leaves none on these rays.
#[test]
fn ga_leaves_cracks() {
    let fma = cfg!(target_feature = "fma");
    leaves_cracks::<kernels_g3::G3Frame<f32>>(fma, true);
    leaves_cracks::<kernels_g3::G3Frame<f64>>(fma, fma);
}

#[test]
fn ga_report_leaves_cracks() {
    leaves_cracks::<kernels_g3::G3Report<f32>>(true, true);
    leaves_cracks::<kernels_g3::G3Report<f64>>(true, true);
}

#[test]
fn g3_mt_leaves_cracks() {
    leaves_cracks::<kernels_g3::G3Mt<f32>>(true, true);
    leaves_cracks::<kernels_g3::G3Mt<f64>>(true, true);
}

/// Plücker coordinates are not watertight, but a shared edge's two sides are exact negatives
/// (both lines negated exactly), so nothing passes through an edge: what it lets through is
/// at vertices, where several rounded sides must agree in sign.
#[test]
fn g3_plucker_cracks_only_at_vertices() {
    for [[edges, vertices], [far_edges, far_vertices]] in
        [report::<kernels_g3::G3Plucker<f32>>(), report::<kernels_g3::G3Plucker<f64>>()]
    {
        assert_eq!((edges, far_edges), (0, 0));
        assert!(vertices + far_vertices > 0, "no crack at a vertex");
    }
}
