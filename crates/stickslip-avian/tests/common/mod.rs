//! Headless avian apps for the tests: `MinimalPlugins`, avian's `PhysicsPlugins` in its
//! default schedule (`FixedPostUpdate`) at 60 Hz, one physics tick per `app.update()`.
//!
//! The same tests run in 2D (stickslip-avian2d links some of them, cfg `dim2`): the helpers
//! take and give 3D vectors (z dropped and z = 0 in 2D) and make the 2D shapes of the 3D
//! ones (a cuboid's x-y rectangle).
#![allow(dead_code)]

#[cfg(not(dim2))]
pub use ::stickslip_avian;
#[cfg(dim2)]
pub use avian2d as avian;
#[cfg(not(dim2))]
pub use avian3d as avian;
#[cfg(dim2)]
pub use stickslip_avian2d as stickslip_avian;

use avian::math::Vector;
use avian::prelude::*;
use bevy::prelude::*;
use bevy::time::TimeUpdateStrategy;
use bevy::transform::TransformPlugin;
use std::time::Duration;
use stickslip_avian::StickSlipAvianPlugin;

/// avian's vector from 3D components (2D: z dropped).
pub fn v(x: f32, y: f32, z: f32) -> Vector {
    #[cfg(not(dim2))]
    {
        Vec3::new(x, y, z)
    }
    #[cfg(dim2)]
    {
        let _ = z;
        Vec2::new(x, y)
    }
}

/// avian's vector in 3D (2D: z = 0).
pub fn lift(v: Vector) -> Vec3 {
    #[cfg(not(dim2))]
    {
        v
    }
    #[cfg(dim2)]
    {
        v.extend(0.0)
    }
}

/// A cuboid collider of full lengths x, y, z (2D: the x-y rectangle).
pub fn cuboid_collider(x: f32, y: f32, z: f32) -> Collider {
    #[cfg(not(dim2))]
    {
        Collider::cuboid(x, y, z)
    }
    #[cfg(dim2)]
    {
        let _ = z;
        Collider::rectangle(x, y)
    }
}

/// A constant force (N, 3D components; 2D: z dropped).
pub fn constant_force(f: Vec3) -> ConstantForce {
    ConstantForce(v(f.x, f.y, f.z))
}

/// Gravity (3D components; 2D: z dropped).
pub fn gravity(g: Vec3) -> Gravity {
    Gravity(v(g.x, g.y, g.z))
}

/// A linear velocity (3D components; 2D: z dropped).
pub fn linear_velocity(l: Vec3) -> LinearVelocity {
    LinearVelocity(v(l.x, l.y, l.z))
}

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
            cuboid_collider(400.0, 0.2, 20.0),
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
            cuboid_collider(0.5, 0.5, 0.5),
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
    app.world()
        .get::<Position>(e)
        .map_or(Vec3::NAN, |p| lift(p.0))
}

/// The body's linear velocity.
pub fn velocity(app: &App, e: Entity) -> Vec3 {
    app.world()
        .get::<LinearVelocity>(e)
        .map_or(Vec3::NAN, |v| lift(v.0))
}

/// Gravity tilted by `theta` about z (a slope of angle θ under a level floor).
pub fn tilted_gravity(theta: f64) -> Gravity {
    gravity(Vec3::new(
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
            cuboid_collider(size.x, size.y, size.z),
            Transform::from_translation(at),
            SleepingDisabled,
            extra,
        ))
        .id()
}

/// The body's rotation (2D: about z).
pub fn rotation(app: &App, e: Entity) -> Quat {
    #[cfg(not(dim2))]
    let q = app.world().get::<Rotation>(e).map_or(Quat::NAN, |r| r.0);
    #[cfg(dim2)]
    let q = app
        .world()
        .get::<Rotation>(e)
        .map_or(Quat::NAN, |r| Quat::from_rotation_z(r.as_radians()));
    q
}

/// A sled of `mass` kg (1 m × 0.2 m × 1 m, rotation locked, never sleeping) on the floor,
/// pressed onto it by a constant force of `press` N: with gravity off, its normal force.
pub fn sled(app: &mut App, mass: f64, press: f64, extra: impl Bundle) -> Entity {
    app.world_mut()
        .spawn((
            RigidBody::Dynamic,
            cuboid_collider(0.5, 0.1, 0.5),
            Mass(mass as f32),
            Transform::from_xyz(0.0, 0.05, 0.0),
            LockedAxes::ROTATION_LOCKED,
            SleepingDisabled,
            constant_force(Vec3::new(0.0, -press as f32, 0.0)),
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
        .insert(linear_velocity(Vec3::new(v as f32, vy, 0.0)));
    app.update();
}

/// An angular velocity (3D components; 2D: the rate about z).
pub fn angular_velocity(w: Vec3) -> AngularVelocity {
    #[cfg(not(dim2))]
    {
        AngularVelocity(w)
    }
    #[cfg(dim2)]
    {
        AngularVelocity(w.z)
    }
}

/// A ball collider (2D: a disc).
pub fn ball_collider(radius: f32) -> Collider {
    #[cfg(not(dim2))]
    {
        Collider::sphere(radius)
    }
    #[cfg(dim2)]
    {
        Collider::circle(radius)
    }
}

/// The body's local y axis in the world.
pub fn up_of(rotation: &Rotation) -> Vector {
    #[cfg(not(dim2))]
    {
        rotation.0 * Vec3::Y
    }
    #[cfg(dim2)]
    {
        *rotation * Vec2::Y
    }
}
