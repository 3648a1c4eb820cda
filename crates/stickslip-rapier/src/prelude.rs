//! What most users of the adapter name: `use stickslip_rapier::prelude::*;` (with
//! `rapier::prelude::*` for the engine's own types).
pub use crate::{ContactReport, ReadBack, StickSlip, StickSlipConfig, WorldSnapshot, WorldTotals};
pub use stickslip_core::prelude::*;
