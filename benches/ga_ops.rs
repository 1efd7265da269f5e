//! G3, PGA and CGA operations beside their glam counterparts, f32 and f64, on the same machine
//! and inputs.
//!
//! Each benchmark maps one operation over a fixed array of `BATCH` random inputs (fixed seed),
//! reached through `black_box` so that neither side can be constant-folded, and passes every
//! result through `black_box` so that none is discarded. Both sides pay the same loop and
//! store overhead; the figure is the median of criterion's samples (time per iteration)
//! divided by `BATCH`, i.e. throughput per operation, not latency. `BATCH` inputs fit in L1 for
//! every type. The median rather than the mean: on a shared machine a few samples come out
//! slow (an interrupt, a descheduling), and at a fraction of a nanosecond per operation they
//! moved the mean by more than the 10% these figures are held to.
//!
//! **Clock.** Time is the benchmark thread's CPU time (`CLOCK_THREAD_CPUTIME_ID`), not wall
//! time: the machine these figures come from is shared (two cores, other jobs compiling), and
//! a thread's CPU time stops while it is descheduled, so figures in the nanosecond range stay
//! meaningful under load. Set `WEDGE_BENCH_WALL=1` to measure wall time instead (criterion's
//! default) on a quiet machine. Both sides of a comparison always use the same clock.
//!
//! **The ratio: paired.** Criterion times the GA side for a few seconds, then the glam side.
//! On the machine of `results/` the speed of the host drifts over seconds, and two full runs
//! of the same binary gave ratios of 1.23 and 0.62 for `Rotor::reverse` against
//! `Quat::inverse`, which compile to the same three instructions. So the ratio in the CSV comes
//! from a paired measurement: 101 rounds, each timing a burst of 200 batches of the GA side and
//! one of the glam side back to back (which goes first alternates), and the median of the
//! rounds' ratios. Both sides of a round see the machine in the same state; the same two
//! instruction sequences then measured 1.000 and 0.995 in two runs.
//!
//! After the groups have run, `main` reads criterion's estimates
//! (`<criterion dir>/<group>/{ga,glam}/new/estimates.json`, the median's point estimate; see
//! `wedge_benches::median_ns`) and writes `results/ga_ops.csv`, one row per operation and
//! precision: criterion's times, the paired ratio, and the target each GA operation is held
//! to: a paired ratio of at most 1.1, or, for the full geometric product of two multivectors
//! of each algebra (glam has no counterpart), a criterion median within 1.2x of the machine's
//! bound: the product's non-zero terms (64 in G3, 192 in PGA, 1024 in CGA; counted from
//! `ga-reference`) times the time of one fused multiply-add at full throughput, measured in
//! the same run (`fma_ns`).
//!
//! Run: `cargo bench -p wedge-benches --bench ga_ops`. With `WEDGE_BENCH_QUICK=1` every
//! benchmark runs for a few milliseconds and the CSV goes to the criterion directory instead
//! of `results/` (a smoke test, not a measurement); so does a run filtered to some benchmarks.
//!
//! **Loop alignment.** The loops measured here are a handful of instructions; where the linker
//! happens to place one across a 64-byte boundary it can take an extra cycle per iteration
//! (seen here: `Rotor::reverse` and `Quat::inverse` compile to the same five instructions, and
//! the copy that straddled a boundary measured 2x slower). The recorded figures therefore come
//! from a build that aligns every loop:
//! `RUSTFLAGS="-C target-cpu=native -C llvm-args=-align-loops=64" cargo bench -p wedge-benches
//! --bench ga_ops` (`RUSTFLAGS` replaces the rustflags of `.cargo/config.toml`, hence the
//! repeated `target-cpu`).

use std::hint::black_box;
use std::time::{Duration, SystemTime};

use criterion::{Criterion, Throughput};
use ga::g3::{Multivector, Rotor, Vector};
use ga::{cga, pga};
use glam::{Affine3A, DAffine3, DQuat, DVec3, Quat, Vec3, Vec3A};
use wedge_benches::clock::{ThreadClock, configured};
use wedge_benches::{
    GaOpsFigures, GaOpsRow, SplitMix64, Target, criterion_dir, machine, median, median_ns,
    output_path, quick_mode, write_csv,
};

/// Inputs per iteration: 256 pairs of the largest type (two `Multivector<f64>`, 128 bytes)
/// make 32 KiB, the size of L1.
const BATCH: usize = 256;
/// Points a call of the one-motor-many-points rows.
const POINTS: usize = 64;

/// One comparison: which operation, at which precision, held to what.
struct Spec {
    op: &'static str,
    precision: &'static str,
    target: Target,
    /// The paired measurement's ratio; `None` exactly when glam has no counterpart.
    paired_ratio: Option<f64>,
}

impl Spec {
    fn group(&self) -> String {
        format!("{}_{}", self.op, self.precision)
    }
}

/// Rounds of the paired measurement, and batches per burst: full run, quick run.
const PAIRED: [(usize, u32); 2] = [(101, 200), (3, 2)];

/// `op`, with its argument type fixed by `inputs` (a closure's parameter type is inferred only
/// where the closure is used, and each is used twice).
fn typed<I, O>(_inputs: &[I], op: impl Fn(&I) -> O) -> impl Fn(&I) -> O {
    op
}

/// `op` mapped over `inputs` once: one batch, the unit both measurements time.
#[inline(always)]
fn map_once<I, O>(inputs: &[I], op: &impl Fn(&I) -> O) {
    for x in black_box(inputs) {
        black_box(op(x));
    }
}

/// Nanoseconds per operation of one burst: `op` mapped over `inputs`, `batches` times.
fn burst<I, O>(clock: &ThreadClock, inputs: &[I], op: &impl Fn(&I) -> O, batches: u32) -> f64 {
    let start = clock.now();
    for _ in 0..batches {
        map_once(inputs, op);
    }
    let ns = clock.now().saturating_sub(start).as_secs_f64() * 1e9;
    ns / f64::from(batches) / BATCH as f64
}

/// The median over rounds of `ga`'s time over `glam`'s, the two timed back to back in each
/// round (which goes first alternates), so that both sides of a ratio see the machine in the
/// same state.
fn paired_ratio(rounds: usize, mut ga: impl FnMut() -> f64, mut glam: impl FnMut() -> f64) -> f64 {
    let mut ratios: Vec<f64> = (0..rounds)
        .map(|round| {
            if round % 2 == 1 {
                let glam_ns = glam();
                ga() / glam_ns
            } else {
                ga() / glam()
            }
        })
        .collect();
    median(&mut ratios)
}

/// Maps `op` over `inputs` once per iteration.
fn map_batch<I, O>(
    b: &mut criterion::Bencher<'_, ThreadClock>,
    inputs: &[I],
    op: impl Fn(&I) -> O,
) {
    b.iter(|| map_once(inputs, &op));
}

/// Benchmarks the GA side and the glam side of `spec` in one criterion group. Both closures
/// are generic parameters, so each side is monomorphised and inlined alike.
fn bench_pair<I, O, J, P>(
    c: &mut Criterion<ThreadClock>,
    spec: &Spec,
    (ga_inputs, ga): (&[I], impl Fn(&I) -> O),
    (glam_inputs, glam): (&[J], impl Fn(&J) -> P),
) {
    let mut group = c.benchmark_group(spec.group());
    group.throughput(Throughput::Elements(BATCH as u64));
    group.bench_function("ga", |b| map_batch(b, ga_inputs, &ga));
    group.bench_function("glam", |b| map_batch(b, glam_inputs, &glam));
    group.finish();
}

/// Benchmarks a GA operation that glam has no counterpart for.
fn bench_ga<I, O>(
    c: &mut Criterion<ThreadClock>,
    spec: &Spec,
    (inputs, ga): (&[I], impl Fn(&I) -> O),
) {
    let mut group = c.benchmark_group(spec.group());
    group.throughput(Throughput::Elements(BATCH as u64));
    group.bench_function("ga", |b| map_batch(b, inputs, &ga));
    group.finish();
}

/// Random inputs in both representations, from the same numbers.
struct Inputs {
    vectors32: Vec<(Vector<f32>, Vector<f32>)>,
    vec3s: Vec<(Vec3, Vec3)>,
    vectors64: Vec<(Vector<f64>, Vector<f64>)>,
    dvec3s: Vec<(DVec3, DVec3)>,
    rotors32: Vec<(Rotor<f32>, Rotor<f32>, Vector<f32>)>,
    quats: Vec<(Quat, Quat, Vec3)>,
    rotors64: Vec<(Rotor<f64>, Rotor<f64>, Vector<f64>)>,
    dquats: Vec<(DQuat, DQuat, DVec3)>,
    multivectors32: Vec<(Multivector<f32>, Multivector<f32>)>,
    multivectors64: Vec<(Multivector<f64>, Multivector<f64>)>,
    pga32: Vec<PgaCase<f32>>,
    pga64: Vec<PgaCase<f64>>,
    cga32: Vec<CgaCase<f32>>,
    cga64: Vec<CgaCase<f64>>,
    affine32: Vec<AffineCase<Affine3A, Vec3A, f32>>,
    affine64: Vec<AffineCase<DAffine3, DVec3, f64>>,
}

/// One random rigid motion pair, point pair and plane in PGA's representation.
#[derive(Clone, Copy)]
struct PgaCase<T: ga::Scalar> {
    motors: (pga::Motor<T>, pga::Motor<T>),
    points: (pga::Point<T>, pga::Point<T>),
    /// The line through the two points (the ray's line).
    line: pga::Line<T>,
    plane: pga::Plane<T>,
    multivectors: (pga::Multivector<T>, pga::Multivector<T>),
}

/// The same numbers in CGA's representation (points are null vectors `up(x)`).
#[derive(Clone, Copy)]
struct CgaCase<T: ga::Scalar> {
    motors: (cga::Motor<T>, cga::Motor<T>),
    /// The first point as a Euclidean vector, as `Motor::transform_point` takes it.
    x: Vector<T>,
    points: (cga::Vector<T>, cga::Vector<T>),
    /// The flat line through the two points, `p ^ q ^ e_inf`.
    line: cga::Trivector<T>,
    /// The dual plane `n + d e_inf`.
    plane: cga::Vector<T>,
    multivectors: (cga::Multivector<T>, cga::Multivector<T>),
}

/// The same numbers for glam: the two motions as affine maps, the two points, the ray from the
/// first point towards the second and the plane as normal and offset (`n · x = d`).
#[derive(Clone, Copy)]
struct AffineCase<A, V, S> {
    maps: (A, A),
    points: (V, V),
    ray: (V, V),
    plane: (V, S),
}

fn unit_rotor(rng: &mut SplitMix64) -> Rotor<f64> {
    let [s, e12, e23, e31] = rng.array();
    Rotor::new(s, e12, e23, e31).normalize()
}

/// The raw numbers of one PGA/CGA/glam case: two rigid motions (axis, angle, translation), two
/// points, a plane (normal, offset) and two multivectors' coefficients.
struct Raw {
    motions: [([f64; 3], f64, [f64; 3]); 2],
    points: [[f64; 3]; 2],
    plane: ([f64; 3], f64),
    pga: [[f64; 16]; 2],
    cga: [[f64; 32]; 2],
}

impl Raw {
    fn new(rng: &mut SplitMix64) -> Self {
        let mut motion = || (rng.array(), 3.0 * rng.range(-1.0, 1.0), rng.array());
        let motions = [motion(), motion()];
        Self {
            motions,
            points: [rng.array(), rng.array()],
            plane: (rng.array(), rng.range(-1.0, 1.0)),
            pga: [rng.array(), rng.array()],
            cga: [rng.array(), rng.array()],
        }
    }

    fn pga<T: ga::Scalar>(&self) -> PgaCase<T> {
        let f = |x: [f64; 3]| x.map(T::from_f64);
        let motor = |&(axis, angle, t): &([f64; 3], f64, [f64; 3])| {
            let r = pga::Rotor::from_axis_angle(f(axis), T::from_f64(angle));
            pga::Motor::from_rotation_translation(r, f(t))
        };
        let [p, q] = self.points.map(|x| pga::Point::from_xyz_array(f(x)));
        let multivector = |m: [f64; 16]| pga::Multivector::from_array(m.map(T::from_f64));
        PgaCase {
            motors: (motor(&self.motions[0]), motor(&self.motions[1])),
            points: (p, q),
            line: pga::Line::through(p, q),
            plane: pga::Plane::from_normal_offset(f(self.plane.0), T::from_f64(self.plane.1)),
            multivectors: (multivector(self.pga[0]), multivector(self.pga[1])),
        }
    }

    fn cga<T: ga::Scalar>(&self) -> CgaCase<T> {
        let v = |x: [f64; 3]| Vector::from_array(x.map(T::from_f64));
        let motor = |&(axis, angle, t): &([f64; 3], f64, [f64; 3])| {
            let axis = v(axis) * T::from_f64(1.0 / length(axis));
            let r = cga::Rotor::from_axis_angle(axis, T::from_f64(angle));
            cga::Motor::translator(v(t)) * cga::Motor::from(r)
        };
        let [p, q] = self.points.map(|x| cga::Vector::up(v(x)));
        let multivector = |m: [f64; 32]| cga::Multivector::from_array(m.map(T::from_f64));
        CgaCase {
            motors: (motor(&self.motions[0]), motor(&self.motions[1])),
            x: v(self.points[0]),
            points: (p, q),
            line: cga::Trivector::line(p, q),
            plane: cga::Vector::dual_plane(v(self.plane.0), T::from_f64(self.plane.1)),
            multivectors: (multivector(self.cga[0]), multivector(self.cga[1])),
        }
    }

    fn affine32(&self) -> AffineCase<Affine3A, Vec3A, f32> {
        let v = |x: [f64; 3]| Vec3A::from(DVec3::from(x).as_vec3());
        let map = |&(axis, angle, t): &([f64; 3], f64, [f64; 3])| {
            let q = Quat::from_axis_angle(v(axis).normalize().into(), angle as f32);
            Affine3A::from_rotation_translation(q, v(t).into())
        };
        let [p, q] = self.points.map(v);
        AffineCase {
            maps: (map(&self.motions[0]), map(&self.motions[1])),
            points: (p, q),
            ray: (p, q - p),
            plane: (v(self.plane.0), self.plane.1 as f32),
        }
    }

    fn affine64(&self) -> AffineCase<DAffine3, DVec3, f64> {
        let map = |&(axis, angle, t): &([f64; 3], f64, [f64; 3])| {
            let q = DQuat::from_axis_angle(DVec3::from(axis).normalize(), angle);
            DAffine3::from_rotation_translation(q, DVec3::from(t))
        };
        let [p, q] = self.points.map(DVec3::from);
        AffineCase {
            maps: (map(&self.motions[0]), map(&self.motions[1])),
            points: (p, q),
            ray: (p, q - p),
            plane: (DVec3::from(self.plane.0), self.plane.1),
        }
    }
}

fn length(x: [f64; 3]) -> f64 {
    DVec3::from(x).length()
}

fn inputs() -> Inputs {
    let mut rng = SplitMix64::new(0x6761_5f6f_7073);
    let vectors64: Vec<_> = (0..BATCH)
        .map(|_| (Vector::from_array(rng.array()), Vector::from_array(rng.array())))
        .collect();
    let rotors64: Vec<_> = (0..BATCH)
        .map(|_| (unit_rotor(&mut rng), unit_rotor(&mut rng), Vector::from_array(rng.array())))
        .collect();
    let multivectors64: Vec<_> = (0..BATCH)
        .map(|_| (Multivector::from_array(rng.array()), Multivector::from_array(rng.array())))
        .collect();
    let v32 = |v: Vector<f64>| Vector::from_array(v.to_array().map(|x| x as f32));
    let r32 = |r: Rotor<f64>| Rotor::from_array(r.to_array().map(|x| x as f32));
    let m32 = |m: Multivector<f64>| Multivector::from_array(m.to_array().map(|x| x as f32));
    let vectors32: Vec<_> = vectors64.iter().map(|&(a, b)| (v32(a), v32(b))).collect();
    let rotors32: Vec<_> = rotors64.iter().map(|&(r, s, v)| (r32(r), r32(s), v32(v))).collect();
    let mut rng = SplitMix64::new(0x0070_6761_5f63_6761);
    let raw: Vec<Raw> = (0..BATCH).map(|_| Raw::new(&mut rng)).collect();
    Inputs {
        pga32: raw.iter().map(Raw::pga).collect(),
        pga64: raw.iter().map(Raw::pga).collect(),
        cga32: raw.iter().map(Raw::cga).collect(),
        cga64: raw.iter().map(Raw::cga).collect(),
        affine32: raw.iter().map(Raw::affine32).collect(),
        affine64: raw.iter().map(Raw::affine64).collect(),
        vec3s: vectors32.iter().map(|&(a, b)| (Vec3::from(a), Vec3::from(b))).collect(),
        dvec3s: vectors64.iter().map(|&(a, b)| (DVec3::from(a), DVec3::from(b))).collect(),
        quats: rotors32
            .iter()
            .map(|&(r, s, v)| (Quat::from(r), Quat::from(s), Vec3::from(v)))
            .collect(),
        dquats: rotors64
            .iter()
            .map(|&(r, s, v)| (DQuat::from(r), DQuat::from(s), DVec3::from(v)))
            .collect(),
        multivectors32: multivectors64.iter().map(|&(a, b)| (m32(a), m32(b))).collect(),
        vectors32,
        vectors64,
        rotors32,
        rotors64,
        multivectors64,
    }
}

/// Registers every benchmark and returns what was measured, for the CSV.
fn run_all(c: &mut Criterion<ThreadClock>, x: &Inputs) -> Vec<Spec> {
    let within = Target::RatioToGlam(1.1);
    let mut specs = Vec::new();
    let clock = ThreadClock::from_env();
    let (rounds, batches) = PAIRED[usize::from(quick_mode())];
    // Each macro call benchmarks one spec (criterion, then the paired measurement) and records
    // it for the CSV.
    macro_rules! pair {
        (
            $op:literal,
            $precision:literal,
            $target:expr,
            $ga_inputs:expr,
            $ga:expr,
            $glam_inputs:expr,
            $glam:expr
        ) => {{
            let (ga, glam) = (typed($ga_inputs, $ga), typed($glam_inputs, $glam));
            let ratio = paired_ratio(
                rounds,
                || burst(&clock, $ga_inputs, &ga, batches),
                || burst(&clock, $glam_inputs, &glam, batches),
            );
            let spec =
                Spec { op: $op, precision: $precision, target: $target, paired_ratio: Some(ratio) };
            bench_pair(c, &spec, ($ga_inputs, ga), ($glam_inputs, glam));
            specs.push(spec);
        }};
    }
    macro_rules! single {
        ($op:literal, $precision:literal, $target:expr, $ga_inputs:expr, $ga:expr) => {{
            let spec = Spec { op: $op, precision: $precision, target: $target, paired_ratio: None };
            bench_ga(c, &spec, ($ga_inputs, $ga));
            specs.push(spec);
        }};
    }

    pair!("outer_vs_cross", "f32", within, &x.vectors32, |&(a, b)| a ^ b, &x.vec3s, |&(a, b)| a
        .cross(b));
    pair!("outer_vs_cross", "f64", within, &x.vectors64, |&(a, b)| a ^ b, &x.dvec3s, |&(a, b)| a
        .cross(b));
    pair!("inner_vs_dot", "f32", within, &x.vectors32, |&(a, b)| a | b, &x.vec3s, |&(a, b)| a
        .dot(b));
    pair!("inner_vs_dot", "f64", within, &x.vectors64, |&(a, b)| a | b, &x.dvec3s, |&(a, b)| a
        .dot(b));
    pair!(
        "rotate_vs_quat_mul_vec3",
        "f32",
        within,
        &x.rotors32,
        |&(r, _, v)| r.rotate(v),
        &x.quats,
        |&(q, _, v)| q * v
    );
    pair!(
        "rotate_vs_quat_mul_vec3",
        "f64",
        within,
        &x.rotors64,
        |&(r, _, v)| r.rotate(v),
        &x.dquats,
        |&(q, _, v)| q * v
    );
    pair!(
        "rotor_mul_vs_quat_mul",
        "f32",
        within,
        &x.rotors32,
        |&(r, s, _)| r * s,
        &x.quats,
        |&(q, p, _)| q * p
    );
    pair!(
        "rotor_mul_vs_quat_mul",
        "f64",
        within,
        &x.rotors64,
        |&(r, s, _)| r * s,
        &x.dquats,
        |&(q, p, _)| q * p
    );
    // glam's Quat::inverse is the conjugate (it assumes a unit quaternion); the like-for-like GA
    // operation is the reverse. Rotor::inverse also divides by the squared norm and checks it.
    pair!(
        "rotor_reverse_vs_quat_inverse",
        "f32",
        within,
        &x.rotors32,
        |&(r, _, _)| r.reverse(),
        &x.quats,
        |&(q, _, _)| q.inverse()
    );
    pair!(
        "rotor_reverse_vs_quat_inverse",
        "f64",
        within,
        &x.rotors64,
        |&(r, _, _)| r.reverse(),
        &x.dquats,
        |&(q, _, _)| q.inverse()
    );
    pair!(
        "rotor_inverse_vs_quat_inverse",
        "f32",
        within,
        &x.rotors32,
        |&(r, _, _)| r.inverse(),
        &x.quats,
        |&(q, _, _)| q.inverse()
    );
    pair!(
        "rotor_inverse_vs_quat_inverse",
        "f64",
        within,
        &x.rotors64,
        |&(r, _, _)| r.inverse(),
        &x.dquats,
        |&(q, _, _)| q.inverse()
    );
    // A rotor's inverse for any non-zero rotor, beside what a glam user writes for a quaternion
    // that may not be unit (glam has no such method): the conjugate divided by the squared
    // norm, with the same check.
    pair!(
        "rotor_inverse_vs_quat_conjugate_over_norm2",
        "f32",
        within,
        &x.rotors32,
        |&(r, _, _)| r.inverse(),
        &x.quats,
        |&(q, _, _)| {
            let n2 = q.length_squared();
            (n2 > 0.0 && n2 < f32::INFINITY).then(|| q.conjugate() / n2)
        }
    );
    pair!(
        "rotor_inverse_vs_quat_conjugate_over_norm2",
        "f64",
        within,
        &x.rotors64,
        |&(r, _, _)| r.inverse(),
        &x.dquats,
        |&(q, _, _)| {
            let n2 = q.length_squared();
            (n2 > 0.0 && n2 < f64::INFINITY).then(|| q.conjugate() / n2)
        }
    );
    // The full geometric products, held to the machine's FMA throughput: every non-zero term
    // of the product is one multiply-add, so `terms x (ns per multiply-add at full throughput)`
    // is the least time any code can take; the target is 1.2x that, measured in this run.
    let bound32 = fma_ns::<f32, 64>(&clock, rounds);
    let bound64 = fma_ns::<f64, 32>(&clock, rounds);
    println!("FMA throughput: {bound32:.4} ns per f32 multiply-add, {bound64:.4} per f64");
    let bound = |algebra: ga_reference::Algebra, ns: f64| Target::MaxNs(1.2 * terms(algebra) * ns);
    let (g3, pga3, cga4) = (
        ga_reference::Algebra::new(3, 0, 0),
        ga_reference::Algebra::new(3, 0, 1),
        ga_reference::Algebra::new(4, 1, 0),
    );
    single!("multivector_geometric_product", "f32", bound(g3, bound32), &x.multivectors32, |&(
        a,
        b,
    )| a
        * b);
    single!("multivector_geometric_product", "f64", bound(g3, bound64), &x.multivectors64, |&(
        a,
        b,
    )| a
        * b);
    single!("multivector_inverse", "f32", Target::None, &x.multivectors32, |&(a, _)| a.inverse());
    single!("multivector_inverse", "f64", Target::None, &x.multivectors64, |&(a, _)| a.inverse());

    // Projective and conformal operations beside what a glam user writes for the same result.
    // Motors act like `Affine3A`s built from the same rotation and translation; the meet of a
    // line and a plane is the textbook ray-plane formula (with its check for a parallel ray
    // where the GA side has one); the join of two points is the line's direction and moment.
    macro_rules! higher {
        ($precision:literal, $pga:expr, $cga:expr, $affine:expr, $transform:ident, $bound:expr) => {
            pair!(
                "pga_motor_point_vs_affine_point",
                $precision,
                within,
                $pga,
                |c| c.motors.0.transform_point(c.points.0),
                $affine,
                |a| a.maps.0.$transform(a.points.0)
            );
            // One motor on many points (64 a call): the sandwich's matrix once, then a 4x4
            // product a point, beside the affine map on the same points.
            let (points, vectors): ([_; POINTS], [_; POINTS]) = (
                core::array::from_fn(|i| $pga[i].points.0),
                core::array::from_fn(|i| $affine[i].points.0),
            );
            // glam's side of the one-motor-many-points rows (PGA's and CGA's).
            let affine_points = typed($affine, move |a| {
                let mut moved = vectors;
                for p in &mut moved {
                    *p = a.maps.0.$transform(*p);
                }
                moved
            });
            pair!(
                "pga_motor_points_vs_affine_points",
                $precision,
                within,
                $pga,
                move |c| {
                    let mut moved = points;
                    c.motors.0.transform_points(&mut moved);
                    moved
                },
                $affine,
                |a| affine_points(a)
            );
            pair!(
                "pga_motor_mul_vs_affine_mul",
                $precision,
                within,
                $pga,
                |c| c.motors.0 * c.motors.1,
                $affine,
                |a| a.maps.0 * a.maps.1
            );
            pair!(
                "pga_meet_line_plane_vs_ray_plane",
                $precision,
                within,
                $pga,
                |c| c.line.meet_plane(c.plane).to_xyz(),
                $affine,
                |a| {
                    let ((o, d), (n, offset)) = (a.ray, a.plane);
                    let den = n.dot(d);
                    (den != 0.0).then(|| o + d * ((offset - n.dot(o)) / den))
                }
            );
            pair!(
                "pga_join_points_vs_cross",
                $precision,
                within,
                $pga,
                |c| c.points.0 & c.points.1,
                $affine,
                |a| (a.points.1 - a.points.0, a.points.0.cross(a.points.1))
            );
            single!(
                "pga_multivector_geometric_product",
                $precision,
                bound(pga3, $bound),
                $pga,
                |c| c.multivectors.0 * c.multivectors.1
            );
            pair!(
                "cga_motor_point_vs_affine_point",
                $precision,
                within,
                $cga,
                |c| c.motors.0.transform_point(c.x),
                $affine,
                |a| a.maps.0.$transform(a.points.0)
            );
            // The same with the CGA map (`Motor::vector_map`) once a call, then a 4x4 product,
            // an addition and a division by the weight a point.
            let xs: [_; POINTS] = core::array::from_fn(|i| $cga[i].x);
            pair!(
                "cga_motor_points_vs_affine_points",
                $precision,
                within,
                $cga,
                move |c| {
                    let mut moved = xs;
                    c.motors.0.transform_points(&mut moved);
                    moved
                },
                $affine,
                |a| affine_points(a)
            );
            pair!(
                "cga_motor_mul_vs_affine_mul",
                $precision,
                within,
                $cga,
                |c| c.motors.0 * c.motors.1,
                $affine,
                |a| a.maps.0 * a.maps.1
            );
            pair!(
                "cga_meet_line_plane_vs_ray_plane",
                $precision,
                within,
                $cga,
                |c| c.line.meet_plane_position(c.plane),
                $affine,
                |a| {
                    let ((o, d), (n, offset)) = (a.ray, a.plane);
                    o + d * ((offset - n.dot(o)) / n.dot(d))
                }
            );
            pair!(
                "cga_join_points_vs_cross",
                $precision,
                within,
                $cga,
                |c| cga::Trivector::line(c.points.0, c.points.1),
                $affine,
                |a| (a.points.1 - a.points.0, a.points.0.cross(a.points.1))
            );
            single!(
                "cga_multivector_geometric_product",
                $precision,
                bound(cga4, $bound),
                $cga,
                |c| c.multivectors.0 * c.multivectors.1
            );
        };
    }
    higher!("f32", &x.pga32, &x.cga32, &x.affine32, transform_point3a, bound32);
    higher!("f64", &x.pga64, &x.cga64, &x.affine64, transform_point3, bound64);
    specs
}

/// The number of non-zero terms of the full geometric product in `algebra`: pairs of basis
/// blades whose product is not zero (all of them but where a degenerate generator meets
/// itself).
fn terms(algebra: ga_reference::Algebra) -> f64 {
    let n = algebra.blade_count();
    let pairs = (0..n).flat_map(|a| (0..n).map(move |b| (a, b)));
    pairs.filter(|&(a, b)| algebra.blade_product(a, b).0 != 0.0).count() as f64
}

/// Nanoseconds per scalar multiply-add at the machine's throughput in this build: `N`
/// independent chains of fused multiply-adds (eight vector registers' worth, enough to cover
/// the instruction's latency on two pipes), the median of `rounds` bursts.
fn fma_ns<T: ga::Scalar, const N: usize>(clock: &ThreadClock, rounds: usize) -> f64 {
    const STEPS: u32 = 20_000;
    let (a, b) = (black_box(T::from_f64(0.999_999)), black_box(T::from_f64(1e-7)));
    let mut per_fma: Vec<f64> = (0..rounds.max(5))
        .map(|_| {
            let mut acc = black_box([T::ONE; N]);
            let start = clock.now();
            for _ in 0..STEPS {
                for x in &mut acc {
                    *x = x.mul_add(a, b);
                }
            }
            black_box(acc);
            let ns = clock.now().saturating_sub(start).as_secs_f64() * 1e9;
            ns / f64::from(STEPS) / N as f64
        })
        .collect();
    median(&mut per_fma)
}

fn main() {
    let started = SystemTime::now();
    // On CPU time a benchmark takes longer in wall time when the machine is busy, so the full
    // run keeps criterion's sample count but shortens its default 3 s + 5 s per benchmark.
    let full = (Duration::from_secs(1), Duration::from_secs(3));
    let criterion = Criterion::default().with_measurement(ThreadClock::from_env());
    let mut criterion = configured(criterion, full).configure_from_args();
    let specs = run_all(&mut criterion, &inputs());
    criterion.final_summary();

    let dir = criterion_dir();
    let cpu = machine();
    let per_op = |group: &str, function: &str| {
        median_ns(&dir, group, function, started).map(|ns| ns / BATCH as f64)
    };
    let rows: Vec<GaOpsRow> = specs
        .iter()
        .filter_map(|spec| {
            let group = spec.group();
            // A benchmark filtered out of this run has no fresh estimate: no row for it.
            let ga = per_op(&group, "ga")?;
            let glam = if spec.paired_ratio.is_some() { per_op(&group, "glam") } else { None };
            let figures =
                GaOpsFigures { ga_ns: Some(ga), glam_ns: glam, paired_ratio: spec.paired_ratio };
            Some(GaOpsRow::new(spec.op, spec.precision, figures, spec.target, &cpu))
        })
        .collect();
    if rows.is_empty() {
        return;
    }
    let path = output_path("ga_ops", "csv", rows.len() == specs.len());
    write_csv(&path, &rows).unwrap_or_else(|e| panic!("writing {}: {e}", path.display()));
    println!("\n{:<44} {:>5} {:>9} {:>9} {:>7}  target", "op", "prec", "ga ns", "glam ns", "ratio");
    for row in &rows {
        let show = |x: Option<f64>| x.map_or_else(|| "-".to_owned(), |x| format!("{x:.3}"));
        println!(
            "{:<44} {:>5} {:>9} {:>9} {:>7}  {} {}",
            row.op,
            row.precision,
            show(row.ga_ns),
            show(row.glam_ns),
            show(row.ratio_ga_over_glam),
            row.target,
            row.meets_target.map_or("", |met| if met { "met" } else { "MISSED" }),
        );
    }
    println!("wrote {}", path.display());
}
