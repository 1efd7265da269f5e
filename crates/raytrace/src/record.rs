//! The run record that `--stats` writes beside the figures: what a reader needs to repeat the
//! run and to tell it apart from another (the program and the commit it was built from, the
//! command, the inputs by path, size and SHA-256, the outputs, the camera, the machine and the
//! build's vector instructions, the date).

use std::io::Read as _;
use std::path::Path;
use std::time::SystemTime;

use anyhow::Context as _;
use render::camera::Camera;
use sha2::{Digest as _, Sha256};

/// Everything in a `--stats` file beside the figures.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Record {
    /// `raytrace` or `raycast`.
    pub program: &'static str,
    /// The programs' version (the workspace's).
    pub version: &'static str,
    /// The git commit the program was built from, with `-dirty` when tracked files differed
    /// from it; `None` (JSON `null`) when it was not built from a git checkout.
    pub commit: Option<&'static str>,
    /// The command line, the program first, as the shell passed it.
    pub command: Vec<String>,
    /// When the run started: RFC 3339, UTC, to the second.
    pub started: String,
    /// The files read: the mesh, and the rays for `raycast`.
    pub inputs: Vec<FileRecord>,
    /// What was written, and in what form.
    pub output: OutputRecord,
    /// The CPU, cores and the build's target features.
    pub machine: MachineRecord,
}

/// An input file, so that a later run can check it reads the same bytes.
#[derive(Clone, Debug, PartialEq, Eq, serde::Serialize)]
pub struct FileRecord {
    /// What the file is (`mesh`, `rays`).
    pub role: &'static str,
    /// The path as given on the command line.
    pub path: String,
    /// Its size in bytes.
    pub bytes: u64,
    /// The SHA-256 of its bytes, in hex (what `sha256sum` prints).
    pub sha256: String,
}

impl FileRecord {
    /// Reads `path` through and records its size and SHA-256.
    ///
    /// # Errors
    ///
    /// If the file cannot be read (it was read once already, so only if it changed).
    pub fn of(role: &'static str, path: &Path) -> anyhow::Result<Self> {
        let mut file = std::fs::File::open(path).with_context(|| path.display().to_string())?;
        let mut hasher = Sha256::new();
        let mut buffer = vec![0; 1 << 16];
        let mut bytes = 0;
        loop {
            let n = file.read(&mut buffer).with_context(|| path.display().to_string())?;
            if n == 0 {
                break;
            }
            hasher.update(&buffer[..n]);
            bytes += n as u64;
        }
        let sha256 = hasher.finalize().iter().map(|b| format!("{b:02x}")).collect();
        Ok(Self { role, path: path.display().to_string(), bytes, sha256 })
    }
}

/// The main output of a run.
#[derive(Clone, Debug, Default, PartialEq, Eq, serde::Serialize)]
pub struct OutputRecord {
    /// The path as given on the command line.
    pub path: String,
    /// The image's width in pixels (`raytrace`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub width: Option<u32>,
    /// The image's height in pixels (`raytrace`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub height: Option<u32>,
    /// What each pixel shows (`raytrace --mode`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mode: Option<String>,
    /// The shape of the hits array (`raycast`): rows, columns.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub shape: Option<[usize; 2]>,
}

/// The camera a frame was rendered with, whatever placed it (`--camera auto` included): the
/// options that repeat the view.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct CameraRecord {
    /// The eye (`--eye`).
    pub eye: [f64; 3],
    /// The point looked at (`--look-at`).
    pub look_at: [f64; 3],
    /// The up direction asked for (`--up`).
    pub up: [f64; 3],
    /// The vertical field of view in degrees (`--fov`).
    pub fov_deg: f64,
}

impl CameraRecord {
    /// The record of `camera`, placed to look at `look_at` with `up` asked for.
    #[must_use]
    pub fn new(camera: &Camera, look_at: [f64; 3], up: [f64; 3]) -> Self {
        Self { eye: camera.eye(), look_at, up, fov_deg: camera.fov_deg() }
    }

    /// The options that place this camera again, e.g. `--eye 0,0.1,-0.5 --look-at 0,0.1,0
    /// --up 0,1,0 --fov 45`. Numbers are printed in the shortest form that reads back to the
    /// same `f64`, so the view is repeated exactly.
    #[must_use]
    pub fn options(&self) -> String {
        let v = |a: [f64; 3]| format!("{},{},{}", a[0], a[1], a[2]);
        format!(
            "--eye {} --look-at {} --up {} --fov {}",
            v(self.eye),
            v(self.look_at),
            v(self.up),
            self.fov_deg
        )
    }
}

/// The machine and the build.
#[derive(Clone, Debug, PartialEq, Eq, serde::Serialize)]
pub struct MachineRecord {
    /// The CPU model (`/proc/cpuinfo`), or `unknown`.
    pub cpu: String,
    /// The cores this process could use.
    pub cores: usize,
    /// The vector instructions the build compiled in (`backends::machine::target_features`).
    pub target_features: String,
    /// The instruction sets of the BVH's node test, chosen at run time
    /// (`backends::machine::node_test`), e.g. `f32 avx512, f64 avx2`.
    pub node_test: String,
    /// The operating system and architecture, e.g. `linux x86_64`.
    pub os: String,
}

impl MachineRecord {
    /// This machine and build.
    #[must_use]
    pub fn this() -> Self {
        use backends::machine;
        Self {
            cpu: machine::cpu_model(),
            cores: machine::cores(),
            target_features: machine::target_features(),
            node_test: machine::node_test(),
            os: format!("{} {}", std::env::consts::OS, std::env::consts::ARCH),
        }
    }
}

impl Record {
    /// The record of a run of `program` that started at `started`, with the command line of
    /// this process; `inputs` are hashed here (a second read of files the run has read, so
    /// from the page cache).
    ///
    /// # Errors
    ///
    /// If an input cannot be read again.
    pub fn new(
        program: &'static str,
        started: SystemTime,
        inputs: &[(&'static str, &Path)],
        output: OutputRecord,
    ) -> anyhow::Result<Self> {
        Ok(Self {
            program,
            version: env!("CARGO_PKG_VERSION"),
            commit: option_env!("WEDGE_GIT_COMMIT"),
            command: std::env::args_os().map(|a| a.to_string_lossy().into_owned()).collect(),
            started: humantime::format_rfc3339_seconds(started).to_string(),
            inputs: inputs
                .iter()
                .map(|&(role, path)| FileRecord::of(role, path))
                .collect::<anyhow::Result<_>>()?,
            output,
            machine: MachineRecord::this(),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn files_are_hashed_like_sha256sum() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("abc.txt");
        std::fs::write(&path, b"abc").unwrap();
        let f = FileRecord::of("mesh", &path).unwrap();
        assert_eq!(f.bytes, 3);
        // FIPS 180-2, appendix B.1.
        assert_eq!(f.sha256, "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
        // Longer than one buffer.
        std::fs::write(&path, vec![b'a'; 1_000_000]).unwrap();
        let f = FileRecord::of("mesh", &path).unwrap();
        assert_eq!(f.sha256, "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
        assert!(FileRecord::of("mesh", &dir.path().join("missing")).is_err());
    }

    #[test]
    fn camera_options_read_back_exactly() {
        let camera =
            Camera::look_at([0.1, -2.5e-3, 1.0 / 3.0], [0.0; 3], [0.0, 1.0, 0.0], 45.0).unwrap();
        let r = CameraRecord::new(&camera, [0.0; 3], [0.0, 1.0, 0.0]);
        let text = r.options();
        assert!(text.starts_with("--eye 0.1,-0.0025,0.3333333333333333 --look-at 0,0,0"), "{text}");
        assert!(text.ends_with("--up 0,1,0 --fov 45"), "{text}");
        let eye: Vec<f64> =
            text.split(' ').nth(1).unwrap().split(',').map(|x| x.parse().unwrap()).collect();
        assert_eq!(eye, camera.eye());
    }
}
