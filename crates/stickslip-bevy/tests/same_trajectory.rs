//! The plugin adds nothing to the physics: a box pushed across an elasto-plastic ground,
//! stepped through the bevy plugin and directly through stickslip-rapier (same objects in the
//! same handle order, same step), follows the same trajectory bit for bit: the plugin only
//! copies values between the ECS and rapier (glam conversions by value are exact) and steps
//! with `StickSlip::step`, so nothing may differ.

mod common;
use bevy::prelude::*;
use common::*;
use rapier3d::prelude as rp;
use stickslip_bevy::convert::to_rapier;
use stickslip_bevy::prelude::*;
use stickslip_bevy::{RapierBody, RapierCollider, SurfaceHooks};
use stickslip_rapier::StickSlip;

#[test]
fn plugin_and_direct_rapier_agree_bit_for_bit() {
    let law = ep(1e5, 0.5, 0.4);
    let push = Vec3::new(45.0, 0.0, 0.0); // above break-away (0.5 · 78.5 N) after a while
    let mut app = app();
    let g = ground(&mut app, law.clone());
    let b = part(&mut app, 0.0);
    steps(&mut app, 1);
    app.world_mut().entity_mut(b).insert(ExternalForce {
        force: push,
        torque: Vec3::ZERO,
    });
    let mut plugin = Vec::new();
    for _ in 0..240 {
        steps(&mut app, 1);
        plugin.push(app.world().get::<Transform>(b).unwrap().translation);
    }
    let ground_body = app.world().get::<RapierBody>(g).unwrap().0;
    let part_body = app.world().get::<RapierBody>(b).unwrap().0;
    let ground_col = app.world().get::<RapierCollider>(g).unwrap().0;
    let part_col = app.world().get::<RapierCollider>(b).unwrap().0;

    // Direct: the same objects, inserted in the plugin's handle order.
    let mut world = rp::PhysicsWorld::default();
    let mut friction = StickSlip::with_hooks(law.clone(), SurfaceHooks::default());
    let mut bodies = [(ground_body, true), (part_body, false)];
    bodies.sort_by_key(|(h, _)| h.0.into_raw_parts().0);
    for (h, fixed) in bodies {
        // As the plugin builds them: bodies never sleep unless `AllowSleep` says so.
        let builder = if fixed {
            rp::RigidBodyBuilder::fixed().can_sleep(false)
        } else {
            rp::RigidBodyBuilder::dynamic()
                .translation(rp::Vector::new(0.0, 0.2, 0.0))
                .lock_rotations()
                .can_sleep(false)
        };
        assert_eq!(world.insert_body(builder), h);
    }
    let mut cols = [
        (ground_col, ground_body, 50.0f32, 0.1, 5.0),
        (part_col, part_body, 0.1, 0.1, 0.1),
    ];
    cols.sort_by_key(|(h, ..)| h.0.into_raw_parts().0);
    for (h, body, hx, hy, hz) in cols {
        let builder = rp::ColliderBuilder::cuboid(hx, hy, hz)
            .friction(0.5)
            .density(1000.0);
        assert_eq!(world.insert_collider(builder, Some(body)), h);
    }
    friction.attach(&mut world.colliders, ground_col, Some(law));
    world.gravity = to_rapier(Gravity::default().0);
    world.integration_parameters.dt = Time::<Fixed>::from_hz(HZ).timestep().as_secs_f32();
    let mut direct = Vec::new();
    for k in 0..241 {
        if k == 1 {
            world.bodies[part_body].add_force(to_rapier(push), true);
        }
        friction.step(&mut world);
        if k >= 1 {
            direct.push(world.bodies[part_body].translation());
        }
    }
    let moved = plugin.last().unwrap().x;
    assert!(
        moved > 0.05,
        "the push should slide the box, it moved {moved}"
    );
    for (k, (p, d)) in plugin.iter().zip(&direct).enumerate() {
        assert_eq!(p.to_array(), d.to_array(), "step {k}");
    }
}
