//! stickslip keeps a friction state exactly while a contact lasts. Invariants: a resting box
//! has one state per contact; despawning the box, removing a collider's `StickSlipFriction`
//! (back to avian's own friction: the box then slides at plain avian's μ_k where it held), or
//! lifting the box off leaves no state after the tick it happens in; a sleeping pair keeps
//! its state and holds again when woken.

mod common;

use bevy::prelude::*;
use common::avian::prelude::*;
use common::stickslip_avian::{ContactStore, StickSlipFriction};
use common::*;

fn states(app: &App) -> usize {
    app.world().resource::<ContactStore>().len()
}

#[test]
fn despawn_and_removal_leave_no_state() {
    // A slope between μ_k 0.4 and μ_s 0.6 of the default material (EP, 0.5 everywhere) and
    // of avian's friction.
    let mut app = app(true, 6, 0.45f64.atan());
    let friction = Friction::new(0.4).with_static_coefficient(0.6);
    floor(&mut app, friction);
    let held = block(&mut app, 0.0, friction);
    // Combined by `Min` with the floor's, its plain friction has no static part (0.4, 0.4).
    let plain = Friction::new(0.4).with_combine_rule(CoefficientCombine::Min);
    let marked = block(&mut app, 3.0, (plain, StickSlipFriction(None)));
    let lifted = block(&mut app, 6.0, friction);
    run(&mut app, 30);
    assert_eq!(states(&app), 3);

    app.world_mut().despawn(held);
    app.update();
    assert_eq!(states(&app), 2);

    // Without its material the marked box is avian's own again: at tan θ 0.45 > 0.4 it
    // slides.
    let x0 = position(&app, marked).x;
    app.world_mut()
        .entity_mut(marked)
        .remove::<StickSlipFriction>();
    app.update();
    assert_eq!(app.world().resource::<ContactStore>().count_of(marked), 0);
    run(&mut app, 60);
    assert!(position(&app, marked).x - x0 > 0.1);
    assert_eq!(app.world().resource::<ContactStore>().count_of(marked), 0);

    app.world_mut()
        .entity_mut(lifted)
        .insert(Position(Vec3::new(6.0, 5.0, 0.0)));
    run(&mut app, 2);
    assert_eq!(app.world().resource::<ContactStore>().count_of(lifted), 0);
}

#[test]
fn a_sleeping_pair_keeps_its_state_and_holds_when_woken() {
    let mut app = app(true, 6, 0.5f64.atan());
    let friction = Friction::new(0.4).with_static_coefficient(0.6);
    floor(&mut app, friction);
    let b = app
        .world_mut()
        .spawn((
            RigidBody::Dynamic,
            Collider::cuboid(0.5, 0.5, 0.5),
            Mass(1.0),
            Transform::from_xyz(0.0, 0.25, 0.0),
            friction,
        ))
        .id();
    run(&mut app, 240);
    assert!(app.world().get::<Sleeping>(b).is_some(), "not asleep");
    assert_eq!(states(&app), 1);
    let x0 = position(&app, b).x;
    app.world_mut()
        .commands()
        .queue(avian3d::dynamics::solver::islands::WakeBody(b));
    run(&mut app, 60);
    assert!(
        (position(&app, b).x - x0).abs() < 2e-3,
        "woken, it slid {} m",
        position(&app, b).x - x0
    );
}
