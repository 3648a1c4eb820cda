//! Hundreds of frictional contacts in one rapier world while contacts appear and disappear.
//! Invariants: with 300 boxes in a row (300 box–ground manifolds, some pushed above
//! break-away, some below) every active manifold has a friction state and every state belongs
//! to a manifold rapier still holds (no loss, no leak while boxes are lifted off and dropped
//! back; storage bounded by the peak), boxes
//! loaded below break-away move no more than under plain rapier in the same scene (and
//! within 10 g_ba) while their neighbours slide, nothing
//! becomes NaN or blows up, and a contact that re-forms after its box was lifted starts
//! from a fresh sticking state instead of reusing the old sliding one. Manifolds that rapier
//! holds without any solver contact (neighbours inside the prediction distance, not
//! touching; two boxes that touched and moved 5 cm apart) keep no state at all: with the
//! per-contact read-back on (a sweep every step) the states are exactly the touching
//! manifolds.
#![cfg(not(dim2))] // no 2D form yet: stickslip-fixtures2d compiles it empty

use stickslip_core::law::{Law, Regime};
use stickslip_core::sliding_curve::Curve;
use stickslip_rapier::rapier::prelude::*;
use stickslip_rapier::{FrictionMaterial, StickSlip};

const N: usize = 300;
const MU_BA: f64 = 0.5;
const MU_MAX: f64 = 0.55;
const C: f64 = 1e4;

/// (manifolds rapier holds, of which active: with solver contacts) between a box and the
/// stickslip ground; box–box contacts of sliding boxes bumping into held ones are plain
/// rapier contacts.
fn manifolds(world: &PhysicsWorld, ground: ColliderHandle) -> (usize, usize) {
    let all: Vec<_> = world
        .narrow_phase
        .contact_pairs()
        .filter(|p| p.collider1 == ground || p.collider2 == ground)
        .flat_map(|p| p.solver_manifolds())
        .collect();
    let active = all
        .iter()
        .filter(|m| !m.data.solver_contacts.is_empty())
        .count();
    (all.len(), active)
}

#[test]
fn hundreds_of_contacts_stay_consistent_through_churn() {
    // Held boxes that stayed on the ground, against plain rapier in the same scene: stickslip's
    // hold is rapier's rigid friction row under the law's limit (see contact_step.rs), so they
    // creep no more than under plain rapier (a push at the centre of mass rocks a box on the
    // compliant normal contact) — and far less than the law's elastic range g_ba allows.
    let plain = churn(false);
    let ep = churn(true);
    let worst = |d: &[f64]| d.iter().cloned().fold(0.0, f64::max);
    println!(
        "held boxes moved at most: stickslip {:.3e} m, plain rapier {:.3e} m (g_ba {:.1e} m)",
        worst(&ep),
        worst(&plain),
        MU_BA / C
    );
    assert!(worst(&ep) <= 1.1 * worst(&plain) + 1e-6);
    assert!(worst(&ep) <= 10.0 * MU_BA / C);
}

/// The churn scene under stickslip (checking its state's consistency on the way) or plain
/// rapier; returns how far each held box's contact point moved.
fn churn(with_stickslip: bool) -> Vec<f64> {
    let mut world = PhysicsWorld::default();
    let ground = world.insert_collider(ColliderBuilder::cuboid(400.0, 0.1, 100.0), None);
    let half = 0.2f32;
    let mut bodies = Vec::new();
    for i in 0..N {
        let (b, _) = world.insert(
            RigidBodyBuilder::dynamic()
                .translation(Vector::new(i as f32 * 1.0, 0.1 + half, 0.0))
                .can_sleep(false),
            ColliderBuilder::cuboid(half, half, half).density(1000.0),
        );
        bodies.push(b);
    }
    let law = Law::elasto_plastic(C, MU_BA, MU_MAX, Curve::constant(MU_MAX).unwrap()).unwrap();
    let mut modifier = StickSlip::new(FrictionMaterial::new(law))
        .with_read_back(stickslip_rapier::ReadBack::Contacts);
    if with_stickslip {
        let all: Vec<ColliderHandle> = world.colliders.iter().map(|(h, _)| h).collect();
        for h in all {
            modifier.attach(&mut world.colliders, h, None);
        }
    }
    let weight = 1000.0 * (2.0 * half as f64).powi(3) * 9.81;
    // Even boxes: pushed along the row at 0.8 of break-away (must hold); odd boxes: across
    // the row at 1.5× (slide clear of their neighbours).
    let push = |i: usize| {
        if i.is_multiple_of(2) {
            Vector::new((0.8 * MU_BA * weight) as f32, 0.0, 0.0)
        } else {
            Vector::new(0.0, 0.0, (1.5 * MU_BA * weight) as f32)
        }
    };
    for _ in 0..30 {
        modifier.step(&mut world);
    }
    // (Without an attached collider the modifier touches nothing: plain rapier.)
    // The contact point (bottom centre) of each box, which is what friction holds: the centre
    // of mass also rocks a little on rapier's compliant normal contact under a push.
    let bottom = |world: &PhysicsWorld, b: RigidBodyHandle| {
        world.bodies[b]
            .position()
            .transform_point(Vector::new(0.0, -half, 0.0))
    };
    let start: Vec<Vector> = bodies.iter().map(|b| bottom(&world, *b)).collect();
    let mut peak = 0;
    let mut lifted = vec![false; N];
    for step in 0..300 {
        // Every 100 steps lift a quarter of the row off the ground (they fall back within
        // ~0.45 s ≈ 27 steps); lifted boxes are not pushed while airborne. Quarter 2 (held
        // boxes) stays down throughout.
        if step % 100 == 50 {
            let q = [0, 1, 3][step / 100];
            for (i, b) in bodies.iter().enumerate() {
                if i % 4 == q {
                    lifted[i] = true;
                    let body = &mut world.bodies[*b];
                    let p = body.translation();
                    body.set_translation(Vector::new(p.x, p.y + 1.0, p.z), true);
                }
            }
        }
        for (i, b) in bodies.iter().enumerate() {
            let body = &mut world.bodies[*b];
            body.reset_forces(true);
            // Loads ramp in over 0.5 s: a step load would excite the contact dynamically.
            let ramp = ((step + 1) as f32 / 30.0).min(1.0);
            if body.translation().y < 0.1 + half + 0.05 {
                body.add_force(push(i) * ramp, true);
            }
        }
        modifier.step(&mut world);
        if with_stickslip {
            // Every active contact has a state (no loss), and every state belongs to a
            // manifold rapier still holds (no leak; the state of a contact that let go stays
            // until the next sweep, at most `SWEEP_INTERVAL` steps).
            let (held, active) = manifolds(&world, ground);
            let states = modifier.active_contacts();
            assert!(
                active <= states && states <= held,
                "step {step}: {active} active, {states} states, {held} manifolds"
            );
            peak = peak.max(states);
        }
        for b in &bodies {
            let body = &world.bodies[*b];
            assert!(body.translation().is_finite() && body.linvel().length() < 50.0);
        }
    }
    if with_stickslip {
        assert!(peak >= 250, "only {peak} contacts");
        assert!(
            modifier.state_capacity() <= peak,
            "storage {} above the peak {peak}",
            modifier.state_capacity()
        );
    }
    let held: Vec<usize> = (0..N).filter(|i| i % 2 == 0 && !lifted[*i]).collect();
    assert_eq!(held.len(), N / 4);
    let moved = held
        .iter()
        .map(|&i| {
            let dv = bottom(&world, bodies[i]) - start[i];
            (dv.x * dv.x + dv.z * dv.z).sqrt() as f64
        })
        .collect();
    for (i, b) in bodies.iter().enumerate().filter(|(i, _)| i % 2 == 1) {
        let dz = (world.bodies[*b].translation().z - start[i].z) as f64;
        assert!(dz > 0.5, "pushed box {i} should slide, moved {dz}");
    }
    for r in modifier.reports().unwrap() {
        assert!(r.mu.is_finite() && r.normal_force.is_finite());
    }
    moved
}

#[test]
fn a_reformed_contact_starts_fresh() {
    let mut world = PhysicsWorld::default();
    let ground = world.insert_collider(ColliderBuilder::cuboid(50.0, 0.1, 5.0), None);
    let (b, bc) = world.insert(
        RigidBodyBuilder::dynamic()
            .translation(Vector::new(0.0, 0.3, 0.0))
            .can_sleep(false),
        ColliderBuilder::cuboid(0.2, 0.2, 0.2).density(1000.0),
    );
    let law = Law::elasto_plastic(C, MU_BA, MU_MAX, Curve::constant(MU_MAX).unwrap()).unwrap();
    let mut modifier = StickSlip::new(FrictionMaterial::new(law))
        .with_read_back(stickslip_rapier::ReadBack::Contacts);
    modifier.attach(&mut world.colliders, ground, None);
    modifier.attach(&mut world.colliders, bc, None);
    for _ in 0..20 {
        modifier.step(&mut world);
    }
    // Slide it: the state goes to the sliding value μ_ve.
    world.bodies[b].set_linvel(Vector::new(3.0, 0.0, 0.0), true);
    modifier.step(&mut world);
    modifier.step(&mut world);
    let sliding = modifier.reports().unwrap()[0];
    assert_eq!(sliding.regime, Regime::Sliding);
    assert!(
        (sliding.mu - MU_MAX).abs() < 0.01,
        "sliding state {}",
        sliding.mu
    );
    // Lift it clear, stop it, and set it down: the old manifold is gone, its state with it.
    let p = world.bodies[b].translation();
    world.bodies[b].set_translation(Vector::new(p.x, 2.0, p.z), true);
    world.bodies[b].set_linvel(Vector::ZERO, true);
    modifier.step(&mut world);
    modifier.step(&mut world);
    assert_eq!(modifier.active_contacts(), 0);
    world.bodies[b].set_translation(Vector::new(p.x, 0.3, p.z), true);
    world.bodies[b].set_linvel(Vector::ZERO, true);
    for _ in 0..10 {
        modifier.step(&mut world);
    }
    let fresh = modifier.reports().unwrap()[0];
    assert_eq!(fresh.regime, Regime::Sticking);
    assert!(fresh.mu < 0.05, "re-formed contact carries {}", fresh.mu);
}

#[test]
fn near_misses_keep_no_state() {
    // 50 boxes under stickslip, 5 cm apart: every neighbour pair is a manifold in rapier's
    // narrow phase (inside the broad phase's margin) without any solver contact (beyond the
    // prediction distance); only the box–ground contacts touch.
    const GAP: f32 = 0.05;
    let mut world = PhysicsWorld::default();
    let ground = world.insert_collider(ColliderBuilder::cuboid(100.0, 0.1, 5.0), None);
    let law = Law::elasto_plastic(C, MU_BA, MU_MAX, Curve::constant(MU_MAX).unwrap()).unwrap();
    let mut modifier = StickSlip::new(FrictionMaterial::new(law))
        .with_read_back(stickslip_rapier::ReadBack::Contacts);
    modifier.attach(&mut world.colliders, ground, None);
    let half = 0.1;
    for i in 0..50 {
        let (_, c) = world.insert(
            RigidBodyBuilder::dynamic()
                .translation(Vector::new(i as f32 * (2.0 * half + GAP), 0.1 + half, 0.0))
                .can_sleep(false),
            ColliderBuilder::cuboid(half, half, half),
        );
        modifier.attach(&mut world.colliders, c, None);
    }
    for _ in 0..30 {
        modifier.step(&mut world);
    }
    let (mut touching, mut near) = (0, 0);
    for pair in world.narrow_phase.contact_pairs() {
        // A field in rapier 0.35, a method in 0.36.
        #[cfg(rapier_035)]
        let manifolds = &pair.manifolds;
        #[cfg(not(rapier_035))]
        let manifolds = pair.manifolds();
        for m in manifolds {
            if m.data.solver_contacts.is_empty() {
                near += 1;
            } else {
                touching += 1;
            }
        }
    }
    assert!(near >= 40, "the scene has near misses: {near}");
    assert_eq!(touching, 50, "every box on the ground");
    assert_eq!(
        modifier.active_contacts(),
        touching,
        "states only for touching contacts"
    );
}

#[test]
fn contacts_that_let_go_keep_no_state() {
    // Two boxes side by side on the ground, touching, then one moved 5 cm away: rapier keeps
    // their manifold (inside the broad phase's margin) without solver contacts. Only touching
    // manifolds keep a state, at every step.
    let mut world = PhysicsWorld::default();
    let ground = world.insert_collider(ColliderBuilder::cuboid(10.0, 0.1, 10.0), None);
    let law = Law::elasto_plastic(C, MU_BA, MU_MAX, Curve::constant(MU_MAX).unwrap()).unwrap();
    let mut modifier = StickSlip::new(FrictionMaterial::new(law))
        .with_read_back(stickslip_rapier::ReadBack::Contacts);
    modifier.attach(&mut world.colliders, ground, None);
    let half = 0.1;
    let mut boxes = Vec::new();
    for x in [0.0, 2.0 * half] {
        let (b, c) = world.insert(
            RigidBodyBuilder::dynamic()
                .translation(Vector::new(x, 0.1 + half, 0.0))
                .can_sleep(false),
            ColliderBuilder::cuboid(half, half, half),
        );
        modifier.attach(&mut world.colliders, c, None);
        boxes.push((b, c));
    }
    let between = |world: &PhysicsWorld| {
        let pair = world.narrow_phase.contact_pair(boxes[0].1, boxes[1].1)?;
        let touching = pair
            .solver_manifolds()
            .iter()
            .any(|m| !m.data.solver_contacts.is_empty());
        Some(touching)
    };
    let touching = stickslip_fixtures::touching_manifolds;
    for _ in 0..20 {
        modifier.step(&mut world);
    }
    assert_eq!(between(&world), Some(true), "the boxes touch");
    assert_eq!(modifier.active_contacts(), touching(&world));
    let p = world.bodies[boxes[1].0].translation();
    world.bodies[boxes[1].0].set_translation(Vector::new(p.x + 0.05, p.y, p.z), true);
    for step in 0..20 {
        modifier.step(&mut world);
        assert_eq!(
            modifier.active_contacts(),
            touching(&world),
            "step {step} after the boxes let go"
        );
    }
    assert_eq!(
        between(&world),
        Some(false),
        "rapier holds the pair, not touching"
    );
}
