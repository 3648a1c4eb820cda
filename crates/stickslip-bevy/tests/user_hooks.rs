//! The app's own `BevyPhysicsHooks` keep working beside stickslip's
//! (`RapierPhysicsPlugin::<MyHooks>` + `StickSlipRapierPlugin::default().with_hooks::<MyHooks>()`): a one-way platform (the user's hook
//! drops the contacts whose normal does not point up out of it) lets a ball thrown from below
//! pass and then carries it, and a conveyor (the user's hook gives a belt's contacts a
//! surface velocity) carries a box at the belt's 0.5 m/s — while stickslip holds a box on its
//! own attached ground, the only pair with a record.

use bevy::ecs::system::SystemParam;
use bevy::prelude::*;
use bevy_rapier3d::prelude::*;
use stickslip_bevy::{StickSlipFriction, StickSlipRapier, StickSlipRapierPlugin};

#[derive(Component)]
struct OneWay;

#[derive(Component)]
struct Belt;

#[derive(SystemParam)]
struct MyHooks<'w, 's> {
    one_way: Query<'w, 's, (), With<OneWay>>,
    belts: Query<'w, 's, (), With<Belt>>,
}

impl BevyPhysicsHooks for MyHooks<'_, '_> {
    fn modify_solver_contacts(&self, context: ContactModificationContextView) {
        let (e1, e2) = (context.collider1(), context.collider2());
        if self.one_way.contains(e1) || self.one_way.contains(e2) {
            // The normal points from collider 1 to collider 2.
            let n = *context.raw.normal;
            let up = if self.one_way.contains(e1) { n } else { -n };
            if up.y < 0.5 {
                context.raw.solver_contacts.clear();
            }
        }
        if self.belts.contains(e1) || self.belts.contains(e2) {
            let v = if self.belts.contains(e1) { 0.5 } else { -0.5 };
            for c in context.raw.solver_contacts.iter_mut() {
                c.tangent_velocity = Vec3::new(v, 0.0, 0.0);
            }
        }
    }
}

#[test]
fn the_apps_own_hooks_work_beside_stickslip() {
    let mut app = App::new();
    app.add_plugins((MinimalPlugins, TransformPlugin))
        .insert_resource(TimestepMode::Fixed {
            dt: 1.0 / 60.0,
            substeps: 1,
        })
        .add_plugins(RapierPhysicsPlugin::<MyHooks>::default())
        .add_plugins(StickSlipRapierPlugin::default().with_hooks::<MyHooks>());
    app.update();
    let world = app.world_mut();
    let hooks = ActiveHooks::MODIFY_SOLVER_CONTACTS;
    // stickslip's ground and box, far from the rest.
    world.spawn((
        RigidBody::Fixed,
        Collider::cuboid(2.0, 0.1, 2.0),
        Transform::from_xyz(-20.0, -0.1, 0.0),
        StickSlipFriction(None),
    ));
    let held = world
        .spawn((
            RigidBody::Dynamic,
            Collider::cuboid(0.2, 0.2, 0.2),
            Transform::from_xyz(-20.0, 0.2, 0.0),
            StickSlipFriction(None),
        ))
        .id();
    // The user's one-way platform (top at y = 1) and a ball thrown up from below it.
    world.spawn((
        RigidBody::Fixed,
        Collider::cuboid(2.0, 0.1, 2.0),
        Transform::from_xyz(0.0, 0.9, 0.0),
        OneWay,
        hooks,
    ));
    let ball = world
        .spawn((
            RigidBody::Dynamic,
            Collider::ball(0.1),
            Transform::from_xyz(0.0, 0.3, 0.0),
            Velocity::linear(Vec3::new(0.0, 6.0, 0.0)),
        ))
        .id();
    // The user's conveyor belt and a box on it.
    world.spawn((
        RigidBody::Fixed,
        Collider::cuboid(20.0, 0.1, 1.0),
        Transform::from_xyz(0.0, -0.1, 10.0),
        Belt,
        hooks,
    ));
    let carried = world
        .spawn((
            RigidBody::Dynamic,
            Collider::cuboid(0.1, 0.1, 0.1),
            LockedAxes::ROTATION_LOCKED,
            Transform::from_xyz(0.0, 0.1, 10.0),
            Velocity::zero(),
        ))
        .id();
    for _ in 0..180 {
        app.update();
    }
    let at = |app: &App, e: Entity| app.world().get::<Transform>(e).unwrap().translation;
    let ball_at = at(&app, ball);
    assert!(
        (ball_at.y - 1.1).abs() < 0.02,
        "the ball should rest on the one-way platform (y 1.1): {ball_at:?}"
    );
    let v = app.world().get::<Velocity>(carried).unwrap().linear;
    assert!((v.x.abs() - 0.5).abs() < 0.01, "belt box velocity {v:?}");
    assert!(
        (at(&app, held).x + 20.0).abs() < 1e-4,
        "stickslip's box moved"
    );
    let mut state = app.world_mut().resource_mut::<StickSlipRapier>();
    assert_eq!(state.modifier.active_contacts(), 1);
}
