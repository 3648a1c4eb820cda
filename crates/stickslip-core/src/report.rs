//! What every engine adapter reads back of a contact after a step: one type for rapier (3D
//! and 2D), bevy_rapier and avian, generic over how the engine names a collider and over the
//! dimension.

use crate::switch::Regime;
use serde::Serialize;

pub use crate::rolling_report::RollingReport;

/// One contact (a manifold, or one face of a composite shape) after a step. `C` names a
/// collider the engine's way (rapier's `ColliderHandle`, a bevy `Entity`); `D` is the number
/// of components of a world vector (3, or 2 in rapier2d). Fields may be added: read them, do
/// not build one.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(bound(serialize = "[f32; D]: Serialize"))]
#[non_exhaustive]
pub struct ContactReport<C, const D: usize = 3> {
    /// First collider of the pair.
    #[serde(skip)]
    pub collider1: C,
    /// Second collider of the pair.
    #[serde(skip)]
    pub collider2: C,
    /// Contact point (m, world): the centroid of the contact's points, midway between the two
    /// surfaces.
    pub point: [f32; D],
    /// Contact normal (world, unit, from collider 1 towards collider 2).
    pub normal: [f32; D],
    /// Regime the law reported this step.
    pub regime: Regime,
    /// Friction state |μ⃗| = |s⃗|/F_n of the law.
    pub mu: f64,
    /// Friction limit the solver used this step (coefficient of the solver's normal force).
    pub limit: f64,
    /// Normal force over the step (N), from the solver's impulses.
    pub normal_force: f64,
    /// Friction force on collider 2's body (N, world), from the solver's impulses.
    pub friction_force: [f32; D],
    /// Slip velocity of collider 2 relative to collider 1's surface (m/s, world).
    pub slip_velocity: [f32; D],
    /// Power dissipated by friction, −F_f·ġ ≥ 0 (W).
    pub dissipated_power: f64,
    /// The contact's inputs were not usable this step (non-finite or beyond f32 velocities,
    /// impulses or positions, e.g. a body given a NaN or 1e38 velocity): its friction state
    /// was reset, the solver got the law's static coefficient, and every number of this
    /// report but `limit` is zero.
    pub reset: bool,
}

impl<C, const D: usize> ContactReport<C, D> {
    /// The report of the pair with every number zero, sticking, not reset: what an adapter
    /// fills in.
    pub fn new(collider1: C, collider2: C) -> Self {
        ContactReport {
            collider1,
            collider2,
            point: [0.0; D],
            normal: [0.0; D],
            regime: Regime::Sticking,
            mu: 0.0,
            limit: 0.0,
            normal_force: 0.0,
            friction_force: [0.0; D],
            slip_velocity: [0.0; D],
            dissipated_power: 0.0,
            reset: false,
        }
    }

    /// The same report with the colliders named another way (rapier handles as bevy
    /// entities).
    pub fn with_colliders<K>(self, collider1: K, collider2: K) -> ContactReport<K, D> {
        ContactReport {
            collider1,
            collider2,
            point: self.point,
            normal: self.normal,
            regime: self.regime,
            mu: self.mu,
            limit: self.limit,
            normal_force: self.normal_force,
            friction_force: self.friction_force,
            slip_velocity: self.slip_velocity,
            dissipated_power: self.dissipated_power,
            reset: self.reset,
        }
    }

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

impl<C> ContactReport<C, 2> {
    /// The 2D report in 3D's arrays, z = 0 (the plane's contacts in the one read-back type
    /// of the bevy add-ons).
    pub fn in_3d(self) -> ContactReport<C, 3> {
        let lift = |[x, y]: [f32; 2]| [x, y, 0.0];
        ContactReport {
            collider1: self.collider1,
            collider2: self.collider2,
            point: lift(self.point),
            normal: lift(self.normal),
            regime: self.regime,
            mu: self.mu,
            limit: self.limit,
            normal_force: self.normal_force,
            friction_force: lift(self.friction_force),
            slip_velocity: lift(self.slip_velocity),
            dissipated_power: self.dissipated_power,
            reset: self.reset,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn effective_mu_is_the_friction_over_the_normal_force() {
        let mut r = ContactReport::<u32>::new(1, 2);
        assert_eq!(r.effective_mu(), 0.0);
        r.normal_force = 10.0;
        r.friction_force = [3.0, 0.0, -4.0];
        assert!((r.effective_mu() - 0.5).abs() < 1e-12);
        let named = r.with_colliders("a", "b");
        assert_eq!((named.collider1, named.collider2), ("a", "b"));
        assert_eq!(named.effective_mu(), r.effective_mu());
    }

    #[test]
    fn a_2d_report_in_3d_keeps_its_numbers_in_the_plane() {
        let mut r = ContactReport::<u32, 2>::new(1, 2);
        r.normal_force = 10.0;
        r.friction_force = [-3.0, 4.0];
        r.normal = [0.0, 1.0];
        let lifted = r.in_3d();
        assert_eq!(lifted.friction_force, [-3.0, 4.0, 0.0]);
        assert_eq!(lifted.normal, [0.0, 1.0, 0.0]);
        assert_eq!(lifted.effective_mu(), r.effective_mu());
    }
}
