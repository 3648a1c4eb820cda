//! In a user's world stickslip touches only what it was given: pairs without an attached
//! collider, hooked by the user's own wrapped hook (a slippery pad, a conveyor belt), move bit
//! for bit as with the user's hook alone; two materials combine by the colliders' rapier
//! combine rules into the documented coefficients (hold below, slide above the combined
//! break-away coefficient; sliding at g (sin θ − μ_k cos θ) of the combined curve); whichever
//! collider rapier lists first, the pair's law is the same bit for bit and the trajectories
//! differ no more than plain rapier's own do (its friction basis follows the pair's normal,
//! which flips with the order); a per-pair material wins; an unattached collider brings its
//! rapier friction. The user's wrapped hook is called on exactly the pairs rapier calls it
//! for without stickslip (a pair whose only hook flag is stickslip's is not theirs; one they
//! flag and stickslip also owns is theirs and the law's), and detaching turns off only
//! stickslip's flag. A panicking wrapped hook leaves no lock held: the next steps
//! finish (bounded by a join timeout, not by the test harness) and the world is consistent.
//! Composite shapes keep one record per manifold. The silent cases speak: reports and totals
//! are an error when read-back is off, a hook call without `begin_step`, a non-Simplified
//! friction model and a step dt out of range (not a pause, dt = 0) log a warning once.
//! A one-way platform (rapier's `update_as_oneway_platform`, which keeps its state in the
//! manifold's `user_data`) that stickslip also owns lets a box through from below bit for bit
//! as the user's hook alone, and once the box has landed on top the law holds it (μ 0.5 >
//! tan θ 0.3) where the platform's rapier friction 0.1 lets it slide. All in 3D and in 2D
//! (stickslip-fixtures2d).

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Mutex, OnceLock};
use std::time::Duration;
use stickslip_core::law::{FrictionLaw, Law};
use stickslip_core::sliding_curve::Curve;
use stickslip_fixtures::dim::cuboid_shape;
use stickslip_fixtures::{cuboid3, v3};
use stickslip_rapier::rapier::prelude::*;
use stickslip_rapier::{FrictionMaterial, NotReadBack, ReadBack, StickSlip};

const G: f64 = 9.81;
const DT: f32 = 1.0 / 60.0;

fn ep(mu_ba: f64, mu_k: f64) -> Law {
    Law::elasto_plastic(1e4, mu_ba, mu_ba.max(mu_k), Curve::constant(mu_k).unwrap()).unwrap()
}

/// A world whose gravity is tilted to `tan_theta` down +x, stepped at [`DT`].
fn tilted_world(tan_theta: f64) -> PhysicsWorld {
    let mut world = PhysicsWorld::default();
    let th = tan_theta.atan();
    world.gravity = v3((G * th.sin()) as f32, -(G * th.cos()) as f32, 0.0);
    world.integration_parameters.dt = DT;
    world
}

fn cube(at: Vector) -> (RigidBodyBuilder, ColliderBuilder) {
    (
        RigidBodyBuilder::dynamic().translation(at).can_sleep(false),
        cuboid3(0.1, 0.1, 0.1).0.density(1000.0),
    )
}

/// The user's own hooks: a pad their hook makes slippery (friction 0.05) and a belt whose
/// surface moves at 0.5 m/s up the slope (−x).
struct UserHooks {
    pad: ColliderHandle,
    belt: ColliderHandle,
}

const BELT_SPEED: f32 = -0.5;

impl PhysicsHooks for UserHooks {
    fn modify_solver_contacts(&self, ctx: &mut ContactModificationContext) {
        let (c1, c2) = (ctx.collider1, ctx.collider2);
        // rapier 0.35 keeps the manifold's friction and contacts on the context.
        #[cfg(rapier_035)]
        let (friction, contacts) = (&mut *ctx.friction, &mut *ctx.solver_contacts);
        #[cfg(not(rapier_035))]
        let Some(m) = ctx.rigid_mut() else { return };
        #[cfg(not(rapier_035))]
        let (friction, contacts) = (&mut *m.friction, &mut *m.solver_contacts);
        if c1 == self.pad || c2 == self.pad {
            *friction = 0.05;
        }
        if c1 == self.belt || c2 == self.belt {
            let v = if c1 == self.belt {
                BELT_SPEED
            } else {
                -BELT_SPEED
            };
            for c in contacts.iter_mut() {
                c.tangent_velocity = v3(v, 0.0, 0.0);
            }
        }
    }
}

#[test]
fn pairs_stickslip_does_not_own_are_the_users_bit_for_bit() {
    let tan_theta = 0.3;
    let build = || {
        let mut world = tilted_world(tan_theta);
        let flag = ActiveHooks::MODIFY_SOLVER_CONTACTS;
        let slab = |x: f32| cuboid3(8.0, 0.1, 2.0).0.translation(v3(x, -0.1, 0.0));
        let ground = world.insert_collider(slab(-60.0), None);
        let pad = world.insert_collider(slab(-20.0).active_hooks(flag), None);
        let belt = world.insert_collider(slab(20.0).active_hooks(flag), None);
        // Neither hooked nor attached: rapier's own friction (0.5 by default).
        let plain = world.insert_collider(slab(60.0), None);
        let mut boxes = Vec::new();
        let mut colliders = Vec::new();
        for x in [-60.0, -20.0, 20.0, 60.0] {
            let (b, c) = cube(v3(x, 0.1, 0.0));
            let (b, c) = world.insert(b, c);
            boxes.push(b);
            colliders.push(c);
        }
        let _ = plain;
        (
            world,
            [ground, colliders[0]],
            UserHooks { pad, belt },
            boxes,
        )
    };
    let steps = 120;
    let record = |world: &PhysicsWorld, boxes: &[RigidBodyHandle]| -> Vec<(Vector, Vector)> {
        boxes[1..]
            .iter()
            .map(|b| {
                let rb = &world.bodies[*b];
                (rb.translation(), rb.linvel())
            })
            .collect()
    };
    // The user's hooks alone.
    let (mut world, _, hooks, boxes) = build();
    let mut alone = Vec::new();
    for _ in 0..steps {
        world.step_with_events(&hooks, &());
        alone.push(record(&world, &boxes));
    }
    // The same hooks wrapped in stickslip, with only the far ground and its box attached.
    let (mut world, attached, hooks, boxes) = build();
    let mut m = StickSlip::with_hooks(FrictionMaterial::new(ep(0.5, 0.5)), hooks);
    for h in attached {
        m.attach(&mut world.colliders, h, None);
    }
    let mut x0 = 0.0;
    for (k, want) in alone.iter().enumerate() {
        m.step(&mut world);
        if k == 10 {
            // The contact has formed.
            x0 = world.bodies[boxes[0]].translation().x;
        }
        assert_eq!(
            &record(&world, &boxes),
            want,
            "step {k}: the user's pairs changed"
        );
    }
    // The physics: the pad slides at g (sin θ − 0.05 cos θ) from rest, the belt carries its
    // box at its speed, rapier's own friction 0.5 holds the unhooked box, and stickslip
    // holds its box (μ 0.5 > tan θ 0.3) within its elastic range g_ba = 50 µm.
    let t = steps as f64 * DT as f64;
    let th = tan_theta.atan();
    let a = G * (th.sin() - 0.05 * th.cos());
    let v_pad = world.bodies[boxes[1]].linvel().x as f64;
    println!("pad: v {v_pad:.4} m/s vs {:.4}", a * t);
    assert!((v_pad / (a * t) - 1.0).abs() < 0.03, "pad {v_pad}");
    let v_belt = world.bodies[boxes[2]].linvel().x;
    println!("belt: v {v_belt:.4} m/s vs {BELT_SPEED}");
    assert!((v_belt - BELT_SPEED).abs() < 1e-3, "belt {v_belt}");
    let held_dx = (world.bodies[boxes[0]].translation().x - x0).abs();
    println!("stickslip's box: crept {held_dx:.2e} m");
    assert!(held_dx < 5e-5, "stickslip's box crept {held_dx} m");
    assert_eq!(
        m.active_contacts(),
        1,
        "only the attached pair has a record"
    );
}

/// The user's hook that only records which pairs rapier called it for.
#[derive(Default)]
struct Recorder(Mutex<std::collections::HashSet<(ColliderHandle, ColliderHandle)>>);

impl PhysicsHooks for Recorder {
    fn modify_solver_contacts(&self, ctx: &mut ContactModificationContext) {
        let (a, b) = (ctx.collider1, ctx.collider2);
        let pair = if a.0.into_raw_parts() < b.0.into_raw_parts() {
            (a, b)
        } else {
            (b, a)
        };
        self.0.lock().unwrap().insert(pair);
    }
}

#[test]
fn the_users_hook_sees_the_pairs_it_sees_without_stickslip() {
    // Three grounds, a box on each: one attached without a user flag (stickslip's alone), one
    // the user flags (their hook's alone), one both (the user's hook and the law).
    let build = || {
        let mut world = tilted_world(0.3);
        let flag = ActiveHooks::MODIFY_SOLVER_CONTACTS;
        let ground = |x: f32| cuboid3(2.0, 0.1, 2.0).0.translation(v3(x, -0.1, 0.0));
        let stickslips = world.insert_collider(ground(-10.0), None);
        let users = world.insert_collider(ground(0.0).active_hooks(flag), None);
        let both = world.insert_collider(ground(10.0).active_hooks(flag), None);
        let mut boxes = Vec::new();
        for x in [-10.0, 0.0, 10.0] {
            let (b, c) = cube(v3(x, 0.1, 0.0));
            boxes.push(world.insert(b, c).1);
        }
        (world, [stickslips, users, both], boxes)
    };
    let steps = 30;
    let (mut world, _, _) = build();
    let alone = Recorder::default();
    for _ in 0..steps {
        world.step_with_events(&alone, &());
    }
    let alone = alone.0.into_inner().unwrap();
    let (mut world, [stickslips, users, both], boxes) = build();
    let mut m = StickSlip::with_hooks(FrictionMaterial::new(ep(0.5, 0.5)), Recorder::default());
    for h in [stickslips, both, boxes[0]] {
        m.attach(&mut world.colliders, h, None);
    }
    // Attaching again (a new material) does not make stickslip's flag the user's.
    m.attach(&mut world.colliders, stickslips, None);
    for _ in 0..steps {
        m.step(&mut world);
    }
    let with = std::mem::take(&mut *m.inner().0.lock().unwrap());
    let pair = |a: ColliderHandle, b: ColliderHandle| {
        if a.0.into_raw_parts() < b.0.into_raw_parts() {
            (a, b)
        } else {
            (b, a)
        }
    };
    assert!(alone.contains(&pair(users, boxes[1])), "{alone:?}");
    assert!(alone.contains(&pair(both, boxes[2])), "{alone:?}");
    assert_eq!(
        with, alone,
        "the user's hook saw other pairs with stickslip attached"
    );
    assert!(!with.contains(&pair(stickslips, boxes[0])));
    // Both attached boxes have a record: the law acts where the user's hook also does.
    assert_eq!(m.active_contacts(), 2);
    // Detaching turns off only stickslip's flag.
    m.detach(&mut world.colliders, stickslips);
    m.detach(&mut world.colliders, both);
    let flagged = |h: ColliderHandle| {
        world.colliders[h]
            .active_hooks()
            .contains(ActiveHooks::MODIFY_SOLVER_CONTACTS)
    };
    assert!(!flagged(stickslips));
    assert!(flagged(both) && flagged(users));
}

/// The user's one-way platform: contacts are kept only while the platform's normal (from
/// the platform) points up.
struct OneWay {
    platform: ColliderHandle,
}

impl PhysicsHooks for OneWay {
    fn modify_solver_contacts(&self, ctx: &mut ContactModificationContext) {
        let allowed = if ctx.collider1 == self.platform {
            Vector::Y
        } else if ctx.collider2 == self.platform {
            -Vector::Y
        } else {
            return;
        };
        ctx.update_as_oneway_platform(allowed, 0.1);
    }
}

#[test]
fn a_one_way_platform_stickslip_also_owns_lets_boxes_through_and_the_law_holds_them() {
    let tan_theta = 0.3;
    const TOP: f32 = 2.1;
    let build = || {
        let mut world = tilted_world(tan_theta);
        let platform = world.insert_collider(
            cuboid3(8.0, 0.1, 2.0)
                .0
                .translation(v3(0.0, 2.0, 0.0))
                .friction(0.1)
                .active_hooks(ActiveHooks::MODIFY_SOLVER_CONTACTS),
            None,
        );
        // Thrown up from below the platform, through it, to land on top.
        let (b, c) = world.insert(
            RigidBodyBuilder::dynamic()
                .translation(v3(-3.0, 1.0, 0.0))
                .linvel(v3(0.0, 6.5, 0.0))
                .lock_rotations()
                .can_sleep(false),
            cuboid3(0.1, 0.1, 0.1).0.density(1000.0).friction(0.1),
        );
        (world, platform, b, c)
    };
    let steps = 180;
    let (mut world, platform, b, _) = build();
    let hook = OneWay { platform };
    let mut alone = Vec::new();
    for _ in 0..steps {
        world.step_with_events(&hook, &());
        let rb = &world.bodies[b];
        alone.push((rb.translation(), rb.linvel()));
    }
    let (mut world, platform, b, c) = build();
    let mut m = StickSlip::with_hooks(FrictionMaterial::new(ep(0.5, 0.5)), OneWay { platform });
    m.attach(&mut world.colliders, platform, None);
    m.attach(&mut world.colliders, c, None);
    let mut with = Vec::new();
    for _ in 0..steps {
        m.step(&mut world);
        let rb = &world.bodies[b];
        with.push((rb.translation(), rb.linvel()));
    }
    // Through the platform both ways alike: the first step that differs has the box on top.
    let first = (0..steps).find(|k| alone[*k] != with[*k]).unwrap_or(steps);
    let went_above = alone.iter().position(|(p, _)| p.y > TOP + 0.1).unwrap();
    println!(
        "above the platform from step {went_above}; trajectories identical up to step {first} \
         (y {:.4})",
        with.get(first).map_or(f32::NAN, |s| s.0.y)
    );
    assert!(
        first > went_above,
        "stickslip changed the pass through the platform"
    );
    assert!(
        with[first].0.y > TOP + 0.1 - 0.01,
        "the first difference is not on top of the platform: {:?}",
        with[first]
    );
    // On top: the law holds (μ 0.5 > tan θ 0.3) where the platform's friction 0.1 lets the box
    // slide under the user's hook alone.
    let rest = &with[steps - 61..];
    let crept = rest[60].0.x - rest[0].0.x;
    let slid = alone[steps - 1].0.x - alone[steps - 61].0.x;
    println!("last second on top: stickslip crept {crept:.2e} m, the hook alone slid {slid:.3} m");
    assert!(rest.iter().all(|s| s.0.y > TOP), "the box fell through");
    assert!(
        crept.abs() < 5e-5,
        "the law did not hold the box: {crept} m"
    );
    assert!(slid > 0.5, "the platform's rapier friction held the box");
    assert_eq!(m.active_contacts(), 1);
}

/// One side of the incline pair.
#[derive(Clone)]
enum Side {
    /// Attached with this law, the collider's rapier combine rule.
    Attached(Law, CoefficientCombineRule),
    /// Not attached: rapier friction and combine rule.
    Plain(f32, CoefficientCombineRule),
}

struct Incline {
    ground: Side,
    cube: Side,
    pair: Option<Law>,
    tan_theta: f64,
    cube_first: bool,
}

/// The cube's position after each step for 1 s on the tilted ground, with stickslip (or, with
/// `plain`, rapier alone with each side's break-away coefficient as its friction), and the
/// pair's law.
fn run_incline(s: &Incline, plain: bool) -> (Vec<Vector>, Option<Law>) {
    let mut world = tilted_world(s.tan_theta);
    let collider = |side: &Side, b: ColliderBuilder| match side {
        Side::Attached(law, rule) => b
            .friction(law.static_coefficient() as f32)
            .friction_combine_rule(*rule),
        Side::Plain(mu, rule) => b.friction(*mu).friction_combine_rule(*rule),
    };
    let ground_builder =
        collider(&s.ground, cuboid3(5.0, 0.1, 5.0).0).translation(Vector::Y * -0.1);
    let (body, cube_builder) = cube(v3(0.0, 0.1, 0.0));
    let cube_builder = collider(&s.cube, cube_builder);
    let (ground, (b, c)) = if s.cube_first {
        let bc = world.insert(body, cube_builder);
        (world.insert_collider(ground_builder, None), bc)
    } else {
        let g = world.insert_collider(ground_builder, None);
        (g, world.insert(body, cube_builder))
    };
    let mut m = StickSlip::new(FrictionMaterial::new(ep(0.5, 0.5)));
    for (side, h) in [(&s.ground, ground), (&s.cube, c)] {
        if let Side::Attached(law, _) = side {
            m.attach(
                &mut world.colliders,
                h,
                Some(FrictionMaterial::new(law.clone())),
            );
        }
    }
    if let Some(law) = &s.pair {
        m.set_pair_material(c, ground, law.clone());
    }
    let law = m.pair_law(&world.colliders, ground, c);
    assert_eq!(
        law,
        m.pair_law(&world.colliders, c, ground),
        "pair law not symmetric"
    );
    let xs = (0..60)
        .map(|_| {
            if plain {
                world.step();
            } else {
                m.step(&mut world);
            }
            world.bodies[b].translation()
        })
        .collect();
    (xs, law)
}

fn incline(s: &Incline) -> Vec<Vector> {
    run_incline(s, false).0
}

/// Both insertion orders: the pair's law is the same bit for bit, and the trajectories differ
/// no more than plain rapier's do (rapier's tangent basis follows the pair's normal, which
/// flips with the order: the cube's sideways settling mirrors).
fn assert_order_free(s: &Incline, what: &str) {
    let flipped = Incline {
        cube_first: !s.cube_first,
        ground: s.ground.clone(),
        cube: s.cube.clone(),
        pair: s.pair.clone(),
        tan_theta: s.tan_theta,
    };
    let (a, law_a) = run_incline(s, false);
    let (b, law_b) = run_incline(&flipped, false);
    assert_eq!(law_a, law_b, "{what}: the law depends on the order");
    let (pa, _) = run_incline(s, true);
    let (pb, _) = run_incline(&flipped, true);
    // Across the slope: |z| in 3D (the sideways settling mirrors), y in 2D.
    #[cfg(not(dim2))]
    let across = |p: &Vector| p.z.abs();
    #[cfg(dim2)]
    let across = |p: &Vector| p.y;
    let gap = |u: &[Vector], v: &[Vector]| {
        u.iter()
            .zip(v)
            .map(|(p, q)| ((p.x - q.x).abs(), (across(p) - across(q)).abs()))
            .fold((0.0f32, 0.0f32), |m, d| (m.0.max(d.0), m.1.max(d.1)))
    };
    let (ours, rapiers) = (gap(&a, &b), gap(&pa, &pb));
    eprintln!("{what}: order gap stickslip {ours:?}, plain rapier {rapiers:?}");
    assert!(
        ours.0 <= 1.05 * rapiers.0 + 1e-7 && ours.1 <= 1.05 * rapiers.1 + 1e-7,
        "{what}: order gap {ours:?} vs plain rapier's {rapiers:?}"
    );
}

fn moved(s: &Incline) -> f64 {
    let xs = incline(s);
    (xs[59].x - xs[0].x) as f64
}

#[test]
fn materials_combine_by_rapiers_rules_whichever_collider_is_first() {
    use CoefficientCombineRule as R;
    let attached = |mu, rule| Side::Attached(ep(mu, mu), rule);
    let case = |ground: Side, cube: Side, tan_theta: f64| Incline {
        ground,
        cube,
        pair: None,
        tan_theta,
        cube_first: false,
    };
    // Ground μ 0.3, cube μ 0.8, both attached: Average 0.55, Min 0.3, Max 0.8, GeometricMean
    // √0.24 = 0.49; the cube's rule decides when it is higher (rapier's order).
    let cases = [
        (R::Average, 0.55),
        (R::Min, 0.3),
        (R::Max, 0.8),
        (R::GeometricMean, 0.24f64.sqrt()),
    ];
    for (rule, mu) in cases {
        for (r_ground, r_cube) in [(R::Average, rule), (rule, R::Average)] {
            let below = case(attached(0.3, r_ground), attached(0.8, r_cube), 0.93 * mu);
            let above = case(attached(0.3, r_ground), attached(0.8, r_cube), 1.07 * mu);
            let (hold, slide) = (moved(&below), moved(&above));
            assert!(hold.abs() < 1e-3, "{rule:?}: held cube moved {hold} m");
            assert!(
                slide > 0.02,
                "{rule:?}: cube above μ = {mu} moved only {slide} m"
            );
            assert_order_free(&below, &format!("{rule:?} below"));
            assert_order_free(&above, &format!("{rule:?} above"));
        }
    }
    // Static above kinetic, Average: μ_ba (0.3+0.8)/2 = 0.55, μ_k (0.2+0.6)/2 = 0.4; sliding
    // from rest above break-away accelerates at g (sin θ − 0.4 cos θ).
    let sliding = case(
        Side::Attached(ep(0.3, 0.2), R::Average),
        Side::Attached(ep(0.8, 0.6), R::Average),
        0.6,
    );
    let xs = incline(&sliding);
    let th = 0.6f64.atan();
    let a = G * (th.sin() - 0.4 * th.cos());
    let (t1, t2) = (20.0 * DT as f64, 59.0 * DT as f64);
    let measured = 2.0 * ((xs[59].x - xs[20].x) as f64 / (t2 - t1) - 0.0) / (t2 + t1);
    // x(t) = x_b + a (t − t_b)²/2 after break-away t_b: the mean speed over [t1, t2] is
    // a ((t1 + t2)/2 − t_b); compare speeds at two windows instead of assuming t_b.
    let v = |i: usize, j: usize| (xs[j].x - xs[i].x) as f64 / ((j - i) as f64 * DT as f64);
    let accel = (v(40, 59) - v(20, 39)) / (20.0 * DT as f64);
    assert!(
        (accel - a).abs() < 0.02 * a,
        "combined kinetic friction: a = {accel} vs {a} (mean-speed estimate {measured})"
    );

    // The pair's own material wins over any rule.
    let mut s = case(attached(0.3, R::Max), attached(0.8, R::Max), 0.3);
    assert!(moved(&s).abs() < 1e-3);
    s.pair = Some(ep(0.2, 0.2));
    assert!(moved(&s) > 0.02, "pair material μ 0.2 did not win");

    // Attached ground (μ 0.3) against an unattached cube with rapier friction 0.7: Average
    // 0.5; with the cube's rule Min, 0.3.
    let plain = |mu, rule| Side::Plain(mu, rule);
    assert!(
        moved(&case(
            attached(0.3, R::Average),
            plain(0.7, R::Average),
            0.46
        ))
        .abs()
            < 1e-3
    );
    assert!(
        moved(&case(
            attached(0.3, R::Average),
            plain(0.7, R::Average),
            0.54
        )) > 0.02
    );
    assert!(moved(&case(attached(0.3, R::Average), plain(0.7, R::Min), 0.46)) > 0.02);
    assert_order_free(
        &case(attached(0.3, R::Average), plain(0.7, R::Average), 0.54),
        "attached vs plain",
    );
}

/// A wrapped hook that panics once when armed.
struct Panicky(AtomicBool);

impl PhysicsHooks for Panicky {
    fn modify_solver_contacts(&self, _: &mut ContactModificationContext) {
        if self.0.swap(false, Ordering::SeqCst) {
            panic!("the user's hook panics");
        }
    }
}

#[test]
fn a_panicking_wrapped_hook_leaves_no_lock_held() {
    let mut world = tilted_world(0.2);
    let ground = world.insert_collider(
        cuboid3(20.0, 0.1, 20.0)
            .0
            .translation(Vector::Y * -0.1)
            .active_hooks(ActiveHooks::MODIFY_SOLVER_CONTACTS),
        None,
    );
    let mut m = StickSlip::with_hooks(
        FrictionMaterial::new(ep(0.5, 0.5)),
        Panicky(AtomicBool::new(false)),
    );
    m.attach(&mut world.colliders, ground, None);
    let mut boxes = Vec::new();
    for i in 0..20 {
        // A 5 × 4 grid; in 2D, a row.
        #[cfg(not(dim2))]
        let at = v3((i % 5) as f32 - 2.0, 0.1, (i / 5) as f32 - 2.0);
        #[cfg(dim2)]
        let at = v3(i as f32 - 10.0, 0.1, 0.0);
        let (b, c) = cube(at);
        let (b, c) = world.insert(b, c);
        m.attach(&mut world.colliders, c, None);
        boxes.push(b);
    }
    for _ in 0..30 {
        m.step(&mut world);
    }
    let before: Vec<Vector> = boxes
        .iter()
        .map(|&b| world.bodies[b].translation())
        .collect();
    m.inner().0.store(true, Ordering::SeqCst);
    let hook = std::panic::take_hook();
    std::panic::set_hook(Box::new(|_| {}));
    let caught = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| m.step(&mut world)));
    std::panic::set_hook(hook);
    assert!(caught.is_err(), "the hook did not panic");
    // Further steps on another thread, joined with a bound.
    let (tx, rx) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        for _ in 0..60 {
            m.step(&mut world);
        }
        let at: Vec<Vector> = boxes
            .iter()
            .map(|&b| world.bodies[b].translation())
            .collect();
        tx.send((at, m.active_contacts())).ok();
    });
    let (after, contacts) = rx
        .recv_timeout(Duration::from_secs(20))
        .expect("steps after a panic did not finish: a lock stayed held");
    assert_eq!(contacts, 20, "one record per resting box");
    for (a, b) in before.iter().zip(&after) {
        assert!(a.is_finite() && b.is_finite());
        assert!(
            (*a - *b).length() < 1e-3,
            "a held box moved {} m",
            (*a - *b).length()
        );
    }
}

#[test]
fn composite_shapes_keep_one_record_per_manifold() {
    // Two compounds without contact clustering: every sub-shape pair is its own manifold.
    // The wide tiles of the top compound straddle three ground tiles each, giving the
    // sub-shape pairs (0,0) (1,0) (2,0) (2,1) (3,1) (4,1) (4,2) (5,2); folded together as
    // stickslip did (XOR), (2,0) and (3,1) both gave 2 and (1,0) and (5,2)^.. collided.
    let mut world = tilted_world(0.0);
    world.integration_parameters.contact_clustering = false;
    let ground_tiles: Vec<(Pose, SharedShape)> = (0..6)
        .map(|i| {
            (
                Pose::from_translation(v3(i as f32, 0.0, 0.0)),
                cuboid_shape(0.5, 0.1, 0.5),
            )
        })
        .collect();
    let ground = world.insert_collider(ColliderBuilder::compound(ground_tiles), None);
    let top_tiles: Vec<(Pose, SharedShape)> = (0..3)
        .map(|j| {
            (
                Pose::from_translation(v3(1.0 + 2.0 * j as f32, 0.0, 0.0)),
                cuboid_shape(0.99, 0.1, 0.4),
            )
        })
        .collect();
    let (top, top_c) = world.insert(
        RigidBodyBuilder::dynamic()
            .translation(v3(0.0, 0.2, 0.0))
            .can_sleep(false),
        ColliderBuilder::compound(top_tiles).density(500.0),
    );
    let mut m =
        StickSlip::new(FrictionMaterial::new(ep(0.5, 0.5))).with_read_back(ReadBack::Contacts);
    m.attach(&mut world.colliders, ground, None);
    m.attach(&mut world.colliders, top_c, None);
    for _ in 0..60 {
        m.step(&mut world);
    }
    let manifolds = world
        .narrow_phase
        .contact_pair(ground, top_c)
        .map_or(0, |p| {
            p.solver_manifolds()
                .iter()
                .filter(|m| !m.data.solver_contacts.is_empty())
                .count()
        });
    assert!(
        manifolds >= 6,
        "only {manifolds} manifolds: not the crafted scene"
    );
    assert_eq!(m.active_contacts(), manifolds, "records vs manifolds");
    assert_eq!(m.reports().unwrap().len(), manifolds);
    let mut data: Vec<u32> = world
        .narrow_phase
        .contact_pair(ground, top_c)
        .map(|p| {
            p.solver_manifolds()
                .iter()
                .map(|m| m.data.user_data)
                .collect()
        })
        .unwrap_or_default();
    data.sort();
    data.dedup();
    assert_eq!(data.len(), manifolds, "two manifolds share a record");
    assert!(world.bodies[top].translation().y > 0.19, "the top sank");
}

/// Log lines captured from the `log` facade (one logger per test binary).
fn captured() -> &'static Mutex<Vec<String>> {
    static LINES: OnceLock<Mutex<Vec<String>>> = OnceLock::new();
    struct Capture;
    impl log::Log for Capture {
        fn enabled(&self, m: &log::Metadata) -> bool {
            m.level() <= log::Level::Warn
        }
        fn log(&self, r: &log::Record) {
            if self.enabled(r.metadata()) {
                captured()
                    .lock()
                    .unwrap_or_else(|e| e.into_inner())
                    .push(r.args().to_string());
            }
        }
        fn flush(&self) {}
    }
    static LOGGER: Capture = Capture;
    let lines = LINES.get_or_init(Default::default);
    if log::set_logger(&LOGGER).is_ok() {
        log::set_max_level(log::LevelFilter::Warn);
    }
    lines
}

fn count(needle: &str) -> usize {
    captured()
        .lock()
        .unwrap_or_else(|e| e.into_inner())
        .iter()
        .filter(|l| l.contains(needle))
        .count()
}

#[test]
fn read_back_off_is_an_error_not_an_empty_world() {
    let mut world = tilted_world(0.0);
    let ground = world.insert_collider(cuboid3(5.0, 0.1, 5.0).0, None);
    let (b, c) = cube(v3(0.0, 0.2, 0.0));
    world.insert(b, c);
    let mut m = StickSlip::new(FrictionMaterial::new(ep(0.5, 0.5)));
    m.attach(&mut world.colliders, ground, None);
    m.step(&mut world);
    let off = NotReadBack {
        needed: ReadBack::Contacts,
        set: ReadBack::Off,
    };
    assert_eq!(m.reports().unwrap_err(), off);
    assert!(m.totals().is_err());
    assert!(
        m.reports()
            .unwrap_err()
            .to_string()
            .contains("set_read_back")
    );
    m.set_read_back(ReadBack::Totals);
    m.step(&mut world);
    assert_eq!(m.totals().unwrap().contacts, 1);
    assert!(m.reports().is_err());
    m.set_read_back(ReadBack::Contacts);
    m.step(&mut world);
    assert_eq!(m.reports().unwrap().len(), 1);
    // With read-back on, "no contacts" is an empty Ok.
    let mut empty =
        StickSlip::new(FrictionMaterial::new(ep(0.5, 0.5))).with_read_back(ReadBack::Contacts);
    let mut lone = tilted_world(0.0);
    empty.step(&mut lone);
    assert_eq!(empty.reports().unwrap().len(), 0);
}

#[test]
fn a_hook_call_without_begin_step_warns_once_and_is_plain_rapier() {
    let build = || {
        let mut world = tilted_world(0.3);
        let ground = world.insert_collider(
            cuboid3(5.0, 0.1, 5.0)
                .0
                .translation(Vector::Y * -0.1)
                .friction(0.2),
            None,
        );
        let (b, c) = cube(v3(0.0, 0.1, 0.0));
        let (b, _) = world.insert(b, c.friction(0.2));
        (world, ground, b)
    };
    let before = count("without StickSlip::begin_step");
    let (mut world, ground, b) = build();
    let mut m = StickSlip::new(FrictionMaterial::new(ep(0.5, 0.5)));
    m.attach(&mut world.colliders, ground, None);
    let (mut plain, ground_p, bp) = build();
    // Same hook flag, rapier's own friction.
    plain.colliders[ground_p].set_active_hooks(ActiveHooks::MODIFY_SOLVER_CONTACTS);
    for _ in 0..30 {
        world.step_with_events(&m, &());
        plain.step_with_events(&(), &());
        assert_eq!(
            world.bodies[b].translation(),
            plain.bodies[bp].translation()
        );
    }
    assert_eq!(
        count("without StickSlip::begin_step") - before,
        1,
        "warned once"
    );
    // Rapier's friction 0.2 < tan θ 0.3: it slid, where the material (μ 0.5) holds.
    assert!(world.bodies[b].translation().x > 0.05);
}

// (rapier2d has one friction model.)
#[cfg(not(dim2))]
#[test]
fn an_unsupported_friction_model_warns_once() {
    let mut world = tilted_world(0.0);
    world.integration_parameters.friction_model = FrictionModel::Coulomb;
    let ground = world.insert_collider(cuboid3(5.0, 0.1, 5.0).0, None);
    let (b, c) = cube(v3(0.0, 0.2, 0.0));
    world.insert(b, c);
    let before = count("needs FrictionModel::Simplified");
    let mut m = StickSlip::new(FrictionMaterial::new(ep(0.5, 0.5)));
    m.attach(&mut world.colliders, ground, None);
    for _ in 0..5 {
        m.step(&mut world);
    }
    assert_eq!(count("needs FrictionModel::Simplified") - before, 1);
}

#[test]
fn a_step_dt_out_of_range_warns_once_and_a_pause_does_not() {
    let mut world = tilted_world(0.0);
    let ground = world.insert_collider(cuboid3(5.0, 0.1, 5.0).0, None);
    let (b, c) = cube(v3(0.0, 0.2, 0.0));
    world.insert(b, c);
    let needle = "stickslip leaves such steps to rapier's friction";
    let before = count(needle);
    let mut m = StickSlip::new(FrictionMaterial::new(ep(0.5, 0.5)));
    m.attach(&mut world.colliders, ground, None);
    let mut params = world.integration_parameters;
    for dt in [0.0, 0.0, 2.0, 5.0, 1.0 / 60.0] {
        params.dt = dt;
        m.begin_step(&params, &world.bodies, &mut world.colliders);
        m.end_step(&world.narrow_phase, &world.bodies, &mut world.colliders);
        if dt == 0.0 {
            assert_eq!(count(needle), before, "a pause (dt = 0) warned");
        }
    }
    assert_eq!(count(needle) - before, 1, "warned once");
    // Only the valid step moved the clock.
    assert!((m.time() - 1.0 / 60.0).abs() < 1e-9, "{}", m.time());
}
