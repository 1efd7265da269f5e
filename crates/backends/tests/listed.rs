//! Every back end of the registry is documented and measured: the README's back-end tables
//! have exactly [`Backend::ALL`]'s rows, and every table and plot in `results/` has each back
//! end (in each precision where the table has a precision column).

use std::fs;
use std::path::{Path, PathBuf};

use backends::{Backend, Precision};

fn workspace_file(name: &str) -> (PathBuf, String) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..").join(name);
    let text = fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    (path, text)
}

fn registry_names() -> Vec<&'static str> {
    Backend::ALL.iter().map(|b| b.name()).collect()
}

/// The cells of a Markdown table row, trimmed (`\|` kept as it is written).
fn cells(line: &str) -> Vec<&str> {
    let inner = line.trim().trim_start_matches('|').trim_end_matches('|');
    let mut cells = Vec::new();
    let mut start = 0;
    let bytes = inner.as_bytes();
    for i in 0..bytes.len() {
        if bytes[i] == b'|' && (i == 0 || bytes[i - 1] != b'\\') {
            cells.push(inner[start..i].trim());
            start = i + 1;
        }
    }
    cells.push(inner[start..].trim());
    cells
}

/// The first cells of the rows of the README table whose header's first cell is `header`.
fn table_first_cells<'a>(text: &'a str, header: &str) -> Vec<&'a str> {
    let mut lines = text.lines().skip_while(|l| !l.starts_with('|') || cells(l)[0] != header);
    assert!(lines.next().is_some(), "README.md: no table headed `{header}`");
    lines.next(); // the |---| line
    lines.take_while(|l| l.starts_with('|')).map(|l| cells(l)[0]).collect()
}

#[test]
fn readme_backend_table_has_exactly_the_registry() {
    let (_, readme) = workspace_file("README.md");
    let rows = table_first_cells(&readme, "`--backend`");
    // Each row starts with the name in backticks; the reference (`exact`, not a `--backend`)
    // closes the table.
    let mut names: Vec<&str> = rows
        .iter()
        .map(|cell| cell.split('`').nth(1).unwrap_or_else(|| panic!("row `{cell}`: no name")))
        .collect();
    assert_eq!(names.pop(), Some("exact"), "the table's last row is the exact reference");
    assert_eq!(names, registry_names(), "README.md's back-end table against Backend::ALL");
}

#[test]
fn readme_option_row_lists_the_registry() {
    let (_, readme) = workspace_file("README.md");
    let row = readme
        .lines()
        .find(|l| l.starts_with("| `--backend "))
        .expect("README.md: no `--backend` option row");
    let option = cells(row)[0];
    let list = option.trim_matches('`').strip_prefix("--backend ").unwrap();
    let names: Vec<&str> = list.split("\\|").collect();
    assert_eq!(names, registry_names(), "README.md's option row against Backend::ALL");
    let default = cells(row)[1].trim_matches('`');
    assert_eq!(default, Backend::default().name());
}

/// The `(backend, precision)` pairs of a CSV file of `results/`.
fn csv_pairs(name: &str) -> Vec<(String, String)> {
    let (path, text) = workspace_file(&format!("results/{name}"));
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap_or_default().split(',').collect();
    let col = |c: &str| {
        header.iter().position(|h| *h == c).unwrap_or_else(|| {
            panic!("{}: no `{c}` column", path.display());
        })
    };
    let (b, p) = (col("backend"), col("precision"));
    lines
        .filter(|l| !l.is_empty())
        .map(|l| {
            let fields: Vec<&str> = l.split(',').collect();
            (fields[b].to_owned(), fields[p].to_owned())
        })
        .collect()
}

#[test]
fn every_results_table_has_every_backend_in_both_precisions() {
    let files = ["throughput.csv", "kernels.csv", "accuracy.csv", "interleaved.csv"];
    for file in files.into_iter().chain(["stability.csv", "instructions.csv"]) {
        let pairs = csv_pairs(file);
        for b in Backend::ALL {
            for p in Precision::ALL {
                let found = pairs.iter().any(|(x, y)| x == b.name() && y == p.name());
                assert!(found, "results/{file}: no row for {} {}", b.name(), p.name());
            }
        }
    }
}

#[test]
fn the_summary_has_every_backend() {
    let (_, summary) = workspace_file("results/SUMMARY.md");
    for b in Backend::ALL {
        let rows = summary.lines().filter(|l| l.starts_with('|') && cells(l)[0] == b.name());
        // The image table, the cost table, the accuracy and aimed tables: several rows each.
        assert!(rows.count() >= 4, "results/SUMMARY.md: too few rows for {}", b.name());
    }
}

#[test]
fn every_plot_has_every_backend() {
    for file in ["throughput.svg", "runtime_vs_error.svg"] {
        let (_, svg) = workspace_file(&format!("results/{file}"));
        // plotters writes each text element's content on a line of its own.
        let texts: Vec<&str> = svg.lines().map(str::trim).collect();
        for b in Backend::ALL {
            let label = |t: &&str| *t == b.name() || t.starts_with(&format!("{} ", b.name()));
            assert!(texts.iter().any(label), "results/{file}: no label for {}", b.name());
        }
    }
}
