//! The report's geometry (sections 2.4 and 3): lines, planes from triangles, line-plane
//! intersection and the point-in-triangle test, with the report's errata corrected.
//!
//! ```
//! use ga::g3::Vector;
//! use ga::g3::geometry::{Line, Plane, point_in_triangle};
//!
//! // The triangle lies in the plane z = 2; a line along +z from the origin meets it at t = 2.
//! let (a, b, c) = (
//!     Vector::new(0.0, 0.0, 2.0),
//!     Vector::new(1.0, 0.0, 2.0),
//!     Vector::new(0.0, 1.0, 2.0),
//! );
//! let plane = Plane::from_triangle(a, b, c);
//! assert_eq!(plane.normal(), Vector::E3);
//! assert_eq!(plane.offset, 2.0);
//! let line = Line::new(Vector::ZERO, Vector::E3);
//! let (t, p) = plane.intersect_line(&line).unwrap();
//! assert_eq!((t, p), (2.0, Vector::new(0.0, 0.0, 2.0)));
//! assert!(point_in_triangle(Vector::new(0.25, 0.25, 2.0), a, b, c));
//! ```

use crate::Scalar;
use crate::g3::{Bivector, Vector};

/// A line through `point` with direction `dir` (report 2.4.1): the points `point + t dir`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Line<T> {
    /// A point on the line.
    pub point: Vector<T>,
    /// The direction (not necessarily unit; the line parameter is in units of `dir`).
    pub dir: Vector<T>,
}

impl<T: Scalar> Line<T> {
    /// The line through `point` with direction `dir`.
    #[must_use]
    #[inline]
    pub const fn new(point: Vector<T>, dir: Vector<T>) -> Self {
        Self { point, dir }
    }

    /// The point at parameter `t`: `point + t dir`.
    #[must_use]
    #[inline]
    pub fn at(&self, t: T) -> Vector<T> {
        self.point + self.dir * t
    }
}

/// A plane (report 2.4.2): a unit bivector `B` for its orientation and a *signed* offset `d`
/// along its normal `n = B*`, so the plane is the set of points `x` with `x · n = d`,
/// equivalently `(x ∧ B)* = d`.
///
/// The report stores the unsigned distance `|a⊥|`; a signed offset is needed to tell a plane
/// in front of the origin from its mirror image behind it (see [`crate::errata`]).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Plane<T> {
    /// The plane's orientation, a unit bivector.
    pub bivector: Bivector<T>,
    /// The signed distance from the origin along the normal `bivector*`.
    pub offset: T,
}

impl<T: Scalar> Plane<T> {
    /// The plane `(x ∧ B)* = offset`, with `bivector` normalised here.
    ///
    /// A zero bivector gives NaN components.
    #[must_use]
    #[inline]
    pub fn new(bivector: Bivector<T>, offset: T) -> Self {
        Self { bivector: bivector.normalize(), offset }
    }

    /// The plane through `point` with normal `normal` (not necessarily unit): `B = n̂ I`.
    #[must_use]
    #[inline]
    pub fn from_point_normal(point: Vector<T>, normal: Vector<T>) -> Self {
        let n = normal.normalize();
        Self { bivector: n.undual(), offset: point | n }
    }

    /// The plane of the triangle `a, b, c` (report 3.1, corrected): `B = b' ∧ c'` with
    /// `b' = b - a`, `c' = c - a`, normalised, and the signed offset `d = a · B*`.
    ///
    /// The orientation follows the vertex order: counter-clockwise seen from the side the
    /// normal `B*` points to. The report writes `B = a' ∧ c'` (but `a' = 0`) and `d = |a⊥|`,
    /// which loses the sign; `a · B*` is the rejection `a⊥ = (a ∧ B) B⁻¹` measured along the
    /// normal. A degenerate (zero-area) triangle gives NaN components; see
    /// [`Plane::try_from_triangle`].
    #[must_use]
    #[inline]
    pub fn from_triangle(a: Vector<T>, b: Vector<T>, c: Vector<T>) -> Self {
        let bivector = ((b - a) ^ (c - a)).normalize();
        Self { bivector, offset: a | bivector.dual() }
    }

    /// [`Plane::from_triangle`], or `None` when the triangle has zero area (or non-finite
    /// vertices).
    #[must_use]
    #[inline]
    pub fn try_from_triangle(a: Vector<T>, b: Vector<T>, c: Vector<T>) -> Option<Self> {
        let bivector = ((b - a) ^ (c - a)).try_normalize()?;
        Some(Self { bivector, offset: a | bivector.dual() })
    }

    /// The unit normal `n = B*`.
    #[must_use]
    #[inline]
    pub fn normal(&self) -> Vector<T> {
        self.bivector.dual()
    }

    /// The signed distance of `p` from the plane, positive on the side the normal points to:
    /// `(p ∧ B)* - d`.
    #[must_use]
    #[inline]
    pub fn signed_distance(&self, p: Vector<T>) -> T {
        (p ^ self.bivector).dual() - self.offset
    }

    /// Where `line` meets the plane (report 3.2): `p = a - ((a ∧ B)* - d) u / (u ∧ B)*` for
    /// the line `a + t u`. Returns the line parameter `t` and the point.
    ///
    /// `None` when the line is parallel to the plane (`(u ∧ B)* = 0`) or the result is not
    /// finite. A line lying in the plane is parallel and gives `None` too.
    #[must_use]
    #[inline]
    pub fn intersect_line(&self, line: &Line<T>) -> Option<(T, Vector<T>)> {
        // (x ∧ B)* = x · B* for a unit bivector B: the trivector x ∧ B is (x · n) I.
        let denom = (line.dir ^ self.bivector).dual();
        let t = -((line.point ^ self.bivector).dual() - self.offset) / denom;
        if denom == T::ZERO || !t.is_finite() {
            return None;
        }
        Some((t, line.at(t)))
    }

    /// The orthogonal projection of the point `p` onto the plane.
    #[must_use]
    #[inline]
    pub fn project_point(&self, p: Vector<T>) -> Vector<T> {
        p - self.normal() * self.signed_distance(p)
    }

    /// The mirror image of the point `p` in the plane (which need not pass through the origin):
    /// `p - 2 dist(p) n`.
    #[must_use]
    #[inline]
    pub fn reflect_point(&self, p: Vector<T>) -> Vector<T> {
        p - self.normal() * (T::TWO * self.signed_distance(p))
    }

    /// The mirror image of the direction `v` (a free vector: the offset does not apply):
    /// `-B v B⁻¹`, see [`Vector::reflect_in_plane`].
    #[must_use]
    #[inline]
    pub fn reflect_direction(&self, v: Vector<T>) -> Vector<T> {
        v.reflect_in_plane(self.bivector)
    }
}

/// Whether `p` lies in the triangle `a, b, c` (report 3.3, sign corrected), boundary included.
///
/// For each edge, `A = edge ∧ (p - start)` and `N = (b - a) ∧ (c - a)` are compared with the
/// report's inner product `s = A | N`. That inner product gives `e12 | e12 = -1`: bivectors of
/// the same orientation have a *negative* `s`, so `p` is on the inner side of an edge when
/// `s ≤ 0` (the report says positive, the opposite; see [`crate::errata`]). The boundary is
/// closed: a point on an edge or a vertex gives `s = 0` for that edge and counts as inside.
///
/// The report compares each edge with `B = edge ∧ (third vertex - start)`; taking the edges in
/// cyclic order `ab, bc, ca`, all three of those bivectors equal `N`, so it is computed once.
/// `p` is meant to lie in the triangle's plane; otherwise the test applies to its projection
/// along the normal. A degenerate (zero-area) triangle contains no point.
#[must_use]
#[inline]
pub fn point_in_triangle<T: Scalar>(
    p: Vector<T>,
    a: Vector<T>,
    b: Vector<T>,
    c: Vector<T>,
) -> bool {
    let n = (b - a) ^ (c - a);
    if n == Bivector::ZERO {
        return false;
    }
    let inside = |start: Vector<T>, end: Vector<T>| (((end - start) ^ (p - start)) | n) <= T::ZERO;
    inside(a, b) && inside(b, c) && inside(c, a)
}

#[cfg(test)]
mod tests {
    use super::*;

    type V = Vector<f64>;

    #[test]
    fn plane_from_triangle_has_a_signed_offset() {
        // Counter-clockwise seen from +z: normal +z; z = 3 is 3 along it.
        let front = Plane::from_triangle(
            V::new(0.0, 0.0, 3.0),
            V::new(1.0, 0.0, 3.0),
            V::new(0.0, 1.0, 3.0),
        );
        assert_eq!(front.bivector, Bivector::E12);
        assert_eq!(front.normal(), V::E3);
        assert_eq!(front.offset, 3.0);
        // The same orientation behind the origin (z = -3): the offset is negative, where the
        // report's |a⊥| would give +3 and put the plane in front.
        let behind = Plane::from_triangle(
            V::new(0.0, 0.0, -3.0),
            V::new(1.0, 0.0, -3.0),
            V::new(0.0, 1.0, -3.0),
        );
        assert_eq!(behind.offset, -3.0);
        // Reversing the vertex order flips the bivector, the normal and the offset's sign.
        let flipped = Plane::from_triangle(
            V::new(0.0, 0.0, 3.0),
            V::new(0.0, 1.0, 3.0),
            V::new(1.0, 0.0, 3.0),
        );
        assert_eq!((flipped.bivector, flipped.offset), (-Bivector::E12, -3.0));
        // A tilted plane: x + y + z = 1 through the three unit points.
        let tilted = Plane::from_triangle(V::E1, V::E2, V::E3);
        let s = 1.0 / 3.0_f64.sqrt();
        assert!(tilted.normal().abs_diff_eq(V::new(s, s, s), 1e-15));
        assert!((tilted.offset - s).abs() < 1e-15);
        // The offset is the signed length of the rejection a⊥ = (a ∧ B) B⁻¹ along the normal.
        let a = V::new(4.0, -1.0, 0.5);
        let p = Plane::from_triangle(a, a + V::new(1.0, 2.0, 0.0), a + V::new(0.0, -1.0, 3.0));
        assert!(((a.reject(p.bivector) | p.normal()) - p.offset).abs() < 1e-14);
        assert!(Plane::try_from_triangle(V::E1, V::E1 * 2.0, V::E1 * 3.0).is_none());
    }

    #[test]
    fn line_plane_intersection_by_hand() {
        // Plane x + y + z = 1 (normal (1,1,1)/√3, offset 1/√3). Line (2, 0, 0) + t (-1, 1, 0)
        // stays on x + y = 2, z = 0, so never meets it: parallel.
        let plane = Plane::from_triangle(V::E1, V::E2, V::E3);
        assert_eq!(
            plane.intersect_line(&Line::new(V::new(2.0, 0.0, 0.0), V::new(-1.0, 1.0, 0.0))),
            None
        );
        // Line (1, 1, 1) + t (1, 0, 0): 3 + t = 1 at t = -2, the point (-1, 1, 1).
        let (t, p) = plane.intersect_line(&Line::new(V::new(1.0, 1.0, 1.0), V::E1)).unwrap();
        assert!((t + 2.0).abs() < 1e-15);
        assert!(p.abs_diff_eq(V::new(-1.0, 1.0, 1.0), 1e-15));
        // A plane behind the origin (z = -2, normal +z), line from the origin toward -z:
        // t = 2 with a unit direction, t = 1 with direction length 2.
        let behind = Plane::from_point_normal(V::new(5.0, 5.0, -2.0), V::E3);
        assert_eq!(behind.offset, -2.0);
        let (t, p) = behind.intersect_line(&Line::new(V::ZERO, V::new(0.0, 0.0, -2.0))).unwrap();
        assert_eq!((t, p), (1.0, V::new(0.0, 0.0, -2.0)));
        assert_eq!(behind.signed_distance(V::ZERO), 2.0);
        assert_eq!(behind.project_point(V::new(1.0, 2.0, 3.0)), V::new(1.0, 2.0, -2.0));
        assert_eq!(behind.reflect_point(V::new(1.0, 2.0, 3.0)), V::new(1.0, 2.0, -7.0));
        assert_eq!(behind.reflect_direction(V::new(1.0, 2.0, 3.0)), V::new(1.0, 2.0, -3.0));
    }

    #[test]
    fn point_in_triangle_inside_outside_and_edges() {
        let (a, b, c) = (V::new(0.0, 0.0, 1.0), V::new(2.0, 0.0, 1.0), V::new(0.0, 2.0, 1.0));
        let p = |x, y| V::new(x, y, 1.0);
        for (q, inside) in [
            (p(0.5, 0.5), true),
            (p(0.1, 1.8), true),
            (p(1.5, 1.5), false),  // beyond the hypotenuse
            (p(-0.1, 0.5), false), // beyond the edge ca
            (p(0.5, -0.1), false), // beyond the edge ab
            (p(1.0, 0.0), true),   // on an edge: the boundary is closed
            (p(1.0, 1.0), true),   // on the hypotenuse
            (p(0.0, 0.0), true),   // a vertex
            (p(3.0, 0.0), false),  // on the line of an edge, outside the triangle
        ] {
            assert_eq!(point_in_triangle(q, a, b, c), inside, "{q}");
            // The vertex order (orientation) does not matter.
            assert_eq!(point_in_triangle(q, a, c, b), inside, "{q} reversed");
            // The report's sign rule as written (s > 0 means inside) rejects interior points.
            let n = (b - a) ^ (c - a);
            let report_rule = (((b - a) ^ (q - a)) | n) > 0.0;
            if inside && q == p(0.5, 0.5) {
                assert!(!report_rule);
            }
        }
        assert!(!point_in_triangle(p(0.0, 0.0), a, a, b));
    }
}
