//! Popov curve sweep in rapier: the effective friction coefficient μ̄ of a sled dragged over a
//! plate whose normal force vibrates as F̄ (1 + α w(f t)), against β for four waveforms.
//! Prints theory (numeric Ψ, Eq. 25/31, and the closed forms Eq. 34–36 where they exist)
//! beside rapier with a time-resolved and an averaged vibration source.
//!
//! Run: `cargo run --release --example popov_sweep`

use stickslip_core::popov;
use stickslip_core::waveform::Waveform;
use stickslip_fixtures::{PopovDrag, PopovDrive};
use stickslip_rapier::VibrationMode;

fn main() -> Result<(), stickslip_core::ParamError> {
    for w in [
        Waveform::Sine,
        Waveform::SawtoothRight,
        Waveform::SawtoothLeft,
        Waveform::Square,
    ] {
        let resolved = PopovDrag::new(w.clone(), PopovDrive::Source(VibrationMode::TimeResolved));
        let averaged = PopovDrag::new(w.clone(), PopovDrive::Source(VibrationMode::Averaged));
        let bc = w.beta_c();
        println!(
            "\n{w:?} (beta_c = {bc:.3}), mu0 = {}, alpha = {}",
            resolved.mu0, resolved.alpha
        );
        println!(
            "{:>8} {:>9} {:>9} {:>10} {:>12} {:>12}",
            "beta", "psi", "closed", "mu theory", "time-resolv", "averaged"
        );
        let top = if bc.is_finite() { 1.5 * bc } else { 20.0 };
        for i in 1..=8 {
            let beta = top * i as f64 / 8.0;
            let psi = popov::psi(&w, beta)?;
            let closed =
                popov::psi_closed_form(&w, beta).map_or("-".to_string(), |c| format!("{c:.5}"));
            println!(
                "{beta:>8.3} {psi:>9.5} {closed:>9} {:>10.5} {:>12.5} {:>12.5}",
                resolved.theory(beta),
                resolved.measure(beta)?,
                averaged.measure(beta)?
            );
        }
    }
    Ok(())
}
