//! Quick start (README) for avian3d: a box on a slope of tan θ = 0.45 with avian's own
//! `Friction::new(0.4).with_static_coefficient(0.5)`. avian alone reads only the dynamic
//! coefficient and lets the box slide; with `StickSlipAvianPlugin` the static coefficient is
//! real and the box holds, without the creep of avian's own hold at μ 0.5. Headless: 2 s of
//! simulation, then it prints how far the box went.
//!
//! `cargo run --release -p stickslip-avian --example quickstart_avian`
use avian3d::prelude::*;
use bevy::prelude::*;
use bevy::time::TimeUpdateStrategy;
use std::time::Duration;
use stickslip_avian::StickSlipAvianPlugin;

fn main() {
    let theta = 0.45f32.atan();
    let mut app = App::new();
    app.add_plugins((MinimalPlugins, TransformPlugin, PhysicsPlugins::default()))
        .add_plugins(StickSlipAvianPlugin::default())
        // A level floor under gravity tilted to tan θ = 0.45, at 60 Hz (one frame a tick).
        .insert_resource(Gravity(Vec3::new(theta.sin(), -theta.cos(), 0.0) * 9.81))
        .insert_resource(Time::<Fixed>::from_hz(60.0))
        .insert_resource(TimeUpdateStrategy::ManualDuration(Duration::from_secs_f64(
            1.0 / 60.0,
        )))
        .add_systems(Startup, setup);
    // What `App::run` does before its first update.
    app.finish();
    app.cleanup();
    // Where the box is after half a second (its contact formed) and after two.
    let mut at = [0.0; 2];
    for step in 1..=120 {
        app.update();
        if step == 30 || step == 120 {
            let mut bodies = app.world_mut().query::<(&RigidBody, &Transform)>();
            for (body, transform) in bodies.iter(app.world()) {
                if *body == RigidBody::Dynamic {
                    at[usize::from(step == 120)] = transform.translation.x;
                }
            }
        }
    }
    println!(
        "avian with stickslip: the box moved {:.3} mm while its contact formed (0.5 s), \
         then {:.3} mm in 1.5 s",
        at[0] * 1e3,
        (at[1] - at[0]) * 1e3
    );
}

/// The floor and a 0.4 m box resting on it (avian's cuboids take full lengths), both with
/// static friction 0.5 above dynamic friction 0.4.
fn setup(mut commands: Commands) {
    let friction = Friction::new(0.4).with_static_coefficient(0.5);
    commands.spawn((
        RigidBody::Static,
        Collider::cuboid(40.0, 0.2, 4.0),
        friction,
    ));
    commands.spawn((
        RigidBody::Dynamic,
        Collider::cuboid(0.4, 0.4, 0.4),
        Transform::from_xyz(0.0, 0.3, 0.0),
        friction,
    ));
}
