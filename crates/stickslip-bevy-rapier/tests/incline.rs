//! stickslip as an add-on to bevy_rapier's `RapierPhysicsPlugin`, headless: a box on an
//! elasto-plastic ground (gravity tilted to a slope tan θ), both marked `StickSlipFriction`,
//! in a bevy_rapier app, in every timestep mode bevy_rapier offers (Fixed, Variable,
//! Interpolated; one substep and several). Invariants, in each mode: every rapier step is
//! bracketed (the modifier's clock equals the simulated time: frames × dt); below break-away
//! (tan θ = 0.9 μ_ba) the box moves no more than the law's elastic range g_ba = μ_ba/c over
//! 5 s once the contact formed; above it (tan θ = 1.2 μ_ba, μ_k = 0.4 < μ_ba) it slides at
//! g (sin θ − μ_k cos θ) within 2 % — friction plain rapier cannot give (it has one
//! coefficient). A stickslip plugin whose hooks type differs from bevy_rapier's is refused at
//! startup (stickslip off, rapier's own friction); despawning leaves no stickslip state.

mod common;

use bevy::prelude::*;
use bevy::time::TimeUpdateStrategy;
use common::bevy_rapier::prelude::*;
use common::stickslip_bevy_rapier::{StickSlipFriction, StickSlipRapier, StickSlipRapierPlugin};
use common::stickslip_rapier::FrictionMaterial;
use common::*;
use std::time::Duration;
use stickslip_core::law::Law;
use stickslip_core::sliding_curve::Curve;

const C: f64 = 1e5;
const MU_BA: f64 = 0.5;
const DT: f32 = 1.0 / 60.0;

fn material(mu_k: f64) -> FrictionMaterial {
    FrictionMaterial::new(
        Law::elasto_plastic(C, MU_BA, MU_BA, Curve::constant(mu_k).unwrap()).unwrap(),
    )
}

fn app(mode: TimestepMode, tan: f64, mu_k: f64) -> (App, Entity) {
    let mut app = App::new();
    app.add_plugins((MinimalPlugins, TransformPlugin))
        .insert_resource(mode)
        // Render frames of exactly dt: Variable and Interpolated then step dt per frame.
        .insert_resource(TimeUpdateStrategy::ManualDuration(Duration::from_secs_f32(
            DT,
        )))
        .add_plugins(RapierPhysicsPlugin::<NoUserData>::default())
        .add_plugins(StickSlipRapierPlugin::new(material(mu_k)));
    app.update();
    let th = tan.atan();
    let g = vect((9.81 * th.sin()) as f32, -(9.81 * th.cos()) as f32, 0.0);
    let mut q = app.world_mut().query::<&mut RapierConfiguration>();
    for mut c in q.iter_mut(app.world_mut()) {
        c.gravity = g;
    }
    app.world_mut().spawn((
        RigidBody::Fixed,
        cuboid(50.0, 0.1, 5.0),
        Transform::from_xyz(0.0, -0.1, 0.0),
        StickSlipFriction(None),
    ));
    let b = app
        .world_mut()
        .spawn((
            RigidBody::Dynamic,
            cuboid(0.1, 0.1, 0.1),
            ColliderMassProperties::Density(1000.0),
            LockedAxes::ROTATION_LOCKED,
            Velocity::zero(),
            Transform::from_xyz(0.0, 0.1, 0.0),
            StickSlipFriction(None),
        ))
        .id();
    (app, b)
}

fn x_v(app: &App, b: Entity) -> (f64, f64) {
    let x = app.world().get::<Transform>(b).unwrap().translation.x as f64;
    let v = app.world().get::<Velocity>(b).unwrap().linear.x as f64;
    (x, v)
}

fn steps(app: &mut App, n: usize) {
    for _ in 0..n {
        app.update();
    }
}

const FIXED: TimestepMode = TimestepMode::Fixed {
    dt: DT,
    substeps: 1,
};

/// Every mode bevy_rapier offers, one substep and several.
const MODES: [TimestepMode; 6] = [
    FIXED,
    TimestepMode::Fixed {
        dt: DT,
        substeps: 4,
    },
    TimestepMode::Variable {
        max_dt: DT,
        time_scale: 1.0,
        substeps: 1,
    },
    TimestepMode::Variable {
        max_dt: DT,
        time_scale: 1.0,
        substeps: 3,
    },
    TimestepMode::Interpolated {
        dt: DT,
        time_scale: 1.0,
        substeps: 1,
    },
    TimestepMode::Interpolated {
        dt: DT,
        time_scale: 1.0,
        substeps: 2,
    },
];

/// The modifier's clock against the simulated time of bevy_rapier's steps.
fn clock(app: &App) -> f64 {
    app.world().resource::<StickSlipRapier>().modifier().time()
}

#[test]
fn every_rapier_step_is_bracketed_in_every_mode() {
    for mode in MODES {
        let (mut app, _) = app(mode, 0.0, 0.4);
        let t0 = clock(&app);
        steps(&mut app, 120);
        let t = clock(&app) - t0;
        println!("{mode:?}: stickslip clock advanced {t:.6} s over 120 frames of {DT:.6} s");
        assert!(app.world().resource::<StickSlipRapier>().is_active());
        // Interpolated may run one round more or less in a frame (float lag), never drifts.
        assert!(
            (t - 120.0 * DT as f64).abs() <= 1.01 * DT as f64,
            "{mode:?}: {t}"
        );
    }
}

#[test]
fn holds_below_break_away_in_every_mode() {
    for mode in MODES {
        let (mut app, b) = app(mode, 0.9 * MU_BA, 0.4);
        steps(&mut app, 5);
        let (x0, _) = x_v(&app, b);
        steps(&mut app, 300);
        let (x1, v1) = x_v(&app, b);
        let g_ba = MU_BA / C;
        println!(
            "{mode:?}: moved {:.3e} m over 5 s (g_ba {g_ba:.1e}), v {v1:.1e}",
            x1 - x0
        );
        assert!((x1 - x0).abs() <= g_ba, "{mode:?}: moved {} m", x1 - x0);
        let state = app.world_mut().resource_mut::<StickSlipRapier>();
        assert_eq!(state.modifier().active_contacts(), 1);
    }
}

#[test]
fn slides_above_break_away_at_the_kinetic_acceleration_in_every_mode() {
    let tan = 1.2 * MU_BA;
    let th = tan.atan();
    let expect = 9.81 * (th.sin() - 0.4 * th.cos());
    for mode in MODES {
        let (mut app, b) = app(mode, tan, 0.4);
        steps(&mut app, 60);
        let (_, v1) = x_v(&app, b);
        let t1 = clock(&app);
        steps(&mut app, 120);
        let (_, v2) = x_v(&app, b);
        let a = (v2 - v1) / (clock(&app) - t1);
        println!("{mode:?}: acceleration {a:.4} m/s², expected {expect:.4}");
        assert!(
            ((a - expect) / expect).abs() < 0.02,
            "{mode:?}: {a} vs {expect}"
        );
    }
}

#[derive(bevy::ecs::system::SystemParam)]
struct OtherHooks<'w> {
    _time: Res<'w, Time>,
}

impl BevyPhysicsHooks for OtherHooks<'_> {}

#[test]
fn a_hooks_type_other_than_bevy_rapiers_is_refused() {
    let mut app = App::new();
    app.add_plugins((MinimalPlugins, TransformPlugin))
        .insert_resource(TimeUpdateStrategy::ManualDuration(Duration::from_secs_f32(
            DT,
        )))
        .add_plugins(RapierPhysicsPlugin::<NoUserData>::default())
        .add_plugins(StickSlipRapierPlugin::default().with_hooks::<OtherHooks>());
    app.update();
    assert!(!app.world().resource::<StickSlipRapier>().is_active());
    // bevy_rapier still steps: a dropped ball falls.
    let ball = app
        .world_mut()
        .spawn((
            RigidBody::Dynamic,
            Collider::ball(0.1),
            Transform::from_xyz(0.0, 1.0, 0.0),
            StickSlipFriction(None),
        ))
        .id();
    steps(&mut app, 30);
    assert!(app.world().get::<Transform>(ball).unwrap().translation.y < 0.99);
    assert!(!app.world().resource::<StickSlipRapier>().is_attached(ball));
}

#[test]
fn despawning_leaves_no_state() {
    let (mut app, b) = app(FIXED, 0.0, 0.4);
    steps(&mut app, 10);
    assert_eq!(
        app.world_mut()
            .resource_mut::<StickSlipRapier>()
            .modifier()
            .active_contacts(),
        1
    );
    app.world_mut().despawn(b);
    steps(&mut app, 2);
    let state = app.world_mut().resource_mut::<StickSlipRapier>();
    assert_eq!(
        state.modifier().active_contacts(),
        0,
        "contact state left behind"
    );
    assert!(
        !state.is_attached(b),
        "the despawned collider is still attached"
    );
}
