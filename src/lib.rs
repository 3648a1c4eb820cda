//! # stickslip
//!
//! Friction that behaves like real friction for rapier3d: sticking without creep, break-away,
//! Stribeck sliding, smooth reversal and vibration-dependent friction.
//!
//! This facade re-exports the workspace crates:
//! - [`core`] (`stickslip-core`): the friction laws, the per-contact kernel and the vibration
//!   sources, free of any engine dependency;
//! - [`rapier`] (`stickslip-rapier`, feature `rapier`, on by default): the rapier3d contact
//!   modifier;
//! - [`prelude`]: both crates' preludes, `use stickslip::prelude::*;`.
#![warn(missing_docs)]

pub use stickslip_core as core;

#[cfg(feature = "rapier")]
pub use stickslip_rapier as rapier;

/// What most users name: the core's prelude and, with feature `rapier`, the rapier modifier's.
pub mod prelude {
    #[cfg(not(feature = "rapier"))]
    pub use stickslip_core::prelude::*;
    #[cfg(feature = "rapier")]
    pub use stickslip_rapier::prelude::*;
}
