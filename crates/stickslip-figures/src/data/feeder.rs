//! The vibratory feeder (`crates/stickslip-fixtures/tests/rapier_feeder.rs`): transport speed against the trough
//! amplitude at f = 25 Hz, throw angle 25°, μ = 0.5, from the core's rigid-body reference
//! (`stickslip_theory::feeder::VibratoryFeeder`), plain rapier at a fine step (1/30 000 s) and
//! rapier with the EP contact (c = 1e5 1/m) at 1/3000 s, all over 20 periods after 20.

use crate::FigureError;
use crate::scenes::feeder_speed;
use serde::Serialize;
use stickslip_theory::feeder::VibratoryFeeder;

/// Friction coefficient.
pub const MU: f64 = 0.5;
/// Gravity (m/s²).
pub const G: f64 = 9.81;
/// Frequency (Hz).
pub const FREQUENCY: f64 = 25.0;
/// Throw angle (deg).
pub const ANGLE_DEG: f64 = 25.0;
/// Fine step (s).
pub const FINE_DT: f64 = 1.0 / 30000.0;
/// Coarse step (s).
pub const COARSE_DT: f64 = 1.0 / 3000.0;
/// EP stiffness at the coarse step (1/m).
pub const EP_C: f64 = 1e5;

/// One amplitude.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct FeederPoint {
    /// Amplitude (m).
    pub amplitude: f64,
    /// Throw number Γ.
    pub throw_number: f64,
    /// Reference transport speed (m/s).
    pub reference: f64,
    /// Plain rapier at [`FINE_DT`] (m/s), if measured at this amplitude.
    pub plain_fine: Option<f64>,
    /// rapier with EP at [`COARSE_DT`] (m/s), if measured.
    pub ep_coarse: Option<f64>,
    /// Plain rapier at [`COARSE_DT`] (m/s), if measured (EP's reference at that step).
    pub plain_coarse: Option<f64>,
}

/// The feeder at amplitude `a` (m).
pub fn feeder(a: f64) -> Result<VibratoryFeeder, FigureError> {
    Ok(VibratoryFeeder::new(
        a,
        FREQUENCY,
        ANGLE_DEG.to_radians(),
        MU,
        G,
    )?)
}

/// Reference on `n` amplitudes in [0.8, 2] mm, rapier at `measured` amplitudes (m).
pub fn compute(
    n: usize,
    measured: &[f64],
) -> Result<(Vec<FeederPoint>, Vec<FeederPoint>), FigureError> {
    let n = n.max(2);
    let line = (0..n)
        .map(|i| {
            let a = 0.8e-3 + 1.2e-3 * i as f64 / (n - 1) as f64;
            let f = feeder(a)?;
            Ok(FeederPoint {
                amplitude: a,
                throw_number: f.throw_number(),
                reference: f.transport_speed(20, 20),
                plain_fine: None,
                ep_coarse: None,
                plain_coarse: None,
            })
        })
        .collect::<Result<Vec<_>, FigureError>>()?;
    let points = measured
        .iter()
        .map(|&a| {
            let f = feeder(a)?;
            Ok(FeederPoint {
                amplitude: a,
                throw_number: f.throw_number(),
                reference: f.transport_speed(20, 20),
                plain_fine: Some(feeder_speed(&f, FREQUENCY, MU, FINE_DT, None, 20, 20)?),
                ep_coarse: Some(feeder_speed(
                    &f,
                    FREQUENCY,
                    MU,
                    COARSE_DT,
                    Some(EP_C),
                    20,
                    20,
                )?),
                plain_coarse: Some(feeder_speed(&f, FREQUENCY, MU, COARSE_DT, None, 20, 20)?),
            })
        })
        .collect::<Result<Vec<_>, FigureError>>()?;
    Ok((line, points))
}
