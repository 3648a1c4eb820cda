//! A box on an incline in a real rapier world, 3D and 2D (stickslip-fixtures2d). Invariants:
//! at 0.95 of the break-away angle (tan θ = 0.95 μ_ba) the elasto-plastic contact keeps the
//! box within g_ba = μ_ba/c of its start over 10 s, while the regularized law creeps at its
//! steady speed ġ_t0 tan θ/μ_ve within 2 % (plain rapier Coulomb is measured beside them);
//! with a sliding coefficient μ_k = 0.4 below μ_ba = 0.5 the box also holds within g_ba at
//! tan θ = 0.45, where plain rapier at μ_k slides; above the angle the box slides with
//! a = g (sin θ − μ_k cos θ) within 2 %, μ_k being the law's steady sliding coefficient.

use stickslip_core::law::{Coulomb, FrictionLaw, Law, Regularization, Regularized};
use stickslip_core::sliding_curve::Curve;
use stickslip_fixtures::BoxOnGround;
use stickslip_rapier::rapier::prelude::*;
use stickslip_rapier::{FrictionMaterial, StickSlip};

fn incline(theta: f64) -> stickslip_fixtures::BoxScene {
    BoxOnGround {
        incline: theta,
        ..BoxOnGround::default()
    }
    .build()
}

const MU_BA: f64 = 0.5;
const MU_MAX: f64 = 0.55;
const C: f64 = 1e4;
const DT_STEPS: usize = 600; // 10 s at 60 Hz

fn ep() -> Law {
    Law::elasto_plastic(C, MU_BA, MU_MAX, Curve::constant(MU_MAX).unwrap()).unwrap()
}

/// Displacement along the slope after settling 1 s then 10 s more, with `law` (None: plain
/// rapier with collider friction `mu`), and the last friction report's (state μ, effective μ).
fn creep(law: Option<Law>, theta: f64, mu: f32) -> (f64, Option<(f64, f64)>) {
    let scene = incline(theta);
    let (mut world, body) = (scene.world, scene.body);
    for (_, c) in world.colliders.iter_mut() {
        c.set_friction(mu);
    }
    let mut modifier = law.map(|l| {
        let mut m = StickSlip::new(FrictionMaterial::new(l))
            .with_read_back(stickslip_rapier::ReadBack::Contacts);
        // Every collider: the pairs are the law's alone.
        let all: Vec<ColliderHandle> = world.colliders.iter().map(|(h, _)| h).collect();
        for h in all {
            m.attach(&mut world.colliders, h, None);
        }
        m
    });
    let x_of =
        |world: &PhysicsWorld, body: RigidBodyHandle| world.bodies[body].translation().x as f64;
    let mut step = |world: &mut PhysicsWorld| match modifier.as_mut() {
        Some(m) => m.step(world),
        None => world.step(),
    };
    for _ in 0..60 {
        step(&mut world);
    }
    let x0 = x_of(&world, body);
    for _ in 0..DT_STEPS {
        step(&mut world);
    }
    let state = modifier.as_ref().and_then(|m| {
        m.reports()
            .unwrap()
            .first()
            .map(|r| (r.mu, r.effective_mu()))
    });
    (x_of(&world, body) - x0, state)
}

#[test]
fn sticks_below_break_away_without_creep() {
    let theta = (0.95 * MU_BA).atan();
    let g_ba = MU_BA / C;
    let (ep_creep, ep_state) = creep(Some(ep()), theta, 0.0);
    let regul = Law::Regularized(
        Regularized::new(
            Curve::constant(MU_MAX).unwrap(),
            0.01,
            Regularization::Linear,
        )
        .unwrap(),
    );
    let (regul_creep, _) = creep(Some(regul), theta, 0.0);
    let (coulomb_creep, _) = creep(None, theta, MU_BA as f32);
    println!(
        "creep over 10 s: EP {ep_creep:.3e} m, Regul {regul_creep:.3e} m, rapier Coulomb {coulomb_creep:.3e} m, g_ba {g_ba:.1e} m"
    );
    assert!(ep_creep.abs() <= g_ba, "EP crept {ep_creep} > g_ba {g_ba}");
    // Quasi-static sticking (seed Eq. 2): the law's state carries exactly the load, tan θ.
    let (mu_state, mu_eff) = ep_state.expect("a report");
    println!(
        "EP state mu {mu_state:.4}, effective {mu_eff:.4}, tan θ {:.4}",
        theta.tan()
    );
    assert!(
        (mu_state - theta.tan()).abs() < 0.01 * theta.tan(),
        "state {mu_state}"
    );
    assert!(
        (mu_eff - theta.tan()).abs() < 0.01 * theta.tan(),
        "effective {mu_eff}"
    );
    assert!(
        regul_creep > 100.0 * g_ba,
        "Regul should creep, moved {regul_creep}"
    );
    // Regul creeps at its steady speed ġ_t0 · tan θ / μ_ve (the law has no sticking).
    let expect = 0.01 * theta.tan() / MU_MAX * (DT_STEPS as f64 / 60.0);
    assert!(
        ((regul_creep - expect) / expect).abs() < 0.02,
        "Regul creep {regul_creep} vs {expect}"
    );
}

/// The EP law of the tests with a sliding coefficient `mu_k` below its break-away μ_ba.
fn ep_sliding_at(mu_k: f64) -> Law {
    Law::elasto_plastic(C, MU_BA, MU_MAX, Curve::constant(mu_k).unwrap()).unwrap()
}

#[test]
fn holds_between_kinetic_and_break_away_where_plain_rapier_slides() {
    const MU_K: f64 = 0.4;
    let g_ba = MU_BA / C;
    for tan in [0.95 * MU_BA, 0.45] {
        let (held, _) = creep(Some(ep_sliding_at(MU_K)), tan.atan(), MU_K as f32);
        assert!(
            held.abs() < g_ba,
            "tan θ = {tan}: moved {held:e} m, elastic range {g_ba:e} m"
        );
    }
    // Plain rapier at the sliding coefficient has no static friction above it.
    let (plain, _) = creep(None, 0.45f64.atan(), MU_K as f32);
    assert!(
        plain > 0.1,
        "plain rapier at μ = {MU_K} moved only {plain} m"
    );
}

#[test]
fn slides_above_break_away_with_kinetic_acceleration() {
    let g = 9.81;
    let cases = [
        (0.7f64, ep()),
        (0.7, Law::Coulomb(Coulomb::new(MU_MAX).unwrap())),
        (0.6, ep_sliding_at(0.4)),
        (1.2, ep_sliding_at(0.4)),
    ];
    for (tan, law) in cases {
        let theta = tan.atan();
        let mu_k = law.sliding_coefficient(1.0);
        let mut scene = incline(theta);
        let mut m = StickSlip::new(FrictionMaterial::new(law.clone()))
            .with_read_back(stickslip_rapier::ReadBack::Contacts);
        m.attach(&mut scene.world.colliders, scene.ground, None);
        m.attach(&mut scene.world.colliders, scene.box_collider, None);
        // Let the contact form, then measure x(t) over 1 s of sliding.
        for _ in 0..10 {
            m.step(&mut scene.world);
        }
        let (x0, v0) = (scene.x(), scene.vx());
        let steps = 60;
        for _ in 0..steps {
            m.step(&mut scene.world);
        }
        let t = steps as f64 / 60.0;
        let a = 2.0 * (scene.x() - x0 - v0 * t) / (t * t);
        let expect = g * (theta.sin() - mu_k * theta.cos());
        println!(
            "{} at tan θ {tan}: a = {a:.4}, expected {expect:.4}",
            law.name()
        );
        assert!(
            ((a - expect) / expect).abs() < 0.02,
            "{} at tan θ {tan}: a {a} vs {expect}",
            law.name()
        );
    }
}
