//! # stickslip-theory
//!
//! The reference theory stickslip's engines are validated against; no engine needs it at run
//! time (the parts of Popov's theory the averaged vibration mode uses live in
//! `stickslip_core::popov`).
//!
//! - [`popov`]: everything in `stickslip_core::popov` (Ψ_w(β), the compliant contact, the
//!   self-drive) plus Popov's (2020) static friction under normal, tangential, transverse and
//!   superimposed oscillation (Eq. 4, 6, 8, 9), the dimensionless α, β and μ̄ (Eq. 16, 17, 33)
//!   and a time-stepped simulator of his spring model.
//! - [`block`]: the seed's Example 1, a block under a time-dependent force, simulated for every
//!   law with adaptive explicit and implicit ODE methods from `differential-equations`, and the
//!   mass–spring on a moving belt.
//! - [`feeder`]: a rigid-body reference for vibratory feeders (point mass, exact ballistic
//!   flight, plastic landing with Coulomb impact friction).
#![warn(missing_docs)]
// `!(x > 0.0)` is deliberate throughout: it rejects NaN along with non-positive values.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod block;
/// The seed's many-contact reference (a chain of blocks), used by the benchmarks only; outside
/// the documented surface.
#[doc(hidden)]
pub mod chain;
pub mod feeder;
mod integrate;
pub mod popov;
pub mod prelude;
