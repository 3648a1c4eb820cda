//! Per-collider friction material.

use crate::law::Law;
use serde::{Deserialize, Serialize};

/// The friction law a collider's contacts use (and its parameters).
///
/// Two colliders' materials combine like the engine combines friction coefficients, by a
/// [`crate::law::CombineRule`] (in rapier, the colliders' `friction_combine_rule`); an adapter
/// may give a pair its own. Colliders attached without one use the adapter's default.
///
/// A material may also resist the bodies' relative rotation at the contact
/// ([`Self::with_rolling`], [`Self::with_spinning`]): off unless asked for.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct FrictionMaterial {
    /// The law: elasto-plastic (the point of stickslip), or a baseline for comparison.
    pub law: Law,
    /// Rolling resistance: a torque M_r = μ_r R F_n against the relative rolling (the
    /// tangential part of the relative angular velocity), R the rolling arm at the contact.
    /// The law's coefficients are μ_r; it is stepped on the rolled arc R θ as the friction
    /// law is on the slip (an elasto-plastic law holds within μ_ba/c of arc, breaks away at
    /// μ_ba and rolls at its sliding curve's μ_r(R |ω|)). `None`: no rolling resistance.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub rolling: Option<Law>,
    /// Spinning resistance: a torque M_s = μ_spin a F_n against the relative spin (the
    /// normal part of the relative angular velocity), a the spinning arm at the contact, by
    /// the same kind of law on the arc a θ. `None`: no spinning resistance.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub spinning: Option<Law>,
}

impl FrictionMaterial {
    /// A material using `law`, without rolling or spinning resistance.
    pub fn new(law: Law) -> Self {
        FrictionMaterial {
            law,
            rolling: None,
            spinning: None,
        }
    }

    /// The same material with rolling resistance by `law` (its coefficients are μ_r).
    pub fn with_rolling(mut self, law: Law) -> Self {
        self.rolling = Some(law);
        self
    }

    /// The same material with spinning resistance by `law` (its coefficients are μ_spin).
    pub fn with_spinning(mut self, law: Law) -> Self {
        self.spinning = Some(law);
        self
    }

    /// Whether the material resists rolling or spinning.
    pub fn resists_rotation(&self) -> bool {
        self.rolling.is_some() || self.spinning.is_some()
    }
}

impl From<Law> for FrictionMaterial {
    fn from(law: Law) -> Self {
        FrictionMaterial::new(law)
    }
}
