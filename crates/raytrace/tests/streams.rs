//! `raycast` on arrays traced a chunk at a time: every RAYS and HITS layout gives the same
//! hits, row for row across chunk boundaries, and the process's memory stays bounded by the
//! chunk, not by the array.

use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};
use std::process::Command;

use render::cast::files::{HitsLayout, HitsWriter, RAYS_PER_CHUNK};
use render::output::npy;

/// A square `[-1, 1]^2` at `z = 4`: triangle 0 is its upper-left half (`y > x`), triangle 1
/// the lower-right half.
const SQUARE: &str = "v -1 -1 4\nv 1 -1 4\nv 1 1 4\nv -1 1 4\nf 1 4 3\nf 1 3 2\n";

/// Ray `k`: from `(x, y, 0)` along `(0, 0, 2)`, with `x, y` spread over `[-1.3, 1.3]` by two
/// coprime strides, as `f32` values (so that every layout and precision holds them exactly).
fn ray(k: usize) -> [f32; 6] {
    let x = -1.3 + 2.6 * ((k * 7919) % 1013) as f64 / 1013.0 + 7e-4;
    let y = -1.3 + 2.6 * ((k * 104_729) % 1019) as f64 / 1019.0 + 3e-4;
    [x as f32, y as f32, 0.0, 0.0, 0.0, 2.0]
}

/// Ray `k`'s hit on the square (`t` 2), worked out by hand: `Some(None)` for a miss, `None`
/// where it passes too near an edge or the diagonal to call.
fn expected(k: usize) -> Option<Option<f64>> {
    let [x, y, ..] = ray(k).map(f64::from);
    let margin = x.abs().max(y.abs()) - 1.0;
    if margin.abs() < 1e-4 || (margin < 0.0 && (y - x).abs() < 1e-4) {
        return None;
    }
    Some((margin < 0.0).then_some(if y > x { 0.0 } else { 1.0 }))
}

/// Writes [`SQUARE`] into `dir`.
fn square(dir: &Path) -> PathBuf {
    let obj = dir.join("square.obj");
    std::fs::write(&obj, SQUARE).unwrap();
    obj
}

fn raycast(args: &[&dyn AsRef<std::ffi::OsStr>]) {
    let out = Command::new(env!("CARGO_BIN_EXE_raycast")).args(args).output().unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
}

/// Writes `n` rays as `.npy` float32, streamed (the test's memory does not matter, but this
/// keeps the file's writing quick).
fn write_npy_rays(path: &Path, n: usize) {
    let mut w = BufWriter::new(File::create(path).unwrap());
    npy::write_header::<f32, _>(&mut w, &[n, 6]).unwrap();
    for k in 0..n {
        for v in ray(k) {
            w.write_all(&v.to_le_bytes()).unwrap();
        }
    }
    w.flush().unwrap();
}

/// Writes `n` rays in `layout` (`.npz` as one member; raw `.f64` as rows) with the writer
/// `raycast` writes its hits with.
fn write_rays(path: &Path, layout: HitsLayout, n: usize) {
    let file = BufWriter::new(File::create(path).unwrap());
    let mut w = HitsWriter::new(file, layout, n, 6).unwrap();
    let values: Vec<f64> = (0..n).flat_map(|k| ray(k).map(f64::from)).collect();
    w.write_rows(&values).unwrap();
    w.finish().unwrap().flush().unwrap();
}

/// Reads `(N, 4)` float64 hits back in any layout.
fn read_hits(path: &Path) -> Vec<f64> {
    let bytes = std::fs::read(path).unwrap();
    match path.extension().and_then(|e| e.to_str()) {
        Some("npy") => npy::read_f64_matrix(&bytes, 4).unwrap().values,
        Some("f64") => {
            bytes.chunks_exact(8).map(|c| f64::from_le_bytes(c.try_into().unwrap())).collect()
        }
        _ => {
            let mut archive = zip::ZipArchive::new(File::open(path).unwrap()).unwrap();
            let mut member = archive.by_name("hits.npy").unwrap();
            let mut bytes = Vec::new();
            std::io::Read::read_to_end(&mut member, &mut bytes).unwrap();
            npy::read_f64_matrix(&bytes, 4).unwrap().values
        }
    }
}

#[test]
fn every_layout_gives_the_same_hits_across_chunks() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let obj = square(d);
    // Two whole chunks and a part of a third.
    let n = 2 * RAYS_PER_CHUNK + 4321;
    let npy_rays = d.join("rays.npy");
    write_npy_rays(&npy_rays, n);
    let npz_rays = d.join("rays.npz");
    write_rays(&npz_rays, HitsLayout::Npz, n);
    let raw_rays = d.join("rays.f64");
    write_rays(&raw_rays, HitsLayout::RawF64, n);

    let reference = d.join("hits.npy");
    raycast(&[&obj, &npy_rays, &reference, &"-q"]);
    let hits = read_hits(&reference);
    assert_eq!(hits.len(), 4 * n);
    let mut called = 0;
    for k in 0..n {
        let row = &hits[4 * k..4 * k + 4];
        match expected(k) {
            Some(Some(tri)) => {
                assert!((row[0] - 2.0).abs() < 1e-6 && row[1] == tri, "ray {k}: {row:?}");
                called += 1;
            }
            Some(None) => assert_eq!((row[0], row[1]), (f64::INFINITY, -1.0), "ray {k}"),
            None => {}
        }
    }
    assert!(called > n / 3, "only {called} rays hit");

    let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
    for rays in [&npy_rays, &npz_rays, &raw_rays] {
        for out in ["out.npy", "out.npz", "out.f64"] {
            let out: PathBuf = d.join(out);
            raycast(&[&obj, rays, &out, &"-q"]);
            assert!(
                bits(&read_hits(&out)) == bits(&hits),
                "{} -> {}",
                rays.display(),
                out.display()
            );
        }
    }
}

/// Runs `raycast` and returns its peak resident memory in bytes, as its `--stats` say.
fn peak_memory(args: &[&dyn AsRef<std::ffi::OsStr>], stats: &Path) -> u64 {
    let mut all = args.to_vec();
    all.extend([&"--stats" as &dyn AsRef<std::ffi::OsStr>, &stats]);
    raycast(&all);
    let v: serde_json::Value = serde_json::from_slice(&std::fs::read(stats).unwrap()).unwrap();
    v["peak_memory_bytes"].as_u64().expect("Linux reports the peak")
}

#[test]
fn memory_is_bounded_by_the_chunk_not_the_array() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let obj = square(d);
    // 3M rays: 72 MB of float32 rays, 144 MB as f64, 96 MB of hits. Reading them whole took
    // all three at once; a chunk is 16 MiB of rays and 8 MiB of hits.
    let n = 3_000_000;
    let rays = d.join("rays.npy");
    write_npy_rays(&rays, n);
    let array = (n * 6 * 8 + n * 4 * 8) as u64;
    for out in ["hits.npy", "hits.npz"] {
        let out = d.join(out);
        let peak = peak_memory(&[&obj, &rays, &out, &"-q", &"--threads", &"2"], &d.join("s.json"));
        assert!(peak < 100 << 20, "{}: peak RSS {} MiB", out.display(), peak >> 20);
        assert!(peak < array / 2, "peak RSS {} MiB", peak >> 20);
        assert_eq!(read_hits(&out).len(), 4 * n);
    }
}
