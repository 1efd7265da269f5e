//! `raycast`'s RAYS and HITS files, read and written a chunk of rows at a time, so that
//! arrays larger than memory trace in memory bounded by the chunk, not by the array.
//!
//! # Layouts
//!
//! | layout | RAYS | HITS |
//! |---|---|---|
//! | NumPy `.npy` | float32 or float64, `(N, 6)` or `(N, 8)` | float64 `(N, columns)` |
//! | NumPy `.npz` | one array (or several, one of them named `rays`), stored or deflated as `np.savez` and `np.savez_compressed` write them | one array, `hits`, deflated at level 1 (`np.load(path)["hits"]`) |
//! | raw | `.f32` or `.f64`: little-endian rows of 6 or 8 values, no header | `.f64`: little-endian rows of float64 |
//!
//! RAYS are recognised by their extension (`.f32`, `.f64`) or else by their first bytes
//! (`PK` for a zip archive, `\x93NUMPY`), so a `.npy` file under another name still reads.
//! HITS are chosen by extension ([`HitsLayout::from_path`]). The `.npz` written is the same
//! for the same hits: its member's date is the zip format's earliest, 1980-01-01.

use std::borrow::Cow;
use std::fs::File;
use std::io::{self, BufReader, Read, Seek, Write};
use std::path::Path;

use intersect::Real;
use zip::ZipArchive;
use zip::write::{SimpleFileOptions, ZipWriter};

use crate::output::npy::{self, NpyError};

/// Rays read at a time (and hits written at a time) by a chunked trace: 16 MiB of `f64` rays
/// with bounds, up to 20 MiB of hits.
pub const RAYS_PER_CHUNK: usize = 1 << 18;

/// The member of a `.npz` RAYS archive with several arrays that holds the rays.
const RAYS_MEMBER: &str = "rays.npy";

/// The member of a `.npz` HITS archive.
const HITS_MEMBER: &str = "hits.npy";

/// Why a RAYS file cannot be read.
#[derive(Debug, thiserror::Error)]
pub enum RaysError {
    /// Missing, not a regular file, or unreadable.
    #[error(transparent)]
    Input(#[from] scene::input::InputError),
    /// The `.npy` array (or the `.npz` member) is not rays.
    #[error(transparent)]
    Npy(#[from] NpyError),
    /// Neither `.npy` nor `.npz`, nor named as raw values.
    #[error(
        "not a NumPy .npy or .npz file (raw float32 or float64 rays need a .f32 or .f64 \
         extension)"
    )]
    Unknown,
    /// The zip archive is damaged, or its member cannot be decompressed.
    #[error("the .npz archive cannot be read: {0}")]
    Zip(String),
    /// No member holds the rays without doubt.
    #[error("the .npz archive holds {0}: expected one array, or one named 'rays'")]
    Members(String),
    /// A raw file that is not whole rows.
    #[error("{bytes} bytes is not a whole number of rays of {columns} {element} values")]
    RawLength {
        /// The file's size.
        bytes: u64,
        /// Values per ray.
        columns: usize,
        /// `float32` or `float64`.
        element: &'static str,
    },
    /// `--ray-columns` disagrees with the array's shape.
    #[error("the rays have {found} columns, not the {asked} asked for")]
    Columns {
        /// The array's columns.
        found: usize,
        /// The columns asked for.
        asked: usize,
    },
    /// Reading the values failed (the file shrank, a disk error, a bad deflate stream).
    #[error("reading the rays failed: {0}")]
    Read(io::Error),
}

/// A RAYS file opened and checked: its shape is known and the data has the length the shape
/// calls for. [`RaysFile::rows_reader`] then reads the values.
#[derive(Debug)]
pub struct RaysFile {
    info: npy::Info,
    /// Bytes before the first value (the `.npy` header; 0 for raw values).
    skip: usize,
    source: Source,
}

#[derive(Debug)]
enum Source {
    Plain(File),
    Zip(Box<ZipArchive<BufReader<File>>>, usize),
}

impl RaysFile {
    /// Opens `path` (see the [module documentation](self)) and checks its shape and length.
    /// `columns` is the width of raw rays (6 when `None`); for `.npy` and `.npz` it is checked
    /// against the array's.
    ///
    /// # Errors
    ///
    /// [`RaysError`] saying what is wrong.
    pub fn open(path: &Path, columns: Option<usize>) -> Result<Self, RaysError> {
        let (mut file, len) = scene::input::open_file(path)?;
        let raw = match path.extension().and_then(|e| e.to_str()) {
            Some(e) if e.eq_ignore_ascii_case("f32") => Some(true),
            Some(e) if e.eq_ignore_ascii_case("f64") => Some(false),
            _ => None,
        };
        let read = RaysError::Read;
        let opened = if let Some(was_f32) = raw {
            let columns = columns.unwrap_or(6);
            let element = if was_f32 { "float32" } else { "float64" };
            let row = columns as u64 * if was_f32 { 4 } else { 8 };
            let rows = usize::try_from(len / row).ok().filter(|_| len % row == 0);
            let rows = rows.ok_or(RaysError::RawLength { bytes: len, columns, element })?;
            let info = npy::Info { rows, columns, was_f32 };
            Self { info, skip: 0, source: Source::Plain(file) }
        } else {
            let mut magic = [0u8; 2];
            let got = file.read(&mut magic).map_err(read)?;
            file.rewind().map_err(read)?;
            if got == 2 && &magic == b"PK" {
                Self::open_zip(file)?
            } else {
                let mut r = BufReader::new(&file);
                let (info, skip) = npy::read_header(&mut r, &[6, 8]).map_err(|e| match e {
                    NpyError::NotNpy => RaysError::Unknown,
                    e => e.into(),
                })?;
                drop(r);
                check_length(info, len.saturating_sub(skip as u64))?;
                Self { info, skip, source: Source::Plain(file) }
            }
        };
        if let Some(asked) = columns.filter(|&c| c != opened.info.columns) {
            return Err(RaysError::Columns { found: opened.info.columns, asked });
        }
        Ok(opened)
    }

    fn open_zip(file: File) -> Result<Self, RaysError> {
        let zip_error = |e: zip::result::ZipError| RaysError::Zip(e.to_string());
        let mut archive = ZipArchive::new(BufReader::new(file)).map_err(zip_error)?;
        let names: Vec<String> = archive
            .file_names()
            .map(|n| n.map(Cow::into_owned))
            .collect::<Result<_, _>>()
            .map_err(zip_error)?;
        let index = match names.len() {
            1 => 0,
            _ => names.iter().position(|n| n == RAYS_MEMBER).ok_or_else(|| {
                let count = match names.len() {
                    0 => "no array".to_string(),
                    n => format!("{n} arrays ({})", shown_names(&names)),
                };
                RaysError::Members(count)
            })?,
        };
        let mut member = archive.by_index(index).map_err(zip_error)?;
        let size = member.size();
        let (info, skip) = npy::read_header(&mut member, &[6, 8])?;
        drop(member);
        check_length(info, size.saturating_sub(skip as u64))?;
        Ok(Self { info, skip, source: Source::Zip(Box::new(archive), index) })
    }

    /// The number of rays.
    #[must_use]
    pub const fn rows(&self) -> usize {
        self.info.rows
    }

    /// Values per ray: 6, or 8 with `t_min` and `t_max`.
    #[must_use]
    pub const fn columns(&self) -> usize {
        self.info.columns
    }

    /// Whether the file holds `f32` values (else `f64`).
    #[must_use]
    pub const fn was_f32(&self) -> bool {
        self.info.was_f32
    }

    /// A reader of the rays from the first.
    ///
    /// # Errors
    ///
    /// [`RaysError::Read`] or [`RaysError::Zip`] if the data cannot be reached.
    pub fn rows_reader(&mut self) -> Result<RowReader<'_>, RaysError> {
        let skip = self.skip as u64;
        let data: Box<dyn Read + '_> = match &mut self.source {
            Source::Plain(file) => {
                file.seek(io::SeekFrom::Start(skip)).map_err(RaysError::Read)?;
                Box::new(BufReader::with_capacity(1 << 20, &*file))
            }
            Source::Zip(archive, index) => {
                let mut member =
                    archive.by_index(*index).map_err(|e| RaysError::Zip(e.to_string()))?;
                io::copy(&mut (&mut member).take(skip), &mut io::sink())
                    .map_err(RaysError::Read)?;
                Box::new(member)
            }
        };
        Ok(RowReader { data, info: self.info, left: self.info.rows, bytes: Vec::new() })
    }
}

/// The data after the header must be exactly what the shape calls for.
fn check_length(info: npy::Info, found: u64) -> Result<(), NpyError> {
    let found_usize = usize::try_from(found).unwrap_or(usize::MAX);
    match info.data_bytes() {
        Some(expected) if expected as u64 == found => Ok(()),
        expected => {
            Err(NpyError::Length { expected: expected.unwrap_or(usize::MAX), found: found_usize })
        }
    }
}

/// At most three member names, quoted, for a message.
fn shown_names(names: &[String]) -> String {
    let mut shown: Vec<String> =
        names.iter().take(3).map(|n| format!("'{}'", n.escape_default())).collect();
    if names.len() > 3 {
        shown.push("...".into());
    }
    shown.join(", ")
}

/// Reads the rays of a [`RaysFile`] in chunks, in the precision asked for (see
/// [`npy::decode`]).
pub struct RowReader<'a> {
    data: Box<dyn Read + 'a>,
    info: npy::Info,
    left: usize,
    bytes: Vec<u8>,
}

impl RowReader<'_> {
    /// Replaces `values` with the next rays, at most `max_rows` of them, in `V`'s precision
    /// (`raycast` reads them in its kernel's, as `cast::kernel_ray` would round them);
    /// returns how many (0 once every ray has been read).
    ///
    /// # Errors
    ///
    /// The reader's I/O error, or [`io::ErrorKind::UnexpectedEof`] if the data ends before
    /// the shape says (the file shrank since it was opened).
    pub fn next_rows<V: Real>(
        &mut self,
        max_rows: usize,
        values: &mut Vec<V>,
    ) -> io::Result<usize> {
        let rows = max_rows.min(self.left);
        let size = if self.info.was_f32 { 4 } else { 8 };
        self.bytes.resize(rows * self.info.columns * size, 0);
        self.data.read_exact(&mut self.bytes)?;
        values.clear();
        npy::decode(&self.bytes, self.info.was_f32, values);
        self.left -= rows;
        Ok(rows)
    }
}

/// How HITS are written.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum HitsLayout {
    /// `.npy`, float64.
    Npy,
    /// `.npz` holding `hits`, deflated.
    Npz,
    /// `.f64`: the float64 rows with no header.
    RawF64,
}

impl HitsLayout {
    /// The layout for a path's extension (`.npy`, `.npz`, `.f64`, any case), if any.
    #[must_use]
    pub fn from_path(path: &Path) -> Option<Self> {
        let ext = path.extension()?.to_str()?.to_ascii_lowercase();
        match ext.as_str() {
            "npy" => Some(Self::Npy),
            "npz" => Some(Self::Npz),
            "f64" => Some(Self::RawF64),
            _ => None,
        }
    }
}

/// Writes HITS a chunk of rows at a time in a [`HitsLayout`].
pub struct HitsWriter<W: Write + Seek> {
    sink: Sink<W>,
    /// Values still to come.
    left: usize,
    bytes: Vec<u8>,
}

enum Sink<W: Write + Seek> {
    Plain(W),
    Zip(Box<ZipWriter<W>>),
}

impl<W: Write + Seek> HitsWriter<W> {
    /// Starts an array of `rows` rows of `columns` float64 values in `w`.
    ///
    /// # Errors
    ///
    /// The writer's I/O errors.
    pub fn new(w: W, layout: HitsLayout, rows: usize, columns: usize) -> io::Result<Self> {
        let shape = [rows, columns];
        let sink = match layout {
            HitsLayout::RawF64 => Sink::Plain(w),
            HitsLayout::Npy => {
                let mut w = w;
                npy::write_header::<f64, _>(&mut w, &shape)?;
                Sink::Plain(w)
            }
            HitsLayout::Npz => {
                let mut zip = ZipWriter::new(w);
                // ZIP64 for members that could reach 4 GiB: with a margin for the header and
                // for deflate's worst case, which stores incompressible data a little larger.
                let bytes = (rows as u64).saturating_mul(columns as u64 * 8);
                let options = SimpleFileOptions::default()
                    .compression_method(zip::CompressionMethod::Deflated)
                    .compression_level(Some(1))
                    .large_file(bytes >= 1 << 31);
                zip.start_file(HITS_MEMBER, options)?;
                npy::write_header::<f64, _>(&mut zip, &shape)?;
                Sink::Zip(Box::new(zip))
            }
        };
        Ok(Self { sink, left: rows * columns, bytes: Vec::new() })
    }

    /// Appends whole rows of values.
    ///
    /// # Errors
    ///
    /// The writer's I/O errors; [`io::ErrorKind::InvalidInput`] for more values than the
    /// shape holds.
    pub fn write_rows(&mut self, values: &[f64]) -> io::Result<()> {
        if values.len() > self.left {
            return Err(io::Error::new(io::ErrorKind::InvalidInput, "more hits than rays"));
        }
        self.left -= values.len();
        self.bytes.clear();
        self.bytes.extend(values.iter().flat_map(|v| v.to_le_bytes()));
        match &mut self.sink {
            Sink::Plain(w) => w.write_all(&self.bytes),
            Sink::Zip(zip) => zip.write_all(&self.bytes),
        }
    }

    /// Ends the array (and the archive) and returns the writer, unflushed.
    ///
    /// # Errors
    ///
    /// The writer's I/O errors; [`io::ErrorKind::InvalidInput`] if fewer values were written
    /// than the shape holds.
    pub fn finish(self) -> io::Result<W> {
        if self.left != 0 {
            return Err(io::Error::new(io::ErrorKind::InvalidInput, "fewer hits than rays"));
        }
        match self.sink {
            Sink::Plain(w) => Ok(w),
            Sink::Zip(zip) => Ok(zip.finish()?),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rays(n: usize, columns: usize) -> Vec<f64> {
        (0..n * columns).map(|k| k as f64 * 0.5 - 3.0).collect()
    }

    fn read_all(file: &mut RaysFile, chunk: usize) -> Vec<f64> {
        let mut reader = file.rows_reader().unwrap();
        let (mut all, mut values) = (Vec::new(), Vec::new());
        while reader.next_rows(chunk, &mut values).unwrap() > 0 {
            all.extend_from_slice(&values);
        }
        all
    }

    #[test]
    fn every_layout_reads_back_in_chunks() {
        let dir = tempfile::tempdir().unwrap();
        let values = rays(1000, 8);
        for layout in [HitsLayout::Npy, HitsLayout::Npz, HitsLayout::RawF64] {
            let name = match layout {
                HitsLayout::Npy => "r.npy",
                HitsLayout::Npz => "r.npz",
                HitsLayout::RawF64 => "r.f64",
            };
            let path = dir.path().join(name);
            assert_eq!(HitsLayout::from_path(&path), Some(layout));
            let mut w = HitsWriter::new(File::create(&path).unwrap(), layout, 1000, 8).unwrap();
            for part in values.chunks(8 * 300) {
                w.write_rows(part).unwrap();
            }
            w.finish().unwrap();
            let columns = (layout == HitsLayout::RawF64).then_some(8);
            let mut file = RaysFile::open(&path, columns).unwrap();
            assert_eq!((file.rows(), file.columns(), file.was_f32()), (1000, 8, false));
            assert_eq!(read_all(&mut file, 333), values, "{name}");
        }
    }

    #[test]
    fn raw_f32_and_sniffed_npy() {
        let dir = tempfile::tempdir().unwrap();
        let values = rays(10, 6);
        let raw = dir.path().join("r.F32");
        let bytes: Vec<u8> = values.iter().flat_map(|&v| (v as f32).to_le_bytes()).collect();
        std::fs::write(&raw, &bytes).unwrap();
        let mut file = RaysFile::open(&raw, None).unwrap();
        assert!(file.was_f32());
        assert_eq!(read_all(&mut file, 4), values);
        let e = RaysFile::open(&raw, Some(8)).unwrap_err();
        assert_eq!(e.to_string(), "240 bytes is not a whole number of rays of 8 float32 values");

        let npy_named_dat = dir.path().join("rays.dat");
        let mut out = Vec::new();
        npy::write(&mut out, &[10, 6], values.iter().map(|&v| v as f32)).unwrap();
        std::fs::write(&npy_named_dat, &out).unwrap();
        assert_eq!(read_all(&mut RaysFile::open(&npy_named_dat, None).unwrap(), 7), values);
        let e = RaysFile::open(&npy_named_dat, Some(8)).unwrap_err();
        assert_eq!(e.to_string(), "the rays have 6 columns, not the 8 asked for");

        std::fs::write(&npy_named_dat, b"hello").unwrap();
        let e = RaysFile::open(&npy_named_dat, None).unwrap_err();
        assert!(matches!(e, RaysError::Unknown), "{e}");
        std::fs::write(&npy_named_dat, &out[..out.len() - 1]).unwrap();
        let e = RaysFile::open(&npy_named_dat, None).unwrap_err();
        assert!(matches!(e, RaysError::Npy(NpyError::Length { expected: 240, found: 239 })));
    }

    #[test]
    fn npz_members_are_chosen_or_refused() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("r.npz");
        let write_archive = |members: &[&str], method| {
            let mut zip = ZipWriter::new(File::create(&path).unwrap());
            for (k, name) in members.iter().enumerate() {
                let options = SimpleFileOptions::default().compression_method(method);
                zip.start_file(*name, options).unwrap();
                let mut bytes = Vec::new();
                npy::write(&mut bytes, &[2, 6], (0..12).map(|x| (x + 100 * k) as f64)).unwrap();
                zip.write_all(&bytes).unwrap();
            }
            zip.finish().unwrap();
        };
        let first = |path: &Path| read_all(&mut RaysFile::open(path, None).unwrap(), 1)[0];
        write_archive(&["arr_0.npy"], zip::CompressionMethod::Stored);
        assert_eq!(first(&path), 0.0);
        write_archive(&["t.npy", "rays.npy"], zip::CompressionMethod::Deflated);
        assert_eq!(first(&path), 100.0);
        write_archive(&["a.npy", "b.npy", "c.npy", "d.npy"], zip::CompressionMethod::Stored);
        let e = RaysFile::open(&path, None).unwrap_err();
        assert_eq!(
            e.to_string(),
            "the .npz archive holds 4 arrays ('a.npy', 'b.npy', 'c.npy', ...): expected one \
             array, or one named 'rays'"
        );
        write_archive(&[], zip::CompressionMethod::Stored);
        let e = RaysFile::open(&path, None).unwrap_err();
        assert!(e.to_string().contains("holds no array"), "{e}");
        std::fs::write(&path, b"PK\x03\x04 and then nothing").unwrap();
        let e = RaysFile::open(&path, None).unwrap_err();
        assert!(e.to_string().starts_with("the .npz archive cannot be read: "), "{e}");
    }

    #[test]
    fn the_writer_counts_the_values() {
        let mut w = HitsWriter::new(io::Cursor::new(Vec::new()), HitsLayout::Npy, 2, 4).unwrap();
        w.write_rows(&[0.0; 4]).unwrap();
        assert!(w.write_rows(&[0.0; 8]).is_err());
        assert!(w.finish().is_err());
    }
}
