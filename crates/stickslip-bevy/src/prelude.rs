//! What a bevy app names from the shared layer: `use stickslip_bevy::prelude::*;` (each
//! engine add-on's prelude re-exports it with its plugin).
pub use crate::{
    ContactReport, RegimeChanged, StickSlipContacts, StickSlipFriction, StickSlipVibration,
    SurfaceVelocity,
};
