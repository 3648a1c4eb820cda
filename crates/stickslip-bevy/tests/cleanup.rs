//! Lifetimes in the ECS. Invariants: despawning bodies (with child colliders) or removing
//! `Collider`/`RigidBody` leaves no rapier body, collider, stickslip contact state or report
//! behind, and what is left of an entity comes back when its components do (a collider whose
//! body goes becomes a fixed collider); removing `FrictionLaw` takes a collider back to plain
//! rapier friction and re-inserting it restores its vibration; `RegimeChanged` messages
//! written in the fixed schedule arrive in `Update`, for new contacts and for break-away.

mod common;
use bevy::prelude::*;
use common::*;
use rapier3d::prelude as rp;
use stickslip_bevy::prelude::*;
use stickslip_bevy::{RapierBody, RapierCollider};

#[derive(Resource, Default)]
struct Seen(Vec<RegimeChanged>);

fn collect(mut seen: ResMut<Seen>, mut reader: MessageReader<RegimeChanged>) {
    seen.0.extend(reader.read().copied());
}

fn hooked(app: &App, e: Entity) -> bool {
    let w = app.world().resource::<StickSlipWorld>();
    let h = w.collider(e).unwrap();
    w.physics.colliders[h]
        .active_hooks()
        .contains(rp::ActiveHooks::MODIFY_SOLVER_CONTACTS)
}

fn state_count(app: &mut App) -> usize {
    let mut w = app.world_mut().resource_mut::<StickSlipWorld>();
    w.friction.active_contacts()
}

#[test]
fn despawn_and_removal_leave_nothing_behind() {
    let mut app = app();
    let g = ground(&mut app, ep(1e5, 0.5, 0.4));
    let a = part(&mut app, 0.0);
    let b = part(&mut app, 1.0);
    // A compound body: two child colliders, despawned with their parent.
    let c = app
        .world_mut()
        .spawn((RigidBody::Dynamic, Transform::from_xyz(3.0, 0.2, 0.0)))
        .with_children(|p| {
            p.spawn((
                Collider::cuboid(0.1, 0.1, 0.1),
                Transform::from_xyz(-0.15, 0.0, 0.0),
            ));
            p.spawn((
                Collider::cuboid(0.1, 0.1, 0.1),
                Transform::from_xyz(0.15, 0.0, 0.0),
            ));
        })
        .id();
    steps(&mut app, 30);
    assert_eq!(rapier_counts(&app), (4, 5));
    assert_eq!(app.world().resource::<ContactReports>().contacts.len(), 4);
    assert_eq!(state_count(&mut app), 4);

    app.world_mut().despawn(a);
    app.world_mut().despawn(c);
    app.world_mut().entity_mut(b).remove::<Collider>();
    // Observers act at once, before any step.
    assert_eq!(
        rapier_counts(&app),
        (2, 1),
        "the ground and b's collider-less body"
    );
    assert!(app.world().get::<RapierCollider>(b).is_none());
    assert_eq!(state_count(&mut app), 0);
    let w = app.world().resource::<StickSlipWorld>();
    assert!(w.friction.reports().unwrap().is_empty());
    assert_eq!(w.counts(), (2, 1));
    steps(&mut app, 1);
    assert!(app.world().resource::<ContactReports>().contacts.is_empty());

    // b gets a collider again, then loses its body: its collider stays, fixed.
    app.world_mut()
        .entity_mut(b)
        .insert(Collider::cuboid(0.1, 0.1, 0.1));
    steps(&mut app, 1);
    assert_eq!(rapier_counts(&app), (2, 2));
    app.world_mut().entity_mut(b).remove::<RigidBody>();
    assert_eq!(rapier_counts(&app), (1, 1));
    assert!(app.world().get::<RapierBody>(b).is_none());
    steps(&mut app, 1);
    assert_eq!(rapier_counts(&app), (1, 2));
    let w = app.world().resource::<StickSlipWorld>();
    let h = w.collider(b).unwrap();
    assert!(w.physics.colliders[h].parent().is_none());

    // Despawning everything leaves an empty world.
    app.world_mut().despawn(b);
    app.world_mut().despawn(g);
    assert_eq!(rapier_counts(&app), (0, 0));
    assert_eq!(app.world().resource::<StickSlipWorld>().counts(), (0, 0));
    assert_eq!(state_count(&mut app), 0);
    steps(&mut app, 1);
    assert!(app.world().resource::<ContactReports>().contacts.is_empty());
}

#[test]
fn friction_law_removal_and_return() {
    let mut app = app();
    let g = ground(&mut app, ep(1e5, 0.5, 0.4));
    let src = VibrationSource::new(
        VibrationDirection::Normal,
        Amplitude::Ratio(0.5),
        1000.0,
        Waveform::Sine,
        0.0,
        VibrationMode::Averaged,
    )
    .unwrap();
    app.world_mut().entity_mut(g).insert(Vibration(src));
    part(&mut app, 0.0);
    steps(&mut app, 10);
    let vibrating = |app: &App| {
        let w = app.world().resource::<StickSlipWorld>();
        w.friction.vibration(w.collider(g).unwrap()).is_some()
    };
    assert!(hooked(&app, g) && vibrating(&app));
    assert_eq!(state_count(&mut app), 1);

    app.world_mut().entity_mut(g).remove::<FrictionLaw>();
    assert!(!hooked(&app, g), "plain rapier friction again");
    assert!(!vibrating(&app));
    assert_eq!(state_count(&mut app), 0);
    steps(&mut app, 5);
    assert!(app.world().resource::<ContactReports>().contacts.is_empty());

    app.world_mut()
        .entity_mut(g)
        .insert(FrictionLaw::new(ep(1e5, 0.5, 0.4)));
    steps(&mut app, 1);
    assert!(
        hooked(&app, g) && vibrating(&app),
        "the law brings the vibration back"
    );
    assert_eq!(app.world().resource::<ContactReports>().contacts.len(), 1);

    // A vibration alone brings the default law with it (a required component).
    let src = app.world().get::<Vibration>(g).unwrap().0.clone();
    let lone = app
        .world_mut()
        .spawn((RigidBody::Fixed, Collider::ball(0.1), Vibration(src)))
        .id();
    assert_eq!(
        app.world().get::<FrictionLaw>(lone),
        Some(&FrictionLaw(None))
    );
}

#[test]
fn regime_messages_arrive_in_update() {
    let mut app = app();
    app.init_resource::<Seen>().add_systems(Update, collect);
    ground(&mut app, ep(1e5, 0.5, 0.4));
    let a = part(&mut app, 0.0);
    let b = part(&mut app, 1.0);
    steps(&mut app, 30);
    let seen = &app.world().resource::<Seen>().0;
    for e in [a, b] {
        let news: Vec<_> = seen
            .iter()
            .filter(|m| m.collider1 == e || m.collider2 == e)
            .collect();
        assert!(
            news.iter().any(|m| m.from.is_none()),
            "a new contact is announced for {e:?}: {seen:?}"
        );
        assert_eq!(news.last().unwrap().to, Regime::Sticking, "{news:?}");
    }
    // Pushing a above break-away (0.5 · 78.5 N): it slides, and Update hears of it.
    app.world_mut().resource_mut::<Seen>().0.clear();
    app.world_mut().entity_mut(a).insert(ExternalForce {
        force: Vec3::new(60.0, 0.0, 0.0),
        torque: Vec3::ZERO,
    });
    steps(&mut app, 30);
    let seen = &app.world().resource::<Seen>().0;
    assert!(
        seen.iter()
            .any(|m| (m.collider1 == a || m.collider2 == a) && m.to == Regime::Sliding),
        "{seen:?}"
    );
    assert!(
        seen.iter().all(|m| m.collider1 != b && m.collider2 != b),
        "b kept sticking: {seen:?}"
    );
}
