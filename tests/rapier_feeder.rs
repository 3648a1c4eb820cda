//! A vibratory feeder in a real rapier world: a kinematic trough vibrating along a throw angle
//! (0.5–2 mm, 20–40 Hz, 15–33°, throw numbers 0.8–1.7, so that the part hops) carries one
//! part forward. Invariants: plain rapier at a fine step (1/30 000 s) is within 3 % of the
//! independent rigid-body reference of the core (`stickslip::core::feeder`: point mass, exact
//! ballistic flight, plastic landing with Coulomb impact friction); with the elasto-plastic law
//! (c = 1e5 1/m, g_ba = 5 µm) the transport speed is within 3 % of plain rapier (Coulomb, same
//! μ) at the same step (1/3000 s): nothing of the contact state survives the flight or brakes
//! the landing. At the fine step the EP contact's tangential compliance k_t = c F̄ shows under a
//! normal load that drops to zero every period (Popov's mechanism lowers the mean friction), so
//! EP approaches the rigid reference as c grows: its deviation does not grow from c = 1e5 to
//! 1e7, and at c = 1e7 (g_ba = 50 nm) it is within 3 %.

use rapier3d::prelude::*;
use stickslip::core::feeder::VibratoryFeeder;
use stickslip::core::law::Law;
use stickslip::core::sliding_curve::Curve;
use stickslip::rapier::{FrictionMaterial, StickSlip};

const MU: f64 = 0.5;
const G: f64 = 9.81;

/// Mean transport speed of the part in rapier, with stickslip's EP law or plain friction.
fn rapier_speed(feeder: &VibratoryFeeder, f: f64, dt: f64, ep: Option<f64>) -> f64 {
    let mut world = PhysicsWorld::default();
    world.integration_parameters.dt = dt as f32;
    let trough = world.insert_body(RigidBodyBuilder::kinematic_position_based());
    let trough_collider = world.insert_collider(
        ColliderBuilder::cuboid(50.0, 0.05, 1.0).friction(MU as f32),
        Some(trough),
    );
    let half = 0.02f32;
    let (v0x, v0y) = feeder.trough_velocity(0.0);
    let (part, _) = world.insert(
        RigidBodyBuilder::dynamic()
            .translation(Vector::new(0.0, 0.05 + half, 0.0))
            .linvel(Vector::new(v0x as f32, v0y as f32, 0.0))
            .lock_rotations()
            .can_sleep(false),
        ColliderBuilder::cuboid(half, half, half)
            .density(1000.0)
            .friction(MU as f32),
    );
    let mut friction = ep.map(|c| {
        let law = Law::elasto_plastic(c, MU, MU, Curve::constant(MU).unwrap()).unwrap();
        let mut m = StickSlip::new(FrictionMaterial::new(law));
        m.attach(&mut world.colliders, trough_collider, None);
        m
    });
    let period = 1.0 / f;
    let (settle, measure) = (20.0 * period, 20.0 * period);
    let steps = ((settle + measure) / dt).round() as usize;
    let mut x_start = None;
    for k in 0..steps {
        let t_next = (k + 1) as f64 * dt;
        let (x, y) = feeder.trough_position(t_next);
        world.bodies[trough].set_next_kinematic_translation(Vector::new(x as f32, y as f32, 0.0));
        match friction.as_mut() {
            Some(m) => m.step(&mut world),
            None => world.step(),
        }
        if x_start.is_none() && t_next >= settle {
            x_start = Some((world.bodies[part].translation().x as f64, t_next));
        }
    }
    let (x0, t0) = x_start.unwrap();
    (world.bodies[part].translation().x as f64 - x0) / (steps as f64 * dt - t0)
}

#[test]
fn feeder_transport_speed_matches_plain_rapier_and_the_rigid_body_reference() {
    let cases = [
        (1e-3, 25.0, 25.0),
        (0.5e-3, 40.0, 30.0),
        (2e-3, 20.0, 15.0),
        (1e-3, 28.0, 33.0),
    ];
    for (a, f, beta_deg) in cases {
        let feeder = VibratoryFeeder::new(a, f, f64::to_radians(beta_deg), MU, G).unwrap();
        let reference = feeder.transport_speed(20, 20);
        let coarse = 1.0 / 3000.0;
        let ep = rapier_speed(&feeder, f, coarse, Some(1e5));
        let plain = rapier_speed(&feeder, f, coarse, None);
        let fine = 1.0 / 30000.0;
        let plain_fine = rapier_speed(&feeder, f, fine, None);
        let ep_fine: Vec<f64> = [1e5, 1e6, 1e7]
            .iter()
            .map(|&c| rapier_speed(&feeder, f, fine, Some(c)))
            .collect();
        println!(
            "A {a} m, f {f} Hz, throw {beta_deg}°, Γ {:.2}: reference {reference:.5} m/s; \
             dt 1/3000: EP {ep:.5}, plain {plain:.5}; dt 1/30000: plain {plain_fine:.5}, \
             EP c = 1e5/1e6/1e7: {:.5} {:.5} {:.5}",
            feeder.throw_number(),
            ep_fine[0],
            ep_fine[1],
            ep_fine[2]
        );
        let rel = |x: f64, y: f64| (x - y).abs() / y;
        assert!(
            rel(plain_fine, reference) < 0.03,
            "plain {plain_fine} vs reference {reference}"
        );
        assert!(
            rel(ep, plain) < 0.03,
            "EP {ep} vs plain {plain} at dt 1/3000"
        );
        let dev: Vec<f64> = ep_fine.iter().map(|&v| rel(v, reference)).collect();
        assert!(
            dev[1] <= dev[0] + 0.005 && dev[2] <= dev[1] + 0.005,
            "EP deviations {dev:?}"
        );
        assert!(
            dev[2] < 0.03,
            "EP at c = 1e7: {} vs reference {reference}",
            ep_fine[2]
        );
    }
}
