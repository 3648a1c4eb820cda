//! Lifetimes in the ECS. Invariants: despawning a body, or removing its `Collider`, leaves no
//! rapier body, collider, stickslip contact state or report behind; removing `FrictionLaw`
//! takes the collider back to plain rapier friction (hook flag off); and `RegimeChanged`
//! messages written in the fixed schedule arrive in `Update`.

mod common;
use bevy::prelude::*;
use common::*;
use rapier3d::prelude as rp;
use stickslip_bevy::prelude::*;
use stickslip_core::law::Regime;

#[derive(Resource, Default)]
struct Seen(Vec<RegimeChanged>);

fn collect(mut seen: ResMut<Seen>, mut reader: MessageReader<RegimeChanged>) {
    seen.0.extend(reader.read().copied());
}

#[test]
fn despawn_and_removal_leave_nothing_behind() {
    let mut app = app();
    app.init_resource::<Seen>().add_systems(Update, collect);
    let g = ground(&mut app, ep(1e5, 0.5, 0.4));
    let a = part(&mut app, 0.0);
    let b = part(&mut app, 1.0);
    steps(&mut app, 30);
    {
        let w = app.world().resource::<StickSlipWorld>();
        assert_eq!((w.physics.bodies.len(), w.physics.colliders.len()), (3, 3));
    }
    let contacts = app.world().resource::<StickSlipContacts>();
    assert_eq!(contacts.contacts.len(), 2);
    // Both resting contacts were reported, in Update, as new sticking contacts.
    let seen = &app.world().resource::<Seen>().0;
    for e in [a, b] {
        assert!(
            seen.iter()
                .any(|m| (m.collider1 == e || m.collider2 == e) && m.to == Regime::Sticking),
            "no RegimeChanged for {e:?}: {seen:?}"
        );
    }

    app.world_mut().despawn(a);
    app.world_mut().entity_mut(b).remove::<Collider>();
    steps(&mut app, 2);
    let w = app.world_mut().resource_mut::<StickSlipWorld>();
    assert_eq!(
        w.physics.colliders.len(),
        1,
        "only the ground's collider remains"
    );
    assert_eq!(
        w.physics.bodies.len(),
        2,
        "the ground and b's (collider-less) body"
    );
    assert!(w.friction.reports().is_empty());
    let mut w = app.world_mut().resource_mut::<StickSlipWorld>();
    assert_eq!(w.friction.active_contacts(), 0);
    assert!(
        app.world()
            .resource::<StickSlipContacts>()
            .contacts
            .is_empty()
    );

    // Removing the law: plain rapier friction again.
    app.world_mut().entity_mut(g).remove::<FrictionLaw>();
    let w = app.world().resource::<StickSlipWorld>();
    let h = w.collider(g).unwrap();
    assert!(
        !w.physics.colliders[h]
            .active_hooks()
            .contains(rp::ActiveHooks::MODIFY_SOLVER_CONTACTS)
    );
    app.world_mut().despawn(b);
    steps(&mut app, 1);
    assert_eq!(
        app.world()
            .resource::<StickSlipWorld>()
            .physics
            .bodies
            .len(),
        1
    );
}
