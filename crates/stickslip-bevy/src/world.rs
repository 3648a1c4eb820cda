//! The physics world resource: one rapier world, the stickslip modifier stepping it, and the
//! maps between entities and rapier handles.

use crate::hooks::SurfaceHooks;
use bevy::prelude::*;
use rapier3d::prelude as rp;
use std::collections::HashMap;
use stickslip_rapier::{FrictionMaterial, StickSlip};

/// One rapier world and the stickslip modifier stepping it. Read it for anything the
/// components do not mirror (rapier queries, the modifier's state); change rapier objects the
/// plugin created through their components, not here, or the next sync overwrites you.
#[derive(Resource)]
pub struct StickSlipWorld {
    /// The rapier world (bodies, colliders, narrow phase, integration parameters).
    pub physics: rp::PhysicsWorld,
    /// The friction modifier (materials, vibration sources, contact states, reports), with
    /// the plugin's own hooks (moving surfaces) inside.
    pub friction: StickSlip<SurfaceHooks>,
    bodies: HashMap<Entity, rp::RigidBodyHandle>,
    colliders: HashMap<Entity, rp::ColliderHandle>,
}

impl StickSlipWorld {
    /// A world whose `FrictionLaw(None)` contacts use `material`.
    pub fn new(material: FrictionMaterial) -> Self {
        StickSlipWorld {
            physics: rp::PhysicsWorld::default(),
            friction: StickSlip::with_hooks(material, SurfaceHooks::default())
                .with_read_back(stickslip_rapier::ReadBack::Contacts),
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

    /// The entity of a rapier body (its `user_data` holds the entity's bits).
    pub fn body_entity(&self, handle: rp::RigidBodyHandle) -> Option<Entity> {
        self.physics
            .bodies
            .get(handle)
            .and_then(|b| Entity::try_from_bits(b.user_data as u64))
    }

    /// The entity of a rapier collider (its `user_data` holds the entity's bits).
    pub fn collider_entity(&self, handle: rp::ColliderHandle) -> Option<Entity> {
        self.physics
            .colliders
            .get(handle)
            .and_then(|c| Entity::try_from_bits(c.user_data as u64))
    }

    /// Number of bodies and colliders the plugin created and still holds (entities mapped).
    pub fn counts(&self) -> (usize, usize) {
        (self.bodies.len(), self.colliders.len())
    }

    pub(crate) fn insert_body(&mut self, entity: Entity, body: rp::RigidBodyBuilder) {
        let h = self
            .physics
            .insert_body(body.user_data(entity.to_bits() as u128));
        self.bodies.insert(entity, h);
    }

    pub(crate) fn insert_collider(
        &mut self,
        entity: Entity,
        collider: rp::ColliderBuilder,
        parent: Option<rp::RigidBodyHandle>,
    ) -> rp::ColliderHandle {
        let collider = collider.user_data(entity.to_bits() as u128);
        let h = self.physics.insert_collider(collider, parent);
        self.colliders.insert(entity, h);
        h
    }

    /// Takes a collider out of stickslip (material, vibration, contact states, reports,
    /// surface velocity) and out of rapier.
    pub(crate) fn remove_collider(&mut self, entity: Entity) -> bool {
        let Some(h) = self.colliders.remove(&entity) else {
            return false;
        };
        self.detach(h);
        self.physics.remove_collider(h);
        true
    }

    /// Takes a body out of rapier with every collider on it; returns the colliders' entities.
    pub(crate) fn remove_body(&mut self, entity: Entity) -> Vec<Entity> {
        let Some(h) = self.bodies.remove(&entity) else {
            return Vec::new();
        };
        let attached: Vec<Entity> = self
            .colliders
            .iter()
            .filter(|(_, c)| self.physics.colliders.get(**c).and_then(|c| c.parent()) == Some(h))
            .map(|(e, _)| *e)
            .collect();
        for e in &attached {
            self.remove_collider(*e);
        }
        self.physics.remove_body(h);
        attached
    }

    /// Back to plain rapier friction: `StickSlip::detach` plus the plugin's surface velocity.
    pub(crate) fn detach(&mut self, h: rp::ColliderHandle) {
        self.friction.detach(&mut self.physics.colliders, h);
        self.friction.inner_mut().surfaces.remove(&h);
    }
}
