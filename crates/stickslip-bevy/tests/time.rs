//! Physics time follows bevy's clocks. Invariants: the step is `Time<Fixed>`'s timestep; a
//! paused `Time<Virtual>` runs no physics step (nothing moves, simulated time stands); half
//! relative speed runs half the steps; the plugins also run in another schedule
//! (`StickSlipPlugins::new`), stepping that schedule's delta.

mod common;
use bevy::prelude::*;
use bevy::time::TimeUpdateStrategy;
use common::*;
use std::time::Duration;
use stickslip_bevy::prelude::*;

#[test]
fn pause_and_slow_motion_follow_virtual_time() {
    let mut app = app();
    let p = app
        .world_mut()
        .spawn((
            RigidBody::Dynamic,
            Collider::ball(0.1),
            Transform::from_xyz(0.0, 10.0, 0.0),
        ))
        .id();
    steps(&mut app, 12);
    let dt = app
        .world()
        .resource::<StickSlipWorld>()
        .physics
        .integration_parameters
        .dt;
    assert_eq!(dt, Time::<Fixed>::from_hz(HZ).timestep().as_secs_f32());
    assert!((sim_time(&app) - 0.1).abs() < 1e-6);

    app.world_mut().resource_mut::<Time<Virtual>>().pause();
    let (t, y) = (
        sim_time(&app),
        app.world().get::<Transform>(p).unwrap().translation.y,
    );
    steps(&mut app, 50);
    assert_eq!(sim_time(&app), t, "no step while paused");
    assert_eq!(app.world().get::<Transform>(p).unwrap().translation.y, y);

    app.world_mut().resource_mut::<Time<Virtual>>().unpause();
    app.world_mut()
        .resource_mut::<Time<Virtual>>()
        .set_relative_speed(0.5);
    steps(&mut app, 60);
    let ran = ((sim_time(&app) - t) * HZ).round();
    assert_eq!(ran, 30.0, "half speed: 30 steps in 60 updates");
}

#[test]
fn runs_in_another_schedule_with_its_delta() {
    let mut app = App::new();
    app.add_plugins((MinimalPlugins, StickSlipPlugins::new(Update)))
        .insert_resource(TimeUpdateStrategy::ManualDuration(Duration::from_millis(5)));
    app.update();
    let p = app
        .world_mut()
        .spawn((
            RigidBody::Dynamic,
            Collider::ball(0.1),
            Transform::from_xyz(0.0, 10.0, 0.0),
        ))
        .id();
    steps(&mut app, 200);
    // Free fall for 1 s (200 × 5 ms): y = 10 − g/2 up to the integrator's O(dt) error
    // (≈ 6 mm with rapier's 4 substeps).
    let y = app.world().get::<Transform>(p).unwrap().translation.y as f64;
    let expect = 10.0 - 9.81 / 2.0;
    assert!((sim_time(&app) - 1.0).abs() < 1e-6);
    assert!((y - expect).abs() < 1e-2, "y = {y}, expected {expect}");
}
