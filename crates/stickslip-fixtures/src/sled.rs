//! A sled pressed onto a long fixed plate and dragged over it, in 3D and 2D: the scene of
//! the Stribeck and vibration tests.

use crate::{cuboid3, v3};
use stickslip_core::law::Law;
use stickslip_rapier::rapier::prelude::*;
use stickslip_rapier::{FrictionMaterial, StickSlip};

/// A sled: a box of half-extent `half` and mass `mass`, rotations locked, on a long fixed
/// plate whose top is y = 0.1, gravity off (the test presses it with a force), sleeping off.
pub struct Sled {
    /// The world.
    pub world: PhysicsWorld,
    /// The sled's body.
    pub body: RigidBodyHandle,
    /// The plate's collider.
    pub plate: ColliderHandle,
    /// The sled's collider.
    pub sled: ColliderHandle,
}

impl Sled {
    /// The sled stepped at `dt`, both colliders' rapier friction `friction`.
    pub fn new(half: f32, mass: f32, dt: f64, friction: f32) -> Self {
        Sled::with_order(half, mass, dt, friction, false)
    }

    /// [`Sled::new`], the sled inserted before the plate when `sled_first` (rapier then
    /// lists the sled as the pair's collider 1: the contact normal points down).
    pub fn with_order(half: f32, mass: f32, dt: f64, friction: f32, sled_first: bool) -> Self {
        let mut world = PhysicsWorld {
            gravity: Vector::ZERO,
            ..PhysicsWorld::default()
        };
        world.integration_parameters.dt = dt as f32;
        let plate_builder = cuboid3(500.0, 0.1, 50.0).0.friction(friction);
        let body_builder = RigidBodyBuilder::dynamic()
            .translation(v3(0.0, 0.1 + half, 0.0))
            .lock_rotations()
            .can_sleep(false);
        let (cube, volume) = cuboid3(half, half, half);
        let sled_builder = cube.density(mass / volume).friction(friction);
        let (plate, (body, sled)) = if sled_first {
            let bs = world.insert(body_builder, sled_builder);
            (world.insert_collider(plate_builder, None), bs)
        } else {
            let p = world.insert_collider(plate_builder, None);
            (p, world.insert(body_builder, sled_builder))
        };
        Sled {
            world,
            body,
            plate,
            sled,
        }
    }

    /// stickslip with `law` on both colliders (the pair is the law's alone).
    pub fn attach(&mut self, law: Law) -> StickSlip {
        let mut m = StickSlip::new(FrictionMaterial::new(law));
        m.attach(&mut self.world.colliders, self.plate, None);
        m.attach(&mut self.world.colliders, self.sled, None);
        m
    }

    /// The sled's position along x (m).
    pub fn x(&self) -> f64 {
        self.world.bodies[self.body].translation().x as f64
    }

    /// The sled's velocity along x (m/s).
    pub fn vx(&self) -> f64 {
        self.world.bodies[self.body].linvel().x as f64
    }

    /// The sled's mass (kg).
    pub fn mass(&self) -> f64 {
        self.world.bodies[self.body].mass() as f64
    }

    /// Replaces the user forces on the sled by `force` (N, world).
    pub fn set_force(&mut self, force: Vector) {
        let b = &mut self.world.bodies[self.body];
        b.reset_forces(true);
        b.add_force(force, true);
    }

    /// Imposes the sled's velocity along x (keeping the rest of it).
    pub fn drive(&mut self, vx: f64) {
        let b = &mut self.world.bodies[self.body];
        let mut v = b.linvel();
        v.x = vx as f32;
        b.set_linvel(v, true);
    }
}
