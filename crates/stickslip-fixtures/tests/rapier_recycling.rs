//! Quiet contacts recycle (stickslip turns its hook flag off, rapier keeps the pair's
//! contacts) without changing the friction law. Invariant: a box resting on a ground, both
//! attached with the default configuration, is recycled while it holds well inside its limit;
//! under a load that then rises slowly, or jumps, it breaks away at the same load as the same
//! box with every contact hooked every step (rapier's `contact_recycling` off), for masses
//! over four decades and two time steps — at μ_ba (EP, static above kinetic), holding without
//! more than plain rapier (+ g_ba) after a jump to 0.6 μ_ba, moving as the hooked box after a
//! jump to 0.9 μ_ba up to plain rapier's own difference between recycled and fresh contacts
//! (both hold: `crates/stickslip-fixtures/tests/rapier_load_jump.rs`), sliding at g (sin θ − μ_k cos θ) after a jump to
//! 1.2 μ_ba. The same box carried at 0.5 m/s by a kinematic platform (a pair that moves,
//! recycled because rapier's own full update writes the same μ) is recycled while it holds and
//! breaks away at μ_ba, where the hooked one does, also while it passes under a fixed beam it
//! never touches; carried towards a wall, it is recycled on its way and every contact it
//! makes with the wall is the law's from the first step. A pair the user filters (rapier
//! updates it in full at every step) keeps the law's limit at every step, also after its box
//! fell asleep and was woken. A box stacked on another on a belt
//! (a surface stickslip hooks at every step) breaks away where a hooked one does too: the
//! boxes' pair between them is recycled while it holds, the belt's pairs being hooked by the
//! belt alone. A world saved while
//! contacts are recycled,
//! and piles on a heightfield and on a compound ground (composite contact patches, recycled or
//! not), resume bit for bit. With rapier's `parallel` feature, the pass after each step that
//! decides which contacts recycle (and steps them ahead) runs on rayon's threads and decides
//! the same on one thread as on two: the same stacks, sliding and settling, and the
//! composite piles step bit for bit alike on pools of both sizes. The pass judges only the
//! pairs of the colliders that may go quiet when those are few, every pair otherwise, and
//! decides the same either way: stacks sliding and settling, a world where only some colliders
//! are attached (one with the user's own flag, which the user takes off) and the composite
//! piles step bit for bit alike both ways. In 3D and in 2D (stickslip-fixtures2d: the platform carries
//! along x, the stacks stand in a row; the composite grounds are 3D).

use stickslip_core::law::Law;
use stickslip_core::sliding_curve::Curve;
use stickslip_fixtures::dim::world_bits;
use stickslip_fixtures::ordinary::{Ground, box_on_slope};
use stickslip_fixtures::{cuboid3, v3};
use stickslip_rapier::rapier::prelude::*;
use stickslip_rapier::{FrictionMaterial, StickSlip, WorldSnapshot};

const MU_BA: f64 = 0.5;
const MU_K: f64 = 0.3;
const C: f64 = 1e5;
const G: f64 = 9.81;

fn ep() -> Law {
    Law::elasto_plastic(C, MU_BA, MU_BA, Curve::constant(MU_K).unwrap()).unwrap()
}

fn set_slope(world: &mut PhysicsWorld, tan_theta: f64) {
    let theta = tan_theta.atan();
    world.gravity = v3((G * theta.sin()) as f32, -(G * theta.cos()) as f32, 0.0);
}

/// A box of `mass` on a cuboid ground, flat, everything attached; `recycling` sets rapier's
/// `contact_recycling` (off: every contact hooked every step).
fn scene(mass: f32, dt: f64, recycling: bool) -> (PhysicsWorld, StickSlip, RigidBodyHandle) {
    scene_with(mass, dt, recycling, true)
}

/// [`scene`], with stickslip attached or (`attach` false) plain rapier.
fn scene_with(
    mass: f32,
    dt: f64,
    recycling: bool,
    attach: bool,
) -> (PhysicsWorld, StickSlip, RigidBodyHandle) {
    let mut s = box_on_slope(Ground::Cuboid, 0.0, 0.5, dt);
    let b = s.bodies[0];
    let body = &mut s.world.bodies[b];
    let density = mass / cuboid3(0.25, 0.25, 0.25).1;
    for h in body.colliders().to_vec() {
        s.world.colliders[h].set_density(density);
    }
    s.world.integration_parameters.contact_recycling = recycling;
    let mut m = StickSlip::new(FrictionMaterial::new(ep()));
    if attach {
        for h in s.all_colliders() {
            m.attach(&mut s.world.colliders, h, None);
        }
    }
    // Settle flat.
    for _ in 0..(0.5 / dt) as usize {
        m.step(&mut s.world);
    }
    (s.world, m, b)
}

fn box_collider(world: &PhysicsWorld, b: RigidBodyHandle) -> ColliderHandle {
    world.bodies[b].colliders()[0]
}

/// The slope's tangent at which the box starts sliding (downhill speed above 1 cm/s) while
/// the tangent rises by `rate` per second from 0.3, and the share of the hold before 0.35 in
/// which the box's contacts were recycled.
fn break_away_under_a_ramp(mass: f32, dt: f64, recycling: bool, rate: f64) -> (f64, f64) {
    let (world, m, b) = scene(mass, dt, recycling);
    ramp_to_break_away(world, m, b, dt, rate, 0.0)
}

/// Raises the slope's tangent by `rate` per second from 0.3 until body `b` slides (downhill
/// speed above 1 cm/s relative to its ground, whose velocity along x is `base_vx`): the tangent
/// then, and the share of the hold before 0.35 in which its collider's contacts were recycled.
fn ramp_to_break_away(
    world: PhysicsWorld,
    m: StickSlip,
    b: RigidBodyHandle,
    dt: f64,
    rate: f64,
    base_vx: f32,
) -> (f64, f64) {
    let collider = box_collider(&world, b);
    ramp_watching(world, m, b, collider, dt, rate, base_vx)
}

/// [`ramp_to_break_away`], with the share of the hold in which `collider`'s contacts were
/// recycled.
fn ramp_watching(
    mut world: PhysicsWorld,
    mut m: StickSlip,
    b: RigidBodyHandle,
    collider: ColliderHandle,
    dt: f64,
    rate: f64,
    base_vx: f32,
) -> (f64, f64) {
    let (mut recycled, mut held) = (0usize, 0usize);
    let mut tan = 0.3;
    while tan < 0.8 {
        set_slope(&mut world, tan);
        m.step(&mut world);
        if tan < 0.35 {
            held += 1;
            recycled += usize::from(m.is_recycled(collider));
        }
        if world.bodies[b].linvel().x - base_vx > 0.01 {
            return (tan, recycled as f64 / held as f64);
        }
        tan += rate * dt;
    }
    panic!("no break-away below tan 0.8 (dt {dt})");
}

/// For masses over four decades and two time steps, `break_away(mass, dt, recycling, rate)`
/// recycles the held box (`what`) and breaks away at μ_ba, at the same load recycled or
/// hooked every step.
fn breaks_away_as_hooked(what: &str, break_away: fn(f32, f64, bool, f64) -> (f64, f64)) {
    for dt in [1.0 / 60.0, 1.0 / 240.0] {
        for mass in [0.1f32, 10.0, 1000.0] {
            let (recycled_at, share) = break_away(mass, dt, true, 0.05);
            let (hooked_at, none) = break_away(mass, dt, false, 0.05);
            println!(
                "dt {dt:.4} mass {mass:6}: {what} breaks away at tan {recycled_at:.4} recycled \
                 ({:.0} % of the hold recycled), {hooked_at:.4} hooked",
                100.0 * share
            );
            assert!(share > 0.9, "the {what} was recycled {share}");
            assert_eq!(none, 0.0, "nothing recycles with contact_recycling off");
            // Break-away at μ_ba (the tangent grows by rate·dt per step; the box needs a few
            // steps to pass 1 cm/s) and at the same load either way.
            for at in [recycled_at, hooked_at] {
                assert!((at - MU_BA).abs() < 0.01, "break-away at tan {at}");
            }
            assert!(
                (recycled_at - hooked_at).abs() < 2.0 * 0.05 * dt + 1e-9,
                "recycled {recycled_at} vs hooked {hooked_at}"
            );
        }
    }
}

#[test]
fn a_recycled_contact_breaks_away_under_a_rising_load_where_a_hooked_one_does() {
    breaks_away_as_hooked("resting box", break_away_under_a_ramp);
}

/// A box of `mass` carried at 0.5 m/s along z by a kinematic platform (so it moves 2–8 mm a
/// step, far more than a resting body), both attached: the slope's tangent at which the box
/// starts sliding on the platform (downhill speed above 1 cm/s) while the tangent rises by
/// `rate` per second from 0.3, and the share of the hold before 0.35 in which the box's
/// contacts were recycled.
/// A platform's velocity and half-length along x: across the load (along z) in 3D, along it
/// in 2D (so the platform is long).
fn carried() -> (Vector, f32) {
    #[cfg(not(dim2))]
    let c = (v3(0.0, 0.0, 0.5), 5.0);
    #[cfg(dim2)]
    let c = (v3(0.5, 0.0, 0.0), 200.0);
    c
}

fn break_away_on_a_moving_platform(mass: f32, dt: f64, recycling: bool, rate: f64) -> (f64, f64) {
    let (world, m, b, _) = carried_box(mass, dt, recycling, None);
    ramp_to_break_away(world, m, b, dt, rate, carried().0.x)
}

/// The box of [`break_away_on_a_moving_platform`] on its platform, both attached, settled
/// level for 0.5 s; with `beam_gap`, also a fixed beam (attached, as long as the platform)
/// that far above the box's top, returned.
fn carried_box(
    mass: f32,
    dt: f64,
    recycling: bool,
    beam_gap: Option<f32>,
) -> (
    PhysicsWorld,
    StickSlip,
    RigidBodyHandle,
    Option<ColliderHandle>,
) {
    let mut world = PhysicsWorld::default();
    world.integration_parameters.dt = dt as f32;
    world.integration_parameters.contact_recycling = recycling;
    let (v, under_half) = carried();
    let platform = world.insert_body(RigidBodyBuilder::kinematic_velocity_based().linvel(v));
    let under = world.insert_collider(
        cuboid3(under_half, 0.1, 200.0)
            .0
            .translation(v3(0.0, -0.1, 0.0))
            .friction(MU_BA as f32),
        Some(platform),
    );
    let (b, on) = world.insert(
        RigidBodyBuilder::dynamic()
            .translation(v3(0.0, 0.25, 0.0))
            .linvel(v)
            .can_sleep(false),
        cuboid3(0.25, 0.25, 0.25)
            .0
            .density(mass / cuboid3(0.25, 0.25, 0.25).1)
            .friction(MU_BA as f32),
    );
    let beam = beam_gap.map(|gap| {
        world.insert_collider(
            cuboid3(under_half, 0.1, 200.0)
                .0
                .translation(v3(0.0, 0.5 + gap + 0.1, 0.0))
                .friction(MU_BA as f32),
            None,
        )
    });
    let mut m = StickSlip::new(FrictionMaterial::new(ep()));
    for h in [Some(under), Some(on), beam].into_iter().flatten() {
        m.attach(&mut world.colliders, h, None);
    }
    set_slope(&mut world, 0.0);
    for _ in 0..(0.5 / dt) as usize {
        m.step(&mut world);
    }
    (world, m, b, beam)
}

#[test]
fn a_carried_contact_recycles_and_breaks_away_where_a_hooked_one_does() {
    breaks_away_as_hooked("carried box", break_away_on_a_moving_platform);
}

/// How far above the carried box's top the beam of [`break_away_under_a_beam`] is (m): more
/// than rapier's prediction distance, so the two never touch, little enough that rapier keeps
/// the pair in its narrow phase.
const BEAM_GAP: f32 = 0.04;

/// [`break_away_on_a_moving_platform`] with the box passing under a fixed beam, `BEAM_GAP`
/// above it all along.
fn break_away_under_a_beam(mass: f32, dt: f64, recycling: bool, rate: f64) -> (f64, f64) {
    let (world, m, b, _) = carried_box(mass, dt, recycling, Some(BEAM_GAP));
    ramp_to_break_away(world, m, b, dt, rate, carried().0.x)
}

#[test]
fn a_carried_contact_passing_under_a_beam_recycles_and_breaks_away_where_a_hooked_one_does() {
    // The pair (box, beam) is in rapier's narrow phase, touches nowhere, and moves at
    // 0.5 m/s: a pair like this kept the carried box hooked at every step before.
    let (world, _, b, beam) = carried_box(1.0, 1.0 / 60.0, true, Some(BEAM_GAP));
    let (on, beam) = (box_collider(&world, b), beam.unwrap());
    let pair = world.narrow_phase.contact_pair(on, beam);
    assert!(
        pair.is_some(),
        "the beam's pair is in rapier's narrow phase"
    );
    assert!(
        pair.unwrap()
            .solver_manifolds()
            .iter()
            .all(|m| m.data.solver_contacts.is_empty()),
        "the beam touches nowhere"
    );
    breaks_away_as_hooked("box carried under a beam", break_away_under_a_beam);
}

#[test]
fn a_carried_box_recycled_on_its_way_meets_a_wall_hooked() {
    // A fixed wall ahead of the carried box, attached, with a grippier collider friction:
    // rapier's own full update of the pair would write their combined 0.7 where the law
    // writes at most μ_ba. The box is recycled while the wall is far; every contact it makes
    // with the wall must still be the law's from its first step.
    for dt in [1.0 / 60.0, 1.0 / 240.0] {
        let (mut world, mut m, b, _) = carried_box(1.0, dt, true, None);
        let on = box_collider(&world, b);
        // 0.3 m ahead of the box's front face.
        let ahead = carried().0.normalize();
        let front = world.bodies[b].translation().dot(ahead) + 0.25;
        let wall = world.insert_collider(
            cuboid3(0.1, 0.5, 0.1)
                .0
                .translation(ahead * (front + 0.3 + 0.1) + v3(0.0, 0.5, 0.0))
                .friction(0.9),
            None,
        );
        // The wall spans the box's path: 1 m across it, 0.1 m thick along it.
        #[cfg(not(dim2))]
        world.colliders[wall].set_shape(SharedShape::cuboid(1.0, 0.5, 0.1));
        m.attach(&mut world.colliders, wall, None);
        let own = 0.5 * (MU_BA as f32 + 0.9);
        let (mut recycled, mut touched) = (0, 0);
        for _ in 0..(1.5 / dt) as usize {
            m.step(&mut world);
            recycled += usize::from(m.is_recycled(on));
            let Some(pair) = world.narrow_phase.contact_pair(on, wall) else {
                continue;
            };
            for manifold in pair.solver_manifolds() {
                if manifold.data.solver_contacts.is_empty() {
                    continue;
                }
                touched += 1;
                assert!(
                    manifold.data.friction <= MU_BA as f32,
                    "dt {dt}: the wall's contact got rapier's own friction {} (combined {own})",
                    manifold.data.friction
                );
            }
        }
        println!(
            "dt {dt:.4}: recycled {recycled} steps, touched the wall in {touched} manifold steps"
        );
        assert!(
            recycled > (0.2 / dt) as usize,
            "the box was recycled on its way"
        );
        assert!(touched > 0, "the box reached the wall");
    }
}

/// User hooks that keep every contact pair (a pair filter that filters nothing out: the
/// default flags, which solve the contacts).
struct KeepEveryPair;

impl PhysicsHooks for KeepEveryPair {
    fn filter_contact_pair(&self, _: &PairFilterContext) -> Option<SolverFlags> {
        Some(SolverFlags::default())
    }
}

#[test]
fn a_pair_the_user_filters_is_never_left_to_rapiers_friction() {
    // A box holding on a slope, on a ground with the user's pair-filter flag: rapier updates
    // such a pair in full at every step, so with stickslip's flag off it would get rapier's
    // friction, their collider coefficients combined: (0.3 + 0.9)/2 = 0.6. The law's limit is
    // μ_ba = 0.5 with the ground attached, and with the ground unattached the box's μ_ba
    // combined with the ground's coefficient (a Coulomb side): (0.5 + 0.9)/2 = 0.7. Either
    // way no contact may carry rapier's own 0.6.
    // Also a box that falls asleep on the unattached ground and is woken by the user: rapier
    // updates the pair in full again from the wake.
    for (attach_ground, sleeps) in [(true, false), (false, false), (false, true)] {
        let mut world = PhysicsWorld::default();
        let ground = world.insert_collider(
            cuboid3(5.0, 0.1, 5.0)
                .0
                .translation(v3(0.0, -0.1, 0.0))
                .friction(0.9),
            None,
        );
        let (b, on) = world.insert(
            RigidBodyBuilder::dynamic()
                .translation(v3(0.0, 0.25, 0.0))
                .can_sleep(sleeps),
            cuboid3(0.25, 0.25, 0.25).0.friction(0.3),
        );
        let own = 0.6;
        // The law's limit: μ_ba of the box's material with the ground's (the same material
        // attached, a Coulomb side with the ground's coefficient unattached).
        let law = if attach_ground { 0.5 } else { 0.7 };
        let mut m = StickSlip::with_hooks(FrictionMaterial::new(ep()), KeepEveryPair);
        m.attach(&mut world.colliders, on, None);
        if attach_ground {
            m.attach(&mut world.colliders, ground, None);
        }
        let c = &mut world.colliders[ground];
        c.set_active_hooks(c.active_hooks() | ActiveHooks::FILTER_CONTACT_PAIRS);
        set_slope(&mut world, 0.2);
        let mut touched = 0;
        let steps = if sleeps { 600 } else { 120 };
        for step in 0..steps {
            if sleeps && step == 540 {
                assert!(world.bodies[b].is_sleeping(), "the box fell asleep");
                world.bodies[b].wake_up(true);
            }
            m.step(&mut world);
            let pair = world.narrow_phase.contact_pair(on, ground).unwrap();
            for manifold in pair.solver_manifolds() {
                if manifold.data.solver_contacts.is_empty() {
                    continue;
                }
                touched += 1;
                assert!(
                    (manifold.data.friction - law).abs() < 1e-6,
                    "ground attached {attach_ground}, sleeps {sleeps}, step {step}: friction {} where the law \
                     gives {law} (rapier's own: {own})",
                    manifold.data.friction
                );
            }
        }
        assert!(touched > 100, "the box rests on the ground");
    }
}

/// Two flat boxes of `mass` stacked on a fixed belt whose surface moves at the platform's
/// velocity (a collider stickslip hooks at every step), all attached: the slope's tangent at
/// which the top box starts sliding (downhill speed above 1 cm/s beyond the belt's), and the
/// share of the hold before 0.35 in which the lower box's contacts were recycled. The belt's
/// own pairs stay hooked; the boxes' pair between them needs no hook while it holds.
fn break_away_stacked_on_a_belt(mass: f32, dt: f64, recycling: bool, rate: f64) -> (f64, f64) {
    let mut world = PhysicsWorld::default();
    world.integration_parameters.dt = dt as f32;
    world.integration_parameters.contact_recycling = recycling;
    let (v, half) = carried();
    let belt = world.insert_collider(
        cuboid3(half, 0.1, 200.0)
            .0
            .translation(v3(0.0, -0.1, 0.0))
            .friction(0.8),
        None,
    );
    let cube = |world: &mut PhysicsWorld, y: f32| {
        world.insert(
            RigidBodyBuilder::dynamic()
                .translation(v3(0.0, y, 0.0))
                .linvel(v)
                .can_sleep(false),
            cuboid3(0.25, 0.1, 0.25)
                .0
                .density(mass / cuboid3(0.25, 0.1, 0.25).1)
                .friction(MU_BA as f32),
        )
    };
    // Flat boxes: the stack would tip at tan θ = 1.25, far beyond μ_ba.
    let (_, lower) = cube(&mut world, 0.1);
    let (top, upper) = cube(&mut world, 0.3);
    let mut m = StickSlip::new(FrictionMaterial::new(ep()));
    for h in [lower, upper] {
        m.attach(&mut world.colliders, h, None);
    }
    // A grippier belt (μ_ba 0.65 with the box): the boxes' own contact breaks away first.
    let grippy = Law::elasto_plastic(C, 0.8, 0.8, Curve::constant(0.6).unwrap()).unwrap();
    m.attach(
        &mut world.colliders,
        belt,
        Some(FrictionMaterial::new(grippy)),
    );
    m.set_surface_velocity(&mut world.colliders, belt, v);
    // Put down on the ramp's first slope: a jump to it from level makes the top box slip
    // faster than 1 cm/s for a step, hooked or recycled, before it holds.
    set_slope(&mut world, 0.3);
    for _ in 0..(0.5 / dt) as usize {
        m.step(&mut world);
    }
    ramp_watching(world, m, top, lower, dt, rate, v.x)
}

#[test]
fn boxes_stacked_on_a_belt_recycle_their_pair_and_break_away_where_hooked_ones_do() {
    breaks_away_as_hooked("box stacked on a belt", break_away_stacked_on_a_belt);
}

/// Downhill displacement (m) over 2 s and the final acceleration (m/s²) of a box resting
/// at tan 0.1 (recycled) when the slope jumps to `tan_theta`.
fn after_a_jump(mass: f32, dt: f64, recycling: bool, tan_theta: f64) -> (f64, f64) {
    jump(mass, dt, recycling, true, tan_theta)
}

/// [`after_a_jump`], with stickslip or (`attach` false) plain rapier.
fn jump(mass: f32, dt: f64, recycling: bool, attach: bool, tan_theta: f64) -> (f64, f64) {
    let (mut world, mut m, b) = scene_with(mass, dt, recycling, attach);
    set_slope(&mut world, 0.1);
    for _ in 0..(1.0 / dt) as usize {
        m.step(&mut world);
    }
    assert_eq!(
        m.is_recycled(box_collider(&world, b)),
        recycling && attach,
        "quiet before the jump"
    );
    set_slope(&mut world, tan_theta);
    let x0 = world.bodies[b].translation().x as f64;
    let steps = (2.0 / dt) as usize;
    let mut v = [0.0; 2];
    for k in 0..steps {
        m.step(&mut world);
        if k + 2 >= steps {
            v[k + 2 - steps] = world.bodies[b].linvel().x as f64;
        }
    }
    (
        world.bodies[b].translation().x as f64 - x0,
        (v[1] - v[0]) / dt,
    )
}

#[test]
fn a_recycled_contact_holds_or_slides_after_a_jump_in_load_as_a_hooked_one() {
    let g_ba = MU_BA / C;
    for dt in [1.0 / 60.0, 1.0 / 240.0] {
        for mass in [0.1f32, 10.0, 1000.0] {
            // Below break-away: both hold, moving no more than plain rapier's first solve
            // after a jump lets the contact slip, plus the law's elastic range.
            let (plain, _) = jump(mass, dt, true, false, 0.6 * MU_BA);
            for recycling in [true, false] {
                let (dx, _) = after_a_jump(mass, dt, recycling, 0.6 * MU_BA);
                assert!(
                    dx.abs() < plain.abs() + g_ba,
                    "mass {mass} dt {dt} recycling {recycling}: moved {dx}, plain {plain}"
                );
            }
            // Closer to break-away a jump in one step makes rapier's first solve let the
            // contact slip (plain rapier too, ~0.2 mm, then it stops); stickslip then does
            // the same recycled or hooked.
            // The law's steps are the same either way; what differs is rapier's own: a
            // recycled pair keeps its contact points. So the two differ by no more than
            // plain rapier recycled and not (+ 0.1 % of the slip for rounding).
            let (recycled, _) = after_a_jump(mass, dt, true, 0.9 * MU_BA);
            let (hooked, _) = after_a_jump(mass, dt, false, 0.9 * MU_BA);
            let (plain_recycled, _) = jump(mass, dt, true, false, 0.9 * MU_BA);
            let (plain_fresh, _) = jump(mass, dt, false, false, 0.9 * MU_BA);
            let rapiers = (plain_recycled - plain_fresh).abs();
            println!(
                "dt {dt:.4} mass {mass:6}: jump to 0.9 μ_ba moves {recycled:.3e} m recycled, \
                 {hooked:.3e} m hooked (plain rapier {plain_recycled:.3e} recycled, \
                 {plain_fresh:.3e} not)"
            );
            assert!(
                (recycled - hooked).abs() <= rapiers + 1e-3 * hooked.abs().max(g_ba),
                "recycled {recycled} vs hooked {hooked}, plain rapier's gap {rapiers}"
            );
            // Above: both slide at the kinetic acceleration.
            let tan: f64 = 1.2 * MU_BA;
            let theta = tan.atan();
            let expected = G * (theta.sin() - MU_K * theta.cos());
            let (_, recycled) = after_a_jump(mass, dt, true, tan);
            let (_, hooked) = after_a_jump(mass, dt, false, tan);
            println!(
                "dt {dt:.4} mass {mass:6}: a {recycled:.4} recycled, {hooked:.4} hooked, \
                 {expected:.4} closed form"
            );
            for a in [recycled, hooked] {
                assert!((a / expected - 1.0).abs() < 0.02, "a = {a} vs {expected}");
            }
        }
    }
}

/// A copy of `world` and `m`, through a snapshot.
fn copy(world: &PhysicsWorld, m: &StickSlip) -> (PhysicsWorld, StickSlip) {
    let mut bytes = Vec::new();
    WorldSnapshot::save_from(world, m, &mut bytes).unwrap();
    WorldSnapshot::load(bytes.as_slice())
        .unwrap()
        .restore(())
        .unwrap()
}

/// How many of the world's colliders `m` lets rapier recycle.
fn recycled(world: &PhysicsWorld, m: &StickSlip) -> usize {
    world
        .colliders
        .iter()
        .filter(|(h, _)| m.is_recycled(*h))
        .count()
}

/// Runs `world` with `m` for `before` steps, saves both, resumes, and compares the two runs
/// bit for bit over `after` steps, with `event` applied to both worlds at step `event_at`
/// after the snapshot. Returns how many attached colliders were recycled at the snapshot.
fn resumes_bit_identically(
    mut world: PhysicsWorld,
    mut m: StickSlip,
    before: usize,
    after: usize,
    event_at: usize,
    event: impl Fn(&mut PhysicsWorld),
) -> usize {
    for _ in 0..before {
        m.step(&mut world);
    }
    let recycled = recycled(&world, &m);
    let (mut w2, mut m2) = copy(&world, &m);
    for k in 0..after {
        if k == event_at {
            event(&mut world);
            event(&mut w2);
        }
        m.step(&mut world);
        m2.step(&mut w2);
        assert!(
            world_bits(&world) == world_bits(&w2),
            "diverged {k} steps after restore"
        );
    }
    recycled
}

/// 36 stacks of two 0.5 m boxes (friction μ_ba, moving at `v`) on the ground already in
/// `world`, every collider attached.
fn stacks_on(world: &mut PhysicsWorld, v: Vector) -> StickSlip {
    stacks_of(world, v, 6)
}

/// [`stacks_on`] with `side` × `side` stacks (in 2D, a row of `side`² stacks).
fn stacks_of(world: &mut PhysicsWorld, v: Vector, side: usize) -> StickSlip {
    let n = side * side;
    for i in 0..n {
        // A grid; in 2D a row.
        #[cfg(not(dim2))]
        let (x, z) = {
            let mid = |k: usize| k as f32 - (side as f32 - 1.0) / 2.0;
            (1.2 * mid(i % side), 1.2 * mid(i / side))
        };
        #[cfg(dim2)]
        let (x, z) = (0.6 * (i as f32 - (n as f32 - 1.0) / 2.0), 0.0);
        for level in 0..2 {
            world.insert(
                RigidBodyBuilder::dynamic()
                    .translation(v3(x, 0.76 + 0.5 * level as f32, z))
                    .linvel(v)
                    .can_sleep(false),
                cuboid3(0.25, 0.25, 0.25)
                    .0
                    .density(500.0)
                    .friction(MU_BA as f32),
            );
        }
    }
    let mut m = StickSlip::new(FrictionMaterial::new(ep()));
    for h in world.colliders.iter().map(|(h, _)| h).collect::<Vec<_>>() {
        m.attach(&mut world.colliders, h, None);
    }
    m
}

#[test]
fn a_snapshot_taken_while_contacts_recycle_resumes_bit_identically() {
    let mut world = PhysicsWorld::default();
    world.insert_collider(cuboid3(12.0, 0.5, 10.0).0.friction(MU_BA as f32), None);
    let m = stacks_on(&mut world, Vector::ZERO);
    // After the snapshot the floor tilts past break-away: recycled contacts are hooked again
    // in both runs, and the stacks slide.
    let recycled = resumes_bit_identically(world, m, 120, 240, 60, |w| set_slope(w, 0.7));
    assert!(recycled >= 60, "only {recycled} colliders recycled");
}

#[test]
fn a_snapshot_taken_while_carried_contacts_recycle_resumes_bit_identically() {
    let mut world = PhysicsWorld::default();
    let (v, half) = carried();
    let platform = world.insert_body(RigidBodyBuilder::kinematic_velocity_based().linvel(v));
    world.insert_collider(
        cuboid3(half.max(12.0), 0.5, 200.0).0.friction(MU_BA as f32),
        Some(platform),
    );
    let m = stacks_on(&mut world, v);
    // Saved while the stacks ride, then tilted past break-away.
    let recycled = resumes_bit_identically(world, m, 120, 240, 60, |w| set_slope(w, 0.7));
    assert!(recycled >= 60, "only {recycled} colliders recycled");
}

/// A pile of boxes and balls dropped on a composite ground.
#[cfg(not(dim2))]
fn pile_on(ground: Ground) -> (PhysicsWorld, StickSlip) {
    let mut world = PhysicsWorld::default();
    ground.insert(&mut world, 6.0, 0.5);
    for i in 0..48 {
        let (x, z, y) = ((i % 4) as f32, ((i / 4) % 4) as f32, (i / 16) as f32);
        let at = v3(0.7 * x - 1.0 + 0.1 * y, 0.4 + 0.8 * y, 0.7 * z - 1.0);
        let shape = if i % 3 == 0 {
            ColliderBuilder::ball(0.25)
        } else {
            cuboid3(0.25, 0.2, 0.3).0
        };
        world.insert(
            RigidBodyBuilder::dynamic().translation(at),
            shape.density(700.0),
        );
    }
    let mut m = StickSlip::new(FrictionMaterial::new(ep()));
    for h in world.colliders.iter().map(|(h, _)| h).collect::<Vec<_>>() {
        m.attach(&mut world.colliders, h, None);
    }
    (world, m)
}

#[cfg(not(dim2))]
#[test]
fn piles_on_a_heightfield_and_a_compound_resume_bit_identically() {
    for ground in [Ground::HeightField, Ground::Compound] {
        let (world, m) = pile_on(ground);
        // Saved while the pile still moves (composite patches measured after the solve),
        // resumed for 2 s as it settles (and recycles).
        let recycled = resumes_bit_identically(world, m, 60, 120, 1000, |_| {});
        println!("{ground:?}: {recycled} colliders recycled at the snapshot");
        let (world, m) = pile_on(ground);
        // Saved once settled, then tilted past break-away.
        let recycled = resumes_bit_identically(world, m, 180, 120, 30, |w| set_slope(w, 0.7));
        println!("{ground:?}: {recycled} colliders recycled at the later snapshot");
    }
}

/// Steps `world` with `m` and a copy, one whose pass after each step judges every contact
/// pair and one whose pass judges only the pairs of the colliders that may go quiet, and
/// compares the two bit for bit at every step; `event(k, world)` runs on both before step k.
/// Returns the most attached colliders recycled at once.
fn walk_as_scan(
    world: PhysicsWorld,
    m: StickSlip,
    steps: usize,
    event: impl Fn(usize, &mut PhysicsWorld),
) -> usize {
    let (mut w2, mut m2) = copy(&world, &m);
    let (mut w1, mut m1) = (world, m);
    m1.set_pass_walks_pairs(Some(false));
    m2.set_pass_walks_pairs(Some(true));
    let mut most = 0;
    for k in 0..steps {
        event(k, &mut w1);
        event(k, &mut w2);
        m1.step(&mut w1);
        m2.step(&mut w2);
        assert!(
            world_bits(&w1) == world_bits(&w2),
            "walking the pairs and scanning them diverged at step {k}"
        );
        let r = recycled(&w1, &m1);
        assert_eq!(r, recycled(&w2, &m2), "recycled sets differ at step {k}");
        // The same friction state, record for record (the snapshot holds every record). Not
        // with rapier's `parallel` feature, whose world saved after a step differs from its
        // copy's in bytes that are not physics (the worlds above are alike).
        #[cfg(not(feature = "parallel"))]
        let state = |w: &PhysicsWorld, m: &StickSlip| {
            let mut bytes = Vec::new();
            WorldSnapshot::save_from(w, m, &mut bytes).unwrap();
            bytes
        };
        #[cfg(not(feature = "parallel"))]
        assert!(
            state(&w1, &m1) == state(&w2, &m2),
            "the friction state differs at step {k}"
        );
        most = most.max(r);
    }
    most
}

#[test]
fn the_pass_after_the_step_decides_alike_on_the_candidates_pairs_and_on_every_pair() {
    // Every collider attached: the stacks settle (recycling), then slide on a tilted floor.
    let mut world = PhysicsWorld::default();
    world.insert_collider(cuboid3(50.0, 0.5, 10.0).0.friction(MU_BA as f32), None);
    let m = stacks_of(&mut world, Vector::ZERO, 8);
    let tilt_at = |at| {
        move |k, w: &mut PhysicsWorld| {
            if k == at {
                set_slope(w, 0.7)
            }
        }
    };
    let most = walk_as_scan(world, m, 240, tilt_at(150));
    assert!(most >= 100, "only {most} colliders recycled");
    // Only some attached: the ground and the lower box of every third stack of two, and the
    // lower box of one more stack, whose flag is the user's (set before attaching): the user
    // takes it off, and puts it back later. The other boxes' pairs are nobody's.
    let mut world = PhysicsWorld::default();
    let ground = world.insert_collider(cuboid3(50.0, 0.5, 10.0).0.friction(MU_BA as f32), None);
    let mut lower = Vec::new();
    for i in 0..24 {
        // A grid; in 2D a row.
        #[cfg(not(dim2))]
        let (x, z) = ((i % 6) as f32 * 0.7 - 2.0, (i / 6) as f32 * 0.7 - 1.5);
        #[cfg(dim2)]
        let (x, z) = (i as f32 * 0.7 - 8.0, 0.0);
        for level in 0..2 {
            let (_, h) = world.insert(
                RigidBodyBuilder::dynamic()
                    .translation(v3(x, 0.76 + 0.5 * level as f32, z))
                    .can_sleep(false),
                cuboid3(0.25, 0.25, 0.25)
                    .0
                    .density(500.0)
                    .friction(MU_BA as f32),
            );
            if level == 0 {
                lower.push(h);
            }
        }
    }
    let users = lower[7];
    world.colliders[users].set_active_hooks(ActiveHooks::MODIFY_SOLVER_CONTACTS);
    let mut m = StickSlip::new(FrictionMaterial::new(ep()));
    m.attach(&mut world.colliders, ground, None);
    for &h in lower.iter().step_by(3).chain([&users]) {
        m.attach(&mut world.colliders, h, None);
    }
    let flag = move |k, w: &mut PhysicsWorld| {
        let hooks = match k {
            100 => ActiveHooks::empty(),
            160 => ActiveHooks::MODIFY_SOLVER_CONTACTS,
            _ => return,
        };
        w.colliders[users].set_active_hooks(hooks);
    };
    let most = walk_as_scan(world, m, 240, move |k, w| {
        flag(k, w);
        tilt_at(200)(k, w);
    });
    assert!(most >= 9, "only {most} colliders recycled");
    #[cfg(not(dim2))]
    for ground in [Ground::HeightField, Ground::Compound] {
        let (world, m) = pile_on(ground);
        let most = walk_as_scan(world, m, 240, tilt_at(180));
        println!("{ground:?}: at most {most} colliders recycled");
    }
}

/// Steps `world` with `m` on a rayon pool of one thread and a copy on a pool of two, and
/// compares the two bit for bit at every step (rapier's own parallel steps are alike on both
/// pools; stickslip's pass after the step must be too, whichever thread judges a pair).
/// Returns the most attached colliders recycled at once.
#[cfg(feature = "parallel")]
fn one_thread_as_two(world: PhysicsWorld, m: StickSlip, steps: usize, tilt_at: usize) -> usize {
    let (mut w2, mut m2) = copy(&world, &m);
    let (mut w1, mut m1) = (world, m);
    let pool = |n| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(n)
            .build()
            .unwrap()
    };
    let (one, two) = (pool(1), pool(2));
    let mut most = 0;
    for k in 0..steps {
        if k == tilt_at {
            set_slope(&mut w1, 0.7);
            set_slope(&mut w2, 0.7);
        }
        one.install(|| m1.step(&mut w1));
        two.install(|| m2.step(&mut w2));
        assert!(
            world_bits(&w1) == world_bits(&w2),
            "one thread and two diverged at step {k}"
        );
        let r = recycled(&w1, &m1);
        assert_eq!(r, recycled(&w2, &m2), "recycled sets differ at step {k}");
        most = most.max(r);
    }
    most
}

#[cfg(feature = "parallel")]
#[test]
fn the_pass_after_the_step_decides_alike_on_one_thread_and_on_two() {
    // 144 stacks: hundreds of pairs, more than a thread takes at a time.
    let mut world = PhysicsWorld::default();
    world.insert_collider(cuboid3(50.0, 0.5, 10.0).0.friction(MU_BA as f32), None);
    let m = stacks_of(&mut world, Vector::ZERO, 12);
    // Settling (recycling), then tilted past break-away: hooked again, sliding.
    let most = one_thread_as_two(world, m, 240, 150);
    assert!(most >= 240, "only {most} colliders recycled");
    #[cfg(not(dim2))]
    for ground in [Ground::HeightField, Ground::Compound] {
        let (world, m) = pile_on(ground);
        let most = one_thread_as_two(world, m, 240, 180);
        println!("{ground:?}: at most {most} colliders recycled");
    }
}
