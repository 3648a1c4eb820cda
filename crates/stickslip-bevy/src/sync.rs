//! The app's stickslip components onto the modifier, each frame before the step: colliders
//! attached and detached, vibration sources, surface velocities (and the `ActiveHooks` flag
//! bevy_rapier writes from the collider's component).

use crate::components::{StickSlipFriction, StickSlipVibration, SurfaceVelocity};
use crate::state::StickSlipRapier;
use bevy::prelude::*;
use bevy_rapier3d::plugin::context::{DefaultRapierContext, RapierContextColliders};
use bevy_rapier3d::prelude::*;

/// Whether a collider lives in the default context (the one stickslip brackets).
fn in_default(link: Option<&RapierContextEntityLink>, default: Entity) -> bool {
    link.is_none_or(|l| l.0 == default)
}

/// Turns on the hook flag bevy_rapier writes into the collider, keeping the app's flags.
fn add_hook_flag(commands: &mut Commands, entity: Entity, hooks: Option<&ActiveHooks>) {
    let flags = hooks.copied().unwrap_or(ActiveHooks::empty());
    if !flags.contains(ActiveHooks::MODIFY_SOLVER_CONTACTS) {
        commands
            .entity(entity)
            .insert(flags | ActiveHooks::MODIFY_SOLVER_CONTACTS);
    }
}

/// Attaches marked colliders once bevy_rapier created them; detaches removed ones.
#[allow(clippy::type_complexity)]
pub(crate) fn attach(
    mut commands: Commands,
    mut state: ResMut<StickSlipRapier>,
    marked: Query<
        (
            Entity,
            &StickSlipFriction,
            &RapierColliderHandle,
            Option<&ActiveHooks>,
            Option<&RapierContextEntityLink>,
        ),
        Or<(Added<RapierColliderHandle>, Changed<StickSlipFriction>)>,
    >,
    mut removed: RemovedComponents<StickSlipFriction>,
    mut context: Query<(Entity, &mut RapierContextColliders), With<DefaultRapierContext>>,
) {
    let Ok((default, mut colliders)) = context.single_mut() else {
        return;
    };
    let state = &mut *state;
    for entity in removed.read() {
        if let Some(h) = state.attached.remove(&entity) {
            state.modifier.detach(&mut colliders.colliders, h);
        }
    }
    if !state.active {
        return;
    }
    for (entity, friction, handle, hooks, link) in &marked {
        if !in_default(link, default) {
            continue;
        }
        state
            .modifier
            .attach(&mut colliders.colliders, handle.0, friction.0.clone());
        state.attached.insert(entity, handle.0);
        add_hook_flag(&mut commands, entity, hooks);
    }
}

/// Vibration sources onto the colliders' contacts (and off again, also on despawn).
#[allow(clippy::type_complexity)]
pub(crate) fn sync_vibrations(
    mut state: ResMut<StickSlipRapier>,
    changed: Query<
        (Entity, &StickSlipVibration, &RapierColliderHandle),
        Or<(Changed<StickSlipVibration>, Added<RapierColliderHandle>)>,
    >,
    mut removed: RemovedComponents<StickSlipVibration>,
) {
    let state = &mut *state;
    for entity in removed.read() {
        if let Some(h) = state.vibrating.remove(&entity) {
            state.modifier.remove_vibration(h);
        }
    }
    for (entity, v, h) in &changed {
        state.modifier.set_vibration(h.0, v.0.clone());
        state.vibrating.insert(entity, h.0);
    }
}

/// Surface velocities for the hooks (and the hook flag on their colliders).
#[allow(clippy::type_complexity)]
pub(crate) fn sync_surfaces(
    mut commands: Commands,
    mut state: ResMut<StickSlipRapier>,
    surfaces: Query<(
        Entity,
        &SurfaceVelocity,
        &RapierColliderHandle,
        Option<&ActiveHooks>,
    )>,
) {
    state.surfaces.clear();
    for (entity, v, h, hooks) in &surfaces {
        state.surfaces.insert(h.0, v.0);
        add_hook_flag(&mut commands, entity, hooks);
    }
}
