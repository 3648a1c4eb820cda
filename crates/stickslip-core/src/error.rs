//! Typed construction errors. Every parameterized type in the core validates its input once,
//! at construction, so nothing inside a step has to check (or can panic on) bad parameters.

use thiserror::Error;

/// Why a set of parameters was rejected (more reasons may come: match with a `_` arm).
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum ParamError {
    /// A parameter is NaN or infinite.
    #[error("parameter `{name}` must be finite, got {}", num(*value))]
    NotFinite {
        /// Parameter name.
        name: &'static str,
        /// Offending value.
        value: f64,
    },
    /// A parameter that must be strictly positive is not.
    #[error("parameter `{name}` must be > 0, got {}", num(*value))]
    NotPositive {
        /// Parameter name.
        name: &'static str,
        /// Offending value.
        value: f64,
    },
    /// A parameter that must be non-negative is negative.
    #[error("parameter `{name}` must be >= 0, got {}", num(*value))]
    Negative {
        /// Parameter name.
        name: &'static str,
        /// Offending value.
        value: f64,
    },
    /// A parameter lies outside its admissible range.
    #[error("parameter `{name}` = {} is outside [{}, {}]", num(*value), num(*min), num(*max))]
    OutOfRange {
        /// Parameter name.
        name: &'static str,
        /// Offending value.
        value: f64,
        /// Lower bound (inclusive).
        min: f64,
        /// Upper bound (inclusive).
        max: f64,
    },
    /// The break-away coefficient exceeds the switch's upper threshold.
    #[error("mu_ba = {mu_ba} must not exceed mu_max = {mu_max} (seed Eq. 5-7)")]
    BreakAwayAboveMax {
        /// μ_ba.
        mu_ba: f64,
        /// μ_max.
        mu_max: f64,
    },
    /// μ_max lies above the sliding curve at zero velocity, which leaves a step in the switch.
    #[error(
        "mu_max = {mu_max} exceeds the sliding curve at 0+ (mu_ve(0+) = {mu_ve0}); the seed requires mu_ba < mu_max = mu_ve(0+)"
    )]
    MaxAboveSlidingCurve {
        /// μ_max.
        mu_max: f64,
        /// μ_ve(0+).
        mu_ve0: f64,
    },
    /// A numerical solution did not settle within its bound (iterations, steps or events);
    /// the parameters lie in a regime the solver cannot resolve.
    #[error("`{name}` exceeded its limit of {limit} without converging")]
    NoConvergence {
        /// What was counted.
        name: &'static str,
        /// The bound that was reached.
        limit: usize,
    },
    /// A sampled table is malformed.
    #[error("table `{name}`: {reason}")]
    BadTable {
        /// Table name.
        name: &'static str,
        /// What is wrong.
        reason: String,
    },
}

/// A number as people write it: plain in [1e-4, 1e9), in scientific notation outside (so
/// that 1e300 is not printed with 300 digits).
pub(crate) fn num(x: f64) -> String {
    let a = x.abs();
    if x == 0.0 || !x.is_finite() || (1e-4..1e9).contains(&a) {
        format!("{x}")
    } else {
        format!("{x:e}")
    }
}

/// Checks that `value` is finite.
#[doc(hidden)]
pub fn finite(name: &'static str, value: f64) -> Result<f64, ParamError> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(ParamError::NotFinite { name, value })
    }
}

/// The range of friction coefficients (and sliding-curve values) the constructors accept.
/// Real materials lie between ~1e-3 (superlubric) and ~5; the bounds keep μ·F_n a normal
/// f32 (rapier's precision) for any normal force rapier can hold, so no accepted coefficient
/// can underflow to a zero limit or overflow in a step.
pub const MIN_COEFFICIENT: f64 = 1e-6;
/// See [`MIN_COEFFICIENT`].
pub const MAX_COEFFICIENT: f64 = 1e3;

/// The range of elasto-plastic stiffnesses c (1/m) the constructors accept: break-away slips
/// g_ba = μ_ba/c from 1e-12·μ_ba m (far below any contact's roughness) to 1e3·μ_ba m.
pub const MIN_STIFFNESS: f64 = 1e-3;
/// See [`MIN_STIFFNESS`].
pub const MAX_STIFFNESS: f64 = 1e12;

/// Checks that `value` is a friction coefficient: finite, in
/// [[`MIN_COEFFICIENT`], [`MAX_COEFFICIENT`]].
pub fn coefficient(name: &'static str, value: f64) -> Result<f64, ParamError> {
    positive(name, value)?;
    in_range(name, value, MIN_COEFFICIENT, MAX_COEFFICIENT)
}

/// Checks that a finite `value` is at most `max` (else [`ParamError::OutOfRange`] with the
/// lower bound 0).
pub fn at_most(name: &'static str, value: f64, max: f64) -> Result<f64, ParamError> {
    if value <= max {
        Ok(value)
    } else {
        Err(ParamError::OutOfRange {
            name,
            value,
            min: 0.0,
            max,
        })
    }
}

/// Checks that `value` is finite and strictly positive.
#[doc(hidden)]
pub fn positive(name: &'static str, value: f64) -> Result<f64, ParamError> {
    finite(name, value)?;
    if value > 0.0 {
        Ok(value)
    } else {
        Err(ParamError::NotPositive { name, value })
    }
}

/// Checks that `value` is finite and not negative.
pub fn non_negative(name: &'static str, value: f64) -> Result<f64, ParamError> {
    finite(name, value)?;
    if value >= 0.0 {
        Ok(value)
    } else {
        Err(ParamError::Negative { name, value })
    }
}

/// Checks that `value` is finite and inside `[min, max]`.
#[doc(hidden)]
pub fn in_range(name: &'static str, value: f64, min: f64, max: f64) -> Result<f64, ParamError> {
    finite(name, value)?;
    if (min..=max).contains(&value) {
        Ok(value)
    } else {
        Err(ParamError::OutOfRange {
            name,
            value,
            min,
            max,
        })
    }
}
