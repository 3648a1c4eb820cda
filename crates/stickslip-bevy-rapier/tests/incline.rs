//! stickslip as an add-on to bevy_rapier's `RapierPhysicsPlugin`, headless: a box on an
//! elasto-plastic ground (gravity tilted to a slope tan θ), both marked `StickSlipFriction`,
//! in a bevy_rapier app with `TimestepMode::Fixed`. Invariants: below break-away (tan θ =
//! 0.9 μ_ba) the box moves no more than the law's elastic range g_ba = μ_ba/c over 5 s once
//! the contact formed; above it (tan θ = 1.2 μ_ba, μ_k = 0.4 < μ_ba) it slides at
//! g (sin θ − μ_k cos θ) within 2 % — friction plain rapier cannot give (it has one
//! coefficient); a timestep mode that runs several rapier steps a frame (`Interpolated`) is
//! refused at startup: stickslip stays off.

use bevy::prelude::*;
use bevy_rapier3d::prelude::*;
use stickslip_bevy_rapier::{
    StickSlipFriction, StickSlipHooks, StickSlipRapier, StickSlipRapierPlugin,
};
use stickslip_core::law::Law;
use stickslip_core::sliding_curve::Curve;
use stickslip_rapier_035::FrictionMaterial;

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
        .add_plugins(RapierPhysicsPlugin::<StickSlipHooks>::default())
        .add_plugins(StickSlipRapierPlugin {
            default_material: material(mu_k),
            ..default()
        });
    app.update();
    let th = tan.atan();
    let g = Vec3::new((9.81 * th.sin()) as f32, -(9.81 * th.cos()) as f32, 0.0);
    let mut q = app.world_mut().query::<&mut RapierConfiguration>();
    for mut c in q.iter_mut(app.world_mut()) {
        c.gravity = g;
    }
    app.world_mut().spawn((
        RigidBody::Fixed,
        Collider::cuboid(50.0, 0.1, 5.0),
        Transform::from_xyz(0.0, -0.1, 0.0),
        StickSlipFriction(None),
    ));
    let b = app
        .world_mut()
        .spawn((
            RigidBody::Dynamic,
            Collider::cuboid(0.1, 0.1, 0.1),
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

#[test]
fn holds_below_break_away() {
    let (mut app, b) = app(FIXED, 0.9 * MU_BA, 0.4);
    steps(&mut app, 5);
    let (x0, _) = x_v(&app, b);
    steps(&mut app, 300);
    let (x1, v1) = x_v(&app, b);
    let g_ba = MU_BA / C;
    println!(
        "moved {:.3e} m over 5 s (g_ba {g_ba:.1e}), v {v1:.1e}",
        x1 - x0
    );
    assert!((x1 - x0).abs() <= g_ba, "moved {} m", x1 - x0);
    let mut state = app.world_mut().resource_mut::<StickSlipRapier>();
    assert_eq!(state.modifier.active_contacts(), 1);
}

#[test]
fn slides_above_break_away_at_the_kinetic_acceleration() {
    let tan = 1.2 * MU_BA;
    let (mut app, b) = app(FIXED, tan, 0.4);
    steps(&mut app, 60);
    let (_, v1) = x_v(&app, b);
    steps(&mut app, 120);
    let (_, v2) = x_v(&app, b);
    let a = (v2 - v1) / (120.0 * DT as f64);
    let th = tan.atan();
    let expect = 9.81 * (th.sin() - 0.4 * th.cos());
    println!("acceleration {a:.4} m/s², expected {expect:.4}");
    assert!(((a - expect) / expect).abs() < 0.02, "{a} vs {expect}");
}

#[test]
fn interpolated_mode_is_refused() {
    let mode = TimestepMode::Interpolated {
        dt: DT,
        time_scale: 1.0,
        substeps: 1,
    };
    let (mut app, _) = app(mode, 0.0, 0.4);
    steps(&mut app, 3);
    assert!(!app.world().resource::<StickSlipRapier>().active);
}

#[test]
fn substeps_are_refused() {
    let mode = TimestepMode::Fixed {
        dt: DT,
        substeps: 2,
    };
    let (mut app, _) = app(mode, 0.0, 0.4);
    steps(&mut app, 3);
    assert!(!app.world().resource::<StickSlipRapier>().active);
}

#[test]
fn despawning_leaves_no_state() {
    let (mut app, b) = app(FIXED, 0.0, 0.4);
    steps(&mut app, 10);
    assert_eq!(
        app.world_mut()
            .resource_mut::<StickSlipRapier>()
            .modifier
            .active_contacts(),
        1
    );
    app.world_mut().despawn(b);
    steps(&mut app, 2);
    let mut state = app.world_mut().resource_mut::<StickSlipRapier>();
    assert_eq!(
        state.modifier.active_contacts(),
        0,
        "contact state left behind"
    );
    assert!(
        !state.is_attached(b),
        "the despawned collider is still attached"
    );
}
