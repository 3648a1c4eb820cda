//! Rapier's state back onto the entities: poses and velocities of the bodies that move.

use crate::components::*;
use crate::convert::{rot_to_bevy, to_bevy};
use crate::world::StickSlipWorld;
use bevy::prelude::*;

/// Poses and velocities of moving bodies back onto their entities (written only when they
/// differ, so change detection sees real motion only).
pub(crate) fn writeback(
    w: Res<StickSlipWorld>,
    mut bodies: Query<(&RigidBody, &RapierBody, &mut Transform, &mut Velocity)>,
) {
    for (kind, h, mut transform, mut velocity) in &mut bodies {
        if matches!(kind, RigidBody::Fixed) {
            continue;
        }
        let Some(b) = w.physics.bodies.get(h.0) else {
            continue;
        };
        let pose = b.position();
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
