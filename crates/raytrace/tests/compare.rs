//! `raytrace --compare`: real processes on the generated scenes of `obj/`.
//!
//! The crack scene is the torus seen along its axis (`obj/README.md`'s camera, as in
//! `backends_agree.rs`'s on-axis test): whole diagonals of rays pass exactly through shared
//! edges, and the non-watertight Moller-Trumbore kernel (`la-mt`) misses both triangles of a
//! few of them where the watertight `la` hits one.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn raytrace(args: &[&dyn AsRef<std::ffi::OsStr>]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_raytrace")).args(args).output().unwrap()
}

fn obj(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../obj").join(name)
}

fn ok(out: &Output) -> String {
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "failed: {stderr}");
    String::from_utf8_lossy(&out.stdout).into_owned()
}

/// Failed with status `code` and exactly one line on stderr, `error: ...` with `needle`.
fn fails(out: &Output, code: i32, needle: &str) {
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(code), "{stderr}");
    assert_eq!(stderr.lines().count(), 1, "not one line: {stderr}");
    assert!(stderr.starts_with("error: ") && stderr.contains(needle), "{needle}: {stderr}");
}

fn names(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

/// The table line of the pair `a`, `b`, split into its cells.
fn row(table: &str, a: &str, b: &str) -> Vec<String> {
    table
        .lines()
        .map(|l| l.split_whitespace().map(str::to_owned).collect::<Vec<_>>())
        .find(|cells| cells.len() == 9 && cells[0] == a && cells[1] == b)
        .unwrap_or_else(|| panic!("no row {a} {b} in:\n{table}"))
}

#[test]
fn a_non_watertight_kernel_cracks_on_the_torus_axis() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("torus.png");
    let stats = dir.path().join("s.json");
    let torus = obj("torus.obj");
    let args: [&dyn AsRef<std::ffi::OsStr>; 13] = [
        &torus,
        &out,
        &"160",
        &"120",
        &"--eye",
        &"0,0,-4",
        &"--look-at",
        &"0,0,0",
        &"--stats",
        &stats,
        &"--compare",
        &"la,la-mt",
        &"--threads=2",
    ];
    let text = ok(&raytrace(&args));
    let cells = row(&text, "la", "la-mt");
    // Columns: a, b, differing, a only, b only, triangle, depth differs, max |dt|, max rel.
    let figure = |k: usize| cells[k].parse::<u64>().unwrap();
    assert!(figure(3) > 0, "la-mt never missed where la hit: {text}");
    assert_eq!(figure(4), 0, "la-mt hit where watertight la missed: {text}");
    assert_eq!(figure(2), figure(3) + figure(4) + figure(5));
    assert!(text.starts_with("compare: 2 back ends, "), "{text}");
    assert_eq!(
        names(dir.path()),
        ["s.json", "torus.diff.la.la-mt.png", "torus.png"],
        "the outputs, and no temporary file"
    );

    // The JSON holds the same figures.
    let json: serde_json::Value = serde_json::from_slice(&std::fs::read(&stats).unwrap()).unwrap();
    let cmp = &json["compare"];
    assert_eq!(cmp["backends"][0]["name"], "la");
    assert_eq!(cmp["backends"][1]["name"], "la-mt");
    assert!(cmp["backends"][1]["trace_ms"].as_f64().unwrap() > 0.0);
    let pair = &cmp["pairs"][0];
    assert_eq!((pair["a"].as_str(), pair["b"].as_str()), (Some("la"), Some("la-mt")));
    for (k, key) in [(2, "differing"), (3, "a_only"), (4, "b_only"), (5, "triangle")] {
        assert_eq!(pair[key].as_u64(), Some(figure(k)), "{key}");
    }
    assert_eq!(pair["depth_differs"].as_u64(), Some(figure(6)));
    let max = pair["max_depth_diff"].as_f64().unwrap();
    assert!(max > 0.0 && max < 1e-4, "f32 depths of the same triangle: {max}");
    assert_eq!(
        pair["diff_image"],
        out.with_file_name("torus.diff.la.la-mt.png").display().to_string()
    );
    assert!(cmp["disagreeing_pixels"].as_u64().unwrap() >= figure(2));
    assert_eq!(json["backend"], "la");
    assert_eq!(json["rays"], 3 * 160 * 120, "la's image and hits, la-mt's hits");

    // The diff image: red exactly where la-mt cracked, yellow for the other triangle.
    let diff = image::open(dir.path().join("torus.diff.la.la-mt.png")).unwrap().into_rgb8();
    assert_eq!(diff.dimensions(), (160, 120));
    let count = |c: [u8; 3]| diff.pixels().filter(|p| p.0 == c).count() as u64;
    assert_eq!(count([255, 0, 0]), figure(3));
    assert_eq!(count([0, 255, 0]), 0);
    assert_eq!(count([255, 255, 0]), figure(5));
    let blue = diff.pixels().filter(|p| p.0[..2] == [0, 0] && p.0[2] >= 64).count() as u64;
    assert_eq!(blue, figure(6));
    // And the image itself is la's plain render.
    let plain = dir.path().join("plain.png");
    let args: [&dyn AsRef<std::ffi::OsStr>; 8] =
        [&torus, &plain, &"160", &"120", &"--eye", &"0,0,-4", &"--look-at", &"0,0,0"];
    ok(&raytrace(&args));
    assert_eq!(image::open(&plain).unwrap(), image::open(&out).unwrap());
}

#[test]
fn bit_identical_back_ends_show_zero() {
    // No back end equals `la` to the last bit of `t` on these scenes, but `la-mt` and `ga`
    // (Moller-Trumbore and the frame method with the same rounding on the tiles' binary
    // lattice) do on the tiles seen along their axis.
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("t.png");
    let tiles = obj("tiles.obj");
    let args: [&dyn AsRef<std::ffi::OsStr>; 10] = [
        &tiles,
        &out,
        &"64",
        &"48",
        &"--eye",
        &"0,0,-3",
        &"--look-at",
        &"0,0,0",
        &"--compare",
        &"la-mt,ga",
    ];
    let text = ok(&raytrace(&args));
    assert_eq!(row(&text, "la-mt", "ga")[2..], ["0", "0", "0", "0", "0", "0", "0"]);
    assert!(text.contains(", 0 of 3072 pixels where some disagree"), "{text}");
    let diff = image::open(dir.path().join("t.diff.la-mt.ga.png")).unwrap().into_rgb8();
    assert!(diff.pixels().all(|p| p.0 == [0, 0, 0]));
}

#[test]
fn compare_alone_means_every_back_end_and_quiet_is_quiet() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("c.png");
    let cube = obj("cube.obj");
    let run = raytrace(&[&cube, &out, &"8", &"6", &"--quiet", &"--compare"]);
    assert!(run.status.success());
    assert!(run.stdout.is_empty() && run.stderr.is_empty());
    let n = backends::Backend::ALL.len();
    // The image and one diff image per pair.
    assert_eq!(names(dir.path()).len(), 1 + n * (n - 1) / 2);
    assert!(out.with_file_name("c.diff.la.cga-plucker.png").exists());
}

#[test]
fn bad_compare_inputs_fail_before_any_work() {
    let dir = tempfile::tempdir().unwrap();
    let cube = obj("cube.obj");
    let out = dir.path().join("o.png");
    let run = |list: &str| raytrace(&[&cube, &out, &"8", &"8", &"--compare", &list]);
    fails(&run("la,nope"), 2, "invalid value 'nope' for '--compare");
    fails(&run("la,ga,la"), 2, "--compare: la is listed twice");
    fails(&run("la"), 2, "la alone has nothing to be compared with");
    fails(
        &raytrace(&[&cube, &out, &"8", &"8", &"--backend", &"ga", &"--compare"]),
        2,
        "cannot be used with",
    );
    assert!(names(dir.path()).is_empty());

    // A diff image's path taken by a directory: refused before rendering, OUT untouched.
    std::fs::write(&out, b"keep").unwrap();
    std::fs::create_dir(dir.path().join("o.diff.la.ga.png")).unwrap();
    fails(&run("la,ga"), 1, "is a directory");
    assert_eq!(std::fs::read(&out).unwrap(), b"keep");
    assert_eq!(names(dir.path()), ["o.diff.la.ga.png", "o.png"]);

    // A diff image that would overwrite the mesh.
    let mesh = dir.path().join("m.diff.la.ga.png");
    std::fs::copy(&cube, &mesh).unwrap();
    let m_out = dir.path().join("m.png");
    fails(
        &raytrace(&[&mesh, &m_out, &"8", &"8", &"--compare", &"la,ga"]),
        2,
        "the diff image would overwrite the mesh",
    );
    assert!(!m_out.exists());

    // A name with no room for the diff suffix.
    let long = dir.path().join(format!("{}.png", "x".repeat(245)));
    fails(
        &raytrace(&[&cube, &long, &"8", &"8", &"--compare", &"la,ga"]),
        2,
        "would be longer than 255 bytes",
    );
    assert!(!long.exists());
}
