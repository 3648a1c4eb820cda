//! Friction state across sleep with nothing read back (the default `ReadBack::Off`), where
//! the store is swept every `SWEEP_INTERVAL` steps from its own slots and the narrow phase is
//! asked only about records the hook did not see. Invariants: a box that falls asleep on a
//! slope keeps its contact's state for as long as it sleeps (rapier keeps the manifold but
//! never calls the hook for it), holds where it stopped when woken (no creep beyond the law's
//! break-away slip g_ba = μ_ba/c); a contact whose box is lifted away loses its state within
//! one sweep interval; the count of states equals the count of manifolds rapier holds with
//! solver contacts.
//! In 3D and in 2D (stickslip-fixtures2d).

use stickslip_core::law::Law;
use stickslip_core::sliding_curve::Curve;
use stickslip_fixtures::{cuboid3, touching_manifolds as touching, v3};
use stickslip_rapier::rapier::prelude::*;
use stickslip_rapier::{FrictionMaterial, SWEEP_INTERVAL, StickSlip};

const MU_BA: f64 = 0.5;
const MU_MAX: f64 = 0.55;
const C: f64 = 1e4;

#[test]
fn sleeping_contacts_keep_their_state_and_vanished_ones_lose_it() {
    let mut world = PhysicsWorld::default();
    // Gravity along a 20° slope (tan 20° = 0.36 < μ_ba = 0.5): the box holds.
    let tilt = 20f32.to_radians();
    world.gravity = v3(9.81 * tilt.sin(), -9.81 * tilt.cos(), 0.0);
    let ground = world.insert_collider(cuboid3(20.0, 0.1, 20.0).0, None);
    let mut boxes = Vec::new();
    for i in 0..2 {
        let (b, _) = world.insert(
            RigidBodyBuilder::dynamic().translation(v3(3.0 * i as f32, 0.3, 0.0)),
            cuboid3(0.2, 0.2, 0.2).0.density(1000.0),
        );
        boxes.push(b);
    }
    let law = Law::elasto_plastic(C, MU_BA, MU_MAX, Curve::constant(MU_MAX).unwrap()).unwrap();
    let mut m = StickSlip::new(FrictionMaterial::new(law));
    m.attach(&mut world.colliders, ground, None);
    // Settle until both boxes sleep.
    let mut steps = 0;
    while !boxes.iter().all(|&b| world.bodies[b].is_sleeping()) {
        m.step(&mut world);
        steps += 1;
        assert!(steps < 2000, "the boxes fall asleep");
    }
    assert_eq!(m.active_contacts(), 2);
    assert_eq!(m.active_contacts(), touching(&world));
    let rest = world.bodies[boxes[0]].translation();
    // Asleep for many sweep intervals: rapier keeps the manifolds, the hook never sees them,
    // the states stay.
    for _ in 0..(10 * SWEEP_INTERVAL) {
        m.step(&mut world);
    }
    assert!(world.bodies[boxes[0]].is_sleeping());
    assert_eq!(m.active_contacts(), 2, "sleeping contacts keep their state");
    // Woken, the box holds where it stopped: its state was kept, not rebuilt from zero
    // by a fresh landing.
    world.bodies[boxes[0]].wake_up(true);
    world.bodies[boxes[1]].set_translation(v3(3.0, 5.0, 0.0), true);
    for _ in 0..(2 * SWEEP_INTERVAL) {
        m.step(&mut world);
    }
    let moved = (world.bodies[boxes[0]].translation() - rest).length() as f64;
    assert!(moved < MU_BA / C, "woken box crept {moved} m");
    // The lifted box is in the air: its contact's state is gone within a sweep interval.
    assert_eq!(touching(&world), 1);
    assert_eq!(
        m.active_contacts(),
        1,
        "the vanished contact's state is dropped"
    );
}
