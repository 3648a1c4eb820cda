//! A piecewise-linear tangential force F(t).

use crate::error::{ParamError, finite};
use serde::{Deserialize, Serialize};

/// F(t) through `(time, force)` knots, linear in between, constant after the last knot.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "Knots", into = "Knots")]
pub struct ForceProfile {
    times: Vec<f64>,
    forces: Vec<f64>,
}

#[derive(Debug, Clone, Serialize, Deserialize)]
struct Knots {
    times: Vec<f64>,
    forces: Vec<f64>,
}

impl TryFrom<Knots> for ForceProfile {
    type Error = ParamError;
    fn try_from(k: Knots) -> Result<Self, ParamError> {
        ForceProfile::new(k.times, k.forces)
    }
}

impl From<ForceProfile> for Knots {
    fn from(p: ForceProfile) -> Self {
        Knots {
            times: p.times,
            forces: p.forces,
        }
    }
}

impl ForceProfile {
    /// Knots at strictly increasing `times` starting at 0, finite `forces` (N).
    pub fn new(times: Vec<f64>, forces: Vec<f64>) -> Result<Self, ParamError> {
        let bad = |reason: &str| ParamError::BadTable {
            name: "force profile",
            reason: reason.to_string(),
        };
        if times.len() != forces.len() || times.len() < 2 {
            return Err(bad("needs at least two (time, force) knots of equal count"));
        }
        for (&t, &f) in times.iter().zip(&forces) {
            finite("time", t)?;
            finite("force", f)?;
        }
        if times[0] != 0.0 {
            return Err(bad("the first knot must be at t = 0"));
        }
        if times.windows(2).any(|w| w[1] <= w[0]) {
            return Err(bad("times must be strictly increasing"));
        }
        Ok(ForceProfile { times, forces })
    }

    /// The seed's Example 1 over 3 s for break-away force `f_ba` (N): phase I (0–1 s) ramps
    /// to `hold`·F_ba (e.g. 0.95) and holds it; phase II (1–2 s) raises the force to
    /// `push`·F_ba (e.g. 1.5), so the block breaks away and slides; phase III (2–3 s) removes
    /// the force, so the block slides back to rest and sticks.
    pub fn example1(f_ba: f64, hold: f64, push: f64) -> Result<Self, ParamError> {
        let f_ba = crate::error::positive("f_ba", f_ba)?;
        ForceProfile::new(
            vec![0.0, 0.5, 1.0, 1.2, 2.0, 2.1, 3.0],
            vec![
                0.0,
                hold * f_ba,
                hold * f_ba,
                push * f_ba,
                push * f_ba,
                0.0,
                0.0,
            ],
        )
    }

    /// F(t).
    pub fn value(&self, t: f64) -> f64 {
        let n = self.times.len();
        if t <= self.times[0] {
            return self.forces[0];
        }
        if t >= self.times[n - 1] {
            return self.forces[n - 1];
        }
        let i = self.times.partition_point(|&k| k <= t);
        let (t0, t1) = (self.times[i - 1], self.times[i]);
        let (f0, f1) = (self.forces[i - 1], self.forces[i]);
        f0 + (f1 - f0) * (t - t0) / (t1 - t0)
    }

    /// Time of the last knot (s).
    pub fn end(&self) -> f64 {
        self.times[self.times.len() - 1]
    }

    /// The knots.
    pub fn knots(&self) -> impl Iterator<Item = (f64, f64)> + '_ {
        self.times.iter().copied().zip(self.forces.iter().copied())
    }

    /// First time in `[from, until]` at which |F(t)| ≥ `level`, exact for the linear pieces.
    pub fn first_reaching(&self, from: f64, until: f64, level: f64) -> Option<f64> {
        if self.value(from).abs() >= level {
            return Some(from);
        }
        // Walk the pieces that overlap [from, until].
        let mut a = from;
        let mut cuts: Vec<f64> = self
            .times
            .iter()
            .copied()
            .filter(|&k| k > from && k < until)
            .collect();
        cuts.push(until);
        for b in cuts {
            let (fa, fb) = (self.value(a), self.value(b));
            for target in [level, -level] {
                if (fa - target) * (fb - target) <= 0.0 && fa != fb {
                    let t = a + (target - fa) / (fb - fa) * (b - a);
                    if t >= a && t <= b {
                        return Some(t);
                    }
                }
            }
            a = b;
        }
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn interpolates_and_finds_levels() {
        let p = ForceProfile::new(vec![0.0, 1.0, 2.0], vec![0.0, 2.0, -2.0]).unwrap();
        assert_eq!(p.value(0.5), 1.0);
        assert_eq!(p.value(1.5), 0.0);
        assert_eq!(p.value(5.0), -2.0);
        assert!((p.first_reaching(0.0, 2.0, 1.0).unwrap() - 0.5).abs() < 1e-12);
        assert_eq!(p.first_reaching(1.0, 2.0, 1.0), Some(1.0));
        // From t = 1.3 (F = 0.8) the force falls through −1 at t = 1.75.
        assert!((p.first_reaching(1.3, 2.0, 1.0).unwrap() - 1.75).abs() < 1e-12);
        assert!(p.first_reaching(0.0, 0.4, 1.0).is_none());
    }

    #[test]
    fn rejects_malformed_knots() {
        assert!(ForceProfile::new(vec![0.0], vec![1.0]).is_err());
        assert!(ForceProfile::new(vec![0.1, 1.0], vec![1.0, 1.0]).is_err());
        assert!(ForceProfile::new(vec![0.0, 0.0], vec![1.0, 1.0]).is_err());
        assert!(ForceProfile::new(vec![0.0, 1.0], vec![1.0, f64::NAN]).is_err());
    }
}
