//! Popov (2020), "The Influence of Vibration on Friction: A Contact-Mechanical Perspective":
//! a quasi-static contact with normal and tangential stiffness and constant Amontons μ0. The
//! parts an engine uses at run time; the static-friction closed forms (Eq. 4–9), the
//! dimensionless μ̄ of Eq. 33 and the spring-model simulator are in stickslip-theory.
//!
//! - [`psi`](mod@psi): the friction-reduction function Ψ_w(β) (Eq. 31) for any
//!   [`Waveform`](crate::waveform::Waveform), numerically, plus the closed forms Eq. 34–38.
//! - [`oscillation`]: the excitation A·w(ft + phase) in each direction.
//! - [`compliant`]: the compliant contact under superimposed oscillation (normal, tangential
//!   and transverse at once, any waveforms and phases): μ̄(v0) in every sliding mode and the
//!   static friction band at rest, from the exact event-driven periodic orbit of the model
//!   (stick in closed form, slip on the friction circle, event roots, period-map fixed point),
//!   checked against the spring model of stickslip-theory.
//! - [`drive`]: self-transport under superimposed oscillation: blocking force and free drive
//!   velocity.

pub mod compliant;
pub mod drive;
/// Root and extremum search shared with stickslip-theory; not part of the API.
#[doc(hidden)]
pub mod numeric;
pub mod oscillation;
pub(crate) mod periodic_orbit;
pub mod psi;
mod slip_arc;

pub use compliant::{
    CompliantContact, CompliantStaticFriction, SteadySliding, mean_friction,
    static_friction_compliant, steady_sliding,
};
pub use drive::{DrivePoint, blocking_force, drive_curve, free_drive_velocity};
pub use oscillation::{Excitation, Oscillation};
pub use psi::{
    StickEvent, beta_at_psi, psi, psi_closed_form, psi_sine_eq37, psi_sine_eq38, stick_events,
};
