//! bevy_rapier keeps working beside stickslip in one app: a sensor reports its intersection
//! with a falling ball, collision groups let a second ball through a floor it is filtered
//! from, `CollisionEvent`s arrive for the ball that lands, and a revolute joint holds a
//! pendulum bob at its arm's length — while stickslip holds a box on the floor (a record for
//! each pair with the attached floor: the box's and the landed ball's).

use bevy::prelude::*;
use bevy_rapier3d::prelude::*;
use stickslip_bevy_rapier::{StickSlipFriction, StickSlipRapier, StickSlipRapierPlugin};

#[derive(Resource, Default)]
struct Seen {
    collisions: usize,
    /// (sensor, ball) to watch, and whether they ever intersected.
    pair: Option<(Entity, Entity)>,
    inside: bool,
}

fn count_events(
    mut events: MessageReader<CollisionEvent>,
    mut seen: ResMut<Seen>,
    context: ReadRapierContext,
) {
    seen.collisions += events.read().count();
    if let (Some((a, b)), Ok(ctx)) = (seen.pair, context.single()) {
        seen.inside |= ctx.intersection_pair(a, b) == Some(true);
    }
}

#[test]
fn sensors_groups_events_and_joints_work_beside_stickslip() {
    let mut app = App::new();
    app.add_plugins((MinimalPlugins, TransformPlugin))
        .insert_resource(TimestepMode::Fixed {
            dt: 1.0 / 60.0,
            substeps: 1,
        })
        .init_resource::<Seen>()
        .add_plugins(RapierPhysicsPlugin::<NoUserData>::default())
        .add_plugins(StickSlipRapierPlugin::default())
        .add_systems(PostUpdate, count_events.after(PhysicsSet::Writeback));
    app.update();
    let world = app.world_mut();
    // The floor (stickslip's), with a box resting on it.
    world.spawn((
        RigidBody::Fixed,
        Collider::cuboid(20.0, 0.1, 20.0),
        Transform::from_xyz(0.0, -0.1, 0.0),
        StickSlipFriction(None),
        CollisionGroups::new(Group::GROUP_1, Group::ALL),
    ));
    let held = world
        .spawn((
            RigidBody::Dynamic,
            Collider::cuboid(0.2, 0.2, 0.2),
            Transform::from_xyz(-5.0, 0.2, 0.0),
            StickSlipFriction(None),
        ))
        .id();
    // A sensor the first ball falls through, and the ball, which lands (events on).
    let sensor = world
        .spawn((
            Collider::cuboid(0.5, 0.5, 0.5),
            Sensor,
            Transform::from_xyz(0.0, 2.0, 0.0),
            ActiveEvents::COLLISION_EVENTS,
        ))
        .id();
    let ball = world
        .spawn((
            RigidBody::Dynamic,
            Collider::ball(0.1),
            Transform::from_xyz(0.0, 4.0, 0.0),
            ActiveEvents::COLLISION_EVENTS,
        ))
        .id();
    // A ball whose groups exclude the floor's: it falls through.
    let ghost = world
        .spawn((
            RigidBody::Dynamic,
            Collider::ball(0.1),
            Transform::from_xyz(3.0, 1.0, 0.0),
            CollisionGroups::new(Group::GROUP_2, Group::GROUP_2),
        ))
        .id();
    // A pendulum: a fixed anchor and a bob 1 m away on a revolute joint about z.
    let anchor = world
        .spawn((RigidBody::Fixed, Transform::from_xyz(6.0, 3.0, 0.0)))
        .id();
    let joint = RevoluteJointBuilder::new(Vec3::Z).local_anchor2(Vec3::new(-1.0, 0.0, 0.0));
    let bob = world
        .spawn((
            RigidBody::Dynamic,
            Collider::ball(0.1),
            Transform::from_xyz(7.0, 3.0, 0.0),
            ImpulseJoint::new(anchor, joint),
        ))
        .id();
    app.world_mut().resource_mut::<Seen>().pair = Some((sensor, ball));
    for _ in 0..120 {
        app.update();
    }
    let inside = app.world().resource::<Seen>().inside;
    let y = |app: &App, e: Entity| app.world().get::<Transform>(e).unwrap().translation;
    assert!(inside, "the sensor never reported the ball");
    assert!(
        y(&app, ball).y > 0.0 && y(&app, ball).y < 0.2,
        "ball {:?}",
        y(&app, ball)
    );
    assert!(
        y(&app, ghost).y < -1.0,
        "the ghost ball did not pass the floor"
    );
    assert!(
        app.world().resource::<Seen>().collisions >= 2,
        "no collision events"
    );
    let arm = (y(&app, bob) - Vec3::new(6.0, 3.0, 0.0)).length();
    assert!((arm - 1.0).abs() < 0.01, "pendulum arm {arm}");
    let held_at = y(&app, held);
    assert!(
        (held_at.x + 5.0).abs() < 1e-4,
        "held box moved to {held_at:?}"
    );
    let state = app.world().resource::<StickSlipRapier>();
    // The box and the landed ball touch the attached floor: two records.
    assert_eq!(state.modifier().active_contacts(), 2);
}
