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
    friction: Option<&'static Friction>,
    combine: Option<&'static FrictionCombine>,
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
    hierarchy: (Query<&Transform>, Query<&ChildOf>, Query<&Children>),
) {
    let (transforms, parents, descendants) = hierarchy;
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
        // Colliders created before their body (fixed until now, or on an outer body) move
        // onto it: its own, and those anywhere below it.
        let own = std::iter::once(entity);
        let below = children.map(|_| descendants.iter_descendants(entity));
        for e in own.chain(below.into_iter().flatten()) {
            if w.remove_collider(e) {
                adopted.push(e);
            }
        }
    }
    for c in new_colliders
        .iter()
        .chain(all_colliders.iter_many(&adopted))
    {
        let h = insert_collider(w, &c, &transforms, &parents);
        // (Re)inserted handles tell the friction layer to attach the collider's law.
        commands.entity(c.entity).insert(RapierCollider(h));
    }
}

/// The nearest ancestor of `entity` with a rapier body, and `entity`'s pose relative to it
/// (the `Transform`s composed along the way); `None` with the pose in the world when no
/// ancestor has a body.
fn body_ancestor(
    w: &StickSlipWorld,
    entity: Entity,
    transforms: &Query<&Transform>,
    parents: &Query<&ChildOf>,
) -> (Option<rp::RigidBodyHandle>, Transform) {
    let mut pose = transforms.get(entity).copied().unwrap_or_default();
    let mut at = entity;
    // Bounded by the hierarchy's depth (bevy forbids cycles).
    while let Ok(parent) = parents.get(at) {
        at = parent.parent();
        if let Some(body) = w.body(at) {
            return (Some(body), pose);
        }
        let step = transforms.get(at).copied().unwrap_or_default();
        pose = step.mul_transform(pose);
    }
    (None, pose)
}

fn insert_collider(
    w: &mut StickSlipWorld,
    c: &ColliderDataItem,
    transforms: &Query<&Transform>,
    parents: &Query<&ChildOf>,
) -> rp::ColliderHandle {
    let builder = rp::ColliderBuilder::new(c.collider.shape.clone())
        .friction(c.friction.map_or(0.5, |f| f.0))
        .friction_combine_rule(c.combine.copied().unwrap_or_default().rapier_rule())
        .restitution(c.restitution.map_or(0.0, |r| r.0));
    // A mass wins over a density (rapier keeps one of the two).
    let builder = match (c.mass, c.density) {
        (Some(m), _) => builder.mass(m.0),
        (None, d) => builder.density(d.map_or(1000.0, |d| d.0)),
    };
    if let Some(own) = w.body(c.entity) {
        return w.insert_collider(c.entity, builder, Some(own));
    }
    // Below a body at any depth: the Transforms down from the body are the offset; below no
    // body: a fixed collider where the whole hierarchy puts it.
    let (body, pose) = body_ancestor(w, c.entity, transforms, parents);
    w.insert_collider(c.entity, builder.position(pose_of(&pose)), body)
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
            (Option<&Friction>, Option<&FrictionCombine>),
            Option<&Restitution>,
            Option<&ColliderMass>,
            Option<&Density>,
        ),
        Or<(
            Changed<Friction>,
            Changed<FrictionCombine>,
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
    for (h, (friction, combine), restitution, mass, density) in &surfaces {
        if let Some(c) = w.physics.colliders.get_mut(h.0) {
            c.set_friction(friction.map_or(0.5, |f| f.0));
            c.set_friction_combine_rule(combine.copied().unwrap_or_default().rapier_rule());
            c.set_restitution(restitution.map_or(0.0, |r| r.0));
            match (mass, density) {
                (Some(m), _) => c.set_mass(m.0),
                (None, d) => c.set_density(d.map_or(1000.0, |d| d.0)),
            }
        }
    }
}
