//! The step: user inputs into rapier, then one step of the world with the stickslip modifier.

use crate::components::*;
use crate::convert::{pose_of, to_rapier};
use crate::world::StickSlipWorld;
use bevy::prelude::*;

/// Gravity of the world (m/s², default −9.81 along y).
#[derive(Resource, Debug, Clone, Copy, PartialEq)]
pub struct Gravity(pub Vec3);

impl Default for Gravity {
    fn default() -> Self {
        Gravity(Vec3::new(0.0, -9.81, 0.0))
    }
}

/// What the user changed since the last writeback goes into rapier: poses of kinematic
/// bodies and teleports, velocities, external forces. (The writeback leaves each `Transform`
/// and `Velocity` equal to rapier's state, so any difference here is the user's.)
pub(crate) fn apply_inputs(
    mut w: ResMut<StickSlipWorld>,
    bodies: Query<(
        &RigidBody,
        &RapierBody,
        &Transform,
        &Velocity,
        Option<&ExternalForce>,
    )>,
) {
    for (kind, h, transform, velocity, force) in &bodies {
        let Some(b) = w.physics.bodies.get_mut(h.0) else {
            continue;
        };
        let pose = pose_of(transform);
        match kind {
            RigidBody::KinematicPositionBased => b.set_next_kinematic_position(pose),
            _ if *b.position() != pose => b.set_position(pose, true),
            _ => {}
        }
        let (lin, ang) = (to_rapier(velocity.linear), to_rapier(velocity.angular));
        if !matches!(kind, RigidBody::KinematicPositionBased | RigidBody::Fixed)
            && (b.linvel() != lin || b.angvel() != ang)
        {
            b.set_linvel(lin, true);
            b.set_angvel(ang, true);
        }
        if let Some(f) = force {
            b.reset_forces(false);
            b.reset_torques(false);
            b.add_force(to_rapier(f.force), true);
            b.add_torque(to_rapier(f.torque), true);
        }
    }
}

/// One rapier step with the stickslip modifier over the schedule's time step: `Time<Fixed>`'s
/// in fixed schedules. A zero step (virtual time paused) steps nothing.
pub(crate) fn step_world(mut w: ResMut<StickSlipWorld>, time: Res<Time>, gravity: Res<Gravity>) {
    let dt = time.delta_secs();
    if dt.is_nan() || dt <= 0.0 {
        return;
    }
    let w = &mut *w;
    w.physics.integration_parameters.dt = dt;
    w.physics.gravity = to_rapier(gravity.0);
    w.friction.step(&mut w.physics);
}
