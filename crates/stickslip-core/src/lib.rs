//! # stickslip-core
//!
//! The pure-math core of stickslip: no rapier, bevy or rerun in here.
//!
//! - [`law`]: the stateful elasto-plastic friction law of the seed paper (Eq. 4–7), its
//!   baselines "Phys" (exact switched, Eq. 1–3), "Regul" (regularized) and plain Coulomb, all
//!   behind one [`law::FrictionLaw`] interface that a physics engine calls once per step.
//! - [`sliding_curve`]: the sliding curve μ_ve(|v|) (constant, Stribeck, table).
//! - [`switch`]: the sine-blended switch α(μ) of Eq. 5–7.
//! - [`waveform`] and [`popov`]: normalized vibration waveforms and the part of Popov's (2020)
//!   theory of friction under oscillation that the averaged vibration mode evaluates at run
//!   time (Ψ_w(β), the compliant contact's μ̄ and static band, its self-drive).
//! - [`contact`]: the per-contact kernel every engine adapter calls, and the vibration sources.
//! - [`report`]: the contact read-back every engine adapter gives, one type for all (and
//!   one for the pairs that resist rolling or spinning).
//! - [`rolling`]: the engine-free part of rolling and spinning resistance (which turns a
//!   contact rolls, the resisting torques' caps and targets per step).
//! - [`profile`]: validated piecewise-linear force profiles F(t), such as the seed's Example 1.
//!
//! The reference simulators and the rest of Popov's theory (static friction, spring model,
//! the seed's block and chain, a vibratory feeder) are in the `stickslip-theory` crate.
#![warn(missing_docs)]
// `!(x > 0.0)` is deliberate throughout: it rejects NaN along with non-positive values.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

mod combine_rule;
pub mod contact;
pub mod error;
pub mod law;
pub mod material;
pub mod popov;
pub mod prelude;
pub mod profile;
pub mod report;
pub mod rolling;
mod rolling_report;
pub mod sliding_curve;
pub mod switch;
pub mod vec2;
pub mod waveform;

pub use error::ParamError;
pub use material::FrictionMaterial;
