//! Rolling resistance (`FrictionMaterial::with_rolling`) in a bevy_rapier app, headless, with
//! elasto-plastic resistance laws (c = 1e4 /m of rolled arc, a sharp band at μ_r) on the
//! `StickSlipFriction` of a ball and its ground. Invariants, against closed forms at μ_r 0.01
//! and 0.05, in bevy_rapier's Fixed mode with 1 and 2 substeps: a ball rolled at v0 across a
//! level floor stops after v0² / (2 k μ_r g) within 2 % (k = 5/7 for a solid ball, 2/3 for a
//! disc in 2D); on a slope below μ_r (tan θ = 0.8 μ_r) it holds, moving less than the laws'
//! elastic ranges (μ_r/c + tan θ/c) over 5 s once formed, and the modifier's rolling reports give
//! the torque of statics, R m g sin θ, within 2 %; above μ_r (tan θ = 2 μ_r) it rolls down at
//! k g (sin θ − μ_r cos θ) within 2 %; spun at 10 rad/s about the normal (3D, spinning
//! resistance μ_spin) it stops after I ω0 / (μ_spin R m g) within 2 %; a resistance that breaks away at 0.05 and
//! rolls at 0.03 brakes a rolled ball at 0.03 (the closed form within 2 %) and holds one put on
//! a slope between the two; the same ball without rolling resistance
//! keeps rolling (the resistance is off unless a material asks for it); a resisting ball
//! despawned while it rolls leaves no joint and no read-back behind.

mod common;

use bevy::prelude::*;
use common::bevy_rapier::prelude::*;
use common::stickslip_bevy_rapier::{StickSlipFriction, StickSlipRapier};
use common::stickslip_rapier::FrictionMaterial;
use common::*;
use stickslip_core::law::Law;
use stickslip_core::sliding_curve::Curve;

const G: f64 = 9.81;
const C: f64 = 1e4;
const R: f32 = 0.1;
const DT: f64 = 1.0 / 60.0;
/// m / (m + I/R²) of the roller: a solid ball 5/7, a disc (2D) 2/3.
const ROLL: f64 = if cfg!(dim2) { 2.0 / 3.0 } else { 5.0 / 7.0 };

fn sharp(mu: f64) -> Law {
    Law::elasto_plastic(C, mu, mu, Curve::constant(mu).unwrap()).unwrap()
}

/// Friction 0.5 and, above 0, rolling resistance `mu_r`.
fn material(mu_r: f64) -> FrictionMaterial {
    let m = FrictionMaterial::new(sharp(0.5));
    if mu_r > 0.0 {
        m.with_rolling(sharp(mu_r))
    } else {
        m
    }
}

/// A ball of radius [`R`] resting on the common ground (top at y = 0.1), both with
/// `material(mu_r)`, gravity tilted to `tan`. It never sleeps (rapier puts a slowly rolling
/// ball to sleep within half a second).
fn scene(substeps: usize, tan: f64, mu_r: f64) -> (App, Entity) {
    scene_with(substeps, tan, material(mu_r))
}

/// As [`scene`], both with `material`.
fn scene_with(substeps: usize, tan: f64, material: FrictionMaterial) -> (App, Entity) {
    let mut app = app(
        TimestepMode::Fixed {
            dt: DT as f32,
            substeps,
        },
        DT,
    );
    incline(&mut app, tan);
    ground(&mut app, material.clone());
    let ball = app
        .world_mut()
        .spawn((
            RigidBody::Dynamic,
            Collider::ball(R),
            ColliderMassProperties::Density(1000.0),
            Velocity::zero(),
            Sleeping::disabled(),
            Transform::from_xyz(0.0, 0.1 + R, 0.0),
            StickSlipFriction(Some(material)),
        ))
        .id();
    (app, ball)
}

/// Rolls the ball along +x at `v` without slipping.
fn roll(app: &mut App, ball: Entity, v: f32) {
    let mut vel = app.world_mut().get_mut::<Velocity>(ball).unwrap();
    vel.linear = vect(v, 0.0, 0.0);
    #[cfg(not(dim2))]
    {
        vel.angular = Vec3::new(0.0, 0.0, -v / R);
    }
    #[cfg(dim2)]
    {
        vel.angular = -v / R;
    }
}

/// The resisting pairs after the last step: the modifier's reports, from the default
/// context's joints.
fn rolling_reports(app: &mut App) -> Vec<common::stickslip_rapier::RollingReport> {
    let mut q = app
        .world_mut()
        .query::<&bevy_rapier::plugin::context::RapierContextJoints>();
    let world = app.world();
    let joints = q.single(world).expect("one rapier context");
    world
        .resource::<StickSlipRapier>()
        .modifier()
        .rolling_reports(&joints.impulse_joints)
}

fn run_for(app: &mut App, secs: f64) {
    steps(app, (secs / DT).round() as usize);
}

#[test]
fn a_rolled_ball_stops_at_the_closed_form_distance() {
    for substeps in [1, 2] {
        for mu_r in [0.01, 0.05] {
            let v0 = 0.5;
            let (mut app, ball) = scene(substeps, 0.0, mu_r);
            run_for(&mut app, 0.25);
            roll(&mut app, ball, v0 as f32);
            let (x0, _) = x_v(&app, ball);
            run_for(&mut app, 1.5 * v0 / (ROLL * mu_r * G));
            let (x, v) = x_v(&app, ball);
            let expected = v0 * v0 / (2.0 * ROLL * mu_r * G);
            let error = (x - x0) / expected - 1.0;
            println!(
                "{substeps} substeps, μ_r {mu_r}: stopped after {:.4} m, closed form {expected:.4} m ({:+.2} %), v {v:.1e}",
                x - x0,
                error * 100.0
            );
            assert!(
                error.abs() < 0.02,
                "{substeps} substeps μ_r {mu_r}: {} m",
                x - x0
            );
            assert!(v.abs() < 1e-3, "still rolling at {v} m/s");
        }
    }
}

#[test]
fn a_ball_below_its_rolling_resistance_holds_on_a_slope() {
    for substeps in [1, 2] {
        for mu_r in [0.01, 0.05] {
            let tan = 0.8 * mu_r;
            let (mut app, ball) = scene(substeps, tan, mu_r);
            run_for(&mut app, 0.5);
            let (x0, _) = x_v(&app, ball);
            run_for(&mut app, 5.0);
            let moved = (x_v(&app, ball).0 - x0).abs();
            let range = mu_r / C + tan / C;
            let reports = rolling_reports(&mut app);
            assert_eq!(reports.len(), 1, "one resisting pair");
            let torque = Vec3::from(reports[0].rolling_torque).length() as f64;
            // The ball's mass at density 1000: a solid ball, a disc in 2D.
            let r = R as f64;
            let mass = if cfg!(dim2) {
                1000.0 * std::f64::consts::PI * r * r
            } else {
                1000.0 * 4.0 / 3.0 * std::f64::consts::PI * r.powi(3)
            };
            let statics = r * mass * G * tan.atan().sin();
            println!(
                "{substeps} substeps, μ_r {mu_r}, tan θ {tan}: moved {:.3} µm in 5 s (range {:.3} µm), torque {torque:.5} N·m (statics {statics:.5})",
                moved * 1e6,
                range * 1e6
            );
            assert!(moved < range, "moved {moved} m (range {range} m)");
            assert!(
                (torque / statics - 1.0).abs() < 0.02,
                "torque {torque} N·m, statics {statics}"
            );
        }
    }
}

#[test]
fn a_resistance_with_break_away_above_its_rolling_level_rolls_at_the_rolling_level() {
    let law = Law::elasto_plastic(C, 0.05, 0.05, Curve::constant(0.03).unwrap()).unwrap();
    let stribeck = FrictionMaterial::new(sharp(0.5)).with_rolling(law);
    for substeps in [1, 2] {
        let v0 = 0.5;
        let (mut app, ball) = scene_with(substeps, 0.0, stribeck.clone());
        run_for(&mut app, 0.25);
        roll(&mut app, ball, v0 as f32);
        let (x0, _) = x_v(&app, ball);
        run_for(&mut app, 1.5 * v0 / (ROLL * 0.03 * G));
        let (x, _) = x_v(&app, ball);
        let expected = v0 * v0 / (2.0 * ROLL * 0.03 * G);
        let error = (x - x0) / expected - 1.0;
        println!(
            "{substeps} substeps: stopped after {:.4} m, closed form at μ_k {expected:.4} m ({:+.2} %)",
            x - x0,
            error * 100.0
        );
        assert!(error.abs() < 0.02, "{substeps} substeps: {} m", x - x0);

        let tan = 0.04;
        let (mut app, ball) = scene_with(substeps, tan, stribeck.clone());
        run_for(&mut app, 0.5);
        let (x0, _) = x_v(&app, ball);
        run_for(&mut app, 5.0);
        let moved = (x_v(&app, ball).0 - x0).abs();
        let range = 0.05 / C + tan / C;
        println!(
            "{substeps} substeps, tan θ {tan}: moved {:.3} µm in 5 s",
            moved * 1e6
        );
        assert!(moved < range, "moved {moved} m (range {range} m)");
    }
}

#[test]
fn without_rolling_resistance_the_ball_keeps_rolling() {
    let (mut app, ball) = scene(1, 0.0, 0.0);
    run_for(&mut app, 0.25);
    roll(&mut app, ball, 0.5);
    run_for(&mut app, 5.0);
    let (_, v) = x_v(&app, ball);
    assert!(v > 0.495, "{v} m/s");
}

/// stickslip's joints live in bevy_rapier's joint set without entities: a resisting ball
/// despawned while it rolls takes its joint along (rapier removes a body's joints), and the
/// app steps on.
#[test]
fn a_despawned_rolling_ball_leaves_no_joint() {
    let joints = |app: &mut App| {
        let mut q = app
            .world_mut()
            .query::<&bevy_rapier::plugin::context::RapierContextJoints>();
        q.iter(app.world())
            .map(|j| j.impulse_joints.len())
            .sum::<usize>()
    };
    let (mut app, ball) = scene(1, 0.0, 0.05);
    run_for(&mut app, 0.25);
    roll(&mut app, ball, 0.5);
    run_for(&mut app, 0.25);
    assert_eq!(
        joints(&mut app),
        1,
        "the rolling ball resists through one joint"
    );
    assert_eq!(rolling_reports(&mut app).len(), 1);
    app.world_mut().despawn(ball);
    run_for(&mut app, 0.5);
    assert_eq!(joints(&mut app), 0);
    assert!(rolling_reports(&mut app).is_empty());
}

/// Above its rolling resistance (tan θ = 2 μ_r) a ball rolls down at k g (sin θ − μ_r cos θ)
/// within 2 %.
#[test]
fn above_its_rolling_resistance_a_ball_rolls_down_at_the_closed_form_acceleration() {
    for substeps in [1, 2] {
        for mu_r in [0.01f64, 0.05] {
            let tan = 2.0 * mu_r;
            let theta = tan.atan();
            let (mut app, ball) = scene(substeps, tan, mu_r);
            run_for(&mut app, 0.25);
            let (_, v0) = x_v(&app, ball);
            run_for(&mut app, 1.0);
            let a = x_v(&app, ball).1 - v0;
            let expected = ROLL * G * (theta.sin() - mu_r * theta.cos());
            let error = a / expected - 1.0;
            println!(
                "{substeps} substeps, μ_r {mu_r}, tan θ {tan}: a {a:.5} m/s², closed form {expected:.5} ({:+.2} %)",
                error * 100.0
            );
            assert!(
                error.abs() < 0.02,
                "{substeps} substeps μ_r {mu_r}: {a} m/s²"
            );
        }
    }
}

/// A solid ball spun at ω0 about the normal (3D) stops after I ω0 / (μ_spin R m g) (the arm of
/// a single point is R) within 2 %.
#[cfg(not(dim2))]
#[test]
fn a_spinning_ball_stops_after_the_closed_form_time() {
    for substeps in [1, 2] {
        for mu_spin in [0.01f64, 0.05] {
            let w0 = 10.0;
            let material = FrictionMaterial::new(sharp(0.5)).with_spinning(sharp(mu_spin));
            let (mut app, ball) = scene_with(substeps, 0.0, material);
            run_for(&mut app, 0.25);
            app.world_mut().get_mut::<Velocity>(ball).unwrap().angular =
                Vec3::new(0.0, w0 as f32, 0.0);
            let expected = 0.4 * R as f64 * w0 / (mu_spin * G);
            let spin = |app: &App| app.world().get::<Velocity>(ball).unwrap().angular.y as f64;
            let (mut ticks, mut before) = (0, w0);
            while spin(&app) > 1e-3 * w0 {
                before = spin(&app);
                app.update();
                ticks += 1;
                assert!(ticks as f64 * DT < 2.0 * expected, "still spinning");
            }
            // The spin falls linearly: where its last tick's line crosses zero.
            let last = before / (before - spin(&app));
            let stopped = (ticks as f64 - 1.0 + last.min(1.0)) * DT;
            let error = stopped / expected - 1.0;
            println!(
                "{substeps} substeps, μ_spin {mu_spin}: stopped after {stopped:.4} s, closed form {expected:.4} s ({:+.2} %)",
                error * 100.0
            );
            assert!(error.abs() < 0.02, "{stopped} s");
        }
    }
}
