//! A collider's surface velocity (`StickSlip::set_surface_velocity`, a conveyor belt).
//! Invariants: a box put down on a belt moving at v_b slips and is accelerated at μ_k g
//! (within 2 %, the closed form of kinetic friction) until it is carried at v_b (within
//! 0.5 %) — under stickslip's elasto-plastic law on an attached belt, and under rapier's own
//! Coulomb friction when nothing is attached (the surface applies on every pair); a box asleep
//! on the belt is woken when it starts; stopping the belt hands an unattached belt's hook
//! flag back and the box comes to rest, and keeps a flag said to be the user's; a snapshot
//! keeps the surface.
//! In 3D and in 2D (stickslip-fixtures2d).

use stickslip_core::law::Law;
use stickslip_core::sliding_curve::Curve;
use stickslip_fixtures::{BoxOnGround, BoxScene, v3};
use stickslip_rapier::rapier::prelude::*;
use stickslip_rapier::{FrictionMaterial, StickSlip};

const G: f64 = 9.81;
const BELT: f32 = 1.0;
const MU_K: f64 = 0.4;

fn scene() -> BoxScene {
    BoxOnGround {
        rotations: false,
        ..BoxOnGround::default()
    }
    .build()
}

fn ep() -> Law {
    Law::elasto_plastic(1e4, 0.5, 0.55, Curve::constant(MU_K).unwrap()).unwrap()
}

/// The box's velocity along x after each of `n` steps.
fn run(scene: &mut BoxScene, m: &mut StickSlip, n: usize) -> Vec<f64> {
    (0..n)
        .map(|_| {
            m.step(&mut scene.world);
            scene.world.bodies[scene.body].linvel().x as f64
        })
        .collect()
}

/// The acceleration over the middle of the run-up (before the box reaches the belt's speed),
/// and the final speed.
fn run_up(scene: &mut BoxScene, m: &mut StickSlip, mu: f64) -> (f64, f64) {
    let v = run(scene, m, 120);
    // At μ g the run-up to 1 m/s takes 1/(μ g) s: measure over its middle third.
    let steps = 60.0 / (mu * G);
    let (a, b) = ((steps / 3.0) as usize, (2.0 * steps / 3.0) as usize);
    ((v[b] - v[a]) / ((b - a) as f64 / 60.0), *v.last().unwrap())
}

#[test]
fn a_belt_accelerates_a_box_at_kinetic_friction_and_carries_it() {
    // Attached: stickslip's law, sliding at μ_k.
    let mut s = scene();
    let mut m = StickSlip::new(FrictionMaterial::new(ep()));
    m.attach(&mut s.world.colliders, s.ground, None);
    m.attach(&mut s.world.colliders, s.box_collider, None);
    m.set_surface_velocity(&mut s.world.colliders, s.ground, v3(BELT, 0.0, 0.0));
    let (a, v) = run_up(&mut s, &mut m, MU_K);
    assert!(
        (a - MU_K * G).abs() < 0.02 * MU_K * G,
        "EP: a = {a}, μ_k g = {}",
        MU_K * G
    );
    assert!((v - BELT as f64).abs() < 0.005, "EP: carried at {v}");

    // Nothing attached: rapier's Coulomb friction (μ 0.5 on both colliders), same belt.
    let mut s = scene();
    let mu = 0.5;
    for (_, c) in s.world.colliders.iter_mut() {
        c.set_friction(mu as f32);
    }
    let mut m = StickSlip::new(FrictionMaterial::new(ep()));
    m.set_surface_velocity(&mut s.world.colliders, s.ground, v3(BELT, 0.0, 0.0));
    let (a, v) = run_up(&mut s, &mut m, mu);
    assert!(
        (a - mu * G).abs() < 0.02 * mu * G,
        "plain: a = {a}, μ g = {}",
        mu * G
    );
    assert!((v - BELT as f64).abs() < 0.005, "plain: carried at {v}");
}

#[test]
fn a_belt_wakes_what_sleeps_on_it_and_stopping_it_hands_the_flag_back() {
    let mut s = scene();
    let mut m = StickSlip::new(FrictionMaterial::new(ep()));
    m.attach(&mut s.world.colliders, s.box_collider, None);
    run(&mut s, &mut m, 30);
    s.world.bodies[s.body].sleep();
    let hooked = |s: &BoxScene| {
        s.world.colliders[s.ground]
            .active_hooks()
            .contains(ActiveHooks::MODIFY_SOLVER_CONTACTS)
    };
    assert!(!hooked(&s));
    m.set_surface_velocity(&mut s.world.colliders, s.ground, v3(BELT, 0.0, 0.0));
    assert!(hooked(&s));
    let v = run(&mut s, &mut m, 60);
    assert!(
        v[59] > 0.5 * BELT as f64,
        "the sleeping box was not carried: {}",
        v[59]
    );

    // A snapshot keeps the belt.
    let snap = m.snapshot();
    let restored = StickSlip::restore(&snap, &s.world.colliders, ()).unwrap();
    assert_eq!(
        restored.surface_velocity(s.ground),
        Some(v3(BELT, 0.0, 0.0))
    );

    // Stopped: the flag stickslip set goes, and the box comes to rest on the ground.
    assert_eq!(
        m.remove_surface_velocity(&mut s.world.colliders, s.ground),
        Some(v3(BELT, 0.0, 0.0))
    );
    assert!(!hooked(&s));
    let v = run(&mut s, &mut m, 60);
    assert!(v[59].abs() < 1e-3, "still moving at {}", v[59]);
}

#[test]
fn whose_belt_flag_it_is_is_the_modifiers_to_keep() {
    // An integration that learns only later that the user's hooks need a belt's flag (bevy's
    // `ActiveHooks` component) says so with `set_user_hook_flag`: the flag then stays when
    // the belt stops; said the other way, stopping the belt hands it back.
    let hooked = |s: &BoxScene| {
        s.world.colliders[s.ground]
            .active_hooks()
            .contains(ActiveHooks::MODIFY_SOLVER_CONTACTS)
    };
    let belt = v3(BELT, 0.0, 0.0);
    for users in [true, false] {
        let mut s = scene();
        let mut m = StickSlip::new(FrictionMaterial::new(ep()));
        m.set_surface_velocity(&mut s.world.colliders, s.ground, belt);
        m.set_user_hook_flag(&mut s.world.colliders, s.ground, users);
        assert!(hooked(&s));
        m.remove_surface_velocity(&mut s.world.colliders, s.ground);
        assert_eq!(hooked(&s), users, "the user's flag: {users}");
        // Neither attached nor a surface any more: the modifier leaves the collider alone.
        m.set_user_hook_flag(&mut s.world.colliders, s.ground, !users);
        assert_eq!(hooked(&s), users);
    }
}
