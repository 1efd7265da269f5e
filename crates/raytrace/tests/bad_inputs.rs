//! Both programs driven through a table of everyday mistakes: bad files (missing, a directory,
//! a device, a FIFO, NUL bytes, empty, formats not read), bad arguments, outputs that would
//! clobber inputs, a stats file that cannot be written, and signals during a render. For each
//! row, in a fresh directory of fixtures, the child runs under a memory limit and a time limit
//! and must:
//!
//! - print exactly one line on stderr, `error: ...`, with the row's words in it, and nothing
//!   on stdout;
//! - exit with the row's status (1 bad data, 2 usage, 130 SIGINT, 143 SIGTERM);
//! - leave the directory exactly as it was: no file added (no output, no temporary), every
//!   file's bytes unchanged.

#![cfg(unix)]

use std::collections::BTreeMap;
use std::ffi::CString;
use std::io::Read as _;
use std::os::unix::ffi::OsStrExt as _;
use std::os::unix::process::CommandExt as _;
use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use render::output::npy;

/// A child taking longer than this is hung: it is killed and the row fails.
const TIME_LIMIT: Duration = Duration::from_secs(20);

/// The children's address-space limit: a program that tries to read `/dev/zero` into memory
/// or allocate a frame larger than the machine fails the row instead of taking the machine.
const MEMORY_LIMIT: u64 = 4 << 30;

const SQUARE: &str = "v -1 -1 4\nv 1 -1 4\nv 1 1 4\nv -1 1 4\nf 1 4 3\nf 1 3 2\n";

/// A stats file as the programs write it (every key they have always written).
const OLD_STATS: &str = r#"{"triangles": 2, "rays": 64, "backend": "la", "precision": "f32"}"#;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Program {
    Raytrace,
    Raycast,
}

/// How the row's child is run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum How {
    Plain,
    /// With `RLIMIT_FSIZE` at this many bytes and SIGXFSZ ignored: writes beyond it fail.
    FileSizeLimit(u64),
    /// Sent this signal once its temporary files exist (it is then rendering).
    Signal(i32),
}

struct Row {
    program: Program,
    args: &'static [&'static str],
    how: How,
    status: i32,
    /// Words the error line must contain.
    words: &'static [&'static str],
}

const fn row(
    program: Program,
    args: &'static [&'static str],
    status: i32,
    words: &'static [&'static str],
) -> Row {
    Row { program, args, how: How::Plain, status, words }
}

use Program::{Raycast, Raytrace};

/// The table. Rows for formats other helpers are adding readers for (`.ply`, `.stl`, `.glb`
/// with contents that are not a mesh in any format) only ask for the file's name and status
/// 1, so they hold before and after those readers.
fn table() -> Vec<Row> {
    let signal = |sig, status| Row {
        program: Raytrace,
        args: &["square.obj", "big.npy", "16000", "16000", "--stats", "big.json"],
        how: How::Signal(sig),
        status,
        words: &["big.npy", "interrupted"],
    };
    vec![
        // Input files.
        row(Raytrace, &["missing.obj", "o.png", "8", "8"], 1, &["missing.obj: file not found"]),
        row(Raytrace, &["sub", "o.png", "8", "8"], 1, &["sub: is a directory"]),
        row(Raytrace, &["/dev/zero", "o.png", "8", "8"], 1, &["/dev/zero: is a character device"]),
        row(Raytrace, &["fifo.obj", "o.png", "8", "8"], 1, &["fifo.obj: is a FIFO"]),
        row(Raytrace, &["nul.obj", "o.png", "8", "8"], 1, &["nul.obj: not a text file"]),
        row(Raytrace, &["nul.obj.gz", "o.png", "8", "8"], 1, &["nul.obj.gz"]),
        row(Raytrace, &["empty.obj", "o.png", "8", "8"], 1, &["empty.obj: the mesh has no faces"]),
        row(Raytrace, &["m.ply", "o.png", "8", "8"], 1, &["m.ply"]),
        row(Raytrace, &["m.stl", "o.png", "8", "8"], 1, &["m.stl"]),
        row(Raytrace, &["m.glb", "o.png", "8", "8"], 1, &["m.glb"]),
        row(Raytrace, &["m.gltf", "o.png", "8", "8"], 1, &["m.gltf"]),
        row(Raytrace, &["m.3ds", "o.png", "8", "8"], 1, &["m.3ds: unsupported mesh format"]),
        row(Raytrace, &["bom-bad.obj", "o.png", "8", "8"], 1, &["bom-bad.obj:7:", "normal index"]),
        row(Raytrace, &["huge.obj", "o.png", "8", "8"], 1, &["huge.obj", "beyond f32's range"]),
        row(Raycast, &["huge.obj", "rays.npy", "h.npy"], 1, &["huge.obj", "--precision f64"]),
        row(Raycast, &["fifo.obj", "rays.npy", "h.npy"], 1, &["fifo.obj: is a FIFO"]),
        row(Raycast, &["square.obj", "missing.npy", "h.npy"], 1, &["missing.npy: file not found"]),
        row(Raycast, &["square.obj", "sub", "h.npy"], 1, &["sub: is a directory"]),
        row(Raycast, &["square.obj", "/dev/zero", "h.npy"], 1, &["/dev/zero: is a character"]),
        row(Raycast, &["square.obj", "fifo.npy", "h.npy"], 1, &["fifo.npy: is a FIFO"]),
        row(Raycast, &["square.obj", "empty.npy", "h.npy"], 1, &["empty.npy", "not a NumPy"]),
        row(Raycast, &["square.obj", "nul.npy", "h.npy"], 1, &["nul.npy", "not a NumPy"]),
        // Outputs: where they cannot go, and outputs that would replace an input.
        row(Raytrace, &["square.obj", "dir.png", "8", "8"], 1, &["dir.png: is a directory"]),
        row(Raytrace, &["square.obj", "fifo.png", "8", "8"], 1, &["fifo.png: is a FIFO"]),
        row(Raytrace, &["square.obj", "nodir/o.png", "8", "8"], 1, &["nodir/o.png: cannot write"]),
        row(Raytrace, &["square.obj", "o.gif", "8", "8"], 2, &["o.gif: unknown output format"]),
        row(Raytrace, &["square.obj", "new.png/", "8", "8"], 2, &["new.png/: ends in a path"]),
        row(Raycast, &["square.obj", "rays.npy", "h.npy", "--stats", "s.json/"], 2, &["s.json/"]),
        row(Raytrace, &["square.obj", "square.obj", "8", "8"], 2, &["square.obj: unknown output"]),
        row(
            Raytrace,
            &["mesh.png", "mesh.png", "8", "8"],
            2,
            &["the image would overwrite the mesh"],
        ),
        row(
            Raycast,
            &["square.obj", "rays.npy", "rays.npy"],
            2,
            &["the hits would overwrite the rays"],
        ),
        row(
            Raycast,
            &["square.obj", "rays.npy", "hard.npy"],
            2,
            &["hits would overwrite the rays"],
        ),
        row(Raycast, &["square.obj", "rays.npy", "square.obj"], 2, &[".npy, .npz or .f64"]),
        row(Raycast, &["square.obj", "rays.npy", "sub"], 2, &[".npy, .npz or .f64"]),
        row(Raycast, &["square.obj", "rays.npy", "h.f32"], 2, &["h.f32", "float64"]),
        // Rays in the other layouts.
        row(Raycast, &["square.obj", "two.npz", "h.npy"], 1, &["two.npz", "2 arrays"]),
        row(Raycast, &["square.obj", "broken.npz", "h.npy"], 1, &["broken.npz", "cannot be read"]),
        row(Raycast, &["square.obj", "odd.f32", "h.npy"], 1, &["odd.f32", "not a whole number"]),
        row(Raycast, &["square.obj", "nul.f64", "h.npy"], 1, &["nul.f64", "not a whole number"]),
        row(Raycast, &["square.obj", "rays.npy", "h.npy", "--ray-columns", "8"], 1, &["6 columns"]),
        row(Raycast, &["square.obj", "rays.npy", "h.npy", "--ray-columns", "7"], 2, &["6, 8"]),
        // --stats.
        row(Raytrace, &["square.obj", "o.png", "8", "8", "--stats", "square.obj"], 2, &[".json"]),
        row(Raytrace, &["square.obj", "out.npy", "8", "8", "--stats", "out.npy"], 2, &[".json"]),
        row(Raycast, &["square.obj", "rays.npy", "h.npy", "--stats", "rays.npy"], 2, &[".json"]),
        row(
            Raytrace,
            &["square.obj", "o.png", "8", "8", "--stats", "d.json"],
            1,
            &["d.json: is a dir"],
        ),
        row(
            Raytrace,
            &["square.obj", "o.png", "8", "8", "--stats", "foreign.json"],
            1,
            &["foreign.json: exists and is not a wedge stats file; remove it or choose another"],
        ),
        row(
            Raytrace,
            &["square.obj", "o.png", "8", "8", "--stats", "link.json"],
            1,
            &["link.json"],
        ),
        row(
            Raytrace,
            &["old.json", "o.png", "8", "8", "--stats", "old.json"],
            2,
            &["overwrite the mesh"],
        ),
        row(
            Raytrace,
            &["square.obj", "o.png", "8", "8", "--stats", "nodir/s.json"],
            1,
            &["s.json"],
        ),
        Row {
            program: Raytrace,
            args: &["square.obj", "tiny.npy", "2", "2", "--stats", "s.json"],
            how: How::FileSizeLimit(200),
            status: 1,
            words: &["s.json: write failed"],
        },
        // Arguments.
        row(Raytrace, &[], 2, &["<INPUT> <OUTPUT> <WIDTH> <HEIGHT>"]),
        row(Raytrace, &["square.obj"], 2, &["not provided: <OUTPUT> <WIDTH> <HEIGHT>"]),
        row(Raycast, &["square.obj"], 2, &["not provided: <RAYS> <HITS>"]),
        row(
            Raytrace,
            &["square.obj", "o.png", "8", "8", "--mode", "normals"],
            2,
            &[
                "[possible values: alpha, depth, normal, shade, prim]",
                "similar value exists: 'normal'",
            ],
        ),
        row(
            Raycast,
            &["square.obj", "rays.npy", "h.npy", "--backend", "cuda"],
            2,
            &["'cuda'", "ga-plucker"],
        ),
        row(Raytrace, &["square.obj", "o.png", "8", "8", "--fov", "-10"], 2, &["(0, 180)", "-10"]),
        row(Raytrace, &["square.obj", "o.png", "8", "8", "--fov", "180"], 2, &["(0, 180)"]),
        row(Raytrace, &["square.obj", "o.png", "8", "8", "--fov", "0"], 2, &["(0, 180)"]),
        row(Raytrace, &["square.obj", "o.png", "4294967296", "8"], 2, &["<WIDTH>", "1..=65535"]),
        row(Raytrace, &["square.obj", "o.png", "0", "8"], 2, &["<WIDTH>", "1..=65535"]),
        row(Raytrace, &["square.obj", "o.png", "8", "-3"], 2, &["<HEIGHT>", "1..=65535"]),
        row(Raytrace, &["square.obj", "o.png", "8", "wide"], 2, &["'wide'", "<HEIGHT>"]),
        row(Raytrace, &["square.obj", "o.png", "8", "8", "--threads", "10000"], 2, &["at most"]),
        row(Raycast, &["square.obj", "rays.npy", "h.npy", "--threads", "-1"], 2, &["'-1'"]),
        row(Raytrace, &["square.obj", "o.png", "8", "8", "--colour"], 2, &["'--colour'"]),
        row(Raytrace, &["square.obj", "o.png", "8", "8", "--eye", "1,2"], 2, &["X,Y,Z"]),
        row(
            Raytrace,
            &["square.obj", "o.png", "65535", "65535", "--mode", "shade"],
            1,
            &["allocate"],
        ),
        // Signals during a render: no output, no temporary.
        signal(libc::SIGINT, 130),
        signal(libc::SIGTERM, 143),
    ]
}

/// Makes the fixtures every row may use in `dir`.
fn fixtures(dir: &Path) {
    let put = |name: &str, bytes: &[u8]| std::fs::write(dir.join(name), bytes).unwrap();
    put("square.obj", SQUARE.as_bytes());
    put("mesh.png", SQUARE.as_bytes());
    put("nul.obj", b"v 0 0 0\0\0\0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    put("nul.npy", &[0; 256]);
    put("empty.obj", b"");
    put("empty.npy", b"");
    // A BOM, then a face naming a normal the file does not have.
    put("bom-bad.obj", format!("\u{feff}{SQUARE}f 1//1 2//1 3//1\n").as_bytes());
    put("huge.obj", b"v 0 0 4\nv 1e39 0 4\nv 0 1 4\nf 1 2 3\n");
    // Not gzip at all, under a .gz name.
    put("nul.obj.gz", b"\0\0\0\0");
    for name in ["m.ply", "m.stl", "m.glb", "m.gltf", "m.3ds"] {
        put(name, b"this is not a mesh in any format\n");
    }
    let mut rays = Vec::new();
    npy::write(&mut rays, &[1, 6], [0.0f32, 0.0, 0.0, 0.0, 0.0, 1.0]).unwrap();
    put("rays.npy", &rays);
    put("odd.f32", &[0; 4 * 7]);
    put("nul.f64", &[0; 5]);
    put("broken.npz", b"PK\x03\x04 and no more of a zip archive");
    let mut two = zip::ZipWriter::new(std::io::Cursor::new(Vec::new()));
    for name in ["a.npy", "b.npy"] {
        two.start_file(name, zip::write::SimpleFileOptions::default()).unwrap();
        std::io::Write::write_all(&mut two, &rays).unwrap();
    }
    put("two.npz", &two.finish().unwrap().into_inner());
    std::fs::hard_link(dir.join("rays.npy"), dir.join("hard.npy")).unwrap();
    put("out.npy", b"an earlier image");
    put("old.json", OLD_STATS.as_bytes());
    put("foreign.json", br#"{"name": "my notes"}"#);
    std::os::unix::fs::symlink("foreign.json", dir.join("link.json")).unwrap();
    for sub in ["sub", "d.json", "dir.png"] {
        std::fs::create_dir(dir.join(sub)).unwrap();
    }
    put("dir.png/keep", b"inside");
    for fifo in ["fifo.obj", "fifo.npy", "fifo.png"] {
        let path = CString::new(dir.join(fifo).as_os_str().as_bytes()).unwrap();
        // SAFETY: `path` is a NUL-terminated string that outlives the call.
        assert_eq!(unsafe { libc::mkfifo(path.as_ptr(), 0o644) }, 0, "mkfifo {fifo}");
    }
}

/// Every entry below `dir` (not following links) with what it holds: a file's bytes, a
/// link's target, a FIFO or a directory as a tag. FIFOs are never opened.
fn snapshot(dir: &Path) -> BTreeMap<String, Vec<u8>> {
    let mut all = BTreeMap::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for entry in std::fs::read_dir(&d).unwrap() {
            let path = entry.unwrap().path();
            let name = path.strip_prefix(dir).unwrap().to_string_lossy().into_owned();
            let kind = std::fs::symlink_metadata(&path).unwrap().file_type();
            let content = if kind.is_symlink() {
                std::fs::read_link(&path).unwrap().as_os_str().as_bytes().to_vec()
            } else if kind.is_dir() {
                stack.push(path);
                b"<directory>".to_vec()
            } else if kind.is_file() {
                std::fs::read(&path).unwrap()
            } else {
                b"<special>".to_vec()
            };
            all.insert(name, content);
        }
    }
    all
}

/// Whether a temporary output file exists in `dir`.
fn has_temporary(dir: &Path) -> bool {
    std::fs::read_dir(dir).unwrap().any(|e| {
        let name = e.unwrap().file_name().to_string_lossy().into_owned();
        name.starts_with('.') && name.ends_with(".tmp")
    })
}

/// The result of a row's run.
struct Run {
    status: Option<i32>,
    stdout: String,
    stderr: String,
}

fn run(row: &Row, dir: &Path) -> Run {
    let exe = match row.program {
        Raytrace => env!("CARGO_BIN_EXE_raytrace"),
        Raycast => env!("CARGO_BIN_EXE_raycast"),
    };
    let mut cmd = Command::new(exe);
    cmd.args(row.args).current_dir(dir).stdin(Stdio::null());
    cmd.stdout(Stdio::piped()).stderr(Stdio::piped());
    let file_size = match row.how {
        How::FileSizeLimit(bytes) => Some(bytes),
        _ => None,
    };
    // SAFETY: between fork and exec the closure only calls setrlimit and signal, which are
    // async-signal-safe, on values built before the fork; it allocates nothing.
    unsafe {
        cmd.pre_exec(move || {
            let limit = |resource, bytes: u64| {
                let rl = libc::rlimit { rlim_cur: bytes, rlim_max: bytes };
                if libc::setrlimit(resource, &rl) == 0 {
                    Ok(())
                } else {
                    Err(std::io::Error::last_os_error())
                }
            };
            limit(libc::RLIMIT_AS, MEMORY_LIMIT)?;
            if let Some(bytes) = file_size {
                limit(libc::RLIMIT_FSIZE, bytes)?;
                // Ignored, SIGXFSZ turns into a write error (EFBIG), which the program reports.
                libc::signal(libc::SIGXFSZ, libc::SIG_IGN);
            }
            Ok(())
        });
    }
    let mut child = cmd.spawn().unwrap();
    let mut stdout = child.stdout.take().unwrap();
    let mut stderr = child.stderr.take().unwrap();
    let read_out = std::thread::spawn(move || {
        let mut s = String::new();
        stdout.read_to_string(&mut s).unwrap();
        s
    });
    let read_err = std::thread::spawn(move || {
        let mut s = String::new();
        stderr.read_to_string(&mut s).unwrap();
        s
    });
    let start = Instant::now();
    let mut signalled = false;
    let status = loop {
        if let Some(status) = child.try_wait().unwrap() {
            break status;
        }
        if let How::Signal(sig) = row.how
            && !signalled
            && has_temporary(dir)
        {
            // The outputs exist as temporaries: the run is past its checks, working.
            std::thread::sleep(Duration::from_millis(200));
            let pid = libc::pid_t::try_from(child.id()).unwrap();
            // SAFETY: kill has no memory-safety preconditions; `pid` is our child, which
            // has not been waited for, so the id is not reused.
            assert_eq!(unsafe { libc::kill(pid, sig) }, 0);
            signalled = true;
        }
        if start.elapsed() > TIME_LIMIT {
            let _ = child.kill();
            let _ = child.wait();
            panic!("{:?} {:?}: still running after {TIME_LIMIT:?}", row.program, row.args);
        }
        std::thread::sleep(Duration::from_millis(10));
    };
    if let How::Signal(_) = row.how {
        assert!(signalled, "{:?}: finished before it could be signalled", row.args);
    }
    Run {
        status: status.code(),
        stdout: read_out.join().unwrap(),
        stderr: read_err.join().unwrap(),
    }
}

#[test]
fn every_bad_input_gets_one_line_the_right_status_and_harms_nothing() {
    let mut failures = Vec::new();
    for row in table() {
        let dir = tempfile::tempdir().unwrap();
        fixtures(dir.path());
        let before = snapshot(dir.path());
        let got = run(&row, dir.path());
        let after = snapshot(dir.path());
        let what = format!("{:?} {}", row.program, row.args.join(" "));
        let mut problems = Vec::new();
        if got.status != Some(row.status) {
            problems.push(format!("status {:?}, expected {}", got.status, row.status));
        }
        let lines: Vec<&str> = got.stderr.lines().collect();
        if lines.len() != 1 || !lines[0].starts_with("error: ") {
            problems.push(format!("stderr is not one error line: {:?}", got.stderr));
        }
        for word in row.words {
            if !got.stderr.contains(word) {
                problems.push(format!("'{word}' not in {:?}", got.stderr));
            }
        }
        if got.stderr.contains("panicked") || got.stderr.contains("internal error") {
            problems.push(format!("a panic: {:?}", got.stderr));
        }
        if !got.stdout.is_empty() {
            problems.push(format!("stdout: {:?}", got.stdout));
        }
        for (name, bytes) in &after {
            match before.get(name) {
                None => problems.push(format!("left behind: {name}")),
                Some(b) if b != bytes => problems.push(format!("changed: {name}")),
                Some(_) => {}
            }
        }
        for name in before.keys().filter(|n| !after.contains_key(*n)) {
            problems.push(format!("removed: {name}"));
        }
        if !problems.is_empty() {
            failures.push(format!("{what}:\n    {}", problems.join("\n    ")));
        }
    }
    assert!(failures.is_empty(), "{} rows failed:\n{}", failures.len(), failures.join("\n"));
}
