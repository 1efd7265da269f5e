//! Conformal geometry on the generated types: the null basis, the embedding `up` and its
//! inverse `down`, spheres and planes (direct and dual), circles, lines and flat points through
//! points, their meets, and (in the versor half) reflections, inversions, rotors, translators,
//! dilators, `exp`, `log` and versor inverses.
//!
//! Everything here is written by hand on the generated products; each function's doc carries
//! its derivation. Euclidean points and directions are [`g3::Vector`]s.
//!
//! ```
//! use ga::cga::{Motor, Quadvector, Rotor, Trivector, Vector};
//! use ga::g3;
//!
//! let p = |x: f64, y: f64, z: f64| Vector::point(x, y, z);
//! // The sphere through four points holds a fifth exactly when the outer product vanishes;
//! // its dual is the dual sphere, whose inner product with a point is zero on the sphere.
//! let sphere = Quadvector::sphere(p(3.0, 0.0, 0.0), p(0.0, 3.0, 0.0), p(0.0, 0.0, 3.0),
//!     p(-3.0, 0.0, 0.0));
//! assert_eq!((sphere ^ p(2.0, 2.0, 1.0)).e12345, 0.0);
//! assert_eq!(sphere.dual() | p(1.0, -2.0, 2.0), 0.0);
//! assert_eq!(sphere.centre(), g3::Vector::new(0.0, 0.0, 0.0));
//! assert_eq!(sphere.radius_squared(), 9.0);
//!
//! // The line through (0,0,0) and (1,1,1) meets the plane z = 2 in the flat point (2,2,2).
//! let line = Trivector::line(p(0.0, 0.0, 0.0), p(1.0, 1.0, 1.0));
//! let plane = Quadvector::plane(p(0.0, 0.0, 2.0), p(1.0, 0.0, 2.0), p(0.0, 1.0, 2.0));
//! assert_eq!((line & plane).flat_point_position(), g3::Vector::new(2.0, 2.0, 2.0));
//!
//! // A quarter turn about z, then a translation by (1, 0, 0): (1, 0, 0) goes to (1, 1, 0).
//! let turn = Rotor::from_axis_angle(g3::Vector::E3, core::f64::consts::FRAC_PI_2);
//! let motor = Motor::translator(g3::Vector::new(1.0, 0.0, 0.0)) * Motor::from(turn);
//! let moved = motor.transform_point(g3::Vector::new(1.0, 0.0, 0.0));
//! assert!((moved - g3::Vector::new(1.0, 1.0, 0.0)).norm() < 1e-14);
//! ```
//!
//! # The null basis and the embedding
//!
//! With `e4 = e+` (`e4² = 1`) and `e5 = e-` (`e5² = -1`), the origin and the point at infinity
//! are `eₒ = (e5 - e4)/2` ([`Vector::E_O`]) and `e∞ = e4 + e5` ([`Vector::E_INF`]):
//! `eₒ² = (e5² + e4²)/4 = 0`, `e∞² = e4² + e5² = 0`, `eₒ · e∞ = (e5² - e4²)/2 = -1`. A vector
//! `X = x + a e4 + b e5` has `X · e∞ = a - b`, so its **weight** `-X · e∞` is `b - a`.
//!
//! `up(x) = eₒ + x + ½x² e∞` has `e4` coefficient `½x² - ½` and `e5` coefficient `½x² + ½`
//! (weight 1), and is null: `up(x)² = x² + 2 (½x²) (eₒ · e∞) = 0`. For two points,
//! `up(x) · up(y) = x · y - ½x² - ½y² = -½|x - y|²`, so the inner product measures squared
//! distance. `down(X)` divides the Euclidean part by the weight, so it inverts `up` on every
//! non-zero multiple `λ up(x)` (the homogeneous points).
//!
//! # Spheres and planes
//!
//! A dual sphere with centre `c` and radius `r` is `σ = up(c) - ½r² e∞`: then
//! `up(x) · σ = -½|x - c|² + ½r²`, zero exactly on the sphere and positive inside. A dual plane
//! `n · x = d` is `π = n + d e∞`: `up(x) · π = n · x - d`. The direct (outer product, "OPNS")
//! forms are the outer products of points: the sphere through four points `p ∧ q ∧ r ∧ s`,
//! the plane through three `p ∧ q ∧ r ∧ e∞` (a sphere through infinity), the circle through
//! three `p ∧ q ∧ r` and the line through two `p ∧ q ∧ e∞`; a point `X` lies on a direct object
//! `A` exactly when `A ∧ X = 0`. The dual `A I⁻¹` of a direct sphere or plane is a multiple of
//! its dual vector, so the centre and radius read back from either. With integer or dyadic
//! coordinates of moderate size every one of these products is exact, so "lies on" is an
//! exact zero (the tests check it).
//!
//! # Meets
//!
//! The intersection of two direct objects is their regressive product `A & B`
//! (`undual(dual(A) ∧ dual(B))`): two planes meet in a line, a sphere and a plane in a circle,
//! and a line and a plane in a **flat point** `w (x ∧ e∞ + eₒ ∧ e∞)`, a bivector read back by
//! [`Bivector::flat_point_position`]. Equivalently, contract the dual of one onto the other:
//! `π ⌋ L` (`pi | line`) is the same flat point up to scale.
//!
//! # Precision
//!
//! The basis `e4, e5` is orthonormal, not null, so `up(x)` stores `½x² - ½` and `½x² + ½` and
//! its weight is their difference: rounding `½x²` loses up to `ε ½x²` of the weight, and
//! every product that mixes points cancels terms of that size. A point read back has relative
//! error about `ε x²` (not `ε`): near `1e-15` at `|x| = 1` and `1e-12` at `|x| = 30` in f64, but
//! `1e-4` at `|x| = 10` in f32, where points beyond `|x| ≈ 4000` lose the weight entirely
//! (`½x² ± ½` round to the same value). Keep coordinates near the origin (scale and centre a
//! scene), or compute in f64. A null basis stored as such (coefficients of `eₒ` and `e∞`)
//! would not cancel; the generated types use `e4, e5`.

mod versor;

use crate::Scalar;
use crate::cga::{Bivector, Quadvector, Trivector, Vector};
use crate::g3;

impl<T: Scalar> Vector<T> {
    /// The origin `eₒ = (e5 - e4)/2 = (e- - e+)/2`, a null vector with `eₒ · e∞ = -1`.
    pub const E_O: Self = Self::new(T::ZERO, T::ZERO, T::ZERO, T::NEG_HALF, T::HALF);
    /// The point at infinity `e∞ = e4 + e5 = e+ + e-`, a null vector with `eₒ · e∞ = -1`.
    pub const E_INF: Self = Self::new(T::ZERO, T::ZERO, T::ZERO, T::ONE, T::ONE);

    /// The conformal point `up(x) = eₒ + x + ½x² e∞`: coefficients `(x, ½x² - ½, ½x² + ½)`
    /// (see the module docs), a null vector of weight 1.
    #[must_use]
    #[inline]
    pub fn up(x: g3::Vector<T>) -> Self {
        let h = T::HALF * (x.e1 * x.e1 + x.e2 * x.e2 + x.e3 * x.e3);
        Self::new(x.e1, x.e2, x.e3, h - T::HALF, h + T::HALF)
    }

    /// [`Vector::up`] of the point `(x, y, z)`.
    #[must_use]
    #[inline]
    pub fn point(x: T, y: T, z: T) -> Self {
        Self::up(g3::Vector::new(x, y, z))
    }

    /// The weight `-X · e∞ = e5 - e4`: 1 for `up(x)`, `λ` for `λ up(x)`, the weight of the
    /// centre for a dual sphere, and zero for a dual plane (and for `e∞` itself).
    #[must_use]
    #[inline]
    pub fn weight(self) -> T {
        self.e5 - self.e4
    }

    /// `down(X)`: the Euclidean part divided by the weight, `(X₁, X₂, X₃) / (-X · e∞)`.
    ///
    /// Inverts [`Vector::up`] on every multiple `λ up(x)`, `λ ≠ 0`. For a dual sphere it is the
    /// centre (`σ = up(c) - ½r² e∞` has the Euclidean part `c` and weight 1). A vector of
    /// weight zero (a dual plane, `e∞`) gives non-finite coordinates.
    #[must_use]
    #[inline]
    pub fn down(self) -> g3::Vector<T> {
        let w = self.weight();
        g3::Vector::new(self.e1 / w, self.e2 / w, self.e3 / w)
    }

    /// [`Vector::down`] as `[x, y, z]`.
    #[must_use]
    #[inline]
    pub fn to_xyz(self) -> [T; 3] {
        self.down().to_array()
    }

    /// The dual sphere `σ = up(c) - ½r² e∞` with centre `c` and radius `r`:
    /// `up(x) · σ = ½(r² - |x - c|²)`, zero on the sphere, positive inside. Its coefficients
    /// are `(c, k - ½, k + ½)` with `k = ½(c² - r²)`.
    #[must_use]
    #[inline]
    pub fn dual_sphere(centre: g3::Vector<T>, radius: T) -> Self {
        let c = centre;
        let k = T::HALF * (c.e1 * c.e1 + c.e2 * c.e2 + c.e3 * c.e3 - radius * radius);
        Self::new(c.e1, c.e2, c.e3, k - T::HALF, k + T::HALF)
    }

    /// The dual plane `π = n + d e∞` of the points with `n · x = d`: `up(x) · π = n · x - d`.
    ///
    /// `normal` need not be unit; when it is, `d` is the signed distance of the plane from
    /// the origin and `π² = n² = 1` (a unit versor: [`Vector::reflect`]).
    #[must_use]
    #[inline]
    pub fn dual_plane(normal: g3::Vector<T>, distance: T) -> Self {
        Self::new(normal.e1, normal.e2, normal.e3, distance, distance)
    }

    /// The squared radius of a dual sphere, `σ² / w²` with `w` its [weight](Vector::weight):
    /// for `σ = w (up(c) - ½r² e∞)`, `σ² = w² (up(c)² - r² up(c) · e∞) = w² r²`. Zero for a
    /// point (a sphere of radius 0), negative for an imaginary sphere; its centre is
    /// [`Vector::down`].
    #[must_use]
    #[inline]
    pub fn radius_squared(self) -> T {
        let w = self.weight();
        self.norm_squared() / (w * w)
    }
}

impl<T: Scalar> Bivector<T> {
    /// The flat point `up(x) ∧ e∞ = x ∧ e∞ + eₒ ∧ e∞` at `x`: the coefficients of `e14, e15`
    /// are `x1` (likewise `e24, e25` and `e34, e35`) and, as `eₒ ∧ e∞ = -e45`, that of `e45`
    /// is -1.
    #[must_use]
    #[inline]
    pub fn flat_point(x: g3::Vector<T>) -> Self {
        Vector::up(x) ^ Vector::E_INF
    }

    /// The position of a flat point `F = w (x ∧ e∞ - e45)` (see [`Bivector::flat_point`]), such
    /// as the meet `line & plane`: `w = -F₄₅` and `xᵢ = (Fᵢ₄ + Fᵢ₅) / (2w)`.
    ///
    /// The coordinates are not finite when `w = 0` (the meet of a line and a plane parallel to
    /// it).
    #[must_use]
    #[inline]
    pub fn flat_point_position(self) -> g3::Vector<T> {
        let w2 = -(self.e45 + self.e45);
        g3::Vector::new(
            (self.e14 + self.e15) / w2,
            (self.e24 + self.e25) / w2,
            (self.e34 + self.e35) / w2,
        )
    }
}

impl<T: Scalar> Trivector<T> {
    /// The circle through three points, `p ∧ q ∧ r` (a line when they are collinear, as a
    /// line is a circle through infinity).
    #[must_use]
    #[inline]
    pub fn circle(p: Vector<T>, q: Vector<T>, r: Vector<T>) -> Self {
        p ^ q ^ r
    }

    /// The line through two points, `p ∧ q ∧ e∞`, in closed form (twelve products, as PGA's
    /// join and the direction and moment `(q - p, p × q)` it replaces).
    ///
    /// With `B = p ∧ q`, `B ∧ e∞ = B ∧ e4 + B ∧ e5`: a blade `eᵢⱼ` (`i < j ≤ 3`) goes to
    /// `eᵢⱼ₄` and `eᵢⱼ₅` with the same coefficient, and `eᵢ₄ ∧ e5 = eᵢ₄₅`,
    /// `eᵢ₅ ∧ e4 = -eᵢ₄₅`, so `eᵢ₄₅` gets `Bᵢ₄ - Bᵢ₅ = qᵢ w_p - pᵢ w_q` with `w = e5 - e4`
    /// the weight; `e123` is zero. For `p = up(x)`, `q = up(y)`: `Bᵢⱼ` is `x × y` and
    /// `qᵢ w_p - pᵢ w_q` is `y - x`.
    #[must_use]
    #[inline]
    pub fn line(p: Vector<T>, q: Vector<T>) -> Self {
        let (wp, wq) = (p.weight(), q.weight());
        let b12 = p.e1 * q.e2 - p.e2 * q.e1;
        let b13 = p.e1 * q.e3 - p.e3 * q.e1;
        let b23 = p.e2 * q.e3 - p.e3 * q.e2;
        let d = [q.e1 * wp - p.e1 * wq, q.e2 * wp - p.e2 * wq, q.e3 * wp - p.e3 * wq];
        Self::new(T::ZERO, b12, b12, b13, b13, d[0], b23, b23, d[1], d[2])
    }

    /// Where the line `self` meets the dual plane `plane`: the position of the flat point
    /// `plane ⌋ self` ([`Bivector::flat_point_position`]), formed from the four of its
    /// coefficients that position needs (twelve products instead of thirty).
    ///
    /// With `π` the plane and `L` the line, the generated `π ⌋ L` gives
    /// `F₁₄ + F₁₅ = -π₂ (L₁₂₄ + L₁₂₅) - π₃ (L₁₃₄ + L₁₃₅) - (π₄ + π₅) L₁₄₅`, likewise for
    /// `e2` and `e3`, and `F₄₅ = π₁ L₁₄₅ + π₂ L₂₄₅ + π₃ L₃₄₅`. Not finite when the line is
    /// parallel to the plane (`F₄₅ = 0`).
    #[must_use]
    #[inline]
    pub fn meet_plane_position(self, plane: Vector<T>) -> g3::Vector<T> {
        let (a, l) = (plane, self);
        let (l12, l13, l23) = (l.e124 + l.e125, l.e134 + l.e135, l.e234 + l.e235);
        let a45 = a.e4 + a.e5;
        let x = -a.e2 * l12 - a.e3 * l13 - a45 * l.e145;
        let y = a.e1 * l12 - a.e3 * l23 - a45 * l.e245;
        let z = a.e1 * l13 + a.e2 * l23 - a45 * l.e345;
        let f45 = a.e1 * l.e145 + a.e2 * l.e245 + a.e3 * l.e345;
        let w2 = -(f45 + f45);
        g3::Vector::new(x / w2, y / w2, z / w2)
    }
}

impl<T: Scalar> Quadvector<T> {
    /// The sphere through four points, `p ∧ q ∧ r ∧ s` (a plane when they are coplanar).
    #[must_use]
    #[inline]
    pub fn sphere(p: Vector<T>, q: Vector<T>, r: Vector<T>, s: Vector<T>) -> Self {
        p ^ q ^ r ^ s
    }

    /// The plane through three points, `p ∧ q ∧ r ∧ e∞`.
    #[must_use]
    #[inline]
    pub fn plane(p: Vector<T>, q: Vector<T>, r: Vector<T>) -> Self {
        p ^ q ^ r ^ Vector::E_INF
    }

    /// The centre of a direct sphere: its dual `S I⁻¹` is a multiple of the dual sphere, whose
    /// [`Vector::down`] is the centre. Not finite for a plane.
    #[must_use]
    #[inline]
    pub fn centre(self) -> g3::Vector<T> {
        self.dual().down()
    }

    /// The squared radius of a direct sphere, [`Vector::radius_squared`] of its dual (which
    /// does not depend on the dual's scale or sign).
    #[must_use]
    #[inline]
    pub fn radius_squared(self) -> T {
        self.dual().radius_squared()
    }
}
