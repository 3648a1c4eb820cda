//! A box on a conveyor belt in a rapier world, 3D and 2D (stickslip-fixtures2d): the belt is a fixed ground whose surface
//! velocity v_b is set by the user's own conveyor hook (the solver contacts' target tangent
//! velocity), which stickslip wraps. Invariants, for an elasto-plastic law with break-away
//! μ_ba = 0.5 above its sliding coefficient μ_k = 0.3 (1 kg box, rotations locked):
//! - put down at rest, the box slips at the kinetic level once its contact has formed,
//!   a = μ_k g within 2 % (as plain rapier at μ_k), then is carried at the belt speed:
//!   |v − v_b| < 1e-4 m/s, creeping less than the elastic range g_ba = μ_ba/c on the belt;
//! - held back by a pull of 0.9 μ_ba m g (above μ_k: plain rapier at μ_k slips there) it
//!   stays carried at v_b, within g_ba of the belt over 2 s;
//! - pulled by 1.2 μ_ba m g it breaks away and slips at the kinetic level,
//!   a = (μ_k m g − F)/m within 2 %, as plain rapier at μ_k;
//! - a mass–spring on the belt stick-slips with the analytic period
//!   T = 2Δ/v_b + (π + 2 atan(v_b/(ωΔ)))/ω, Δ = (μ_ba − μ_k) N/k, within 2 %, for the exact
//!   switched law and for the elasto-plastic law at c = 1e5…1e7 1/m (Δ = 0: T = 2π/ω).

use stickslip_core::law::{Coulomb, ElastoPlastic, Law, Physical};
use stickslip_core::sliding_curve::Curve;
use stickslip_fixtures::{Conveyor, cuboid3, v3};
use stickslip_rapier::rapier::prelude::*;
use stickslip_rapier::{FrictionMaterial, StickSlip};

/// Standard gravity (m/s²).
const G: f64 = 9.81;

/// The EP law of the tests: c = 1e4 1/m, μ_ba = 0.5, μ_max = 0.55, sliding at μ_k.
fn ep(mu_k: f64) -> Law {
    Law::elasto_plastic(C, MU_BA, 0.55, Curve::constant(mu_k).unwrap()).unwrap()
}

const MU_BA: f64 = 0.5;
const MU_K: f64 = 0.3;
/// Stiffness of [`ep`] (1/m).
const C: f64 = 1e4;
const M: f64 = 1.0;
const V_B: f64 = 0.5;
const DT: f64 = 1.0 / 60.0;

/// A 0.2 m box of mass [`M`] (rotations locked, never sleeping) on a fixed belt whose
/// surface moves at `v_b` along +x, starting at `v0`; `law` on both colliders (None: plain
/// rapier at μ_k).
struct Belt {
    world: PhysicsWorld,
    body: RigidBodyHandle,
    modifier: Option<StickSlip<Conveyor>>,
    conveyor: Conveyor,
}

impl Belt {
    fn new(law: Option<Law>, v_b: f64, v0: f64, dt: f64) -> Belt {
        let mut world = PhysicsWorld::default();
        world.integration_parameters.dt = dt as f32;
        let belt = world.insert_collider(
            cuboid3(500.0, 0.1, 50.0)
                .0
                .friction(MU_K as f32)
                // The user flags the belt for their hook, as without stickslip.
                .active_hooks(ActiveHooks::MODIFY_SOLVER_CONTACTS),
            None,
        );
        let half = 0.1;
        let (body, cube) = world.insert(
            RigidBodyBuilder::dynamic()
                .translation(v3(0.0, 0.1 + half, 0.0))
                .linvel(v3(v0 as f32, 0.0, 0.0))
                .lock_rotations()
                .can_sleep(false),
            {
                let (cube, volume) = cuboid3(half, half, half);
                cube.density(M as f32 / volume).friction(MU_K as f32)
            },
        );
        let conveyor = Conveyor {
            belt,
            velocity: v3(v_b as f32, 0.0, 0.0),
        };
        let modifier = law.map(|law| {
            let mut m = StickSlip::with_hooks(FrictionMaterial::new(law), conveyor);
            m.attach(&mut world.colliders, belt, None);
            m.attach(&mut world.colliders, cube, None);
            m
        });
        Belt {
            world,
            body,
            modifier,
            conveyor,
        }
    }

    fn step(&mut self) {
        match self.modifier.as_mut() {
            Some(m) => m.step(&mut self.world),
            None => self.world.step_with_events(&self.conveyor, &()),
        }
    }

    fn steps(&mut self, n: usize) {
        for _ in 0..n {
            self.step();
        }
    }

    fn x(&self) -> f64 {
        self.world.bodies[self.body].translation().x as f64
    }

    fn vx(&self) -> f64 {
        self.world.bodies[self.body].linvel().x as f64
    }

    fn pull(&mut self, fx: f64) {
        let b = &mut self.world.bodies[self.body];
        b.reset_forces(true);
        b.add_force(v3(fx as f32, 0.0, 0.0), true);
    }
}

#[test]
fn put_down_at_rest_it_slips_at_mu_k_then_rides_at_belt_speed() {
    // A faster belt here: slipping lasts v/(μ_k g) = 0.51 s. The acceleration is measured
    // over steps 5 to 25, after the contact has formed (a new contact holds at its capacity
    // for its first steps: see `stickslip_core::contact::step`), the ride from 1 s on.
    let v_b = 1.5;
    for law in [Some(ep(MU_K)), None] {
        let name = if law.is_some() { "stickslip" } else { "plain" };
        let mut belt = Belt::new(law, v_b, 0.0, DT);
        belt.steps(5);
        let v1 = belt.vx();
        belt.steps(20);
        let a = (belt.vx() - v1) / (20.0 * DT);
        println!(
            "{name}: slipping a = {a:.4} m/s², μ_k g = {:.4} ({:+.2} %)",
            MU_K * G,
            100.0 * (a / (MU_K * G) - 1.0)
        );
        assert!((a / (MU_K * G) - 1.0).abs() < 0.02, "{name}: a = {a}");
        belt.steps(35);
        let x0 = belt.x();
        let n = 120;
        let mut worst: f64 = 0.0;
        for _ in 0..n {
            belt.step();
            worst = worst.max((belt.vx() - v_b).abs());
        }
        let creep = belt.x() - x0 - v_b * n as f64 * DT;
        println!("{name}: riding |v − v_b| ≤ {worst:.2e} m/s, creep over 2 s {creep:.2e} m");
        assert!(worst < 1e-4, "{name}: not carried at belt speed ({worst})");
        if name == "stickslip" {
            assert!(
                creep.abs() < MU_BA / C,
                "{name}: crept {creep} m on the belt"
            );
        }
    }
}

/// Speed relative to the belt (max over 2 s after 0.5 s) and creep relative to the belt
/// over those 2 s of a box starting at belt speed, pulled against the belt by `pull` m g.
fn held_back(law: Option<Law>, pull: f64) -> (f64, f64) {
    let mut belt = Belt::new(law, V_B, V_B, DT);
    belt.pull(-pull * M * G);
    belt.steps(30);
    let x0 = belt.x();
    let n = 120;
    let mut worst: f64 = 0.0;
    for _ in 0..n {
        belt.step();
        worst = worst.max((belt.vx() - V_B).abs());
    }
    (worst, belt.x() - x0 - V_B * n as f64 * DT)
}

#[test]
fn pulled_below_break_away_it_is_carried_where_plain_rapier_slips() {
    let pull = 0.9 * MU_BA;
    let (slip, creep) = held_back(Some(ep(MU_K)), pull);
    println!("stickslip, pull {pull} m g: |v − v_b| ≤ {slip:.2e} m/s, creep {creep:.2e} m");
    assert!(
        slip < 1e-4,
        "the pulled box slipped on the belt at {slip} m/s"
    );
    assert!(
        creep.abs() < MU_BA / C,
        "crept {creep} m, elastic range {} m",
        MU_BA / C
    );
    let (plain_slip, plain_creep) = held_back(None, pull);
    println!("plain rapier at μ_k: |v − v_b| up to {plain_slip:.3} m/s, {plain_creep:.3} m");
    assert!(plain_creep < -0.1, "plain rapier at μ_k held the box");
}

#[test]
fn pulled_above_break_away_it_slips_at_the_kinetic_level() {
    let pull = 1.2 * MU_BA;
    let expected = (MU_K - pull) * G;
    for law in [Some(ep(MU_K)), None] {
        let name = if law.is_some() { "stickslip" } else { "plain" };
        let mut belt = Belt::new(law, V_B, V_B, DT);
        belt.steps(10);
        belt.pull(-pull * M * G);
        // Break-away, then 0.5 s of slipping (the box slows from v_b by 1.5 m/s).
        belt.steps(5);
        let v0 = belt.vx();
        let n = 30;
        belt.steps(n);
        let a = (belt.vx() - v0) / (n as f64 * DT);
        println!(
            "{name}: a = {a:.4} m/s², (μ_k − F/mg) g = {expected:.4} ({:+.2} %)",
            100.0 * (a / expected - 1.0)
        );
        assert!((a / expected - 1.0).abs() < 0.02, "{name}: a = {a}");
    }
}

const K: f64 = 100.0;
const V_SPRING_BELT: f64 = 0.1;

/// Times where the block's velocity falls through v_b/2 (once per stick-slip cycle).
fn slip_marks(law: Law, seconds: f64) -> Vec<f64> {
    let dt = 1.0 / 480.0;
    let mut belt = Belt::new(Some(law), V_SPRING_BELT, 0.0, dt);
    let mut marks = Vec::new();
    let mut v_prev = belt.vx();
    for k in 0..(seconds / dt) as usize {
        let x = belt.x();
        belt.pull(-K * x);
        belt.step();
        let v = belt.vx();
        let level = 0.5 * V_SPRING_BELT;
        if v_prev >= level && v < level {
            let w = (v_prev - level) / (v_prev - v);
            marks.push((k as f64 + w) * dt);
        }
        v_prev = v;
    }
    marks
}

fn check_period(law: Law, mu_s: f64, mu_k: f64) {
    let marks = slip_marks(law, 8.0);
    let periods: Vec<f64> = marks.windows(2).skip(1).map(|w| w[1] - w[0]).collect();
    assert!(periods.len() >= 5, "too few stick-slip cycles: {marks:?}");
    let measured = periods.iter().sum::<f64>() / periods.len() as f64;
    let omega = (K / M).sqrt();
    let delta = (mu_s - mu_k) * M * G / K;
    let v_b = V_SPRING_BELT;
    let analytic = if delta > 0.0 {
        2.0 * delta / v_b + (std::f64::consts::PI + 2.0 * (v_b / (omega * delta)).atan()) / omega
    } else {
        2.0 * std::f64::consts::PI / omega
    };
    let err = measured / analytic - 1.0;
    println!(
        "μ_s {mu_s} μ_k {mu_k}: period {measured:.4} s, analytic {analytic:.4} s ({:+.2} %)",
        100.0 * err
    );
    assert!(err.abs() < 0.02, "{measured} vs {analytic}");
}

#[test]
fn a_mass_spring_on_the_belt_stick_slips_with_the_analytic_period() {
    let physical = Physical::new(MU_BA, Curve::constant(MU_K).unwrap()).unwrap();
    check_period(Law::Physical(physical), MU_BA, MU_K);
    check_period(Law::Coulomb(Coulomb::new(MU_K).unwrap()), MU_K, MU_K);
    for c in [1e5, 1e6, 1e7] {
        let law = ElastoPlastic::new(c, MU_BA, MU_BA, Curve::constant(MU_K).unwrap()).unwrap();
        check_period(Law::ElastoPlastic(law), MU_BA, MU_K);
    }
}
