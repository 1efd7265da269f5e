//! Reading input files without surprises: regular files only, never more bytes than the file
//! held when it was opened, and memory reserved up front so that a file too large for memory
//! is an error, not an abort.
//!
//! Why each rule:
//! - A device (`/dev/zero`), a FIFO or a socket has no end, or blocks until a writer appears:
//!   it is refused from its metadata, before it is opened (opening a FIFO blocks).
//! - A directory cannot be read as a file.
//! - The read is bounded by the size the file system reported, so a file that grows while it
//!   is read cannot grow the program's memory without limit.
//! - The buffer is reserved with `try_reserve_exact`, so a refusal by the allocator is an
//!   error naming the file and the size.
//!
//! ```
//! let dir = tempfile::tempdir()?;
//! let path = dir.path().join("a.obj");
//! std::fs::write(&path, "v 0 0 0\n")?;
//! assert_eq!(scene::input::read_file(&path)?, b"v 0 0 0\n");
//! let err = scene::input::read_file(dir.path()).unwrap_err();
//! assert!(err.to_string().ends_with("is a directory, not a file"));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use std::fs::File;
use std::io::{self, Read};
use std::path::{Path, PathBuf};

/// Why an input file could not be read. Each message is one line naming the file.
#[derive(Debug, thiserror::Error)]
pub enum InputError {
    /// The path does not exist.
    #[error("{}: file not found", path.display())]
    NotFound {
        /// The path as given.
        path: PathBuf,
    },
    /// The path exists but is not a regular file.
    #[error("{}: is a {kind}, not a file", path.display())]
    NotAFile {
        /// The path as given.
        path: PathBuf,
        /// `"directory"`, `"character device"`, `"FIFO"`, ...
        kind: &'static str,
    },
    /// The file exists but could not be read.
    #[error("{}: cannot read the file: {source}", path.display())]
    Unreadable {
        /// The path as given.
        path: PathBuf,
        /// The operating system's reason.
        source: io::Error,
    },
    /// Memory for the file's bytes could not be reserved.
    #[error("{}: not enough memory to read the file ({bytes} bytes)", path.display())]
    OutOfMemory {
        /// The path as given.
        path: PathBuf,
        /// The file's size.
        bytes: u64,
    },
}

/// What kind of file system object `meta` describes, for messages; `None` for a regular file.
fn not_a_file(meta: &std::fs::Metadata) -> Option<&'static str> {
    let t = meta.file_type();
    if t.is_file() {
        return None;
    }
    if t.is_dir() {
        return Some("directory");
    }
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt as _;
        if t.is_char_device() {
            return Some("character device");
        }
        if t.is_block_device() {
            return Some("block device");
        }
        if t.is_fifo() {
            return Some("FIFO (named pipe)");
        }
        if t.is_socket() {
            return Some("socket");
        }
    }
    Some("special file")
}

/// Checks that `path` is a regular file (following symbolic links) and returns its size.
///
/// # Errors
///
/// [`InputError::NotFound`], [`InputError::NotAFile`] or [`InputError::Unreadable`].
pub fn regular_file_size(path: &Path) -> Result<u64, InputError> {
    let meta = std::fs::metadata(path).map_err(|source| match source.kind() {
        io::ErrorKind::NotFound => InputError::NotFound { path: path.to_path_buf() },
        _ => InputError::Unreadable { path: path.to_path_buf(), source },
    })?;
    if let Some(kind) = not_a_file(&meta) {
        return Err(InputError::NotAFile { path: path.to_path_buf(), kind });
    }
    Ok(meta.len())
}

/// Opens a regular file for reading and returns it with its size (see the
/// [module documentation](self) for the rules).
///
/// # Errors
///
/// As [`regular_file_size`], and [`InputError::Unreadable`] if opening fails.
pub fn open_file(path: &Path) -> Result<(File, u64), InputError> {
    let len = regular_file_size(path)?;
    let unreadable = |source| InputError::Unreadable { path: path.to_path_buf(), source };
    let file = File::open(path).map_err(unreadable)?;
    Ok((file, len))
}

/// Reads a whole regular file, at most the size it had when opened (see the
/// [module documentation](self)).
///
/// # Errors
///
/// [`InputError`]: missing, not a regular file, unreadable, or too large for memory.
pub fn read_file(path: &Path) -> Result<Vec<u8>, InputError> {
    let (file, len) = open_file(path)?;
    let out_of_memory = || InputError::OutOfMemory { path: path.to_path_buf(), bytes: len };
    let mut bytes = Vec::new();
    bytes
        .try_reserve_exact(usize::try_from(len).map_err(|_| out_of_memory())?)
        .map_err(|_| out_of_memory())?;
    file.take(len)
        .read_to_end(&mut bytes)
        .map_err(|source| InputError::Unreadable { path: path.to_path_buf(), source })?;
    Ok(bytes)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn regular_files_are_read_whole() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("x.bin");
        std::fs::write(&path, [0u8, 1, 2, 3]).unwrap();
        assert_eq!(read_file(&path).unwrap(), [0, 1, 2, 3]);
        assert_eq!(regular_file_size(&path).unwrap(), 4);
    }

    #[test]
    fn missing_files_and_directories_are_named() {
        let dir = tempfile::tempdir().unwrap();
        let missing = dir.path().join("nope.obj");
        let e = read_file(&missing).unwrap_err();
        assert!(matches!(e, InputError::NotFound { .. }));
        assert!(e.to_string().ends_with("nope.obj: file not found"), "{e}");
        let e = read_file(dir.path()).unwrap_err();
        assert!(matches!(e, InputError::NotAFile { kind: "directory", .. }), "{e}");
    }

    #[cfg(unix)]
    #[test]
    fn devices_are_refused_without_reading() {
        // /dev/zero never ends: reading it would fill memory.
        let e = read_file(Path::new("/dev/zero")).unwrap_err();
        assert_eq!(e.to_string(), "/dev/zero: is a character device, not a file");
    }
}
