//! Popov (2020), "The Influence of Vibration on Friction: A Contact-Mechanical Perspective":
//! a quasi-static contact with normal and tangential stiffness and constant Amontons μ0.
//!
//! - [`static_friction`]: μ_s under normal, tangential and transverse oscillation (Eq. 4, 6,
//!   8) and a numeric solver for superimposed oscillations (Eq. 9).
//! - [`psi`](mod@psi): the friction-reduction function Ψ_w(β) (Eq. 31) for any
//!   [`Waveform`](crate::waveform::Waveform), numerically, plus the closed forms Eq. 34–38.
//! - [`dimensionless`]: α (Eq. 16), β (Eq. 17) and μ̄ = μ0 (1 − α Ψ_w(β)) (Eq. 33).
//! - [`spring_model`]: a time-stepped simulator of the spring contact that yields μ̄ directly,
//!   also for tangential and transverse oscillation where the seed has no closed form.
//! - [`oscillation`]: the excitation A·w(ft + phase) in each direction.
//! - [`compliant`]: the compliant contact under superimposed oscillation (normal, tangential
//!   and transverse at once, any waveforms and phases): μ̄(v0) in every sliding mode and the
//!   static friction band at rest, from the exact event-driven periodic orbit of the model
//!   (stick in closed form, slip on the friction circle, event roots, period-map fixed point),
//!   checked against [`spring_model`].
//! - [`drive`]: self-transport under superimposed oscillation: blocking force and free drive
//!   velocity.

pub mod compliant;
pub mod dimensionless;
pub mod drive;
pub(crate) mod numeric;
pub mod oscillation;
pub(crate) mod periodic_orbit;
pub mod psi;
mod slip_arc;
pub mod spring_model;
pub mod static_friction;

pub use compliant::{
    CompliantContact, CompliantStaticFriction, SteadySliding, mean_friction,
    static_friction_compliant, steady_sliding,
};
pub use dimensionless::{alpha, beta_from_force, beta_from_springs, mu_eff};
pub use drive::{DrivePoint, blocking_force, drive_curve, free_drive_velocity};
pub use oscillation::{Excitation, Oscillation};
pub use psi::{StickEvent, psi, psi_closed_form, psi_sine_eq37, psi_sine_eq38, stick_events};
pub use spring_model::{SimulationOptions, SpringModel, SpringModelOutcome};
pub use static_friction::{
    StaticFriction, mu_s_normal, mu_s_tangential, mu_s_transverse, static_friction_superimposed,
};
