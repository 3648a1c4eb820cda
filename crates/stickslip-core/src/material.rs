//! Per-collider friction material.

use crate::law::Law;
use serde::{Deserialize, Serialize};

/// The friction law a collider's contacts use (and its parameters).
///
/// Two colliders' materials combine like the engine combines friction coefficients, by a
/// [`crate::law::CombineRule`] (in rapier, the colliders' `friction_combine_rule`); an adapter
/// may give a pair its own. Colliders attached without one use the adapter's default.
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
