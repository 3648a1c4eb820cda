//! A disc (a ball collider in 2D) on an incline (gravity tilted) in a rapier2d world, with
//! stickslip's elasto-plastic law attached to every collider, beside plain rapier2d in the same
//! test. Invariants, at 60 Hz and 240 Hz, with the default `StickSlipConfig`:
//! - below the no-slip limit (tan θ = 0.3 < μ (1 + m r²/I) = 3 μ, μ = 0.5) it rolls without
//!   slipping at a = g sin θ / (1 + I/(m r²)) = 2/3 g sin θ within 2 %, and its contact does
//!   not creep: the contact point's slip speed |v + ω r| stays within plain rapier2d's own
//!   (+1 mm/s) and the slip accumulated over 1.5 s, Δx + r Δφ, within plain rapier2d's
//!   (+0.1 mm) — for μ_ba = μ_k and for static above kinetic friction;
//! - above it (tan θ = 0.5, μ = 0.1) it rolls with slip at a = g (sin θ − μ cos θ) and spins
//!   up at ω̇ = μ g cos θ / (r I/(m r²)) within 2 %.

mod support;

use stickslip_rapier2d::core::law::Law;
use stickslip_rapier2d::rapier::prelude::*;
use stickslip_rapier2d::{FrictionMaterial, StickSlip};
use support::{G, ep, ep_flat};

const R: f32 = 0.2;

struct Rolled {
    /// Acceleration along the slope (m/s²).
    accel: f64,
    /// Spin-up rate (rad/s², positive rolling down the slope).
    spin_up: f64,
    /// Largest contact-point slip speed |v_x + ω r| (m/s).
    max_slip: f64,
    /// Slip accumulated at the contact, Δx + r Δφ (m).
    creep: f64,
    /// I / (m r²) of the disc.
    k: f64,
}

/// A disc of radius [`R`] (density 1000) at rest on a ground slab, gravity tilted to
/// `tan_theta` down +x, every collider's rapier friction `mu`; `law` on every collider, or
/// plain rapier2d. Measured over 1.5 s after 0.25 s.
fn roll(tan_theta: f64, mu: f32, dt: f64, law: Option<Law>) -> Rolled {
    let mut world = PhysicsWorld::default();
    world.integration_parameters.dt = dt as f32;
    let th = tan_theta.atan();
    world.gravity = Vector::new((G * th.sin()) as f32, -(G * th.cos()) as f32);
    world.insert_collider(
        ColliderBuilder::cuboid(50.0, 0.5)
            .translation(Vector::new(0.0, -0.5))
            .friction(mu),
        None,
    );
    let (body, _) = world.insert(
        RigidBodyBuilder::dynamic()
            .translation(Vector::new(-15.0, R))
            .can_sleep(false),
        ColliderBuilder::ball(R).density(1000.0).friction(mu),
    );
    let mut m = law.map(|law| {
        let mut m = StickSlip::new(FrictionMaterial::new(law));
        let all: Vec<ColliderHandle> = world.colliders.iter().map(|(h, _)| h).collect();
        for h in all {
            m.attach(&mut world.colliders, h, None);
        }
        m
    });
    let mut step = |world: &mut PhysicsWorld| match m.as_mut() {
        Some(m) => m.step(world),
        None => world.step(),
    };
    for _ in 0..(0.25 / dt).round() as usize {
        step(&mut world);
    }
    let b = &world.bodies[body];
    let k = b.mass_properties().local_mprops.principal_inertia() as f64
        / (b.mass() as f64 * (R as f64).powi(2));
    let (v0, w0, x0) = (
        b.linvel().x as f64,
        -b.angvel() as f64,
        b.translation().x as f64,
    );
    let mut angle = b.rotation().angle() as f64;
    let mut turned = 0.0;
    let n = (1.5 / dt).round() as usize;
    let mut max_slip: f64 = 0.0;
    for _ in 0..n {
        step(&mut world);
        let b = &world.bodies[body];
        // Bottom point: v + ω ẑ × (−r ŷ) = v + ω r x̂.
        max_slip = max_slip.max((b.linvel().x + b.angvel() * R).abs() as f64);
        let now = b.rotation().angle() as f64;
        let mut d = now - angle;
        d -= std::f64::consts::TAU * (d / std::f64::consts::TAU).round();
        turned += d;
        angle = now;
    }
    let t = n as f64 * dt;
    let b = &world.bodies[body];
    Rolled {
        accel: (b.linvel().x as f64 - v0) / t,
        spin_up: (-b.angvel() as f64 - w0) / t,
        max_slip,
        creep: b.translation().x as f64 - x0 + R as f64 * turned,
        k,
    }
}

fn rel(measured: f64, expected: f64) -> f64 {
    measured / expected - 1.0
}

#[test]
fn a_disc_rolls_without_slipping_below_the_limit() {
    let (tan_theta, mu) = (0.3, 0.5);
    let s = tan_theta.atan().sin();
    for dt in [1.0 / 60.0, 1.0 / 240.0] {
        let plain = roll(tan_theta, mu as f32, dt, None);
        assert!((plain.k - 0.5).abs() < 1e-3, "a disc's I/(m r²) is 1/2");
        let expected = G * s / (1.0 + plain.k);
        println!(
            "{:.0} Hz: 2/3 g sin θ = {expected:.4} m/s²; plain rapier2d {:+.2} %, slip ≤ \
             {:.1e} m/s, creep {:.1e} m",
            1.0 / dt,
            100.0 * rel(plain.accel, expected),
            plain.max_slip,
            plain.creep
        );
        for (name, law) in [("ep 0.5", ep_flat(1e5, mu, mu)), ("ep 0.5/0.4", ep(0.4))] {
            let r = roll(tan_theta, mu as f32, dt, Some(law));
            println!(
                "    {name:10} {:+.2} %, slip ≤ {:.1e} m/s, creep {:.1e} m",
                100.0 * rel(r.accel, expected),
                r.max_slip,
                r.creep
            );
            assert!(
                rel(r.accel, expected).abs() < 0.02,
                "{name} at {dt}: a = {} vs {expected}",
                r.accel
            );
            assert!(
                r.max_slip <= plain.max_slip + 1e-3,
                "{name} at {dt}: slip {} vs plain {}",
                r.max_slip,
                plain.max_slip
            );
            assert!(
                r.creep.abs() <= plain.creep.abs() + 1e-4,
                "{name} at {dt}: the contact crept {} m (plain {})",
                r.creep,
                plain.creep
            );
        }
    }
}

#[test]
fn a_disc_rolls_with_slip_above_the_limit() {
    let (tan_theta, mu) = (0.5, 0.1);
    let th = tan_theta.atan();
    let expected = G * (th.sin() - mu * th.cos());
    for dt in [1.0 / 60.0, 1.0 / 240.0] {
        let plain = roll(tan_theta, mu as f32, dt, None);
        let spin = mu * G * th.cos() / (plain.k * R as f64);
        let r = roll(tan_theta, mu as f32, dt, Some(ep_flat(1e5, mu, mu)));
        println!(
            "{:.0} Hz: a {expected:.4} m/s², ω̇ {spin:.3} rad/s²; plain {:+.2} % / {:+.2} %, \
             stickslip {:+.2} % / {:+.2} %",
            1.0 / dt,
            100.0 * rel(plain.accel, expected),
            100.0 * rel(plain.spin_up, spin),
            100.0 * rel(r.accel, expected),
            100.0 * rel(r.spin_up, spin)
        );
        assert!(rel(r.accel, expected).abs() < 0.02, "a = {}", r.accel);
        assert!(rel(r.spin_up, spin).abs() < 0.02, "ω̇ = {}", r.spin_up);
    }
}
