//! The vibrating conveyor of the `avian_conveyor` example, headless: a part (rotation locked)
//! at rest on a slope under an elasto-plastic material (μ0 = 0.8 for break-away and sliding,
//! flat sliding curve, c = 2e4 1/m), whose floor carries Popov's averaged normal vibration
//! (α = 0.6, 20 kHz, sine) — a tilted trough under vertical gravity, as in the example, and a
//! level floor under tilted gravity (a contact at exact rest along the world's axes).
//! Invariants, in both: the vibration lowers the static coefficient to μ0 (1 − α) = 0.32
//! (Popov 2020, Eq. 4): the part holds at tan θ = 0.98 × 0.32 and breaks away at 1.02 × 0.32;
//! for slopes between 0.32 and μ0, at 60 and 240 Hz and at avian's default 6 substeps and 2
//! and 12, without vibration the part holds (less than 1 mm in 2 s), with it the part flows
//! and settles at the conveying speed v* of the theory, where the mean sliding friction
//! μ0 (1 − α Ψ_w(β*)) equals tan θ, β* = c v*/(μ0 α f) (Eq. 33), within 2 %.

mod common;

use bevy::prelude::*;
use common::avian::prelude::*;
use common::stickslip_avian::{FrictionMaterial, StickSlipFriction, StickSlipVibration};
use common::*;
use stickslip_core::contact::{Amplitude, VibrationDirection, VibrationMode, VibrationSource};
use stickslip_core::law::Law;
use stickslip_core::popov;
use stickslip_core::sliding_curve::Curve;
use stickslip_core::waveform::Waveform;

const MU0: f64 = 0.8;
const C: f64 = 2e4;
const ALPHA: f64 = 0.6;
const F: f64 = 20_000.0;

/// Popov's conveying speed on slope `tan`: Ψ_w(β*) = (1 − tan θ/μ0)/α, v* = β* μ0 α f / c.
fn theory_speed(tan: f64) -> f64 {
    let target = (1.0 - tan / MU0) / ALPHA;
    let beta = popov::beta_at_psi(&Waveform::Sine, target).unwrap();
    beta * MU0 * ALPHA * F / C
}

/// How the slope is made.
#[derive(Debug, Clone, Copy)]
enum Slope {
    /// A tilted trough, gravity along −y (the example).
    TiltedTrough,
    /// A level floor, gravity tilted.
    TiltedGravity,
}

/// The part's travel down the slope over 2 s after 2 s of settling (m), and its mean speed
/// over them (m/s).
fn convey(slope: Slope, hz: f64, substeps: u32, tan: f64, vibration: bool) -> (f64, f64) {
    travel(slope, hz, substeps, tan, Some(vibration))
}

/// As [`convey`], with avian's own `Friction::new(μ0 (1 − α))` on floor and part instead of
/// the material and its vibration (`material` `None`): how firmly avian itself holds at that
/// coefficient.
fn avians_hold(slope: Slope, tan: f64) -> f64 {
    travel(slope, 60.0, 6, tan, None).0
}

fn travel(slope: Slope, hz: f64, substeps: u32, tan: f64, material: Option<bool>) -> (f64, f64) {
    let (gravity, tilt) = match slope {
        Slope::TiltedTrough => (
            Gravity(Vec3::new(0.0, -G as f32, 0.0)),
            Quat::from_rotation_z(-(tan.atan() as f32)),
        ),
        Slope::TiltedGravity => (tilted_gravity(tan.atan()), Quat::IDENTITY),
    };
    let mut app = app_at(true, hz, substeps, gravity);
    let down = tilt * Vec3::X;
    let law = Law::elasto_plastic(C, MU0, MU0, Curve::constant(MU0).unwrap()).unwrap();
    let vibration = material == Some(true);
    let avian = Friction::new((MU0 * (1.0 - ALPHA)) as f32);
    let floor = app
        .world_mut()
        .spawn((
            RigidBody::Static,
            Collider::cuboid(400.0, 0.2, 20.0),
            Transform::from_translation(tilt * Vec3::new(0.0, -0.1, 0.0)).with_rotation(tilt),
            avian,
        ))
        .id();
    if vibration {
        let source = VibrationSource::new(
            VibrationDirection::Normal,
            Amplitude::Ratio(ALPHA),
            F,
            Waveform::Sine,
            0.0,
            VibrationMode::Averaged,
        )
        .unwrap();
        app.world_mut()
            .entity_mut(floor)
            .insert(StickSlipVibration(source));
    }
    let part = app
        .world_mut()
        .spawn((
            RigidBody::Dynamic,
            Collider::cuboid(0.08, 0.08, 0.08),
            Transform::from_translation(tilt * Vec3::new(0.0, 0.04, 0.0)).with_rotation(tilt),
            LockedAxes::ROTATION_LOCKED,
            avian,
        ))
        .id();
    if material.is_some() {
        let material = StickSlipFriction(Some(FrictionMaterial::new(law)));
        app.world_mut().entity_mut(floor).insert(material.clone());
        app.world_mut().entity_mut(part).insert(material);
    }
    let ticks = |s: f64| (s * hz).round() as usize;
    run(&mut app, ticks(2.0));
    let x0 = position(&app, part).dot(down) as f64;
    run(&mut app, ticks(2.0));
    let dx = position(&app, part).dot(down) as f64 - x0;
    assert!(velocity(&app, part).is_finite());
    (dx, dx / 2.0)
}

#[test]
fn vibration_lowers_the_static_coefficient_to_mu0_one_minus_alpha() {
    let mu_s = MU0 * (1.0 - ALPHA);
    for slope in [Slope::TiltedTrough, Slope::TiltedGravity] {
        let (held, _) = convey(slope, 60.0, 6, 0.98 * mu_s, true);
        let avian = avians_hold(slope, 0.98 * mu_s);
        let (moved, _) = convey(slope, 60.0, 6, 1.02 * mu_s, true);
        println!(
            "{slope:?}: at 0.98 μ0 (1 − α) {:.1} µm (avian's own hold at μ0 (1 − α): {:.1} µm), \
             at 1.02 μ0 (1 − α) {:.1} mm in 2 s",
            1e6 * held,
            1e6 * avian,
            1e3 * moved
        );
        // avian's friction is soft: its own hold creeps near the limit; stickslip's no more.
        assert!(
            held.abs() <= 1.1 * avian.abs() + 1e-5 && held.abs() < 1e-3,
            "{slope:?}: crept {held} m below break-away, avian's own hold {avian} m"
        );
        assert!(
            moved > 1e-3,
            "{slope:?}: moved only {moved} m above break-away"
        );
    }
}

#[test]
fn popov_vibration_conveys_at_the_theorys_speed_and_without_it_the_part_holds() {
    let mut worst: f64 = 0.0;
    for (slope, hz, substeps, tan) in [Slope::TiltedTrough, Slope::TiltedGravity]
        .into_iter()
        .flat_map(|s| [(60.0, 6), (240.0, 6), (60.0, 2), (60.0, 12)].map(|(h, n)| (s, h, n)))
        .flat_map(|(s, h, n)| [0.4, 0.5, 0.65].map(|t| (s, h, n, t)))
    {
        {
            let (held, _) = convey(slope, hz, substeps, tan, false);
            let (dx, v) = convey(slope, hz, substeps, tan, true);
            let expect = theory_speed(tan);
            let error = v / expect - 1.0;
            worst = worst.max(error.abs());
            println!(
                "{slope:?}, {hz} Hz, {substeps} substeps, tan θ {tan}: without vibration {:.1} µm; \
                 with it {dx:.4} m at {v:.4} m/s, Popov {expect:.4} m/s ({:+.2} %)",
                1e6 * held,
                100.0 * error
            );
            assert!(
                held.abs() < 1e-3,
                "{hz} Hz, {substeps} substeps, tan θ {tan}: crept {held} m without vibration"
            );
            assert!(
                error.abs() < 0.02,
                "{hz} Hz, {substeps} substeps, tan θ {tan}: {v} m/s vs Popov's {expect}"
            );
        }
    }
    println!("worst relative error {:.2} %", 100.0 * worst);
}
