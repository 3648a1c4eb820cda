//! Shared setup of the headless bevy_rapier tests (not a test itself).
//!
//! Some tests run in 2D too (stickslip-bevy-rapier2d links them, cfg `dim2`): the helpers
//! below make bevy_rapier's vectors and shapes from 3D components (z dropped in 2D).
#![allow(dead_code)]

#[cfg(not(dim2))]
pub use ::stickslip_bevy_rapier;
#[cfg(dim2)]
pub use bevy_rapier2d as bevy_rapier;
#[cfg(not(dim2))]
pub use bevy_rapier3d as bevy_rapier;
#[cfg(dim2)]
pub use stickslip_bevy_rapier2d as stickslip_bevy_rapier;
#[cfg(not(dim2))]
pub use stickslip_rapier_035 as stickslip_rapier;
#[cfg(dim2)]
pub use stickslip_rapier2d_035 as stickslip_rapier;

use bevy::prelude::*;
use bevy::time::TimeUpdateStrategy;
use bevy_rapier::prelude::*;
use std::time::Duration;
use stickslip_bevy_rapier::{StickSlipFriction, StickSlipRapier, StickSlipRapierPlugin};
use stickslip_core::law::Law;
use stickslip_core::sliding_curve::Curve;
use stickslip_rapier::FrictionMaterial;

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
    let g = vect(
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
            cuboid(50.0, 0.1, 5.0),
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
            cuboid(0.1, 0.1, 0.1),
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

/// bevy_rapier's vector from 3D components (2D: z dropped).
pub fn vect(x: f32, y: f32, z: f32) -> Vect {
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

/// A cuboid of half-extents x, y, z (2D: the x-y rectangle).
pub fn cuboid(x: f32, y: f32, z: f32) -> Collider {
    #[cfg(not(dim2))]
    {
        Collider::cuboid(x, y, z)
    }
    #[cfg(dim2)]
    {
        let _ = z;
        Collider::cuboid(x, y)
    }
}
