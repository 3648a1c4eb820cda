//! Snapshot and restore: save a running world with its friction state, load it, and the
//! resumed run is bit-identical to the one that went on.
//!
//! `cargo run --release -p stickslip-rapier --example snapshot`
use stickslip_rapier::core::law::{EpParams, Law};
use stickslip_rapier::core::sliding_curve::Curve;
use stickslip_rapier::rapier::prelude::*;
use stickslip_rapier::{FrictionMaterial, StickSlip, WorldSnapshot};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    // A box sliding down a slope of tan θ = 0.6 (above its break-away coefficient 0.5).
    let mut world = PhysicsWorld::default();
    let theta = 0.6f32.atan();
    world.gravity = Vector::new(theta.sin(), -theta.cos(), 0.0) * 9.81;
    let floor = world.insert_collider(ColliderBuilder::cuboid(50.0, 0.1, 2.0), None);
    let (body, part) = world.insert(
        RigidBodyBuilder::dynamic().translation(Vector::new(0.0, 0.3, 0.0)),
        ColliderBuilder::cuboid(0.2, 0.2, 0.2),
    );
    let law = Law::try_from(EpParams {
        stiffness: 1e4,
        static_coefficient: 0.5,
        peak_coefficient: 0.55,
        sliding: Curve::constant(0.4)?,
    })?;
    let mut friction = StickSlip::new(FrictionMaterial::new(law));
    friction.attach(&mut world.colliders, floor, None);
    friction.attach(&mut world.colliders, part, None);
    for _ in 0..60 {
        friction.step(&mut world);
    }

    // Between two steps: the world and the friction state to a file (here a buffer).
    let mut file = Vec::new();
    WorldSnapshot::save_from(&world, &friction, &mut file)?;
    let (mut resumed, mut resumed_friction) = WorldSnapshot::load(file.as_slice())?.restore(())?;

    for _ in 0..60 {
        friction.step(&mut world);
        resumed_friction.step(&mut resumed);
    }
    let (a, b) = (
        world.bodies[body].translation(),
        resumed.bodies[body].translation(),
    );
    println!("snapshot: {} bytes", file.len());
    println!(
        "after 2 s: x = {} m, resumed x = {} m, identical: {}",
        a.x,
        b.x,
        a == b
    );
    Ok(())
}
