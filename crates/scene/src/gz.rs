//! gzip decompression with a bound on the output.
//!
//! A gzip stream states its decompressed size only modulo 2^32 (and a crafted one lies), so
//! the output is read in chunks, each reserved with `try_reserve`, and the read stops with
//! [`SceneError::OutOfMemory`] as soon as it passes the limit: a "gzip bomb" (a few
//! kilobytes that expand to gigabytes) costs at most the limit, and the limit comes from the
//! memory available ([`memory::decompression_limit`](super::memory::decompression_limit)).
//! Concatenated gzip members are read as one stream, as `gzip -d` does.

use std::io::Read;

use super::SceneError;

/// Bytes decompressed per step.
const CHUNK: usize = 1 << 20;

/// Decompresses the gzip data `bytes` (of the file `name`), refusing output beyond `limit`
/// bytes.
///
/// ```
/// use std::io::Write;
/// let mut gz = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::fast());
/// gz.write_all(&[b'#'; 10_000])?;
/// let gz = gz.finish()?;
/// assert_eq!(scene::gz::gunzip(&gz, 10_000, "a.obj.gz")?.len(), 10_000);
/// let err = scene::gz::gunzip(&gz, 9_999, "a.obj.gz").unwrap_err();
/// assert!(err.to_string().starts_with("a.obj.gz: too large for memory: "));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// # Errors
///
/// [`SceneError::Invalid`] if the data is not gzip or is corrupt or truncated;
/// [`SceneError::OutOfMemory`] beyond `limit` or if the allocator refuses.
pub fn gunzip(bytes: &[u8], limit: u64, name: &str) -> Result<Vec<u8>, SceneError> {
    if !bytes.starts_with(&[0x1f, 0x8b]) {
        return Err(SceneError::invalid(name, "not gzip data (no gzip header)"));
    }
    let mut decoder = flate2::read::MultiGzDecoder::new(bytes);
    let mut out: Vec<u8> = Vec::new();
    let too_large = |needed: u64| SceneError::OutOfMemory {
        file: name.to_owned(),
        needed,
        available: super::memory::available().unwrap_or(limit),
    };
    loop {
        if out.len() as u64 > limit {
            // The trailer's size (modulo 2^32) is a better guess of the whole than the limit.
            let stated = bytes.len().checked_sub(4).map_or(0, |at| {
                u32::from_le_bytes(bytes[at..].try_into().unwrap_or([0; 4])) as u64
            });
            return Err(too_large(stated.max(out.len() as u64)));
        }
        let start = out.len();
        out.try_reserve(CHUNK).map_err(|_| too_large((start + CHUNK) as u64))?;
        out.resize(start + CHUNK, 0);
        let n = loop {
            match decoder.read(&mut out[start..]) {
                Ok(n) => break n,
                Err(e) if e.kind() == std::io::ErrorKind::Interrupted => {}
                Err(e) => {
                    return Err(SceneError::invalid(name, format!("corrupt gzip data: {e}")));
                }
            }
        };
        out.truncate(start + n);
        if n == 0 {
            return Ok(out);
        }
    }
}
