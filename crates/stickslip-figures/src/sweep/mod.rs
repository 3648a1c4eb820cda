//! Parameter sweeps over independent worlds, in parallel.
//!
//! - [`Range`]: a validated `LO:HI:N` grid.
//! - [`popov`]: μ̄ over β × α per waveform, theory and rapier.
//! - [`feeder`]: transport speed over amplitude × frequency × throw angle in rapier worlds,
//!   beside the rigid-body reference.
//! - [`run_parallel`]: maps a function over the points on an explicit rayon pool; every point
//!   builds its own world, so the results do not depend on the number of threads.
//! - [`output`]: CSV, JSON and heat maps.
//! - [`shard`]: task `K` of `N` (`--shard K/N`) computes a fixed, balanced slice of the grid;
//!   [`shard_file`] writes it with what a merge needs (grid, fingerprint, version, slice) in
//!   the [`exact`] JSON form; [`merge`] checks the shards and puts the full sweep back
//!   together, so its output is byte for byte the unsharded run's.

pub mod exact;
pub mod feeder;
pub mod merge;
pub mod output;
pub mod popov;
mod range;
pub mod shard;
pub mod shard_file;

pub use range::{MAX_RANGE_POINTS, Range};
pub use shard::Shard;

use crate::FigureError;
use rayon::prelude::*;

/// The most points one sweep may have.
pub const MAX_SWEEP_POINTS: u64 = 20_000;
/// The most worker threads a sweep accepts.
pub const MAX_THREADS: usize = 256;

/// Checks that `counts` multiply to at most [`MAX_SWEEP_POINTS`].
pub fn check_total(counts: &[usize]) -> Result<usize, FigureError> {
    let total = counts
        .iter()
        .fold(1u64, |acc, &n| acc.saturating_mul(n as u64));
    if total > MAX_SWEEP_POINTS {
        return Err(FigureError::TooManyPoints {
            count: total,
            limit: MAX_SWEEP_POINTS,
        });
    }
    Ok(total as usize)
}

/// The items at `indices`, in that order; an index off the end is an error.
fn select<T: Copy>(items: &[T], indices: &[usize]) -> Result<Vec<T>, FigureError> {
    indices
        .iter()
        .map(|&i| {
            items.get(i).copied().ok_or_else(|| FigureError::Option {
                name: "--shard".into(),
                reason: format!("point {i} is not on a grid of {} points", items.len()),
            })
        })
        .collect()
}

/// Maps `f` over `items` on a pool of `threads` workers (1..=[`MAX_THREADS`]), calling `tick`
/// after each point; results come back in the order of `items`.
pub fn run_parallel<T, R, F>(
    items: &[T],
    threads: usize,
    tick: &(dyn Fn() + Sync),
    f: F,
) -> Result<Vec<R>, FigureError>
where
    T: Sync,
    R: Send,
    F: Fn(&T) -> Result<R, FigureError> + Sync,
{
    if threads == 0 || threads > MAX_THREADS {
        return Err(FigureError::Option {
            name: "--threads".into(),
            reason: format!("{threads} is not in 1..={MAX_THREADS}"),
        });
    }
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .map_err(|e| FigureError::Threads(e.to_string()))?;
    pool.install(|| {
        items
            .par_iter()
            .map(|item| {
                let r = f(item);
                tick();
                r
            })
            .collect()
    })
}
