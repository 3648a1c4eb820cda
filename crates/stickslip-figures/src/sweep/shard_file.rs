//! What one shard writes: `NAME.shard-K-of-N.csv` (its rows of the table, in grid order, in
//! the unsharded CSV's format) and `NAME.shard-K-of-N.json`, the [`ShardFile`]: format and
//! tool version, the sweep kind, the grid's fingerprint and size, the shard `K/N`, the
//! indices of its points in the grid, the grid itself and the points, the last two in the
//! [exact form](super::exact) so a merge reproduces the unsharded output byte for byte.
//!
//! ```json
//! {
//!   "format": "stickslip-sweep-shard",
//!   "format_version": 1,
//!   "tool_version": "0.1.0",
//!   "kind": "popov",
//!   "fingerprint": "fnv1a64:9f0c6d2a1b3e4f57",
//!   "total": 16,
//!   "shard": { "index": 2, "count": 7 },
//!   "indices": [3, 11],
//!   "sweep": { "waveforms": ["sine"], "beta": { "lo": "5e-1", "hi": "1.2e1", "n": 8 }, … },
//!   "points": [ { "waveform": "sine", "beta": "2.142857142857143e0", … }, … ]
//! }
//! ```

use super::exact::{ExactJson, ExactRef};
use super::feeder::{FeederPoint, FeederSweep};
use super::output::{self, feeder_csv, popov_csv, write_feeder, write_popov};
use super::popov::{PopovPoint, PopovSweep};
use super::shard::Shard;
use crate::FigureError;
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};

/// The `format` of a shard file.
pub const FORMAT: &str = "stickslip-sweep-shard";
/// The `format_version` this build writes and reads.
pub const FORMAT_VERSION: u32 = 1;
/// The version of stickslip that writes the shard files (the workspace's version).
pub const TOOL_VERSION: &str = env!("CARGO_PKG_VERSION");

/// A sweep that can be cut into shards and merged back: Popov and feeder sweeps.
pub trait Sharded: ExactJson + Sized {
    /// One point of its table.
    type Point: ExactJson + Clone;
    /// Its name: the output's file stem and the shard file's `kind`.
    const NAME: &'static str;
    /// Checks the sweep; the number of points of its grid.
    fn total(&self) -> Result<usize, FigureError>;
    /// Computes the points at `indices` of the grid on `threads` workers, calling `tick` after
    /// each point.
    fn run_indices(
        &self,
        indices: &[usize],
        threads: usize,
        tick: &(dyn Fn() + Sync),
    ) -> Result<Vec<Self::Point>, FigureError>;
    /// The first of `indices` whose point in `points` (in the same order) does not have the
    /// coordinates of the grid's point there: a merge's check that a shard's points are where
    /// its indices say.
    fn off_grid(&self, indices: &[usize], points: &[Self::Point]) -> Option<usize>;
    /// The CSV table of `points`.
    fn csv(points: &[Self::Point]) -> String;
    /// Writes the unsharded output (CSV, JSON, heat maps) of the whole grid into `dir`.
    fn write(&self, dir: &Path, points: &[Self::Point]) -> Result<Vec<PathBuf>, FigureError>;
}

/// The JSON file of one shard. `S` and `P` are the sweep and point types in their exact form
/// (or [`serde::de::IgnoredAny`] to read the rest alone).
#[derive(Debug, Serialize, Deserialize)]
pub struct ShardFile<S, P> {
    /// Always [`FORMAT`].
    pub format: String,
    /// [`FORMAT_VERSION`] of the writer.
    pub format_version: u32,
    /// [`TOOL_VERSION`] of the writer.
    pub tool_version: String,
    /// [`Sharded::NAME`] of the sweep.
    pub kind: String,
    /// [`fingerprint`] of the sweep.
    pub fingerprint: String,
    /// Points in the whole grid.
    pub total: usize,
    /// Which shard.
    pub shard: Shard,
    /// The grid indices of `points`, ascending: [`Shard::indices`] of `total`.
    pub indices: Vec<usize>,
    /// The sweep (the whole grid).
    pub sweep: S,
    /// The shard's points, in the order of `indices`.
    pub points: Vec<P>,
}

/// The grid's fingerprint: FNV-1a (64 bit) of the kind and the sweep's exact JSON, as
/// `fnv1a64:` and 16 hex digits. Equal sweeps have equal fingerprints on every machine.
pub fn fingerprint<S: Sharded>(sweep: &S) -> Result<String, FigureError> {
    let text = serde_json::to_string(&ExactRef(sweep))?;
    let mut hash: u64 = 0xcbf2_9ce4_8422_2325;
    for byte in S::NAME.bytes().chain([b'\n']).chain(text.bytes()) {
        hash = (hash ^ u64::from(byte)).wrapping_mul(0x0000_0100_0000_01b3);
    }
    Ok(format!("fnv1a64:{hash:016x}"))
}

/// The file stem of `shard` of a `NAME` sweep: `NAME.shard-K-of-N`.
pub fn stem(name: &str, shard: Shard) -> String {
    format!("{name}.{}", shard.tag())
}

/// Writes `NAME.shard-K-of-N.csv` and `NAME.shard-K-of-N.json` for the `points` (at
/// `shard.indices(total)`) of `sweep` into `dir`; returns the paths.
pub fn write_shard<S: Sharded>(
    dir: &Path,
    sweep: &S,
    shard: Shard,
    points: &[S::Point],
) -> Result<Vec<PathBuf>, FigureError> {
    let total = sweep.total()?;
    let indices = shard.indices(total);
    if indices.len() != points.len() {
        return Err(FigureError::Option {
            name: "--shard".into(),
            reason: format!(
                "shard {shard} has {} points, {} were given",
                indices.len(),
                points.len()
            ),
        });
    }
    std::fs::create_dir_all(dir).map_err(|e| FigureError::io(dir, e))?;
    let stem = stem(S::NAME, shard);
    let file = ShardFile {
        format: FORMAT.into(),
        format_version: FORMAT_VERSION,
        tool_version: TOOL_VERSION.into(),
        kind: S::NAME.into(),
        fingerprint: fingerprint(sweep)?,
        total,
        shard,
        indices,
        sweep: ExactRef(sweep),
        points: points.iter().map(ExactRef).collect(),
    };
    Ok(vec![
        output::write(dir.join(format!("{stem}.csv")), &S::csv(points))?,
        output::write(
            dir.join(format!("{stem}.json")),
            &serde_json::to_string_pretty(&file)?,
        )?,
    ])
}

/// Bit-for-bit equality.
fn same(a: f64, b: f64) -> bool {
    a.to_bits() == b.to_bits()
}

/// The first index whose point fails `on_grid` (or has no point).
fn first_off<P>(
    indices: &[usize],
    points: &[P],
    on_grid: impl Fn(usize, &P) -> bool,
) -> Option<usize> {
    indices
        .iter()
        .enumerate()
        .find(|&(k, &i)| !points.get(k).is_some_and(|p| on_grid(i, p)))
        .map(|(_, &i)| i)
}

impl Sharded for PopovSweep {
    type Point = PopovPoint;
    const NAME: &'static str = "popov";

    fn total(&self) -> Result<usize, FigureError> {
        self.validate()
    }

    fn run_indices(
        &self,
        indices: &[usize],
        threads: usize,
        tick: &(dyn Fn() + Sync),
    ) -> Result<Vec<PopovPoint>, FigureError> {
        PopovSweep::run_indices(self, indices, threads, tick)
    }

    fn off_grid(&self, indices: &[usize], points: &[PopovPoint]) -> Option<usize> {
        let grid = self.points();
        first_off(indices, points, |i, p| {
            grid.get(i).is_some_and(|&(w, beta, alpha)| {
                w.name() == p.waveform && same(beta, p.beta) && same(alpha, p.alpha)
            })
        })
    }

    fn csv(points: &[PopovPoint]) -> String {
        popov_csv(points)
    }

    fn write(&self, dir: &Path, points: &[PopovPoint]) -> Result<Vec<PathBuf>, FigureError> {
        write_popov(dir, self, points)
    }
}

impl Sharded for FeederSweep {
    type Point = FeederPoint;
    const NAME: &'static str = "feeder";

    fn total(&self) -> Result<usize, FigureError> {
        self.validate()
    }

    fn run_indices(
        &self,
        indices: &[usize],
        threads: usize,
        tick: &(dyn Fn() + Sync),
    ) -> Result<Vec<FeederPoint>, FigureError> {
        FeederSweep::run_indices(self, indices, threads, tick)
    }

    fn off_grid(&self, indices: &[usize], points: &[FeederPoint]) -> Option<usize> {
        let grid = self.points();
        first_off(indices, points, |i, p| {
            grid.get(i).is_some_and(|&(a, f, g)| {
                same(a, p.amplitude_mm) && same(f, p.frequency) && same(g, p.angle_deg)
            })
        })
    }

    fn csv(points: &[FeederPoint]) -> String {
        feeder_csv(points)
    }

    fn write(&self, dir: &Path, points: &[FeederPoint]) -> Result<Vec<PathBuf>, FigureError> {
        write_feeder(dir, self, points)
    }
}
