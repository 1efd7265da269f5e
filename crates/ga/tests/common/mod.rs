//! Shared by the integration tests: every G3 type seen as eight coefficients in the report's
//! basis, so that any kernel can be compared with the reference algebra, and seeded random
//! values of each type.

// Each test binary uses a different subset of these helpers.
#![allow(dead_code)]

use ga::g3::{Bivector, Multivector, Rotor, Trivector, Vector};
use ga::{Real, Scalar};
use ga_reference::{Multivector as Reference, from_g3_report, to_g3_report};
use rand::{Rng, SeedableRng};
use rand_pcg::Pcg64;

/// Which report-basis slots (`1, e1, e2, e3, e12, e23, e31, e123`) each type holds.
const SCALAR: [bool; 8] = [true, false, false, false, false, false, false, false];
const VECTOR: [bool; 8] = [false, true, true, true, false, false, false, false];
const BIVECTOR: [bool; 8] = [false, false, false, false, true, true, true, false];
const TRIVECTOR: [bool; 8] = [false, false, false, false, false, false, false, true];
const EVEN: [bool; 8] = [true, false, false, false, true, true, true, false];
const ALL: [bool; 8] = [true; 8];

/// A G3 value as coefficients in the report's basis, converted through `f64`.
pub trait Embed: Copy {
    /// The report-basis slots the type holds.
    const SLOTS: [bool; 8];
    /// The coefficients, in the report's order, as `f64`.
    fn to_report(self) -> [f64; 8];
    /// The value from coefficients; slots the type does not hold are ignored.
    fn from_report(c: [f64; 8]) -> Self;

    /// The value as a multivector of the reference algebra.
    fn to_reference(self) -> Reference {
        from_g3_report(self.to_report())
    }
}

macro_rules! embed_scalar {
    ($t:ty) => {
        impl Embed for $t {
            const SLOTS: [bool; 8] = SCALAR;
            fn to_report(self) -> [f64; 8] {
                [f64::from(self), 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]
            }
            fn from_report(c: [f64; 8]) -> Self {
                <$t as Real>::from_f64(c[0])
            }
        }
    };
}
embed_scalar!(f32);
embed_scalar!(f64);

fn f<T: Scalar>(x: f64) -> T {
    T::from_f64(x)
}

impl<T: Scalar> Embed for Vector<T> {
    const SLOTS: [bool; 8] = VECTOR;
    fn to_report(self) -> [f64; 8] {
        [0.0, self.e1.to_f64(), self.e2.to_f64(), self.e3.to_f64(), 0.0, 0.0, 0.0, 0.0]
    }
    fn from_report(c: [f64; 8]) -> Self {
        Self::new(f(c[1]), f(c[2]), f(c[3]))
    }
}

impl<T: Scalar> Embed for Bivector<T> {
    const SLOTS: [bool; 8] = BIVECTOR;
    fn to_report(self) -> [f64; 8] {
        [0.0, 0.0, 0.0, 0.0, self.e12.to_f64(), self.e23.to_f64(), self.e31.to_f64(), 0.0]
    }
    fn from_report(c: [f64; 8]) -> Self {
        Self::new(f(c[4]), f(c[5]), f(c[6]))
    }
}

impl<T: Scalar> Embed for Trivector<T> {
    const SLOTS: [bool; 8] = TRIVECTOR;
    fn to_report(self) -> [f64; 8] {
        [0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, self.e123.to_f64()]
    }
    fn from_report(c: [f64; 8]) -> Self {
        Self::new(f(c[7]))
    }
}

impl<T: Scalar> Embed for Rotor<T> {
    const SLOTS: [bool; 8] = EVEN;
    fn to_report(self) -> [f64; 8] {
        let [s, e12, e23, e31] = self.to_array().map(Real::to_f64);
        [s, 0.0, 0.0, 0.0, e12, e23, e31, 0.0]
    }
    fn from_report(c: [f64; 8]) -> Self {
        Self::new(f(c[0]), f(c[4]), f(c[5]), f(c[6]))
    }
}

impl<T: Scalar> Embed for Multivector<T> {
    const SLOTS: [bool; 8] = ALL;
    fn to_report(self) -> [f64; 8] {
        self.to_array().map(Real::to_f64)
    }
    fn from_report(c: [f64; 8]) -> Self {
        Self::from_array(c.map(f))
    }
}

/// A reference multivector as report coefficients.
pub fn report(m: &Reference) -> [f64; 8] {
    to_g3_report(m)
}

/// A deterministic generator for one test.
pub fn rng(seed: u64) -> Pcg64 {
    Pcg64::seed_from_u64(seed)
}

/// A random value: coefficients uniform in (-1, 1) times a common scale between 1/8 and 8, so
/// that kernels are exercised away from unit size too.
pub fn random<E: Embed>(rng: &mut Pcg64) -> E {
    let scale = 2.0_f64.powf(rng.random_range(-3.0..3.0));
    E::from_report(std::array::from_fn(|_| rng.random_range(-1.0..1.0) * scale))
}

/// A random unit vector.
pub fn random_unit_vector(rng: &mut Pcg64) -> Vector<f64> {
    loop {
        let v = Vector::new(
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
        );
        let n = v.norm();
        if n > 0.1 && n <= 1.0 {
            return v / n;
        }
    }
}

/// A random unit rotor (a rotation), uniform enough for testing.
pub fn random_unit_rotor(rng: &mut Pcg64) -> Rotor<f64> {
    let angle = rng.random_range(-std::f64::consts::PI..std::f64::consts::PI);
    Rotor::from_angle_plane(angle, random_unit_vector(rng).undual())
}

/// The largest absolute coefficient.
pub fn max_abs(c: &[f64; 8]) -> f64 {
    c.iter().fold(0.0, |m, x| m.max(x.abs()))
}

/// The Euclidean norm of the coefficients.
pub fn norm(c: &[f64; 8]) -> f64 {
    c.iter().map(|x| x * x).sum::<f64>().sqrt()
}

/// Asserts `|got - want|_max <= tolerance * scale`, naming the case.
#[track_caller]
pub fn assert_close(what: &str, got: [f64; 8], want: [f64; 8], scale: f64, tolerance: f64) {
    let error = got.iter().zip(&want).fold(0.0_f64, |m, (g, w)| m.max((g - w).abs()));
    assert!(
        error <= tolerance * scale,
        "{what}:\n  got  {got:?}\n  want {want:?}\n  \
         error {error:e} > {tolerance:e} x scale {scale:e}"
    );
}
