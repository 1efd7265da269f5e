//! Memory bounds of `Mesh::from_bytes`, measured with a counting allocator: absurd header
//! counts allocate nothing for them, and no input costs more than the stated multiple of
//! its size. (A test binary of its own: the allocator counts every allocation of the
//! process, so the tests run one after another under a lock.)

use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};

use scene::memory::FROM_BYTES_MULTIPLE;
use scene::{Mesh, MeshFormat};

/// The system allocator, counting the bytes live and their peak.
struct Counting;

static LIVE: AtomicUsize = AtomicUsize::new(0);
static PEAK: AtomicUsize = AtomicUsize::new(0);

// SAFETY: every call forwards to the system allocator with the same arguments; the counters
// only observe.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        let live = LIVE.fetch_add(layout.size(), Ordering::Relaxed) + layout.size();
        PEAK.fetch_max(live, Ordering::Relaxed);
        // SAFETY: the caller's layout is passed on unchanged.
        unsafe { System.alloc(layout) }
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        LIVE.fetch_sub(layout.size(), Ordering::Relaxed);
        // SAFETY: `ptr` came from `alloc` with this layout.
        unsafe { System.dealloc(ptr, layout) }
    }
}

#[global_allocator]
static ALLOCATOR: Counting = Counting;

static ONE_AT_A_TIME: Mutex<()> = Mutex::new(());

/// Peak bytes allocated beyond those live before, while `f` runs.
fn peak_of(f: impl FnOnce()) -> usize {
    let base = LIVE.load(Ordering::Relaxed);
    PEAK.store(base, Ordering::Relaxed);
    f();
    PEAK.load(Ordering::Relaxed) - base
}

/// Peak allocation of parsing `bytes`, checked to fail.
fn refusal_cost(bytes: &[u8], format: MeshFormat) -> usize {
    let _lock = ONE_AT_A_TIME.lock().unwrap_or_else(|e| e.into_inner());
    peak_of(|| {
        assert!(Mesh::from_bytes(bytes, format, "a.mesh").is_err());
    })
}

#[test]
fn absurd_counts_allocate_nothing_for_them() {
    let ply = b"ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\n\
                property float x\nproperty float y\nproperty float z\nelement face 4000000000\n\
                property list uchar int vertex_indices\nend_header\n\0\0\0\0\0\0\0\0";
    let mut stl = [0u8; 84 + 50];
    stl[80..84].copy_from_slice(&u32::MAX.to_le_bytes());
    let gltf = br#"{"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],
        "nodes":[{"mesh":0}],"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],
        "accessors":[{"bufferView":0,"componentType":5126,"count":4000000000,"type":"VEC3"}],
        "bufferViews":[{"buffer":0,"byteLength":12}],
        "buffers":[{"byteLength":12,"uri":"data:;base64,AAAAAAAAAAAAAAAA"}]}"#;
    let ascii_ply = b"ply\nformat ascii 1.0\nelement vertex 4000000000\nproperty float x\n\
                      property float y\nproperty float z\nend_header\n0 0 0\n";
    for (bytes, format) in [
        (&ply[..], MeshFormat::Ply),
        (&ascii_ply[..], MeshFormat::Ply),
        (&stl[..], MeshFormat::Stl),
        (&gltf[..], MeshFormat::Gltf),
    ] {
        let cost = refusal_cost(bytes, format);
        // Parsers' fixed buffers and the error text: well under a megabyte, where honouring
        // a count would take gigabytes.
        assert!(cost < 1 << 20, "{format:?}: {cost} bytes");
    }
}

#[test]
fn dense_inputs_stay_within_the_stated_multiple() {
    // The lock first: the counters are global, and building these inputs (a megabyte) while
    // the other test measures would be counted against its parser.
    let _lock = ONE_AT_A_TIME.lock().unwrap_or_else(|e| e.into_inner());
    // The densest inputs there are: one triangle per one or two input bytes.
    let mut ply = b"ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty uchar x\n\
                    property uchar y\nproperty uchar z\nproperty float nx\nproperty float ny\n\
                    property float nz\nelement face 2000\n\
                    property list uchar uchar vertex_indices\nend_header\n"
        .to_vec();
    for v in [[0u8, 0, 0], [1, 0, 0], [0, 1, 0]] {
        ply.extend(v);
        for x in [0.0f32, 0.0, 1.0] {
            ply.extend(x.to_le_bytes());
        }
    }
    for _ in 0..2000 {
        ply.push(255);
        ply.extend((0..255).map(|i| (i % 3) as u8));
    }
    let mut obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf".to_owned();
    for i in 0..200_000 {
        obj += [" 1", " 2", " 3"][i % 3];
    }
    obj.push('\n');
    for (bytes, format) in [(&ply[..], MeshFormat::Ply), (obj.as_bytes(), MeshFormat::Obj)] {
        let mut triangles = 0;
        let cost = peak_of(|| {
            triangles = Mesh::from_bytes(bytes, format, "d.mesh").unwrap().len();
        });
        assert!(triangles as f64 > bytes.len() as f64 / 2.5, "{format:?}: {triangles}");
        let bound = FROM_BYTES_MULTIPLE as usize * bytes.len() + (1 << 20);
        assert!(cost <= bound, "{format:?}: {cost} bytes for {} input bytes", bytes.len());
    }
}
