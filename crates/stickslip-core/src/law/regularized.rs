//! "Regul": the sliding curve regularized around zero slip velocity (seed Fig. 1E).
//!
//! μ(ġ) = μ_ve(|ġ|)·r(ġ/ġ_t0) with r a smooth or linear ramp from −1 to 1. It has no sticking:
//! under any tangential load below break-away the contact creeps at a speed of order
//! ġ_t0·F_et/(μ F_n). Smaller ġ_t0 creeps less but makes the ODE stiffer.

use super::{FrictionLaw, FrictionState, Regime, StepInput, StepOutput, memoryless, unloaded};
use crate::error::{ParamError, at_most, positive};
use crate::sliding_curve::{Curve, SlidingCurve};
use crate::vec2::{normalize, scale};
use serde::{Deserialize, Serialize};

/// Shape of the regularizing ramp r(x), x = ġ/ġ_t0.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Regularization {
    /// r(x) = clamp(x, −1, 1): full friction from |ġ| = ġ_t0 on.
    #[default]
    Linear,
    /// r(x) = tanh(x): smooth, 76 % of full friction at |ġ| = ġ_t0.
    Tanh,
}

impl Regularization {
    /// r(x) for x ≥ 0.
    #[inline]
    pub fn ramp(self, x: f64) -> f64 {
        match self {
            Regularization::Linear => x.min(1.0),
            Regularization::Tanh => x.tanh(),
        }
    }

    /// The inverse r⁻¹(y) for y in [0, 1): the normalized creep speed under a load y·μ F_n
    /// (capped just below full sliding for the asymptotic tanh).
    #[inline]
    pub fn inverse(self, y: f64) -> f64 {
        let y = y.clamp(0.0, 1.0);
        match self {
            Regularization::Linear => y,
            Regularization::Tanh => y.min(1.0 - 1e-9).atanh(),
        }
    }
}

/// The regularized model.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "RegularizedParams", into = "RegularizedParams")]
pub struct Regularized {
    curve: Curve,
    v_reg: f64,
    shape: Regularization,
}

#[derive(Debug, Clone, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct RegularizedParams {
    curve: Curve,
    v_reg: f64,
    #[serde(default)]
    shape: Regularization,
}

impl TryFrom<RegularizedParams> for Regularized {
    type Error = ParamError;
    fn try_from(p: RegularizedParams) -> Result<Self, ParamError> {
        Regularized::new(p.curve, p.v_reg, p.shape)
    }
}

impl From<Regularized> for RegularizedParams {
    fn from(l: Regularized) -> Self {
        RegularizedParams {
            curve: l.curve,
            v_reg: l.v_reg,
            shape: l.shape,
        }
    }
}

/// The largest regularization velocity ġ_t0 (m/s) [`Regularized::new`] accepts.
pub const MAX_REGULARIZATION_SPEED: f64 = 1e3;

impl Regularized {
    /// Sliding curve, regularization velocity ġ_t0 = `v_reg` (m/s) > 0, ramp shape.
    pub fn new(curve: Curve, v_reg: f64, shape: Regularization) -> Result<Self, ParamError> {
        curve.validate()?;
        positive("v_reg", v_reg)?;
        // Beyond this no contact ever reaches full friction; the ramp's slopes stay finite.
        at_most("v_reg", v_reg, MAX_REGULARIZATION_SPEED)?;
        Ok(Regularized {
            curve,
            v_reg,
            shape,
        })
    }

    /// ġ_t0 (m/s).
    pub fn v_reg(&self) -> f64 {
        self.v_reg
    }

    /// The sliding curve.
    pub fn curve(&self) -> &Curve {
        &self.curve
    }

    /// The ramp shape.
    pub fn shape(&self) -> Regularization {
        self.shape
    }

    /// Steady creep speed under a tangential load of `ratio` = F_et/F_n at slip speed scale
    /// `speed` (for the sliding curve): ġ_t0 · r⁻¹(ratio/μ_ve).
    pub fn creep_speed(&self, ratio: f64, speed: f64) -> f64 {
        self.v_reg * self.shape.inverse(ratio.abs() / self.curve.mu(speed))
    }

    /// Signed coefficient μ(ġ) in 1D.
    #[inline]
    pub fn coefficient(&self, v: f64) -> f64 {
        let s = v.abs();
        self.curve.mu(s) * self.shape.ramp(s / self.v_reg) * v.signum()
    }
}

impl FrictionLaw for Regularized {
    fn step(&self, state: &mut FrictionState, input: &StepInput) -> StepOutput {
        if !(input.normal_force > 0.0 && input.normal_force.is_finite()) {
            return unloaded(state);
        }
        let speed = input.speed();
        match normalize(input.slip) {
            Some(e) if speed > 0.0 => {
                let mu = self.coefficient(speed);
                let regime = if speed < self.v_reg {
                    Regime::StickSlip
                } else {
                    Regime::Sliding
                };
                memoryless(state, input, scale(e, mu), regime, mu)
            }
            _ => memoryless(state, input, [0.0; 2], Regime::Sticking, 0.0),
        }
    }
    fn sliding_coefficient(&self, speed: f64) -> f64 {
        self.coefficient(speed.abs())
    }
    fn static_coefficient(&self) -> f64 {
        0.0
    }
    fn name(&self) -> &'static str {
        "regul"
    }
}
