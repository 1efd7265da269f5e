//! The seam between the renderer and its ray-triangle back ends.
//!
//! This crate holds plain data ([`Ray`], [`Triangle`], [`Hit`], and [`Algebra`], [`Method`],
//! [`Guarantees`] by which a kernel describes itself) and one trait,
//! [`Intersector`]. The renderer (`render`) is generic over it and knows no back end; the back
//! ends (`kernels-la` with glam, `kernels-g3` with geometric algebra) implement it and know no
//! renderer. Beside them live only what every back end needs of the seam: the exact
//! [`is_degenerate`] test, the `[f64; 3]` helpers of [`vec3`], and, behind the `conformance`
//! feature, the checks every back end's tests run (`conformance`).
//!
//! ```
//! use intersect::{Algebra, Guarantees, Intersector, Method, Ray, Triangle, TriangleHit};
//!
//! /// A toy back end: the plane z = 0 restricted to the triangle, rays along +z only.
//! struct Toy;
//!
//! impl Intersector for Toy {
//!     type Real = f64;
//!     type Prim = Triangle<f64>;
//!     type RayData = ();
//!     type Block = ();
//!     const NAME: &'static str = "toy";
//!     // The plane, then the point tested against the edges; no promise beyond the contract.
//!     const ALGEBRA: Algebra = Algebra::La;
//!     const METHOD: Method = Method::Report;
//!     const GUARANTEES: Guarantees = Guarantees { watertight: false, exact: false };
//!     const VARIANT: Option<&'static str> = None;
//!
//!     fn prepare(&self, tri: &Triangle<f64>) -> Triangle<f64> {
//!         *tri
//!     }
//!     fn prepare_ray(&self, _ray: &Ray<f64>) {}
//!     fn intersect(&self, p: &Triangle<f64>, ray: &Ray<f64>, _: &(), t_max: f64)
//!         -> Option<TriangleHit<f64>>
//!     {
//!         let t = -ray.origin[2] / ray.dir[2];
//!         let [x, y] = [ray.origin[0], ray.origin[1]];
//!         (t > 0.0 && t <= t_max && x >= 0.0 && y >= 0.0 && x + y <= 1.0)
//!             .then_some(TriangleHit { t, u: x, v: y })
//!     }
//! }
//!
//! let tri = Triangle::new([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
//! let ray = Ray::new([0.25, 0.25, -1.0], [0.0, 0.0, 1.0]);
//! let toy = Toy;
//! let prim = toy.prepare(&tri);
//! let hit = toy.intersect(&prim, &ray, &toy.prepare_ray(&ray), f64::INFINITY).unwrap();
//! assert_eq!(hit.t, 1.0);
//! assert!(toy.occludes(&prim, &ray, &(), 2.0));
//! ```
//!
//! # Why the trait has this shape
//!
//! - **Static dispatch.** The renderer calls the kernel once per ray-triangle pair, hundreds of
//!   millions of times a second. A `dyn` call there costs an indirect branch and, worse, stops
//!   inlining of a kernel that is a few dozen instructions long. So the trait is used as a
//!   generic bound: the back end is chosen once, at the top of a program, and everything below
//!   is monomorphised for it.
//! - **Per-triangle data is the back end's own** ([`Intersector::Prim`]). Moller-Trumbore wants
//!   a vertex and two edges; the GA back end wants a bivector and an offset; the watertight
//!   kernel wants plain vertices. The renderer builds one `Prim` per triangle at scene build
//!   ([`Intersector::prepare`]) and stores them in BVH order, so the kernel reads only what it
//!   needs and the cost of that precomputation is paid once, not per ray.
//! - **A leaf's triangles together, if the kernel likes** ([`Intersector::Block`]). Testing a
//!   leaf's triangles one by one costs a branch per triangle; a kernel may instead keep blocks
//!   of [`Intersector::BLOCK`] triangles laid out lane by lane ([`Intersector::prepare_blocks`])
//!   and test a block at once ([`Intersector::intersect_leaf`], [`Intersector::occludes_leaf`]).
//!   The BVH then starts every leaf at a multiple of `BLOCK`, so a leaf's blocks follow from its
//!   first slot. The hits stay those of the one-by-one loop, bit for bit; kernels without
//!   blocks declare `type Block = ()` and keep the defaults.
//! - **Per-ray data is the back end's own too** ([`Intersector::RayData`]): the watertight
//!   kernel's axis permutation and shear, or an inverse direction. It is computed once per ray
//!   and passed to every triangle test of that ray. Back ends that need none use `()`.
//! - **Closest hit and any hit.** [`Intersector::intersect`] returns the distance and
//!   barycentrics of a hit within `(0, t_max]`; [`Intersector::occludes`] only says whether
//!   there is one and may skip the barycentrics. The default `occludes` calls `intersect`.
//! - **f32 and f64.** Every type is generic over [`Real`], implemented for `f32` and `f64`
//!   only, so one renderer serves both precisions of every back end.
//! - **Kernels describe themselves.** [`Intersector::ALGEBRA`], [`Intersector::METHOD`],
//!   [`Intersector::GUARANTEES`] and [`Intersector::VARIANT`] (a cell of the method x algebra
//!   matrix, or a labelled variant beside it) are declared by each kernel, with no defaults, so
//!   that the registry of back ends (crate `backends`), the benches and the tests read what a
//!   kernel is from the kernel instead of keeping lists of names.
//! - **Plain data across the seam.** Points are `[T; 3]`: no glam or GA type leaks through,
//!   and neither back end depends on the other's vector types.

#![deny(missing_docs)]

#[cfg(feature = "conformance")]
pub mod conformance;
pub mod vec3;

use robust::{Coord, orient2d};

/// The algebra a kernel is written in ([`Intersector::ALGEBRA`]).
///
/// `Pga` and `Cga` have no kernel yet; they are here so that the projective and conformal
/// back ends to come need only their kernel and a registry entry, and so that code sorting
/// back ends by algebra (GA against linear algebra) already says where they go.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Algebra {
    /// Linear algebra: vectors, cross and dot products, determinants (`la`).
    La,
    /// The geometric algebra G(3,0,0) of Euclidean 3-space (`g3`).
    G3,
    /// Projective geometric algebra G(3,0,1) (`pga`).
    Pga,
    /// Conformal geometric algebra G(4,1,0) (`cga`).
    Cga,
}

impl Algebra {
    /// The short name used in tables: `"la"`, `"g3"`, `"pga"` or `"cga"`.
    #[must_use]
    pub const fn name(self) -> &'static str {
        match self {
            Algebra::La => "la",
            Algebra::G3 => "g3",
            Algebra::Pga => "pga",
            Algebra::Cga => "cga",
        }
    }

    /// Whether this is a geometric algebra (every algebra but [`Algebra::La`]): the back ends
    /// the project compares with linear algebra.
    #[must_use]
    pub const fn is_geometric(self) -> bool {
        !matches!(self, Algebra::La)
    }
}

/// The ray-triangle algorithm a kernel implements ([`Intersector::METHOD`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Method {
    /// The triangle's plane first, then the point where the ray meets it tested against the
    /// edges, everything per ray (the report's method as written).
    Report,
    /// Moller-Trumbore (1997): Cramer's rule on the ray and two edges, barycentrics first.
    MollerTrumbore,
    /// The plane and the reciprocal frame of two edges precomputed per triangle, so that each
    /// edge test is one inner product giving a barycentric coordinate.
    Frame,
    /// Edge functions decided as the signs of the ray's signed volumes with the edges (in a
    /// frame of the ray), exactly antisymmetric, with a tie rule for exact zeros: no cracks.
    Watertight,
    /// Plücker coordinates: the ray and the edges as lines, each edge test the side of the
    /// ray's line against the edge's line (their permuted inner product), edge lines
    /// precomputed per triangle.
    Plucker,
}

impl Method {
    /// Every method, in the order of the rows of the method x algebra tables.
    pub const ALL: [Method; 5] = [
        Method::Report,
        Method::MollerTrumbore,
        Method::Frame,
        Method::Watertight,
        Method::Plucker,
    ];

    /// The short name used in tables: `"report"`, `"mt"`, `"frame"`, `"watertight"` or
    /// `"plucker"`.
    #[must_use]
    pub const fn name(self) -> &'static str {
        match self {
            Method::Report => "report",
            Method::MollerTrumbore => "mt",
            Method::Frame => "frame",
            Method::Watertight => "watertight",
            Method::Plucker => "plucker",
        }
    }
}

/// What a kernel promises beyond the [`Intersector`] contract ([`Intersector::GUARANTEES`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Guarantees {
    /// A ray through an edge or vertex shared by consistently oriented triangles (identical
    /// vertex values in each) hits exactly one of them: no cracks, no double hits.
    pub watertight: bool,
    /// Hit or miss is decided exactly for the values given, and `t`, `u`, `v` are correctly
    /// rounded (the reference the others are judged against).
    pub exact: bool,
}

/// The scalar of the seam: the workspace's one float trait, implemented for `f32` and `f64`
/// only, re-exported so that back ends and the renderer name it from here. Its `mul_add` is
/// always fused (see the `real` crate).
pub use real::Real;

/// A ray: `origin + t * dir` for `t > 0`. `dir` need not be normalised; `t` is measured in
/// units of `dir`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Ray<T> {
    /// The starting point.
    pub origin: [T; 3],
    /// The direction (not necessarily unit length).
    pub dir: [T; 3],
}

impl<T: Real> Ray<T> {
    /// A ray from `origin` along `dir`.
    #[must_use]
    pub const fn new(origin: [T; 3], dir: [T; 3]) -> Self {
        Self { origin, dir }
    }

    /// The point at parameter `t`.
    #[must_use]
    pub fn at(&self, t: T) -> [T; 3] {
        core::array::from_fn(|k| self.origin[k] + t * self.dir[k])
    }

    /// Converts to another precision (rounding to nearest).
    #[must_use]
    pub fn cast<U: Real>(&self) -> Ray<U> {
        Ray { origin: cast3(self.origin), dir: cast3(self.dir) }
    }
}

/// A triangle `(a, b, c)`, counter-clockwise seen from the side its geometric normal
/// `(b - a) x (c - a)` points to.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Triangle<T> {
    /// First vertex.
    pub a: [T; 3],
    /// Second vertex.
    pub b: [T; 3],
    /// Third vertex.
    pub c: [T; 3],
}

impl<T: Real> Triangle<T> {
    /// A triangle from its three vertices.
    #[must_use]
    pub const fn new(a: [T; 3], b: [T; 3], c: [T; 3]) -> Self {
        Self { a, b, c }
    }

    /// The vertices as an array `[a, b, c]`.
    #[must_use]
    pub const fn vertices(&self) -> [[T; 3]; 3] {
        [self.a, self.b, self.c]
    }

    /// The point with barycentric coordinates `(1 - u - v, u, v)`.
    #[must_use]
    pub fn point(&self, u: T, v: T) -> [T; 3] {
        let w = T::ONE - u - v;
        core::array::from_fn(|k| w * self.a[k] + u * self.b[k] + v * self.c[k])
    }

    /// Converts to another precision (rounding to nearest).
    #[must_use]
    pub fn cast<U: Real>(&self) -> Triangle<U> {
        Triangle { a: cast3(self.a), b: cast3(self.b), c: cast3(self.c) }
    }
}

/// What a kernel reports for one ray and one triangle: the distance along the ray and the
/// barycentric coordinates of the hit point, `p = (1 - u - v) a + u b + v c`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct TriangleHit<T> {
    /// Ray parameter of the hit (in units of the ray's direction).
    pub t: T,
    /// Barycentric weight of vertex `b`.
    pub u: T,
    /// Barycentric weight of vertex `c`.
    pub v: T,
}

/// A hit in a scene: a [`TriangleHit`] and the index of the triangle that was hit.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Hit<T> {
    /// Ray parameter of the hit (in units of the ray's direction).
    pub t: T,
    /// Index of the triangle in the scene's triangle order.
    pub prim: u32,
    /// Barycentric weight of vertex `b`.
    pub u: T,
    /// Barycentric weight of vertex `c`.
    pub v: T,
}

impl<T: Real> Hit<T> {
    /// The scene hit made of a kernel's hit on triangle `prim`.
    #[must_use]
    pub const fn new(prim: u32, hit: TriangleHit<T>) -> Self {
        Self { t: hit.t, prim, u: hit.u, v: hit.v }
    }

    /// Whether `self` is nearer than `other`. Ties in `t` (a ray through an edge or vertex
    /// shared by several triangles) go to the lower triangle index, so that every traversal
    /// order, brute force or any BVH, reports the same triangle.
    #[must_use]
    pub fn nearer_than(&self, other: &Self) -> bool {
        self.t < other.t || (self.t == other.t && self.prim < other.prim)
    }
}

/// A ray-triangle back end. See the [crate documentation](crate) for why it has this shape.
///
/// Contract for implementors:
/// - `intersect` reports a hit exactly when the ray meets the triangle's closed interior at a
///   parameter `t` with `0 < t <= t_max`; barycentrics satisfy `u >= 0`, `v >= 0`,
///   `u + v <= 1` up to the kernel's documented rounding.
/// - A degenerate (zero-area) triangle is never hit; no input, NaN included, makes a kernel
///   panic or report a NaN `t`.
/// - `occludes` agrees with `intersect(..).is_some()`.
pub trait Intersector: Sync + Send {
    /// The scalar type: `f32` or `f64`.
    type Real: Real;
    /// Per-triangle data, computed once per triangle by [`Intersector::prepare`].
    type Prim: Send + Sync;
    /// Per-ray data, computed once per ray by [`Intersector::prepare_ray`]; `()` if none.
    type RayData: Copy + Send + Sync;
    /// Data of several consecutive triangles laid out to be tested together (say, their
    /// vertices axis by axis, one lane per triangle), computed once by
    /// [`Intersector::prepare_blocks`]; `()` for a kernel that tests a leaf's triangles one by
    /// one.
    type Block: Send + Sync;
    /// A short name for tables and command lines (`"la"`, `"ga"`, ...).
    const NAME: &'static str;
    /// The algebra the kernel is written in.
    const ALGEBRA: Algebra;
    /// The ray-triangle algorithm the kernel implements.
    const METHOD: Method;
    /// What the kernel promises beyond the trait's contract.
    const GUARANTEES: Guarantees;
    /// Triangles per [`Intersector::Block`]: a BVH starts every leaf at a multiple of it. 1
    /// (the default) for a kernel without blocks.
    const BLOCK: usize = 1;
    /// `None` for a cell of the method x algebra matrix: the method written in the algebra's
    /// own types, with no hand intrinsics and no per-test code on raw arrays. `Some(what)` for
    /// a labelled variant beside its cell (the same method and algebra), `what` saying how it
    /// departs from that rule, e.g. `"hand four-lane SIMD over arrays"`.
    const VARIANT: Option<&'static str>;

    /// Precomputes what the kernel needs of one triangle.
    fn prepare(&self, tri: &Triangle<Self::Real>) -> Self::Prim;

    /// Precomputes what the kernel needs of one ray.
    fn prepare_ray(&self, ray: &Ray<Self::Real>) -> Self::RayData;

    /// The hit of `ray` with the triangle, if any, with `0 < t <= t_max`.
    fn intersect(
        &self,
        prim: &Self::Prim,
        ray: &Ray<Self::Real>,
        ray_data: &Self::RayData,
        t_max: Self::Real,
    ) -> Option<TriangleHit<Self::Real>>;

    /// The blocks of a scene's prepared triangles `prims`, [`Intersector::BLOCK`] at a time:
    /// block `b` holds `prims[BLOCK b..BLOCK (b + 1)]` (the last one padded as the kernel
    /// likes), for [`Intersector::intersect_leaf`] and [`Intersector::occludes_leaf`]. A BVH
    /// starts each leaf at a multiple of `BLOCK`, so a leaf's triangles are the first lanes of
    /// its blocks. The default is none: the leaf queries' defaults test `prims` one by one.
    fn prepare_blocks(&self, prims: &[Self::Prim]) -> Vec<Self::Block> {
        let _ = prims;
        Vec::new()
    }

    /// [`Intersector::intersect`] of `ray` with each triangle of a leaf in turn: `prims`, whose
    /// blocks (from [`Intersector::prepare_blocks`]: the leaf starts at a multiple of
    /// [`Intersector::BLOCK`]) begin `blocks`, which may go on with other leaves' blocks. For
    /// every hit, `found(k, hit, limit)`, `k` the triangle's position in `prims`; `found` may
    /// lower the limit before the next triangle. The calls are exactly those of that loop, in
    /// its order, so every hit is the one `intersect` reports.
    ///
    /// The default is the loop. A kernel with blocks overrides it to test a block's triangles
    /// together, with the same hits bit for bit, ties and limits included
    /// (`conformance::leaf::leaf_agrees_with_one_by_one` tests this).
    #[inline(always)]
    fn intersect_leaf<F>(
        &self,
        prims: &[Self::Prim],
        blocks: &[Self::Block],
        ray: &Ray<Self::Real>,
        ray_data: &Self::RayData,
        limit: &mut Self::Real,
        found: &mut F,
    ) where
        F: FnMut(usize, TriangleHit<Self::Real>, &mut Self::Real),
    {
        let _ = blocks;
        for (k, prim) in prims.iter().enumerate() {
            if let Some(hit) = self.intersect(prim, ray, ray_data, *limit) {
                found(k, hit, limit);
            }
        }
    }

    /// Whether `ray` hits any triangle of a leaf within `(0, t_max]`: what
    /// [`Intersector::occludes`] says of one of them (see [`Intersector::intersect_leaf`]).
    #[inline(always)]
    fn occludes_leaf(
        &self,
        prims: &[Self::Prim],
        blocks: &[Self::Block],
        ray: &Ray<Self::Real>,
        ray_data: &Self::RayData,
        t_max: Self::Real,
    ) -> bool {
        let _ = blocks;
        // A plain loop: `Iter::any` can stay out of line in a traversal loop.
        for prim in prims {
            if self.occludes(prim, ray, ray_data, t_max) {
                return true;
            }
        }
        false
    }

    /// [`Intersector::intersect`] of each of `prims` in turn with each ray of a group: the
    /// rays at the distinct positions `members` of `rays`, ray `r` prepared as `data[r]` and
    /// searching within `limits[r]` (the positions index all three, so that a caller hands
    /// over a subset of its rays without copying them). For every hit,
    /// `found(r, k, hit, &mut limits[r])`, `k` the triangle's position in `prims`; `found` may
    /// lower the limit before the ray meets the next triangle. Each ray sees exactly the calls
    /// of its own loop over `prims`, in order, so every hit is the one `intersect` reports;
    /// rays not in `members` see none.
    ///
    /// The default is that loop. A kernel may override it to test several rays at once (the
    /// leaf stage of the BVH's packet traversal), with the same hits bit for bit, ties and
    /// limits included (`conformance::check_group` tests this).
    #[inline]
    fn intersect_group<F>(
        &self,
        prims: &[Self::Prim],
        rays: &[Ray<Self::Real>],
        data: &[Self::RayData],
        members: &[usize],
        limits: &mut [Self::Real],
        found: &mut F,
    ) where
        F: FnMut(usize, usize, TriangleHit<Self::Real>, &mut Self::Real),
    {
        one_ray_at_a_time(self, prims, rays, data, members, limits, found);
    }

    /// Whether `ray` hits the triangle with `0 < t <= t_max` (any-hit queries, shadows,
    /// alpha masks). The default calls [`Intersector::intersect`].
    #[inline(always)]
    fn occludes(
        &self,
        prim: &Self::Prim,
        ray: &Ray<Self::Real>,
        ray_data: &Self::RayData,
        t_max: Self::Real,
    ) -> bool {
        self.intersect(prim, ray, ray_data, t_max).is_some()
    }
}

/// [`Intersector::intersect_group`] as its default: each triangle in turn with each ray in
/// turn. For kernels that override it and keep this loop for the groups they do not take.
#[inline]
pub fn one_ray_at_a_time<I, F>(
    kernel: &I,
    prims: &[I::Prim],
    rays: &[Ray<I::Real>],
    data: &[I::RayData],
    members: &[usize],
    limits: &mut [I::Real],
    found: &mut F,
) where
    I: Intersector + ?Sized,
    F: FnMut(usize, usize, TriangleHit<I::Real>, &mut I::Real),
{
    for (k, prim) in prims.iter().enumerate() {
        for &r in members {
            if let Some(hit) = kernel.intersect(prim, &rays[r], &data[r], limits[r]) {
                found(r, k, hit, &mut limits[r]);
            }
        }
    }
}

/// The triangles of block `b` of a leaf of `n`, [`Intersector::BLOCK`] to a block, as a mask
/// of the block's lanes (bit `l` for lane `l`), for kernels with blocks.
#[inline(always)]
#[must_use]
pub fn block_lanes<I: Intersector + ?Sized>(b: usize, n: usize) -> u32 {
    let left = n - b * I::BLOCK;
    if left >= I::BLOCK { (1 << I::BLOCK) - 1 } else { (1 << left) - 1 }
}

/// The end of [`Intersector::intersect_leaf`] for a kernel with blocks, once it has tested
/// block `b` of a leaf (`prims`) at once against the limit of the block's start: the lanes
/// `hits`, with `t, u, v` in `out[0..3][lane]`, and the lanes `fallback`, for which the
/// kernel's [`Intersector::intersect`] decides. Reports them in lane order, each hit checked
/// again against the limit that the hits before it left and each fallback lane tested with
/// it, so that the calls of `found` are those of the one-by-one loop.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub fn report_block<I, F, const W: usize>(
    kernel: &I,
    prims: &[I::Prim],
    b: usize,
    (hits, fallback): (u32, u32),
    out: &[[I::Real; W]; 3],
    (ray, ray_data): (&Ray<I::Real>, &I::RayData),
    limit: &mut I::Real,
    found: &mut F,
) where
    I: Intersector + ?Sized,
    F: FnMut(usize, TriangleHit<I::Real>, &mut I::Real),
{
    let mut report = hits | fallback;
    while report != 0 {
        let l = report.trailing_zeros() as usize;
        report &= report - 1;
        let k = b * I::BLOCK + l;
        if fallback >> l & 1 == 1 {
            if let Some(hit) = kernel.intersect(&prims[k], ray, ray_data, *limit) {
                found(k, hit, limit);
            }
        } else if out[0][l] <= *limit {
            found(k, TriangleHit { t: out[0][l], u: out[1][l], v: out[2][l] }, limit);
        }
    }
}

/// Whether a triangle has zero area, decided exactly: its vertices are collinear, or two of
/// them coincide. Every back end that promises never to hit a degenerate triangle asks this
/// once per triangle, at `prepare`.
///
/// The cross product `(b - a) x (c - a)` (the GA back ends' bivector `(b - a) ∧ (c - a)`) has
/// as components the signed areas of the triangle projected onto the yz, zx and xy planes;
/// it is zero exactly when all three are. Each is evaluated with Shewchuk's adaptive exact
/// predicate (`robust::orient2d`); `f32` and `f64` coordinates convert to `f64` exactly, so the
/// answer is exact however the coordinates round, unless an intermediate product underflows
/// (coordinates differing by less than about 1e-150) or overflows. A triangle with a NaN or
/// infinite coordinate is not reported degenerate (its orientations are not zero); the kernels
/// miss it anyway.
///
/// ```
/// use intersect::{Triangle, is_degenerate};
///
/// assert!(is_degenerate(&Triangle::new([0.1, 0.2, 0.3], [0.1, 0.2, 0.3], [1.0, 2.0, 3.0])));
/// assert!(is_degenerate(&Triangle::new([0.0f32, 0.0, 0.0], [1.0, 1.0, 1.0], [3.0, 3.0, 3.0])));
/// assert!(!is_degenerate(&Triangle::new([0.0, 0.0, 0.0], [1.0, 1.0, 1.0], [3.0, 3.0, 3.5])));
/// ```
#[must_use]
pub fn is_degenerate<T: Real>(tri: &Triangle<T>) -> bool {
    let [a, b, c] = tri.vertices().map(|p| p.map(Real::to_f64));
    // (i, j) picks the plane: yz, zx, xy.
    [(1, 2), (2, 0), (0, 1)].into_iter().all(|(i, j)| {
        let project = |p: [f64; 3]| Coord { x: p[i], y: p[j] };
        orient2d(project(a), project(b), project(c)) == 0.0
    })
}

fn cast3<T: Real, U: Real>(p: [T; 3]) -> [U; 3] {
    p.map(|x| U::from_f64(x.to_f64()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ties_go_to_the_lower_index() {
        let a = Hit { t: 1.0, prim: 3, u: 0.0, v: 0.0 };
        let b = Hit { t: 1.0, prim: 7, u: 0.0, v: 0.0 };
        let c = Hit { t: 0.5, prim: 9, u: 0.0, v: 0.0 };
        assert!(a.nearer_than(&b));
        assert!(!b.nearer_than(&a));
        assert!(c.nearer_than(&a));
        assert!(!a.nearer_than(&a));
    }

    #[test]
    fn triangle_point_uses_barycentrics_of_b_and_c() {
        let t = Triangle::new([0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [0.0, 4.0, 0.0]);
        assert_eq!(t.point(0.5, 0.25), [1.0, 1.0, 0.0]);
        assert_eq!(t.point(0.0, 0.0), t.a);
    }

    /// Lattice triangles, some exactly degenerate by chance: [`is_degenerate`] agrees with an
    /// exact integer cross product both ways (so it cannot pass by saying "yes" to
    /// everything), in both precisions.
    #[test]
    fn is_degenerate_matches_an_exact_integer_cross_product() {
        use rand::{Rng, SeedableRng};
        let exact_cross = |[a, b, c]: [[i64; 3]; 3]| -> [i64; 3] {
            let (e, f): ([i64; 3], [i64; 3]) =
                (core::array::from_fn(|n| b[n] - a[n]), core::array::from_fn(|n| c[n] - a[n]));
            [e[1] * f[2] - e[2] * f[1], e[2] * f[0] - e[0] * f[2], e[0] * f[1] - e[1] * f[0]]
        };
        let mut rng = rand_pcg::Pcg64::seed_from_u64(0x5eed_0004);
        let mut flat = 0;
        for _ in 0..20_000 {
            // Small range so that exactly collinear triples happen by chance too.
            let v = [0; 3].map(|_| [0; 3].map(|_| rng.random_range(-2i64..=2)));
            let expect = exact_cross(v) == [0; 3];
            flat += u32::from(expect);
            // Scaled by a power of two, so the coordinates stay exact.
            let [a, b, c] = v.map(|p| p.map(|x| x as f64 * 0.125));
            assert_eq!(is_degenerate(&Triangle::new(a, b, c)), expect, "{v:?}");
            let t32: Triangle<f32> = Triangle::new(a, b, c).cast();
            assert_eq!(is_degenerate(&t32), expect, "{v:?}");
        }
        assert!(flat > 500 && flat < 19_000, "{flat} degenerate of 20000");
    }

    #[test]
    fn ray_at_and_cast() {
        let r = Ray::new([1.0f64, 2.0, 3.0], [0.0, 0.0, -1.0]);
        assert_eq!(r.at(2.0), [1.0, 2.0, 1.0]);
        let r32: Ray<f32> = r.cast();
        assert_eq!(r32.origin, [1.0f32, 2.0, 3.0]);
    }
}
