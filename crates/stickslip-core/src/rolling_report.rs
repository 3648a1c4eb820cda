//! What an adapter reads back of a pair resisting rolling or spinning after a step (see
//! [`crate::FrictionMaterial::with_rolling`]), generic like [`crate::report::ContactReport`].

use crate::switch::Regime;
use serde::Serialize;

/// One pair resisting rolling or spinning after a step. `C` names a collider the engine's
/// way; `D` is the number of components of a world vector (3, or 2 in 2D). Torques are
/// always three components (N·m, world): in 2D the one rotation axis is z, so they are
/// `[0, 0, τ]`. Fields may be added: read them, do not build one.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(bound(serialize = "[f32; D]: Serialize"))]
#[non_exhaustive]
pub struct RollingReport<C, const D: usize = 3> {
    /// First collider of the pair.
    #[serde(skip)]
    pub collider1: C,
    /// Second collider of the pair.
    #[serde(skip)]
    pub collider2: C,
    /// Contact point (m, world) the resistance acts at.
    pub point: [f32; D],
    /// Contact normal (world, unit, from collider 1 towards collider 2).
    pub normal: [f32; D],
    /// Normal force the torque limits were set from (N): the last solve's, as a contact's
    /// friction limit.
    pub normal_force: f64,
    /// Rolling arm R (m): the reduced distance of the bodies' centres of mass from the
    /// contact plane.
    pub rolling_arm: f32,
    /// Spinning arm a (m): the spread of the contact's points, or R for a single point.
    pub spinning_arm: f32,
    /// Regime of the rolling law this step; `None` when the pair's materials do not resist
    /// rolling or the contact cannot roll (a patch of points, a box on its face: its normal
    /// forces hold every turn).
    pub rolling: Option<Regime>,
    /// Coefficient μ_r of the torque cap given to the solver this step (torque ≤ μ_r R F_n).
    pub rolling_limit: f64,
    /// Rolling-resistance torque on collider 2's body (N·m, world), from the solver's
    /// impulses.
    pub rolling_torque: [f32; 3],
    /// Regime of the spinning law this step; `None` when the pair's materials do not resist
    /// spinning (always in 2D).
    pub spinning: Option<Regime>,
    /// Coefficient μ_spin of the torque cap given to the solver this step.
    pub spinning_limit: f64,
    /// Spinning-resistance torque on collider 2's body (N·m, world, along the normal).
    pub spinning_torque: [f32; 3],
}

impl<C, const D: usize> RollingReport<C, D> {
    /// The report of the pair with every number zero and no regime: what an adapter fills
    /// in.
    pub fn new(collider1: C, collider2: C) -> Self {
        RollingReport {
            collider1,
            collider2,
            point: [0.0; D],
            normal: [0.0; D],
            normal_force: 0.0,
            rolling_arm: 0.0,
            spinning_arm: 0.0,
            rolling: None,
            rolling_limit: 0.0,
            rolling_torque: [0.0; 3],
            spinning: None,
            spinning_limit: 0.0,
            spinning_torque: [0.0; 3],
        }
    }

    /// The same report with the colliders named another way (rapier handles as bevy
    /// entities).
    pub fn with_colliders<K>(self, collider1: K, collider2: K) -> RollingReport<K, D> {
        RollingReport {
            collider1,
            collider2,
            point: self.point,
            normal: self.normal,
            normal_force: self.normal_force,
            rolling_arm: self.rolling_arm,
            spinning_arm: self.spinning_arm,
            rolling: self.rolling,
            rolling_limit: self.rolling_limit,
            rolling_torque: self.rolling_torque,
            spinning: self.spinning,
            spinning_limit: self.spinning_limit,
            spinning_torque: self.spinning_torque,
        }
    }

    /// |rolling torque| / (R F_n): the rolling coefficient the contact actually used.
    pub fn effective_rolling_mu(&self) -> f64 {
        effective(self.rolling_torque, self.rolling_arm, self.normal_force)
    }

    /// |spinning torque| / (a F_n): the spinning coefficient the contact actually used.
    pub fn effective_spinning_mu(&self) -> f64 {
        effective(self.spinning_torque, self.spinning_arm, self.normal_force)
    }
}

impl<C> RollingReport<C, 2> {
    /// The 2D report in 3D (point and normal with z = 0; torques are 3D already), for
    /// read-backs that take both (bevy's).
    pub fn in_3d(self) -> RollingReport<C, 3> {
        let lift = |[x, y]: [f32; 2]| [x, y, 0.0];
        RollingReport {
            collider1: self.collider1,
            collider2: self.collider2,
            point: lift(self.point),
            normal: lift(self.normal),
            normal_force: self.normal_force,
            rolling_arm: self.rolling_arm,
            spinning_arm: self.spinning_arm,
            rolling: self.rolling,
            rolling_limit: self.rolling_limit,
            rolling_torque: self.rolling_torque,
            spinning: self.spinning,
            spinning_limit: self.spinning_limit,
            spinning_torque: self.spinning_torque,
        }
    }
}

/// |torque| / (arm · normal force), 0 without load or arm.
fn effective(torque: [f32; 3], arm: f32, normal_force: f64) -> f64 {
    let lever = arm as f64 * normal_force;
    if lever > 0.0 {
        (torque.iter().map(|x| x * x).sum::<f32>() as f64).sqrt() / lever
    } else {
        0.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn effective_coefficients_are_torque_over_arm_and_load() {
        let mut r = RollingReport::<u32>::new(1, 2);
        assert_eq!(r.effective_rolling_mu(), 0.0);
        r.normal_force = 10.0;
        r.rolling_arm = 0.5;
        r.spinning_arm = 0.25;
        r.rolling_torque = [0.3, 0.0, -0.4];
        r.spinning_torque = [0.0, 0.05, 0.0];
        assert!((r.effective_rolling_mu() - 0.1).abs() < 1e-7);
        assert!((r.effective_spinning_mu() - 0.02).abs() < 1e-7);
        let named = r.with_colliders("a", "b");
        assert_eq!((named.collider1, named.collider2), ("a", "b"));
        assert_eq!(named.rolling_torque, r.rolling_torque);
    }

    #[test]
    fn a_2d_report_in_3d_lifts_point_and_normal_and_keeps_the_rest() {
        let mut r = RollingReport::<u32, 2>::new(1, 2);
        r.point = [1.0, 2.0];
        r.normal = [0.0, 1.0];
        r.rolling_torque = [0.0, 0.0, -0.3];
        r.normal_force = 5.0;
        let lifted = r.in_3d();
        assert_eq!(lifted.point, [1.0, 2.0, 0.0]);
        assert_eq!(lifted.normal, [0.0, 1.0, 0.0]);
        assert_eq!(lifted.rolling_torque, r.rolling_torque);
        assert_eq!(lifted.normal_force, 5.0);
    }
}
