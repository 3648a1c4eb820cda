//! Headless avian apps for the tests: `MinimalPlugins`, avian's `PhysicsPlugins` in its
//! default schedule (`FixedPostUpdate`) at 60 Hz, one physics tick per `app.update()`.
#![allow(dead_code)]

use avian3d::prelude::*;
use bevy::prelude::*;
use bevy::time::TimeUpdateStrategy;
use bevy::transform::TransformPlugin;
use std::time::Duration;
use stickslip_avian::StickSlipAvianPlugin;

/// The physics rate (Hz).
pub const HZ: f64 = 60.0;
/// Gravity (m/s²).
pub const G: f64 = 9.81;

/// An app with avian (and stickslip unless `plain`), `substeps` solver substeps and gravity
/// tilted by `theta` about z (the floor stays level: a slope of angle θ), at 60 Hz.
pub fn app(stickslip: bool, substeps: u32, theta: f64) -> App {
    app_at(stickslip, HZ, substeps, tilted_gravity(theta))
}

/// An app with avian (and stickslip unless `plain`) at `hz` ticks per second (one per
/// update), `substeps` solver substeps and `gravity`.
pub fn app_at(stickslip: bool, hz: f64, substeps: u32, gravity: Gravity) -> App {
    let mut app = App::new();
    app.add_plugins((MinimalPlugins, TransformPlugin, PhysicsPlugins::default()))
        .insert_resource(Time::<Fixed>::from_hz(hz))
        .insert_resource(TimeUpdateStrategy::ManualDuration(Duration::from_secs_f64(
            1.0 / hz,
        )))
        .insert_resource(SubstepCount(substeps))
        .insert_resource(gravity);
    if stickslip {
        app.add_plugins(StickSlipAvianPlugin::default());
    }
    app.finish();
    app.cleanup();
    // The first update only starts the clocks.
    app.update();
    app
}

/// A static floor, 400 m long (x) and 20 m wide, its top at y = 0.
pub fn floor(app: &mut App, extra: impl Bundle) -> Entity {
    app.world_mut()
        .spawn((
            RigidBody::Static,
            Collider::cuboid(400.0, 0.2, 20.0),
            Transform::from_xyz(0.0, -0.1, 0.0),
            extra,
        ))
        .id()
}

/// A 1 kg box (0.5 m cube) resting on the floor at x.
pub fn block(app: &mut App, x: f32, extra: impl Bundle) -> Entity {
    app.world_mut()
        .spawn((
            RigidBody::Dynamic,
            Collider::cuboid(0.5, 0.5, 0.5),
            Mass(1.0),
            Transform::from_xyz(x, 0.25, 0.0),
            SleepingDisabled,
            extra,
        ))
        .id()
}

/// Runs `n` physics ticks.
pub fn run(app: &mut App, n: usize) {
    for _ in 0..n {
        app.update();
    }
}

/// The body's position.
pub fn position(app: &App, e: Entity) -> Vec3 {
    app.world().get::<Position>(e).map_or(Vec3::NAN, |p| p.0)
}

/// The body's linear velocity.
pub fn velocity(app: &App, e: Entity) -> Vec3 {
    app.world()
        .get::<LinearVelocity>(e)
        .map_or(Vec3::NAN, |v| v.0)
}

/// Gravity tilted by `theta` about z (a slope of angle θ under a level floor).
pub fn tilted_gravity(theta: f64) -> Gravity {
    Gravity(Vec3::new(
        (G * theta.sin()) as f32,
        -(G * theta.cos()) as f32,
        0.0,
    ))
}

/// Tilts the app's gravity to `theta` (the floor becomes a slope of angle θ).
pub fn tilt(app: &mut App, theta: f64) {
    app.insert_resource(tilted_gravity(theta));
}

/// As [`app`], with the app's own collision hooks `H` in avian's plugins
/// (`PhysicsPlugins::default().with_collision_hooks::<H>()`).
pub fn app_with_hooks<H>(stickslip: bool, substeps: u32, theta: f64) -> App
where
    H: CollisionHooks + 'static,
    for<'w, 's> bevy::ecs::system::SystemParamItem<'w, 's, H>: CollisionHooks,
{
    let mut app = App::new();
    app.add_plugins((
        MinimalPlugins,
        TransformPlugin,
        PhysicsPlugins::default().with_collision_hooks::<H>(),
    ))
    .insert_resource(Time::<Fixed>::from_hz(HZ))
    .insert_resource(TimeUpdateStrategy::ManualDuration(Duration::from_secs_f64(
        1.0 / HZ,
    )))
    .insert_resource(SubstepCount(substeps))
    .insert_resource(tilted_gravity(theta));
    if stickslip {
        app.add_plugins(StickSlipAvianPlugin::default());
    }
    app.finish();
    app.cleanup();
    // The first update only starts the clocks.
    app.update();
    app
}

/// A dynamic cuboid (full lengths `size`) at `at`, never sleeping.
pub fn cuboid(app: &mut App, at: Vec3, size: Vec3, extra: impl Bundle) -> Entity {
    app.world_mut()
        .spawn((
            RigidBody::Dynamic,
            Collider::cuboid(size.x, size.y, size.z),
            Transform::from_translation(at),
            SleepingDisabled,
            extra,
        ))
        .id()
}

/// The body's rotation.
pub fn rotation(app: &App, e: Entity) -> Quat {
    app.world().get::<Rotation>(e).map_or(Quat::NAN, |r| r.0)
}

/// A sled of `mass` kg (1 m × 0.2 m × 1 m, rotation locked, never sleeping) on the floor,
/// pressed onto it by a constant force of `press` N: with gravity off, its normal force.
pub fn sled(app: &mut App, mass: f64, press: f64, extra: impl Bundle) -> Entity {
    app.world_mut()
        .spawn((
            RigidBody::Dynamic,
            Collider::cuboid(0.5, 0.1, 0.5),
            Mass(mass as f32),
            Transform::from_xyz(0.0, 0.05, 0.0),
            LockedAxes::ROTATION_LOCKED,
            SleepingDisabled,
            ConstantForce(Vec3::new(0.0, -press as f32, 0.0)),
            extra,
        ))
        .id()
}

/// One tick with the body's velocity along x set to `v` before it (its other components
/// kept): the body is dragged at an imposed speed.
pub fn drag_tick(app: &mut App, e: Entity, v: f64) {
    let vy = velocity(app, e).y;
    app.world_mut()
        .entity_mut(e)
        .insert(LinearVelocity(Vec3::new(v as f32, vy, 0.0)));
    app.update();
}
