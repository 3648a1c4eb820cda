//! Feeder maps: the transport speed of a part on a vibrating trough over amplitude ×
//! frequency × throw angle, each point a rapier world
//! (`crate::scenes::feeder_speed`), beside the rigid-body reference
//! (`stickslip_theory::feeder::VibratoryFeeder`).

use super::{Range, check_total, run_parallel, select};
use crate::FigureError;
use crate::scenes::feeder_speed;
use serde::Serialize;
use stickslip_theory::feeder::VibratoryFeeder;

/// Amplitude limits (mm).
pub const AMPLITUDE_LIMITS: (f64, f64) = (0.01, 20.0);
/// Frequency limits (Hz).
pub const FREQUENCY_LIMITS: (f64, f64) = (1.0, 500.0);
/// Throw-angle limits (deg).
pub const ANGLE_LIMITS: (f64, f64) = (0.0, 90.0);
/// The most rapier steps one point may take.
pub const MAX_STEPS_PER_POINT: f64 = 5e6;
/// The fewest steps per vibration period.
pub const MIN_STEPS_PER_PERIOD: f64 = 20.0;

/// A feeder sweep.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FeederSweep {
    /// Amplitudes (mm).
    pub amplitude: Range,
    /// Frequencies (Hz).
    pub frequency: Range,
    /// Throw angles (deg).
    pub angle: Range,
    /// Friction coefficient.
    pub mu: f64,
    /// rapier's step (s).
    pub dt: f64,
    /// EP stiffness c (1/m), or plain rapier friction when `None`.
    pub ep: Option<f64>,
    /// Periods before measuring.
    pub settle: usize,
    /// Periods measured.
    pub measure: usize,
}

/// One point of the map.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FeederPoint {
    /// Amplitude (mm).
    pub amplitude_mm: f64,
    /// Frequency (Hz).
    pub frequency: f64,
    /// Throw angle (deg).
    pub angle_deg: f64,
    /// Throw number Γ.
    pub throw_number: f64,
    /// Transport speed in rapier (m/s).
    pub rapier: f64,
    /// Reference transport speed (m/s).
    pub reference: f64,
}

fn option(name: &str, reason: String) -> FigureError {
    FigureError::Option {
        name: name.into(),
        reason,
    }
}

impl FeederSweep {
    /// Checks the ranges' domains, the step, the periods and the total count.
    pub fn validate(&self) -> Result<usize, FigureError> {
        for (name, r, (lo, hi)) in [
            ("--amplitude", self.amplitude, AMPLITUDE_LIMITS),
            ("--frequency", self.frequency, FREQUENCY_LIMITS),
            ("--angle", self.angle, ANGLE_LIMITS),
        ] {
            if r.lo < lo || r.hi > hi || r.n == 0 {
                return Err(FigureError::Range {
                    name: name.into(),
                    text: format!("{}:{}:{}", r.lo, r.hi, r.n),
                    reason: format!("values must lie in [{lo}, {hi}]"),
                });
            }
        }
        if !(self.mu > 0.0 && self.mu <= 10.0) {
            return Err(option("--mu", format!("{} is not in (0, 10]", self.mu)));
        }
        if let Some(c) = self.ep
            && !(1e2..=1e8).contains(&c)
        {
            return Err(option("--c", format!("{c} is not in [1e2, 1e8] 1/m")));
        }
        if !(self.dt > 0.0 && self.dt <= 0.01) {
            return Err(option("--dt", format!("{} is not in (0, 0.01] s", self.dt)));
        }
        if self.dt * self.frequency.hi * MIN_STEPS_PER_PERIOD > 1.0 {
            return Err(option(
                "--dt",
                format!(
                    "{} s resolves {} Hz with fewer than {MIN_STEPS_PER_PERIOD} steps per period",
                    self.dt, self.frequency.hi
                ),
            ));
        }
        if !(1..=1000).contains(&self.settle) || !(1..=1000).contains(&self.measure) {
            return Err(option(
                "--periods",
                "settle and measure periods must each be in 1..=1000".into(),
            ));
        }
        let steps = (self.settle + self.measure) as f64 / (self.frequency.lo * self.dt);
        if steps > MAX_STEPS_PER_POINT {
            return Err(option(
                "--dt",
                format!(
                    "a point at {} Hz would take {steps:.0} steps, more than {MAX_STEPS_PER_POINT:.0}",
                    self.frequency.lo
                ),
            ));
        }
        check_total(&[self.amplitude.n, self.frequency.n, self.angle.n])
    }

    /// The points in order angle, frequency, amplitude (amplitude fastest).
    pub fn points(&self) -> Vec<(f64, f64, f64)> {
        let mut out = Vec::new();
        for g in self.angle.values() {
            for f in self.frequency.values() {
                for a in self.amplitude.values() {
                    out.push((a, f, g));
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
    ) -> Result<Vec<FeederPoint>, FigureError> {
        let total = self.validate()?;
        self.run_indices(&(0..total).collect::<Vec<_>>(), threads, tick)
    }

    /// Runs the points at `indices` of [`FeederSweep::points`] (e.g. one shard's) on
    /// `threads` workers, calling `tick` after each point; results come back in the order of
    /// `indices`.
    pub fn run_indices(
        &self,
        indices: &[usize],
        threads: usize,
        tick: &(dyn Fn() + Sync),
    ) -> Result<Vec<FeederPoint>, FigureError> {
        self.validate()?;
        let points = select(&self.points(), indices)?;
        run_parallel(&points, threads, tick, |&(a, f, g)| {
            let feeder = VibratoryFeeder::new(a * 1e-3, f, g.to_radians(), self.mu, 9.81)?;
            Ok(FeederPoint {
                amplitude_mm: a,
                frequency: f,
                angle_deg: g,
                throw_number: feeder.throw_number(),
                rapier: feeder_speed(
                    &feeder,
                    f,
                    self.mu,
                    self.dt,
                    self.ep,
                    self.settle,
                    self.measure,
                )?,
                reference: feeder.transport_speed(self.settle, self.measure),
            })
        })
    }
}
