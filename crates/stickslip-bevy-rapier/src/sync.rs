//! The app's stickslip components onto the modifier: colliders attached, vibration sources
//! and surface velocities each frame before the step; removals (and despawns) in `PostUpdate`
//! before bevy_rapier removes the colliders, so that none is missed whatever schedule the
//! physics runs in.
//!
//! The rapier hook flag `MODIFY_SOLVER_CONTACTS` on a stickslip collider is stickslip's unless
//! the app's own `ActiveHooks` component carries it. The component stays the app's (stickslip
//! never writes it); the modifier is the one owner of whose flag it is: this add-on tells it
//! what the component says after attaching, after setting a surface velocity and after
//! bevy_rapier rewrote the flags from a changed component (`StickSlip::set_user_hook_flag`).
//! The modifier turns the flag on, runs the app's hooks only on pairs with a collider whose
//! flag is the app's, turns its own flag off while the collider's contacts are quiet (so that
//! rapier recycles them as it does without stickslip) and off again on detach or surface
//! removal.

use crate::state::StickSlipRapier;
use bevy::prelude::*;
use bevy_rapier::plugin::context::{DefaultRapierContext, RapierContextColliders};
use bevy_rapier::prelude::*;
use bevy_rapier::rapier::geometry::{ColliderHandle, ColliderSet};
use stickslip_bevy::{StickSlipFriction, StickSlipVibration, SurfaceVelocity};

/// Whether a collider lives in the default context (the one stickslip brackets).
fn in_default(link: Option<&RapierContextEntityLink>, default: Entity) -> bool {
    link.is_none_or(|l| l.0 == default)
}

/// Tells the modifier whether the app's `ActiveHooks` component has the hook flag of `h` (an
/// attached collider or a moving surface): the modifier owns the answer.
fn declare_app_flag(
    state: &mut StickSlipRapier,
    colliders: &mut ColliderSet,
    h: ColliderHandle,
    app: Option<&ActiveHooks>,
) {
    let apps = app.is_some_and(|f| f.contains(ActiveHooks::MODIFY_SOLVER_CONTACTS));
    state.modifier.set_user_hook_flag(colliders, h, apps);
}

/// Attaches marked colliders once bevy_rapier made them (and again with a changed material).
#[allow(clippy::type_complexity)]
pub(crate) fn attach(
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
    mut context: Query<(Entity, &mut RapierContextColliders), With<DefaultRapierContext>>,
) {
    let Ok((default, mut colliders)) = context.single_mut() else {
        return;
    };
    let state = &mut *state;
    if !state.active {
        return;
    }
    let colliders = &mut colliders.bypass_change_detection().colliders;
    for (entity, friction, handle, hooks, link) in &marked {
        if !in_default(link, default) {
            continue;
        }
        // A new collider of the same entity (its `Collider` replaced): the old one goes.
        if let Some(&old) = state.attached.get(&entity)
            && old != handle.0
        {
            state.attached.remove(&entity);
            state.modifier.detach(colliders, old);
        }
        state
            .modifier
            .attach(colliders, handle.0, friction.0.clone());
        state.attached.insert(entity, handle.0);
        declare_app_flag(state, colliders, handle.0, hooks);
    }
}

/// Vibration sources onto the colliders' contacts.
#[allow(clippy::type_complexity)]
pub(crate) fn sync_vibrations(
    mut state: ResMut<StickSlipRapier>,
    changed: Query<
        (
            Entity,
            &StickSlipVibration,
            &RapierColliderHandle,
            Option<&RapierContextEntityLink>,
        ),
        Or<(Changed<StickSlipVibration>, Added<RapierColliderHandle>)>,
    >,
    context: Query<Entity, With<DefaultRapierContext>>,
) {
    let Ok(default) = context.single() else {
        return;
    };
    for (entity, v, h, link) in &changed {
        if in_default(link, default) {
            state.modifier.set_vibration(h.0, v.0.clone());
            state.vibrating.insert(entity, h.0);
        }
    }
}

/// Surface velocities onto the modifier (which applies them on every pair of the default
/// context and keeps what they carry awake), and the hook flag on their colliders.
#[allow(clippy::type_complexity)]
pub(crate) fn sync_surfaces(
    mut state: ResMut<StickSlipRapier>,
    changed: Query<
        (
            Entity,
            &SurfaceVelocity,
            &RapierColliderHandle,
            Option<&ActiveHooks>,
            Option<&RapierContextEntityLink>,
        ),
        Or<(Changed<SurfaceVelocity>, Added<RapierColliderHandle>)>,
    >,
    mut context: Query<(Entity, &mut RapierContextColliders), With<DefaultRapierContext>>,
) {
    let Ok((default, mut colliders)) = context.single_mut() else {
        return;
    };
    let state = &mut *state;
    // Without the bracketed step (see the startup error) bevy_rapier's own step knows no
    // surfaces.
    if !state.active {
        return;
    }
    let colliders = &mut colliders.bypass_change_detection().colliders;
    for (entity, v, h, hooks, link) in &changed {
        if in_default(link, default) {
            // The shared component is 3D; a 2D surface moves in the plane (z dropped).
            #[cfg(dim2)]
            let v = v.0.truncate();
            #[cfg(not(dim2))]
            let v = v.0;
            state.modifier.set_surface_velocity(colliders, h.0, v);
            state.surface_entities.insert(entity, h.0);
            declare_app_flag(state, colliders, h.0, hooks);
        }
    }
}

/// After bevy_rapier wrote a changed `ActiveHooks` component into rapier's collider: the flag
/// back on for stickslip's colliders, and whose it is now.
#[allow(clippy::type_complexity)]
pub(crate) fn follow_app_hooks(
    mut state: ResMut<StickSlipRapier>,
    changed: Query<(Entity, &ActiveHooks, &RapierColliderHandle), Changed<ActiveHooks>>,
    mut context: Query<&mut RapierContextColliders, With<DefaultRapierContext>>,
) {
    let Ok(mut colliders) = context.single_mut() else {
        return;
    };
    let state = &mut *state;
    let colliders = &mut colliders.bypass_change_detection().colliders;
    for (entity, hooks, h) in &changed {
        if state.attached.get(&entity) == Some(&h.0)
            || state.surface_entities.get(&entity) == Some(&h.0)
        {
            declare_app_flag(state, colliders, h.0, Some(hooks));
        }
    }
}

/// Removed components and despawned entities: at the head of the physics chain (before a
/// collider made this frame could reuse a removed one's index) and in `PostUpdate` before
/// bevy_rapier removes the colliders (bevy forgets removals after two frames; the physics may
/// not run in between). Each runs with its own reader; the state is keyed by entity, so the
/// second sight of a removal finds nothing left to do. An entity that has the component again
/// on the same collider (removed and inserted again) stays.
#[allow(clippy::type_complexity)]
pub(crate) fn removals(
    mut state: ResMut<StickSlipRapier>,
    mut friction: RemovedComponents<StickSlipFriction>,
    mut vibration: RemovedComponents<StickSlipVibration>,
    mut surface: RemovedComponents<SurfaceVelocity>,
    mut collider: RemovedComponents<Collider>,
    present: Query<(
        Option<&RapierColliderHandle>,
        Has<StickSlipFriction>,
        Has<StickSlipVibration>,
        Has<SurfaceVelocity>,
    )>,
    mut context: Query<&mut RapierContextColliders, With<DefaultRapierContext>>,
) {
    let state = &mut *state;
    let mut scratch = ColliderSet::new();
    let mut context = context.single_mut().ok();
    let colliders = match context.as_mut() {
        Some(c) => &mut c.bypass_change_detection().colliders,
        // No default context any more: only the bookkeeping goes.
        None => &mut scratch,
    };
    // Whether `entity` still has the component (per `which`) on collider `h`.
    let kept = |entity: Entity, h: ColliderHandle, which: usize| {
        present
            .get(entity)
            .is_ok_and(|(handle, f, v, s)| handle.is_some_and(|c| c.0 == h) && [f, v, s][which])
    };
    let collider: Vec<Entity> = collider.read().collect();
    let removed: Vec<Entity> = friction.read().chain(collider.iter().copied()).collect();
    for entity in removed {
        if let Some(&h) = state.attached.get(&entity)
            && !kept(entity, h, 0)
        {
            state.attached.remove(&entity);
            state.modifier.detach(colliders, h);
        }
    }
    let removed: Vec<Entity> = vibration.read().chain(collider.iter().copied()).collect();
    for entity in removed {
        if let Some(&h) = state.vibrating.get(&entity)
            && !kept(entity, h, 1)
        {
            state.vibrating.remove(&entity);
            state.modifier.remove_vibration(h);
        }
    }
    let removed: Vec<Entity> = surface.read().chain(collider.iter().copied()).collect();
    for entity in removed {
        if let Some(&h) = state.surface_entities.get(&entity)
            && !kept(entity, h, 2)
        {
            state.surface_entities.remove(&entity);
            state.modifier.remove_surface_velocity(colliders, h);
        }
    }
}
