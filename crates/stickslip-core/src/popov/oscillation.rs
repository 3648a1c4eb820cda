//! A periodic excitation A·w(f t + phase) and the set of them acting on one contact.

use crate::error::{ParamError, finite, non_negative};
use crate::waveform::Waveform;

/// One oscillation component A·w(φ + phase), φ = f t.
///
/// The unit of `amplitude` is set by the consumer: a force ratio A/F_z in
/// stickslip-theory's `static_friction_superimposed`, a displacement in
/// `SpringModel`.
#[derive(Clone, Debug)]
pub struct Oscillation {
    amplitude: f64,
    waveform: Waveform,
    phase: f64,
}

impl Oscillation {
    /// Validates `amplitude ≥ 0` and a finite `phase` (taken modulo 1).
    pub fn new(amplitude: f64, waveform: Waveform, phase: f64) -> Result<Self, ParamError> {
        non_negative("oscillation amplitude", amplitude)?;
        finite("oscillation phase", phase)?;
        Ok(Self {
            amplitude,
            waveform,
            phase: phase.rem_euclid(1.0),
        })
    }

    /// Amplitude A.
    pub fn amplitude(&self) -> f64 {
        self.amplitude
    }

    /// Waveform w.
    pub fn waveform(&self) -> &Waveform {
        &self.waveform
    }

    /// Phase offset in [0, 1).
    pub fn phase(&self) -> f64 {
        self.phase
    }

    /// The normalized waveform g(φ) = w(φ + phase).
    pub fn shape(&self, phase: f64) -> f64 {
        self.waveform.value(phase + self.phase)
    }

    /// The excitation A·w(φ + phase).
    pub fn at(&self, phase: f64) -> f64 {
        self.amplitude * self.shape(phase)
    }
}

/// Oscillations in the three directions of the seed: normal (z), tangential (x, along the
/// sliding direction) and transverse (y, in-plane, across it). `None` means no oscillation.
#[derive(Clone, Debug, Default)]
pub struct Excitation {
    /// Normal oscillation (g_z of Eq. 9, u_z of Eq. 11).
    pub normal: Option<Oscillation>,
    /// Tangential oscillation (g_x of Eq. 9).
    pub tangential: Option<Oscillation>,
    /// Transverse oscillation (g_y of Eq. 9).
    pub transverse: Option<Oscillation>,
}

impl Excitation {
    /// Only a normal oscillation.
    pub fn normal(osc: Oscillation) -> Self {
        Self {
            normal: Some(osc),
            ..Self::default()
        }
    }

    /// Only a tangential oscillation.
    pub fn tangential(osc: Oscillation) -> Self {
        Self {
            tangential: Some(osc),
            ..Self::default()
        }
    }

    /// Only a transverse oscillation.
    pub fn transverse(osc: Oscillation) -> Self {
        Self {
            transverse: Some(osc),
            ..Self::default()
        }
    }

    /// The present components, as (normal, tangential, transverse) with absent ones as `None`.
    pub fn components(&self) -> [Option<&Oscillation>; 3] {
        [
            self.normal.as_ref(),
            self.tangential.as_ref(),
            self.transverse.as_ref(),
        ]
    }
}
