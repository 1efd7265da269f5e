//! Points, planes and lines of R(3,0,1) from Euclidean data and back, their incidences,
//! distances, angles and projections: hand-written on the generated types and products.
//!
//! # Coordinates
//!
//! Read off the generated join and meet (see each function):
//!
//! - the point `(x, y, z)` is `x e032 + y e013 + z e021 + e123`; a weight `w` scales all four,
//!   and `w = 0` is the ideal point (direction) `(x, y, z)`;
//! - the plane `n · x + c = 0` is `n1 e1 + n2 e2 + n3 e3 + c e0`;
//! - a line has a **direction** `d = (e23, e31, e12)` and a **moment** `m = (e01, e02, e03)`,
//!   its Plücker coordinates: `m = p × d` for any point `p` on it, so `d · m = 0`. The join
//!   `P & Q` of the points `p` and `q` has `d = q - p` and `m = p × q`; the meet `a ^ b` of the
//!   planes `(n_a, c_a)` and `(n_b, c_b)` has `d = n_a × n_b` and `m = c_a n_b - c_b n_a`. An
//!   ideal line (the line at infinity of a plane) has `d = 0`.
//!
//! Norms are those of the generated `norm`, which only counts the blades without `e0`: a
//! plane's `|n|`, a line's `|d|`, a point's `|w|`. Distances divide by them, so no function
//! here needs its arguments normalised.
//!
//! ```
//! use ga::pga::{Line, Plane, Point};
//!
//! let (p, q) = (Point::from_xyz(1.0, 0.0, 0.0), Point::from_xyz(1.0, 2.0, 0.0));
//! let line = Line::through(p, q);
//! assert_eq!((line.direction(), line.moment()), ([0.0, 2.0, 0.0], [0.0, 0.0, 2.0]));
//! // The line x = 1, z = 0 meets the plane y = 3 (0 x + 1 y + 0 z - 3 = 0) in (1, 3, 0).
//! let y3 = Plane::from_normal_offset([0.0, 1.0, 0.0], 3.0);
//! assert_eq!(line.meet_plane(y3).to_xyz(), Some([1.0, 3.0, 0.0]));
//! // The origin is at distance 1 from the line.
//! assert_eq!(line.distance_to_point(Point::from_xyz(0.0, 0.0, 0.0)), 1.0);
//! ```

use crate::Scalar;
use crate::pga::{Line, Plane, Point};

/// `a × b`.
#[inline]
pub(crate) fn cross<T: Scalar>(a: [T; 3], b: [T; 3]) -> [T; 3] {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

/// `a · b`.
#[inline]
fn dot<T: Scalar>(a: [T; 3], b: [T; 3]) -> T {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// `|a|`.
#[inline]
pub(crate) fn length<T: Scalar>(a: [T; 3]) -> T {
    dot(a, a).sqrt()
}

/// The angle between two vectors in `[0, π]` as `atan2(|a × b|, a · b)`, accurate near 0 and
/// π where `acos` of the normalised dot product is not.
#[inline]
fn angle_between<T: Scalar>(a: [T; 3], b: [T; 3]) -> T {
    length(cross(a, b)).atan2(dot(a, b))
}

impl<T: Scalar> Point<T> {
    /// The Euclidean point `(x, y, z)`: `x e032 + y e013 + z e021 + e123` (weight 1).
    #[must_use]
    #[inline]
    pub const fn from_xyz(x: T, y: T, z: T) -> Self {
        Self::new(z, y, x, T::ONE)
    }

    /// The Euclidean point `[x, y, z]`, as [`Point::from_xyz`]. (`from_array` is the generated
    /// constructor from the four coefficients.)
    #[must_use]
    #[inline]
    pub const fn from_xyz_array(p: [T; 3]) -> Self {
        Self::from_xyz(p[0], p[1], p[2])
    }

    /// The ideal point (point at infinity) in the direction `(x, y, z)`: weight 0. It is
    /// what a line and a plane parallel to it meet in, and translations leave it fixed.
    #[must_use]
    #[inline]
    pub const fn direction(x: T, y: T, z: T) -> Self {
        Self::new(z, y, x, T::ZERO)
    }

    /// The weight `w` (the `e123` coefficient): 0 for ideal points.
    #[must_use]
    #[inline]
    pub const fn weight(self) -> T {
        self.e123
    }

    /// `true` for an ideal point (weight exactly 0).
    #[must_use]
    #[inline]
    pub fn is_ideal(self) -> bool {
        self.e123 == T::ZERO
    }

    /// The homogeneous coordinates `[x, y, z]` before the division by the weight: the
    /// Euclidean point times `w`, or the direction of an ideal point.
    #[must_use]
    #[inline]
    pub const fn xyz_weighted(self) -> [T; 3] {
        [self.e032, self.e013, self.e021]
    }

    /// The Euclidean coordinates `(x, y, z) / w`, or `None` for an ideal point (`w = 0`),
    /// which has a direction ([`Point::xyz_weighted`]) but no position.
    #[must_use]
    #[inline]
    pub fn to_xyz(self) -> Option<[T; 3]> {
        if self.is_ideal() {
            return None;
        }
        // Dividing (not multiplying by 1/w) keeps integer coordinates exact; all four lanes
        // at once, one vector division.
        let [z, y, x, _] = T::divide_by_last(*self.as_array());
        Some([x, y, z])
    }

    /// The same point with weight 1 (the ideal points, which have none, are returned as they
    /// are).
    #[must_use]
    #[inline]
    pub fn normalized(self) -> Self {
        if self.is_ideal() { self } else { self / self.e123 }
    }

    /// The Euclidean distance to `q`. Both are Euclidean points (weight not 0), of any weight.
    ///
    /// The join `P & Q` has direction `w_P w_Q (q - p)` for the Euclidean points `p`, `q`
    /// ([`Line::through`]), whose length is `|w_P w_Q|` times the distance.
    #[must_use]
    #[inline]
    pub fn distance(self, q: Self) -> T {
        (self & q).norm() / (self.e123 * q.e123).abs()
    }

    /// The orthogonal projection onto `plane`: `(plane | P) ^ plane`, the meet of the plane
    /// with the line through `P` along its normal.
    ///
    /// `plane | P` has direction `w n` and moment `w p × n` ([`Plane::normal_line_through`]);
    /// by [`Line::meet_plane`] its meet with the plane `(n, c)` is, for `w = 1`, the point
    /// `p |n|² - n (n · p + c)` of weight `|n|²`, i.e. `p - n (n · p + c) / |n|²`. The
    /// result has weight `w |n|²`, which [`Point::to_xyz`] divides out.
    #[must_use]
    #[inline]
    pub fn project_onto_plane(self, plane: Plane<T>) -> Self {
        plane.normal_line_through(self) ^ plane
    }

    /// The orthogonal projection onto `line`: `(line | P) ^ line`, the meet of the line with
    /// the plane through `P` orthogonal to it: `line | P` is the plane
    /// `-w d · x + d · (w p) = 0`, and by [`Line::meet_plane`] it meets the line in
    /// `(d × m + (d · p) d) / |d|²` (weight `-w |d|²`), the point of the line closest to the
    /// origin plus the component of `p` along `d`.
    #[must_use]
    #[inline]
    pub fn project_onto_line(self, line: Line<T>) -> Self {
        (line | self) ^ line
    }
}

impl<T: Scalar> Plane<T> {
    /// The plane `n · x = offset`, i.e. `n1 x + n2 y + n3 z - offset = 0`. For a unit normal
    /// `offset` is the signed distance of the plane from the origin along `n`.
    #[must_use]
    #[inline]
    pub fn from_normal_offset(normal: [T; 3], offset: T) -> Self {
        Self::new(-offset, normal[0], normal[1], normal[2])
    }

    /// The plane with normal `normal` through the Euclidean point `point`.
    #[must_use]
    #[inline]
    pub fn from_normal_point(normal: [T; 3], point: [T; 3]) -> Self {
        Self::from_normal_offset(normal, dot(normal, point))
    }

    /// The plane through three points, the join `P & Q & R`: for Euclidean points of weight
    /// 1 its normal is `(q - p) × (r - p)` (counter-clockwise `p, q, r` seen from the side it
    /// points to) and its `e0` coefficient `-(p × q) · r`.
    ///
    /// From the generated `Line & Point`: the line `(d, m)` joined with `r` is the plane
    /// `(m + d × r) · x - m · r = 0`; with `d = q - p` and `m = p × q = p × d`,
    /// `m + d × r = d × (r - p) = (q - p) × (r - p)`. Collinear points give the zero plane.
    #[must_use]
    #[inline]
    pub fn through(p: Point<T>, q: Point<T>, r: Point<T>) -> Self {
        (p & q) & r
    }

    /// The normal `n = (e1, e2, e3)` (not normalised).
    #[must_use]
    #[inline]
    pub const fn normal(self) -> [T; 3] {
        [self.e1, self.e2, self.e3]
    }

    /// The plane scaled to a unit normal, so that [`Plane::signed_distance`] and `e0` (minus
    /// the offset from the origin) are Euclidean distances. The ideal plane `e0` (zero normal)
    /// has no such scale and becomes non-finite.
    #[must_use]
    #[inline]
    pub fn normalized(self) -> Self {
        self / self.norm()
    }

    /// The signed distance of the Euclidean point `p` from the plane, positive on the side
    /// the normal points to: `(plane & P) / (|n| w)`, where the generated `Plane & Point` is
    /// `n · (w p) + c w`.
    #[must_use]
    #[inline]
    pub fn signed_distance(self, p: Point<T>) -> T {
        (self & p) / (self.norm() * p.e123)
    }

    /// `true` when the point lies on the plane: `plane & P` exactly 0 (exact for integer
    /// coordinates; compare [`Plane::signed_distance`] with a tolerance otherwise).
    #[must_use]
    #[inline]
    pub fn contains(self, p: Point<T>) -> bool {
        (self & p) == T::ZERO
    }

    /// The angle between the two planes' normals, in `[0, π]`: `atan2(|n_a × n_b|, n_a · n_b)`,
    /// where `|n_a × n_b|` is the norm of their meet `a ^ b` and `n_a · n_b` is `a | b`.
    #[must_use]
    #[inline]
    pub fn angle(self, other: Self) -> T {
        (self ^ other).norm().atan2(self | other)
    }

    /// The line through `p` along the plane's normal: the generated `Plane | Point`, with
    /// direction `w n` and moment `p × n` (times `w`).
    #[must_use]
    #[inline]
    pub fn normal_line_through(self, p: Point<T>) -> Line<T> {
        self | p
    }
}

impl<T: Scalar> Line<T> {
    /// The line from its direction `d` and moment `m` (see the module docs; `d · m = 0` for a
    /// line, which this does not check).
    #[must_use]
    #[inline]
    pub const fn from_direction_moment(d: [T; 3], m: [T; 3]) -> Self {
        Self::new(m[0], m[1], m[2], d[2], d[1], d[0])
    }

    /// The line through the Euclidean point `p` with direction `d`: moment `p × d`.
    #[must_use]
    #[inline]
    pub fn from_point_direction(p: [T; 3], d: [T; 3]) -> Self {
        Self::from_direction_moment(d, cross(p, d))
    }

    /// The ideal line with moment `m`: the line at infinity of the planes with normal `m`
    /// (direction 0). Its exponential is a translation ([`Line::exp`]).
    #[must_use]
    #[inline]
    pub const fn ideal(m: [T; 3]) -> Self {
        Self::new(m[0], m[1], m[2], T::ZERO, T::ZERO, T::ZERO)
    }

    /// The line through two points, their join `P & Q`.
    ///
    /// The generated `Point & Point` gives, in the weighted coordinates `p_h = w_P p`,
    /// `q_h = w_Q q` ([`Point::xyz_weighted`]), direction `w_P q_h - w_Q p_h` (`q - p` for
    /// weight 1) and moment `p_h × q_h` (`p × q = p × (q - p)` for weight 1, as it must).
    /// With an ideal point `Q` it is the line through `p` in the direction `q_h`.
    #[must_use]
    #[inline]
    pub fn through(p: Point<T>, q: Point<T>) -> Self {
        p & q
    }

    /// The line where two planes meet, `a ^ b`: direction `n_a × n_b`, moment
    /// `c_a n_b - c_b n_a`. Check: a point `p` on both has `n_a · p = -c_a`,
    /// `n_b · p = -c_b`, and `p × (n_a × n_b) = n_a (p · n_b) - n_b (p · n_a)`. Parallel
    /// planes meet in an ideal line.
    #[must_use]
    #[inline]
    pub fn meet(a: Plane<T>, b: Plane<T>) -> Self {
        a ^ b
    }

    /// The point where the line meets `plane`, `line ^ plane`: the weighted point
    /// `(n × m - c d, n · d)` for the plane `(n, c)`. Check: with `m = p × d`,
    /// `n × (p × d) = p (n · d) - d (n · p)`, so the Euclidean point is
    /// `p - d (n · p + c) / (n · d)`, on the line and on the plane. A line parallel to the
    /// plane meets it in the ideal point of its direction (weight `n · d = 0`).
    #[must_use]
    #[inline]
    pub fn meet_plane(self, plane: Plane<T>) -> Point<T> {
        self ^ plane
    }

    /// The direction `d = (e23, e31, e12)`.
    #[must_use]
    #[inline]
    pub const fn direction(self) -> [T; 3] {
        [self.e23, self.e31, self.e12]
    }

    /// The moment `m = (e01, e02, e03)`, `p × d` for every point `p` of the line.
    #[must_use]
    #[inline]
    pub const fn moment(self) -> [T; 3] {
        [self.e01, self.e02, self.e03]
    }

    /// `true` for an ideal line (direction exactly 0).
    #[must_use]
    #[inline]
    pub fn is_ideal(self) -> bool {
        self.e12 == T::ZERO && self.e31 == T::ZERO && self.e23 == T::ZERO
    }

    /// The line scaled to a unit direction (then `L² = -1` and `L & P` has the distance as its
    /// norm); an ideal line is scaled to a unit moment instead.
    #[must_use]
    #[inline]
    pub fn normalized(self) -> Self {
        if self.is_ideal() { self / length(self.moment()) } else { self / self.norm() }
    }

    /// The point of the line closest to the origin, `d × m / |d|²` (`None` for an ideal line).
    /// Check: with `m = p × d`, `d × (p × d) = p |d|² - d (d · p)`, `p` minus its component
    /// along `d`.
    #[must_use]
    #[inline]
    pub fn closest_point_to_origin(self) -> Option<[T; 3]> {
        if self.is_ideal() {
            return None;
        }
        let (d, m) = (self.direction(), self.moment());
        let n2 = dot(d, d);
        let c = cross(d, m);
        Some([c[0] / n2, c[1] / n2, c[2] / n2])
    }

    /// The distance of the Euclidean point `p` from the line: `|L & P| / (|d| |w|)`.
    ///
    /// The generated `Line & Point` is the plane through both with normal
    /// `w m + d × (w p) = w (a - p) × d` for a point `a` on the line (`m = a × d`), whose
    /// length is `|w| |d|` times the distance.
    #[must_use]
    #[inline]
    pub fn distance_to_point(self, p: Point<T>) -> T {
        (self & p).norm() / (self.norm() * p.e123.abs())
    }

    /// `true` when the point lies on the line: `L & P` exactly zero.
    #[must_use]
    #[inline]
    pub fn contains(self, p: Point<T>) -> bool {
        (self & p) == Plane::ZERO
    }

    /// The distance between two Euclidean lines.
    ///
    /// Skew or intersecting lines: `|d_a · m_b + d_b · m_a| / |d_a × d_b|`, where the
    /// numerator is the `e0123` coefficient of `a ^ b` (it vanishes exactly when the lines
    /// meet). Derivation: with `m_a = p_a × d_a`, `m_b = p_b × d_b`,
    /// `d_a · m_b + d_b · m_a = (p_a - p_b) · (d_a × d_b)`, the distance times
    /// `|d_a × d_b|` up to sign. Parallel lines (`d_a × d_b` exactly 0, `d_b = k d_a`):
    /// `m_b / k - m_a = (p_b - p_a) × d_a`, so the distance is `|m_b / k - m_a| / |d_a|`, with
    /// `k = (d_a · d_b) / |d_a|²`.
    #[must_use]
    pub fn distance_to_line(self, other: Self) -> T {
        let (da, db) = (self.direction(), other.direction());
        let c = cross(da, db);
        let c2 = dot(c, c);
        if c2 == T::ZERO {
            let (ma, mb) = (self.moment(), other.moment());
            let na2 = dot(da, da);
            let k = dot(da, db) / na2;
            let r = [mb[0] / k - ma[0], mb[1] / k - ma[1], mb[2] / k - ma[2]];
            return length(r) / na2.sqrt();
        }
        (self ^ other).e0123.abs() / c2.sqrt()
    }

    /// The angle between the two lines' directions, in `[0, π]`
    /// (`atan2(|d_a × d_b|, d_a · d_b)`; `-(a | b)` is `d_a · d_b`).
    #[must_use]
    #[inline]
    pub fn angle(self, other: Self) -> T {
        angle_between(self.direction(), other.direction())
    }

    /// The orthogonal projection of the line onto `plane`: `plane ^ (plane | L)`, oriented like
    /// `L`. The generated `Plane | Line` is the plane through `L` orthogonal to `plane` (normal
    /// `d × n`, orthogonal to both), which meets `plane` in the line of direction
    /// `n × (d × n) = |n|² d - (n · d) n`, the projection of `d` times `|n|²`. A line
    /// orthogonal to the plane projects to the zero line (a point has no direction).
    #[must_use]
    #[inline]
    pub fn project_onto_plane(self, plane: Plane<T>) -> Self {
        plane ^ (plane | self)
    }
}
