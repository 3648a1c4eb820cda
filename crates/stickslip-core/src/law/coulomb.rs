//! Plain Coulomb friction: what rapier does without stickslip.

use super::{FrictionLaw, FrictionState, Regime, StepInput, StepOutput, memoryless, unloaded};
use crate::error::{ParamError, coefficient};
use crate::vec2::{normalize, scale};
use serde::{Deserialize, Serialize};

/// Coulomb friction with one coefficient for sticking and sliding.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "CoulombParams")]
pub struct Coulomb {
    mu: f64,
}

#[derive(Deserialize)]
struct CoulombParams {
    mu: f64,
}

impl TryFrom<CoulombParams> for Coulomb {
    type Error = ParamError;
    fn try_from(p: CoulombParams) -> Result<Self, ParamError> {
        Coulomb::new(p.mu)
    }
}

impl Coulomb {
    /// Coulomb friction with coefficient 0 < `mu` ≤ [`crate::error::MAX_COEFFICIENT`].
    pub fn new(mu: f64) -> Result<Self, ParamError> {
        Ok(Coulomb {
            mu: coefficient("mu", mu)?,
        })
    }

    /// Coulomb friction with the valid coefficient nearest to `mu` (clamped into
    /// [[`crate::error::MIN_COEFFICIENT`], [`crate::error::MAX_COEFFICIENT`]]; NaN gives the
    /// minimum): for coefficients from elsewhere, e.g. a rapier collider's `friction` of 0.
    pub fn clamped(mu: f64) -> Self {
        use crate::error::{MAX_COEFFICIENT, MIN_COEFFICIENT};
        Coulomb {
            mu: if mu.is_nan() {
                MIN_COEFFICIENT
            } else {
                mu.clamp(MIN_COEFFICIENT, MAX_COEFFICIENT)
            },
        }
    }

    /// The coefficient.
    pub fn mu(&self) -> f64 {
        self.mu
    }
}

impl FrictionLaw for Coulomb {
    fn step(&self, state: &mut FrictionState, input: &StepInput) -> StepOutput {
        if !(input.normal_force > 0.0) {
            return unloaded(state);
        }
        match normalize(input.slip) {
            Some(e) => memoryless(state, input, scale(e, self.mu), Regime::Sliding, self.mu),
            None => memoryless(state, input, [0.0; 2], Regime::Sticking, self.mu),
        }
    }
    fn sliding_coefficient(&self, _speed: f64) -> f64 {
        self.mu
    }
    fn static_coefficient(&self) -> f64 {
        self.mu
    }
    fn name(&self) -> &'static str {
        "coulomb"
    }
}
