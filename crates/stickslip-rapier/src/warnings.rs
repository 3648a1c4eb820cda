//! One-time warnings through the `log` facade (which rapier and bevy users already route):
//! stickslip never falls back to plain rapier silently.

use std::sync::atomic::{AtomicBool, Ordering};

/// What stickslip warns about, once per modifier each.
#[derive(Debug, Clone, Copy)]
pub(crate) enum Warning {
    /// The hook ran with no `begin_step` since the last `end_step`.
    NoBeginStep,
    /// The world's `FrictionModel` is not the one stickslip realizes its law with.
    #[cfg(not(dim2))]
    FrictionModel,
    /// Two materials did not combine into a valid law.
    Combine,
    /// A step's dt outside the modifier's range (not a pause, dt = 0).
    StepDt,
}

/// Which warnings were given.
#[derive(Debug, Default)]
pub(crate) struct Warned([AtomicBool; 4]);

impl Warned {
    /// Logs `message` at warn level the first time `warning` occurs.
    pub(crate) fn once(&self, warning: Warning, message: &str) {
        if !self.0[warning as usize].swap(true, Ordering::Relaxed) {
            log::warn!("{message}");
        }
    }
}
