//! Regenerates `results/SUMMARY.md` from `results/accuracy.csv`, `results/stability.csv` and,
//! when present, `results/throughput.csv`, without running any benchmark (for instance after
//! the throughput bench has been run again).
//!
//! ```text
//! cargo run -p wedge-benches --bin summary [RESULTS_DIR]
//! ```

use std::path::PathBuf;
use std::process::ExitCode;

fn main() -> ExitCode {
    let dir = std::env::args_os().nth(1).map_or_else(wedge_benches::results_dir, PathBuf::from);
    match wedge_benches::accuracy::summary::write_summary(&dir) {
        Ok(()) => {
            println!("wrote {}", dir.join("SUMMARY.md").display());
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}
