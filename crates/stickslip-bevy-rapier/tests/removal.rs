//! Removing stickslip's components (or despawning their entities) leaves no stickslip state
//! behind. Invariants: removing `StickSlipFriction` from both sides of a resting contact
//! detaches both colliders (no material, no contact state) and their pair goes back to
//! rapier's own friction; removing `StickSlipVibration` drops the collider's vibration source,
//! and so does despawning a vibrating entity (its rapier handle may be reused by the next
//! collider, which must not inherit the source). With the physics in `FixedUpdate` at 60 Hz
//! and frames of 1 ms (a fixed tick every ~17 frames), a removal made between two ticks is
//! still seen: bevy forgets removals after two frames, so stickslip reads them in
//! `PostUpdate`, beside bevy_rapier's own.

mod common;
use bevy::prelude::*;
use bevy_rapier3d::prelude::*;
use common::*;
use stickslip_bevy_rapier::{StickSlipFriction, StickSlipRapier, StickSlipVibration};
use stickslip_core::waveform::Waveform;
use stickslip_rapier_035::{Amplitude, VibrationDirection, VibrationMode, VibrationSource};

const DT: f64 = 1.0 / 60.0;

fn fixed() -> TimestepMode {
    TimestepMode::Fixed {
        dt: DT as f32,
        substeps: 1,
    }
}

fn shaker() -> StickSlipVibration {
    StickSlipVibration(
        VibrationSource::new(
            VibrationDirection::Normal,
            Amplitude::Ratio(0.5),
            1000.0,
            Waveform::Sine,
            0.0,
            VibrationMode::Averaged,
        )
        .unwrap(),
    )
}

fn handle(app: &App, e: Entity) -> bevy_rapier3d::rapier::geometry::ColliderHandle {
    app.world().get::<RapierColliderHandle>(e).unwrap().0
}

#[test]
fn removing_the_friction_component_detaches_both_sides() {
    let mut app = app(fixed(), DT);
    let law = ep(1e5, 0.5, 0.5);
    let g = ground(&mut app, law.clone());
    let b = part(&mut app, 0.0, law);
    steps(&mut app, 10);
    {
        let state = app.world().resource::<StickSlipRapier>();
        assert!(state.is_attached(g) && state.is_attached(b));
        assert_eq!(state.modifier().active_contacts(), 1);
    }
    let (hg, hb) = (handle(&app, g), handle(&app, b));
    for e in [g, b] {
        app.world_mut().entity_mut(e).remove::<StickSlipFriction>();
    }
    steps(&mut app, 3);
    let state = app.world().resource::<StickSlipRapier>();
    assert!(!state.is_attached(g) && !state.is_attached(b));
    assert_eq!(state.attached_count(), 0);
    assert!(!state.modifier().is_attached(hg) && !state.modifier().is_attached(hb));
    assert!(state.modifier().material(hg).is_none() && state.modifier().material(hb).is_none());
    assert_eq!(
        state.modifier().active_contacts(),
        0,
        "contact state left behind"
    );
}

#[test]
fn removing_or_despawning_a_vibration_drops_its_source() {
    let mut app = app(fixed(), DT);
    let law = ep(1e5, 0.5, 0.5);
    let g = ground(&mut app, law.clone());
    app.world_mut().entity_mut(g).insert(shaker());
    // A second vibrating collider, not under stickslip's friction.
    let plate = app
        .world_mut()
        .spawn((
            RigidBody::Fixed,
            Collider::cuboid(1.0, 0.1, 1.0),
            Transform::from_xyz(0.0, -5.0, 0.0),
            shaker(),
        ))
        .id();
    steps(&mut app, 3);
    let (hg, hp) = (handle(&app, g), handle(&app, plate));
    {
        let state = app.world().resource::<StickSlipRapier>();
        assert!(state.modifier().vibration(hg).is_some());
        assert!(state.modifier().vibration(hp).is_some());
    }
    app.world_mut().entity_mut(g).remove::<StickSlipVibration>();
    app.world_mut().despawn(plate);
    steps(&mut app, 3);
    let state = app.world().resource::<StickSlipRapier>();
    assert!(
        state.modifier().vibration(hg).is_none(),
        "removed source kept"
    );
    assert!(
        state.modifier().vibration(hp).is_none(),
        "despawned source kept"
    );
    assert!(state.is_attached(g), "the friction stays attached");
}

#[test]
fn removals_between_fixed_ticks_are_not_missed() {
    use bevy::time::TimeUpdateStrategy;
    use std::time::Duration;
    let mut app = App::new();
    app.add_plugins((MinimalPlugins, TransformPlugin))
        .insert_resource(Time::<Fixed>::from_hz(60.0))
        .insert_resource(fixed())
        .insert_resource(TimeUpdateStrategy::ManualDuration(Duration::from_millis(1)))
        .add_plugins(RapierPhysicsPlugin::<NoUserData>::default().in_fixed_schedule())
        .add_plugins(stickslip_bevy_rapier::StickSlipRapierPlugin::default().in_fixed_schedule());
    app.update();
    let law = ep(1e5, 0.5, 0.5);
    let g = ground(&mut app, law.clone());
    let b = part(&mut app, 0.0, law);
    steps(&mut app, 300);
    let clock = |app: &App| app.world().resource::<StickSlipRapier>().modifier().time();
    // Remove right after a fixed tick: the next one is ~17 frames away.
    let t = clock(&app);
    while clock(&app) == t {
        app.update();
    }
    {
        let state = app.world_mut().resource_mut::<StickSlipRapier>();
        assert!(state.is_attached(g) && state.is_attached(b));
    }
    let hb = handle(&app, b);
    for e in [g, b] {
        app.world_mut().entity_mut(e).remove::<StickSlipFriction>();
    }
    steps(&mut app, 60);
    let state = app.world().resource::<StickSlipRapier>();
    assert!(clock_moved(t, state.modifier().time()), "no fixed tick ran");
    assert_eq!(state.attached_count(), 0, "a removal was missed");
    assert!(!state.modifier().is_attached(hb));
    assert_eq!(
        state.modifier().active_contacts(),
        0,
        "contact state left behind"
    );
}

fn clock_moved(before: f64, now: f64) -> bool {
    now > before + 2.0 * DT - 1e-9
}
