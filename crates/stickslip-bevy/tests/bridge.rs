//! The rapier bridge moves what it should. Invariants: child colliders make one compound body
//! with the summed mass that rests where its shapes say; balls and capsules rest on their
//! radius; a kinematic velocity-based or position-based carrier carries a sticking part
//! with it; a `SurfaceVelocity` belt brings a part to the belt's speed; `Transform` and
//! `Velocity` set by the user (teleports, kicks) reach rapier; an `ExternalForce` accelerates
//! a free body at F/m and stops when removed; a body added to an entity with a (so far
//! fixed) collider takes the collider over; colliders any number of levels below a body
//! join it at the composed offset (and below no body sit fixed where the whole hierarchy
//! puts them), also when the body arrives after them; `ColliderMass` sets the mass, `Damping` slows a
//! free body by rapier's implicit factor 1/(1 + c·dt) per step (≈ e^(−c·t)), `Restitution`
//! makes a ball bounce back to e²·h, and changing them on a live body takes effect.

mod common;
use bevy::prelude::*;
use common::*;
use stickslip_bevy::prelude::*;

fn zero_gravity(app: &mut App) {
    app.insert_resource(Gravity(Vec3::ZERO));
}

fn pos(app: &App, e: Entity) -> Vec3 {
    app.world().get::<Transform>(e).unwrap().translation
}

fn vel(app: &App, e: Entity) -> Vec3 {
    app.world().get::<Velocity>(e).unwrap().linear
}

#[test]
fn child_colliders_make_one_body() {
    let mut app = app();
    ground(&mut app, ep(1e5, 0.5, 0.5));
    // Two 0.2 m cubes side by side (8 kg each) under a collider-less parent.
    let body = app
        .world_mut()
        .spawn((RigidBody::Dynamic, Transform::from_xyz(0.0, 0.25, 0.0)))
        .with_children(|p| {
            p.spawn((
                Collider::cuboid(0.1, 0.1, 0.1),
                Transform::from_xyz(-0.1, 0.0, 0.0),
            ));
            p.spawn((
                Collider::cuboid(0.1, 0.1, 0.1),
                Transform::from_xyz(0.1, 0.0, 0.0),
                Density(2000.0),
            ));
        })
        .id();
    steps(&mut app, 120);
    let w = app.world().resource::<StickSlipWorld>();
    let b = &w.physics.bodies[w.body(body).unwrap()];
    assert_eq!(b.colliders().len(), 2);
    assert!((b.mass() - 24.0).abs() < 1e-3, "mass {}", b.mass());
    // Resting on the ground (top at 0.1): the shapes' bottom at 0.1.
    let y = pos(&app, body).y;
    assert!((y - 0.2).abs() < 2e-3, "y = {y}");
}

#[test]
fn balls_and_capsules_rest_on_their_radius() {
    let mut app = app();
    ground(&mut app, ep(1e5, 0.5, 0.5));
    let ball = app
        .world_mut()
        .spawn((
            RigidBody::Dynamic,
            Collider::ball(0.1),
            Transform::from_xyz(0.0, 0.3, 0.0),
        ))
        .id();
    // A capsule lying along x (half length 0.2 of its cylinder part, radius 0.05).
    let capsule = app
        .world_mut()
        .spawn((
            RigidBody::Dynamic,
            Collider::capsule(Vec3::new(-0.2, 0.0, 0.0), Vec3::new(0.2, 0.0, 0.0), 0.05),
            Transform::from_xyz(1.0, 0.3, 0.0),
        ))
        .id();
    steps(&mut app, 240);
    assert!(
        (pos(&app, ball).y - 0.2).abs() < 2e-3,
        "{}",
        pos(&app, ball)
    );
    assert!(
        (pos(&app, capsule).y - 0.15).abs() < 2e-3,
        "{}",
        pos(&app, capsule)
    );
    assert!(vel(&app, ball).length() < 1e-3);
}

/// A 0.2 m cube on a kinematic platform (EP friction), the platform driven by `drive`.
fn carried(kind: RigidBody, drive: impl Fn(&mut App, f32)) -> (Vec3, Vec3) {
    let mut app = app();
    let platform = app
        .world_mut()
        .spawn((
            kind,
            Collider::cuboid(2.0, 0.1, 1.0),
            FrictionLaw::new(ep(1e5, 0.5, 0.5)),
        ))
        .id();
    let box_ = part(&mut app, 0.0);
    steps(&mut app, 60);
    let start = pos(&app, box_);
    for k in 0..120 {
        drive(&mut app, k as f32 / HZ as f32);
        steps(&mut app, 1);
    }
    let _ = platform;
    (pos(&app, box_) - start, vel(&app, box_))
}

#[test]
fn kinematic_carriers_carry_a_sticking_part() {
    // Velocity-based: 0.4 m/s for 1 s (accelerating 0.4 m/s in one step would break away;
    // the platform ramps up over 0.25 s: a ≈ 1.6 m/s² < 0.5 g).
    let (dx, v) = carried(RigidBody::KinematicVelocityBased, |app, t| {
        let v = 0.4 * (t / 0.25).min(1.0);
        let mut q = app
            .world_mut()
            .query_filtered::<&mut Velocity, Without<LockRotations>>();
        for mut vel in q.iter_mut(app.world_mut()) {
            vel.linear = Vec3::new(v, 0.0, 0.0);
        }
    });
    let expect = 0.4 * (1.0 - 0.125) - 0.4 / 120.0 * 0.5;
    println!("velocity-based: moved {dx}, v {v}, expected about {expect}");
    assert!((v.x - 0.4).abs() < 1e-3, "{v}");
    assert!((dx.x as f64 - expect).abs() < 0.01, "{dx}");
    // Position-based: x(t) = 0.2 (1 − cos π t), from rest (peak acceleration 2 m/s² < 0.5 g);
    // at t = 1 s the platform is at 0.4 m and (nearly: its last step moves 0.07 mm) at rest.
    let (dx, v) = carried(RigidBody::KinematicPositionBased, |app, t| {
        let x = 0.2 * (1.0 - (std::f32::consts::PI * (t + 1.0 / 120.0)).cos());
        let mut q = app
            .world_mut()
            .query_filtered::<&mut Transform, (With<RigidBody>, Without<LockRotations>)>();
        for mut tr in q.iter_mut(app.world_mut()) {
            tr.translation.x = x;
        }
    });
    println!("position-based: moved {dx}, v {v}, platform moved 0.4 m");
    assert!((dx.x - 0.4).abs() < 1e-3, "{dx}");
    assert!(v.x.abs() < 0.02, "{v}");
}

#[test]
fn a_belt_brings_a_part_to_its_speed() {
    let mut app = app();
    let belt = ground(&mut app, ep(1e5, 0.5, 0.5));
    app.world_mut()
        .entity_mut(belt)
        .insert(SurfaceVelocity(Vec3::new(0.3, 0.0, 0.0)));
    let p = part(&mut app, 0.0);
    steps(&mut app, 120);
    let v = vel(&app, p);
    println!("part on the belt: {v}");
    assert!((v.x - 0.3).abs() < 1e-3 && v.z.abs() < 1e-4, "{v}");
    // Stopping the belt stops the part (μ g = 4.9 m/s²: within 0.1 s).
    app.world_mut().entity_mut(belt).remove::<SurfaceVelocity>();
    steps(&mut app, 30);
    assert!(vel(&app, p).length() < 1e-3, "{}", vel(&app, p));
}

#[test]
fn user_inputs_reach_rapier() {
    let mut app = app();
    zero_gravity(&mut app);
    let b = app
        .world_mut()
        .spawn((
            RigidBody::Dynamic,
            Collider::cuboid(0.1, 0.1, 0.1),
            LockRotations,
        ))
        .id();
    steps(&mut app, 1);
    // Teleport.
    app.world_mut().get_mut::<Transform>(b).unwrap().translation = Vec3::new(5.0, 1.0, 0.0);
    steps(&mut app, 1);
    assert_eq!(pos(&app, b), Vec3::new(5.0, 1.0, 0.0));
    // Kick: 1.2 m/s for 1 s.
    app.world_mut().get_mut::<Velocity>(b).unwrap().linear = Vec3::new(1.2, 0.0, 0.0);
    steps(&mut app, 120);
    assert!((pos(&app, b).x - 6.2).abs() < 1e-3, "{}", pos(&app, b));
    // A force of 8 N on 8 kg: +1 m/s in 1 s, then nothing once removed.
    app.world_mut().entity_mut(b).insert(ExternalForce {
        force: Vec3::new(8.0, 0.0, 0.0),
        torque: Vec3::ZERO,
    });
    steps(&mut app, 120);
    assert!((vel(&app, b).x - 2.2).abs() < 1e-3, "{}", vel(&app, b));
    app.world_mut().entity_mut(b).remove::<ExternalForce>();
    steps(&mut app, 60);
    assert!((vel(&app, b).x - 2.2).abs() < 1e-3, "{}", vel(&app, b));
}

#[test]
fn a_body_added_later_takes_over_its_colliders() {
    let mut app = app();
    ground(&mut app, ep(1e5, 0.5, 0.5));
    // A collider alone is fixed: it floats.
    let e = app
        .world_mut()
        .spawn((
            Collider::cuboid(0.1, 0.1, 0.1),
            Transform::from_xyz(0.0, 1.0, 0.0),
        ))
        .id();
    steps(&mut app, 30);
    assert_eq!(pos(&app, e).y, 1.0);
    assert_eq!(rapier_counts(&app), (1, 2));
    // With a body it falls onto the ground, one body, one collider on it.
    app.world_mut().entity_mut(e).insert(RigidBody::Dynamic);
    steps(&mut app, 120);
    assert_eq!(rapier_counts(&app), (2, 2));
    let w = app.world().resource::<StickSlipWorld>();
    let c = &w.physics.colliders[w.collider(e).unwrap()];
    assert_eq!(c.parent(), w.body(e));
    assert!((pos(&app, e).y - 0.2).abs() < 2e-3, "{}", pos(&app, e));
}

#[test]
fn mass_damping_and_restitution_reach_rapier() {
    let mut app = app();
    zero_gravity(&mut app);
    let c = 2.0f32;
    let free = app
        .world_mut()
        .spawn((
            RigidBody::Dynamic,
            Collider::ball(0.1),
            ColliderMass(3.0),
            Damping {
                linear: c,
                angular: 0.0,
            },
            Velocity {
                linear: Vec3::X,
                angular: Vec3::ZERO,
            },
            Transform::from_xyz(0.0, 5.0, 0.0),
        ))
        .id();
    steps(&mut app, 1);
    let w = app.world().resource::<StickSlipWorld>();
    let mass = w.physics.bodies[w.body(free).unwrap()].mass();
    assert!((mass - 3.0).abs() < 1e-5, "mass {mass}");
    steps(&mut app, HZ as usize - 1);
    let v = app.world().get::<Velocity>(free).unwrap().linear.x as f64;
    let discrete = (1.0 + c as f64 / HZ).powi(-(HZ as i32));
    assert!((v - discrete).abs() < 1e-5, "v {v} vs rapier's {discrete}");
    assert!(
        (v / (-(c as f64)).exp() - 1.0).abs() < 0.02,
        "v {v} vs e^-ct"
    );

    // Changing the damping on the live body: now none, the velocity stays.
    app.world_mut().entity_mut(free).insert(Damping::default());
    steps(&mut app, 1);
    let v1 = app.world().get::<Velocity>(free).unwrap().linear.x;
    steps(&mut app, 10);
    let v2 = app.world().get::<Velocity>(free).unwrap().linear.x;
    assert_eq!(v1, v2, "no damping: constant velocity");
}

#[test]
fn restitution_bounces_a_ball_back() {
    let mut app = app();
    let e = 0.8f32;
    app.world_mut().spawn((
        RigidBody::Fixed,
        Collider::cuboid(5.0, 0.1, 5.0),
        Restitution(e),
    ));
    let h = 0.5f32;
    let ball = app
        .world_mut()
        .spawn((
            RigidBody::Dynamic,
            Collider::ball(0.05),
            Restitution(e),
            Transform::from_xyz(0.0, 0.15 + h, 0.0),
        ))
        .id();
    // Fall, bounce, and find the top of the first bounce.
    let mut top = 0.0f32;
    let mut bounced = false;
    for _ in 0..(2 * HZ as usize) {
        steps(&mut app, 1);
        let y = pos(&app, ball).y - 0.15;
        let vy = app.world().get::<Velocity>(ball).unwrap().linear.y;
        if vy > 0.0 {
            bounced = true;
        }
        if bounced {
            top = top.max(y);
            if vy < 0.0 {
                break;
            }
        }
    }
    let expected = e * e * h;
    assert!(
        (top - expected).abs() < 0.05 * expected,
        "bounce height {top} m vs e²h = {expected} m"
    );
}

#[test]
fn colliders_deeper_in_the_hierarchy_join_their_body() {
    use stickslip_bevy::convert::to_bevy;
    let mut app = app();
    zero_gravity(&mut app);
    // body ─ arm (no collider, shifted and turned 90° about z) ─ collider 0.5 m along the
    // arm's x: the collider sits at body + (0.3, 0, 0) + R_z(90°)·(0.5, 0, 0) = (0.3, 0.5, 0).
    let arm = Transform::from_xyz(0.3, 0.0, 0.0)
        .with_rotation(Quat::from_rotation_z(std::f32::consts::FRAC_PI_2));
    let mut grandchild = Entity::PLACEHOLDER;
    let body = app
        .world_mut()
        .spawn((RigidBody::Dynamic, Transform::from_xyz(1.0, 2.0, 3.0)))
        .with_children(|p| {
            p.spawn(arm).with_children(|q| {
                grandchild = q
                    .spawn((Collider::ball(0.1), Transform::from_xyz(0.5, 0.0, 0.0)))
                    .id();
            });
        })
        .id();
    steps(&mut app, 1);
    let w = app.world().resource::<StickSlipWorld>();
    let h = w
        .collider(grandchild)
        .expect("the grandchild has a collider");
    let c = &w.physics.colliders[h];
    assert_eq!(
        c.parent(),
        w.body(body),
        "attached to the body two levels up"
    );
    let offset = to_bevy(c.position_wrt_parent().unwrap().translation);
    assert!(
        (offset - Vec3::new(0.3, 0.5, 0.0)).length() < 1e-6,
        "{offset}"
    );
    let world_at = to_bevy(c.position().translation);
    assert!(
        (world_at - Vec3::new(1.3, 2.5, 3.0)).length() < 1e-5,
        "{world_at}"
    );

    // The same hierarchy under no body: fixed where the hierarchy puts it; then a body
    // added at the root takes it over.
    let root = app
        .world_mut()
        .spawn(Transform::from_xyz(-1.0, 0.0, 0.0))
        .with_children(|p| {
            p.spawn(arm).with_children(|q| {
                grandchild = q
                    .spawn((Collider::ball(0.1), Transform::from_xyz(0.5, 0.0, 0.0)))
                    .id();
            });
        })
        .id();
    steps(&mut app, 1);
    let w = app.world().resource::<StickSlipWorld>();
    let c = &w.physics.colliders[w.collider(grandchild).unwrap()];
    assert!(c.parent().is_none(), "fixed");
    let at = to_bevy(c.position().translation);
    assert!((at - Vec3::new(-0.7, 0.5, 0.0)).length() < 1e-6, "{at}");
    app.world_mut().entity_mut(root).insert(RigidBody::Dynamic);
    steps(&mut app, 1);
    let w = app.world().resource::<StickSlipWorld>();
    let c = &w.physics.colliders[w.collider(grandchild).unwrap()];
    assert_eq!(c.parent(), w.body(root), "taken over by the new body");
    let offset = to_bevy(c.position_wrt_parent().unwrap().translation);
    assert!(
        (offset - Vec3::new(0.3, 0.5, 0.0)).length() < 1e-6,
        "{offset}"
    );
}
