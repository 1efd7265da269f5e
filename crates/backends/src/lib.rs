//! The registry of ray-triangle back ends: every program, bench and test that needs "each back
//! end" reads [`Backend::ALL`] and runs work through [`dispatch`], so that no list of back
//! ends is written anywhere else.
//!
//! What a back end is (its `--backend` name, [`Algebra`], [`Method`], [`Guarantees`] and
//! whether it is a cell of the method x algebra matrix or a labelled variant beside one) is
//! declared by its kernel, as the consts of [`Intersector`]; the registry reads them from the
//! kernel ([`Backend::declared`], [`Backend::name`], [`Backend::algebra`],
//! [`Backend::variant`], ...) and keeps nothing of its own but the one-line description shown
//! by `--help`.
//!
//! ```
//! use backends::{Algebra, Backend, Job, Precision, dispatch};
//! use intersect::{Intersector, Real};
//!
//! /// A job that reports which kernel it was given, and in which precision.
//! struct Name;
//!
//! impl Job for Name {
//!     type Output = (&'static str, u32);
//!     fn run<I: Intersector + 'static>(self, _intersector: I) -> (&'static str, u32) {
//!         (I::NAME, <I::Real as Real>::MANTISSA_DIGITS)
//!     }
//! }
//!
//! assert_eq!(dispatch(Backend::LaWatertight, Precision::F32, Name), ("la", 24));
//! assert_eq!(dispatch(Backend::LaMt, Precision::F64, Name), ("la-mt", 53));
//! // Every back end, in both precisions, runs the kernel the registry names.
//! for backend in Backend::ALL {
//!     for precision in Precision::ALL {
//!         assert_eq!(dispatch(backend, precision, Name).0, backend.name());
//!     }
//! }
//! assert_eq!(Backend::from_name("ga-plucker"), Some(Backend::G3Watertight));
//! assert!(Backend::ALL.iter().any(|b| b.algebra() == Algebra::G3));
//! ```
//!
//! # The method x algebra matrix
//!
//! Rows are methods ([`Method`]), columns algebras ([`Algebra`]); a *cell* is the back end
//! that implements one method in one algebra ([`Backend::variant`] is `None`), and
//! [`Backend::cell`] finds it. A back end that implements a cell's method and algebra but
//! breaks one of the rules below (hand intrinsics, per-test code on raw arrays) is a
//! *variant*: it is listed and measured beside its cell, labelled with what it does
//! differently (`Some("hand four-lane SIMD over arrays")`), and never stands for the cell.
//!
//! ## Rules for a fair row
//!
//! A row compares algebras, so everything but the algebra is held fixed across it, and each
//! kernel's module documentation states what is needed to check it by review:
//!
//! 1. **The same method**: the same mathematics in every cell of a row (the method's
//!    derivation is written once per cell, in the cell's own terms, and says which cell it
//!    mirrors).
//! 2. **The same per-triangle data**: the same quantities precomputed at
//!    [`Intersector::prepare`], in the same precision, the bytes per triangle reported in the
//!    kernel's documentation (a cell may not precompute what its neighbours compute per ray).
//!    Leaf blocks ([`Intersector::Block`]) lay out the same data for testing several triangles
//!    at once. The watertight row has them in every algebra, four triangles per test: `la` in
//!    glam's 4-vectors, the GA cells in their own types on four-lane coefficients
//!    (`ga::Lanes4`: `Vector<Lanes4<f32>>` is four vectors, and the generated products act
//!    lane by lane), with the leaf stage of `kernels_g3::blocks`, for closest hits (any-hit
//!    queries test the GA cells' triangles one by one: their blocks lost there). The other rows
//!    test one triangle at a time in every cell.
//! 3. **The same decision order and tie rule**: the tests made in the same order (which
//!    decides which branch ends most tests), the same closed or half-open edges, the same tie
//!    rule and exact fallback for watertight methods, the same `t_max` slack.
//! 4. **Per-test code in the cell's own algebra types**: glam `Vec3A` / `DVec3` for
//!    [`Algebra::La`], `ga::g3` types and their operators (`^`, `|`, `*`, `&`) for
//!    [`Algebra::G3`], `ga::pga` planes, lines, points and motors for [`Algebra::Pga`],
//!    `ga::cga` vectors, flats and dual planes for [`Algebra::Cga`], with no hand intrinsics and no
//!    per-test code on raw arrays or lanes; what the generated products and the compiler make of
//!    that is what is measured, so that the cost of writing a tracer in the algebra is the cost
//!    reported. (A leaf block's products are the same types on `ga::Lanes4` coefficients; the
//!    decisions on the values they give, signs, the distance test and the division, are on
//!    scalars, or lane by lane on `Lanes4` in a block, as in every algebra of the row.)
//!
//! # Adding a back end
//!
//! 1. Write the kernel in a kernel crate (`kernels-la`, `kernels-g3`, `kernels-pga`, `kernels-cga`,
//!    or a new one added to this crate's dependencies): a type generic over `f32` and `f64` with a
//!    `new()` constructor, implementing [`Intersector`] with its `NAME` (the `--backend` name),
//!    `ALGEBRA`, `METHOD`, `GUARANTEES` and `VARIANT` (`None` for a cell), and its own tests (one
//!    call per precision to the conformance checks of `intersect`, and a call in `kernels-la`'s
//!    `tests/agreement.rs` or `kernels-g3`'s `tests/accuracy.rs`). The kernel's module
//!    documentation states what the [rules for a fair row](#rules-for-a-fair-row) ask: the method
//!    and which cells it mirrors, the bytes per triangle, the operations per test and the tie rule.
//! 2. Add one entry to the `registry!` list in this file: a one-line description (the
//!    variant's doc and the `--help` text), the variant, and the kernel's path. Every test
//!    that loops over [`Backend::ALL`] then runs it, `tests/rows.rs` among them (each cell
//!    against its row's LA cell).
//! 3. Document it: a row in the README's back-end tables (a test fails until the rows match
//!    [`Backend::ALL`]), and rerun the benches so that `results/` holds it (a test fails
//!    until every table of `results/` has a row for it).
//!
//! The CLI's `--backend`, every bench and every test that enumerates back ends (the
//! agreement tests, the accuracy suite and its summary, which sorts back ends by
//! [`Algebra`]) follow from the entry.

#![deny(missing_docs)]

pub mod machine;

pub use intersect::{Algebra, Guarantees, Method};

use intersect::Intersector;

/// Declares the back ends: each entry is a one-line description, the variant and the
/// kernel's type (generic over the precision), and becomes a variant of [`Backend`], an
/// element of [`Backend::ALL`] and an arm of [`dispatch`].
macro_rules! registry {
    ($(#[doc = $help:literal] $variant:ident => $($kernel:ident)::+,)+) => {
        /// The ray-triangle back ends a program can use (`--backend`): see [`Backend::ALL`].
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
        pub enum Backend {
            $(#[doc = $help] $variant,)+
        }

        impl Backend {
            /// Every back end, in the order of tables and `--help`; the first is the default.
            pub const ALL: [Backend; [$(Backend::$variant),+].len()] = [$(Backend::$variant),+];

            /// What the back end's kernel declares about itself (read from its `f32`
            /// instance; a test checks that the `f64` one declares the same).
            #[must_use]
            pub const fn declared(self) -> Declared {
                match self {
                    $(Backend::$variant => Declared::of::<$($kernel)::+<f32>>(),)+
                }
            }

            /// The one-line description (`--help`), without its final full stop.
            #[must_use]
            pub fn help(self) -> &'static str {
                let line = match self {
                    $(Backend::$variant => $help,)+
                };
                let line = line.trim();
                line.strip_suffix('.').unwrap_or(line)
            }
        }

        /// Runs `job` with the back end named by `backend` and `precision`.
        pub fn dispatch<J: Job>(backend: Backend, precision: Precision, job: J) -> J::Output {
            let f64 = precision == Precision::F64;
            match backend {
                $(Backend::$variant => either(
                    f64,
                    job,
                    $($kernel)::+::<f32>::new(),
                    $($kernel)::+::<f64>::new(),
                ),)+
            }
        }
    };
}

registry! {
    /// glam, watertight kernel (Woop, Benthin, Wald 2013): no cracks between triangles.
    LaWatertight => kernels_la::Watertight,
    /// glam, Moller-Trumbore kernel.
    LaMt => kernels_la::MollerTrumbore,
    /// glam, the report's method step by step (plane, line-plane intersection, edge tests).
    LaReport => kernels_la::Report,
    /// glam, the frame method: precomputed unit normal and reciprocal frame (as `ga`).
    LaFrame => kernels_la::Frame,
    /// glam, Plücker coordinates: the ray's line against the edges' lines (six-vector form).
    LaPlucker => kernels_la::Plucker,
    /// geometric algebra, the report's method with the per-triangle part precomputed.
    G3Frame => kernels_g3::G3Frame,
    /// geometric algebra, the report's method step by step, as written.
    G3Report => kernels_g3::G3Report,
    /// geometric algebra, watertight: which side of each edge the ray passes, as a trivector.
    G3Watertight => kernels_g3::G3Watertight,
    /// geometric algebra, Moller-Trumbore with its determinants as trivectors.
    G3Mt => kernels_g3::G3Mt,
    /// geometric algebra, the frame method (as `ga`) written in plain GA types.
    G3FrameCell => kernels_g3::G3FrameCell,
    /// geometric algebra, watertight edge trivectors (as `ga-plucker`) in plain GA types.
    G3WatertightCell => kernels_g3::G3WatertightCell,
    /// geometric algebra, Plücker lines as direction vectors and moment bivectors.
    G3Plucker => kernels_g3::G3Plucker,
    /// projective GA, the report's method step by step: join, meet, edge planes.
    PgaReport => kernels_pga::PgaReport,
    /// projective GA, Moller-Trumbore with its determinants as joins of ideal points.
    PgaMt => kernels_pga::PgaMt,
    /// projective GA, the frame method: the triangle's plane and two barycentric planes.
    PgaFrame => kernels_pga::PgaFrame,
    /// projective GA, watertight: vertices seen along the ray by two planes of its pencil.
    PgaWatertight => kernels_pga::PgaWatertight,
    /// projective GA, Plücker lines: each edge test the join `line & line`.
    PgaPlucker => kernels_pga::PgaPlucker,
    /// conformal GA, the report's steps with conformal planes, lines and flat points.
    CgaReport => kernels_cga::CgaReport,
    /// conformal GA, Moller-Trumbore with its determinants as outer products of directions.
    CgaMt => kernels_cga::CgaMt,
    /// conformal GA, the frame method: the plane and reciprocal frame as dual planes.
    CgaFrame => kernels_cga::CgaFrame,
    /// conformal GA, watertight: each edge's points outer the ray's flat line, exact signs.
    CgaWatertight => kernels_cga::CgaWatertight,
    /// conformal GA, Plücker coordinates as flat lines, sides from their regressive product.
    CgaPlucker => kernels_cga::CgaPlucker,
}

impl Backend {
    /// The kernel's [`Intersector::NAME`]: the `--backend` name and the name in tables
    /// (`"la"`, `"ga-plucker"`, ...).
    #[must_use]
    pub const fn name(self) -> &'static str {
        self.declared().name
    }

    /// The kernel's [`Intersector::ALGEBRA`].
    #[must_use]
    pub const fn algebra(self) -> Algebra {
        self.declared().algebra
    }

    /// The kernel's [`Intersector::METHOD`].
    #[must_use]
    pub const fn method(self) -> Method {
        self.declared().method
    }

    /// The kernel's [`Intersector::GUARANTEES`].
    #[must_use]
    pub const fn guarantees(self) -> Guarantees {
        self.declared().guarantees
    }

    /// The kernel's [`Intersector::VARIANT`]: `None` for the cell of its method and algebra,
    /// `Some(what)` for a labelled variant beside that cell, `what` saying how it departs
    /// from the [rules for a fair row](crate#rules-for-a-fair-row).
    #[must_use]
    pub const fn variant(self) -> Option<&'static str> {
        self.declared().variant
    }

    /// The cell of the method x algebra matrix for `method` and `algebra`: the back end with
    /// that method and algebra that is not a variant, if there is one.
    #[must_use]
    pub fn cell(method: Method, algebra: Algebra) -> Option<Backend> {
        Backend::ALL
            .into_iter()
            .find(|b| b.method() == method && b.algebra() == algebra && b.variant().is_none())
    }

    /// The back end the others are compared with (the `ratio_to_la` columns of `results/`)
    /// and the default of `--backend`.
    pub const BASELINE: Backend = Backend::ALL[0];

    /// The back end whose [`name`](Backend::name) is `name`, if any.
    #[must_use]
    pub fn from_name(name: &str) -> Option<Backend> {
        Backend::ALL.into_iter().find(|b| b.name() == name)
    }
}

impl Default for Backend {
    fn default() -> Self {
        Backend::BASELINE
    }
}

#[cfg(feature = "clap")]
impl clap::ValueEnum for Backend {
    fn value_variants<'a>() -> &'a [Self] {
        &Backend::ALL
    }

    fn to_possible_value(&self) -> Option<clap::builder::PossibleValue> {
        Some(clap::builder::PossibleValue::new(self.name()).help(self.help()))
    }
}

/// What a kernel declares about itself: its [`Intersector`] consts, as one value.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Declared {
    /// [`Intersector::NAME`].
    pub name: &'static str,
    /// [`Intersector::ALGEBRA`].
    pub algebra: Algebra,
    /// [`Intersector::METHOD`].
    pub method: Method,
    /// [`Intersector::GUARANTEES`].
    pub guarantees: Guarantees,
    /// [`Intersector::VARIANT`].
    pub variant: Option<&'static str>,
}

impl Declared {
    /// What `I` declares (also for kernels that are not a `--backend`, such as the exact
    /// reference).
    #[must_use]
    pub const fn of<I: Intersector>() -> Declared {
        Declared {
            name: I::NAME,
            algebra: I::ALGEBRA,
            method: I::METHOD,
            guarantees: I::GUARANTEES,
            variant: I::VARIANT,
        }
    }
}

/// The precision of rays, triangles and kernels (`--precision`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "clap", derive(clap::ValueEnum))]
pub enum Precision {
    /// 32-bit floats.
    #[default]
    F32,
    /// 64-bit floats.
    F64,
}

impl Precision {
    /// Both precisions, `f32` first.
    pub const ALL: [Precision; 2] = [Precision::F32, Precision::F64];

    /// `"f32"` or `"f64"`.
    #[must_use]
    pub const fn name(self) -> &'static str {
        match self {
            Precision::F32 => "f32",
            Precision::F64 => "f64",
        }
    }

    /// The precision whose [`name`](Precision::name) is `name`, if any.
    #[must_use]
    pub fn from_name(name: &str) -> Option<Precision> {
        Precision::ALL.into_iter().find(|p| p.name() == name)
    }
}

/// Work to be done with one back end, whichever it is: [`dispatch`] picks the back end from
/// the command line once, and `run` is then compiled for each back end (static dispatch all
/// the way down to the kernel).
pub trait Job {
    /// What the work produces.
    type Output;
    /// Does the work with `intersector`.
    fn run<I: Intersector + 'static>(self, intersector: I) -> Self::Output;
}

/// `job` run with `b` if `second`, else with `a`.
fn either<J: Job, A, B>(second: bool, job: J, a: A, b: B) -> J::Output
where
    A: Intersector + 'static,
    B: Intersector + 'static,
{
    if second { job.run(b) } else { job.run(a) }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// What the kernel dispatched for a back end and precision declares, and its precision.
    struct Dispatched;

    impl Job for Dispatched {
        type Output = (Declared, u32);
        fn run<I: Intersector + 'static>(self, _: I) -> Self::Output {
            (Declared::of::<I>(), <I::Real as intersect::Real>::MANTISSA_DIGITS)
        }
    }

    #[test]
    fn every_backend_and_precision_dispatches() {
        let name_digits = |b, p| {
            let (declared, digits) = dispatch(b, p, Dispatched);
            (declared.name, digits)
        };
        assert_eq!(name_digits(Backend::LaWatertight, Precision::F32), ("la", 24));
        assert_eq!(name_digits(Backend::LaWatertight, Precision::F64), ("la", 53));
        assert_eq!(name_digits(Backend::LaMt, Precision::F32), ("la-mt", 24));
        assert_eq!(name_digits(Backend::LaMt, Precision::F64), ("la-mt", 53));
        assert_eq!(name_digits(Backend::G3Frame, Precision::F32), ("ga", 24));
        assert_eq!(name_digits(Backend::G3Report, Precision::F64), ("ga-report", 53));
        assert_eq!(name_digits(Backend::G3Watertight, Precision::F32), ("ga-plucker", 24));
    }

    #[test]
    fn the_registry_reads_what_the_dispatched_kernel_declares() {
        for b in Backend::ALL {
            for p in Precision::ALL {
                let (declared, digits) = dispatch(b, p, Dispatched);
                assert_eq!(declared, b.declared(), "{b:?} {p:?}");
                assert_eq!(digits, if p == Precision::F32 { 24 } else { 53 });
            }
        }
    }

    #[test]
    fn kernels_declare_their_algebra_method_and_guarantees() {
        let wt = Guarantees { watertight: true, exact: false };
        let none = Guarantees::default();
        let expect = [
            (Backend::LaWatertight, Algebra::La, Method::Watertight, wt),
            (Backend::LaMt, Algebra::La, Method::MollerTrumbore, none),
            (Backend::G3Frame, Algebra::G3, Method::Frame, none),
            (Backend::G3Report, Algebra::G3, Method::Report, none),
            (Backend::G3Watertight, Algebra::G3, Method::Watertight, wt),
            (Backend::PgaWatertight, Algebra::Pga, Method::Watertight, wt),
            (Backend::PgaPlucker, Algebra::Pga, Method::Plucker, none),
        ];
        for (b, algebra, method, guarantees) in expect {
            assert_eq!((b.algebra(), b.method(), b.guarantees()), (algebra, method, guarantees));
        }
        // The reference is not a `--backend`, but declares itself the same way.
        let exact = Declared::of::<exact::Exact>();
        assert_eq!(exact.guarantees, Guarantees { watertight: true, exact: true });
        assert_eq!((exact.name, exact.method), ("exact", Method::Watertight));
    }

    /// `ga` and `ga-plucker` are hand-SIMD variants; every other back end is a cell, and no
    /// two cells share a method and an algebra.
    #[test]
    fn variants_are_labelled_and_cells_are_unique() {
        let simd = Some("hand four-lane SIMD over arrays");
        assert_eq!(Backend::G3Frame.variant(), simd);
        assert_eq!(Backend::G3Watertight.variant(), simd);
        assert_eq!(Backend::LaWatertight.variant(), None);
        assert_eq!(Backend::cell(Method::Watertight, Algebra::La), Some(Backend::LaWatertight));
        assert_eq!(Backend::cell(Method::Report, Algebra::G3), Some(Backend::G3Report));
        assert_eq!(Backend::cell(Method::Frame, Algebra::G3), Some(Backend::G3FrameCell));
        let watertight = Backend::cell(Method::Watertight, Algebra::G3);
        assert_eq!(watertight, Some(Backend::G3WatertightCell));
        assert_eq!(Backend::cell(Method::Report, Algebra::Cga), Some(Backend::CgaReport));
        assert_eq!(Backend::cell(Method::Frame, Algebra::Pga), Some(Backend::PgaFrame));
        for (i, b) in Backend::ALL.into_iter().enumerate() {
            assert!(b.variant().is_none_or(|v| !v.is_empty()), "{b:?}");
            // A variant stands beside its cell, never alone.
            let cell = Backend::cell(b.method(), b.algebra());
            assert!(cell.is_some_and(|c| c.variant().is_none()), "{b:?} has no cell");
            let same_cell = |a: &Backend| {
                a.variant().is_none() && (a.method(), a.algebra()) == (b.method(), b.algebra())
            };
            assert!(b.variant().is_some() || !Backend::ALL[..i].iter().any(same_cell), "{b:?}");
        }
    }

    #[test]
    fn names_are_unique_and_found_back() {
        for (i, b) in Backend::ALL.into_iter().enumerate() {
            assert_eq!(Backend::from_name(b.name()), Some(b));
            assert!(Backend::ALL[..i].iter().all(|a| a.name() != b.name()), "{b:?}");
            assert!(!b.help().is_empty() && !b.help().ends_with('.'), "{b:?}");
        }
        assert_eq!(Backend::from_name("exact"), None);
        assert_eq!(Backend::from_name("LA"), None);
        assert_eq!(Backend::default(), Backend::LaWatertight);
        assert_eq!(Backend::BASELINE, Backend::LaWatertight);
    }

    #[test]
    fn algebra_names_and_kinds() {
        assert_eq!(Algebra::La.name(), "la");
        assert!(!Algebra::La.is_geometric());
        for a in [Algebra::G3, Algebra::Pga, Algebra::Cga] {
            assert!(a.is_geometric(), "{a:?}");
        }
        assert_eq!(Method::MollerTrumbore.name(), "mt");
    }

    #[cfg(feature = "clap")]
    #[test]
    fn clap_values_are_the_registry() {
        use clap::ValueEnum as _;
        assert_eq!(Backend::value_variants(), Backend::ALL);
        for b in Backend::ALL {
            let value = b.to_possible_value().unwrap();
            assert_eq!(value.get_name(), b.name());
            assert_eq!(Backend::from_str(b.name(), false), Ok(b));
        }
        assert_eq!(Precision::from_str("f64", false), Ok(Precision::F64));
    }
}
