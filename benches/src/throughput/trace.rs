//! The tracing loops the throughput bench times: one thread on the calling thread, or every
//! thread of a rayon pool over chunks of rays.

use bvh::accel::Accel;
use intersect::{Intersector, Ray, Real};
use rayon::ThreadPool;
use rayon::prelude::*;

use super::rays::Query;

/// Rays per parallel task: big enough that scheduling costs nothing measurable, small enough
/// (a few image rows) that two threads share the uneven work of a frame evenly.
pub const CHUNK: usize = 2048;

/// What a tracing loop found: the number of hits and a checksum of the triangles hit (so that
/// no result can be discarded, and back ends can be compared).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Traced {
    /// Rays that hit something.
    pub hits: u64,
    /// Wrapping sum of the indices of the triangles hit (0 for any-hit queries).
    pub checksum: u64,
}

impl Traced {
    /// Both counts added.
    #[must_use]
    pub fn merge(self, other: Self) -> Self {
        Self { hits: self.hits + other.hits, checksum: self.checksum.wrapping_add(other.checksum) }
    }
}

/// Traces `rays` one after the other on the calling thread.
#[must_use]
pub fn trace<I: Intersector>(accel: &Accel<I>, rays: &[Ray<I::Real>], query: Query) -> Traced {
    let mut out = Traced::default();
    match query {
        Query::Closest => {
            for ray in rays {
                if let Some(hit) = accel.closest_hit(ray) {
                    out.hits += 1;
                    out.checksum = out.checksum.wrapping_add(u64::from(hit.prim));
                }
            }
        }
        Query::Any => {
            let inf = <I::Real as Real>::INFINITY;
            for ray in rays {
                out.hits += u64::from(accel.any_hit(ray, inf));
            }
        }
    }
    out
}

/// Traces `rays` on every thread of `pool`, [`CHUNK`] rays per task.
#[must_use]
pub fn trace_parallel<I: Intersector>(
    pool: &ThreadPool,
    accel: &Accel<I>,
    rays: &[Ray<I::Real>],
    query: Query,
) -> Traced {
    pool.install(|| {
        rays.par_chunks(CHUNK)
            .map(|chunk| trace(accel, chunk, query))
            .reduce(Traced::default, Traced::merge)
    })
}
