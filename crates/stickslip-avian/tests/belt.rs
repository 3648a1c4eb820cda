//! A collider's `SurfaceVelocity` (a conveyor belt) in an avian world. Invariants: a box put
//! down on a belt moving at 1 m/s slips and is accelerated at μ_k g (within 2 %, the closed
//! form of kinetic friction) until it is carried at the belt's speed (within 0.5 %) — with
//! avian's own `Friction` (no static coefficient: avian's Coulomb friction, the surface
//! applied by stickslip), with a static coefficient (stickslip's "Phys") and with an
//! elasto-plastic material; a box asleep on a floor that starts moving is woken and carried.

mod common;

use bevy::prelude::*;
use common::avian::prelude::*;
use common::stickslip_avian::{FrictionMaterial, StickSlipFriction, SurfaceVelocity};
use common::*;
use stickslip_core::law::Law;
use stickslip_core::sliding_curve::Curve;

const BELT: f32 = 1.0;
const MU_K: f32 = 0.4;

/// The box's velocity along x after each of `n` ticks.
fn speeds(app: &mut App, b: Entity, n: usize) -> Vec<f64> {
    (0..n)
        .map(|_| {
            app.update();
            velocity(app, b).x as f64
        })
        .collect()
}

/// (acceleration over the middle third of the run-up, speed after 1 s).
fn run_up(v: &[f64]) -> (f64, f64) {
    // At μ_k g the run-up to 1 m/s takes 1/(μ_k g) s: measure over its middle third.
    let ticks = HZ / (MU_K as f64 * G);
    let (a, b) = ((ticks / 3.0) as usize, (2.0 * ticks / 3.0) as usize);
    ((v[b] - v[a]) * HZ / (b - a) as f64, v[59])
}

fn belt_with(friction: impl Bundle + Clone) -> (f64, f64) {
    let mut app = app(true, 6, 0.0);
    floor(
        &mut app,
        (SurfaceVelocity(Vec3::new(BELT, 0.0, 0.0)), friction.clone()),
    );
    let b = block(&mut app, 0.0, friction);
    let v = speeds(&mut app, b, 60);
    run_up(&v)
}

#[test]
fn a_belt_accelerates_a_box_at_kinetic_friction_and_carries_it() {
    let expected = MU_K as f64 * G;
    let ep = Law::elasto_plastic(0.5e5, 0.6, 0.6, Curve::constant(MU_K as f64).unwrap()).unwrap();
    for (name, (a, v)) in [
        ("avian's Coulomb", belt_with(Friction::new(MU_K))),
        (
            "avian's static coefficient",
            belt_with(Friction::new(MU_K).with_static_coefficient(0.6)),
        ),
        (
            "elasto-plastic",
            belt_with(StickSlipFriction(Some(FrictionMaterial::new(ep)))),
        ),
    ] {
        println!("{name}: a {a:.4} (μ_k g {expected:.4}), carried at {v:.4} m/s");
        assert!(
            (a / expected - 1.0).abs() < 0.02,
            "{name}: a {a} vs μ_k g {expected}"
        );
        assert!(
            (v / BELT as f64 - 1.0).abs() < 0.005,
            "{name}: carried at {v}"
        );
    }
}

#[test]
fn a_floor_that_starts_moving_wakes_what_sleeps_on_it() {
    let mut app = app(true, 6, 0.0);
    let friction = Friction::new(MU_K).with_static_coefficient(0.6);
    let ground = floor(&mut app, friction);
    let b = app
        .world_mut()
        .spawn((
            RigidBody::Dynamic,
            cuboid_collider(0.5, 0.5, 0.5),
            Mass(1.0),
            Transform::from_xyz(0.0, 0.25, 0.0),
            friction,
        ))
        .id();
    run(&mut app, 180);
    assert!(
        app.world().get::<Sleeping>(b).is_some(),
        "the box should have fallen asleep"
    );
    app.world_mut()
        .entity_mut(ground)
        .insert(SurfaceVelocity(Vec3::new(BELT, 0.0, 0.0)));
    let v = speeds(&mut app, b, 60);
    assert!(
        (v[59] / BELT as f64 - 1.0).abs() < 0.005,
        "the sleeping box was not carried: {}",
        v[59]
    );
    // While the belt runs, the box stays awake.
    run(&mut app, 240);
    assert!(app.world().get::<Sleeping>(b).is_none());
    assert!((velocity(&app, b).x / BELT - 1.0).abs() < 0.005);
}
