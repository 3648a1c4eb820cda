//! In a user's rapier2d world stickslip touches only what it was given. Invariants:
//! - pairs without an attached collider, hooked by the user's own wrapped hook (a pad it makes
//!   slippery, a conveyor belt setting a tangent velocity), move bit for bit as with the
//!   user's hook alone (and unhooked, unattached pairs as in plain rapier2d), with the
//!   physics of that hook: the pad slides at g (sin θ − 0.05 cos θ), the belt carries its box
//!   at belt speed, while stickslip holds its own box within the elastic range;
//! - the user's hook is called on exactly the pairs rapier2d calls it for without stickslip;
//! - a one-way platform (rapier2d's `update_as_oneway_platform`, which keeps its state in the
//!   manifold's `user_data`) that stickslip also owns lets a box through from below bit for
//!   bit as the user's hook alone, and once the box has landed on top the law holds it
//!   (μ 0.5 > tan θ 0.3) where the platform's rapier friction 0.1 lets it slide;
//! - two materials combine by the colliders' rapier combine rules (Average, Min, Max,
//!   GeometricMean, the higher rule in rapier's order winning): the box holds 7 % below and
//!   slides 7 % above the combined break-away coefficient, whichever collider is inserted
//!   first (the pair's law the same bit for bit), slides at g (sin θ − μ_k cos θ) of the
//!   combined kinetic coefficient within 2 %; a per-pair material wins; an unattached
//!   collider brings its rapier friction as plain Coulomb.

mod support;

use std::collections::HashSet;
use std::sync::Mutex;
use stickslip_rapier2d::core::law::{FrictionLaw, Law};
use stickslip_rapier2d::core::sliding_curve::Curve;
use stickslip_rapier2d::rapier::prelude::*;
use stickslip_rapier2d::{FrictionMaterial, StickSlip};
use support::G;

const DT: f32 = 1.0 / 60.0;

fn ep(mu_ba: f64, mu_k: f64) -> Law {
    Law::elasto_plastic(1e4, mu_ba, mu_ba.max(mu_k), Curve::constant(mu_k).unwrap()).unwrap()
}

/// A world with gravity tilted to `tan_theta` down +x, stepped at [`DT`].
fn tilted_world(tan_theta: f64) -> PhysicsWorld {
    let mut world = PhysicsWorld::default();
    let th = tan_theta.atan();
    world.gravity = Vector::new((G * th.sin()) as f32, -(G * th.cos()) as f32);
    world.integration_parameters.dt = DT;
    world
}

/// A 0.2 m box (density 1000) at `at`, never sleeping.
fn cube(at: Vector) -> (RigidBodyBuilder, ColliderBuilder) {
    (
        RigidBodyBuilder::dynamic().translation(at).can_sleep(false),
        ColliderBuilder::cuboid(0.1, 0.1).density(1000.0),
    )
}

/// The user's own hooks: a pad made slippery (friction 0.05) and a belt whose surface moves
/// at 0.5 m/s up the slope (−x).
struct UserHooks {
    pad: ColliderHandle,
    belt: ColliderHandle,
}

const BELT_SPEED: f32 = -0.5;

impl PhysicsHooks for UserHooks {
    fn modify_solver_contacts(&self, ctx: &mut ContactModificationContext) {
        let (c1, c2) = (ctx.collider1, ctx.collider2);
        let Some(m) = ctx.rigid_mut() else { return };
        if c1 == self.pad || c2 == self.pad {
            *m.friction = 0.05;
        }
        if c1 == self.belt || c2 == self.belt {
            let v = if c1 == self.belt {
                BELT_SPEED
            } else {
                -BELT_SPEED
            };
            for c in m.solver_contacts.iter_mut() {
                c.tangent_velocity = Vector::new(v, 0.0);
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
        let slab = |x: f32| ColliderBuilder::cuboid(8.0, 0.1).translation(Vector::new(x, -0.1));
        let ground = world.insert_collider(slab(-60.0), None);
        let pad = world.insert_collider(slab(-20.0).active_hooks(flag), None);
        let belt = world.insert_collider(slab(20.0).active_hooks(flag), None);
        // Neither hooked nor attached: rapier2d's own friction (0.5 by default).
        let plain = world.insert_collider(slab(60.0), None);
        let mut boxes = Vec::new();
        let mut colliders = Vec::new();
        for x in [-60.0, -20.0, 20.0, 60.0] {
            let (b, c) = cube(Vector::new(x, 0.1));
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
    // box at its speed, rapier2d's own friction 0.5 holds the unhooked box, and stickslip
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

/// The user's hook that only records which pairs rapier2d called it for.
#[derive(Default)]
struct Recorder(Mutex<HashSet<(ColliderHandle, ColliderHandle)>>);

fn ordered(a: ColliderHandle, b: ColliderHandle) -> (ColliderHandle, ColliderHandle) {
    if a.0.into_raw_parts() < b.0.into_raw_parts() {
        (a, b)
    } else {
        (b, a)
    }
}

impl PhysicsHooks for Recorder {
    fn modify_solver_contacts(&self, ctx: &mut ContactModificationContext) {
        self.0
            .lock()
            .unwrap()
            .insert(ordered(ctx.collider1, ctx.collider2));
    }
}

#[test]
fn the_users_hook_sees_the_pairs_it_sees_without_stickslip() {
    // Three grounds, a box on each: one attached without a user flag (stickslip's alone), one
    // the user flags (their hook's alone), one both (the user's hook and the law).
    let build = || {
        let mut world = tilted_world(0.3);
        let flag = ActiveHooks::MODIFY_SOLVER_CONTACTS;
        let ground = |x: f32| ColliderBuilder::cuboid(2.0, 0.1).translation(Vector::new(x, -0.1));
        let stickslips = world.insert_collider(ground(-10.0), None);
        let users = world.insert_collider(ground(0.0).active_hooks(flag), None);
        let both = world.insert_collider(ground(10.0).active_hooks(flag), None);
        let mut boxes = Vec::new();
        for x in [-10.0, 0.0, 10.0] {
            let (b, c) = cube(Vector::new(x, 0.1));
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
    for _ in 0..steps {
        m.step(&mut world);
    }
    let with = std::mem::take(&mut *m.inner().0.lock().unwrap());
    assert!(alone.contains(&ordered(users, boxes[1])), "{alone:?}");
    assert!(alone.contains(&ordered(both, boxes[2])), "{alone:?}");
    assert_eq!(
        with, alone,
        "the user's hook saw other pairs with stickslip attached"
    );
    assert!(!with.contains(&ordered(stickslips, boxes[0])));
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
            Vector::new(0.0, 1.0)
        } else if ctx.collider2 == self.platform {
            Vector::new(0.0, -1.0)
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
            ColliderBuilder::cuboid(8.0, 0.1)
                .translation(Vector::new(0.0, 2.0))
                .friction(0.1)
                .active_hooks(ActiveHooks::MODIFY_SOLVER_CONTACTS),
            None,
        );
        // Thrown up from below the platform, through it, to land on top.
        let (b, c) = world.insert(
            RigidBodyBuilder::dynamic()
                .translation(Vector::new(-3.0, 1.0))
                .linvel(Vector::new(0.0, 6.5))
                .lock_rotations()
                .can_sleep(false),
            ColliderBuilder::cuboid(0.1, 0.1)
                .density(1000.0)
                .friction(0.1),
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

/// The cube's x after each of 60 steps on the tilted ground, and the pair's law.
fn run_incline(s: &Incline) -> (Vec<f32>, Option<Law>) {
    let mut world = tilted_world(s.tan_theta);
    let collider = |side: &Side, b: ColliderBuilder| match side {
        Side::Attached(law, rule) => b
            .friction(law.static_coefficient() as f32)
            .friction_combine_rule(*rule),
        Side::Plain(mu, rule) => b.friction(*mu).friction_combine_rule(*rule),
    };
    let ground_builder =
        collider(&s.ground, ColliderBuilder::cuboid(5.0, 0.1)).translation(Vector::new(0.0, -0.1));
    let (body, cube_builder) = cube(Vector::new(0.0, 0.1));
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
            m.step(&mut world);
            world.bodies[b].translation().x
        })
        .collect();
    (xs, law)
}

/// Displacement over 59 steps, the same (hold or slide) and with the same law bit for bit
/// whichever collider is inserted first.
fn moved(s: &Incline) -> f64 {
    let flipped = Incline {
        cube_first: !s.cube_first,
        ground: s.ground.clone(),
        cube: s.cube.clone(),
        pair: s.pair.clone(),
        tan_theta: s.tan_theta,
    };
    let (xs, law) = run_incline(s);
    let (xf, law_f) = run_incline(&flipped);
    assert_eq!(law, law_f, "the pair's law depends on the insertion order");
    let (d, df) = ((xs[59] - xs[0]) as f64, (xf[59] - xf[0]) as f64);
    assert_eq!(
        d.abs() < 1e-3,
        df.abs() < 1e-3,
        "hold or slide depends on the insertion order: {d} vs {df}"
    );
    d
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
    // √0.24 = 0.49; the higher rule in rapier's order decides.
    let cases = [
        (R::Average, 0.55),
        (R::Min, 0.3),
        (R::Max, 0.8),
        (R::GeometricMean, 0.24f64.sqrt()),
    ];
    for (rule, mu) in cases {
        for (r_ground, r_cube) in [(R::Average, rule), (rule, R::Average)] {
            let hold = moved(&case(
                attached(0.3, r_ground),
                attached(0.8, r_cube),
                0.93 * mu,
            ));
            let slide = moved(&case(
                attached(0.3, r_ground),
                attached(0.8, r_cube),
                1.07 * mu,
            ));
            println!("{rule:?} (μ {mu:.3}): 0.93 μ moved {hold:.2e} m, 1.07 μ moved {slide:.3} m");
            assert!(hold.abs() < 1e-3, "{rule:?}: held cube moved {hold} m");
            assert!(
                slide > 0.02,
                "{rule:?}: cube above μ = {mu} moved only {slide} m"
            );
        }
    }
    // Static above kinetic, Average: μ_ba (0.3+0.8)/2 = 0.55, μ_k (0.2+0.6)/2 = 0.4; sliding
    // above break-away accelerates at g (sin θ − 0.4 cos θ).
    let (xs, _) = run_incline(&case(
        Side::Attached(ep(0.3, 0.2), R::Average),
        Side::Attached(ep(0.8, 0.6), R::Average),
        0.6,
    ));
    let th = 0.6f64.atan();
    let a = G * (th.sin() - 0.4 * th.cos());
    let dt = DT as f64;
    let v = |i: usize, j: usize| (xs[j] - xs[i]) as f64 / ((j - i) as f64 * dt);
    let accel = (v(40, 59) - v(20, 39)) / (20.0 * dt);
    println!("combined kinetic friction: a {accel:.4} m/s² vs {a:.4}");
    assert!((accel - a).abs() < 0.02 * a, "a = {accel} vs {a}");

    // The pair's own material wins over any rule.
    let mut s = case(attached(0.3, R::Max), attached(0.8, R::Max), 0.3);
    assert!(moved(&s).abs() < 1e-3);
    s.pair = Some(ep(0.2, 0.2));
    assert!(moved(&s) > 0.02, "pair material μ 0.2 did not win");

    // Attached ground (μ 0.3) against an unattached cube with rapier friction 0.7: Average
    // 0.5; with the cube's rule Min, 0.3.
    let plain = |mu, rule| Side::Plain(mu, rule);
    let avg = |tan| {
        moved(&case(
            attached(0.3, R::Average),
            plain(0.7, R::Average),
            tan,
        ))
    };
    assert!(avg(0.46).abs() < 1e-3);
    assert!(avg(0.54) > 0.02);
    assert!(moved(&case(attached(0.3, R::Average), plain(0.7, R::Min), 0.46)) > 0.02);
}
