//! The bevy_rapier app with stickslip and stickslip-rapier driving rapier 0.35 directly give
//! the same trajectory for the same scene — a box on an elasto-plastic ground, gravity tilted
//! above break-away so that it sticks, breaks away and slides — bit for bit, over 2 s.

use bevy::prelude::*;
use bevy_rapier3d::prelude::*;
use bevy_rapier3d::rapier::prelude as rp;
use stickslip_bevy_rapier::{StickSlipFriction, StickSlipRapierPlugin};
use stickslip_core::law::Law;
use stickslip_core::sliding_curve::Curve;
use stickslip_rapier_035::{FrictionMaterial, StickSlip};

const DT: f32 = 1.0 / 60.0;
const STEPS: usize = 120;

fn material() -> FrictionMaterial {
    FrictionMaterial::new(
        Law::elasto_plastic(1e5, 0.5, 0.5, Curve::constant(0.4).unwrap()).unwrap(),
    )
}

fn gravity() -> Vec3 {
    let th = 0.55f64.atan();
    Vec3::new((9.81 * th.sin()) as f32, -(9.81 * th.cos()) as f32, 0.0)
}

fn in_bevy_rapier() -> Vec<Vec3> {
    let mut app = App::new();
    app.add_plugins((MinimalPlugins, TransformPlugin))
        .insert_resource(TimestepMode::Fixed {
            dt: DT,
            substeps: 1,
        })
        .add_plugins(RapierPhysicsPlugin::<NoUserData>::default())
        .add_plugins(StickSlipRapierPlugin::new(material()));
    app.update();
    let mut q = app.world_mut().query::<&mut RapierConfiguration>();
    for mut c in q.iter_mut(app.world_mut()) {
        c.gravity = gravity();
    }
    app.world_mut().spawn((
        RigidBody::Fixed,
        Collider::cuboid(5.0, 0.1, 1.0),
        Transform::from_xyz(0.0, -0.1, 0.0),
        StickSlipFriction(None),
    ));
    let b = app
        .world_mut()
        .spawn((
            RigidBody::Dynamic,
            Collider::cuboid(0.1, 0.1, 0.1),
            ColliderMassProperties::Density(1000.0),
            Transform::from_xyz(0.0, 0.1, 0.0),
            StickSlipFriction(None),
        ))
        .id();
    (0..STEPS)
        .map(|_| {
            app.update();
            app.world().get::<Transform>(b).unwrap().translation
        })
        .collect()
}

fn in_rapier() -> Vec<Vec3> {
    let mut world = rp::PhysicsWorld {
        gravity: gravity(),
        ..Default::default()
    };
    world.integration_parameters.dt = DT;
    let (_, ground) = world.insert(
        rp::RigidBodyBuilder::fixed().translation(Vec3::new(0.0, -0.1, 0.0)),
        rp::ColliderBuilder::cuboid(5.0, 0.1, 1.0),
    );
    let (b, cube) = world.insert(
        rp::RigidBodyBuilder::dynamic().translation(Vec3::new(0.0, 0.1, 0.0)),
        rp::ColliderBuilder::cuboid(0.1, 0.1, 0.1).density(1000.0),
    );
    let mut m = StickSlip::new(material());
    m.attach(&mut world.colliders, ground, None);
    m.attach(&mut world.colliders, cube, None);
    (0..STEPS)
        .map(|_| {
            m.step(&mut world);
            world.bodies[b].translation()
        })
        .collect()
}

#[test]
fn the_same_scene_moves_the_same_in_bevy_rapier_and_in_rapier() {
    let (a, b) = (in_bevy_rapier(), in_rapier());
    let moved = a[STEPS - 1].x - a[0].x;
    assert!(
        moved > 0.05,
        "the box should break away and slide: {moved} m"
    );
    for (k, (p, q)) in a.iter().zip(&b).enumerate() {
        assert_eq!(p, q, "step {k}: bevy_rapier {p:?}, rapier {q:?}");
    }
}
