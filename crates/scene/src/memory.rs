//! Memory estimates: a mesh too large for memory is refused before it is parsed, with a
//! clear message, rather than ending in an abort or the out-of-memory killer.
//!
//! The estimate of a run's peak memory is `file size + PEAK_BYTES_PER_TRIANGLE x triangles`,
//! with the triangle count estimated from the file size and the format's least number of
//! bytes per triangle in a typical file ([`bytes_per_triangle`]). [`PEAK_BYTES_PER_TRIANGLE`]
//! covers the loaded mesh, the parser's intermediate data and what a render builds from the
//! mesh (the BVH and a back end's prepared triangles); the README gives the measurements it
//! comes from. The estimate is compared with `MemAvailable` from `/proc/meminfo` (on systems
//! without it, nothing is refused up front, and the large vectors are still reserved with
//! `try_reserve`, so a refusal by the allocator is an error too).

use super::{MeshFormat, SceneError};

/// Peak bytes per triangle of loading a mesh and rendering it, beyond the file's own bytes:
/// the mesh (positions and indices), the BVH and a back end's prepared triangles, which
/// dominate. Measured with `raytrace` on subdivided bunnies (the README's "Loading" section)
/// and rounded up.
pub const PEAK_BYTES_PER_TRIANGLE: u64 = 200;

/// [`Mesh::from_bytes`](super::Mesh::from_bytes) allocates at most this many times the
/// input's size (plus a constant). The densest inputs give about one triangle per input
/// byte: a binary PLY polygon of one-byte indices (a 12-byte triangle, a 36-byte corner
/// normal triple and 4 bytes of the parsed face per byte), an OBJ `f` line of `1 1 1 ...`
/// (one triangle per 2 bytes); glTF output is capped at half this multiple (instancing).
pub const FROM_BYTES_MULTIPLE: u64 = 200;

/// Least bytes per triangle of a typical file of the format, for estimates from a file size.
/// A closed mesh has about half a vertex per triangle. OBJ: a `v` line of full-precision
/// coordinates takes ~40 bytes and an `f` line ~25, so ~45 per triangle; 40 leaves room for
/// shorter numbers. Binary PLY with float coordinates and int indices: 12 bytes per vertex
/// and 13 per face, 19. Binary STL: 50 per facet. glTF with float positions and 16-bit
/// indices: 6 + 6.
#[must_use]
pub fn bytes_per_triangle(format: MeshFormat) -> u64 {
    match format {
        MeshFormat::Obj => 40,
        MeshFormat::Ply => 19,
        MeshFormat::Stl => 50,
        MeshFormat::Gltf | MeshFormat::Glb => 12,
    }
}

/// Estimated peak bytes of loading and rendering a file of `size` (uncompressed) bytes.
#[must_use]
pub fn peak_estimate(format: MeshFormat, size: u64) -> u64 {
    let triangles = size / bytes_per_triangle(format);
    size.saturating_add(triangles.saturating_mul(PEAK_BYTES_PER_TRIANGLE))
}

/// Bytes of memory available (`MemAvailable` in `/proc/meminfo`), if the system says.
#[must_use]
pub fn available() -> Option<u64> {
    let info = std::fs::read_to_string("/proc/meminfo").ok()?;
    parse_meminfo(&info)
}

/// `MemAvailable` in bytes from the text of `/proc/meminfo`.
fn parse_meminfo(info: &str) -> Option<u64> {
    let line = info.lines().find(|l| l.starts_with("MemAvailable:"))?;
    let mut words = line.split_whitespace().skip(1);
    let kib: u64 = words.next()?.parse().ok()?;
    (words.next() == Some("kB")).then_some(kib.saturating_mul(1024))
}

/// [`SceneError::OutOfMemory`] if `needed` bytes exceed the memory available.
///
/// # Errors
///
/// As said; never if the system does not report the memory available.
pub fn check_fits(name: &str, needed: u64) -> Result<(), SceneError> {
    match available() {
        Some(available) if needed > available => {
            Err(SceneError::OutOfMemory { file: name.to_owned(), needed, available })
        }
        _ => Ok(()),
    }
}

/// The largest decompressed size of a file of `format` that fits in the memory available
/// by [`peak_estimate`]; unbounded if the system does not say.
#[must_use]
pub fn decompression_limit(format: MeshFormat) -> u64 {
    let Some(available) = available() else { return u64::MAX };
    let per_byte = 1 + PEAK_BYTES_PER_TRIANGLE / bytes_per_triangle(format);
    available / per_byte
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn meminfo_is_read_in_kilobytes() {
        let info = "MemTotal:       16000000 kB\nMemFree:  100 kB\nMemAvailable:   8000000 kB\n";
        assert_eq!(parse_meminfo(info), Some(8_000_000 * 1024));
        assert_eq!(parse_meminfo("MemTotal: 5 kB\n"), None);
    }

    #[test]
    fn estimates_grow_with_the_size_and_refuse_the_impossible() {
        for f in MeshFormat::ALL {
            assert!(peak_estimate(f, 2_000_000) > peak_estimate(f, 1_000_000));
            assert!(peak_estimate(f, 1_000_000) > 1_000_000);
        }
        if available().is_some() {
            let e = check_fits("x.obj", u64::MAX).unwrap_err().to_string();
            assert!(e.starts_with("x.obj: too large for memory: needs about "), "{e}");
            assert!(e.ends_with(" GB available"), "{e}");
        }
    }
}
