//! Every conformance check of the seam (`intersect::conformance`) on the exact kernel (`f64`
//! only): watertight, and its decisions exact. Its own tests (`accuracy.rs`, `predicates.rs`,
//! `robustness.rs`, `watertight.rs`) check it against independent exact rational arithmetic.

use intersect::conformance::check_all;
use intersect::{Guarantees, Intersector};

#[test]
fn exact_conforms() {
    assert_eq!(
        <exact::Exact as Intersector>::GUARANTEES,
        Guarantees { watertight: true, exact: true },
        "declared guarantees"
    );
    check_all::<exact::Exact>();
}
