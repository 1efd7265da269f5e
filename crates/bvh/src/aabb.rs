//! Axis-aligned bounding boxes in the tree's own precision.

use intersect::{Real, Triangle};

use super::PAD_ULPS;

/// `min(a, b)`, ignoring `b` if it is NaN (a compare and a select: one `minss`/`minsd`, cheaper
/// than the NaN-symmetric `f64::min`). `a` is never NaN where this is used.
#[inline(always)]
pub(crate) fn min_or<T: PartialOrd>(a: T, b: T) -> T {
    if b < a { b } else { a }
}

/// `max(a, b)`, ignoring `b` if it is NaN (see [`min_or`]).
#[inline(always)]
pub(crate) fn max_or<T: PartialOrd>(a: T, b: T) -> T {
    if b > a { b } else { a }
}

/// An axis-aligned bounding box. The empty box has `min = +inf`, `max = -inf`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aabb<T> {
    /// Lower corner.
    pub min: [T; 3],
    /// Upper corner.
    pub max: [T; 3],
}

impl<T: Real> Default for Aabb<T> {
    fn default() -> Self {
        Self::empty()
    }
}

impl<T: Real> Aabb<T> {
    /// The empty box: growing it by a point gives that point's box.
    #[must_use]
    pub fn empty() -> Self {
        Self { min: [T::INFINITY; 3], max: [-T::INFINITY; 3] }
    }

    /// The smallest box holding all `points` (empty if there are none).
    #[must_use]
    pub fn from_points(points: &[[T; 3]]) -> Self {
        let mut b = Self::empty();
        for p in points {
            b.grow_point(*p);
        }
        b
    }

    /// The exact box of a triangle's three vertices.
    #[must_use]
    #[inline]
    pub fn of_triangle(tri: &Triangle<T>) -> Self {
        let (a, b, c) = (tri.a, tri.b, tri.c);
        Self {
            min: core::array::from_fn(|k| min_or(min_or(a[k], b[k]), c[k])),
            max: core::array::from_fn(|k| max_or(max_or(a[k], b[k]), c[k])),
        }
    }

    /// Whether the box holds no point.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        !(0..3).all(|k| self.min[k] <= self.max[k])
    }

    /// Grows the box to hold `p` (NaN coordinates are ignored).
    #[inline]
    pub fn grow_point(&mut self, p: [T; 3]) {
        for (k, x) in p.into_iter().enumerate() {
            self.min[k] = min_or(self.min[k], x);
            self.max[k] = max_or(self.max[k], x);
        }
    }

    /// Grows the box to hold `other` (NaN coordinates are ignored).
    #[inline]
    pub fn grow(&mut self, other: &Self) {
        for k in 0..3 {
            self.min[k] = min_or(self.min[k], other.min[k]);
            self.max[k] = max_or(self.max[k], other.max[k]);
        }
    }

    /// The smallest box holding both.
    #[must_use]
    pub fn union(&self, other: &Self) -> Self {
        let mut b = *self;
        b.grow(other);
        b
    }

    /// Whether `other` lies inside `self` (boundary included). The empty box lies in every box.
    #[must_use]
    pub fn contains(&self, other: &Self) -> bool {
        other.is_empty()
            || (0..3).all(|k| self.min[k] <= other.min[k] && other.max[k] <= self.max[k])
    }

    /// Whether the point lies inside the box (boundary included).
    #[must_use]
    pub fn contains_point(&self, p: [T; 3]) -> bool {
        (0..3).all(|k| self.min[k] <= p[k] && p[k] <= self.max[k])
    }

    /// The centre of the box.
    #[must_use]
    pub fn center(&self) -> [T; 3] {
        let half = T::from_f64(0.5);
        core::array::from_fn(|k| (self.min[k] + self.max[k]) * half)
    }

    /// The edge lengths (`max - min`).
    #[must_use]
    pub fn extent(&self) -> [T; 3] {
        core::array::from_fn(|k| self.max[k] - self.min[k])
    }

    /// Half the surface area, in `f64` (0 for an empty box): the SAH only needs ratios.
    #[must_use]
    pub fn half_area(&self) -> f64 {
        if self.is_empty() {
            return 0.0;
        }
        let [x, y, z] = self.extent().map(Real::to_f64);
        x * y + y * z + z * x
    }

    /// The box grown outwards by [`PAD_ULPS`] units in the last place (of precision `T`) of its
    /// largest coordinate magnitude (see the [module documentation](super) for why).
    #[must_use]
    pub fn padded(&self) -> Self {
        if self.is_empty() {
            return *self;
        }
        let mut magnitude = T::ZERO;
        for k in 0..3 {
            magnitude = magnitude.max(self.min[k].abs()).max(self.max[k].abs());
        }
        // `pad >= PAD_ULPS * ulp(c)` for every coordinate `c` of the box, so the subtraction
        // and addition below move each face by many ulps and never round back.
        let pad = magnitude * T::EPSILON * T::from_f64(f64::from(PAD_ULPS));
        Self { min: self.min.map(|m| m - pad), max: self.max.map(|m| m + pad) }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn padding_moves_every_face_outwards() {
        let b = Aabb { min: [1.0f32, -3.0, 0.0], max: [2.0, 1e6, 0.0] };
        let p = b.padded();
        for k in 0..3 {
            assert!(p.min[k] < b.min[k] && p.max[k] > b.max[k]);
        }
    }

    #[test]
    fn triangle_box_is_the_vertex_box() {
        let t = Triangle::new([1.0, -2.0, 3.0], [0.5, 4.0, 3.0], [2.0, 0.0, -1.0]);
        let b = Aabb::of_triangle(&t);
        assert_eq!(b, Aabb::from_points(&t.vertices()));
        assert_eq!((b.min, b.max), ([0.5, -2.0, -1.0], [2.0, 4.0, 3.0]));
    }
}
