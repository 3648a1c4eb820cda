//! # stickslip-bevy
//!
//! What stickslip's bevy add-ons share, whichever physics plugin an app runs:
//!
//! - the components an app puts on its colliders: [`StickSlipFriction`] (a stickslip
//!   material), [`StickSlipVibration`] (a vibration source), [`SurfaceVelocity`] (a conveyor
//!   belt's moving surface);
//! - the read-back: [`StickSlipContacts`], the contacts of the last physics step as
//!   [`ContactReport`]s whose colliders are entities, and the [`RegimeChanged`] message;
//! - the contact gizmos (feature `debug`, [`debug::StickSlipDebugPlugin`]);
//! - what windowed apps share (feature `window`): their command line, the display check and
//!   a screenshot at a given frame ([`window::ScreenshotAndExit`]).
//!
//! An app adds one add-on, which re-exports all of this: `stickslip-bevy-rapier`
//! (bevy_rapier3d) or `stickslip-avian` (avian3d). Moving an app from one to the other changes
//! its plugin line; the components, the read-back and the gizmos stay.
#![warn(missing_docs)]

mod components;
#[cfg(feature = "debug")]
pub mod debug;
pub mod prelude;
mod read_back;
#[cfg(feature = "window")]
pub mod window;

pub use components::{StickSlipFriction, StickSlipVibration, SurfaceVelocity};
pub use read_back::{
    ContactReport, RegimeChanged, RollingReport, StickSlipContacts, StickSlipRolling,
};
