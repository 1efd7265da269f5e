//! The committed generated files are exactly what the generator writes.

#[test]
fn generated_files_are_up_to_date() {
    let root = ga_codegen::workspace_root();
    let files = ga_codegen::render_all(&root).expect("the generator runs");
    let stale = ga_codegen::stale(&root, &files);
    assert!(
        stale.is_empty(),
        "{} files were different (run `cargo run -p ga-codegen`): {stale:?}",
        stale.len()
    );
}
