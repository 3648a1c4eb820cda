//! Slicing a grid into `N` shards: task `K` of `N` (1-based, `K` in `1..=N`, as Slurm's
//! `SLURM_ARRAY_TASK_ID` with `--array=1-N`) computes [`Shard::indices`] of the grid's points.
//!
//! The rule: the point indices `0..total` are put in a fixed pseudo-random order (a
//! Fisher–Yates shuffle driven by SplitMix64 with a constant seed, integer arithmetic only, so
//! the same on every machine), then dealt round-robin: shard `K` gets positions `K − 1`,
//! `K − 1 + N`, `K − 1 + 2N`, … of that order, returned sorted. So every point is in exactly
//! one shard for any `N`, and the shards' sizes differ by at most one.
//!
//! Why not contiguous ranges or plain round-robin over the grid order: a point's cost depends
//! on where it is in the grid (a feeder point at 20 Hz takes twice the steps of one at 40 Hz,
//! and frequency is a middle axis), and a job array takes as long as its slowest task.
//! Contiguous ranges give one task all the slow points of a region. Plain round-robin
//! (`i mod N`) balances well when `N` shares no factor with the axes' lengths, but lines up
//! with the axes when it does: `N = 12` on the default 4 × 3 × 3 feeder grid, or `N = 100` on a
//! 10 × 10 × 10 grid, gives every task a single frequency, and the slowest task takes 1.4
//! times the mean. Dealing a scrambled order never lines up with the grid's axes; its balance
//! is statistical: within 1.25 of the mean in those two cases, and within a few percent once
//! every task has tens of points (see the tests).

use serde::{Deserialize, Serialize};
use std::fmt;
use std::str::FromStr;
use thiserror::Error;

/// The most shards a sweep may be cut into (the most points a sweep may have).
pub const MAX_SHARDS: usize = super::MAX_SWEEP_POINTS as usize;

/// The seed of the shuffle. Changing it changes every shard's slice (merges check the slices,
/// so shards from before and after such a change never mix).
const SEED: u64 = 0x5715_C451_1D00_0001;

/// Why a shard specification is invalid.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
pub enum ShardError {
    /// Not of the form `K/N`.
    #[error("`{0}` is not K/N (task K of N, e.g. 3/8)")]
    Syntax(String),
    /// `N` is zero or too large.
    #[error("the shard count N = {0} must be in 1..={MAX_SHARDS}")]
    Count(usize),
    /// `K` is not in `1..=N`.
    #[error("the task K = {index} must be in 1..={count} (K is 1-based)")]
    Index {
        /// K.
        index: usize,
        /// N.
        count: usize,
    },
}

/// Task `index` of `count` (1-based): one slice of a sweep's grid.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(try_from = "RawShard")]
pub struct Shard {
    index: usize,
    count: usize,
}

/// A shard as read from a file, checked by [`Shard::new`].
#[derive(Deserialize)]
struct RawShard {
    index: usize,
    count: usize,
}

impl TryFrom<RawShard> for Shard {
    type Error = ShardError;
    fn try_from(raw: RawShard) -> Result<Self, ShardError> {
        Shard::new(raw.index, raw.count)
    }
}

impl Shard {
    /// Task `index` (1-based) of `count`.
    pub fn new(index: usize, count: usize) -> Result<Shard, ShardError> {
        if count == 0 || count > MAX_SHARDS {
            return Err(ShardError::Count(count));
        }
        if index == 0 || index > count {
            return Err(ShardError::Index { index, count });
        }
        Ok(Shard { index, count })
    }

    /// K, 1-based.
    pub fn index(self) -> usize {
        self.index
    }

    /// N.
    pub fn count(self) -> usize {
        self.count
    }

    /// The indices (ascending) of the points of a grid of `total` points that this shard
    /// computes; see the module's documentation for the rule.
    pub fn indices(self, total: usize) -> Vec<usize> {
        let order = scrambled(total);
        let mut out: Vec<usize> = order
            .into_iter()
            .skip(self.index - 1)
            .step_by(self.count)
            .collect();
        out.sort_unstable();
        out
    }

    /// The file-name tag of this shard, `shard-K-of-N`.
    pub fn tag(self) -> String {
        format!("shard-{}-of-{}", self.index, self.count)
    }
}

impl fmt::Display for Shard {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}/{}", self.index, self.count)
    }
}

impl FromStr for Shard {
    type Err = ShardError;
    fn from_str(text: &str) -> Result<Shard, ShardError> {
        let syntax = || ShardError::Syntax(text.to_string());
        let (k, n) = text.split_once('/').ok_or_else(syntax)?;
        let k: usize = k.trim().parse().map_err(|_| syntax())?;
        let n: usize = n.trim().parse().map_err(|_| syntax())?;
        Shard::new(k, n)
    }
}

/// SplitMix64 (Steele, Lea, Flood 2014): a tiny, well-mixed generator with a fixed output for
/// a fixed seed.
struct SplitMix64(u64);

impl SplitMix64 {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// A value in `0..bound` (`bound ≥ 1`; the modulo bias is below 2⁻⁴⁹ for the grids here and
    /// only makes the order a little less uniform, never wrong).
    fn below(&mut self, bound: usize) -> usize {
        (self.next() % bound as u64) as usize
    }
}

/// `0..total` in the fixed scrambled order (Fisher–Yates).
fn scrambled(total: usize) -> Vec<usize> {
    let mut order: Vec<usize> = (0..total).collect();
    let mut rng = SplitMix64(SEED);
    for i in (1..total).rev() {
        let j = rng.below(i + 1);
        order.swap(i, j);
    }
    order
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_point_is_in_exactly_one_shard_and_sizes_differ_by_at_most_one() {
        for total in [0, 1, 2, 7, 16, 36, 100, 1001] {
            for count in [1, 2, 3, 7, 12, 36, 50, 2000] {
                let mut seen = vec![0u32; total];
                let mut sizes = Vec::new();
                for k in 1..=count {
                    let idx = Shard::new(k, count).unwrap().indices(total);
                    assert!(idx.windows(2).all(|w| w[0] < w[1]), "sorted, no repeats");
                    for &i in &idx {
                        seen[i] += 1;
                    }
                    sizes.push(idx.len());
                }
                assert!(seen.iter().all(|&s| s == 1), "total {total}, N {count}");
                let (lo, hi) = (sizes.iter().min().unwrap(), sizes.iter().max().unwrap());
                assert!(hi - lo <= 1, "total {total}, N {count}: sizes {lo}..{hi}");
            }
        }
    }

    #[test]
    fn one_shard_is_the_whole_grid() {
        assert_eq!(
            Shard::new(1, 1).unwrap().indices(10),
            (0..10).collect::<Vec<_>>()
        );
    }

    #[test]
    fn the_slices_are_fixed() {
        // A change of the rule or the seed shows here first (shard files record their slices
        // and merges check them, so such a change needs the format version bumped).
        let got: Vec<Vec<usize>> = (1..=3)
            .map(|k| Shard::new(k, 3).unwrap().indices(10))
            .collect();
        assert_eq!(got, FIXED_SLICES_10_OF_3);
    }

    const FIXED_SLICES_10_OF_3: [&[usize]; 3] = [&[1, 2, 5, 8], &[3, 7, 9], &[0, 4, 6]];

    /// The slowest task's cost over the mean task's, on a feeder-like grid (amplitude
    /// fastest, then frequency from 20 to 40 Hz, then angle) where a point costs 1/f.
    fn worst_over_mean(axes: (usize, usize, usize), slices: &[Vec<usize>]) -> f64 {
        let (na, nf, _) = axes;
        let cost = |i: usize| 1.0 / (20.0 + 20.0 * ((i / na) % nf) as f64 / (nf - 1) as f64);
        let costs: Vec<f64> = slices
            .iter()
            .map(|s| s.iter().map(|&i| cost(i)).sum())
            .collect();
        let mean = costs.iter().sum::<f64>() / costs.len() as f64;
        costs.iter().cloned().fold(0.0, f64::max) / mean
    }

    #[test]
    fn scrambling_avoids_the_grid_axes() {
        // When N is the product of the inner axes' lengths (12 for the default 4 × 3 × 3
        // feeder grid, 100 for a 10 × 10 × 10 grid), `i mod N` gives every task one
        // frequency: its slowest task is 1.4 times the mean; the scrambled deal stays within
        // 1.25 (and within 1.02 of i mod N's balance elsewhere, e.g. N = 12 on 10 × 10 × 10).
        for (axes, n, scrambled_max, round_robin_min) in [
            ((4, 3, 3), 12, 1.25, 1.38),
            ((10, 10, 10), 100, 1.2, 1.4),
            ((10, 10, 10), 12, 1.02, 1.0),
        ] {
            let total = axes.0 * axes.1 * axes.2;
            let scrambled: Vec<Vec<usize>> = (1..=n)
                .map(|k| Shard::new(k, n).unwrap().indices(total))
                .collect();
            let round_robin: Vec<Vec<usize>> =
                (0..n).map(|k| (k..total).step_by(n).collect()).collect();
            let (s, r) = (
                worst_over_mean(axes, &scrambled),
                worst_over_mean(axes, &round_robin),
            );
            assert!(s <= scrambled_max, "{axes:?} N {n}: scrambled {s:.3}");
            assert!(r >= round_robin_min, "{axes:?} N {n}: i mod N {r:.3}");
        }
    }

    #[test]
    fn parses_and_refuses() {
        let s: Shard = "3/7".parse().unwrap();
        assert_eq!((s.index(), s.count(), s.to_string()), (3, 7, "3/7".into()));
        assert_eq!(s.tag(), "shard-3-of-7");
        assert_eq!("1/1".parse::<Shard>(), Shard::new(1, 1));
        for (bad, err) in [
            ("", ShardError::Syntax(String::new())),
            ("3", ShardError::Syntax("3".into())),
            ("a/3", ShardError::Syntax("a/3".into())),
            ("1/2/3", ShardError::Syntax("1/2/3".into())),
            ("-1/3", ShardError::Syntax("-1/3".into())),
            ("0/3", ShardError::Index { index: 0, count: 3 }),
            ("4/3", ShardError::Index { index: 4, count: 3 }),
            ("1/0", ShardError::Count(0)),
            ("1/20001", ShardError::Count(20001)),
        ] {
            assert_eq!(bad.parse::<Shard>(), Err(err), "{bad}");
        }
        let json: Result<Shard, _> = serde_json::from_str(r#"{"index":0,"count":2}"#);
        assert!(json.unwrap_err().to_string().contains("1-based"));
    }
}
