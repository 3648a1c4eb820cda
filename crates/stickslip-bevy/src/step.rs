//! The step itself: user inputs into rapier, one step of the world with the stickslip
//! modifier, poses and velocities back onto the entities.

use crate::components::*;
use crate::convert::{pose_of, rot_to_bevy, to_bevy, to_rapier};
use crate::world::StickSlipWorld;
use bevy::prelude::*;
use rapier3d::prelude as rp;

/// Gravity of the world (m/s², default −9.81 along y).
#[derive(Resource, Debug, Clone, Copy, PartialEq)]
pub struct Gravity(pub Vec3);

impl Default for Gravity {
    fn default() -> Self {
        Gravity(Vec3::new(0.0, -9.81, 0.0))
    }
}

/// What the user changed since the last writeback goes into rapier: poses of kinematic bodies
/// and teleports, velocities, external forces.
pub(crate) fn apply_inputs(
    mut w: ResMut<StickSlipWorld>,
    bodies: Query<(
        Entity,
        &RigidBody,
        &Transform,
        &Velocity,
        Option<&ExternalForce>,
    )>,
) {
    let w = &mut *w;
    for (entity, kind, transform, velocity, force) in &bodies {
        let Some(b) = w.body(entity).and_then(|h| w.physics.bodies.get_mut(h)) else {
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

/// One rapier step with the stickslip modifier, with the schedule's time step (the fixed
/// one in fixed schedules). Nothing happens for a zero step (paused virtual time).
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

/// Poses and velocities of moving bodies back onto their entities.
pub(crate) fn writeback(
    w: Res<StickSlipWorld>,
    mut bodies: Query<(Entity, &RigidBody, &mut Transform, &mut Velocity)>,
) {
    for (entity, kind, mut transform, mut velocity) in &mut bodies {
        if matches!(kind, RigidBody::Fixed) {
            continue;
        }
        let Some(b) = w.body(entity).and_then(|h| w.physics.bodies.get(h)) else {
            continue;
        };
        let pose: &rp::Pose = b.position();
        let (translation, rotation) = (to_bevy(pose.translation), rot_to_bevy(pose.rotation));
        if transform.translation != translation || transform.rotation != rotation {
            transform.translation = translation;
            transform.rotation = rotation;
        }
        let v = Velocity {
            linear: to_bevy(b.linvel()),
            angular: to_bevy(b.angvel()),
        };
        if *velocity != v {
            *velocity = v;
        }
    }
}
