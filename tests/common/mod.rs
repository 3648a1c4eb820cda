//! Shared scene builders for the rapier integration tests.
#![allow(dead_code)]

use rapier3d::prelude::*;

/// A fixed ground slab and a resting box, gravity tilted by `theta` about z so the slope
/// runs along +x. Returns (world, box body, ground collider).
pub fn incline(theta: f64, half: f32) -> (PhysicsWorld, RigidBodyHandle, ColliderHandle) {
    let mut world = PhysicsWorld::default();
    let g = 9.81f32;
    world.gravity = Vector::new(g * (theta.sin() as f32), -g * (theta.cos() as f32), 0.0);
    let ground = world.insert_collider(ColliderBuilder::cuboid(50.0, 0.1, 5.0).friction(0.0), None);
    let (body, _) = world.insert(
        RigidBodyBuilder::dynamic()
            .translation(Vector::new(0.0, 0.1 + half, 0.0))
            .can_sleep(false),
        ColliderBuilder::cuboid(half, half, half)
            .density(1000.0)
            .friction(0.0),
    );
    (world, body, ground)
}

/// x-position of a body.
pub fn x_of(world: &PhysicsWorld, body: RigidBodyHandle) -> f64 {
    world.bodies[body].translation().x as f64
}
