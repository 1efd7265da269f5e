//! The report's multiplication tables (figures 2.5, 2.6 and 2.7), copied blade by blade as
//! printed, against the reference algebra and against `ga::g3`.
//!
//! As printed, the entry in row `r`, column `c` is `c r`, not `r c`: row `e1`, column `e2` of
//! figure 2.5 reads `-e12`, but `e1 e2 = +e12` (the report's own equation 2.11). These tests
//! assert that every entry equals the transposed product, that the untransposed reading fails
//! exactly on the pairs of blades that anticommute, and that our products agree with the
//! transposed tables. See erratum E1 in `ga::errata`.

use ga::g3::Multivector;
use ga_reference::{G3_REPORT_NAMES, Multivector as Reference, from_g3_report, to_g3_report};

/// Figure 2.5, the geometric product, exactly as printed (`s` is the scalar 1).
const GEOMETRIC: [[&str; 8]; 8] = [
    ["s", "e1", "e2", "e3", "e12", "e23", "e31", "e123"],
    ["e1", "s", "-e12", "e31", "-e2", "e123", "e3", "e23"],
    ["e2", "e12", "s", "-e23", "e1", "-e3", "e123", "e31"],
    ["e3", "-e31", "e23", "s", "e123", "e2", "-e1", "e12"],
    ["e12", "e2", "-e1", "e123", "-s", "e31", "-e23", "-e3"],
    ["e23", "e123", "e3", "-e2", "-e31", "-s", "e12", "-e1"],
    ["e31", "-e3", "e123", "e1", "e23", "-e12", "-s", "-e2"],
    ["e123", "e23", "e31", "e12", "-e3", "-e1", "-e2", "-s"],
];

/// Figure 2.6, the outer product, exactly as printed.
const OUTER: [[&str; 8]; 8] = [
    ["s", "e1", "e2", "e3", "e12", "e23", "e31", "e123"],
    ["e1", "0", "-e12", "e31", "0", "e123", "0", "0"],
    ["e2", "e12", "0", "-e23", "0", "0", "e123", "0"],
    ["e3", "-e31", "e23", "0", "e123", "0", "0", "0"],
    ["e12", "0", "0", "e123", "0", "0", "0", "0"],
    ["e23", "e123", "0", "0", "0", "0", "0", "0"],
    ["e31", "0", "e123", "0", "0", "0", "0", "0"],
    ["e123", "0", "0", "0", "0", "0", "0", "0"],
];

/// Figure 2.7, the inner product, exactly as printed.
const INNER: [[&str; 8]; 8] = [
    ["0", "0", "0", "0", "0", "0", "0", "0"],
    ["0", "s", "0", "0", "-e2", "0", "e3", "e23"],
    ["0", "0", "s", "0", "e1", "-e3", "0", "e31"],
    ["0", "0", "0", "s", "0", "e2", "-e1", "e12"],
    ["0", "e2", "-e1", "0", "-s", "0", "0", "-e3"],
    ["0", "0", "e3", "-e2", "0", "-s", "0", "-e1"],
    ["0", "-e3", "0", "e1", "0", "0", "-s", "-e2"],
    ["0", "e23", "e31", "e12", "-e3", "-e1", "-e2", "-s"],
];

/// The coefficients (report basis) of a printed entry such as `-e12`, `s` or `0`.
fn parse(entry: &str) -> [f64; 8] {
    let mut out = [0.0; 8];
    if entry == "0" {
        return out;
    }
    let (sign, name) = match entry.strip_prefix('-') {
        Some(name) => (-1.0, name),
        None => (1.0, entry),
    };
    let name = if name == "s" { "1" } else { name };
    let index = G3_REPORT_NAMES.iter().position(|&n| n == name).expect("a blade of the report");
    out[index] = sign;
    out
}

fn unit(k: usize) -> [f64; 8] {
    let mut out = [0.0; 8];
    out[k] = 1.0;
    out
}

/// Which product a table shows, in the reference algebra and in `ga::g3`.
struct Table {
    name: &'static str,
    entries: [[&'static str; 8]; 8],
    reference: fn(&Reference, &Reference) -> Reference,
    ours: fn(Multivector<f64>, Multivector<f64>) -> Multivector<f64>,
    /// How many printed entries are wrong when read as `row * column`.
    untransposed_failures: usize,
}

fn tables() -> [Table; 3] {
    [
        Table {
            name: "figure 2.5 (geometric)",
            entries: GEOMETRIC,
            reference: Reference::geometric,
            ours: |a, b| a * b,
            untransposed_failures: 24,
        },
        Table {
            name: "figure 2.6 (outer)",
            entries: OUTER,
            reference: Reference::outer,
            ours: |a, b| a ^ b,
            untransposed_failures: 6,
        },
        Table {
            name: "figure 2.7 (inner)",
            entries: INNER,
            reference: Reference::inner,
            ours: |a, b| a | b,
            untransposed_failures: 12,
        },
    ]
}

fn reference_product(table: &Table, left: usize, right: usize) -> [f64; 8] {
    to_g3_report(&(table.reference)(&from_g3_report(unit(left)), &from_g3_report(unit(right))))
}

/// Every printed entry (row `r`, column `c`) is the product `c r`.
#[test]
fn every_entry_is_column_times_row() {
    for table in tables() {
        for (r, row) in table.entries.iter().enumerate() {
            for (c, entry) in row.iter().enumerate() {
                assert_eq!(
                    parse(entry),
                    reference_product(&table, c, r),
                    "{}: row {}, column {}",
                    table.name,
                    G3_REPORT_NAMES[r],
                    G3_REPORT_NAMES[c]
                );
            }
        }
    }
}

/// Read as `row * column`, the printed tables are wrong exactly where the two blades
/// anticommute (and the product is non-zero): 24, 6 and 12 entries.
#[test]
fn row_times_column_reading_fails_on_anticommuting_pairs() {
    for table in tables() {
        let mut failures = 0;
        for (r, row) in table.entries.iter().enumerate() {
            for (c, entry) in row.iter().enumerate() {
                let row_first = reference_product(&table, r, c);
                let column_first = reference_product(&table, c, r);
                let anticommute = row_first != column_first;
                if anticommute {
                    assert_eq!(row_first.map(|x| -x), column_first, "{}", table.name);
                }
                if parse(entry) != row_first {
                    assert!(anticommute, "{}: {r},{c} fails without anticommuting", table.name);
                    failures += 1;
                }
            }
        }
        assert_eq!(failures, table.untransposed_failures, "{}", table.name);
    }
}

/// `ga::g3`'s products reproduce the transposed tables blade by blade.
#[test]
fn our_products_match_the_transposed_tables() {
    for table in tables() {
        for (r, row) in table.entries.iter().enumerate() {
            for (c, entry) in row.iter().enumerate() {
                let column = Multivector::from_array(unit(c));
                let row_blade = Multivector::from_array(unit(r));
                assert_eq!(
                    (table.ours)(column, row_blade).to_array(),
                    parse(entry),
                    "{}: {} times {}",
                    table.name,
                    G3_REPORT_NAMES[c],
                    G3_REPORT_NAMES[r]
                );
            }
        }
    }
}
