//! Every conformance check of the seam (`intersect::conformance`) on the exact kernel (`f64`
//! only): watertight, and its decisions exact. Its own tests (`accuracy.rs`, `predicates.rs`,
//! `robustness.rs`, `watertight.rs`) check it against independent exact rational arithmetic.

use intersect::conformance::{Guarantees, check_all};

#[test]
fn exact_conforms() {
    check_all::<exact_tracer::Exact>(&Guarantees { watertight: true, exact: true });
}
