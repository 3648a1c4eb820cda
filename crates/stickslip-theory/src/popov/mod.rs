//! Popov (2020), "The Influence of Vibration on Friction: A Contact-Mechanical Perspective":
//! everything `stickslip_core::popov` has (Ψ_w(β), the excitation, the compliant contact and
//! its self-drive), and the parts no engine needs at run time:
//!
//! - [`static_friction`]: μ_s under normal, tangential and transverse oscillation (Eq. 4, 6,
//!   8) and a numeric solver for superimposed oscillations (Eq. 9).
//! - [`dimensionless`]: α (Eq. 16), β (Eq. 17) and μ̄ = μ0 (1 − α Ψ_w(β)) (Eq. 33).
//! - [`spring_model`]: a time-stepped simulator of the spring contact that yields μ̄ directly,
//!   also for tangential and transverse oscillation where the seed has no closed form.

pub use stickslip_core::popov::*;

pub mod dimensionless;
pub mod spring_model;
pub mod static_friction;

pub use dimensionless::{alpha, beta_from_force, beta_from_springs, mu_eff};
pub use spring_model::{SimulationOptions, SpringModel, SpringModelOutcome};
pub use static_friction::{
    StaticFriction, mu_s_normal, mu_s_tangential, mu_s_transverse, static_friction_superimposed,
};
