//! Removals, seen by observers the moment they happen (a fixed schedule can skip frames and
//! miss `RemovedComponents`): despawns and removed components take their rapier objects and
//! stickslip state with them.

use crate::components::*;
use crate::world::StickSlipWorld;
use bevy::prelude::*;

/// Despawning a body or removing its `RigidBody` removes the rapier body with every collider
/// on it. Colliders whose entities live on are created again (fixed) at the next step.
pub(crate) fn on_remove_body(
    remove: On<Remove, RigidBody>,
    mut w: ResMut<StickSlipWorld>,
    mut commands: Commands,
) {
    let attached = w.remove_body(remove.entity);
    // `try_remove`: during a despawn these entities are going away anyway.
    commands.entity(remove.entity).try_remove::<RapierBody>();
    for e in attached {
        commands.entity(e).try_remove::<RapierCollider>();
    }
}

/// Despawning a collider or removing its `Collider` removes it from rapier and stickslip.
pub(crate) fn on_remove_collider(
    remove: On<Remove, Collider>,
    mut w: ResMut<StickSlipWorld>,
    mut commands: Commands,
) {
    if w.remove_collider(remove.entity) {
        commands
            .entity(remove.entity)
            .try_remove::<RapierCollider>();
    }
}

/// Removing `ExternalForce` stops the force.
pub(crate) fn on_remove_force(remove: On<Remove, ExternalForce>, mut w: ResMut<StickSlipWorld>) {
    if let Some(h) = w.body(remove.entity)
        && let Some(b) = w.physics.bodies.get_mut(h)
    {
        b.reset_forces(true);
        b.reset_torques(true);
    }
}
