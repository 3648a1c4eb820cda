//! Friction of the seed's compliant spring contact (Section 3) under superimposed normal,
//! tangential and transverse oscillation, each with its own waveform, amplitude and phase:
//! the effective coefficient μ̄(v0) = ⟨F_x⟩/⟨F_z⟩ (Eq. 10) at any drag speed, in every sliding
//! mode (pure sliding, simple and multiple stick-slip, lost contact), and the static friction
//! of the compliant contact at zero drag speed.
//!
//! Conventions: the spring base (the slider) is dragged at the signed speed v0 along x over
//! the substrate; F_x is the spring force along x, positive when it resists a drag towards +x.
//! Oscillation amplitudes are displacements: u_z = ū_z + A_z g_z (normal, F_z = k_z (u_z)⁺), the
//! base moving by A_x g_x along x and A_y g_y along y; the in-plane spring is isotropic (k_x).
//!
//! The numbers come from the exact event-driven periodic orbit of the model (stick phases in
//! closed form, slip on the friction circle with an adaptive integrator for the in-plane
//! direction, transitions by root finding, iterated to the fixed point of the period map),
//! not from time stepping; the spring model of stickslip-theory (`SpringModel`) is the independent check.

use super::oscillation::Excitation;
use super::periodic_orbit::Orbit;
use crate::error::{ParamError, coefficient, finite, in_range, positive};

/// The largest scaled amplitude or drift (displacement over the elastic slip length
/// μ0 k_z ū_z / k_x, or A_z/ū_z) the theory accepts: far beyond any regime of interest, and
/// small enough that no product in the orbit overflows.
pub const MAX_SCALED: f64 = 1e9;

/// Mean force ratio below which [`CompliantStaticFriction::drive`] reports no drive.
pub const DRIVE_TOLERANCE: f64 = 1e-9;

/// The seed's contact spring: tangential stiffness k_x, normal stiffness k_z, Amontons μ0 at
/// the contact point, mean indentation ū_z.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CompliantContact {
    k_x: f64,
    k_z: f64,
    mu0: f64,
    mean_indentation: f64,
}

impl CompliantContact {
    /// Validates positive, finite stiffnesses and indentation and a friction coefficient μ0.
    pub fn new(k_x: f64, k_z: f64, mu0: f64, mean_indentation: f64) -> Result<Self, ParamError> {
        Ok(Self {
            k_x: positive("k_x", k_x)?,
            k_z: positive("k_z", k_z)?,
            mu0: coefficient("mu0", mu0)?,
            mean_indentation: positive("mean indentation", mean_indentation)?,
        })
    }

    /// Tangential stiffness k_x.
    pub fn k_x(&self) -> f64 {
        self.k_x
    }

    /// Normal stiffness k_z.
    pub fn k_z(&self) -> f64 {
        self.k_z
    }

    /// Friction coefficient μ0 at the contact point.
    pub fn mu0(&self) -> f64 {
        self.mu0
    }

    /// Mean indentation ū_z.
    pub fn mean_indentation(&self) -> f64 {
        self.mean_indentation
    }

    /// Mean normal force without oscillation, k_z ū_z.
    pub fn mean_normal_force(&self) -> f64 {
        self.k_z * self.mean_indentation
    }

    /// The tangential displacement that loads the spring to μ0 k_z ū_z (the elastic slip
    /// length): the unit of in-plane amplitudes in the theory.
    pub fn slip_length(&self) -> f64 {
        self.mu0 * self.k_z * self.mean_indentation / self.k_x
    }

    /// The drag speed at which the base travels one slip length per period at `frequency`.
    pub fn speed_scale(&self, frequency: f64) -> f64 {
        self.slip_length() * frequency
    }
}

/// Period averages of the steady state.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SteadySliding {
    /// μ̄ = ⟨F_x⟩/⟨F_z⟩ (Eq. 10), signed.
    pub mu_eff: f64,
    /// ⟨F_x⟩, along the drag axis.
    pub mean_fx: f64,
    /// ⟨F_y⟩, across it.
    pub mean_fy: f64,
    /// ⟨F_z⟩.
    pub mean_fz: f64,
    /// Fraction of the period in stick.
    pub stick_fraction: f64,
    /// Periods the fixed-point iteration ran.
    pub periods: usize,
}

/// The scaled parameters of the orbit, validated against [`MAX_SCALED`].
pub(crate) struct Scaled {
    pub alpha: f64,
    pub a_x: f64,
    pub a_y: f64,
    pub drift: f64,
}

pub(crate) fn scaled(
    contact: &CompliantContact,
    excitation: &Excitation,
    frequency: f64,
    v0: f64,
) -> Result<Scaled, ParamError> {
    positive("frequency", frequency)?;
    finite("v0", v0)?;
    let len = contact.slip_length();
    let amp = |o: &Option<super::Oscillation>| o.as_ref().map_or(0.0, |o| o.amplitude());
    let bounded = |name, x| in_range(name, x, -MAX_SCALED, MAX_SCALED);
    Ok(Scaled {
        alpha: bounded(
            "normal amplitude / mean indentation",
            amp(&excitation.normal) / contact.mean_indentation,
        )?,
        a_x: bounded(
            "tangential amplitude / slip length",
            amp(&excitation.tangential) / len,
        )?,
        a_y: bounded(
            "transverse amplitude / slip length",
            amp(&excitation.transverse) / len,
        )?,
        drift: bounded("v0 / (slip length · frequency)", v0 / (len * frequency))?,
    })
}

fn steady(
    contact: &CompliantContact,
    excitation: &Excitation,
    s: &Scaled,
    rest_side: f64,
) -> Result<SteadySliding, ParamError> {
    let orbit = Orbit::new(excitation, s.alpha, s.a_x, s.a_y, s.drift, rest_side);
    let avg = orbit.solve()?;
    let force = contact.mu0 * contact.mean_normal_force();
    Ok(SteadySliding {
        mu_eff: contact.mu0 * avg.fx / avg.radius,
        mean_fx: force * avg.fx,
        mean_fy: force * avg.fy,
        mean_fz: contact.mean_normal_force() * avg.radius,
        stick_fraction: avg.stick,
        periods: avg.periods,
    })
}

/// The steady state at drag speed `v0` (signed, along x) and oscillation `frequency`.
///
/// At v0 = 0 a contact that can stick throughout has a whole band of steady states; the one
/// returned is the limit v0 → 0+ (the upper end of [`static_friction_compliant`]).
pub fn steady_sliding(
    contact: &CompliantContact,
    excitation: &Excitation,
    frequency: f64,
    v0: f64,
) -> Result<SteadySliding, ParamError> {
    let s = scaled(contact, excitation, frequency, v0)?;
    steady(contact, excitation, &s, 1.0)
}

/// μ̄(v0) = ⟨F_x⟩/⟨F_z⟩: the mean tangential force along the drag axis over the mean normal
/// force, signed (v0 → 0+ at v0 = 0, see [`steady_sliding`]).
///
/// Reduces to μ0 (1 − α Ψ_w(β)) (Eq. 33) under normal oscillation alone, to μ0 in pure
/// sliding (Eq. 12), and to Eq. 4, 6, 8 as v0 → 0 for a single direction.
pub fn mean_friction(
    contact: &CompliantContact,
    excitation: &Excitation,
    frequency: f64,
    v0: f64,
) -> Result<f64, ParamError> {
    Ok(steady_sliding(contact, excitation, frequency, v0)?.mu_eff)
}

/// The mean tangential forces (over the mean normal force) at which the compliant contact
/// rests on average: every μ in [`lower`](Self::lower), [`upper`](Self::upper) holds it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CompliantStaticFriction {
    /// μ̄(0−): the most negative holding force ratio.
    pub lower: f64,
    /// μ̄(0+): the static coefficient μ_s. It is negative when the oscillation drives the
    /// contact forwards by itself (seed Section 2.1).
    pub upper: f64,
}

impl CompliantStaticFriction {
    /// The holding force ratio of least magnitude: 0 if the contact can rest without one
    /// (within [`DRIVE_TOLERANCE`], so round-off in a symmetric band is no drive), else the
    /// end of the band nearest zero (the sign says which way it is driven).
    pub fn drive(&self) -> f64 {
        if self.upper < -DRIVE_TOLERANCE {
            self.upper
        } else if self.lower > DRIVE_TOLERANCE {
            self.lower
        } else {
            0.0
        }
    }
}

/// Static friction of the compliant contact under superimposed oscillation: the band of mean
/// tangential force ratios that hold it at zero mean drag speed (μ̄ as v0 → 0∓).
///
/// Where the contact can stick throughout, its in-plane force is k_x times the base motion
/// and the band is exactly the rigid Eq. 9 interval with force amplitudes k_z A_z, k_x A_x,
/// k_x A_y (stickslip-theory's `static_friction_superimposed`), for any
/// stiffness. Where Eq. 9 has no solution the compliant contact still has a steady state: it
/// slides in place, and along one axis the band shrinks to the single mean force of that
/// motion (zero for a symmetric oscillation, nonzero for a drive). Independent of frequency.
pub fn static_friction_compliant(
    contact: &CompliantContact,
    excitation: &Excitation,
) -> Result<CompliantStaticFriction, ParamError> {
    let s = scaled(contact, excitation, 1.0, 0.0)?;
    Ok(CompliantStaticFriction {
        lower: steady(contact, excitation, &s, -1.0)?.mu_eff,
        upper: steady(contact, excitation, &s, 1.0)?.mu_eff,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::popov::{Oscillation, psi};
    use crate::waveform::Waveform;

    fn contact() -> CompliantContact {
        CompliantContact::new(2.0, 1.0, 0.5, 1.0).unwrap()
    }

    #[test]
    fn rejects_bad_parameters() {
        assert!(CompliantContact::new(0.0, 1.0, 0.5, 1.0).is_err());
        assert!(CompliantContact::new(1.0, 1.0, f64::NAN, 1.0).is_err());
        let ex = Excitation::default();
        assert!(mean_friction(&contact(), &ex, 0.0, 1.0).is_err());
        assert!(mean_friction(&contact(), &ex, 1.0, f64::INFINITY).is_err());
        assert!(mean_friction(&contact(), &ex, 1e-300, 1.0).is_err());
    }

    #[test]
    fn without_oscillation_it_slides_at_plus_or_minus_mu0() {
        let ex = Excitation::default();
        assert!((mean_friction(&contact(), &ex, 1.0, 0.3).unwrap() - 0.5).abs() < 1e-12);
        assert!((mean_friction(&contact(), &ex, 1.0, -0.3).unwrap() + 0.5).abs() < 1e-12);
        let s = static_friction_compliant(&contact(), &ex).unwrap();
        assert!(
            (s.upper - 0.5).abs() < 1e-12 && (s.lower + 0.5).abs() < 1e-12,
            "{s:?}"
        );
        assert_eq!(s.drive(), 0.0);
    }

    #[test]
    fn normal_oscillation_gives_eq_33() {
        let c = contact();
        let alpha = 0.7;
        let ex = Excitation::normal(Oscillation::new(alpha, Waveform::Sine, 0.0).unwrap());
        for beta in [0.2, 1.0, 3.0, 5.5] {
            // β = k_x v0 / (μ0 k_z A_z f) (Eq. 17).
            let v0 = beta * c.mu0() * c.k_z() * alpha / c.k_x();
            let mu = mean_friction(&c, &ex, 1.0, v0).unwrap();
            let eq33 = 0.5 * (1.0 - alpha * psi(&Waveform::Sine, beta).unwrap());
            assert!((mu - eq33).abs() < 1e-7, "β={beta}: {mu} vs {eq33}");
        }
    }
}
