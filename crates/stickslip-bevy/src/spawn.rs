//! Mirroring entities into rapier: new bodies and colliders, changed body kinds and shapes.

use crate::components::*;
use crate::convert::{pose_of, to_rapier};
use crate::world::StickSlipWorld;
use bevy::ecs::query::QueryData;
use bevy::prelude::*;
use rapier3d::prelude as rp;

/// What a collider is made of.
#[derive(QueryData)]
pub(crate) struct ColliderData {
    entity: Entity,
    collider: &'static Collider,
    transform: &'static Transform,
    parent: Option<&'static ChildOf>,
    friction: Option<&'static Friction>,
    density: Option<&'static Density>,
    mass: Option<&'static ColliderMass>,
    restitution: Option<&'static Restitution>,
}

/// Creates rapier bodies for new `RigidBody` entities, then colliders for new `Collider`
/// entities (on the entity's own body, on its parent's, or fixed). A body that arrives after
/// its colliders takes them over.
#[allow(clippy::type_complexity)]
pub(crate) fn create_objects(
    mut commands: Commands,
    mut w: ResMut<StickSlipWorld>,
    bodies: Query<
        (
            Entity,
            &RigidBody,
            &Transform,
            &Velocity,
            Has<LockRotations>,
            Has<AllowSleep>,
            (Option<&Damping>, Has<Ccd>),
            Option<&Children>,
        ),
        Without<RapierBody>,
    >,
    new_colliders: Query<ColliderData, Without<RapierCollider>>,
    all_colliders: Query<ColliderData>,
    transforms: Query<&Transform>,
) {
    let w = &mut *w;
    let mut adopted = Vec::new();
    for (entity, kind, transform, velocity, locked, sleepy, (damping, ccd), children) in &bodies {
        let damping = damping.copied().unwrap_or_default();
        let mut builder = rp::RigidBodyBuilder::new(kind.rapier_type())
            .pose(pose_of(transform))
            .linvel(to_rapier(velocity.linear))
            .angvel(to_rapier(velocity.angular))
            .linear_damping(damping.linear)
            .angular_damping(damping.angular)
            .ccd_enabled(ccd)
            .can_sleep(sleepy);
        if locked {
            builder = builder.lock_rotations();
        }
        w.insert_body(entity, builder);
        commands
            .entity(entity)
            .insert(RapierBody(w.body(entity).unwrap()));
        // Colliders created before their body (fixed until now) move onto it.
        let own = std::iter::once(entity);
        for e in own.chain(children.into_iter().flatten().copied()) {
            if w.remove_collider(e) {
                adopted.push(e);
            }
        }
    }
    for c in new_colliders
        .iter()
        .chain(all_colliders.iter_many(&adopted))
    {
        let h = insert_collider(w, &c, &transforms);
        // (Re)inserted handles tell the friction layer to attach the collider's law.
        commands.entity(c.entity).insert(RapierCollider(h));
    }
}

fn insert_collider(
    w: &mut StickSlipWorld,
    c: &ColliderDataItem,
    transforms: &Query<&Transform>,
) -> rp::ColliderHandle {
    let builder = rp::ColliderBuilder::new(c.collider.shape.clone())
        .friction(c.friction.map_or(0.5, |f| f.0))
        .restitution(c.restitution.map_or(0.0, |r| r.0));
    // A mass wins over a density (rapier keeps one of the two).
    let builder = match (c.mass, c.density) {
        (Some(m), _) => builder.mass(m.0),
        (None, d) => builder.density(d.map_or(1000.0, |d| d.0)),
    };
    let parent = c.parent.map(ChildOf::parent);
    if let Some(own) = w.body(c.entity) {
        return w.insert_collider(c.entity, builder, Some(own));
    }
    if let Some(body) = parent.and_then(|p| w.body(p)) {
        // A child: its Transform is the offset from the body.
        return w.insert_collider(c.entity, builder.position(pose_of(c.transform)), Some(body));
    }
    // Fixed, where the hierarchy puts it (one level: the parent's Transform).
    let at = match parent.and_then(|p| transforms.get(p).ok()) {
        Some(p) => p.mul_transform(*c.transform),
        None => *c.transform,
    };
    w.insert_collider(c.entity, builder.position(pose_of(&at)), None)
}

/// Applies changed body kinds, damping, shapes and collider materials to existing rapier
/// objects.
#[allow(clippy::type_complexity)]
pub(crate) fn sync_changes(
    mut w: ResMut<StickSlipWorld>,
    kinds: Query<(&RigidBody, &RapierBody), Changed<RigidBody>>,
    damping: Query<(&Damping, &RapierBody), Changed<Damping>>,
    shapes: Query<(&Collider, &RapierCollider), Changed<Collider>>,
    surfaces: Query<
        (
            &RapierCollider,
            Option<&Friction>,
            Option<&Restitution>,
            Option<&ColliderMass>,
            Option<&Density>,
        ),
        Or<(
            Changed<Friction>,
            Changed<Restitution>,
            Changed<ColliderMass>,
            Changed<Density>,
        )>,
    >,
) {
    let w = &mut *w;
    for (kind, h) in &kinds {
        if let Some(b) = w.physics.bodies.get_mut(h.0) {
            b.set_body_type(kind.rapier_type(), true);
        }
    }
    for (d, h) in &damping {
        if let Some(b) = w.physics.bodies.get_mut(h.0) {
            b.set_linear_damping(d.linear);
            b.set_angular_damping(d.angular);
        }
    }
    for (collider, h) in &shapes {
        if let Some(c) = w.physics.colliders.get_mut(h.0) {
            c.set_shape(collider.shape.clone());
        }
    }
    for (h, friction, restitution, mass, density) in &surfaces {
        if let Some(c) = w.physics.colliders.get_mut(h.0) {
            c.set_friction(friction.map_or(0.5, |f| f.0));
            c.set_restitution(restitution.map_or(0.0, |r| r.0));
            match (mass, density) {
                (Some(m), _) => c.set_mass(m.0),
                (None, d) => c.set_density(d.map_or(1000.0, |d| d.0)),
            }
        }
    }
}
