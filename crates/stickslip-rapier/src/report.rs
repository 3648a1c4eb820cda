//! What the modifier reports after each step: per contact and per world.

use rapier::prelude::ColliderHandle;
use serde::Serialize;
use stickslip_core::law::Regime;

/// Components of a world vector in a report: 3 (x, y, z) in 3D, 2 (x, y) in 2D.
#[cfg(not(dim2))]
pub const DIM: usize = 3;
/// Components of a world vector in a report: 3 (x, y, z) in 3D, 2 (x, y) in 2D.
#[cfg(dim2)]
pub const DIM: usize = 2;

/// One contact manifold after a step (fields may be added: read them, do not build one).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[non_exhaustive]
pub struct ContactReport {
    /// First collider of the pair.
    #[serde(skip)]
    pub collider1: ColliderHandle,
    /// Second collider of the pair.
    #[serde(skip)]
    pub collider2: ColliderHandle,
    /// Contact point (m, world): the centroid of the manifold's solver contacts after the
    /// step, midway between the two surfaces.
    pub point: [f32; DIM],
    /// Contact normal (world, from collider 1 towards collider 2).
    pub normal: [f32; DIM],
    /// Regime the law reported this step.
    pub regime: Regime,
    /// Friction state |μ⃗| = |s⃗|/F_n of the law.
    pub mu: f64,
    /// Friction limit the solver used this step (coefficient of the solver's normal force).
    pub limit: f64,
    /// Normal force over the step (N), from the solver's impulses.
    pub normal_force: f64,
    /// Friction force on collider 2's body (N, world), from the solver's impulses.
    pub friction_force: [f32; DIM],
    /// Slip velocity of collider 2 relative to collider 1's surface after the step (m/s).
    pub slip_velocity: [f32; DIM],
    /// Power dissipated by friction, −F_f·ġ ≥ 0 (W).
    pub dissipated_power: f64,
    /// The contact's inputs were not usable this step (non-finite or beyond f32 velocities,
    /// impulses or positions, e.g. a body given a NaN or 1e38 velocity): its friction state
    /// was reset, the solver got the law's static coefficient, and every number of this
    /// report is zero.
    pub reset: bool,
}

impl ContactReport {
    /// |friction force| / normal force: the coefficient the contact actually used.
    pub fn effective_mu(&self) -> f64 {
        if self.normal_force > 0.0 {
            let f = self.friction_force;
            (f.iter().map(|x| x * x).sum::<f32>() as f64).sqrt() / self.normal_force
        } else {
            0.0
        }
    }
}

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
