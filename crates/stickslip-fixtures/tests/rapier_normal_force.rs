//! The normal force stickslip reads from rapier is the load the contact carries, under both
//! rapier versions it builds against (0.36, and 0.35 where the reported impulse still holds
//! the step's warm start: read as is it comes out ~1/4 high with 4 substeps). Invariants: a
//! box resting on the ground reports its weight m g within 0.5 % (masses 1–100 kg, 60 and
//! 240 Hz); a box pressed by an extra downward force oscillating at 2 Hz between 0 and m g
//! reports, step by step, its weight plus the force within 2 % of m g.
//! In 3D and in 2D (stickslip-fixtures2d).

use stickslip_core::law::Law;
use stickslip_core::sliding_curve::Curve;
use stickslip_fixtures::{cuboid3, v3};
use stickslip_rapier::rapier::prelude::*;
use stickslip_rapier::{FrictionMaterial, ReadBack, StickSlip};

const G: f64 = 9.81;

/// A box of `mass` on a fixed ground, both attached, reports on.
fn scene(mass: f32, dt: f32) -> (PhysicsWorld, RigidBodyHandle, StickSlip) {
    let mut world = PhysicsWorld::default();
    world.integration_parameters.dt = dt;
    let ground =
        world.insert_collider(cuboid3(5.0, 0.1, 5.0).0.translation(Vector::Y * -0.1), None);
    let (b, c) = world.insert(
        RigidBodyBuilder::dynamic()
            .translation(v3(0.0, 0.1, 0.0))
            .can_sleep(false),
        cuboid3(0.1, 0.1, 0.1).0.mass(mass),
    );
    let law = Law::elasto_plastic(1e5, 0.5, 0.5, Curve::constant(0.5).unwrap()).unwrap();
    let mut m = StickSlip::new(FrictionMaterial::new(law)).with_read_back(ReadBack::Contacts);
    m.attach(&mut world.colliders, ground, None);
    m.attach(&mut world.colliders, c, None);
    (world, b, m)
}

fn normal_force(m: &StickSlip) -> f64 {
    m.reports().unwrap().iter().map(|r| r.normal_force).sum()
}

#[test]
fn a_resting_box_reports_its_weight() {
    for mass in [1.0f32, 10.0, 100.0] {
        for hz in [60.0f32, 240.0] {
            let (mut world, _, mut m) = scene(mass, 1.0 / hz);
            for _ in 0..(hz as usize) {
                m.step(&mut world);
            }
            let (f, w) = (normal_force(&m), mass as f64 * G);
            assert!(
                (f - w).abs() < 0.005 * w,
                "{mass} kg at {hz} Hz: {f} N vs m g {w} N"
            );
        }
    }
}

#[test]
fn an_oscillating_load_is_read_step_by_step() {
    let (mass, hz) = (10.0f32, 240.0f32);
    let (mut world, b, mut m) = scene(mass, 1.0 / hz);
    let w = mass as f64 * G;
    for _ in 0..60 {
        m.step(&mut world);
    }
    let mut worst = 0.0f64;
    for k in 0..240 {
        let t = (k as f64 + 0.5) / hz as f64;
        let extra = 0.5 * w * (1.0 - (2.0 * std::f64::consts::PI * 2.0 * t).cos());
        let body = &mut world.bodies[b];
        body.reset_forces(true);
        body.add_force(v3(0.0, -(extra as f32), 0.0), true);
        m.step(&mut world);
        worst = worst.max((normal_force(&m) - (w + extra)).abs());
    }
    assert!(worst < 0.02 * w, "worst step off by {worst} N (m g {w} N)");
}
