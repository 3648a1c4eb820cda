//! Popov's Fig. 4: the effective coefficient μ̄(β) = μ0 (1 − α Ψ_w(β)) (Eq. 33) for the four
//! closed-form waveforms, with points measured in rapier worlds on top
//! (`crate::scenes::PopovDrag`, time-resolved normal vibration source, the setup of
//! `crates/stickslip-fixtures/tests/rapier_popov.rs`: μ0 = 0.5, α = 0.5, c = 1e4 1/m, f = 5 Hz); and the static
//! coefficient under normal, tangential and transverse oscillation (Eq. 4, 6, 8).

use crate::FigureError;
use crate::scenes::{PopovDrag, PopovDrive};
use serde::Serialize;
use stickslip_core::waveform::{Waveform, WaveformKind};
use stickslip_rapier::VibrationMode;
use stickslip_theory::popov;

/// The waveforms of Popov's Fig. 4.
pub const WAVEFORMS: [WaveformKind; 4] = [
    WaveformKind::Sine,
    WaveformKind::SawtoothRight,
    WaveformKind::SawtoothLeft,
    WaveformKind::Square,
];

/// One rapier measurement beside its theory.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Measured {
    /// β = c v0 / (μ0 α f).
    pub beta: f64,
    /// Theory μ̄.
    pub theory: f64,
    /// μ̄ = ⟨F_x⟩/⟨F_z⟩ measured in rapier.
    pub rapier: f64,
}

impl Measured {
    /// (rapier − theory) / theory.
    pub fn relative_error(&self) -> f64 {
        (self.rapier - self.theory) / self.theory
    }
}

/// μ̄(β) of one waveform.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PopovCurve {
    /// Waveform name.
    pub waveform: String,
    /// β_c (∞ for the left sawtooth and the square wave).
    pub beta_c: f64,
    /// μ0.
    pub mu0: f64,
    /// α.
    pub alpha: f64,
    /// β grid of the theory line.
    pub beta: Vec<f64>,
    /// μ̄ on that grid.
    pub theory: Vec<f64>,
    /// Points measured in rapier.
    pub measured: Vec<Measured>,
}

/// The β values measured for `w`: `crates/stickslip-fixtures/tests/rapier_popov.rs`'s grid, 0.25, 0.6, 0.9 and 1.5 β_c
/// (0.5, 2, 5 and 12 without a finite β_c), plus 0.4 and 1.2 β_c (1 and 8) in full size;
/// `quick` keeps two of them.
pub fn measured_betas(w: &Waveform, quick: bool) -> Vec<f64> {
    let bc = w.beta_c();
    let f: Vec<f64> = if quick {
        vec![0.6, 1.5]
    } else {
        vec![0.25, 0.4, 0.6, 0.9, 1.2, 1.5]
    };
    if bc.is_finite() {
        f.into_iter().map(|k| k * bc).collect()
    } else if quick {
        vec![2.0, 12.0]
    } else {
        vec![0.5, 1.0, 2.0, 5.0, 8.0, 12.0]
    }
}

/// The largest β of the figure.
pub const BETA_MAX: f64 = 14.0;

/// Theory on `n` points of β ∈ (0, BETA_MAX] and rapier at [`measured_betas`].
pub fn fig4(n: usize, quick: bool) -> Result<Vec<PopovCurve>, FigureError> {
    let n = n.max(2);
    let mut out = Vec::new();
    for kind in WAVEFORMS {
        let w = Waveform::from(kind);
        let setup = PopovDrag::new(w.clone(), PopovDrive::Source(VibrationMode::TimeResolved));
        let beta: Vec<f64> = (1..=n).map(|i| BETA_MAX * i as f64 / n as f64).collect();
        let theory = beta
            .iter()
            .map(|&b| Ok(setup.mu0 * (1.0 - setup.alpha * popov::psi(&w, b)?)))
            .collect::<Result<Vec<f64>, FigureError>>()?;
        let measured = measured_betas(&w, quick)
            .into_iter()
            .map(|b| {
                Ok(Measured {
                    beta: b,
                    theory: setup.theory(b),
                    rapier: setup.measure(b)?,
                })
            })
            .collect::<Result<Vec<_>, FigureError>>()?;
        out.push(PopovCurve {
            waveform: kind.name().into(),
            beta_c: w.beta_c(),
            mu0: setup.mu0,
            alpha: setup.alpha,
            beta,
            theory,
            measured,
        });
    }
    Ok(out)
}

/// μ_s(A/F_z) for the three directions (Eq. 4, 6, 8).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct StaticFriction {
    /// μ0.
    pub mu0: f64,
    /// Amplitude ratios A/F_z.
    pub ratio: Vec<f64>,
    /// Normal oscillation (Eq. 4).
    pub normal: Vec<f64>,
    /// Tangential oscillation along the pull (Eq. 6).
    pub tangential: Vec<f64>,
    /// Transverse oscillation (Eq. 8).
    pub transverse: Vec<f64>,
}

/// Eq. 4, 6 and 8 for μ0 = 0.5 over A/F_z ∈ [0, 1.1] with `n` points.
pub fn static_friction(n: usize) -> Result<StaticFriction, FigureError> {
    let n = n.max(2);
    let mu0 = 0.5;
    let ratio: Vec<f64> = (0..n).map(|i| 1.1 * i as f64 / (n - 1) as f64).collect();
    let eval = |f: fn(f64, f64) -> Result<f64, stickslip_core::ParamError>| {
        ratio
            .iter()
            .map(|&r| f(mu0, r))
            .collect::<Result<Vec<_>, _>>()
    };
    Ok(StaticFriction {
        mu0,
        normal: eval(popov::mu_s_normal)?,
        tangential: eval(popov::mu_s_tangential)?,
        transverse: eval(popov::mu_s_transverse)?,
        ratio,
    })
}
