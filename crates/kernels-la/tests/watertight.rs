//! What is true of Moller-Trumbore on the conformance kit's height field (rays aimed exactly
//! at shared edges and vertices; see `intersect::conformance::cracks::height_field`): it is
//! not watertight, which is why it is not the default. That the watertight kernel lets no ray
//! through and counts none twice is part of its conformance run (`tests/conformance.rs`).
//! The counts are printed with `--nocapture`.

use intersect::conformance::cracks::height_field::report;

/// The rays do reach the edges exactly: a kernel with closed triangles (the tie rule left
/// out, here Moller-Trumbore in `f64`, which counts `u = 0` as inside) hits both sides of
/// some of them.
#[test]
fn rays_land_exactly_on_edges() {
    for c in report::<kernels_la::MollerTrumbore<f64>>() {
        assert!(c.multiple > 0, "{c:?}");
    }
}

#[test]
fn moller_trumbore_cracks_in_f32() {
    let [near, far] = report::<kernels_la::MollerTrumbore<f32>>();
    // Measured (seeded, so reproducible): 1119 of 12676 rays slip through near the origin,
    // 7 of 12676 far from it. Far away the vertices are quantised to 2^-9, which leaves them
    // few significant bits relative to the triangles' size, so Moller-Trumbore's arithmetic
    // is nearly exact there; near the origin every vertex has 24 significant bits. Asserted
    // loosely: at least 1% near, some far.
    assert!(near.cracks * 100 > near.rays, "{near:?}");
    assert!(far.cracks > 0, "{far:?}");
}
