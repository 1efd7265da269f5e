//! The NumPy `.npy` format (version 1.0 written; 1.0, 2.0 and 3.0 read), for plain
//! little-endian, C-ordered arrays.
//!
//! A file is the magic `\x93NUMPY`, a two-byte version, the header length (2 bytes in 1.0, 4
//! in 2.0 and 3.0), a header that is a Python dict literal such as
//! `{'descr': '<f4', 'fortran_order': False, 'shape': (3, 6), }` padded with spaces to a
//! multiple of 64 bytes and ending in `\n`, then the values.
//!
//! ```
//! use render::output::npy;
//!
//! let mut bytes = Vec::new();
//! npy::write(&mut bytes, &[2, 3], [1.0f64, 2.0, 3.0, 4.0, 5.0, 6.0]).unwrap();
//! let array = npy::read_f64_matrix(&bytes, 3).unwrap();
//! assert_eq!(array.rows, 2);
//! assert_eq!(array.values[4], 5.0);
//! ```

use std::io::{self, Read, Write};

use intersect::Real;

const MAGIC: &[u8; 6] = b"\x93NUMPY";

/// A value type that `.npy` files can hold.
pub trait Element: Copy {
    /// The NumPy type string (`'<f4'`, ...).
    const DESCR: &'static str;
    /// Appends the value's little-endian bytes.
    fn put(self, out: &mut Vec<u8>);
}

macro_rules! element {
    ($t:ty, $descr:literal) => {
        impl Element for $t {
            const DESCR: &'static str = $descr;
            #[inline]
            fn put(self, out: &mut Vec<u8>) {
                out.extend_from_slice(&self.to_le_bytes());
            }
        }
    };
}
element!(u8, "|u1");
element!(u32, "<u4");
element!(f32, "<f4");
element!(f64, "<f8");

/// Writes an array of the given `shape` (C order: the last index varies fastest).
///
/// # Errors
///
/// The writer's I/O errors; [`io::ErrorKind::InvalidInput`] if the number of values is not
/// the product of the shape.
pub fn write<T: Element, W: Write>(
    w: &mut W,
    shape: &[usize],
    values: impl IntoIterator<Item = T>,
) -> io::Result<()> {
    write_header::<T, W>(w, shape)?;
    let expected: usize = shape.iter().product();
    let mut count = 0usize;
    let mut buf = Vec::with_capacity(1 << 16);
    for v in values {
        v.put(&mut buf);
        count += 1;
        if buf.len() >= (1 << 16) - 16 {
            w.write_all(&buf)?;
            buf.clear();
        }
    }
    w.write_all(&buf)?;
    if count != expected {
        return Err(io::Error::new(
            io::ErrorKind::InvalidInput,
            format!("npy: {count} values for shape {shape:?}"),
        ));
    }
    Ok(())
}

/// Writes the header of an array of `T` with the given `shape`: the values, little-endian in
/// C order, follow it (for arrays written a piece at a time).
///
/// # Errors
///
/// The writer's I/O errors; [`io::ErrorKind::InvalidInput`] for a shape too long for a
/// version 1.0 header.
pub fn write_header<T: Element, W: Write>(w: &mut W, shape: &[usize]) -> io::Result<()> {
    let dims: Vec<String> = shape.iter().map(usize::to_string).collect();
    // A one-element tuple needs its trailing comma in Python.
    let shape_text =
        if dims.len() == 1 { format!("({},)", dims[0]) } else { format!("({})", dims.join(", ")) };
    let mut header =
        format!("{{'descr': '{}', 'fortran_order': False, 'shape': {shape_text}, }}", T::DESCR);
    // Pad so that the data starts at a multiple of 64 bytes (magic + version + u16 length = 10).
    let unpadded = 10 + header.len() + 1;
    header.extend(std::iter::repeat_n(' ', unpadded.next_multiple_of(64) - unpadded));
    header.push('\n');
    let len = u16::try_from(header.len())
        .map_err(|_| io::Error::new(io::ErrorKind::InvalidInput, "npy header too long"))?;
    w.write_all(MAGIC)?;
    w.write_all(&[1, 0])?;
    w.write_all(&len.to_le_bytes())?;
    w.write_all(header.as_bytes())
}

/// Why an `.npy` array could not be read.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum NpyError {
    /// The data does not start with the `.npy` magic.
    #[error("not a NumPy .npy file")]
    NotNpy,
    /// A format version other than 1.0, 2.0 or 3.0.
    #[error("unsupported .npy format version {0}.{1}")]
    Version(u8, u8),
    /// The file ends inside the header.
    #[error("the .npy header is truncated")]
    TruncatedHeader,
    /// The header is not the expected dict.
    #[error("malformed .npy header: {0}")]
    Header(String),
    /// An element type other than little-endian float32 or float64, as written in the file
    /// (quoted as messages quote the header: escaped and cut short).
    #[error("unsupported dtype '{0}': expected little-endian float32 ('<f4') or float64 ('<f8')")]
    Dtype(String),
    /// The array is stored in Fortran (column-major) order.
    #[error("the array is in Fortran order: expected C order")]
    FortranOrder,
    /// The array's shape is not `(N, columns)` for an accepted number of columns.
    #[error("array shape {found}: expected {expected}")]
    Shape {
        /// The shape found, as written in the header (escaped and cut short).
        found: String,
        /// The accepted shapes, e.g. `(N, 6)` or `(N, 6) or (N, 8)`.
        expected: String,
    },
    /// The data is shorter or longer than the shape says.
    #[error("the array data is {found} bytes, but shape and dtype call for {expected}")]
    Length {
        /// Bytes the header promises.
        expected: usize,
        /// Bytes present.
        found: usize,
    },
}

/// A two-dimensional floating-point array read from `.npy`, widened to `f64` (exactly).
#[derive(Clone, Debug, PartialEq)]
pub struct Matrix {
    /// Number of rows.
    pub rows: usize,
    /// Number of columns.
    pub columns: usize,
    /// The values in C order (`values[r * columns + c]`).
    pub values: Vec<f64>,
    /// Whether the file held `f32` (`'<f4'`) rather than `f64`.
    pub was_f32: bool,
}

/// Reads an `(N, columns)` little-endian float32 or float64 array in C order.
///
/// # Errors
///
/// [`NpyError`] naming what is wrong: not `.npy`, another dtype (integers, big-endian,
/// ...), Fortran order, another shape, or data shorter or longer than the shape.
pub fn read_f64_matrix(bytes: &[u8], columns: usize) -> Result<Matrix, NpyError> {
    read_f64_matrix_of(bytes, &[columns])
}

/// Reads an `(N, c)` array as [`read_f64_matrix`] does, for any `c` of `columns` (the
/// matrix's `columns` says which).
///
/// # Errors
///
/// As [`read_f64_matrix`]; a shape error names every accepted shape.
pub fn read_f64_matrix_of(bytes: &[u8], columns: &[usize]) -> Result<Matrix, NpyError> {
    let mut data = bytes;
    let (info, _) = read_header(&mut data, columns)?;
    let expected =
        info.data_bytes().ok_or(NpyError::Length { expected: usize::MAX, found: data.len() })?;
    if data.len() != expected {
        return Err(NpyError::Length { expected, found: data.len() });
    }
    let mut values = Vec::new();
    decode(data, info.was_f32, &mut values);
    Ok(Matrix { rows: info.rows, columns: info.columns, values, was_f32: info.was_f32 })
}

/// What the header of an `(N, columns)` float32 or float64 array says.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Info {
    /// Number of rows.
    pub rows: usize,
    /// Number of columns.
    pub columns: usize,
    /// Whether the values are `f32` (`'<f4'`) rather than `f64`.
    pub was_f32: bool,
}

impl Info {
    /// The bytes of the values that follow the header (`None` if beyond `usize`).
    #[must_use]
    pub fn data_bytes(&self) -> Option<usize> {
        let size = if self.was_f32 { 4 } else { 8 };
        self.rows.checked_mul(self.columns)?.checked_mul(size)
    }
}

/// The longest header read (NumPy itself refuses more than 10,000 bytes by default).
const MAX_HEADER: u32 = 1 << 20;

/// Reads the header of an `(N, c)` little-endian float32 or float64 array in C order, for any
/// `c` of `columns`, from `r`, which is left at the first value; returns it with the number of
/// bytes read (magic, version, length and header: where the values start).
///
/// # Errors
///
/// As [`read_f64_matrix`], except the data length, which the caller checks.
pub fn read_header(r: &mut impl Read, columns: &[usize]) -> Result<(Info, usize), NpyError> {
    let mut start = [0u8; 8];
    if read_up_to(r, &mut start) < 8 || &start[..6] != MAGIC {
        return Err(NpyError::NotNpy);
    }
    let (major, minor) = (start[6], start[7]);
    let mut len = [0u8; 4];
    let (header_len, prefix) = match major {
        1 if read_up_to(r, &mut len[..2]) == 2 => {
            (u32::from(u16::from_le_bytes([len[0], len[1]])), 10)
        }
        2 | 3 if read_up_to(r, &mut len) == 4 => (u32::from_le_bytes(len), 12),
        1..=3 => return Err(NpyError::TruncatedHeader),
        _ => return Err(NpyError::Version(major, minor)),
    };
    if header_len > MAX_HEADER {
        return Err(NpyError::Header(format!("the header is {header_len} bytes, more than 1 MiB")));
    }
    let mut header = Vec::new();
    r.take(u64::from(header_len))
        .read_to_end(&mut header)
        .map_err(|_| NpyError::TruncatedHeader)?;
    if header.len() != header_len as usize {
        return Err(NpyError::TruncatedHeader);
    }
    let header = std::str::from_utf8(&header)
        .map_err(|_| NpyError::Header("the header is not text".into()))?;
    let fields = Header::parse(header)?;

    let was_f32 = match fields.descr.as_str() {
        "<f4" => true,
        "<f8" => false,
        other => return Err(NpyError::Dtype(shown(other))),
    };
    if fields.fortran_order {
        return Err(NpyError::FortranOrder);
    }
    let shape_error = || {
        let shapes: Vec<String> = columns.iter().map(|c| format!("(N, {c})")).collect();
        NpyError::Shape { found: fields.shape_text.clone(), expected: shapes.join(" or ") }
    };
    let [rows, cols] = fields.shape[..] else { return Err(shape_error()) };
    if !columns.contains(&cols) {
        return Err(shape_error());
    }
    Ok((Info { rows, columns: cols, was_f32 }, prefix + header_len as usize))
}

/// Reads into `buf` until it is full or the reader ends (or fails); returns the bytes read.
fn read_up_to(r: &mut impl Read, buf: &mut [u8]) -> usize {
    let mut n = 0;
    while n < buf.len() {
        match r.read(&mut buf[n..]) {
            Ok(0) => break,
            Ok(k) => n += k,
            Err(e) if e.kind() == io::ErrorKind::Interrupted => {}
            Err(_) => break,
        }
    }
    n
}

/// Appends the little-endian `f32` (`was_f32`) or `f64` values of `data` to `out` in `V`'s
/// precision: exactly where `V` holds them (`f32` into `f32` or `f64`), else rounded to
/// nearest (`f64` into `f32`).
///
/// # Panics
///
/// If `data` is not a whole number of values.
pub fn decode<V: Real>(data: &[u8], was_f32: bool, out: &mut Vec<V>) {
    if was_f32 {
        assert!(data.len().is_multiple_of(4), "not whole f32 values");
        out.extend(
            data.chunks_exact(4)
                .map(|c| V::from_f64(f64::from(f32::from_le_bytes(c.try_into().expect("4"))))),
        );
    } else {
        assert!(data.len().is_multiple_of(8), "not whole f64 values");
        out.extend(
            data.chunks_exact(8).map(|c| V::from_f64(f64::from_le_bytes(c.try_into().expect("8")))),
        );
    }
}

/// The three keys of a `.npy` header.
struct Header {
    descr: String,
    fortran_order: bool,
    shape: Vec<usize>,
    shape_text: String,
}

impl Header {
    /// Parses `{'descr': '<f8', 'fortran_order': False, 'shape': (3, 6), }`: a dict literal with
    /// exactly these keys, in any order, single- or double-quoted.
    fn parse(text: &str) -> Result<Self, NpyError> {
        let bad = |why: &str| NpyError::Header(why.to_string());
        let body = text
            .trim()
            .strip_prefix('{')
            .and_then(|t| t.strip_suffix('}'))
            .ok_or_else(|| bad("expected a {...} dict"))?;
        let (mut descr, mut fortran, mut shape) = (None, None, None);
        let mut rest = body.trim_start();
        while !rest.is_empty() {
            let (key, after) = quoted(rest).ok_or_else(|| bad("expected a quoted key"))?;
            let after = after.trim_start().strip_prefix(':').ok_or_else(|| bad("expected ':'"))?;
            let after = after.trim_start();
            let after = match key {
                "descr" => {
                    let (v, a) = quoted(after).ok_or_else(|| bad("descr is not a string"))?;
                    descr = Some(v.to_string());
                    a
                }
                "fortran_order" => {
                    let (v, a) = if let Some(a) = after.strip_prefix("False") {
                        (false, a)
                    } else if let Some(a) = after.strip_prefix("True") {
                        (true, a)
                    } else {
                        return Err(bad("fortran_order is not True or False"));
                    };
                    fortran = Some(v);
                    a
                }
                "shape" => {
                    let inner =
                        after.strip_prefix('(').ok_or_else(|| bad("shape is not a tuple"))?;
                    let close = inner.find(')').ok_or_else(|| bad("shape is not a tuple"))?;
                    let dims = inner[..close]
                        .split(',')
                        .map(str::trim)
                        .filter(|d| !d.is_empty())
                        .map(|d| d.parse::<usize>().map_err(|_| bad("shape has a bad dimension")))
                        .collect::<Result<Vec<_>, _>>()?;
                    shape = Some((dims, shown(&format!("({})", &inner[..close]))));
                    &inner[close + 1..]
                }
                other => return Err(bad(&format!("unexpected key '{}'", shown(other)))),
            };
            let after = after.trim_start();
            rest = match after.strip_prefix(',') {
                Some(a) => a.trim_start(),
                None if after.is_empty() => after,
                None => return Err(bad("expected ',' between entries")),
            };
        }
        let (shape, shape_text) = shape.ok_or_else(|| bad("no 'shape' key"))?;
        Ok(Self {
            descr: descr.ok_or_else(|| bad("no 'descr' key"))?,
            fortran_order: fortran.ok_or_else(|| bad("no 'fortran_order' key"))?,
            shape,
            shape_text,
        })
    }
}

/// Header text as quoted in a message: at most [`SHOWN_CHARS`] characters (then `...`), control
/// characters escaped (`\n`, `\u{1b}`), so that a message stays one short printable line
/// whatever the file holds.
fn shown(text: &str) -> String {
    let mut out = String::new();
    for c in text.chars().take(SHOWN_CHARS) {
        if c.is_control() {
            out.extend(c.escape_default());
        } else {
            out.push(c);
        }
    }
    if text.chars().nth(SHOWN_CHARS).is_some() {
        out.push_str("...");
    }
    out
}

/// The most characters of the file's text that a message quotes.
const SHOWN_CHARS: usize = 40;

/// A leading `'...'` or `"..."` string and the text after it.
fn quoted(text: &str) -> Option<(&str, &str)> {
    let q = text.chars().next().filter(|&c| c == '\'' || c == '"')?;
    let inner = &text[1..];
    let end = inner.find(q)?;
    Some((&inner[..end], &inner[end + 1..]))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A `.npy` file as NumPy 1.26 writes `np.arange(6, dtype='<f4').reshape(2, 3)`, bytes
    /// spelt out by hand from the format description: an independent check of the writer.
    fn numpy_written_f4_2x3() -> Vec<u8> {
        let mut v = b"\x93NUMPY\x01\x00\x76\x00".to_vec();
        let mut h = "{'descr': '<f4', 'fortran_order': False, 'shape': (2, 3), }".to_string();
        while !(10 + h.len() + 1).is_multiple_of(64) {
            h.push(' ');
        }
        h.push('\n');
        assert_eq!(h.len(), 0x76);
        v.extend_from_slice(h.as_bytes());
        for x in 0..6 {
            v.extend_from_slice(&(x as f32).to_le_bytes());
        }
        v
    }

    #[test]
    fn writer_matches_numpy_layout() {
        let mut out = Vec::new();
        write(&mut out, &[2, 3], (0..6).map(|x| x as f32)).unwrap();
        assert_eq!(out, numpy_written_f4_2x3());
        assert_eq!((out.len() - 24) % 64, 0);
    }

    #[test]
    fn reads_f32_and_f64_and_other_versions() {
        let m = read_f64_matrix(&numpy_written_f4_2x3(), 3).unwrap();
        assert_eq!((m.rows, m.columns, m.was_f32), (2, 3, true));
        assert_eq!(m.values, vec![0.0, 1.0, 2.0, 3.0, 4.0, 5.0]);

        let mut out = Vec::new();
        write(&mut out, &[1, 2], [0.1f64, -2.5]).unwrap();
        let m = read_f64_matrix(&out, 2).unwrap();
        assert_eq!(m.values, vec![0.1, -2.5]);
        assert!(!m.was_f32);

        // Version 2.0: four-byte header length, double quotes, keys reordered.
        let header = "{\"shape\": (1, 2), \"fortran_order\": False, \"descr\": \"<f8\"}\n";
        let mut v2 = b"\x93NUMPY\x02\x00".to_vec();
        v2.extend_from_slice(&(header.len() as u32).to_le_bytes());
        v2.extend_from_slice(header.as_bytes());
        v2.extend_from_slice(&1.5f64.to_le_bytes());
        v2.extend_from_slice(&(-3.0f64).to_le_bytes());
        assert_eq!(read_f64_matrix(&v2, 2).unwrap().values, vec![1.5, -3.0]);

        let mut empty = Vec::new();
        write::<f64, _>(&mut empty, &[0, 6], []).unwrap();
        assert_eq!(read_f64_matrix(&empty, 6).unwrap().rows, 0);
    }

    #[test]
    fn bad_arrays_are_named() {
        let good = numpy_written_f4_2x3();
        assert_eq!(read_f64_matrix(b"hello world", 3), Err(NpyError::NotNpy));
        assert_eq!(read_f64_matrix(&good[..20], 3), Err(NpyError::TruncatedHeader));
        assert_eq!(
            read_f64_matrix(&good[..good.len() - 1], 3),
            Err(NpyError::Length { expected: 24, found: 23 })
        );
        assert_eq!(
            read_f64_matrix(&good, 6),
            Err(NpyError::Shape { found: "(2, 3)".into(), expected: "(N, 6)".into() })
        );
        let swap = |from: &str, to: &str| {
            assert_eq!(from.len(), to.len());
            let mut v = good.clone();
            let at = v.windows(from.len()).position(|w| w == from.as_bytes()).unwrap();
            v[at..at + from.len()].copy_from_slice(to.as_bytes());
            v
        };
        // Same-length substitutions keep the header length valid.
        assert_eq!(read_f64_matrix(&swap("<f4", "<i4"), 3), Err(NpyError::Dtype("<i4".into())));
        assert_eq!(read_f64_matrix(&swap("<f4", ">f4"), 3), Err(NpyError::Dtype(">f4".into())));
        assert_eq!(read_f64_matrix(&swap("False", "True "), 3), Err(NpyError::FortranOrder));
        assert!(matches!(
            read_f64_matrix(&swap("(2, 3)", "(6,)  "), 3),
            Err(NpyError::Shape { .. })
        ));
        let mut v9 = good.clone();
        v9[6] = 9;
        assert_eq!(read_f64_matrix(&v9, 3), Err(NpyError::Version(9, 0)));
    }

    #[test]
    fn messages_quote_the_header_on_one_short_line() {
        let with_header = |header: &str| {
            let mut v = b"\x93NUMPY\x01\x00".to_vec();
            v.extend_from_slice(&(header.len() as u16).to_le_bytes());
            v.extend_from_slice(header.as_bytes());
            read_f64_matrix(&v, 6).unwrap_err().to_string()
        };
        // Found by the fuzzer: a line break in a key split the message in two.
        let e = with_header("{'descr': '<f8', 'fortran_order': False, 'sh\npe': (1, 6), }");
        assert_eq!(e, "malformed .npy header: unexpected key 'sh\\npe'");
        let e = with_header("{'descr': '<f\u{1b}[2J', 'fortran_order': False, 'shape': (1, 6)}");
        assert!(e.starts_with("unsupported dtype '<f\\u{1b}[2J': expected"), "{e}");
        let long = "1, ".repeat(300);
        let e = with_header(&format!(
            "{{'descr': '<f8', 'fortran_order': False, 'shape': (\n{long})}}"
        ));
        let shape = format!("(\\n{}...", &long[..38]);
        assert_eq!(e, format!("array shape {shape}: expected (N, 6)"));
    }

    #[test]
    fn write_checks_the_value_count() {
        let mut out = Vec::new();
        let e = write(&mut out, &[2, 2], [1u32, 2, 3]).unwrap_err();
        assert_eq!(e.kind(), io::ErrorKind::InvalidInput);
    }
}
