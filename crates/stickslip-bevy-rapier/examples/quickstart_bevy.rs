//! Quick start (README) for bevy_rapier3d: a box on a slope of tan θ = 0.45 in a bevy_rapier
//! app, with stickslip's elasto-plastic law (static 0.5, kinetic 0.4) on the floor and the box.
//! bevy_rapier alone, with one coefficient 0.4, lets it slide; with stickslip it holds.
//! Headless (2 s of simulation, then it prints where the box is); the windowed examples are
//! `vibrating_conveyor` and `bevy_elliptical_drive`.
//!
//! `cargo run --release -p stickslip-bevy-rapier --example quickstart_bevy`
use bevy::prelude::*;
use bevy::time::TimeUpdateStrategy;
use bevy_rapier3d::prelude::*;
use std::time::Duration;
use stickslip_bevy_rapier::core::law::{EpParams, Law};
use stickslip_bevy_rapier::core::sliding_curve::Curve;
use stickslip_bevy_rapier::{FrictionMaterial, StickSlipFriction, StickSlipRapierPlugin};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    // c = 1e4 /m, break-away μ_ba 0.5, μ_max 0.55, sliding at 0.4.
    let law = Law::try_from(EpParams {
        stiffness: 1e4,
        static_coefficient: 0.5,
        peak_coefficient: 0.55,
        sliding: Curve::constant(0.4)?,
    })?;
    let mut app = App::new();
    app.add_plugins((MinimalPlugins, TransformPlugin))
        // 60 Hz physics, one frame a step (a game would keep its own timing).
        .insert_resource(TimestepMode::Fixed {
            dt: 1.0 / 60.0,
            substeps: 1,
        })
        .insert_resource(TimeUpdateStrategy::ManualDuration(Duration::from_secs_f64(
            1.0 / 60.0,
        )))
        .add_plugins(RapierPhysicsPlugin::<NoUserData>::default())
        .add_plugins(StickSlipRapierPlugin::new(FrictionMaterial::new(law)))
        .add_systems(Startup, setup);
    for _ in 0..120 {
        app.update();
    }
    let mut boxes = app
        .world_mut()
        .query_filtered::<&Transform, With<RigidBody>>();
    for transform in boxes.iter(app.world()) {
        println!(
            "the box is at x = {:.3} mm after 2 s",
            transform.translation.x * 1e3
        );
    }
    Ok(())
}

/// A level floor under gravity tilted to tan θ = 0.45 and a 0.4 m box resting on it, both
/// with stickslip's friction (the plugin's material).
fn setup(mut commands: Commands, mut config: Query<&mut RapierConfiguration>) {
    let theta = 0.45f32.atan();
    for mut config in &mut config {
        config.gravity = Vec3::new(theta.sin(), -theta.cos(), 0.0) * 9.81;
    }
    commands.spawn((Collider::cuboid(20.0, 0.1, 2.0), StickSlipFriction(None)));
    commands.spawn((
        RigidBody::Dynamic,
        Collider::cuboid(0.2, 0.2, 0.2),
        Transform::from_xyz(0.0, 0.3, 0.0),
        StickSlipFriction(None),
    ));
}
