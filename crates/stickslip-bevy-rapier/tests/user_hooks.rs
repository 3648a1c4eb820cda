//! The app's own `BevyPhysicsHooks` keep working beside stickslip's
//! (`RapierPhysicsPlugin::<MyHooks>` + `StickSlipRapierPlugin::default().with_hooks::<MyHooks>()`): a one-way platform (the user's hook
//! drops the contacts whose normal does not point up out of it) lets a ball thrown from below
//! pass and then carries it, and a conveyor (the user's hook gives a belt's contacts a
//! surface velocity) carries a box at the belt's 0.5 m/s — while stickslip holds a box on its
//! own attached ground, the only pair with a record. The app's hook is called on exactly the
//! pairs bevy_rapier calls it for without stickslip — not on a pair whose only hook flag is
//! stickslip's (an attached ground, a `SurfaceVelocity` belt), on a pair whose collider the
//! app flagged also when stickslip owns it — also after the app rewrites its `ActiveHooks`
//! component (bevy_rapier then rewrites rapier's flags: stickslip takes its own back — on, or
//! off while it recycles a quiet collider — and a flag the app adds is the app's, on every
//! step); removing stickslip's components turns off only stickslip's flags.

mod common;

use bevy::ecs::system::SystemParam;
use bevy::prelude::*;
use common::bevy_rapier::plugin::context::RapierContextColliders;
use common::bevy_rapier::prelude::*;
use common::stickslip_bevy_rapier::{
    StickSlipFriction, StickSlipRapier, StickSlipRapierPlugin, SurfaceVelocity,
};
use common::*;
use std::collections::BTreeSet;
use std::sync::Mutex;

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
                c.tangent_velocity = vect(v, 0.0, 0.0);
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
        cuboid(2.0, 0.1, 2.0),
        Transform::from_xyz(-20.0, -0.1, 0.0),
        StickSlipFriction(None),
    ));
    let held = world
        .spawn((
            RigidBody::Dynamic,
            cuboid(0.2, 0.2, 0.2),
            Transform::from_xyz(-20.0, 0.2, 0.0),
            StickSlipFriction(None),
        ))
        .id();
    // The user's one-way platform (top at y = 1) and a ball thrown up from below it.
    world.spawn((
        RigidBody::Fixed,
        cuboid(2.0, 0.1, 2.0),
        Transform::from_xyz(0.0, 0.9, 0.0),
        OneWay,
        hooks,
    ));
    let ball = world
        .spawn((
            RigidBody::Dynamic,
            Collider::ball(0.1),
            Transform::from_xyz(0.0, 0.3, 0.0),
            Velocity::linear(vect(0.0, 6.0, 0.0)),
        ))
        .id();
    // The user's conveyor belt and a box on it (apart along x: the same scene in 2D).
    world.spawn((
        RigidBody::Fixed,
        cuboid(20.0, 0.1, 1.0),
        Transform::from_xyz(40.0, -0.1, 0.0),
        Belt,
        hooks,
    ));
    let carried = world
        .spawn((
            RigidBody::Dynamic,
            cuboid(0.1, 0.1, 0.1),
            LockedAxes::ROTATION_LOCKED,
            Transform::from_xyz(40.0, 0.1, 0.0),
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
    let state = app.world_mut().resource_mut::<StickSlipRapier>();
    assert_eq!(state.modifier().active_contacts(), 1);
}

/// The pairs the app's hook was called for.
#[derive(Resource, Default)]
struct Seen(Mutex<BTreeSet<(Entity, Entity)>>);

#[derive(SystemParam)]
struct Recorder<'w> {
    seen: Res<'w, Seen>,
}

impl BevyPhysicsHooks for Recorder<'_> {
    fn modify_solver_contacts(&self, context: ContactModificationContextView) {
        let (a, b) = (context.collider1(), context.collider2());
        let pair = if a < b { (a, b) } else { (b, a) };
        self.seen.0.lock().unwrap().insert(pair);
    }
}

fn recorder_app(stickslip: bool) -> App {
    let mut app = App::new();
    app.add_plugins((MinimalPlugins, TransformPlugin))
        .init_resource::<Seen>()
        .insert_resource(TimestepMode::Fixed {
            dt: 1.0 / 60.0,
            substeps: 1,
        })
        .add_plugins(RapierPhysicsPlugin::<Recorder>::default());
    if stickslip {
        app.add_plugins(StickSlipRapierPlugin::default().with_hooks::<Recorder>());
    }
    app.update();
    app
}

/// Four grounds with a box each: stickslip's, the app's, both, a stickslip belt. Returns the
/// grounds and the boxes.
fn four_grounds(app: &mut App) -> ([Entity; 4], [Entity; 4]) {
    let world = app.world_mut();
    let flag = ActiveHooks::MODIFY_SOLVER_CONTACTS;
    let mut ground = |x: f32| {
        world
            .spawn((
                RigidBody::Fixed,
                cuboid(1.0, 0.1, 1.0),
                Transform::from_xyz(x, -0.1, 0.0),
            ))
            .id()
    };
    let grounds = [ground(-10.0), ground(0.0), ground(10.0), ground(20.0)];
    world.entity_mut(grounds[0]).insert(StickSlipFriction(None));
    world.entity_mut(grounds[1]).insert(flag);
    world
        .entity_mut(grounds[2])
        .insert((flag, StickSlipFriction(None)));
    world
        .entity_mut(grounds[3])
        .insert(SurfaceVelocity(Vec3::new(0.3, 0.0, 0.0)));
    let boxes = [-10.0, 0.0, 10.0, 20.0].map(|x| {
        world
            .spawn((
                RigidBody::Dynamic,
                cuboid(0.1, 0.1, 0.1),
                Transform::from_xyz(x, 0.1, 0.0),
                // A sleeping box's pair is not hooked at all.
                Sleeping::disabled(),
            ))
            .id()
    });
    (grounds, boxes)
}

/// The pairs the app's hook saw since the last call, as (ground k, box k) index pairs (the
/// two apps' entity ids differ: bevy's resources are entities too).
fn take_seen(
    app: &mut App,
    grounds: &[Entity; 4],
    boxes: &[Entity; 4],
) -> BTreeSet<(usize, usize)> {
    let seen = std::mem::take(&mut *app.world_mut().resource_mut::<Seen>().0.lock().unwrap());
    let index = |e: Entity| {
        grounds
            .iter()
            .chain(boxes)
            .position(|&x| x == e)
            .expect("a scene entity")
    };
    seen.into_iter()
        .map(|(a, b)| {
            let (a, b) = (index(a), index(b));
            (a.min(b), a.max(b) - 4)
        })
        .collect()
}

/// Whether rapier's collider of `e` carries the MODIFY_SOLVER_CONTACTS flag.
/// Whether stickslip has turned the collider's flag off to let rapier recycle its pairs.
fn recycled(app: &App, e: Entity) -> bool {
    let h = app.world().get::<RapierColliderHandle>(e).unwrap().0;
    app.world()
        .resource::<StickSlipRapier>()
        .modifier()
        .is_recycled(h)
}

fn rapier_flag(app: &mut App, e: Entity) -> bool {
    let h = app.world().get::<RapierColliderHandle>(e).unwrap().0;
    let mut q = app.world_mut().query::<&RapierContextColliders>();
    let colliders = q.single(app.world()).unwrap();
    colliders.colliders[h]
        .active_hooks()
        .contains(common::bevy_rapier::rapier::pipeline::ActiveHooks::MODIFY_SOLVER_CONTACTS)
}

#[test]
fn the_apps_hook_sees_the_pairs_it_sees_without_stickslip() {
    let mut alone = recorder_app(false);
    let (alone_grounds, alone_boxes) = four_grounds(&mut alone);
    for _ in 0..30 {
        alone.update();
    }
    let mut app = recorder_app(true);
    let (grounds, boxes) = four_grounds(&mut app);
    for _ in 0..30 {
        app.update();
    }
    let want = take_seen(&mut alone, &alone_grounds, &alone_boxes);
    let seen = take_seen(&mut app, &grounds, &boxes);
    // Ground k and box k: the app's ground (1) and the ground of both (2).
    assert_eq!(want, BTreeSet::from([(1, 1), (2, 2)]), "without stickslip");
    assert_eq!(seen, want, "with stickslip");
    // Each ground's flag is on, or off because stickslip recycles its quiet contacts (the
    // ground only stickslip flags: the app's hook never sees its pair either way).
    for g in grounds {
        assert!(rapier_flag(&mut app, g) || recycled(&app, g), "{g:?}");
    }
    assert!(rapier_flag(&mut app, grounds[1]) && rapier_flag(&mut app, grounds[2]));
    let records = |app: &mut App| {
        app.world_mut()
            .resource_mut::<StickSlipRapier>()
            .modifier()
            .active_contacts()
    };
    assert_eq!(records(&mut app), 2, "stickslip's two attached grounds");

    // The app rewrites its component on stickslip's ground without the flag: bevy_rapier
    // clears rapier's flag, stickslip takes it back (on, or off while it recycles the quiet
    // ground); the app's hook still stays out.
    app.world_mut()
        .entity_mut(grounds[0])
        .insert(ActiveHooks::empty());
    for _ in 0..10 {
        app.update();
    }
    assert!(rapier_flag(&mut app, grounds[0]) || recycled(&app, grounds[0]));
    assert!(!take_seen(&mut app, &grounds, &boxes).contains(&(0, 0)));
    assert_eq!(records(&mut app), 2);
    // Now with the flag: the pair is the app's hook's too.
    app.world_mut()
        .entity_mut(grounds[0])
        .insert(ActiveHooks::MODIFY_SOLVER_CONTACTS);
    for _ in 0..10 {
        app.update();
    }
    assert!(take_seen(&mut app, &grounds, &boxes).contains(&(0, 0)));
    assert_eq!(records(&mut app), 2);

    // Removing stickslip's components: its flags go (the belt's), the app's stay (ground 0
    // now, ground 2), and so do the records.
    for g in grounds {
        app.world_mut().entity_mut(g).remove::<StickSlipFriction>();
    }
    app.world_mut()
        .entity_mut(grounds[3])
        .remove::<SurfaceVelocity>();
    for _ in 0..3 {
        app.update();
    }
    assert!(rapier_flag(&mut app, grounds[0]));
    assert!(rapier_flag(&mut app, grounds[2]));
    assert!(!rapier_flag(&mut app, grounds[3]));
    assert_eq!(records(&mut app), 0);
}
