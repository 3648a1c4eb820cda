//! The sliding curve μ_ve(|ġ_t|) of the seed (Eq. 1, Fig. 1E): the friction coefficient during
//! sliding as a function of the slip speed.
//!
//! The curve is behind the [`SlidingCurve`] trait so users can bring their own; [`Curve`] is the
//! built-in, serializable set: constant, Stribeck with exponential or Gaussian decay plus an
//! optional viscous term, and a sampled table. All are validated at construction.

use crate::error::{
    MAX_COEFFICIENT, ParamError, at_most, coefficient, finite, non_negative, positive,
};
use serde::{Deserialize, Serialize};

/// A sliding curve μ_ve(v) for slip speeds v ≥ 0.
///
/// Implementations must return a finite, strictly positive coefficient for every finite
/// `speed >= 0` (the seed requires μ_ve > 0); `at_rest()` is the limit v ↓ 0.
pub trait SlidingCurve: Send + Sync + std::fmt::Debug {
    /// μ_ve at slip speed `speed` (m/s, ≥ 0).
    fn mu(&self, speed: f64) -> f64;
    /// μ_ve(0+), the value the seed sets equal to μ_max.
    fn at_rest(&self) -> f64 {
        self.mu(0.0)
    }
}

/// How a Stribeck curve decays from its rest value to the Coulomb level.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum StribeckDecay {
    /// `exp(-v / v_s)`.
    Exponential,
    /// `exp(-(v / v_s)^2)`.
    Gaussian,
}

/// The built-in sliding curves.
///
/// ```
/// use stickslip_core::sliding_curve::{Curve, SlidingCurve, StribeckDecay};
/// let c = Curve::stribeck(0.6, 0.4, 0.01, StribeckDecay::Gaussian, 0.0).unwrap();
/// assert!((c.at_rest() - 0.6).abs() < 1e-12);
/// assert!((c.mu(1.0) - 0.4).abs() < 1e-12);
/// assert!(Curve::constant(-0.1).is_err());
/// ```
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "kebab-case")]
pub enum Curve {
    /// μ_ve(v) = μ.
    Constant {
        /// The coefficient.
        mu: f64,
    },
    /// μ_ve(v) = μ_k + (μ_s − μ_k)·decay(v / v_s) + k_v·v.
    Stribeck {
        /// Value at rest, μ_ve(0+).
        mu_s: f64,
        /// Coulomb level reached at high speed (before the viscous term).
        mu_k: f64,
        /// Stribeck velocity v_s (m/s).
        v_s: f64,
        /// Decay shape.
        decay: StribeckDecay,
        /// Viscous slope k_v (s/m), ≥ 0.
        viscous: f64,
    },
    /// Piecewise-linear in speed through `(speed, mu)` samples, constant beyond the ends.
    Table {
        /// Strictly increasing speeds, the first one 0.
        speeds: Vec<f64>,
        /// Coefficients at those speeds, all > 0.
        mus: Vec<f64>,
    },
    /// Two curves combined point by point by a rule: the curve of a pair of surfaces (see
    /// [`Curve::combine`]).
    Combined {
        /// How the two values combine.
        rule: crate::combine_rule::CombineRule,
        /// The two surfaces' curves.
        curves: Box<[Curve; 2]>,
    },
}

impl Curve {
    /// A constant curve (plain Coulomb level).
    pub fn constant(mu: f64) -> Result<Self, ParamError> {
        coefficient("mu", mu)?;
        Ok(Curve::Constant { mu })
    }

    /// A Stribeck curve. `mu_k` may lie above or below `mu_s`.
    pub fn stribeck(
        mu_s: f64,
        mu_k: f64,
        v_s: f64,
        decay: StribeckDecay,
        viscous: f64,
    ) -> Result<Self, ParamError> {
        coefficient("mu_s", mu_s)?;
        coefficient("mu_k", mu_k)?;
        positive("v_s", v_s)?;
        non_negative("viscous", viscous)?;
        // k_v·v stays finite for any speed rapier can hold.
        at_most("viscous", viscous, MAX_COEFFICIENT)?;
        Ok(Curve::Stribeck {
            mu_s,
            mu_k,
            v_s,
            decay,
            viscous,
        })
    }

    /// A sampled curve.
    pub fn table(speeds: Vec<f64>, mus: Vec<f64>) -> Result<Self, ParamError> {
        let bad = |reason: &str| ParamError::BadTable {
            name: "sliding curve",
            reason: reason.to_string(),
        };
        if speeds.len() != mus.len() {
            return Err(bad("speeds and mus differ in length"));
        }
        if speeds.is_empty() {
            return Err(bad("needs at least one sample"));
        }
        if speeds[0] != 0.0 {
            return Err(bad("the first speed must be 0"));
        }
        for (&v, &m) in speeds.iter().zip(&mus) {
            finite("speed", v)?;
            coefficient("mu", m)?;
        }
        if speeds.windows(2).any(|w| w[1] <= w[0]) {
            return Err(bad("speeds must be strictly increasing"));
        }
        Ok(Curve::Table { speeds, mus })
    }

    /// Re-checks a curve that was built without the constructors (e.g. deserialized).
    pub fn validate(&self) -> Result<(), ParamError> {
        match self {
            Curve::Constant { mu } => Curve::constant(*mu).map(drop),
            Curve::Stribeck {
                mu_s,
                mu_k,
                v_s,
                decay,
                viscous,
            } => Curve::stribeck(*mu_s, *mu_k, *v_s, *decay, *viscous).map(drop),
            Curve::Table { speeds, mus } => Curve::table(speeds.clone(), mus.clone()).map(drop),
            Curve::Combined { curves, .. } => {
                curves[0].validate()?;
                curves[1].validate()?;
                coefficient("combined mu_ve(0+)", self.at_rest())?;
                Ok(())
            }
        }
    }
}

impl SlidingCurve for Curve {
    #[inline]
    fn mu(&self, speed: f64) -> f64 {
        let v = speed.abs();
        match self {
            Curve::Constant { mu } => *mu,
            Curve::Stribeck {
                mu_s,
                mu_k,
                v_s,
                decay,
                viscous,
            } => {
                let x = v / v_s;
                let d = match decay {
                    StribeckDecay::Exponential => (-x).exp(),
                    StribeckDecay::Gaussian => (-x * x).exp(),
                };
                mu_k + (mu_s - mu_k) * d + viscous * v
            }
            Curve::Table { speeds, mus } => {
                // Binary search keeps long tables cheap in the per-contact hot path.
                match speeds.binary_search_by(|s| s.total_cmp(&v)) {
                    Ok(i) => mus[i],
                    Err(0) => mus[0],
                    Err(i) if i >= speeds.len() => mus[speeds.len() - 1],
                    Err(i) => {
                        let t = (v - speeds[i - 1]) / (speeds[i] - speeds[i - 1]);
                        mus[i - 1] + t * (mus[i] - mus[i - 1])
                    }
                }
            }
            Curve::Combined { rule, curves } => rule.apply(curves[0].mu(v), curves[1].mu(v)),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stribeck_shapes() {
        let e = Curve::stribeck(0.5, 0.3, 0.1, StribeckDecay::Exponential, 0.0).unwrap();
        assert!((e.mu(0.1) - (0.3 + 0.2 * (-1.0f64).exp())).abs() < 1e-12);
        let g = Curve::stribeck(0.5, 0.3, 0.1, StribeckDecay::Gaussian, 0.2).unwrap();
        assert!((g.mu(0.2) - (0.3 + 0.2 * (-4.0f64).exp() + 0.04)).abs() < 1e-12);
        assert_eq!(g.at_rest(), 0.5);
    }

    #[test]
    fn table_interpolates_and_rejects_bad_input() {
        let t = Curve::table(vec![0.0, 1.0, 2.0], vec![0.5, 0.3, 0.4]).unwrap();
        assert!((t.mu(0.5) - 0.4).abs() < 1e-12);
        assert!((t.mu(1.5) - 0.35).abs() < 1e-12);
        assert_eq!(t.mu(10.0), 0.4);
        assert!(Curve::table(vec![0.0, 0.0], vec![0.5, 0.3]).is_err());
        assert!(Curve::table(vec![0.1], vec![0.5]).is_err());
        assert!(Curve::table(vec![0.0], vec![f64::NAN]).is_err());
        assert!(Curve::table(vec![0.0, 1.0], vec![0.5]).is_err());
    }

    #[test]
    fn rejects_non_finite_and_non_positive() {
        assert!(Curve::constant(f64::NAN).is_err());
        assert!(Curve::constant(0.0).is_err());
        assert!(Curve::stribeck(0.5, 0.3, 0.0, StribeckDecay::Gaussian, 0.0).is_err());
        assert!(Curve::stribeck(0.5, 0.3, 0.1, StribeckDecay::Gaussian, -1.0).is_err());
        assert!(Curve::stribeck(f64::INFINITY, 0.3, 0.1, StribeckDecay::Gaussian, 0.0).is_err());
    }
}
