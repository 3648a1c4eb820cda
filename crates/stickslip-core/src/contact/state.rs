//! The friction state of one contact patch: what the kernel keeps between steps (30 bytes).
//! An engine adapter stores it with whatever it needs to find the contact again.

use super::tangent::World;
use crate::law::Regime;

/// Regime code of a contact whose inputs were not usable in its last step (see
/// [`super::step_contact`]); adapters' business (readers get `ContactReport::reset`).
#[doc(hidden)]
pub const REGIME_RESET: u8 = 254;
/// Regime code of a contact the law has not run on yet.
#[doc(hidden)]
pub const REGIME_NONE: u8 = u8::MAX;

impl Regime {
    /// The code a [`ContactState`] stores for the regime (0, 1, 2).
    pub fn code(self) -> u8 {
        match self {
            Regime::Sticking => 0,
            Regime::StickSlip => 1,
            Regime::Sliding => 2,
        }
    }

    /// The regime of a stored code: [`REGIME_RESET`] and [`REGIME_NONE`] read as sticking.
    pub fn from_code(code: u8) -> Regime {
        match code {
            1 => Regime::StickSlip,
            2 => Regime::Sliding,
            _ => Regime::Sticking,
        }
    }
}

/// The state of one contact patch between steps.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactState {
    /// Friction-law state s⃗ (tangential spring force, N) in world coordinates, so that it
    /// follows the contact plane as the normal turns.
    pub force: World,
    /// Friction-law break-away progress σ (elasto-plastic law; 0 otherwise).
    pub slide: f32,
    /// The friction coefficient limit given to the solver last step (0: none yet).
    pub limit: f32,
    /// Slip speed seen last step (m/s; 0 while holding).
    pub slip_speed: f32,
    /// Mean normal force (N), low-pass filtered: sets the law's tangential stiffness.
    pub mean_normal_force: f32,
    /// Regime code ([`Regime::code`], [`REGIME_RESET`], [`REGIME_NONE`] until the law has
    /// run).
    pub regime: u8,
    /// Steps left (0–2) in which the solver is still forming the contact after a solve
    /// that started cold, or [`super::GIVING`] while it gives under a jump in load.
    pub forming: u8,
}

impl Default for ContactState {
    fn default() -> Self {
        ContactState {
            force: [0.0; 3],
            slide: 0.0,
            limit: 0.0,
            slip_speed: 0.0,
            mean_normal_force: 0.0,
            regime: REGIME_NONE,
            forming: 0,
        }
    }
}

impl ContactState {
    /// The regime of the last step, or `None` for a contact the law has not run on yet or
    /// whose inputs were reset.
    pub fn regime(&self) -> Option<Regime> {
        matches!(self.regime, 0..=2).then(|| Regime::from_code(self.regime))
    }

    /// Whether the last step's inputs were not usable (the contact was reset).
    pub fn was_reset(&self) -> bool {
        self.regime == REGIME_RESET
    }
}
