//! The app's own avian features beside stickslip. Invariants: the app keeps its own
//! `CollisionHooks` (a one-way platform: a box thrown up from below passes through it, stickslip
//! stepping no contact of the pair while the hook removes it, then lands and rests on it with
//! its weight on the contact stickslip steps, and holds on it when gravity tilts to tan θ = 0.5,
//! between μ_k = 0.4 and μ_s = 0.6, as firmly as plain avian's `Friction::new(0.6)` holds
//! it, where plain avian with the same `Friction` slides it off); a `Sensor` gets no stickslip
//! contact and exerts no force (a box sliding through a static sensor and a kinematic one
//! moving with it, both with avian friction that stickslip would own, moves exactly as
//! without them); `CollisionLayers` that filter a pair leave it without contact while both boxes rest
//! and hold on the floor; and a box hung from a static anchor by a `RevoluteJoint` swings as in
//! plain avian (its angle within 1e-3 rad of plain avian's over 3 s) while a box resting on the
//! floor of the same world holds. (avian solves joints only with its `xpbd_joints` feature:
//! without it the bob falls free and the joint test says so.)

mod common;

use bevy::ecs::system::SystemParam;
use bevy::prelude::*;
use common::avian::prelude::*;
use common::stickslip_avian::StickSlipContacts;
use common::*;
use std::collections::HashSet;

const MU_K: f32 = 0.4;
const MU_S: f32 = 0.6;
/// Between μ_k and μ_s: held by static friction, slides at μ_k.
const TAN_HOLD: f64 = 0.5;

fn friction() -> Friction {
    Friction::new(MU_K).with_static_coefficient(MU_S)
}

/// The contacts stickslip stepped in the last tick between `a` and `b`.
fn contacts_between(app: &App, a: Entity, b: Entity) -> Vec<stickslip_avian::ContactReport> {
    app.world()
        .get_resource::<StickSlipContacts>()
        .map(|c| {
            c.0.iter()
                .filter(|c| {
                    (c.collider1 == a && c.collider2 == b) || (c.collider1 == b && c.collider2 == a)
                })
                .copied()
                .collect()
        })
        .unwrap_or_default()
}

/// Whether avian's contact graph has `a` and `b` touching.
fn touching(app: &App, a: Entity, b: Entity) -> bool {
    app.world()
        .resource::<ContactGraph>()
        .get(a, b)
        .is_some_and(|(_, pair)| pair.is_touching())
}

// ---------------------------------------------------------------------------------------
// A one-way platform, after avian's `one_way_platform_2d` example.

/// A platform bodies pass through from below and from the sides: the colliders passing
/// through it now.
#[derive(Component, Default)]
struct OneWayPlatform(HashSet<Entity>);

#[derive(SystemParam)]
struct PlatformHooks<'w, 's> {
    platforms: Query<'w, 's, (&'static OneWayPlatform, &'static Rotation)>,
}

impl CollisionHooks for PlatformHooks<'_, '_> {
    fn modify_contacts(&self, contacts: &mut ContactPair, commands: &mut Commands) -> bool {
        // The platform, the other collider, and the sign that turns the manifold's normal
        // (from collider 1 to collider 2) into one out of the platform.
        let (platform, (passing, rotation), other, sign) =
            if let Ok(p) = self.platforms.get(contacts.collider1) {
                (contacts.collider1, p, contacts.collider2, 1.0)
            } else if let Ok(p) = self.platforms.get(contacts.collider2) {
                (contacts.collider2, p, contacts.collider1, -1.0)
            } else {
                return true;
            };
        if passing.0.contains(&other) {
            let penetrating = contacts
                .manifolds
                .iter()
                .any(|m| m.points.iter().any(|p| p.penetration > 0.0));
            if penetrating {
                return false;
            }
            commands.queue(move |world: &mut World| {
                if let Some(mut p) = world.get_mut::<OneWayPlatform>(platform) {
                    p.0.remove(&other);
                }
            });
        }
        let up = up_of(rotation);
        let on_top = contacts.manifolds.iter().all(|m| {
            let n = m.normal * sign;
            n.length() > f32::EPSILON && n.dot(up) >= 0.5
        });
        if !on_top {
            commands.queue(move |world: &mut World| {
                if let Some(mut p) = world.get_mut::<OneWayPlatform>(platform) {
                    p.0.insert(other);
                }
            });
        }
        on_top
    }
}

/// The platform's top (m).
const PLATFORM_TOP: f32 = 2.1;

/// What happened to a box thrown up through a one-way platform from the floor under it.
#[derive(Debug)]
struct Platform {
    /// Highest point of the box's centre (m).
    apex: f32,
    /// Ticks the box overlapped the platform on its way up.
    passing_ticks: usize,
    /// stickslip contacts of the pair in those ticks.
    passing_contacts: usize,
    /// The box's height and speed 3 s after the throw.
    rest_y: f32,
    rest_speed: f32,
    /// Normal force of the platform–box contact stickslip stepped then (N).
    normal_force: Option<f64>,
    /// The box's slide along x in 3 s after gravity tilted to `TAN_HOLD`.
    slide: f64,
}

fn one_way_platform(stickslip: bool, material: Friction) -> Platform {
    let mut app = app_with_hooks::<PlatformHooks>(stickslip, 6, 0.0);
    floor(&mut app, material);
    let platform = app
        .world_mut()
        .spawn((
            RigidBody::Static,
            cuboid_collider(8.0, 0.2, 8.0),
            Transform::from_xyz(0.0, PLATFORM_TOP - 0.1, 0.0),
            OneWayPlatform::default(),
            ActiveCollisionHooks::MODIFY_CONTACTS,
            material,
        ))
        .id();
    let b = block(
        &mut app,
        0.0,
        (material, linear_velocity(Vec3::new(0.0, 9.0, 0.0))),
    );
    let mut out = Platform {
        apex: 0.0,
        passing_ticks: 0,
        passing_contacts: 0,
        rest_y: 0.0,
        rest_speed: 0.0,
        normal_force: None,
        slide: 0.0,
    };
    for _ in 0..180 {
        app.update();
        let p = position(&app, b);
        let v = velocity(&app, b);
        out.apex = out.apex.max(p.y);
        // Overlapping the platform (its 0.2 m slab) on the way up.
        if v.y > 0.5 && p.y + 0.25 > PLATFORM_TOP - 0.2 && p.y - 0.25 < PLATFORM_TOP {
            out.passing_ticks += 1;
            out.passing_contacts += contacts_between(&app, platform, b).len();
        }
    }
    out.rest_y = position(&app, b).y;
    out.rest_speed = velocity(&app, b).length();
    if stickslip {
        let c = contacts_between(&app, platform, b);
        out.normal_force = Some(c.iter().map(|c| c.normal_force).sum());
    }
    tilt(&mut app, TAN_HOLD.atan());
    run(&mut app, 30);
    let x0 = position(&app, b).x as f64;
    run(&mut app, 180);
    out.slide = position(&app, b).x as f64 - x0;
    out
}

#[test]
fn a_one_way_platform_lets_a_box_through_then_holds_it() {
    let ss = one_way_platform(true, friction());
    let same = one_way_platform(false, friction());
    let hold = one_way_platform(false, Friction::new(MU_S));
    println!("one-way platform, stickslip Friction(0.4, s 0.6): {ss:?}");
    println!("one-way platform, plain Friction(0.4, s 0.6):     {same:?}");
    println!("one-way platform, plain Friction(0.6):            {hold:?}");
    for (label, p) in [("stickslip", &ss), ("plain", &same), ("plain 0.6", &hold)] {
        assert!(
            p.apex > PLATFORM_TOP + 1.0 && p.passing_ticks > 0,
            "{label}: the box did not pass through the platform: {p:?}"
        );
        assert!(
            (p.rest_y - (PLATFORM_TOP + 0.25)).abs() < 0.01 && p.rest_speed < 0.01,
            "{label}: the box does not rest on the platform: {p:?}"
        );
    }
    assert_eq!(
        ss.passing_contacts, 0,
        "stickslip stepped a contact the app's hook removed"
    );
    // Its weight (1 kg) on the contact.
    let f_n = ss.normal_force.unwrap_or(0.0);
    assert!(
        (f_n / G - 1.0).abs() < 0.05,
        "platform–box normal force {f_n} N, weight {G} N"
    );
    assert!(
        ss.slide.abs() <= hold.slide.abs() * 1.1 + 1e-6 && ss.slide.abs() < 0.02,
        "tan θ {TAN_HOLD}: stickslip crept {} m, plain avian's hold at μ_s {} m",
        ss.slide,
        hold.slide
    );
    assert!(
        same.slide > 0.1,
        "plain avian at tan θ {TAN_HOLD} should slide at μ_k: {} m",
        same.slide
    );
}

// ---------------------------------------------------------------------------------------
// Sensors.

/// A box sliding down tan θ = 0.9 (above μ_s) through a static sensor on its path, a
/// kinematic sensor inside it at the start moving down the slope at 1 m/s: the box's position (x, y) every 10 ticks over 1.5 s, the
/// stickslip contacts that involved a sensor, and the ticks a sensor touched the box in
/// avian's contact graph.
fn through_sensors(sensors: bool) -> (Vec<Vec3>, usize, usize) {
    let mut app = app(true, 6, 0.9f64.atan());
    floor(&mut app, friction());
    let b = block(&mut app, 0.0, friction());
    let mut ids = Vec::new();
    if sensors {
        ids.push(
            app.world_mut()
                .spawn((
                    RigidBody::Static,
                    cuboid_collider(1.0, 1.0, 2.0),
                    Transform::from_xyz(1.0, 0.4, 0.0),
                    Sensor,
                    friction(),
                ))
                .id(),
        );
        ids.push(
            app.world_mut()
                .spawn((
                    RigidBody::Kinematic,
                    ball_collider(0.4),
                    Transform::from_xyz(0.0, 0.3, 0.0),
                    linear_velocity(Vec3::new(1.0, 0.0, 0.0)),
                    Sensor,
                    friction(),
                ))
                .id(),
        );
    }
    let mut path = Vec::new();
    let (mut sensor_contacts, mut overlaps) = (0, 0);
    for tick in 1..=90 {
        app.update();
        for &s in &ids {
            sensor_contacts += app.world().resource::<StickSlipContacts>().of(s).count();
            overlaps += touching(&app, s, b) as usize;
        }
        if tick % 10 == 0 {
            path.push(position(&app, b));
        }
    }
    (path, sensor_contacts, overlaps)
}

#[test]
fn a_sensor_gets_no_contact_and_exerts_no_force() {
    let (with, sensor_contacts, overlaps) = through_sensors(true);
    let (without, ..) = through_sensors(false);
    let gap = with
        .iter()
        .zip(&without)
        .map(|(a, b)| (*a - *b).length())
        .fold(0.0f32, f32::max);
    println!(
        "sensors: the box overlapped a sensor in {overlaps} sensor-ticks, stickslip contacts with a sensor {sensor_contacts}, largest gap to the run without sensors {gap:e} m, slid {:.3} m",
        with.last().map_or(f32::NAN, |p| p.x)
    );
    assert!(
        overlaps > 10,
        "the box never overlapped the sensors: {overlaps}"
    );
    assert_eq!(sensor_contacts, 0, "stickslip stepped a sensor contact");
    assert!(gap < 1e-5, "the sensors moved the box by {gap} m");
    // It slid (tan θ 0.9 is above break-away): through the static sensor, 1 m down the slope.
    assert!(with.last().is_some_and(|p| p.x > 1.5), "{with:?}");
}

// ---------------------------------------------------------------------------------------
// Collision layers.

/// Two boxes spawned in one place on the floor, in layers that do not interact, gravity
/// tilted to `TAN_HOLD`: their slides along x over 3 s after 0.5 s, their normal forces on
/// the floor as stickslip measured them, and the ticks stickslip or avian had a contact
/// between them.
fn layered(stickslip: bool, material: Friction) -> ([f64; 2], [f64; 2], usize) {
    let mut app = app(stickslip, 6, TAN_HOLD.atan());
    let f = floor(
        &mut app,
        (material, CollisionLayers::new(0b001, LayerMask::ALL)),
    );
    let a = block(
        &mut app,
        0.0,
        (material, CollisionLayers::new(0b010, 0b001)),
    );
    let b = block(
        &mut app,
        0.0,
        (material, CollisionLayers::new(0b100, 0b001)),
    );
    let mut between = 0;
    let mut step = |app: &mut App, n: usize| {
        for _ in 0..n {
            app.update();
            between += contacts_between(app, a, b).len() + touching(app, a, b) as usize;
        }
    };
    step(&mut app, 30);
    let x0 = [position(&app, a).x as f64, position(&app, b).x as f64];
    step(&mut app, 180);
    let slides = [
        position(&app, a).x as f64 - x0[0],
        position(&app, b).x as f64 - x0[1],
    ];
    let load = |e: Entity| {
        contacts_between(&app, f, e)
            .iter()
            .map(|c| c.normal_force)
            .sum()
    };
    (slides, [load(a), load(b)], between)
}

#[test]
fn collision_layers_filter_a_pair_out() {
    let (slides, loads, between) = layered(true, friction());
    let (hold, ..) = layered(false, Friction::new(MU_S));
    let (same, _, plain_between) = layered(false, friction());
    println!(
        "layers, tan θ {TAN_HOLD}: stickslip slides {slides:?} m, floor loads {loads:?} N (m g cos θ = {:.3}), contacts between the boxes {between}; plain Friction(0.6) slides {hold:?}, plain Friction(0.4, s 0.6) slides {same:?} (contacts between {plain_between})",
        G * TAN_HOLD.atan().cos()
    );
    assert_eq!(
        between, 0,
        "stickslip or avian had a contact between filtered boxes"
    );
    assert_eq!(plain_between, 0);
    let weight = G * TAN_HOLD.atan().cos();
    for i in 0..2 {
        assert!(
            (loads[i] / weight - 1.0).abs() < 0.05,
            "box {i}: floor load {} N vs m g cos θ {weight} N",
            loads[i]
        );
        assert!(
            slides[i].abs() <= hold[i].abs() * 1.1 + 1e-6 && slides[i].abs() < 0.02,
            "box {i}: crept {} m, plain avian's hold at μ_s {} m",
            slides[i],
            hold[i]
        );
        assert!(
            same[i] > 0.1,
            "plain avian box {i} should slide at μ_k: {}",
            same[i]
        );
    }
}

// ---------------------------------------------------------------------------------------
// Joints.

/// A box hung 2 m under a static anchor by a revolute joint (hinge along z), let go at
/// −0.5 rad, beside a box resting on the floor, gravity tilted to `TAN_HOLD`: the pendulum's
/// angle every tick over 3 s, the resting box's slide along x over those 3 s, and how far
/// the bob's distance to the anchor strayed from 2 m.
fn pendulum(stickslip: bool) -> (Vec<f32>, f64, f32) {
    let mut app = app(stickslip, 6, TAN_HOLD.atan());
    floor(&mut app, friction());
    let resting = block(&mut app, 0.0, friction());
    let anchor_at = Vec3::new(-20.0, 6.0, 0.0);
    let anchor = app
        .world_mut()
        .spawn((RigidBody::Static, Transform::from_translation(anchor_at)))
        .id();
    let phi0 = -0.5f32;
    let bob = app
        .world_mut()
        .spawn((
            RigidBody::Dynamic,
            cuboid_collider(0.5, 0.5, 0.5),
            Mass(1.0),
            Transform::from_translation(anchor_at + 2.0 * Vec3::new(phi0.sin(), -phi0.cos(), 0.0))
                .with_rotation(Quat::from_rotation_z(phi0)),
            SleepingDisabled,
            friction(),
        ))
        .id();
    app.world_mut()
        .spawn(RevoluteJoint::new(anchor, bob).with_local_anchor2(v(0.0, 2.0, 0.0)));
    let x0 = position(&app, resting).x as f64;
    let angle = |app: &App| {
        let r = rotation(app, bob);
        2.0 * r.z.atan2(r.w)
    };
    let mut angles = Vec::new();
    let mut stretch = 0.0f32;
    for _ in 0..180 {
        app.update();
        angles.push(angle(&app));
        stretch = stretch.max(((position(&app, bob) - anchor_at).length() - 2.0).abs());
    }
    (angles, position(&app, resting).x as f64 - x0, stretch)
}

#[test]
fn a_jointed_pendulum_swings_as_in_plain_avian() {
    let (ss, held, ss_stretch) = pendulum(true);
    let (plain, slid, plain_stretch) = pendulum(false);
    let gap = ss
        .iter()
        .zip(&plain)
        .map(|(a, b)| (a - b).abs())
        .fold(0.0f32, f32::max);
    let swing = |a: &[f32]| {
        a.iter().cloned().fold(f32::MIN, f32::max) - a.iter().cloned().fold(f32::MAX, f32::min)
    };
    println!(
        "pendulum: angle range stickslip {:.4} rad, plain {:.4} rad, largest angle gap {gap:e} rad; resting box slid {held:e} m with stickslip, {slid:.3} m in plain avian (μ_k)",
        swing(&ss),
        swing(&plain)
    );
    println!(
        "pendulum: bob–anchor distance off 2 m by ≤ {ss_stretch} m (stickslip), {plain_stretch} m (plain)"
    );
    // The joint holds the bob (avian solves joints only with its `xpbd_joints` feature;
    // its XPBD joint stretches by 1 cm as the bob swings).
    assert!(
        plain_stretch < 0.05 && ss_stretch < 0.05,
        "the joint does not hold: the bob strays {plain_stretch} m (plain), {ss_stretch} m (stickslip) from 2 m — is avian3d's `xpbd_joints` feature on?"
    );
    // It swings (the tilted gravity's equilibrium is at +0.46 rad, it starts at −0.5).
    assert!(
        swing(&plain) > 1.0,
        "plain pendulum swings {}",
        swing(&plain)
    );
    assert!(gap < 1e-3, "the pendulum's angle differs by {gap} rad");
    assert!(held.abs() < 0.02, "the resting box crept {held} m");
    assert!(
        slid > 0.1,
        "plain avian's resting box should slide at μ_k: {slid} m"
    );
}
