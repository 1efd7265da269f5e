//! The compiled code of G3 operations beside their glam counterparts, for reading.
//!
//! Sub-nanosecond timings move by 10-30% from one build to the next (where the loop and the
//! data land), so `results/README.md` also compares what the compiler makes of each pair.
//! Each function below is one operation, not inlined, under an unmangled name:
//!
//! ```text
//! cargo build --release -p wedge-benches --example ga_glam_asm
//! objdump -d --no-show-raw-insn target/release/examples/ga_glam_asm | awk '/<ga_inner>:/,/ret/'
//! ```
//!
//! With `-C target-cpu=native` on the machine of `results/` (rustc 1.95.0, glam 0.34): `ga_inner`
//! and `glam_dot` are the same eight instructions, as are `ga_reverse` and `glam_inverse`
//! (three: load, XOR with a sign mask, store); `ga_outer` is twelve instructions and
//! `glam_cross` sixteen.
//!
//! Running it prints the results of each pair on one input, which must agree (the outer
//! product's `e23`, `e31`, `e12` are the cross product's `x`, `y`, `z`).

use ga::g3::{Bivector, Rotor, Vector};
use glam::{Quat, Vec3};

/// `a | b`, the inner product of two vectors.
#[inline(never)]
#[unsafe(no_mangle)]
pub fn ga_inner(a: &Vector<f32>, b: &Vector<f32>) -> f32 {
    *a | *b
}

/// glam's `dot`.
#[inline(never)]
#[unsafe(no_mangle)]
pub fn glam_dot(a: &Vec3, b: &Vec3) -> f32 {
    a.dot(*b)
}

/// `a ^ b`, the outer product of two vectors.
#[inline(never)]
#[unsafe(no_mangle)]
pub fn ga_outer(a: &Vector<f32>, b: &Vector<f32>, out: &mut Bivector<f32>) {
    *out = *a ^ *b;
}

/// glam's `cross`.
#[inline(never)]
#[unsafe(no_mangle)]
pub fn glam_cross(a: &Vec3, b: &Vec3, out: &mut Vec3) {
    *out = a.cross(*b);
}

/// The reverse of a rotor (its inverse when it is unit).
#[inline(never)]
#[unsafe(no_mangle)]
pub fn ga_reverse(r: &Rotor<f32>, out: &mut Rotor<f32>) {
    *out = r.reverse();
}

/// glam's `Quat::inverse` (the conjugate: it assumes a unit quaternion).
#[inline(never)]
#[unsafe(no_mangle)]
pub fn glam_inverse(q: &Quat, out: &mut Quat) {
    *out = q.inverse();
}

fn main() {
    let (a, b) = ([1.0, 2.0, 3.0], [-0.5, 0.25, 2.0]);
    let (va, vb) = (Vector::from_array(a), Vector::from_array(b));
    let (ga, gb) = (Vec3::from_array(a), Vec3::from_array(b));
    let (mut outer, mut cross) = (Bivector::default(), Vec3::ZERO);
    ga_outer(&va, &vb, &mut outer);
    glam_cross(&ga, &gb, &mut cross);
    let rotor = Rotor::new(0.5f32, 0.5, 0.5, 0.5);
    let (mut reverse, mut inverse) = (Rotor::default(), Quat::IDENTITY);
    ga_reverse(&rotor, &mut reverse);
    glam_inverse(&Quat::from(rotor), &mut inverse);
    println!("inner {} dot {}", ga_inner(&va, &vb), glam_dot(&ga, &gb));
    println!("outer {outer} cross {cross}");
    println!("reverse {reverse} inverse {inverse}");
}
