//! How two coefficients combine, as the engines combine two colliders' friction: its own
//! file, because both the laws (`law::combine`) and the sliding curves combine by it.

use serde::{Deserialize, Serialize};

/// How two coefficients combine: rapier's `CoefficientCombineRule`, with its precedence (the
/// order of the variants: a later one wins when two sides disagree, see [`Self::effective`]).
#[derive(
    Debug, Clone, Copy, Default, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize,
)]
#[serde(rename_all = "kebab-case")]
pub enum CombineRule {
    /// (a + b)/2 (rapier's default).
    #[default]
    Average,
    /// min(a, b).
    Min,
    /// a·b.
    Multiply,
    /// max(a, b).
    Max,
    /// min(a + b, 1).
    ClampedSum,
    /// √(a·b).
    GeometricMean,
}

impl CombineRule {
    /// The rule two sides with rules `self` and `other` use: the higher in rapier's order.
    pub fn effective(self, other: CombineRule) -> CombineRule {
        self.max(other)
    }

    /// `a` and `b` combined (symmetric in `a`, `b`).
    pub fn apply(self, a: f64, b: f64) -> f64 {
        if a == b && self.is_idempotent() {
            return a;
        }
        match self {
            CombineRule::Average => 0.5 * (a + b),
            CombineRule::Min => a.min(b),
            CombineRule::Multiply => a * b,
            CombineRule::Max => a.max(b),
            CombineRule::ClampedSum => (a + b).clamp(0.0, 1.0),
            CombineRule::GeometricMean => (a * b).sqrt(),
        }
    }

    /// Whether a value combined with itself is that value.
    pub fn is_idempotent(self) -> bool {
        !matches!(self, CombineRule::Multiply | CombineRule::ClampedSum)
    }
}
