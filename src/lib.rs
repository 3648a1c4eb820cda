//! # stickslip
//!
//! Friction that behaves like real friction for rapier3d: sticking without creep, break-away,
//! Stribeck sliding, smooth reversal and vibration-dependent friction.
//!
//! This facade re-exports the workspace crates:
//! - [`core`] (`stickslip-core`): the friction laws, vibration theory and reference simulators,
//!   free of any engine dependency;
//! - [`rapier`] (`stickslip-rapier`, feature `rapier`, on by default): the rapier3d contact
//!   modifier.
#![warn(missing_docs)]

pub use stickslip_core as core;

#[cfg(feature = "rapier")]
pub use stickslip_rapier as rapier;
