//! "Phys": the exact switched friction model of the seed (Eq. 1–3).
//!
//! Sliding (ġ ≠ 0): F_f = −F_n μ_ve(|ġ|) sgn ġ. Sticking (ġ = 0, |F_et| < F_ba): F_f = −F_et,
//! a constraint force the law cannot compute on its own; a rigid solver realizes it within the
//! limit μ_ba. Stick-slip (ġ = 0, |F_et| ≥ F_ba): F_f = −F_n μ_ba sgn F_et.

use super::{FrictionLaw, FrictionState, Regime, StepInput, StepOutput, memoryless, unloaded};
use crate::error::{ParamError, coefficient, positive};
use crate::sliding_curve::{Curve, SlidingCurve};
use crate::vec2::{normalize, scale};
use serde::{Deserialize, Serialize};

/// The exact switched model.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "PhysicalParams", into = "PhysicalParams")]
pub struct Physical {
    mu_ba: f64,
    curve: Curve,
    stick_speed: f64,
}

#[derive(Debug, Clone, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct PhysicalParams {
    mu_ba: f64,
    curve: Curve,
    #[serde(default = "default_stick_speed")]
    stick_speed: f64,
}

fn default_stick_speed() -> f64 {
    1e-6
}

impl TryFrom<PhysicalParams> for Physical {
    type Error = ParamError;
    fn try_from(p: PhysicalParams) -> Result<Self, ParamError> {
        p.curve.validate()?;
        Physical::new(p.mu_ba, p.curve)?.with_stick_speed(p.stick_speed)
    }
}

impl From<Physical> for PhysicalParams {
    fn from(l: Physical) -> Self {
        PhysicalParams {
            mu_ba: l.mu_ba,
            curve: l.curve,
            stick_speed: l.stick_speed,
        }
    }
}

impl Physical {
    /// Break-away coefficient `mu_ba` > 0 and sliding curve.
    pub fn new(mu_ba: f64, curve: Curve) -> Result<Self, ParamError> {
        coefficient("mu_ba", mu_ba)?;
        curve.validate()?;
        Ok(Physical {
            mu_ba,
            curve,
            stick_speed: default_stick_speed(),
        })
    }

    /// Slip speeds at or below `speed` (m/s) count as ġ = 0 (default 1e-6 m/s).
    pub fn with_stick_speed(mut self, speed: f64) -> Result<Self, ParamError> {
        self.stick_speed = positive("stick_speed", speed)?;
        Ok(self)
    }

    /// Break-away coefficient.
    pub fn mu_ba(&self) -> f64 {
        self.mu_ba
    }

    /// Sliding curve.
    pub fn curve(&self) -> &Curve {
        &self.curve
    }

    /// Speed at or below which the contact counts as sticking (m/s).
    pub fn stick_speed(&self) -> f64 {
        self.stick_speed
    }
}

impl FrictionLaw for Physical {
    fn step(&self, state: &mut FrictionState, input: &StepInput) -> StepOutput {
        if !(input.normal_force > 0.0 && input.normal_force.is_finite()) {
            return unloaded(state);
        }
        let speed = input.speed();
        match normalize(input.slip) {
            Some(e) if speed > self.stick_speed => {
                let mu = self.curve.mu(speed);
                memoryless(state, input, scale(e, mu), Regime::Sliding, mu)
            }
            _ => memoryless(state, input, [0.0; 2], Regime::Sticking, self.mu_ba),
        }
    }
    fn sliding_coefficient(&self, speed: f64) -> f64 {
        self.curve.mu(speed)
    }
    fn static_coefficient(&self) -> f64 {
        self.mu_ba
    }
    fn name(&self) -> &'static str {
        "phys"
    }
}
