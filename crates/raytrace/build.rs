//! Records the git commit the programs are built from, for `--stats`: `WEDGE_GIT_COMMIT` is the
//! full hash, with `-dirty` when tracked files differed from it at build time; it is unset
//! outside a git checkout or without git, and the record then says `null`.

use std::process::Command;

fn git(args: &[&str]) -> Option<String> {
    let out = Command::new("git").args(args).output().ok()?;
    out.status.success().then(|| String::from_utf8_lossy(&out.stdout).trim().to_owned())
}

fn main() {
    let Some(commit) = git(&["rev-parse", "HEAD"]) else {
        return;
    };
    // Run again when HEAD moves (a commit, a checkout: HEAD, the branch's ref, the packed refs
    // and the index are what git rewrites) or a source of the workspace changes (cargo scans a
    // directory for any modified file), so that the hash and the `-dirty` mark stay true.
    let mut watched = vec!["HEAD".to_owned(), "index".to_owned(), "packed-refs".to_owned()];
    watched.extend(git(&["symbolic-ref", "-q", "HEAD"]));
    for file in &watched {
        if let Some(path) = git(&["rev-parse", "--path-format=absolute", "--git-path", file]) {
            println!("cargo:rerun-if-changed={path}");
        }
    }
    for source in ["../../crates", "../../Cargo.toml", "../../Cargo.lock"] {
        println!("cargo:rerun-if-changed={source}");
    }
    let status = git(&["status", "--porcelain", "--untracked-files=no"]);
    let dirty = if status.is_some_and(|s| !s.is_empty()) { "-dirty" } else { "" };
    println!("cargo:rustc-env=WEDGE_GIT_COMMIT={commit}{dirty}");
}
