//! Per-collider friction material.

use serde::{Deserialize, Serialize};
use stickslip_core::law::Law;

/// The friction law a collider's contacts use (and its parameters).
///
/// Two colliders' materials combine like rapier's friction coefficients, by the colliders'
/// `friction_combine_rule` (see [`crate::StickSlip::attach`]); a pair can have its own
/// ([`crate::StickSlip::set_pair_material`]). Attached colliders without one use the
/// modifier's default.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct FrictionMaterial {
    /// The law: elasto-plastic (the point of stickslip), or a baseline for comparison.
    pub law: Law,
}

impl FrictionMaterial {
    /// A material using `law`.
    pub fn new(law: Law) -> Self {
        FrictionMaterial { law }
    }
}

impl From<Law> for FrictionMaterial {
    fn from(law: Law) -> Self {
        FrictionMaterial { law }
    }
}
