//! Crack counters: rays aimed exactly at the shared edges and vertices of meshes without
//! holes, and the check that a watertight kernel lets none through and counts none twice.
//! Non-watertight kernels' tests use the counters to say what is true of them.

pub mod grid;
pub mod height_field;

use super::label;
use crate::Intersector;

/// The height field near the origin and far from it, and the tile grid near and far, with
/// consistent and with mixed winding (then the edge value is the same in both neighbours,
/// not negated, and each accepts the other sign): no ray slips through, none hits twice.
///
/// # Panics
///
/// If a ray finds a crack or a double hit.
pub fn no_cracks_and_no_double_hits<I: Intersector + Default>() {
    let name = label::<I>();
    for c in height_field::report::<I>() {
        assert!(c.rays > 10_000, "{name}: {c:?}");
        assert_eq!((c.cracks, c.multiple), (0, 0), "{name}: height field {c:?}");
    }
    for offset in [0.0, 8e3] {
        for (seed, mixed) in [(0x6a_2001, false), (0x6a_2002, false), (0x6a_2003, true)] {
            let counts = grid::cracks_and_doubles::<I>(seed, offset, mixed, 20_000);
            assert_eq!(counts, [[0, 0]; 2], "{name}: grid at {offset}, mixed winding {mixed}");
        }
    }
}
