//! Shared setup of the headless tests (not a test itself).
#![allow(dead_code)]

use bevy::prelude::*;
use bevy::time::TimeUpdateStrategy;
use stickslip_bevy::prelude::*;
use stickslip_core::sliding_curve::Curve;

/// Physics rate of the tests (Hz).
pub const HZ: f64 = 120.0;

/// A headless app: `MinimalPlugins`, the stickslip plugins, one fixed step per update.
pub fn app() -> App {
    let mut app = App::new();
    app.add_plugins((MinimalPlugins, StickSlipPlugins::default()))
        .insert_resource(Time::<Fixed>::from_hz(HZ))
        .insert_resource(TimeUpdateStrategy::FixedTimesteps(1));
    app.update(); // the first update has no time step
    app
}

/// Runs `n` fixed steps.
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
pub fn incline(tan: f64) -> Gravity {
    let theta = tan.atan();
    let g = 9.81;
    Gravity(Vec3::new(
        (g * theta.sin()) as f32,
        -(g * theta.cos()) as f32,
        0.0,
    ))
}

/// A fixed ground (top face at y = 0.1) with friction `law`.
pub fn ground(app: &mut App, law: FrictionMaterial) -> Entity {
    app.world_mut()
        .spawn((
            RigidBody::Fixed,
            Collider::cuboid(50.0, 0.1, 5.0),
            FrictionLaw::new(law),
        ))
        .id()
}

/// A 8 kg box (half extent 0.1 m) resting on the ground at x.
pub fn part(app: &mut App, x: f32) -> Entity {
    app.world_mut()
        .spawn((
            RigidBody::Dynamic,
            Collider::cuboid(0.1, 0.1, 0.1),
            LockRotations,
            Transform::from_xyz(x, 0.2, 0.0),
        ))
        .id()
}

/// Simulated time of the physics (s).
pub fn sim_time(app: &App) -> f64 {
    app.world().resource::<StickSlipWorld>().friction.time()
}

/// Rapier bodies and colliders in the world.
pub fn rapier_counts(app: &App) -> (usize, usize) {
    let w = app.world().resource::<StickSlipWorld>();
    (w.physics.bodies.len(), w.physics.colliders.len())
}

/// Position and velocity of an entity along x.
pub fn x_v(app: &App, e: Entity) -> (f64, f64) {
    let t = app.world().get::<Transform>(e).unwrap().translation.x as f64;
    let v = app.world().get::<Velocity>(e).unwrap().linear.x as f64;
    (t, v)
}
