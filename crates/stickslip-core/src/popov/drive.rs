//! Self-transport of a compliant contact under superimposed oscillation (seed Section 2.1,
//! Popov & Li 2018): the blocking force (the mean force at zero drag speed) and the free drive
//! velocity (the drag speed at which the mean force vanishes), e.g. for elliptical vibration,
//! normal and tangential 90° apart.
//!
//! Sign convention as in [`compliant`](super::compliant): a negative blocking force pushes the
//! slider towards +x, and it then runs freely at a positive drive velocity.

use std::cell::RefCell;

use roots::{SimpleConvergency, find_root_brent};
use serde::Serialize;

use super::compliant::{
    CompliantContact, mean_friction, scaled, static_friction_compliant, steady_sliding,
};
use super::oscillation::Excitation;
use crate::error::ParamError;

/// Doublings of the drag speed tried while bracketing the drive velocity, from 1e-3 of the
/// speed scale (slip length × frequency) up to ~1e15 of it.
const MAX_DOUBLINGS: usize = 60;
/// Brent's tolerance on the drive velocity, in units of the speed scale, and on μ̄.
const ROOT_EPS: f64 = 1e-11;
/// Brent's iteration cap.
const ROOT_ITERATIONS: usize = 200;

/// The mean tangential force ⟨F_x⟩ that holds the contact at zero mean drag speed with the
/// least effort: 0 if it can rest without one, negative if the oscillation drives it towards
/// +x, positive if towards −x ([`CompliantStaticFriction::drive`](super::CompliantStaticFriction::drive)
/// times the mean normal force).
pub fn blocking_force(
    contact: &CompliantContact,
    excitation: &Excitation,
) -> Result<f64, ParamError> {
    let band = static_friction_compliant(contact, excitation)?;
    let mean_fz = steady_sliding(contact, excitation, 1.0, 0.0)?.mean_fz;
    Ok(band.drive() * mean_fz)
}

/// The drag speed v0 at which the mean tangential force vanishes: the speed a free slider
/// reaches by the oscillation alone (positive: towards +x). `None` if the contact rests (the
/// blocking force is zero).
pub fn free_drive_velocity(
    contact: &CompliantContact,
    excitation: &Excitation,
    frequency: f64,
) -> Result<Option<f64>, ParamError> {
    scaled(contact, excitation, frequency, 0.0)?;
    let band = static_friction_compliant(contact, excitation)?;
    let side = match band.drive() {
        d if d < 0.0 => 1.0,
        d if d > 0.0 => -1.0,
        _ => return Ok(None),
    };
    let unit = contact.speed_scale(frequency);
    let mu = |u: f64| mean_friction(contact, excitation, frequency, u * unit);
    let at_rest = band.drive();
    // Bracket: from rest (μ̄ = the drive, nonzero) double the speed until μ̄ changes sign.
    let (mut lo, mut hi) = (0.0, side * 1e-3);
    let mut found = false;
    for _ in 0..MAX_DOUBLINGS {
        if mu(hi)? * at_rest <= 0.0 {
            found = true;
            break;
        }
        lo = hi;
        hi *= 2.0;
    }
    if !found {
        return Err(ParamError::NoConvergence {
            name: "doublings of the drag speed bracketing the drive velocity",
            limit: MAX_DOUBLINGS,
        });
    }
    // Brent needs a plain function: the first error is kept and returned after it.
    let failure = RefCell::new(None);
    let plain = |u: f64| {
        mu(u).unwrap_or_else(|e| {
            failure.borrow_mut().get_or_insert(e);
            0.0
        })
    };
    let mut conv = SimpleConvergency {
        eps: ROOT_EPS,
        max_iter: ROOT_ITERATIONS,
    };
    let root = find_root_brent(lo, hi, plain, &mut conv);
    if let Some(e) = failure.into_inner() {
        return Err(e);
    }
    let u = root.map_err(|_| ParamError::NoConvergence {
        name: "Brent iterations for the drive velocity",
        limit: ROOT_ITERATIONS,
    })?;
    Ok(Some(u.clamp(lo.min(hi), lo.max(hi)) * unit))
}

/// One phase shift of a [`drive_curve`], in the theory's units: forces over the mean normal
/// force, speeds over the speed scale (slip length × frequency).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct DrivePoint {
    /// Phase of the tangential oscillation after the normal one (periods).
    pub phase_shift: f64,
    /// μ̄(0−): the lower end of the static band.
    pub lower: f64,
    /// μ̄(0+): the upper end of the static band (the static coefficient, negative for a drive
    /// towards +x).
    pub upper: f64,
    /// Blocking force over the mean normal force (0 if the contact rests; negative: driven
    /// towards +x).
    pub blocking: f64,
    /// μ̄ at the requested drag speed.
    pub mu_eff: f64,
    /// Free drive velocity over the speed scale (0 if the contact rests).
    pub drive_velocity: f64,
}

/// Drive under elliptical-type vibration over the phase shift: a normal oscillation of
/// amplitude `alpha` (A_z/ū_z) and a tangential one of `tangential` slip lengths, both with
/// `waveform`, the tangential one `phase_shift` periods later, on a contact with coefficient
/// `mu0`; μ̄ at the drag speed `speed` (in speed scales). The data of the figure "μ̄ and drive
/// speed over phase shift" and of `stickslip theory drive`.
pub fn drive_curve(
    mu0: f64,
    alpha: f64,
    tangential: f64,
    waveform: &crate::waveform::Waveform,
    speed: f64,
    phase_shifts: &[f64],
) -> Result<Vec<DrivePoint>, ParamError> {
    use super::oscillation::Oscillation;
    // Slip length 1, frequency 1: speeds are in speed scales.
    let contact = CompliantContact::new(mu0, 1.0, mu0, 1.0)?;
    phase_shifts
        .iter()
        .map(|&shift| {
            let ex = Excitation {
                normal: Some(Oscillation::new(alpha, waveform.clone(), 0.0)?),
                tangential: Some(Oscillation::new(tangential, waveform.clone(), shift)?),
                transverse: None,
            };
            let band = static_friction_compliant(&contact, &ex)?;
            let mean_fz = steady_sliding(&contact, &ex, 1.0, 0.0)?.mean_fz;
            Ok(DrivePoint {
                phase_shift: shift,
                lower: band.lower,
                upper: band.upper,
                blocking: band.drive() * mean_fz / contact.mean_normal_force(),
                mu_eff: mean_friction(&contact, &ex, 1.0, speed)?,
                drive_velocity: free_drive_velocity(&contact, &ex, 1.0)?.unwrap_or(0.0),
            })
        })
        .collect()
}
