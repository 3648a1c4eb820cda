//! The physics world resource and the systems that mirror entities into it: creation of
//! bodies and colliders, the friction layer's components, removal observers.

use crate::components::*;
use crate::convert::{pose_of, to_rapier};
use crate::hooks::SurfaceHooks;
use bevy::prelude::*;
use rapier3d::prelude as rp;
use std::collections::HashMap;
use stickslip_rapier::{FrictionMaterial, StickSlip};

/// One rapier world and the stickslip modifier stepping it.
#[derive(Resource)]
pub struct StickSlipWorld {
    /// The rapier world (bodies, colliders, narrow phase, integration parameters).
    pub physics: rp::PhysicsWorld,
    /// The friction modifier (materials, vibration sources, contact states, reports).
    pub friction: StickSlip<SurfaceHooks>,
    pub(crate) bodies: HashMap<Entity, rp::RigidBodyHandle>,
    pub(crate) colliders: HashMap<Entity, rp::ColliderHandle>,
}

impl StickSlipWorld {
    /// A world whose stickslip contacts default to `material`.
    pub fn new(material: FrictionMaterial) -> Self {
        StickSlipWorld {
            physics: rp::PhysicsWorld::default(),
            friction: StickSlip::with_hooks(material, SurfaceHooks::default()),
            bodies: HashMap::new(),
            colliders: HashMap::new(),
        }
    }

    /// The rapier body of `entity`.
    pub fn body(&self, entity: Entity) -> Option<rp::RigidBodyHandle> {
        self.bodies.get(&entity).copied()
    }

    /// The rapier collider of `entity`.
    pub fn collider(&self, entity: Entity) -> Option<rp::ColliderHandle> {
        self.colliders.get(&entity).copied()
    }

    /// The entity a rapier collider belongs to.
    pub fn collider_entity(&self, handle: rp::ColliderHandle) -> Option<Entity> {
        self.physics
            .colliders
            .get(handle)
            .and_then(|c| Entity::try_from_bits(c.user_data as u64))
    }

    /// Takes a collider out of rapier and stickslip.
    fn remove_collider(&mut self, entity: Entity) {
        if let Some(h) = self.colliders.remove(&entity) {
            self.friction.detach(&mut self.physics.colliders, h);
            self.friction.inner_mut().surfaces.remove(&h);
            self.physics.remove_collider(h);
        }
    }
}

/// The stickslip material new `FrictionLaw(None)` colliders get.
#[derive(Resource, Debug, Clone)]
pub struct DefaultFriction(pub FrictionMaterial);

/// Creates rapier bodies for new `RigidBody` entities, then colliders for new `Collider`
/// entities (on the entity's own body, on its parent's, or fixed).
#[allow(clippy::type_complexity)]
pub(crate) fn create_objects(
    mut commands: Commands,
    mut w: ResMut<StickSlipWorld>,
    defaults: Res<DefaultFriction>,
    bodies: Query<
        (
            Entity,
            &RigidBody,
            &Transform,
            &Velocity,
            Has<LockRotations>,
            Has<AllowSleep>,
        ),
        Without<RapierBody>,
    >,
    colliders: Query<
        (
            Entity,
            &Collider,
            &Transform,
            Option<&ChildOf>,
            Option<&Friction>,
            Option<&Density>,
            (
                Option<&FrictionLaw>,
                Option<&Vibration>,
                Option<&SurfaceVelocity>,
            ),
        ),
        Without<RapierCollider>,
    >,
) {
    let w = &mut *w;
    for (entity, kind, transform, velocity, locked, sleepy) in &bodies {
        let body_type = match kind {
            RigidBody::Dynamic => rp::RigidBodyType::Dynamic,
            RigidBody::Fixed => rp::RigidBodyType::Fixed,
            RigidBody::KinematicPositionBased => rp::RigidBodyType::KinematicPositionBased,
            RigidBody::KinematicVelocityBased => rp::RigidBodyType::KinematicVelocityBased,
        };
        let mut builder = rp::RigidBodyBuilder::new(body_type)
            .pose(pose_of(transform))
            .linvel(to_rapier(velocity.linear))
            .angvel(to_rapier(velocity.angular))
            .user_data(entity.to_bits() as u128)
            .can_sleep(sleepy);
        if locked {
            builder = builder.lock_rotations();
        }
        let h = w.physics.insert_body(builder);
        w.bodies.insert(entity, h);
        commands.entity(entity).insert(RapierBody(h));
    }
    for (entity, collider, transform, parent, friction, density, (law, vibration, surface)) in
        &colliders
    {
        let own = w.bodies.get(&entity).copied();
        let of_parent = parent.and_then(|p| w.bodies.get(&p.parent()).copied());
        let builder = rp::ColliderBuilder::new(collider.shape.clone())
            .friction(friction.map_or(0.5, |f| f.0))
            .density(density.map_or(1000.0, |d| d.0))
            .user_data(entity.to_bits() as u128);
        let h = match (own, of_parent) {
            (Some(b), _) => w.physics.insert_collider(builder, Some(b)),
            (None, Some(b)) => w
                .physics
                .insert_collider(builder.position(pose_of(transform)), Some(b)),
            (None, None) => w
                .physics
                .insert_collider(builder.position(pose_of(transform)), None),
        };
        w.colliders.insert(entity, h);
        commands.entity(entity).insert(RapierCollider(h));
        if let Some(law) = law {
            let material = law.0.clone().unwrap_or_else(|| defaults.0.clone());
            w.friction
                .attach(&mut w.physics.colliders, h, Some(material));
        }
        if let Some(v) = vibration {
            w.friction.set_vibration(h, v.0.clone());
        }
        if let Some(s) = surface {
            set_surface(w, h, s.0, &defaults);
        }
    }
}

fn set_surface(w: &mut StickSlipWorld, h: rp::ColliderHandle, v: Vec3, defaults: &DefaultFriction) {
    // The hooks only run for hooked colliders: a moving surface is a stickslip collider (its
    // own FrictionLaw, or the default material).
    let hooked = w.physics.colliders.get(h).is_some_and(|c| {
        c.active_hooks()
            .contains(rp::ActiveHooks::MODIFY_SOLVER_CONTACTS)
    });
    if !hooked {
        w.friction
            .attach(&mut w.physics.colliders, h, Some(defaults.0.clone()));
    }
    w.friction.inner_mut().surfaces.insert(h, to_rapier(v));
}

/// Applies changes of the friction layer's components on existing colliders.
#[allow(clippy::type_complexity)]
pub(crate) fn sync_friction(
    mut w: ResMut<StickSlipWorld>,
    defaults: Res<DefaultFriction>,
    laws: Query<(Entity, &FrictionLaw), Changed<FrictionLaw>>,
    vibrations: Query<(Entity, &Vibration), Changed<Vibration>>,
    surfaces: Query<(Entity, &SurfaceVelocity), Changed<SurfaceVelocity>>,
) {
    let w = &mut *w;
    for (e, law) in &laws {
        if let Some(h) = w.collider(e) {
            let material = law.0.clone().unwrap_or_else(|| defaults.0.clone());
            w.friction
                .attach(&mut w.physics.colliders, h, Some(material));
        }
    }
    for (e, v) in &vibrations {
        if let Some(h) = w.collider(e) {
            w.friction.set_vibration(h, v.0.clone());
        }
    }
    for (e, s) in &surfaces {
        if let Some(h) = w.collider(e) {
            set_surface(w, h, s.0, &defaults);
        }
    }
}

/// Despawning a body or removing its `RigidBody` removes the rapier body with its colliders.
pub(crate) fn on_remove_body(remove: On<Remove, RigidBody>, mut w: ResMut<StickSlipWorld>) {
    let entity = remove.entity;
    let Some(h) = w.bodies.remove(&entity) else {
        return;
    };
    let attached: Vec<Entity> = w
        .colliders
        .iter()
        .filter(|(_, c)| w.physics.colliders.get(**c).and_then(|c| c.parent()) == Some(h))
        .map(|(e, _)| *e)
        .collect();
    for e in attached {
        w.remove_collider(e);
    }
    w.physics.remove_body(h);
}

/// Despawning a collider or removing its `Collider` removes it from rapier and stickslip.
pub(crate) fn on_remove_collider(remove: On<Remove, Collider>, mut w: ResMut<StickSlipWorld>) {
    w.remove_collider(remove.entity);
}

/// Removing `FrictionLaw` takes the collider back to plain rapier friction.
pub(crate) fn on_remove_friction_law(
    remove: On<Remove, FrictionLaw>,
    mut w: ResMut<StickSlipWorld>,
) {
    let w = &mut *w;
    if let Some(h) = w.collider(remove.entity) {
        w.friction.detach(&mut w.physics.colliders, h);
        w.friction.inner_mut().surfaces.remove(&h);
    }
}

/// Removing `Vibration` stops the collider's vibration.
pub(crate) fn on_remove_vibration(remove: On<Remove, Vibration>, mut w: ResMut<StickSlipWorld>) {
    if let Some(h) = w.collider(remove.entity) {
        w.friction.remove_vibration(h);
    }
}

/// Removing `SurfaceVelocity` stops the surface.
pub(crate) fn on_remove_surface(
    remove: On<Remove, SurfaceVelocity>,
    mut w: ResMut<StickSlipWorld>,
) {
    if let Some(h) = w.collider(remove.entity) {
        w.friction.inner_mut().surfaces.remove(&h);
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
