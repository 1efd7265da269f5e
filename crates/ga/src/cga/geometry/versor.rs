//! Versors: reflections and inversions (vectors), rotors, translators and dilators (even), their
//! exponentials and logarithms in closed form, and versor inverses.
//!
//! A versor `V` acts by the sandwich `V X Ṽ` (`V.sandwich(X)`), which for a unit versor
//! (`V Ṽ = ±1`) is the conformal map; composition is the geometric product, `(U V) X (U V)~ =
//! U (V X Ṽ) Ũ`, so `U * V` applies `V` first. For a vector versor (a dual plane or sphere) the
//! map of a point is `-V X V⁻¹`, the sign that makes it the reflection.

use crate::Scalar;
use crate::cga::{Bivector, Motor, Rotor, Vector};
use crate::g3;

impl<T: Scalar> Vector<T> {
    /// The reflection of the point (or dual sphere, dual plane) `x` in `self`, `-v x v⁻¹`:
    ///
    /// - for a unit dual plane `π = n + d e∞` (`π² = 1`) it is `x - 2 (n · x - d) n`, and
    ///   `π e∞ π = -e∞` keeps the weight of a point;
    /// - for a dual sphere `σ` with centre `c` and radius `r` it is the inversion
    ///   `c + r² (x - c) / |x - c|²`, scaled (take [`Vector::down`]).
    ///
    /// Both are `x - 2 (v · x) v / v²` (expand `v x v = 2 (v · x) v - v² x`), which is how it is
    /// computed, through the generated sandwich `v x ṽ`. Not finite for a null `self`.
    ///
    /// A direct object (a `k`-blade `A`: line, circle, plane, sphere) maps to
    /// `(-1)^k v A v⁻¹`, which is `v.sandwich(A)` up to sign and scale; incidence (`A ∧ X = 0`)
    /// does not depend on either.
    #[must_use]
    #[inline]
    pub fn reflect(self, x: Self) -> Self {
        self.sandwich(x) * (-self.norm_squared().recip())
    }

    /// The versor inverse `v⁻¹ = v / v²` (`v v = v · v` is a scalar), or `None` when `v²` is
    /// zero (a point, `e∞`) or not finite.
    #[must_use]
    #[inline]
    pub fn inverse(self) -> Option<Self> {
        let n2 = self.norm_squared();
        (n2 != T::ZERO && n2.is_finite()).then(|| self / n2)
    }
}

impl<T: Scalar> Rotor<T> {
    /// The rotor `cos(θ/2) - sin(θ/2) (n I₃)` turning by `angle` right-handedly about the unit
    /// `axis` through the origin (`n I₃ = n1 e23 - n2 e13 + n3 e12` is the plane normal to
    /// `n`, with `e31 = -e13`), as [`g3::Rotor`] and glam's `Quat::from_axis_angle` do.
    #[must_use]
    #[inline]
    pub fn from_axis_angle(axis: g3::Vector<T>, angle: T) -> Self {
        let (s, c) = (T::HALF * angle).sin_cos();
        Self::new(c, -s * axis.e3, s * axis.e2, -s * axis.e1)
    }

    /// The versor inverse `R̃ / (R R̃)`, or `None` when `R R̃` is zero or not finite.
    #[must_use]
    #[inline]
    pub fn inverse(self) -> Option<Self> {
        let n2 = self.norm_squared();
        (n2 != T::ZERO && n2.is_finite()).then(|| self.reverse() / n2)
    }
}

/// The same rotor: G3's `s + e12 + e23 + e31` is `s + e12 - e13 + e23` in CGA's blade order.
impl<T: Scalar> From<g3::Rotor<T>> for Rotor<T> {
    #[inline]
    fn from(r: g3::Rotor<T>) -> Self {
        Self::new(r.s, r.e12, -r.e31, r.e23)
    }
}

impl<T: Scalar> Bivector<T> {
    /// `exp(B)` of a 2-blade `B` (`B ∧ B = 0`) in closed form. Such a `B` squares to the scalar
    /// `λ = ⟨B B⟩₀`, so the series sums to
    ///
    /// - `cos √-λ + B sin √-λ / √-λ` when `λ < 0`: rotations, `exp(-θ/2 B̂)` about any axis;
    /// - `1 + B` when `λ = 0`: translators, `exp(-½ t e∞) = 1 - ½ t e∞`;
    /// - `cosh √λ + B sinh √λ / √λ` when `λ > 0`: dilators, `exp(½ ln(s) eₒ ∧ e∞)`, scaling by
    ///   `s` about the origin.
    ///
    /// The three agree in the limit `λ → 0`. `sinh` comes from `exp_m1`, so small `λ` lose
    /// nothing. For a bivector that is not a blade (a screw: `B ∧ B ≠ 0`) `B²` has a grade-4
    /// part and this is not `exp(B)`; compose the exponentials of commuting blades instead.
    #[must_use]
    #[inline]
    pub fn exp_blade(self) -> Motor<T> {
        let lambda = self.scalar_product(self);
        let (c, k) = if lambda < T::ZERO {
            let a = (-lambda).sqrt();
            let (s, c) = a.sin_cos();
            (c, s / a)
        } else if lambda > T::ZERO {
            let a = lambda.sqrt();
            let (p, m) = (a.exp_m1(), (-a).exp_m1());
            (T::ONE + T::HALF * (p + m), T::HALF * (p - m) / a)
        } else {
            (T::ONE, T::ONE)
        };
        Motor::from(self * k) + Motor::ONE * c
    }
}

impl<T: Scalar> Motor<T> {
    /// The translator `T = 1 - ½ t e∞ = exp(-½ t e∞)` by `t`: `-½ t e∞` squares to zero, and
    /// `T eₒ T̃ = eₒ + t + ½t² e∞ = up(t)` (`eₒ (t e∞) + (t e∞) eₒ = -2 t (eₒ · e∞)`), so it
    /// moves every point by `t`. Coefficients: `e14 = e15 = -½ t1`, likewise for `e2`, `e3`.
    #[must_use]
    #[inline]
    pub fn translator(t: g3::Vector<T>) -> Self {
        let (a, b, c) = (t.e1 * T::NEG_HALF, t.e2 * T::NEG_HALF, t.e3 * T::NEG_HALF);
        let z = T::ZERO;
        Self::new(T::ONE, z, z, a, a, z, b, b, c, c, z, z, z, z, z, z)
    }

    /// The dilator scaling by `s > 0` about the origin, `exp(½ ln(s) E)` with
    /// `E = eₒ ∧ e∞ = -e45`: `E² = 1`, so it is `cosh(½ ln s) + sinh(½ ln s) E`, which with
    /// `q = √s` is `(s + 1)/(2q) + (1 - s)/(2q) e45`.
    ///
    /// Derivation: `e45` commutes with `e1, e2, e3` and anticommutes with `e4, e5`, and
    /// `e45 e∞ = -e∞`, `e45 eₒ = eₒ`; so `D = cosh α + sinh α e45` takes `e∞` to `e^(-2α) e∞`
    /// and `eₒ` to `e^(2α) eₒ`, and `up(x)` to `e^(2α) up(e^(-2α) x)`: a scaling by
    /// `s = e^(-2α)`. The weight changes (by `1/s`), so read points back with
    /// [`Vector::down`].
    #[must_use]
    #[inline]
    pub fn dilator(s: T) -> Self {
        let d = (s.sqrt() + s.sqrt()).recip();
        let mut m = Self::ONE * ((s + T::ONE) * d);
        m.e45 = (T::ONE - s) * d;
        m
    }

    /// The logarithm of `exp(B)` for a 2-blade `B` ([`Bivector::exp_blade`]'s inverse): with
    /// `M = c + B'` (grades 0 and 2; a grade-4 part, zero for these motors, is ignored) and
    /// `λ' = ⟨B' B'⟩₀`,
    ///
    /// - `λ' < 0` (rotations): `B' θ / √-λ'` with `θ = atan2(√-λ', c)`;
    /// - `λ' = 0` (translators): `B' / c`;
    /// - `λ' > 0` (dilators): `B' β / √λ'` with `β = atanh(√λ' / c) = ½ ln_1p(2x / (c - x))`,
    ///   `x = √λ'` (after turning `M` into `-M` when `c < 0`; `c > x` for a dilator).
    ///
    /// Each is unchanged when `M` is scaled by a positive factor, so `M` need not be unit.
    /// For a screw motion (a rotation composed with a translation along its axis) `B'` is not
    /// a blade and the result is not its logarithm.
    #[must_use]
    #[inline]
    pub fn log_blade(self) -> Bivector<T> {
        let b = Bivector::new(
            self.e12, self.e13, self.e14, self.e15, self.e23, self.e24, self.e25, self.e34,
            self.e35, self.e45,
        );
        let lambda = b.scalar_product(b);
        if lambda < T::ZERO {
            let x = (-lambda).sqrt();
            b * (x.atan2(self.s) / x)
        } else if lambda > T::ZERO {
            let (c, b) = if self.s < T::ZERO { (-self.s, -b) } else { (self.s, b) };
            let x = lambda.sqrt();
            b * (T::HALF * ((x + x) / (c - x)).ln_1p() / x)
        } else {
            b / self.s
        }
    }

    /// The versor inverse `M̃ / (M M̃)` (for a versor `M M̃` is the scalar `⟨M M̃⟩₀`), or `None`
    /// when that is zero or not finite. For a unit motor it is the reverse.
    #[must_use]
    #[inline]
    pub fn inverse(self) -> Option<Self> {
        let n2 = self.norm_squared();
        (n2 != T::ZERO && n2.is_finite()).then(|| self.reverse() / n2)
    }

    /// The image of the Euclidean point `x` under the even versor `M`, `down(M up(x) M̃)`:
    /// rotors and translators keep the weight 1, a dilator scales it, and `down` divides it out.
    #[must_use]
    #[inline]
    pub fn transform_point(self, x: g3::Vector<T>) -> g3::Vector<T> {
        self.sandwich(Vector::up(x)).down()
    }

    /// [`Motor::transform_point`] on each of `points` in place, with the map worked out once.
    ///
    /// The sandwich is linear: [`Motor::vector_map`] is its matrix `m`, and
    /// `up(x) = (x₁, x₂, x₃, h - ½, h + ½)` with `h = ½x²`, so the image is
    /// `Σᵢ xᵢ cᵢ + h (c₄ + c₅) + ½ (c₅ - c₄)` with `cⱼ` the columns of `m`. Only the Euclidean
    /// part and the weight (`e5 - e4`) of the image are needed, so each column is four numbers
    /// and a point costs `h`, one 4×4 matrix-vector product whose chain starts from the offset
    /// `½ (c₅ - c₄)`, and the division by the weight (one 4-lane division, see `cga::simd`).
    /// This holds for every even versor, those that move `e∞` too (the product of two sphere
    /// inversions): the weight then depends on the point, which the division per point takes
    /// care of.
    pub fn transform_points(self, points: &mut [g3::Vector<T>]) {
        let m = self.vector_map();
        let column = |j: usize| [m[0][j], m[1][j], m[2][j], m[4][j] - m[3][j]];
        let (c4, c5) = (column(3), column(4));
        let columns = [column(0), column(1), column(2), core::array::from_fn(|i| c4[i] + c5[i])];
        let origin: [T; 4] = core::array::from_fn(|i| T::HALF * (c5[i] - c4[i]));
        for p in points {
            let h = T::HALF * (p.e1 * p.e1 + p.e2 * p.e2 + p.e3 * p.e3);
            let [x1, x2, x3] = T::map_down(&columns, origin, [p.e1, p.e2, p.e3, h]);
            *p = g3::Vector::new(x1, x2, x3);
        }
    }
}
