//! Taking a collider back out of stickslip. Invariant: after `StickSlip::detach`, no contact
//! record or report involving the collider remains, its hook flag is off again, and the world
//! continues bit for bit as a plain rapier world (no hooks) started from the same state would,
//! with the pair's friction back to rapier's own combined coefficient.
//! In 3D and in 2D (stickslip-fixtures2d).

use stickslip_core::law::Law;
use stickslip_core::sliding_curve::Curve;
use stickslip_fixtures::{cuboid3, v3};
use stickslip_rapier::rapier::prelude::*;
use stickslip_rapier::{FrictionMaterial, StickSlip};

/// Two boxes resting and being pushed on a ground: one pair to detach, one to keep.
fn world() -> (PhysicsWorld, ColliderHandle, [RigidBodyHandle; 2]) {
    let mut world = PhysicsWorld::default();
    let ground = world.insert_collider(cuboid3(20.0, 0.1, 20.0).0.friction(0.4), None);
    let mut boxes = [RigidBodyHandle::invalid(); 2];
    for (i, b) in boxes.iter_mut().enumerate() {
        let (h, _) = world.insert(
            RigidBodyBuilder::dynamic()
                .translation(v3(2.0 * i as f32, 0.3, 0.0))
                .can_sleep(false),
            cuboid3(0.2, 0.2, 0.2).0.density(1000.0).friction(0.4),
        );
        *b = h;
    }
    (world, ground, boxes)
}

fn push(world: &mut PhysicsWorld, boxes: &[RigidBodyHandle; 2], k: usize) {
    // A force that would slide the boxes with plain friction and hold them with a stronger law:
    // up to 0.64 of the weight (200 N on the 64 kg cube, scaled to the 2D box's mass).
    for b in boxes {
        let body = &mut world.bodies[*b];
        let f = 200.0 * (body.mass() / 64.0) * (1.0 + (k as f32 * 0.05).sin());
        body.reset_forces(true);
        body.add_force(v3(f, 0.0, 0.0), true);
    }
}

#[test]
fn a_detached_collider_behaves_like_plain_rapier() {
    let law = Law::elasto_plastic(1e5, 0.8, 0.8, Curve::constant(0.6).unwrap()).unwrap();
    let (mut a, ground_a, boxes_a) = world();
    let (mut b, ground_b, boxes_b) = world();
    let mut fa = StickSlip::new(FrictionMaterial::new(law.clone()))
        .with_read_back(stickslip_rapier::ReadBack::Contacts);
    let mut fb = StickSlip::new(FrictionMaterial::new(law))
        .with_read_back(stickslip_rapier::ReadBack::Contacts);
    fa.attach(&mut a.colliders, ground_a, None);
    fb.attach(&mut b.colliders, ground_b, None);
    for k in 0..60 {
        push(&mut a, &boxes_a, k);
        push(&mut b, &boxes_b, k);
        fa.step(&mut a);
        fb.step(&mut b);
    }
    assert!(fa.active_contacts() >= 2 && !fa.reports().unwrap().is_empty());

    // A: detach; B: the same state handed to plain rapier (flag off by hand, no hooks at all).
    fa.detach(&mut a.colliders, ground_a);
    // (B's pairs also get the full narrow-phase update that plain rapier would give pairs it
    // meets fresh: groups marked changed with the same value.)
    let c = &mut b.colliders[ground_b];
    c.set_active_hooks(c.active_hooks() - ActiveHooks::MODIFY_SOLVER_CONTACTS);
    let groups = c.solver_groups();
    c.set_solver_groups(InteractionGroups::none());
    c.set_solver_groups(groups);
    assert_eq!(fa.active_contacts(), 0);
    assert!(fa.reports().unwrap().is_empty());
    assert!(
        !a.colliders[ground_a]
            .active_hooks()
            .contains(ActiveHooks::MODIFY_SOLVER_CONTACTS)
    );
    for k in 60..400 {
        push(&mut a, &boxes_a, k);
        push(&mut b, &boxes_b, k);
        fa.step(&mut a);
        b.step();
        for (ba, bb) in boxes_a.iter().zip(&boxes_b) {
            assert_eq!(
                a.bodies[*ba].position(),
                b.bodies[*bb].position(),
                "step {k}"
            );
            assert_eq!(a.bodies[*ba].linvel(), b.bodies[*bb].linvel(), "step {k}");
        }
        assert_eq!(fa.active_contacts(), 0);
        assert!(fa.reports().unwrap().is_empty());
    }
    // rapier's own friction again on every manifold of the pair.
    for pair in a.narrow_phase.contact_pairs() {
        for m in pair.solver_manifolds() {
            assert_eq!(m.data.friction, 0.4);
        }
    }
    // The boxes slide under plain friction (0.4 < the push) where the law held them.
    let x = a.bodies[boxes_a[0]].translation().x;
    assert!(x > 0.5, "plain friction should let the box slide, x = {x}");
}
