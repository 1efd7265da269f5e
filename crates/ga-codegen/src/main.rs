//! `cargo run -p ga-codegen` writes ga's generated files; `-- --check` only compares them.

use std::process::ExitCode;

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let check = match args.as_slice() {
        [] => false,
        [a] if a == "--check" => true,
        _ => {
            eprintln!("error: usage: ga-codegen [--check]");
            return ExitCode::from(2);
        }
    };
    let root = ga_codegen::workspace_root();
    let files = match ga_codegen::render_all(&root) {
        Ok(files) => files,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::FAILURE;
        }
    };
    let stale = ga_codegen::stale(&root, &files);
    if check {
        for path in &stale {
            eprintln!("error: {}: differs from what ga-codegen writes", path.display());
        }
        if stale.is_empty() {
            return ExitCode::SUCCESS;
        }
        eprintln!("error: {} files were different; run `cargo run -p ga-codegen`", stale.len());
        return ExitCode::FAILURE;
    }
    for (path, text) in files.iter().filter(|(p, _)| stale.contains(p)) {
        let full = root.join(path);
        // Write beside the target and rename, so that no file is ever left half-written.
        let tmp = full.with_extension("tmp");
        let result = full
            .parent()
            .map_or(Ok(()), std::fs::create_dir_all)
            .and_then(|()| std::fs::write(&tmp, text))
            .and_then(|()| std::fs::rename(&tmp, &full));
        if let Err(e) = result {
            let _ = std::fs::remove_file(&tmp);
            eprintln!("error: {}: {e}", full.display());
            return ExitCode::FAILURE;
        }
        println!("wrote {}", path.display());
    }
    ExitCode::SUCCESS
}
