//! Golden images from scenes whose answer is known in closed form, for every back end and
//! precision.
//!
//! The expected image is computed here from the camera contract (written out again by hand in
//! [`contract_dir`], not taken from `render::camera`) and the scene's analytic geometry. Each
//! pixel is either expected to **miss**, expected to **hit** at a known distance (or within
//! known bounds), on a known triangle where that is decided, or **not judged** because its ray
//! passes within [`UNDECIDED_BAND`] of an edge, where rounding may go either way. The metrics,
//! per configuration:
//!
//! | metric | tolerance |
//! |---|---|
//! | pixels whose hit or miss (in the `alpha` frame and the closest-hit query) is wrong | 0 |
//! | pixels whose `prim` frame names the wrong triangle | 0 |
//! | largest relative depth error `dist(t, [t_lo, t_hi]) / t_lo` of the closest hit, in the back end's precision | `1e-5` (`f32`), `1e-12` (`f64`) |
//! | pixels not judged | a bound per scene (about the band's share of the image) |
//!
//! (The `depth` frame holds the same `t` rounded to `f32`; `backends_agree.rs` checks that the
//! frames equal the per-pixel queries.)
//!
//! On failure the test writes a diff image (colours: `common::LEGEND`) to
//! `target/test-output/golden-<scene>-<config>-diff.png` and names it in the message.

mod common;

use common::{
    BLACK, BLUE, DARK_GREY, GREY, LEGEND, RED, Scene, WHITE, YELLOW, camera, trace_all,
    write_diff_image,
};
use render::camera::Camera;
use scene::Mesh;

/// Rays passing nearer than this to an edge (in scene units, on scenes of unit size) are not
/// judged. `f32` rounding of the ray and the vertices moves a hit point by about `1e-6` at
/// these distances; a pixel is about `0.03` wide.
const UNDECIDED_BAND: f64 = 1e-5;

/// `tan(fov / 2)` for the default 45 degree field of view.
fn tan_half_fov() -> f64 {
    22.5f64.to_radians().tan()
}

/// The unit direction of the ray through the centre of pixel `(i, j)` of a `w x h` image, for
/// a camera looking along +z with +y up (every camera here): the contract of
/// `render::camera`, `x = (2 (i + 0.5) / W - 1) tan(fov / 2) W / H`,
/// `y = (1 - 2 (j + 0.5) / H) tan(fov / 2)`, `dir = normalize((x, y, 1))`.
fn contract_dir(i: u32, j: u32, w: u32, h: u32) -> [f64; 3] {
    let (w, h) = (f64::from(w), f64::from(h));
    let x = (2.0 * (f64::from(i) + 0.5) / w - 1.0) * tan_half_fov() * w / h;
    let y = (1.0 - 2.0 * (f64::from(j) + 0.5) / h) * tan_half_fov();
    let n = (x * x + y * y + 1.0).sqrt();
    [x / n, y / n, 1.0 / n]
}

/// What a pixel should show.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Expect {
    /// Not judged: the ray passes too near an edge, or through a band the analysis leaves
    /// open.
    Either,
    /// No hit.
    Miss,
    /// A hit at a distance in `[t_lo, t_hi]` (equal when known exactly), on triangle `prim`
    /// when that is decided (`None` near an edge between two triangles).
    Hit { t_lo: f64, t_hi: f64, prim: Option<u32> },
}

/// A flat scene in a plane `z = plane_z`, seen by a camera at `(0, 0, eye_z)` looking along
/// +z: its outline (a simple polygon) decides hit or miss, its triangles (with their mesh
/// indices) which one is hit.
struct Planar {
    eye_z: f64,
    plane_z: f64,
    outline: Vec<[f64; 2]>,
    triangles: Vec<(u32, [[f64; 2]; 3])>,
}

impl Planar {
    fn expect(&self, i: u32, j: u32, w: u32, h: u32) -> Expect {
        let d = contract_dir(i, j, w, h);
        let t = (self.plane_z - self.eye_z) / d[2];
        let p = [t * d[0], t * d[1]];
        let n = self.outline.len();
        let edges = (0..n).map(|k| (self.outline[k], self.outline[(k + 1) % n]));
        if edges.clone().map(|(a, b)| segment_distance(p, a, b)).fold(f64::INFINITY, f64::min)
            < UNDECIDED_BAND
        {
            return Expect::Either;
        }
        // Crossing number: the outline is at least the band away, so no tie.
        let crossings = edges
            .filter(|(a, b)| {
                (a[1] > p[1]) != (b[1] > p[1])
                    && p[0] < a[0] + (p[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1])
            })
            .count();
        if crossings % 2 == 0 {
            return Expect::Miss;
        }
        let prim = self
            .triangles
            .iter()
            .find(|(_, tri)| inside_by(p, tri) > UNDECIDED_BAND)
            .map(|&(k, _)| k);
        Expect::Hit { t_lo: t, t_hi: t, prim }
    }
}

/// Distance from `p` to the segment `a b`.
fn segment_distance(p: [f64; 2], a: [f64; 2], b: [f64; 2]) -> f64 {
    let (e, w) = ([b[0] - a[0], b[1] - a[1]], [p[0] - a[0], p[1] - a[1]]);
    let s = ((w[0] * e[0] + w[1] * e[1]) / (e[0] * e[0] + e[1] * e[1])).clamp(0.0, 1.0);
    (w[0] - s * e[0]).hypot(w[1] - s * e[1])
}

/// How far `p` is inside the triangle: the smallest distance to the lines of its edges,
/// negative outside (either winding).
fn inside_by(p: [f64; 2], tri: &[[f64; 2]; 3]) -> f64 {
    let cross = |a: [f64; 2], b: [f64; 2], q: [f64; 2]| {
        (b[0] - a[0]) * (q[1] - a[1]) - (b[1] - a[1]) * (q[0] - a[0])
    };
    let sign = cross(tri[0], tri[1], tri[2]).signum();
    (0..3)
        .map(|k| {
            let (a, b) = (tri[k], tri[(k + 1) % 3]);
            sign * cross(a, b, p) / (b[0] - a[0]).hypot(b[1] - a[1])
        })
        .fold(f64::INFINITY, f64::min)
}

/// The triangles of `mesh` lying in the plane `z = plane_z`, projected, with their indices.
fn triangles_in_plane(mesh: &Mesh, plane_z: f64) -> Vec<(u32, [[f64; 2]; 3])> {
    (0..mesh.len())
        .filter_map(|k| {
            let vertices = mesh.triangle::<f64>(k).vertices();
            vertices
                .iter()
                .all(|v| v[2] == plane_z)
                .then(|| (k as u32, vertices.map(|v| [v[0], v[1]])))
        })
        .collect()
}

/// Total area of projected triangles.
fn area(triangles: &[(u32, [[f64; 2]; 3])]) -> f64 {
    triangles
        .iter()
        .map(|(_, [a, b, c])| {
            ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])).abs() / 2.0
        })
        .sum()
}

/// Renders `scene` through every configuration and compares each with `expect`; at most
/// `max_undecided` pixels may be left unjudged.
fn golden(scene: &Scene, max_undecided: usize, expect: impl Fn(u32, u32) -> Expect) {
    let expected: Vec<Expect> = (0..scene.pixels())
        .map(|p| {
            let (i, j) = scene.ij(p);
            expect(i, j)
        })
        .collect();
    let undecided = expected.iter().filter(|e| **e == Expect::Either).count();
    assert!(
        undecided <= max_undecided,
        "{}: {undecided} pixels too near an edge to judge (at most {max_undecided})",
        scene.name
    );
    assert!(expected.iter().any(|e| matches!(e, Expect::Hit { .. })), "nothing to hit");
    assert!(expected.contains(&Expect::Miss), "nothing to miss");

    let count = |f: fn(&Expect) -> bool| expected.iter().filter(|e| f(e)).count();
    // Seen with `--nocapture`.
    println!(
        "{}: {} pixels, {} expected hits, {} expected misses, {undecided} not judged",
        scene.name,
        scene.pixels(),
        count(|e| matches!(e, Expect::Hit { .. })),
        count(|e| *e == Expect::Miss),
    );
    let (mut failures, mut worst_depths) = (Vec::new(), Vec::new());
    for traced in trace_all(scene, &[]) {
        let config = traced.config;
        let tolerance = config.depth_tolerance();
        let (mut mask_wrong, mut prim_wrong, mut depth_wrong, mut worst) = (0, 0, 0, 0.0f64);
        let mut notes = Vec::new();
        let mut colours = Vec::with_capacity(scene.pixels());
        for (p, e) in expected.iter().enumerate() {
            let (i, j) = scene.ij(p);
            let (alpha, hit) = (traced.alpha[p], traced.hits[p]);
            let colour = match (*e, hit) {
                (Expect::Either, _) => {
                    if alpha {
                        GREY
                    } else {
                        DARK_GREY
                    }
                }
                (Expect::Miss, None) if !alpha => BLACK,
                (Expect::Miss, _) => {
                    mask_wrong += 1;
                    notes.push(format!("({i}, {j}) expected a miss, got {hit:?} (alpha {alpha})"));
                    BLUE
                }
                (Expect::Hit { t_lo, t_hi, prim }, Some(hit)) if alpha => {
                    let error = (t_lo - hit.t).max(hit.t - t_hi).max(0.0) / t_lo;
                    worst = worst.max(error);
                    let frame_prim = traced.prim_frame[p];
                    let wrong_prim = prim.is_some_and(|k| frame_prim != k);
                    if wrong_prim {
                        prim_wrong += 1;
                        notes.push(format!(
                            "({i}, {j}) expected triangle {prim:?}, the prim frame says \
                             {frame_prim}"
                        ));
                    }
                    if error > tolerance {
                        depth_wrong += 1;
                        notes.push(format!(
                            "({i}, {j}) expected t in [{t_lo}, {t_hi}], got {} (relative \
                             error {error:.3e})",
                            hit.t
                        ));
                    }
                    if wrong_prim || error > tolerance { YELLOW } else { WHITE }
                }
                (Expect::Hit { t_lo, .. }, _) => {
                    mask_wrong += 1;
                    notes.push(format!(
                        "({i}, {j}) expected a hit at t = {t_lo}, got {hit:?} (alpha {alpha})"
                    ));
                    RED
                }
            };
            colours.push(colour);
        }
        if mask_wrong + prim_wrong + depth_wrong > 0 {
            let name = format!("golden-{}-{}", scene.name, config.name());
            let image = write_diff_image(&name, scene.width, scene.height, &colours);
            failures.push(format!(
                "{}: {mask_wrong} pixels hit/miss wrong (tolerance 0), {prim_wrong} wrong \
                 triangles (tolerance 0), largest relative depth error {worst:.3e} (tolerance \
                 {tolerance:e}, exceeded on {depth_wrong} pixels); diff image {image}\n    {}",
                config.name(),
                notes.iter().take(6).cloned().collect::<Vec<_>>().join("\n    ")
            ));
        }
        worst_depths.push(format!("{} {worst:.1e}", config.name()));
    }
    println!("{}: largest relative depth errors: {}", scene.name, worst_depths.join(", "));
    assert!(
        failures.is_empty(),
        "{} golden image ({LEGEND}):\n{}",
        scene.name,
        failures.join("\n")
    );
}

/// A rectangle off the image centre (so that a mirrored or flipped image fails), in front of
/// the report's camera, built here as OBJ text: triangle 0 is the half above the diagonal from
/// its lower-left to its upper-right corner, triangle 1 the half below.
#[test]
fn rectangle_in_front_of_the_origin_camera() {
    let (x0, x1, y0, y1, z) = (-1.5, 0.5, -0.25, 1.0, 3.0);
    let obj = format!(
        "v {x0} {y0} {z}\nv {x1} {y0} {z}\nv {x1} {y1} {z}\nv {x0} {y1} {z}\nf 1 4 3\nf 1 3 2\n"
    );
    let mesh = Mesh::from_obj_str(&obj, "rectangle.obj").unwrap();
    let planar = Planar {
        eye_z: 0.0,
        plane_z: z,
        outline: vec![[x0, y0], [x1, y0], [x1, y1], [x0, y1]],
        triangles: vec![(0, [[x0, y0], [x0, y1], [x1, y1]]), (1, [[x0, y0], [x1, y1], [x1, y0]])],
    };
    // Odd sizes: pixel centres fall on the axes, and a half-pixel slip would show.
    let scene = Scene::new("rectangle", mesh, Camera::origin(), 101, 75);
    golden(&scene, 10, |i, j| planar.expect(i, j, 101, 75));
}

/// The unit cube face-on from `(0, 0, -3)`: only its front face `z = -0.5` shows (the side
/// faces hide behind its outline in perspective), a square at distance 2.5. The centre pixel
/// of an odd-sized image looks exactly along +z, through the diagonal the face's two triangles
/// share: every back end must hit it, at exactly `t = 2.5` to the tolerance.
#[test]
fn cube_face_on() {
    let (w, h) = (97, 97);
    let scene = Scene::obj("cube.obj", camera([0.0, 0.0, -3.0], [0.0; 3]), w, h);
    let front = triangles_in_plane(&scene.mesh, -0.5);
    assert_eq!((front.len(), area(&front)), (2, 1.0), "the front face is two triangles");
    let planar = Planar {
        eye_z: -3.0,
        plane_z: -0.5,
        outline: vec![[-0.5, -0.5], [0.5, -0.5], [0.5, 0.5], [-0.5, 0.5]],
        triangles: front,
    };
    let centre = planar.expect(w / 2, h / 2, w, h);
    assert_eq!(centre, Expect::Hit { t_lo: 2.5, t_hi: 2.5, prim: None }, "centre pixel");
    golden(&scene, 10, |i, j| planar.expect(i, j, w, h));
}

/// The report's star from the report's camera: its outline and fan are computed here from the
/// documented construction (points of radius 1.5 and notches of radius 1.5 (3 - sqrt 5) / 2,
/// 36 degrees apart clockwise from straight up, triangle `k` from the centre to vertices
/// `k + 1` and `k + 2`). The centre pixel of an odd-sized image looks through the vertex all
/// ten triangles share.
#[test]
fn star_from_the_origin_camera() {
    let (w, h) = (101, 101);
    let scene = Scene::obj("star.obj", Camera::origin(), w, h);
    let rim: Vec<[f64; 2]> = (0..10)
        .map(|k| {
            let radius = if k % 2 == 0 { 1.5 } else { 1.5 * (3.0 - 5f64.sqrt()) / 2.0 };
            let angle = (90.0 - 36.0 * f64::from(k)).to_radians();
            [radius * angle.cos(), radius * angle.sin()]
        })
        .collect();
    let triangles = (0..10).map(|k| (k as u32, [[0.0, 0.0], rim[k], rim[(k + 1) % 10]])).collect();
    let planar = Planar { eye_z: 0.0, plane_z: 5.0, outline: rim, triangles };
    assert_eq!(
        planar.expect(w / 2, h / 2, w, h),
        Expect::Hit { t_lo: 5.0, t_hi: 5.0, prim: None },
        "the centre pixel"
    );
    golden(&scene, 10, |i, j| planar.expect(i, j, w, h));
}

/// 16 x 16 tiles covering `[-1, 1]^2` in `z = 0`, from `(0, 0, -3)`: the square's outline, and
/// each pixel on the tile triangle under it. The centre pixel of an odd-sized image looks
/// through a lattice vertex shared by six triangles.
#[test]
fn tiles_face_on() {
    let (w, h) = (97, 97);
    let scene = Scene::obj("tiles.obj", camera([0.0, 0.0, -3.0], [0.0; 3]), w, h);
    let triangles = triangles_in_plane(&scene.mesh, 0.0);
    assert_eq!((triangles.len(), area(&triangles)), (512, 4.0), "tiles cover [-1, 1]^2");
    let planar = Planar {
        eye_z: -3.0,
        plane_z: 0.0,
        outline: vec![[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]],
        triangles,
    };
    golden(&scene, 10, |i, j| planar.expect(i, j, w, h));
}

/// The icosphere from `(0, 0, -4)`: every vertex lies on the unit sphere (to the file's 9
/// decimals) and the mesh is star-shaped around the centre, so it lies between the sphere
/// through its farthest vertex and the sphere touching its nearest face plane. A ray passing
/// the centre nearer than the inner radius must hit, between the two spheres' entry
/// distances; one passing farther than the outer radius must miss; the thin ring between is
/// not judged.
#[test]
fn icosphere_between_its_inner_and_outer_spheres() {
    let (w, h) = (96, 96);
    let eye_z = -4.0;
    let scene = Scene::obj("icosphere.obj", camera([0.0, 0.0, eye_z], [0.0; 3]), w, h);
    let mesh = &scene.mesh;
    let outer = mesh.positions.iter().map(|v| common::norm(*v)).fold(0.0, f64::max);
    let inner = (0..mesh.len())
        .map(|k| {
            let t = mesh.triangle::<f64>(k);
            let n = common::cross(common::sub(t.b, t.a), common::sub(t.c, t.a));
            common::dot(n, t.a).abs() / common::norm(n)
        })
        .fold(f64::INFINITY, f64::min);
    assert!(inner > 0.99 && (outer - 1.0).abs() < 1e-8, "inner {inner}, outer {outer}");
    let expect = |i, j| {
        let d = contract_dir(i, j, w, h);
        // Distance of the ray's line from the centre, and the parameter of closest approach.
        let (b, s) = (-eye_z * d[0].hypot(d[1]), -eye_z * d[2]);
        if b < inner - UNDECIDED_BAND {
            let entry = |r: f64| s - (r * r - b * b).sqrt();
            Expect::Hit { t_lo: entry(outer), t_hi: entry(inner), prim: None }
        } else if b > outer + UNDECIDED_BAND {
            Expect::Miss
        } else {
            Expect::Either
        }
    };
    // The ring is about 0.003 wide against a radius of 29 pixels: some 20 pixels.
    golden(&scene, 60, expect);
}
