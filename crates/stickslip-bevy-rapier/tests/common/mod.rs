//! Shared setup of the headless bevy_rapier tests (not a test itself).
#![allow(dead_code)]

use bevy::prelude::*;
use bevy::time::TimeUpdateStrategy;
use bevy_rapier3d::prelude::*;
use std::time::Duration;
use stickslip_bevy_rapier::{StickSlipFriction, StickSlipRapier, StickSlipRapierPlugin};
use stickslip_core::law::Law;
use stickslip_core::sliding_curve::Curve;
use stickslip_rapier_035::FrictionMaterial;

/// A headless bevy_rapier app with stickslip, in `mode`, each update `frame` seconds of
/// render time (what Variable and Interpolated step by).
pub fn app(mode: TimestepMode, frame: f64) -> App {
    let mut app = App::new();
    app.add_plugins((MinimalPlugins, TransformPlugin))
        .insert_resource(mode)
        .insert_resource(TimeUpdateStrategy::ManualDuration(Duration::from_secs_f64(
            frame,
        )))
        .add_plugins(RapierPhysicsPlugin::<NoUserData>::default())
        .add_plugins(StickSlipRapierPlugin::default());
    app.update(); // contexts exist from here on
    app
}

/// Runs `n` updates.
pub fn steps(app: &mut App, n: usize) {
    for _ in 0..n {
        app.update();
    }
}

/// The elasto-plastic law with break-away `mu_ba` and a flat sliding curve `mu_k`.
pub fn ep(c: f64, mu_ba: f64, mu_k: f64) -> FrictionMaterial {
    let max = mu_ba.max(mu_k);
    FrictionMaterial::new(
        Law::elasto_plastic(c, mu_ba, max, Curve::constant(mu_k).unwrap()).unwrap(),
    )
}

/// Gravity of magnitude g tilted so that the horizontal ground is an incline of slope `tan`
/// (downhill is +x).
pub fn incline(app: &mut App, tan: f64) {
    let theta = tan.atan();
    let g = Vec3::new(
        (9.81 * theta.sin()) as f32,
        -(9.81 * theta.cos()) as f32,
        0.0,
    );
    let mut q = app.world_mut().query::<&mut RapierConfiguration>();
    for mut c in q.iter_mut(app.world_mut()) {
        c.gravity = g;
    }
}

/// A fixed ground (top face at y = 0.1) with friction `law`.
pub fn ground(app: &mut App, law: FrictionMaterial) -> Entity {
    app.world_mut()
        .spawn((
            RigidBody::Fixed,
            Collider::cuboid(50.0, 0.1, 5.0),
            Transform::default(),
            StickSlipFriction(Some(law)),
        ))
        .id()
}

/// An 8 kg box (half extent 0.1 m, rotation locked) resting on the ground at x, with the
/// same law as the ground.
pub fn part(app: &mut App, x: f32, law: FrictionMaterial) -> Entity {
    app.world_mut()
        .spawn((
            RigidBody::Dynamic,
            Collider::cuboid(0.1, 0.1, 0.1),
            ColliderMassProperties::Mass(8.0),
            LockedAxes::ROTATION_LOCKED,
            Velocity::zero(),
            Transform::from_xyz(x, 0.2, 0.0),
            StickSlipFriction(Some(law)),
        ))
        .id()
}

/// Simulated time of the bracketed rapier steps (s): the modifier's clock.
pub fn sim_time(app: &App) -> f64 {
    app.world().resource::<StickSlipRapier>().modifier().time()
}

/// Position and velocity of an entity along x.
pub fn x_v(app: &App, e: Entity) -> (f64, f64) {
    let t = app.world().get::<Transform>(e).unwrap().translation.x as f64;
    let v = app.world().get::<Velocity>(e).unwrap().linear.x as f64;
    (t, v)
}
