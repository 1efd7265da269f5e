//! Writing results to files: formats chosen by extension, and files that appear whole or not
//! at all.
//!
//! | extension | format | what is written |
//! |---|---|---|
//! | `.png` | PNG, 8-bit | [`Frame::to_display`]: grey for `alpha` and `depth`, RGB otherwise |
//! | `.jpg`, `.jpeg` | JPEG, quality 95 | the same 8-bit image |
//! | `.exr` | OpenEXR, 32-bit float RGBA | [`Frame::to_float`]: raw values, A = hit |
//! | `.npy` | NumPy array | the raw values ([`crate::frame`]): `alpha` `|u1` `(H, W)`, `depth` `<f4` `(H, W)`, `normal` and `shade` `<f4` `(H, W, 3)`, `prim` `<u4` `(H, W)` |
//!
//! Extensions are matched without regard to case.
//!
//! # Atomic writes
//!
//! [`AtomicFile`] writes into a temporary file (`.NAME.XXXXXX.tmp`, `NAME` cut to 64 bytes so
//! that any destination name fits) in the destination's own directory and renames it over the
//! destination only when everything has been written, so a reader never sees half a file and
//! a failed run leaves nothing behind (the temporary file is removed when the [`AtomicFile`]
//! is dropped). Creating it first also proves the directory is writable: a program should
//! create its outputs before doing the work.
//!
//! A program with several outputs writes each completely ([`AtomicFile::write`],
//! [`ImageOutput::encode`]) and then renames them all with [`commit_all`]: a failure while
//! writing any of them leaves none. Every live temporary file is listed for the process, so
//! that a signal handler can remove them all before exiting ([`remove_temporaries_and_exit`]).
//!
//! ```
//! use render::frame::{Frame, Mode};
//! use render::output::ImageOutput;
//!
//! let dir = tempfile::tempdir()?;
//! let path = dir.path().join("mask.png");
//! let out = ImageOutput::create(&path)?; // checks the extension and the directory now
//! let frame = Frame::new(Mode::Alpha, 4, 3)?; // ... render into it ...
//! out.write(&frame)?;
//! assert_eq!(image::open(&path)?.width(), 4);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

pub mod npy;

use std::fs::File;
use std::io::{self, BufWriter, Write};
use std::path::{Path, PathBuf};
use std::sync::{Mutex, MutexGuard, PoisonError};

use image::ImageFormat;
use image::codecs::jpeg::JpegEncoder;
use tempfile::NamedTempFile;

use crate::frame::{Frame, FrameData, FrameError};

/// JPEG quality (1 to 100): high, since the images are for inspection.
const JPEG_QUALITY: u8 = 95;

/// An output file format.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Format {
    /// PNG, 8 bits per channel.
    Png,
    /// JPEG, 8 bits per channel.
    Jpeg,
    /// OpenEXR, 32-bit float RGBA.
    Exr,
    /// NumPy `.npy`, the raw values.
    Npy,
}

impl Format {
    /// The format for a path's extension (`.png`, `.jpg`, `.jpeg`, `.exr`, `.npy`, any case).
    ///
    /// # Errors
    ///
    /// [`OutputError::UnknownExtension`] for anything else, no extension included.
    pub fn from_path(path: &Path) -> Result<Self, OutputError> {
        let ext = path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase);
        match ext.as_deref() {
            Some("png") => Ok(Self::Png),
            Some("jpg" | "jpeg") => Ok(Self::Jpeg),
            Some("exr") => Ok(Self::Exr),
            Some("npy") => Ok(Self::Npy),
            _ => Err(OutputError::UnknownExtension { path: path.to_path_buf() }),
        }
    }
}

/// Why an output could not be written. Each message is one line naming the file.
#[derive(Debug, thiserror::Error)]
pub enum OutputError {
    /// The extension names no supported format.
    #[error(
        "{}: unknown output format (use a .png, .jpg, .jpeg, .exr or .npy extension)",
        path.display()
    )]
    UnknownExtension {
        /// The path as given.
        path: PathBuf,
    },
    /// The temporary file could not be created: the directory is missing or not writable.
    #[error("{}: cannot write to this location: {}", path.display(), reason(error))]
    Create {
        /// The destination path.
        path: PathBuf,
        /// The operating system's reason (in the message, so not also a `source()`).
        error: io::Error,
    },
    /// Writing or renaming failed.
    #[error("{}: write failed: {}", path.display(), reason(error))]
    Write {
        /// The destination path.
        path: PathBuf,
        /// The operating system's reason (in the message, so not also a `source()`).
        error: io::Error,
    },
    /// The image encoder failed.
    #[error("{}: cannot encode the image: {error}", path.display())]
    Encode {
        /// The destination path.
        path: PathBuf,
        /// The encoder's reason.
        error: image::ImageError,
    },
    /// The image to encode could not be made.
    #[error("{}: {error}", path.display())]
    Frame {
        /// The destination path.
        path: PathBuf,
        /// Why.
        error: FrameError,
    },
}

/// The operating system's reason for an I/O error. `tempfile` appends ` at path "TEMP"`,
/// naming its temporary file, which would only confuse the user: cut it.
fn reason(e: &io::Error) -> String {
    let text = e.to_string();
    match text.rfind(" at path ") {
        Some(i) => text[..i].to_owned(),
        None => text,
    }
}

/// How many bytes of the destination's name the temporary file's name keeps: with the dot
/// before it, the dot after, tempfile's six random characters and `.tmp`, a temporary name is
/// at most 76 bytes, well inside any file system's name limit (255 on Linux) whatever the
/// destination's name.
const TEMP_NAME_BYTES: usize = 64;

/// The temporary file's prefix for a destination named `name`: `.NAME.` with `NAME` cut to
/// [`TEMP_NAME_BYTES`] on a character boundary.
fn temp_prefix(name: &str) -> String {
    let mut end = name.len().min(TEMP_NAME_BYTES);
    while !name.is_char_boundary(end) {
        end -= 1;
    }
    format!(".{}.", &name[..end])
}

/// The temporary files of every [`AtomicFile`] and [`Written`] alive in the process, so that
/// [`remove_temporaries_and_exit`] can remove them from a signal-handling thread. A path is
/// added under the lock together with the file's creation and taken out under the lock
/// together with its rename, so the list and the directory never disagree for another thread.
static LIVE: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

fn live() -> MutexGuard<'static, Vec<PathBuf>> {
    LIVE.lock().unwrap_or_else(PoisonError::into_inner)
}

/// A temporary file's entry in [`LIVE`], taken out when dropped (after the file itself is
/// removed: it is declared after the [`NamedTempFile`] that owns the file).
#[derive(Debug)]
struct Entry {
    temp: PathBuf,
    listed: bool,
}

impl Entry {
    /// Takes the entry out of `list`, which the caller has locked.
    fn unlist(&mut self, list: &mut Vec<PathBuf>) {
        if let Some(i) = list.iter().position(|p| *p == self.temp) {
            list.swap_remove(i);
        }
        self.listed = false;
    }
}

impl Drop for Entry {
    fn drop(&mut self) {
        if self.listed {
            let mut list = live();
            self.unlist(&mut list);
        }
    }
}

/// Removes the temporary file of every [`AtomicFile`] and [`Written`] alive in the process,
/// then exits with `code`: for a thread that handles SIGINT or SIGTERM. The list stays
/// locked until the process has exited, so no other thread can create or commit a file
/// meanwhile: an interrupted run leaves either no output at all or, when the signal came
/// while [`commit_all`] was renaming, every output complete; never a temporary file.
pub fn remove_temporaries_and_exit(code: i32) -> ! {
    let list = live();
    for temp in list.iter() {
        // Already gone (dropped a moment ago) is as good as removed.
        let _ = std::fs::remove_file(temp);
    }
    std::process::exit(code)
}

/// A file that appears at its path only when it is committed (see the
/// [module documentation](self)).
#[derive(Debug)]
pub struct AtomicFile {
    path: PathBuf,
    temp: NamedTempFile,
    entry: Entry,
}

impl AtomicFile {
    /// Creates the temporary file next to `path`.
    ///
    /// # Errors
    ///
    /// [`OutputError::Create`] if the directory does not exist or is not writable.
    pub fn create(path: &Path) -> Result<Self, OutputError> {
        let dir = match path.parent() {
            Some(d) if !d.as_os_str().is_empty() => d,
            _ => Path::new("."),
        };
        let name = path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
        let prefix = temp_prefix(&name);
        let mut builder = tempfile::Builder::new();
        builder.prefix(&prefix).suffix(".tmp");
        // Temporary files are private (0600) by default; the result should get the usual
        // permissions of a new file (0666 less the umask).
        #[cfg(unix)]
        builder.permissions(std::os::unix::fs::PermissionsExt::from_mode(0o666));
        // Created and listed under one lock: a signal handler never misses a temporary.
        let mut list = live();
        let temp = builder
            .tempfile_in(dir)
            .map_err(|error| OutputError::Create { path: path.to_path_buf(), error })?;
        list.push(temp.path().to_path_buf());
        let entry = Entry { temp: temp.path().to_path_buf(), listed: true };
        Ok(Self { path: path.to_path_buf(), temp, entry })
    }

    /// The destination path.
    #[must_use]
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// Writes the contents with `write` and flushes them, without putting the file in place:
    /// [`commit_all`] does that for several files at once.
    ///
    /// # Errors
    ///
    /// [`OutputError::Write`] if writing or flushing fails; the temporary file is removed.
    pub fn write(
        self,
        write: impl FnOnce(&mut BufWriter<&File>) -> io::Result<()>,
    ) -> Result<Written, OutputError> {
        self.write_streamed(|w, fail| write(w).map_err(fail))
    }

    /// Like [`AtomicFile::write`] for work that can also fail for reasons of its own (reading
    /// an input while the output is written a piece at a time): `write`'s error `E` is
    /// returned as it is, while an I/O error of the file is reported by `write` through the
    /// `fail` it is given, which names the file.
    ///
    /// # Errors
    ///
    /// `write`'s error, or the flush's as an [`OutputError::Write`] converted to `E`; the
    /// temporary file is removed.
    pub fn write_streamed<E: From<OutputError>>(
        self,
        write: impl FnOnce(&mut BufWriter<&File>, &WriteFailed) -> Result<(), E>,
    ) -> Result<Written, E> {
        let path = self.path.clone();
        let fail = move |error| OutputError::Write { path: path.clone(), error };
        let mut w = BufWriter::new(self.temp.as_file());
        write(&mut w, &fail)?;
        w.flush().map_err(&fail)?;
        drop(w);
        Ok(Written { path: self.path, temp: self.temp, entry: self.entry })
    }

    /// Writes the contents with `write`, flushes them and renames the file into place,
    /// replacing any file already there.
    ///
    /// # Errors
    ///
    /// [`OutputError::Write`] if writing, flushing or renaming fails; the temporary file is
    /// removed and the destination is left as it was.
    pub fn commit(
        self,
        write: impl FnOnce(&mut BufWriter<&File>) -> io::Result<()>,
    ) -> Result<(), OutputError> {
        commit_all([self.write(write)?])
    }

    /// Encodes `image` as PNG into the file, for [`commit_all`] (diff images and other
    /// pictures that are not a [`Frame`]).
    ///
    /// # Errors
    ///
    /// [`OutputError::Encode`] or [`OutputError::Write`]; the temporary file is removed.
    pub fn write_png(self, image: &image::RgbImage) -> Result<Written, OutputError> {
        self.write_with(
            |w| image.write_to(w, ImageFormat::Png),
            |path, error| OutputError::Encode { path, error },
        )
    }

    /// Like [`AtomicFile::write`] for writers whose error is not an [`io::Error`].
    fn write_with<E>(
        self,
        write: impl FnOnce(&mut BufWriter<&File>) -> Result<(), E>,
        wrap: impl FnOnce(PathBuf, E) -> OutputError,
    ) -> Result<Written, OutputError> {
        let path = self.path.clone();
        let mut failure = None;
        let result = self.write(|w| {
            write(w).map_err(|e| {
                failure = Some(e);
                io::Error::other("encoding failed")
            })
        });
        match failure {
            Some(e) => Err(wrap(path, e)),
            None => result,
        }
    }
}

/// Makes an I/O error of an [`AtomicFile`] an [`OutputError::Write`] naming it.
pub type WriteFailed = dyn Fn(io::Error) -> OutputError;

/// A temporary file written completely, waiting for [`commit_all`] (or [`Written::commit`])
/// to put it in place; dropped, it is removed.
#[derive(Debug)]
pub struct Written {
    path: PathBuf,
    temp: NamedTempFile,
    entry: Entry,
}

impl Written {
    /// The destination path.
    #[must_use]
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// Renames the file into place, replacing any file already there.
    ///
    /// # Errors
    ///
    /// [`OutputError::Write`] if the rename fails; the temporary file is removed.
    pub fn commit(self) -> Result<(), OutputError> {
        commit_all([self])
    }
}

/// Renames every written file into place, in order: the outputs of a run appear together.
/// Write them all first ([`AtomicFile::write`]), so that a failure while writing leaves none.
///
/// A rename within a directory fails only in unusual cases (the destination became a
/// directory meanwhile, the file system went read-only); if one does, the files renamed
/// before it that did not exist before are removed again, and the rest are not renamed.
///
/// # Errors
///
/// [`OutputError::Write`] for the first rename that fails.
pub fn commit_all(files: impl IntoIterator<Item = Written>) -> Result<(), OutputError> {
    let mut files: Vec<Written> = files.into_iter().collect();
    let mut list = live();
    let mut done: Vec<(PathBuf, bool)> = Vec::new();
    let mut failure = None;
    for mut file in files.drain(..) {
        // Unlisted under the lock we hold (its drop would take the lock again).
        file.entry.unlist(&mut list);
        if failure.is_some() {
            // Dropped here: that removes the temporary file.
            continue;
        }
        let existed = file.path.symlink_metadata().is_ok();
        match file.temp.persist(&file.path) {
            Ok(_) => done.push((file.path, existed)),
            Err(e) => failure = Some(OutputError::Write { path: file.path, error: e.error }),
        }
    }
    match failure {
        None => Ok(()),
        Some(e) => {
            for (path, existed) in done {
                if !existed {
                    let _ = std::fs::remove_file(path);
                }
            }
            Err(e)
        }
    }
}

/// An image file about to be written: its format is known and its directory writable.
#[derive(Debug)]
pub struct ImageOutput {
    file: AtomicFile,
    format: Format,
}

impl ImageOutput {
    /// Checks the extension, then creates the temporary file (see [`AtomicFile::create`]).
    ///
    /// # Errors
    ///
    /// [`OutputError::UnknownExtension`] or [`OutputError::Create`].
    pub fn create(path: &Path) -> Result<Self, OutputError> {
        let format = Format::from_path(path)?;
        Ok(Self { file: AtomicFile::create(path)?, format })
    }

    /// The format chosen by the extension.
    #[must_use]
    pub const fn format(&self) -> Format {
        self.format
    }

    /// The destination path.
    #[must_use]
    pub fn path(&self) -> &Path {
        self.file.path()
    }

    /// Encodes `frame` in the file's format and puts the file in place.
    ///
    /// # Errors
    ///
    /// [`OutputError`]: the image cannot be allocated, encoded or written.
    pub fn write(self, frame: &Frame) -> Result<(), OutputError> {
        self.encode(frame)?.commit()
    }

    /// Encodes `frame` in the file's format into the temporary file, for [`commit_all`].
    ///
    /// # Errors
    ///
    /// [`OutputError`]: the image cannot be allocated, encoded or written.
    pub fn encode(self, frame: &Frame) -> Result<Written, OutputError> {
        let path = self.file.path().to_path_buf();
        let frame_error = |error| OutputError::Frame { path: path.clone(), error };
        let encode = |path, error| OutputError::Encode { path, error };
        match self.format {
            Format::Png => {
                let img = frame.to_display().map_err(frame_error)?;
                self.file.write_with(|w| img.write_to(w, ImageFormat::Png), encode)
            }
            Format::Jpeg => {
                let img = frame.to_display().map_err(frame_error)?;
                self.file.write_with(
                    |w| img.write_with_encoder(JpegEncoder::new_with_quality(w, JPEG_QUALITY)),
                    encode,
                )
            }
            Format::Exr => {
                let img = image::DynamicImage::from(frame.to_float().map_err(frame_error)?);
                self.file.write_with(|w| img.write_to(w, ImageFormat::OpenExr), encode)
            }
            Format::Npy => self.file.write(|w| write_npy(frame, w)),
        }
    }
}

/// Writes a frame's raw values as `.npy` (shapes in the [module documentation](self)).
///
/// # Errors
///
/// The writer's I/O errors.
pub fn write_npy(frame: &Frame, w: &mut impl Write) -> io::Result<()> {
    let (h, wd) = (frame.height() as usize, frame.width() as usize);
    match frame.data() {
        FrameData::Alpha(v) => npy::write(w, &[h, wd], v.iter().copied()),
        FrameData::Depth(v) => npy::write(w, &[h, wd], v.iter().copied()),
        FrameData::Normal(v) | FrameData::Shade(v) => {
            npy::write(w, &[h, wd, 3], v.iter().flatten().copied())
        }
        FrameData::Prim(v) => npy::write(w, &[h, wd], v.iter().copied()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn files_in(dir: &Path) -> Vec<String> {
        let mut v: Vec<String> = std::fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        v.sort();
        v
    }

    #[test]
    fn formats_by_extension() {
        for (name, f) in [
            ("a.png", Format::Png),
            ("a.PNG", Format::Png),
            ("a.jpg", Format::Jpeg),
            ("dir/a.jpeg", Format::Jpeg),
            ("a.exr", Format::Exr),
            ("a.npy", Format::Npy),
        ] {
            assert_eq!(Format::from_path(Path::new(name)).unwrap(), f, "{name}");
        }
        for name in ["a.gif", "a", "a.png.bak"] {
            let e = Format::from_path(Path::new(name)).unwrap_err();
            assert!(e.to_string().starts_with(&format!("{name}: unknown output format")));
        }
    }

    #[test]
    fn nothing_is_left_behind_without_commit() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("out.png");
        let out = ImageOutput::create(&path).unwrap();
        assert_eq!(files_in(dir.path()).len(), 1, "the temporary file exists meanwhile");
        drop(out);
        assert!(files_in(dir.path()).is_empty());
    }

    #[test]
    fn missing_directory_fails_at_create() {
        let e = ImageOutput::create(Path::new("/nonexistent/dir/x.png")).unwrap_err();
        assert!(matches!(e, OutputError::Create { .. }));
        assert!(e.to_string().starts_with("/nonexistent/dir/x.png: cannot write"), "{e}");
        assert!(!e.to_string().contains(".tmp"), "names the temporary file: {e}");
    }

    #[test]
    fn every_format_round_trips_its_pixels() {
        let dir = tempfile::tempdir().unwrap();
        let frame = Frame::from_data(3, 2, FrameData::Alpha(vec![1, 0, 1, 0, 0, 1])).unwrap();
        for ext in ["png", "jpg", "exr"] {
            let path = dir.path().join(format!("a.{ext}"));
            ImageOutput::create(&path).unwrap().write(&frame).unwrap();
            let img = image::open(&path).unwrap().into_rgba32f();
            assert_eq!(img.dimensions(), (3, 2));
            for (k, &a) in [1u8, 0, 1, 0, 0, 1].iter().enumerate() {
                let v = img.get_pixel(k as u32 % 3, k as u32 / 3).0[0];
                // JPEG is lossy: within a tenth.
                assert!((v - f32::from(a)).abs() < 0.1, "{ext} pixel {k}: {v}");
            }
        }
        let path = dir.path().join("a.npy");
        ImageOutput::create(&path).unwrap().write(&frame).unwrap();
        let bytes = std::fs::read(&path).unwrap();
        assert!(String::from_utf8_lossy(&bytes[..80]).contains("'descr': '|u1'"));
        assert!(String::from_utf8_lossy(&bytes[..80]).contains("'shape': (2, 3)"));
        assert_eq!(&bytes[bytes.len() - 6..], &[1, 0, 1, 0, 0, 1]);
        let mut names = files_in(dir.path());
        names.retain(|n| n.starts_with('.'));
        assert!(names.is_empty(), "temporary files left: {names:?}");
    }

    #[test]
    fn npy_frames_have_the_documented_shapes() {
        let f = Frame::from_data(2, 1, FrameData::Shade(vec![[0.5, 0.25, 1.0], [0.0; 3]])).unwrap();
        let mut bytes = Vec::new();
        write_npy(&f, &mut bytes).unwrap();
        let m = npy::read_f64_matrix(&bytes, 3);
        // (1, 2, 3) is three-dimensional: the two-dimensional reader must refuse it.
        assert!(matches!(m, Err(npy::NpyError::Shape { .. })));
        let text = String::from_utf8_lossy(&bytes[..128]).into_owned();
        assert!(text.contains("'descr': '<f4'") && text.contains("(1, 2, 3)"), "{text}");
        let data: Vec<f32> = bytes[bytes.len() - 24..]
            .chunks_exact(4)
            .map(|c| f32::from_le_bytes(c.try_into().unwrap()))
            .collect();
        assert_eq!(data, vec![0.5, 0.25, 1.0, 0.0, 0.0, 0.0]);
    }

    #[test]
    fn a_name_at_the_file_system_limit_still_gets_a_temporary() {
        let dir = tempfile::tempdir().unwrap();
        // 255 bytes is Linux's NAME_MAX; multi-byte characters test the cut's boundary.
        let name = format!("{}é.npy", "a".repeat(249));
        assert_eq!(name.len(), 255);
        let path = dir.path().join(&name);
        AtomicFile::create(&path).unwrap().commit(|w| w.write_all(b"x")).unwrap();
        assert_eq!(files_in(dir.path()), [name]);
        let prefix = temp_prefix(&format!("{}é", "a".repeat(63)));
        assert_eq!(prefix, format!(".{}.", "a".repeat(63)), "cut before the 2-byte char");
    }

    #[test]
    fn outputs_written_but_not_committed_leave_nothing() {
        let dir = tempfile::tempdir().unwrap();
        let (a, b) = (dir.path().join("a.npy"), dir.path().join("b.json"));
        let first = AtomicFile::create(&a).unwrap().write(|w| w.write_all(b"a")).unwrap();
        let second = AtomicFile::create(&b).unwrap();
        // Other tests run meanwhile: look for these two temporaries only.
        let temps = [first.entry.temp.clone(), second.entry.temp.clone()];
        let listed = |t: &PathBuf| live().contains(t);
        assert!(temps.iter().all(listed), "both temporaries listed");
        let e = second.write(|_| Err(io::Error::other("disk full"))).unwrap_err();
        assert!(e.to_string().starts_with(&format!("{}: write failed", b.display())), "{e}");
        drop(first);
        assert!(files_in(dir.path()).is_empty());
        assert!(!temps.iter().any(listed));
        let first = AtomicFile::create(&a).unwrap().write(|w| w.write_all(b"a")).unwrap();
        let second = AtomicFile::create(&b).unwrap().write(|w| w.write_all(b"b")).unwrap();
        let temps = [first.entry.temp.clone(), second.entry.temp.clone()];
        commit_all([first, second]).unwrap();
        assert_eq!(files_in(dir.path()), ["a.npy", "b.json"]);
        assert!(!temps.iter().any(listed));
    }

    #[test]
    fn a_failed_rename_takes_back_the_new_files_before_it() {
        let dir = tempfile::tempdir().unwrap();
        let (a, b) = (dir.path().join("a.npy"), dir.path().join("b.json"));
        let first = AtomicFile::create(&a).unwrap().write(|w| w.write_all(b"a")).unwrap();
        let second = AtomicFile::create(&b).unwrap().write(|w| w.write_all(b"b")).unwrap();
        let temps = [first.entry.temp.clone(), second.entry.temp.clone()];
        // A directory (not empty) appears where the second output goes: its rename fails.
        std::fs::create_dir(&b).unwrap();
        std::fs::write(b.join("keep"), b"k").unwrap();
        let e = commit_all([first, second]).unwrap_err();
        assert!(e.to_string().starts_with(&format!("{}: write failed", b.display())), "{e}");
        assert_eq!(files_in(dir.path()), ["b.json"]);
        assert_eq!(std::fs::read(b.join("keep")).unwrap(), b"k");
        assert!(!temps.iter().any(|t| live().contains(t)));
    }

    #[cfg(unix)]
    #[test]
    fn written_files_get_ordinary_permissions() {
        use std::os::unix::fs::PermissionsExt;
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("s.json");
        AtomicFile::create(&path).unwrap().commit(|w| w.write_all(b"{}")).unwrap();
        let mode = std::fs::metadata(&path).unwrap().permissions().mode();
        // Readable by others unless the umask forbids it; never private-only by our doing.
        assert_eq!(mode & 0o600, 0o600);
        assert_eq!(std::fs::read(&path).unwrap(), b"{}");
    }
}
