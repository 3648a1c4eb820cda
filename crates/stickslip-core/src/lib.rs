//! # stickslip-core
//!
//! The pure-math core of stickslip: no rapier, bevy or rerun in here.
//!
//! - [`law`]: the stateful elasto-plastic friction law of the seed paper (Eq. 4–7), its
//!   baselines "Phys" (exact switched, Eq. 1–3), "Regul" (regularized) and plain Coulomb, all
//!   behind one [`law::FrictionLaw`] interface that a physics engine calls once per step.
//! - [`sliding_curve`]: the sliding curve μ_ve(|v|) (constant, Stribeck, table).
//! - [`switch`]: the sine-blended switch α(μ) of Eq. 5–7.
//! - [`waveform`] and [`popov`]: normalized vibration waveforms and Popov's (2020) theory of
//!   friction under normal, tangential and transverse oscillation (Ψ_w(β), μ̄, static
//!   coefficients) plus a time-stepped reference simulator of his spring model.
//! - [`feeder`]: a rigid-body reference for vibratory feeders (point mass, exact ballistic
//!   flight, plastic landing with Coulomb impact friction).
//! - [`block`]: the seed's Example 1, a block under a time-dependent force: its force profile,
//!   and (feature `reference`) its simulation with adaptive explicit and implicit ODE methods
//!   from `differential-equations`, which builds without the feature do not carry.
#![warn(missing_docs)]
// `!(x > 0.0)` is deliberate throughout: it rejects NaN along with non-positive values.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod block;
/// The seed's many-contact reference (a chain of blocks), used by the benchmarks only: behind
/// the `reference` feature, outside the default public surface.
#[cfg(feature = "reference")]
#[doc(hidden)]
pub mod chain;
mod combine_rule;
pub mod contact;
pub mod error;
pub mod feeder;
#[cfg(feature = "reference")]
mod integrate;
pub mod law;
pub mod material;
pub mod popov;
pub mod prelude;
pub mod sliding_curve;
pub mod switch;
pub mod vec2;
pub mod waveform;

pub use error::ParamError;
pub use material::FrictionMaterial;
