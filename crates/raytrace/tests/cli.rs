//! End-to-end tests of the `raytrace` and `raycast` programs: real processes, temporary
//! directories, answers known analytically.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use render::output::npy;

/// A square `[-1, 1]^2` at `z = 4`: triangle 0 is its upper-left half (`y > x`), triangle 1
/// the lower-right half, both wound towards -z.
const SQUARE: &str = "v -1 -1 4\nv 1 -1 4\nv 1 1 4\nv -1 1 4\nf 1 4 3\nf 1 3 2\n";

/// One triangle in the upper-right quadrant of the origin camera's view, at `z = 4`.
const UPPER_RIGHT: &str = "v 0.2 0.2 4\nv 1.2 0.2 4\nv 0.2 1.2 4\nf 1 2 3\n";

fn raytrace(args: &[&dyn AsRef<std::ffi::OsStr>]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_raytrace")).args(args).output().unwrap()
}

fn raycast(args: &[&dyn AsRef<std::ffi::OsStr>]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_raycast")).args(args).output().unwrap()
}

fn ok(out: &Output) -> String {
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "failed: {stderr}");
    String::from_utf8_lossy(&out.stdout).into_owned()
}

/// The program failed with exactly one line on stderr, `error: ...` containing `needle`.
fn fails(out: &Output, needle: &str) {
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success(), "succeeded, expected an error with '{needle}'");
    assert_eq!(stderr.lines().count(), 1, "not one line: {stderr}");
    assert!(stderr.starts_with("error: "), "{stderr}");
    assert!(stderr.contains(needle), "'{needle}' not in: {stderr}");
    assert!(!stderr.contains("panicked"), "{stderr}");
}

fn names(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

fn write(dir: &Path, name: &str, text: &str) -> PathBuf {
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

/// The camera contract for the origin camera, written out independently of `render`:
/// where pixel (i, j)'s ray meets the plane z = `depth`, and its unit direction's z.
fn origin_ray(i: u32, j: u32, w: u32, h: u32, depth: f64) -> ([f64; 2], f64) {
    let t = 22.5f64.to_radians().tan();
    let x = (2.0 * (f64::from(i) + 0.5) / f64::from(w) - 1.0) * t * f64::from(w) / f64::from(h);
    let y = (1.0 - 2.0 * (f64::from(j) + 0.5) / f64::from(h)) * t;
    ([depth * x, depth * y], 1.0 / (1.0 + x * x + y * y).sqrt())
}

/// `Some(inside)` for the square at z = 4, `None` for pixels too near an edge to call.
fn square_mask(i: u32, j: u32, w: u32, h: u32) -> Option<bool> {
    let ([x, y], _) = origin_ray(i, j, w, h, 4.0);
    let margin = x.abs().max(y.abs()) - 1.0;
    (margin.abs() > 1e-4).then_some(margin < 0.0)
}

#[test]
fn alpha_png_matches_the_analytic_square_on_every_backend_and_precision() {
    let dir = tempfile::tempdir().unwrap();
    let obj = write(dir.path(), "square.obj", SQUARE);
    let (w, h) = (48u32, 32u32);
    let backends = backends::Backend::ALL.map(backends::Backend::name);
    for (backend, precision) in backends.iter().flat_map(|b| [(b, "f32"), (b, "f64")]) {
        let png = dir.path().join(format!("{backend}-{precision}.png"));
        let out = raytrace(&[
            &obj,
            &png,
            &"48",
            &"32",
            &"--camera",
            &"origin",
            &"--backend",
            &backend,
            &"--precision",
            &precision,
            &"--quiet",
        ]);
        assert_eq!(ok(&out), "", "--quiet prints nothing");
        let img = image::open(&png).unwrap().into_luma8();
        assert_eq!(img.dimensions(), (w, h));
        let mut hits = 0;
        for j in 0..h {
            for i in 0..w {
                let px = img.get_pixel(i, j).0[0];
                assert!(px == 0 || px == 255);
                if let Some(inside) = square_mask(i, j, w, h) {
                    assert_eq!(px == 255, inside, "{backend} {precision} pixel ({i}, {j})");
                }
                hits += u32::from(px == 255);
            }
        }
        assert!(hits > 100, "{hits}");
    }
}

#[test]
fn image_is_not_mirrored() {
    // +x is right and +y is up for the origin camera (documented handedness): a triangle in
    // the upper-right quadrant of the view lands in the upper-right quarter of the image.
    let dir = tempfile::tempdir().unwrap();
    let obj = write(dir.path(), "ur.obj", UPPER_RIGHT);
    let png = dir.path().join("ur.png");
    ok(&raytrace(&[&obj, &png, &"40", &"40", &"--camera", &"origin", &"-q"]));
    let img = image::open(&png).unwrap().into_luma8();
    let mut hits = 0;
    for (i, j, p) in img.enumerate_pixels() {
        if p.0[0] == 255 {
            assert!(i >= 20 && j < 20, "hit at ({i}, {j})");
            hits += 1;
        }
    }
    assert!(hits > 10);
}

#[test]
fn every_mode_writes_every_format() {
    let dir = tempfile::tempdir().unwrap();
    let obj = write(dir.path(), "square.obj", SQUARE);
    let (w, h) = (20u32, 14u32);
    for mode in ["alpha", "depth", "normal", "shade", "prim"] {
        for ext in ["png", "jpg", "jpeg", "exr", "npy"] {
            let path = dir.path().join(format!("{mode}.{ext}"));
            let out =
                raytrace(&[&obj, &path, &"20", &"14", &"--camera", &"origin", &"--mode", &mode]);
            let summary = ok(&out);
            assert!(summary.contains("2 triangles") && summary.contains("Mrays/s"), "{summary}");
            assert_eq!(summary.lines().count(), 1);
            if ext == "npy" {
                check_npy(&path, mode, w, h);
            } else {
                let img = image::open(&path).unwrap();
                assert_eq!((img.width(), img.height()), (w, h), "{mode}.{ext}");
                if ext == "exr" {
                    // A = hit: the centre pixel hits the square, the corner misses.
                    let f = img.into_rgba32f();
                    assert_eq!(f.get_pixel(w / 2, h / 2).0[3], 1.0, "{mode}");
                    assert_eq!(f.get_pixel(0, 0).0[3], 0.0, "{mode}");
                }
            }
        }
    }
    let leftovers: Vec<String> =
        names(dir.path()).into_iter().filter(|n| n.starts_with('.')).collect();
    assert!(leftovers.is_empty(), "{leftovers:?}");
}

fn check_npy(path: &Path, mode: &str, w: u32, h: u32) {
    let bytes = std::fs::read(path).unwrap();
    let header = String::from_utf8_lossy(&bytes[..128]).into_owned();
    let (descr, shape) = match mode {
        "alpha" => ("|u1", format!("({h}, {w})")),
        "depth" => ("<f4", format!("({h}, {w})")),
        "prim" => ("<u4", format!("({h}, {w})")),
        _ => ("<f4", format!("({h}, {w}, 3)")),
    };
    assert!(header.contains(&format!("'descr': '{descr}'")), "{mode}: {header}");
    assert!(header.contains(&format!("'shape': {shape}")), "{mode}: {header}");
    if mode == "depth" {
        // The hit distance along the unit ray is 4 / dir_z; a miss is +inf.
        let m = npy::read_f64_matrix(&bytes, w as usize).unwrap();
        for j in 0..h {
            for i in 0..w {
                let t = m.values[(j * w + i) as usize];
                match square_mask(i, j, w, h) {
                    Some(true) => {
                        let expect = 4.0 / origin_ray(i, j, w, h, 4.0).1;
                        assert!((t - expect).abs() < 1e-5 * expect, "({i}, {j}) {t} vs {expect}");
                    }
                    Some(false) => assert_eq!(t, f64::INFINITY),
                    None => {}
                }
            }
        }
    }
}

#[test]
fn auto_camera_frames_the_whole_mesh_and_eye_overrides() {
    let dir = tempfile::tempdir().unwrap();
    let obj = write(dir.path(), "square.obj", SQUARE);
    let png = dir.path().join("auto.png");
    ok(&raytrace(&[&obj, &png, &"30", &"20", &"-q"]));
    let img = image::open(&png).unwrap().into_luma8();
    let (w, h) = img.dimensions();
    let border =
        img.enumerate_pixels().filter(|(i, j, _)| *i == 0 || *j == 0 || *i == w - 1 || *j == h - 1);
    assert!(border.into_iter().all(|(_, _, p)| p.0[0] == 0), "the mesh touches the border");
    assert!(img.pixels().filter(|p| p.0[0] == 255).count() > 50);

    // From (0, 0, -4) towards the square's centre: distance 8, the square looks half as big
    // as from the origin, and its hit test is the origin's at depth 8.
    let npy_path = dir.path().join("far.npy");
    ok(&raytrace(&[
        &obj,
        &npy_path,
        &"24",
        &"24",
        &"--eye",
        &"0,0,-4",
        &"--look-at",
        &"0,0,4",
        &"--mode",
        &"depth",
        &"--precision",
        &"f64",
        &"-q",
    ]));
    let m = npy::read_f64_matrix(&std::fs::read(&npy_path).unwrap(), 24).unwrap();
    for j in 0..24 {
        for i in 0..24 {
            let ([x, y], dz) = origin_ray(i, j, 24, 24, 8.0);
            let t = m.values[(j * 24 + i) as usize];
            if x.abs().max(y.abs()) < 0.999 {
                // Depth frames hold f32.
                assert!((t - 8.0 / dz).abs() < 1e-5 * t, "({i}, {j}) {t}");
            } else if x.abs().max(y.abs()) > 1.001 {
                assert_eq!(t, f64::INFINITY);
            }
        }
    }
}

#[test]
fn stats_json_has_exactly_the_documented_keys() {
    let dir = tempfile::tempdir().unwrap();
    let obj = write(dir.path(), "square.obj", SQUARE);
    let stats = dir.path().join("stats.json");
    ok(&raytrace(&[
        &obj,
        &dir.path().join("a.png"),
        &"10",
        &"8",
        &"--stats",
        &stats,
        &"--threads",
        &"2",
        &"--backend",
        &"la-mt",
        &"--precision",
        &"f64",
        &"-q",
    ]));
    let v: serde_json::Value = serde_json::from_slice(&std::fs::read(&stats).unwrap()).unwrap();
    let fields = v.as_object().unwrap();
    let mut keys: Vec<&str> = fields.keys().map(String::as_str).collect();
    keys.sort_unstable();
    let expected = [
        "backend",
        "build_ms",
        "camera",
        "command",
        "commit",
        "inputs",
        "load_ms",
        "machine",
        "mrays_per_s",
        "output",
        "peak_memory_bytes",
        "precision",
        "program",
        "rays",
        "started",
        "threads",
        "trace_ms",
        "triangles",
        "version",
        "wall_ms",
        "write_ms",
    ];
    assert_eq!(keys, expected);
    // The run record: enough to repeat the run and to know the input is the same file.
    assert_eq!(v["program"], "raytrace");
    assert_eq!(v["version"], env!("CARGO_PKG_VERSION"));
    // Built from a checkout: the commit is a 40-digit hash, `-dirty` when modified; `null`
    // only where git cannot name one (a source archive).
    if let Some(commit) = v["commit"].as_str() {
        let hash = &commit[..40.min(commit.len())];
        assert!(hash.len() == 40 && hash.bytes().all(|b| b.is_ascii_hexdigit()), "{commit}");
        assert!(commit.len() == 40 || &commit[40..] == "-dirty", "{commit}");
    } else {
        let git = Command::new("git").args(["rev-parse", "HEAD"]).output();
        assert!(!git.is_ok_and(|o| o.status.success()), "a checkout, but no commit recorded");
    }
    assert_eq!(v["command"][1], obj.display().to_string());
    assert_eq!(v["command"].as_array().unwrap().len(), 14);
    let started = v["started"].as_str().unwrap();
    assert!(humantime::parse_rfc3339(started).is_ok(), "{started}");
    let input = &v["inputs"][0];
    assert_eq!((input["role"].as_str(), input["path"].as_str()), (Some("mesh"), obj.to_str()));
    assert_eq!(input["bytes"], SQUARE.len());
    let sha = input["sha256"].as_str().unwrap();
    assert!(sha.len() == 64 && sha.bytes().all(|b| b.is_ascii_hexdigit()), "{sha}");
    let output = &v["output"];
    assert_eq!(output["path"].as_str(), dir.path().join("a.png").to_str());
    assert_eq!((output["width"].as_u64(), output["height"].as_u64()), (Some(10), Some(8)));
    assert_eq!(output["mode"], "alpha");
    assert!(v["machine"]["cores"].as_u64().unwrap() >= 1);
    assert!(!v["machine"]["cpu"].as_str().unwrap().is_empty());
    assert!(v["machine"]["target_features"].is_string());
    assert!(v["machine"]["node_test"].as_str().unwrap().starts_with("f32 "));
    // The auto camera frames the square from -z.
    let eye = &v["camera"]["eye"];
    assert!(eye[2].as_f64().unwrap() < 4.0, "{eye}");
    assert_eq!(v["camera"]["up"], serde_json::json!([0.0, 1.0, 0.0]));
    assert_eq!(v["camera"]["fov_deg"], 45.0);
    assert_eq!(v["triangles"], 2);
    assert_eq!(v["rays"], 80);
    assert_eq!(v["threads"], 2);
    // Linux: at least the program's own code is resident; far less than a gigabyte here.
    let peak = v["peak_memory_bytes"].as_u64().unwrap();
    assert!((1 << 20..1 << 30).contains(&peak), "{peak}");
    assert_eq!(v["backend"], "la-mt");
    assert_eq!(v["precision"], "f64");
    for k in ["load_ms", "build_ms", "trace_ms", "write_ms", "wall_ms", "mrays_per_s"] {
        assert!(v[k].as_f64().unwrap() >= 0.0, "{k}");
    }
    // The wall time is the whole run's: at least the phases it contains.
    let phases: f64 = ["load_ms", "build_ms", "trace_ms", "write_ms"]
        .iter()
        .map(|k| v[k].as_f64().unwrap())
        .sum();
    assert!(v["wall_ms"].as_f64().unwrap() >= phases, "{v}");
}

#[test]
fn the_summary_prints_the_auto_camera_so_that_the_view_can_be_repeated() {
    let dir = tempfile::tempdir().unwrap();
    let obj = write(dir.path(), "tri.obj", UPPER_RIGHT);
    let (auto, again) = (dir.path().join("auto.npy"), dir.path().join("again.npy"));
    let line = ok(&raytrace(&[&obj, &auto, &"24", &"16", &"--mode", &"depth"]));
    let options = line.split(", camera ").nth(1).expect("camera in the summary");
    let options = options.split(" -> ").next().unwrap();
    assert!(options.starts_with("--eye ") && options.contains(" --fov 45"), "{line}");
    let mut args: Vec<String> = vec![
        obj.display().to_string(),
        again.display().to_string(),
        "24".into(),
        "16".into(),
        "--mode".into(),
        "depth".into(),
        // The origin placement, overridden by every option printed.
        "--camera".into(),
        "origin".into(),
    ];
    args.extend(options.split(' ').map(str::to_owned));
    let refs: Vec<&dyn AsRef<std::ffi::OsStr>> =
        args.iter().map(|a| a as &dyn AsRef<std::ffi::OsStr>).collect();
    ok(&raytrace(&refs));
    let (a, b) = (std::fs::read(&auto).unwrap(), std::fs::read(&again).unwrap());
    assert_eq!(a, b, "the printed camera renders the same depths");
    // Something was hit, so the comparison says something.
    let depths = npy::read_f64_matrix(&a, 24).unwrap();
    assert!(depths.values.iter().any(|d| d.is_finite() && *d > 0.0));
}

/// Rays from `(x, y, 0)` along `(0, 0, 2)` at the square: `t = 2` in units of the direction.
fn square_rays() -> Vec<[f64; 6]> {
    vec![
        [-0.5, 0.5, 0.0, 0.0, 0.0, 2.0],  // upper left: triangle 0
        [0.5, -0.25, 0.0, 0.0, 0.0, 2.0], // lower right: triangle 1
        [3.0, 0.0, 0.0, 0.0, 0.0, 2.0],   // beside the square
        [0.0, 0.0, 0.0, 0.0, 0.0, -1.0],  // away from it
        [f64::NAN, 0.0, 0.0, 0.0, 0.0, 1.0],
        [0.0, 0.0, 0.0, 0.0, 0.0, 0.0], // no direction
    ]
}

/// Barycentrics `(u, v)` of point `(x, y)` in triangle (a, b, c) of the square.
fn barycentrics(tri: usize, x: f64, y: f64) -> (f64, f64) {
    // Triangle 0: a = (-1,-1), b = (-1,1), c = (1,1); triangle 1: a = (-1,-1), b = (1,1), c =
    // (1,-1). p - a = u (b - a) + v (c - a), solved by hand for each.
    let (px, py) = (x + 1.0, y + 1.0);
    if tri == 0 { ((py - px) / 2.0, px / 2.0) } else { (py / 2.0, (px - py) / 2.0) }
}

#[test]
fn raycast_segments_and_extra_columns() {
    let dir = tempfile::tempdir().unwrap();
    let obj = write(dir.path(), "square.obj", SQUARE);
    let inf = f64::INFINITY;
    // Each ray meets the square at t = 2; the last two columns are t_min, t_max.
    let rays: Vec<[f64; 8]> = vec![
        [-0.5, 0.5, 0.0, 0.0, 0.0, 2.0, 0.0, 1.5], // ends before the square
        [-0.5, 0.5, 0.0, 0.0, 0.0, 2.0, 2.0, 2.0], // both ends inclusive
        [-0.5, 0.5, 0.0, 0.0, 0.0, 2.0, 2.5, inf], // starts past it
        [-0.5, 0.5, 0.0, 0.0, 0.0, 2.0, f64::NAN, inf],
        [0.5, -0.25, 0.0, 0.0, 0.0, 2.0, -1.0, inf], // a negative t_min acts as 0
    ];
    let rays_path = dir.path().join("segments.npy");
    let mut bytes = Vec::new();
    npy::write(&mut bytes, &[rays.len(), 8], rays.iter().flatten().copied()).unwrap();
    std::fs::write(&rays_path, bytes).unwrap();
    for precision in ["f32", "f64"] {
        let hits = dir.path().join(format!("hits-{precision}.npy"));
        let args: [&dyn AsRef<std::ffi::OsStr>; 7] =
            [&obj, &rays_path, &hits, &"--with", &"normal,point", &"--precision", &precision];
        ok(&raycast(&args));
        let m = npy::read_f64_matrix(&std::fs::read(&hits).unwrap(), 10).unwrap();
        let row = |r: usize| &m.values[10 * r..10 * r + 10];
        for r in [0, 2, 3] {
            assert_eq!((row(r)[0], row(r)[1]), (inf, -1.0), "{precision} ray {r}");
            assert!(row(r)[2..].iter().all(|x| x.is_nan()), "{precision} ray {r}: {:?}", row(r));
        }
        // t, triangle, then the point on the square and the triangles' normal, worked out by
        // hand: (b - a) x (c - a) = (0, 0, -4) for both triangles of SQUARE.
        for (r, tri, xy) in [(1, 0.0, [-0.5, 0.5]), (4, 1.0, [0.5, -0.25])] {
            let got = row(r);
            assert!((got[0] - 2.0).abs() < 1e-6 && got[1] == tri, "{precision} {got:?}");
            let point = [xy[0], xy[1], 4.0];
            assert!((0..3).all(|k| (got[4 + k] - point[k]).abs() < 1e-6), "{got:?}");
            assert_eq!(&got[7..], &[0.0, 0.0, -1.0], "{precision}");
        }
        // Any hit honours the segments too, and names the triangle.
        let any = dir.path().join(format!("any-{precision}.npy"));
        let args: [&dyn AsRef<std::ffi::OsStr>; 8] =
            [&obj, &rays_path, &any, &"--any-hit", &"--with", &"prim", &"--precision", &precision];
        ok(&raycast(&args));
        let m = npy::read_f64_matrix(&std::fs::read(&any).unwrap(), 2).unwrap();
        assert_eq!(m.values, [0.0, -1.0, 1.0, 0.0, 0.0, -1.0, 0.0, -1.0, 1.0, 1.0], "{precision}");
    }
    // Extras that do not go with the query, and a shape that is neither.
    let out = dir.path().join("bad.npy");
    fails(&raycast(&[&obj, &rays_path, &out, &"--any-hit", &"--with", &"point"]), "--any-hit");
    fails(&raycast(&[&obj, &rays_path, &out, &"--with", &"prim"]), "--any-hit");
    let seven = dir.path().join("seven.npy");
    let mut bytes = Vec::new();
    npy::write(&mut bytes, &[1, 7], [0.0; 7]).unwrap();
    std::fs::write(&seven, bytes).unwrap();
    fails(&raycast(&[&obj, &seven, &out]), "expected (N, 6) or (N, 8)");
    assert!(!out.exists());
}

#[test]
fn raycast_round_trip_f32_and_f64() {
    let dir = tempfile::tempdir().unwrap();
    let obj = write(dir.path(), "square.obj", SQUARE);
    let rays = square_rays();
    for dtype in ["f32", "f64"] {
        let rays_path = dir.path().join(format!("rays-{dtype}.npy"));
        let mut bytes = Vec::new();
        let flat = rays.iter().flatten().copied();
        if dtype == "f32" {
            npy::write(&mut bytes, &[rays.len(), 6], flat.map(|x| x as f32)).unwrap();
        } else {
            npy::write(&mut bytes, &[rays.len(), 6], flat).unwrap();
        }
        std::fs::write(&rays_path, bytes).unwrap();
        for precision in ["f32", "f64"] {
            let hits_path = dir.path().join(format!("hits-{dtype}-{precision}.npy"));
            let stats = dir.path().join("cast.json");
            let out = raycast(&[
                &obj,
                &rays_path,
                &hits_path,
                &"--precision",
                &precision,
                &"--stats",
                &stats,
            ]);
            assert!(ok(&out).contains("6 rays"));
            let hits = npy::read_f64_matrix(&std::fs::read(&hits_path).unwrap(), 4).unwrap();
            assert!(!hits.was_f32);
            assert_eq!(hits.rows, rays.len());
            let row = |r: usize| &hits.values[4 * r..4 * r + 4];
            for (r, tri) in [(0usize, 0usize), (1, 1)] {
                let (u, v) = barycentrics(tri, rays[r][0], rays[r][1]);
                let got = row(r);
                assert!((got[0] - 2.0).abs() < 1e-6, "{dtype} {precision} t = {}", got[0]);
                assert_eq!(got[1], tri as f64);
                assert!(
                    (got[2] - u).abs() < 1e-6 && (got[3] - v).abs() < 1e-6,
                    "{got:?} vs {u},{v}"
                );
            }
            for r in 2..rays.len() {
                let got = row(r);
                assert_eq!((got[0], got[1]), (f64::INFINITY, -1.0), "ray {r}");
                assert!(got[2].is_nan() && got[3].is_nan());
            }
            let v: serde_json::Value =
                serde_json::from_slice(&std::fs::read(&stats).unwrap()).unwrap();
            assert_eq!(v["rays"], 6);
            assert_eq!(v["program"], "raycast");
            let roles: Vec<&str> = v["inputs"]
                .as_array()
                .unwrap()
                .iter()
                .map(|f| f["role"].as_str().unwrap())
                .collect();
            assert_eq!(roles, ["mesh", "rays"]);
            let rays_bytes = std::fs::metadata(&rays_path).unwrap().len();
            assert_eq!(v["inputs"][1]["bytes"].as_u64(), Some(rays_bytes));
            assert_eq!(v["output"]["shape"], serde_json::json!([6, 4]));
            assert!(v.get("camera").is_none(), "raycast has no camera: {v}");
        }
        let any_path = dir.path().join("any.npy");
        ok(&raycast(&[&obj, &rays_path, &any_path, &"--any-hit", &"-q"]));
        let any = npy::read_f64_matrix(&std::fs::read(&any_path).unwrap(), 1).unwrap();
        assert_eq!(any.values, vec![1.0, 1.0, 0.0, 0.0, 0.0, 0.0]);
    }
}

#[test]
fn bad_render_inputs_fail_with_one_line_and_leave_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let good = write(d, "square.obj", SQUARE);
    let malformed = write(d, "bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x\n");
    let empty = write(d, "empty.obj", "v 0 0 0\nv 1 0 0\n");
    let nan = write(d, "nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n");
    let inputs = names(d);
    let out = d.join("out.png");
    let (gif, bare) = (d.join("out.gif"), d.join("out"));
    let cases: Vec<(Vec<&dyn AsRef<std::ffi::OsStr>>, &str)> = vec![
        (vec![&"/nonexistent/missing.obj", &out, &"8", &"8"], "missing.obj"),
        (vec![&malformed, &out, &"8", &"8"], "bad.obj:4"),
        (vec![&empty, &out, &"8", &"8"], "no faces"),
        (vec![&nan, &out, &"8", &"8"], "nan.obj:2"),
        // Sides are checked by the parser now (usage errors): the message gives the range.
        (vec![&good, &out, &"0", &"8"], "not in 1..=65535"),
        (vec![&good, &out, &"8", &"0"], "not in 1..=65535"),
        (vec![&good, &out, &"100000", &"100000"], "not in 1..=65535"),
        (vec![&good, &gif, &"8", &"8"], "unknown output format"),
        (vec![&good, &bare, &"8", &"8"], "unknown output format"),
        (vec![&good, &"/nonexistent/dir/x.png", &"8", &"8"], "/nonexistent/dir/x.png"),
        (vec![&good, &out, &"8", &"8", &"--stats", &"/nonexistent/s.json"], "s.json"),
        (vec![&good, &out, &"8", &"8", &"--eye", &"0,0,4", &"--look-at", &"0,0,4"], "coincide"),
        (vec![&good, &out, &"8", &"8", &"--fov", &"200"], "field of view"),
        (vec![&good, &out, &"8", &"8", &"--eye", &"1,2"], "X,Y,Z"),
        (vec![&good, &out, &"8", &"wide"], "HEIGHT"),
        (vec![&good, &out, &"8", &"8", &"--mode", &"colour"], "colour"),
    ];
    for (args, needle) in cases {
        fails(&raytrace(&args), needle);
        assert_eq!(names(d), inputs, "a file was left behind ({needle})");
    }
}

#[cfg(unix)]
#[test]
fn read_only_directory_is_refused_before_rendering() {
    use std::os::unix::fs::PermissionsExt;
    let dir = tempfile::tempdir().unwrap();
    let obj = write(dir.path(), "square.obj", SQUARE);
    let ro = dir.path().join("ro");
    std::fs::create_dir(&ro).unwrap();
    std::fs::set_permissions(&ro, std::fs::Permissions::from_mode(0o555)).unwrap();
    // Root (as in some containers) may write anyway: then there is nothing to test.
    if std::fs::write(ro.join("probe"), b"").is_ok() {
        std::fs::remove_file(ro.join("probe")).unwrap();
        return;
    }
    fails(&raytrace(&[&obj, &ro.join("x.png"), &"8", &"8"]), "cannot write");
    assert!(names(&ro).is_empty());
    std::fs::set_permissions(&ro, std::fs::Permissions::from_mode(0o755)).unwrap();
}

#[test]
fn bad_raycast_inputs_fail_with_one_line_and_leave_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let obj = write(d, "square.obj", SQUARE);
    let npy_file = |name: &str, descr: &str, fortran: &str, shape: &str, data: &[u8]| {
        let mut header =
            format!("{{'descr': '{descr}', 'fortran_order': {fortran}, 'shape': {shape}, }}");
        while (10 + header.len() + 1) % 64 != 0 {
            header.push(' ');
        }
        header.push('\n');
        let mut bytes = b"\x93NUMPY\x01\x00".to_vec();
        bytes.extend_from_slice(&(header.len() as u16).to_le_bytes());
        bytes.extend_from_slice(header.as_bytes());
        bytes.extend_from_slice(data);
        let p = d.join(name);
        std::fs::write(&p, bytes).unwrap();
        p
    };
    let ints = npy_file("ints.npy", "<i4", "False", "(1, 6)", &[0; 24]);
    let shape = npy_file("shape.npy", "<f4", "False", "(2, 5)", &[0; 40]);
    let short = npy_file("short.npy", "<f8", "False", "(2, 6)", &[0; 95]);
    let big_endian = npy_file("be.npy", ">f4", "False", "(1, 6)", &[0; 24]);
    let fortran = npy_file("fortran.npy", "<f4", "True", "(1, 6)", &[0; 24]);
    let text_file = write(d, "rays.txt", "0 0 0 0 0 1\n");
    let good = npy_file("good.npy", "<f4", "False", "(1, 6)", &[0; 24]);
    let inputs = names(d);
    let hits = d.join("hits.npy");
    let (none, no_obj, csv) = (d.join("none.npy"), d.join("no.obj"), d.join("hits.csv"));
    let cases: Vec<(Vec<&dyn AsRef<std::ffi::OsStr>>, &str)> = vec![
        (vec![&obj, &none, &hits], "none.npy: file not found"),
        (vec![&obj, &ints, &hits], "'<i4'"),
        (vec![&obj, &big_endian, &hits], "'>f4'"),
        (vec![&obj, &shape, &hits], "(2, 5)"),
        (vec![&obj, &short, &hits], "95 bytes"),
        (vec![&obj, &fortran, &hits], "Fortran"),
        (vec![&obj, &text_file, &hits], "not a NumPy"),
        (vec![&no_obj, &good, &hits], "no.obj"),
        (vec![&obj, &good, &csv], ".npy, .npz or .f64 extension"),
        (vec![&obj, &good, &"/nonexistent/hits.npy"], "/nonexistent/hits.npy"),
    ];
    for (args, needle) in cases {
        fails(&raycast(&args), needle);
        assert_eq!(names(d), inputs, "a file was left behind ({needle})");
    }
}

#[test]
fn report_star_is_upright_and_symmetric() {
    // The generated star (obj/star.obj): tip at (0, 1.5, 5), lowest points at y = -1.2135.
    // Seen from the origin its tip is at y/z = 0.3 and its lowest points at -0.2427.
    let star = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../obj/star.obj");
    let dir = tempfile::tempdir().unwrap();
    let png = dir.path().join("star.png");
    let n = 101u32;
    ok(&raytrace(&[&star, &png, &"101", &"101", &"--camera", &"origin", &"-q"]));
    let img = image::open(&png).unwrap().into_luma8();
    let hit = |i: u32, j: u32| img.get_pixel(i, j).0[0] == 255;
    let rows: Vec<u32> = (0..n).filter(|&j| (0..n).any(|i| hit(i, j))).collect();
    let (top, bottom) = (rows[0], *rows.last().unwrap());
    // Row j's centre is at y = (1 - 2 (j + 0.5) / n) tan(22.5 deg): the first row below the
    // tip, and the last row above the lowest points (a row or two less near those sharp
    // points, which the pixel centres may straddle).
    let t = 22.5f64.to_radians().tan();
    let y = |j: u32| (1.0 - 2.0 * (f64::from(j) + 0.5) / f64::from(n)) * t;
    let expect_top = (0..n).find(|&j| y(j) < 0.3).unwrap();
    let expect_bottom = (0..n).rev().find(|&j| y(j) > -1.213_525_492 / 5.0).unwrap();
    assert_eq!(top, expect_top, "the tip is at the top: not upside down");
    assert!(bottom <= expect_bottom && bottom + 3 >= expect_bottom, "{bottom} vs {expect_bottom}");
    // Symmetric about the vertical axis (the middle column is x = 0 exactly).
    let asymmetric = (0..n)
        .flat_map(|j| (0..n).map(move |i| (i, j)))
        .filter(|&(i, j)| hit(i, j) != hit(n - 1 - i, j))
        .count();
    assert!(asymmetric <= 4, "{asymmetric} pixels differ from their mirror image");
}

#[test]
fn each_program_names_itself() {
    let version = |out: Output| ok(&out);
    assert_eq!(
        version(raycast(&[&"--version"])),
        format!("raycast {}\n", env!("CARGO_PKG_VERSION"))
    );
    assert_eq!(
        version(raytrace(&[&"--version"])),
        format!("raytrace {}\n", env!("CARGO_PKG_VERSION"))
    );
    let cast = ok(&raycast(&[&"-h"]));
    assert!(cast.starts_with("Trace your own rays"), "{cast}");
    assert!(cast.contains("Usage: raycast "), "{cast}");
    let trace = ok(&raytrace(&[&"-h"]));
    assert!(trace.starts_with("Render a triangle mesh"), "{trace}");
    assert!(trace.contains("Usage: raytrace "), "{trace}");
}

#[test]
fn a_name_at_the_file_system_limit_is_written() {
    let dir = tempfile::tempdir().unwrap();
    let obj = write(dir.path(), "square.obj", SQUARE);
    // 255 bytes, Linux's NAME_MAX: the temporary file's name must still fit.
    let name = format!("{}.png", "n".repeat(251));
    let out = raytrace(&[&obj, &dir.path().join(&name), &"8", &"8", &"-q"]);
    assert_eq!(ok(&out), "");
    assert_eq!(names(dir.path()), [name, "square.obj".to_owned()]);
}

#[test]
fn threads_zero_is_one_per_core_and_nothing_is_drawn_off_a_terminal() {
    let dir = tempfile::tempdir().unwrap();
    let obj = write(dir.path(), "square.obj", SQUARE);
    let stats = dir.path().join("s.json");
    let out = raytrace(&[
        &obj,
        &dir.path().join("a.npy"),
        &"8",
        &"8",
        &"--threads",
        &"0",
        &"--stats",
        &stats,
    ]);
    ok(&out);
    assert!(
        out.stderr.is_empty(),
        "progress on a pipe: {:?}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&std::fs::read(&stats).unwrap()).unwrap();
    let cores = std::thread::available_parallelism().unwrap().get();
    assert_eq!(v["threads"], cores);
    // The earlier stats file is replaced; so is the image.
    let out = raytrace(&[&obj, &dir.path().join("a.npy"), &"4", &"2", &"--stats", &stats]);
    assert!(ok(&out).contains("8 rays"));
    let v: serde_json::Value = serde_json::from_slice(&std::fs::read(&stats).unwrap()).unwrap();
    assert_eq!(v["rays"], 8);
    assert_eq!(names(dir.path()), ["a.npy", "s.json", "square.obj"]);
}

/// `raycast` reads a file's rays straight into the kernel's precision; the library's
/// `cast::trace_rays` (the Python module's path) takes `f64` values and rounds each ray as it
/// traces it. Both must give the same rows, bit for bit: rays whose values round in `f32`,
/// rays finite in `f64` but not in `f32`, NaN bounds, zero directions, every back end of the
/// registry and both precisions, with and without bounds.
#[test]
fn raycast_reads_rays_rounded_as_the_library_rounds_them() {
    struct Library<'a> {
        mesh: &'a scene::Mesh,
        rays: &'a [f64],
        stride: usize,
    }
    impl backends::Job for Library<'_> {
        type Output = Vec<f64>;
        fn run<I: intersect::Intersector + 'static>(self, intersector: I) -> Vec<f64> {
            let accel = bvh::accel::Accel::build(intersector, &self.mesh.triangles());
            let columns = render::cast::Columns { point: true, normal: true, ..Default::default() };
            let mut out = vec![0.0; self.rays.len() / self.stride * columns.count()];
            render::cast::trace_rays(
                &accel,
                self.mesh,
                self.rays,
                self.stride,
                columns,
                &mut out,
                &|_| {},
            );
            out
        }
    }

    let dir = tempfile::tempdir().unwrap();
    let obj = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../obj/torus.obj");
    let mesh = scene::Mesh::load(&obj).unwrap();
    // Origins on a ring around the torus, aimed at points near its centre, in thirds and
    // sevenths (inexact in f32), then the special rays.
    let mut rays = Vec::new();
    for k in 0..400 {
        let a = f64::from(k) / 7.0;
        let o = [3.0 * a.cos(), 1.0 / 3.0 + (a * 3.0).sin(), 3.0 * a.sin()];
        let aim = [f64::from(k % 9) / 30.0, f64::from(k % 5) / 21.0 - 0.1, 0.1 / 3.0];
        let d = [aim[0] - o[0], aim[1] - o[1], aim[2] - o[2]];
        let (t_min, t_max) = (f64::from(k % 4) / 3.0, 1.0 + f64::from(k % 11) / 7.0);
        rays.push([o[0], o[1], o[2], d[0], d[1], d[2], t_min, t_max]);
    }
    let aimed = [0.0, 0.0, 3.0, 0.01, 0.02, -1.0, 0.0, f64::INFINITY];
    let mut special = |k: usize, x: f64| {
        let mut r = aimed;
        r[k] = x;
        rays.push(r);
    };
    special(0, 1e300); // finite in f64, infinite in f32: a miss in f32 only
    special(2, 1e-300); // zero in f32
    special(6, f64::NAN);
    special(7, f64::NAN);
    special(7, 1e-50);
    special(5, 0.0);
    rays.push([0.0, 0.0, 3.0, 0.0, 0.0, 0.0, 0.0, 1.0]);
    let out = dir.path().join("hits.npy");
    for stride in [6, 8] {
        let values: Vec<f64> = rays.iter().flat_map(|r| r[..stride].to_vec()).collect();
        let rays_path = dir.path().join(format!("rays-{stride}.npy"));
        let mut bytes = Vec::new();
        npy::write(&mut bytes, &[rays.len(), stride], values.iter().copied()).unwrap();
        std::fs::write(&rays_path, bytes).unwrap();
        for backend in backends::Backend::ALL {
            for precision in backends::Precision::ALL {
                let (name, digits) = (backend.name(), precision.name());
                let args: [&dyn AsRef<std::ffi::OsStr>; 10] = [
                    &obj,
                    &rays_path,
                    &out,
                    &"--backend",
                    &name,
                    &"--precision",
                    &digits,
                    &"--with",
                    &"point,normal",
                    &"-q",
                ];
                ok(&raycast(&args));
                let got = npy::read_f64_matrix(&std::fs::read(&out).unwrap(), 10).unwrap();
                let job = Library { mesh: &mesh, rays: &values, stride };
                let want = backends::dispatch(backend, precision, job);
                let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
                assert_eq!(bits(&got.values), bits(&want), "{name} {digits} stride {stride}");
                let hits = want.chunks_exact(10).filter(|r| r[1] >= 0.0).count();
                assert!(hits > 50, "{name} {digits}: only {hits} hits");
            }
        }
    }
}
