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

/// `stale` names every file that is missing or differs, and only those.
#[test]
fn stale_names_missing_and_changed_files() {
    let root = ga_codegen::workspace_root();
    let files = ga_codegen::render_all(&root).expect("the generator runs");
    let dir = std::env::temp_dir().join(format!("ga-codegen-stale-{}", std::process::id()));
    let (first, second) = (&files[0], &files[1]);
    for (path, text) in [first, second] {
        let full = dir.join(path);
        std::fs::create_dir_all(full.parent().unwrap()).unwrap();
        std::fs::write(&full, text).unwrap();
    }
    // The second file changed by one character.
    std::fs::write(dir.join(&second.0), format!("{} ", second.1)).unwrap();
    let stale = ga_codegen::stale(&dir, &files);
    std::fs::remove_dir_all(&dir).unwrap();
    assert!(!stale.contains(&first.0));
    assert!(stale.contains(&second.0));
    assert_eq!(stale.len(), files.len() - 1);
}
