//! A sled dragged over a plate in a bevy_rapier app feels the friction of its material's
//! closed forms (in 3D, and in 2D in stickslip-bevy-rapier2d). The sled is pressed onto a fixed
//! plate by F = 9.81 N (gravity off, rotations locked) and dragged at an imposed speed v (its
//! velocity along x set before every step). Invariants, with stickslip's default configuration:
//! - an elasto-plastic material on a Stribeck curve: from 1 mm/s to 1 m/s the sled feels
//!   μ_ve(v) within 2 % once its elastic range is behind it, from its momentum (m Δv per step
//!   over F dt; the sled is heavy enough that a step's friction changes its speed by 1 %) and
//!   from the read-back (`StickSlipContacts`);
//! - over a plate with an averaged normal vibration source (α = 0.5, f = 5 Hz, 40 steps per
//!   period) and the law in the seed's sharp limit (μ_ba = μ_max = μ0 = 0.5, c = 1e4 1/m), the
//!   sled feels Popov's μ̄ = μ0 (1 − α Ψ_w(β)), β = c v/(μ0 α f) (Eq. 33), within 3 % on both
//!   sides of β_c, for the sine and the right sawtooth.

mod common;

use bevy::prelude::*;
use bevy::time::TimeUpdateStrategy;
use common::bevy_rapier::prelude::*;
use common::stickslip_bevy_rapier::{
    StickSlipContacts, StickSlipFriction, StickSlipRapier, StickSlipRapierPlugin,
    StickSlipVibration,
};
use common::stickslip_rapier::{FrictionMaterial, ReadBack};
use common::*;
use std::time::Duration;
use stickslip_core::contact::{Amplitude, VibrationDirection, VibrationMode, VibrationSource};
use stickslip_core::law::Law;
use stickslip_core::popov;
use stickslip_core::sliding_curve::{Curve, SlidingCurve, StribeckDecay};
use stickslip_core::waveform::Waveform;

/// Pressing force (N).
const F: f64 = 9.81;

/// A bevy_rapier app with stickslip (read-back on), one step of 1/`hz` s per update, gravity
/// off; a fixed plate (top at y = 0) with `plate` and a sled of `mass` kg on it pressed by F,
/// both with `material`. Returns the app and the sled.
fn sled_on_plate(
    hz: f64,
    mass: f64,
    material: FrictionMaterial,
    plate: impl Bundle,
) -> (App, Entity) {
    let dt = (1.0 / hz) as f32;
    let mut app = App::new();
    app.add_plugins((MinimalPlugins, TransformPlugin))
        .insert_resource(TimestepMode::Fixed { dt, substeps: 1 })
        .insert_resource(TimeUpdateStrategy::ManualDuration(Duration::from_secs_f32(
            dt,
        )))
        .add_plugins(RapierPhysicsPlugin::<NoUserData>::default())
        .add_plugins(StickSlipRapierPlugin::default());
    app.update();
    let mut q = app.world_mut().query::<&mut RapierConfiguration>();
    for mut c in q.iter_mut(app.world_mut()) {
        c.gravity = vect(0.0, 0.0, 0.0);
    }
    app.world_mut()
        .resource_mut::<StickSlipRapier>()
        .modifier_mut()
        .set_read_back(ReadBack::Contacts);
    app.world_mut().spawn((
        RigidBody::Fixed,
        cuboid(500.0, 0.1, 50.0),
        Transform::from_xyz(0.0, -0.1, 0.0),
        StickSlipFriction(Some(material.clone())),
        plate,
    ));
    let sled = app
        .world_mut()
        .spawn((
            RigidBody::Dynamic,
            cuboid(0.5, 0.1, 0.5),
            ColliderMassProperties::Mass(mass as f32),
            LockedAxes::ROTATION_LOCKED,
            Velocity::zero(),
            ExternalForce {
                force: vect(0.0, -F as f32, 0.0),
                ..default()
            },
            Sleeping::disabled(),
            Transform::from_xyz(0.0, 0.1, 0.0),
            StickSlipFriction(Some(material)),
        ))
        .id();
    (app, sled)
}

/// One step with the sled's velocity along x set to `v` before it; returns its velocity along
/// x after it and the read-back's (|friction force|, normal force) on it.
fn drag_step(app: &mut App, sled: Entity, v: f64) -> (f64, f64, f64) {
    app.world_mut()
        .get_mut::<Velocity>(sled)
        .expect("the sled")
        .linear
        .x = v as f32;
    app.update();
    let vx = app
        .world()
        .get::<Velocity>(sled)
        .expect("the sled")
        .linear
        .x as f64;
    let (mut f, mut n) = (0.0, 0.0);
    for c in app.world().resource::<StickSlipContacts>().of(sled) {
        f += Vec3::from(c.friction_force).length() as f64;
        n += c.normal_force;
    }
    (vx, f, n)
}

/// μ_ve(v) = 0.3 + 0.25 e^(−v/0.02) + 0.1 v: 0.55 at rest, 0.31 near 0.1 m/s, 0.40 at 1 m/s.
fn stribeck() -> Curve {
    Curve::stribeck(0.55, 0.3, 0.02, StribeckDecay::Exponential, 0.1).unwrap()
}

#[test]
fn a_dragged_sled_follows_the_stribeck_curve_over_three_decades() {
    const HZ: f64 = 60.0;
    const C: f64 = 1e4;
    const MU_BA: f64 = 0.5;
    let law = Law::elasto_plastic(C, MU_BA, stribeck().at_rest(), stribeck()).unwrap();
    let mut worst = 0.0f64;
    for v in [1e-3, 3e-3, 1e-2, 3e-2, 0.1, 0.3, 1.0] {
        let mass = stribeck().at_rest() * F / (HZ * 0.01 * v);
        let (mut app, sled) = sled_on_plate(HZ, mass, FrictionMaterial::new(law.clone()), ());
        // Once the contact has slid 25 elastic ranges (and at least 0.5 s), over 1 s.
        let settle = ((25.0 * MU_BA / C / v).max(0.5) * HZ).ceil() as usize;
        let (mut impulse, mut friction, mut normal) = (0.0, 0.0, 0.0);
        for k in 0..settle + HZ as usize {
            let (vx, f, n) = drag_step(&mut app, sled, v);
            if k >= settle {
                impulse += mass * (v - vx);
                friction += f;
                normal += n;
            }
        }
        let expected = stribeck().mu(v);
        let momentum = impulse / F;
        let reports = friction / normal;
        let (e_m, e_r) = (momentum / expected - 1.0, reports / expected - 1.0);
        worst = worst.max(e_m.abs()).max(e_r.abs());
        println!(
            "v {v:7.3} m/s: μ_ve {expected:.4}, momentum {momentum:.4} ({:+.2} %), read-back \
             {reports:.4} ({:+.2} %)",
            100.0 * e_m,
            100.0 * e_r
        );
        assert!(
            e_m.abs() < 0.02 && e_r.abs() < 0.02,
            "v {v}: momentum {momentum}, read-back {reports}, curve {expected}"
        );
    }
    println!("worst relative error {:.2} %", 100.0 * worst);
}

#[test]
fn sliding_friction_under_averaged_normal_vibration_is_eq_33() {
    const MU0: f64 = 0.5;
    const C: f64 = 1e4;
    const ALPHA: f64 = 0.5;
    const FREQUENCY: f64 = 5.0;
    const STEPS: usize = 40;
    let hz = FREQUENCY * STEPS as f64;
    let mass = 1000.0;
    let law = Law::elasto_plastic(C, MU0, MU0, Curve::constant(MU0).unwrap()).unwrap();
    let mut worst = 0.0f64;
    for w in [Waveform::Sine, Waveform::SawtoothRight] {
        let bc = w.beta_c();
        for beta in [0.25 * bc, 0.6 * bc, 0.9 * bc, 1.5 * bc] {
            let source = VibrationSource::new(
                VibrationDirection::Normal,
                Amplitude::Ratio(ALPHA),
                FREQUENCY,
                w.clone(),
                0.0,
                VibrationMode::Averaged,
            )
            .unwrap();
            let (mut app, sled) = sled_on_plate(
                hz,
                mass,
                FrictionMaterial::new(law.clone()),
                StickSlipVibration(source),
            );
            let v = beta * MU0 * ALPHA * FREQUENCY / C;
            // The contact spring reaches the cone after ~(1 − α)/(αβ) periods.
            let warm = ((1.0 - ALPHA) / (ALPHA * beta)).ceil() as usize + 3;
            let periods = 4;
            let (mut impulse, mut friction, mut normal) = (0.0, 0.0, 0.0);
            for k in 0..(warm + periods) * STEPS {
                let (vx, f, n) = drag_step(&mut app, sled, v);
                if k >= warm * STEPS {
                    impulse += mass * (v - vx);
                    friction += f;
                    normal += n;
                }
            }
            let theory = MU0 * (1.0 - ALPHA * popov::psi(&w, beta).unwrap());
            let time = periods as f64 / FREQUENCY;
            let momentum = impulse / (F * time);
            let reports = friction / normal;
            let (e_m, e_r) = (momentum / theory - 1.0, reports / theory - 1.0);
            worst = worst.max(e_m.abs()).max(e_r.abs());
            println!(
                "{w:?} β {beta:6.3}: Eq. 33 {theory:.4}, momentum {momentum:.4} ({:+.2} %), \
                 read-back {reports:.4} ({:+.2} %)",
                100.0 * e_m,
                100.0 * e_r
            );
            assert!(
                e_m.abs() < 0.03 && e_r.abs() < 0.03,
                "{w:?} β {beta}: {momentum} / {reports} vs {theory}"
            );
        }
    }
    println!("worst relative error {:.2} %", 100.0 * worst);
}
