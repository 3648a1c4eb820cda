//! Per-collider friction material.

use serde::{Deserialize, Serialize};
use stickslip_core::law::Law;

/// The friction law a collider's contacts use (and its parameters).
///
/// When both colliders of a contact carry a material, the first collider's (rapier's
/// `collider1` of the pair) is used; colliders without one fall back to the modifier's default.
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
