//! Quick start in 2D (README): a box on a slope of tan θ = 0.45, with plain rapier2d friction at
//! μ 0.4 and with stickslip's elasto-plastic law, static 0.5 and kinetic 0.4.
//! Plain rapier has one coefficient, so the box slides; stickslip's holds it (0.45 is below
//! its break-away coefficient) until something pushes it past 0.5.
//!
//! `cargo run --release -p stickslip-rapier2d --example quickstart_2d`
use stickslip_rapier2d::prelude::*;
use stickslip_rapier2d::rapier::prelude::*;

/// A level floor under gravity tilted to tan θ = 0.45 (a slope) and a 0.4 m square resting on it.
fn slope(
    friction: f32,
) -> (
    PhysicsWorld,
    ColliderHandle,
    RigidBodyHandle,
    ColliderHandle,
) {
    let mut world = PhysicsWorld::default();
    let theta = 0.45f32.atan();
    world.gravity = Vector::new(theta.sin(), -theta.cos()) * 9.81;
    let floor = world.insert_collider(ColliderBuilder::cuboid(20.0, 0.1).friction(friction), None);
    let (body, part) = world.insert(
        RigidBodyBuilder::dynamic().translation(Vector::new(0.0, 0.3)),
        ColliderBuilder::cuboid(0.2, 0.2).friction(friction),
    );
    (world, floor, body, part)
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    // Plain rapier: one friction coefficient, 0.4.
    let (mut plain, _, body, _) = slope(0.4);
    for _ in 0..120 {
        plain.step();
    }
    let slid = plain.bodies[body].translation().x;
    println!("plain rapier, μ 0.4:        the box slid {slid:.3} m in 2 s");

    // stickslip: c = 1e4 /m, break-away μ_ba 0.5, μ_max 0.55, sliding at 0.4.
    let law = Law::try_from(EpParams {
        stiffness: 1e4,
        static_coefficient: 0.5,
        peak_coefficient: 0.55,
        sliding: Curve::constant(0.4)?,
    })?;
    let mut friction = StickSlip::new(FrictionMaterial::new(law));
    let (mut world, floor, body, part) = slope(0.4);
    friction.attach(&mut world.colliders, floor, None);
    friction.attach(&mut world.colliders, part, None);
    let mut formed = 0.0;
    for step in 1..=120 {
        friction.step(&mut world); // instead of world.step()
        if step == 30 {
            formed = world.bodies[body].translation().x;
        }
    }
    let held = world.bodies[body].translation().x - formed;
    println!(
        "stickslip, μ_s 0.5, μ_k 0.4: the box moved {:.3} mm while its contact formed (0.5 s), \
         then {:.3} µm in 1.5 s",
        formed * 1e3,
        held * 1e6
    );
    Ok(())
}
