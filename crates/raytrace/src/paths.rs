//! The rules for the files a run names, checked before any work (before the mesh is loaded):
//!
//! - No output path may end in a path separator (it names a directory).
//! - No output may be the same file as an input or as another output. "The same file" is the
//!   same device and inode when the path exists (so a symbolic link or a second hard link to
//!   the input is caught), else the same canonical directory and name.
//! - An output path that exists must be a regular file (not a directory, a FIFO, a device).
//! - The `--stats` path must end in `.json` (any case), and a file already there is replaced
//!   only if it is an earlier stats file: a JSON object with the keys `triangles`, `rays` and
//!   `backend` (every version of the programs has written them), at most
//!   [`MAX_STATS_BYTES`] long. Anything else is refused, never overwritten.
//!
//! Naming the same file twice or a wrong extension is a usage error ([`UsageError`], exit
//! status 2); what is found on the file system (a directory, a file that is not a stats
//! file) is an error of the data (status 1).

use std::path::{Path, PathBuf};

use anyhow::bail;

/// A mistake in the command line itself: the programs exit with status 2 for it, as for
/// clap's errors.
#[derive(Debug, thiserror::Error)]
#[error("{0}")]
pub struct UsageError(pub String);

/// Anything larger than this is not a stats file (they are a few hundred bytes).
pub const MAX_STATS_BYTES: u64 = 64 * 1024;

/// The keys an existing file must have to be replaced as an earlier stats file.
pub const STATS_KEYS: [&str; 3] = ["triangles", "rays", "backend"];

/// Identifies a file for "is it the same file": device and inode when it exists.
#[derive(Debug, PartialEq, Eq)]
enum Identity {
    #[cfg(unix)]
    Inode(u64, u64),
    Name(PathBuf),
}

/// `path`'s identity, `None` when there is nothing to compare (its directory does not exist:
/// creating the output fails later with its own message).
fn identity(path: &Path) -> Option<Identity> {
    if let Ok(meta) = std::fs::metadata(path) {
        #[cfg(unix)]
        {
            use std::os::unix::fs::MetadataExt as _;
            return Some(Identity::Inode(meta.dev(), meta.ino()));
        }
        #[cfg(not(unix))]
        {
            let _ = meta;
            return std::fs::canonicalize(path).ok().map(Identity::Name);
        }
    }
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    Some(Identity::Name(std::fs::canonicalize(dir).ok()?.join(path.file_name()?)))
}

/// A file the run names, with its role for messages (`"mesh"`, `"rays"`, `"image"`, ...).
#[derive(Clone, Copy, Debug)]
pub struct Named<'a> {
    /// What the file is to the program.
    pub role: &'static str,
    /// The path as given.
    pub path: &'a Path,
}

/// Checks that no output path ends in a path separator (`out.png/` names a directory, and
/// would fail only when the finished output is renamed).
///
/// # Errors
///
/// [`UsageError`] naming the path.
pub fn check_output_names(outputs: &[Named<'_>]) -> anyhow::Result<()> {
    for out in outputs {
        let text = out.path.as_os_str().to_string_lossy();
        if text.ends_with(std::path::is_separator) {
            return Err(UsageError(format!(
                "{}: ends in a path separator, so it names a directory, not the {} file",
                out.path.display(),
                out.role
            ))
            .into());
        }
    }
    Ok(())
}

/// Checks every output against the inputs and the other outputs, and that an output which
/// exists is a regular file (see the [module documentation](self)).
///
/// # Errors
///
/// [`UsageError`] for an output that is the same file as another named file; a data error
/// for an output that exists and is not a regular file.
pub fn check_outputs(inputs: &[Named<'_>], outputs: &[Named<'_>]) -> anyhow::Result<()> {
    for (k, out) in outputs.iter().enumerate() {
        match scene::input::regular_file_size(out.path) {
            Ok(_) | Err(scene::input::InputError::NotFound { .. }) => {}
            Err(e) => bail!("{e} (the {} is written there)", out.role),
        }
        let Some(id) = identity(out.path) else { continue };
        let others = inputs.iter().chain(&outputs[..k]);
        if let Some(other) = others.into_iter().find(|o| identity(o.path).as_ref() == Some(&id)) {
            return Err(UsageError(format!(
                "{}: the {} would overwrite the {} ({}): choose another path",
                out.path.display(),
                out.role,
                other.role,
                other.path.display()
            ))
            .into());
        }
    }
    Ok(())
}

/// Checks the `--stats` path's extension and what is there already (see the
/// [module documentation](self)); the checks against the other files are
/// [`check_outputs`]'s.
///
/// # Errors
///
/// [`UsageError`] without a `.json` extension; a data error for a directory or another
/// special file, or a file that is not an earlier stats file.
pub fn check_stats_path(path: &Path) -> anyhow::Result<()> {
    let json =
        path.extension().and_then(|e| e.to_str()).is_some_and(|e| e.eq_ignore_ascii_case("json"));
    if !json {
        return Err(UsageError(format!(
            "{}: the stats are written as JSON: use a .json extension",
            path.display()
        ))
        .into());
    }
    let size = match scene::input::regular_file_size(path) {
        Ok(size) => size,
        Err(scene::input::InputError::NotFound { .. }) => return Ok(()),
        Err(e) => bail!("{e} (the stats are written there)"),
    };
    if size > MAX_STATS_BYTES || !is_stats_file(path) {
        bail!(
            "{}: exists and is not a wedge stats file; remove it or choose another path",
            path.display()
        );
    }
    Ok(())
}

/// Whether `path` holds a JSON object with every key of [`STATS_KEYS`].
fn is_stats_file(path: &Path) -> bool {
    let Ok(bytes) = scene::input::read_file(path) else { return false };
    match serde_json::from_slice::<serde_json::Value>(&bytes) {
        Ok(serde_json::Value::Object(map)) => STATS_KEYS.iter().all(|k| map.contains_key(*k)),
        _ => false,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn named<'a>(role: &'static str, path: &'a Path) -> Named<'a> {
        Named { role, path }
    }

    #[test]
    fn an_output_may_not_be_an_input_by_name_or_by_link() {
        let dir = tempfile::tempdir().unwrap();
        let rays = dir.path().join("rays.npy");
        std::fs::write(&rays, b"x").unwrap();
        let mesh = dir.path().join("m.obj");
        let inputs = [named("mesh", &mesh), named("rays", &rays)];
        let e = check_outputs(&inputs, &[named("hits", &rays)]).unwrap_err();
        assert!(e.downcast_ref::<UsageError>().is_some());
        assert!(e.to_string().contains("the hits would overwrite the rays"), "{e}");
        // Through "dir/./rays.npy" and a hard link: the same inode.
        let dotted = dir.path().join(".").join("rays.npy");
        assert!(check_outputs(&inputs, &[named("hits", &dotted)]).is_err());
        let link = dir.path().join("link.npy");
        std::fs::hard_link(&rays, &link).unwrap();
        assert!(check_outputs(&inputs, &[named("hits", &link)]).is_err());
        // Two outputs that do not exist yet, by their canonical directory and name.
        let a = dir.path().join("a.npy");
        let a2 = dir.path().join(".").join("a.npy");
        let e = check_outputs(&inputs, &[named("hits", &a), named("stats", &a2)]).unwrap_err();
        assert!(e.to_string().contains("the stats would overwrite the hits"), "{e}");
        assert!(check_outputs(&inputs, &[named("hits", &a)]).is_ok());
        assert!(check_output_names(&[named("hits", &a)]).is_ok());
        let slash = PathBuf::from("new.npy/");
        let e = check_output_names(&[named("hits", &a), named("stats", &slash)]).unwrap_err();
        assert!(e.to_string().starts_with("new.npy/: ends in a path separator"), "{e}");
        let e = check_outputs(&inputs, &[named("image", dir.path())]).unwrap_err();
        assert!(e.downcast_ref::<UsageError>().is_none());
        assert!(e.to_string().contains("is a directory"), "{e}");
    }

    #[test]
    fn only_earlier_stats_files_are_replaced() {
        let dir = tempfile::tempdir().unwrap();
        let p = |name: &str| dir.path().join(name);
        assert!(check_stats_path(&p("new.JSON")).is_ok());
        let e = check_stats_path(&p("s.npy")).unwrap_err();
        assert!(e.downcast_ref::<UsageError>().is_some(), "{e}");
        std::fs::write(p("old.json"), r#"{"triangles": 2, "rays": 4, "backend": "la"}"#).unwrap();
        assert!(check_stats_path(&p("old.json")).is_ok());
        for (name, text) in [
            ("list.json", "[1, 2]"),
            ("other.json", r#"{"triangles": 2}"#),
            ("text.json", "not json"),
        ] {
            std::fs::write(p(name), text).unwrap();
            let e = check_stats_path(&p(name)).unwrap_err().to_string();
            assert!(
                e.ends_with(
                    "exists and is not a wedge stats file; remove it or choose another path"
                ),
                "{e}"
            );
        }
        std::fs::create_dir(p("d.json")).unwrap();
        assert!(check_stats_path(&p("d.json")).unwrap_err().to_string().contains("directory"));
    }
}
