//! What the modifier reports after each step: per contact and per world.

use rapier::prelude::ColliderHandle;
use serde::Serialize;

/// Components of a world vector in a report: 3 (x, y, z) in 3D, 2 (x, y) in 2D.
#[cfg(not(dim2))]
pub const DIM: usize = 3;
/// Components of a world vector in a report: 3 (x, y, z) in 3D, 2 (x, y) in 2D.
#[cfg(dim2)]
pub const DIM: usize = 2;

/// One contact manifold after a step, its colliders as rapier handles (see
/// [`stickslip_core::report::ContactReport`], the one read-back type of every stickslip
/// engine).
pub type ContactReport = stickslip_core::report::ContactReport<ColliderHandle, DIM>;

/// One pair resisting rolling or spinning after a step, its colliders as rapier handles (see
/// [`stickslip_core::report::RollingReport`]).
pub type RollingReport = stickslip_core::report::RollingReport<ColliderHandle, DIM>;

/// Totals over all stickslip contacts after a step.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize)]
pub struct WorldTotals {
    /// Contacts reported.
    pub contacts: usize,
    /// Contacts sticking.
    pub sticking: usize,
    /// Contacts in stick-slip transition.
    pub stick_slip: usize,
    /// Contacts sliding.
    pub sliding: usize,
    /// Sum of normal forces (N).
    pub normal_force: f64,
    /// Sum of friction force magnitudes (N).
    pub friction_force: f64,
    /// Total dissipated power (W).
    pub dissipated_power: f64,
    /// Energy dissipated since the modifier was created (J).
    pub dissipated_energy: f64,
    /// Contacts reset this step because their inputs were not usable (see
    /// [`ContactReport::reset`]); they count as sticking above.
    pub reset: usize,
}
