//! Popov maps: μ̄ over β × α for each waveform, from theory (Eq. 33) and measured in rapier
//! worlds (`crate::scenes::PopovDrag`, the setup of `crates/stickslip-fixtures/tests/rapier_popov.rs` with
//! the swept α).

use super::{Range, check_total, run_parallel, select};
use crate::FigureError;
use crate::scenes::{PopovDrag, PopovDrive};
use serde::{Deserialize, Serialize};
use stickslip_core::popov;
use stickslip_core::waveform::{Waveform, WaveformKind};
use stickslip_rapier::VibrationMode;

/// Smallest and largest β a sweep accepts.
pub const BETA_LIMITS: (f64, f64) = (0.01, 100.0);
/// Smallest and largest α a sweep accepts (α ≤ 1: the load never lifts off).
pub const ALPHA_LIMITS: (f64, f64) = (0.01, 1.0);

/// How rapier modulates the normal force.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Drive {
    /// A time-resolved normal vibration source on the plate (400 steps per period).
    Resolved,
    /// An averaged vibration source (40 steps per period).
    Averaged,
    /// A real oscillating force on the sled.
    Load,
}

impl Drive {
    fn scene(self) -> PopovDrive {
        match self {
            Drive::Resolved => PopovDrive::Source(VibrationMode::TimeResolved),
            Drive::Averaged => PopovDrive::Source(VibrationMode::Averaged),
            Drive::Load => PopovDrive::RealLoad,
        }
    }
}

/// A Popov sweep.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PopovSweep {
    /// Waveforms (at least one, no repeats).
    pub waveforms: Vec<WaveformKind>,
    /// β grid.
    pub beta: Range,
    /// α grid.
    pub alpha: Range,
    /// Measure in rapier too (otherwise theory only).
    pub rapier: bool,
    /// rapier's drive.
    pub drive: Drive,
}

/// One point of the map.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PopovPoint {
    /// Waveform.
    pub waveform: String,
    /// β.
    pub beta: f64,
    /// α.
    pub alpha: f64,
    /// μ̄ from theory.
    pub theory: f64,
    /// μ̄ measured in rapier.
    pub rapier: Option<f64>,
}

impl PopovSweep {
    /// Checks the waveform list and the ranges' domains and the total count.
    pub fn validate(&self) -> Result<usize, FigureError> {
        if self.waveforms.is_empty() {
            return Err(FigureError::Option {
                name: "--waveforms".into(),
                reason: "give at least one waveform".into(),
            });
        }
        for (i, w) in self.waveforms.iter().enumerate() {
            if self.waveforms[..i].contains(w) {
                return Err(FigureError::Option {
                    name: "--waveforms".into(),
                    reason: format!("{w} is listed twice"),
                });
            }
        }
        for (name, r, (lo, hi)) in [
            ("--beta", self.beta, BETA_LIMITS),
            ("--alpha", self.alpha, ALPHA_LIMITS),
        ] {
            if r.lo < lo || r.hi > hi || r.n == 0 {
                return Err(FigureError::Range {
                    name: name.into(),
                    text: format!("{}:{}:{}", r.lo, r.hi, r.n),
                    reason: format!("values must lie in [{lo}, {hi}]"),
                });
            }
        }
        check_total(&[self.waveforms.len(), self.beta.n, self.alpha.n])
    }

    /// The points in order waveform, α, β (β fastest).
    pub fn points(&self) -> Vec<(WaveformKind, f64, f64)> {
        let mut out = Vec::new();
        for &w in &self.waveforms {
            for a in self.alpha.values() {
                for b in self.beta.values() {
                    out.push((w, b, a));
                }
            }
        }
        out
    }

    /// Runs the sweep on `threads` workers, calling `tick` after each point.
    pub fn run(
        &self,
        threads: usize,
        tick: &(dyn Fn() + Sync),
    ) -> Result<Vec<PopovPoint>, FigureError> {
        let total = self.validate()?;
        self.run_indices(&(0..total).collect::<Vec<_>>(), threads, tick)
    }

    /// Runs the points at `indices` of [`PopovSweep::points`] (e.g. one shard's) on `threads`
    /// workers, calling `tick` after each point; results come back in the order of `indices`.
    pub fn run_indices(
        &self,
        indices: &[usize],
        threads: usize,
        tick: &(dyn Fn() + Sync),
    ) -> Result<Vec<PopovPoint>, FigureError> {
        self.validate()?;
        let points = select(&self.points(), indices)?;
        run_parallel(&points, threads, tick, |&(kind, beta, alpha)| {
            let w = Waveform::from(kind);
            let setup = PopovDrag {
                alpha,
                ..PopovDrag::new(w.clone(), self.drive.scene())
            };
            let theory = setup.mu0 * (1.0 - alpha * popov::psi(&w, beta)?);
            let rapier = if self.rapier {
                Some(setup.measure(beta)?)
            } else {
                None
            };
            Ok(PopovPoint {
                waveform: kind.name().into(),
                beta,
                alpha,
                theory,
                rapier,
            })
        })
    }
}
