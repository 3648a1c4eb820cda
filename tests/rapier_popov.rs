//! Popov's friction under vibration, measured in real rapier worlds. A box lies on a fixed
//! plate, pressed by a normal force F̄, and is dragged at constant velocity v0 (a massive sled:
//! its horizontal velocity is imposed every step and the friction impulse of one step cannot
//! stop it, so the solver applies the contact's full friction); its contact uses the elasto-plastic law in the seed's sharp limit (μ_ba = μ_max,
//! flat sliding curve), whose tangential stiffness k_t = c·F̄ is Popov's contact spring.
//! Invariant: the measured effective coefficient μ̄ = ⟨F_x⟩/⟨F_z⟩ over a β grid on both sides
//! of β_c reproduces the core theory μ0 (1 − α Ψ_w(β)), β = c v0/(μ0 α f), within 3 % for
//! the sine, right and left sawtooth and square waves — with the normal force modulated once
//! as a real oscillating load on the box and once by a time-resolved vibration source on the
//! plate — and in averaged mode (f ≫ 1/dt). And the static coefficient of a box pulled by a
//! slowly growing force matches Eq. 4, 6 and 8 under normal, tangential and transverse
//! oscillation within 3 %.

use rapier3d::prelude::*;
use stickslip::core::law::Law;
use stickslip::core::popov;
use stickslip::core::sliding_curve::Curve;
use stickslip::core::waveform::Waveform;
use stickslip::rapier::scenes::{BoxOnGround, PopovDrag, PopovDrive};
use stickslip::rapier::{
    Amplitude, FrictionMaterial, StickSlip, StickSlipConfig, VibrationDirection, VibrationMode,
    VibrationSource,
};

const MU0: f64 = 0.5;
const C: f64 = 1e4;
const ALPHA: f64 = 0.5;
/// The statically pulled box's mass: light, so it moves as soon as it can.
const BOX_MASS: f32 = 1.0;
/// The mean normal force (N), applied as a force (gravity is off).
const F_MEAN: f64 = 9.81;

struct Scene {
    world: PhysicsWorld,
    modifier: StickSlip,
    body: RigidBodyHandle,
    plate: ColliderHandle,
}

fn scene(dt: f32, mass: f32, stick_speed: f64) -> Scene {
    let box_scene = BoxOnGround {
        half: 0.1,
        mass,
        gravity: 0.0,
        dt,
        rotations: false,
        ..BoxOnGround::default()
    }
    .build();
    let mut world = box_scene.world;
    let law = Law::elasto_plastic(C, MU0, MU0, Curve::constant(MU0).unwrap()).unwrap();
    let config = StickSlipConfig {
        stick_speed,
        ..StickSlipConfig::default()
    };
    let mut modifier = StickSlip::new(FrictionMaterial::new(law))
        .with_config(config)
        .unwrap();
    modifier.attach(&mut world.colliders, box_scene.ground, None);
    Scene {
        world,
        modifier,
        body: box_scene.body,
        plate: box_scene.ground,
    }
}

fn beta_grid(w: &Waveform) -> Vec<f64> {
    let bc = w.beta_c();
    if bc.is_finite() {
        vec![0.25 * bc, 0.6 * bc, 0.9 * bc, 1.5 * bc]
    } else {
        vec![0.5, 2.0, 5.0, 12.0]
    }
}

fn check_drive(drive: PopovDrive) {
    let mut worst: f64 = 0.0;
    for w in [
        Waveform::Sine,
        Waveform::SawtoothRight,
        Waveform::SawtoothLeft,
        Waveform::Square,
    ] {
        for beta in beta_grid(&w) {
            let setup = PopovDrag::new(w.clone(), drive);
            assert_eq!((setup.mu0, setup.c, setup.alpha), (MU0, C, ALPHA));
            let theory = setup.theory(beta);
            let got = setup.measure(beta).unwrap();
            let err = (got - theory) / theory;
            worst = worst.max(err.abs());
            println!(
                "{drive:?} {w:?} beta {beta:6.3}: rapier {got:.4} theory {theory:.4} ({:+.2} %)",
                100.0 * err
            );
            assert!(
                err.abs() < 0.03,
                "{drive:?} {w:?} beta {beta}: {got} vs {theory}"
            );
        }
    }
    println!("{drive:?}: worst relative error {:.2} %", 100.0 * worst);
}

#[test]
fn sliding_friction_under_a_real_oscillating_load() {
    check_drive(PopovDrive::RealLoad);
}

#[test]
fn sliding_friction_under_a_time_resolved_vibration_source() {
    check_drive(PopovDrive::Source(VibrationMode::TimeResolved));
}

#[test]
fn sliding_friction_under_an_averaged_vibration_source() {
    check_drive(PopovDrive::Source(VibrationMode::Averaged));
}

/// The pull force (over F̄) at which the box starts to slide under `direction` vibration.
fn measured_static(
    direction: VibrationDirection,
    ratio: f64,
    mode: VibrationMode,
    expect: f64,
) -> f64 {
    let f = 10.0;
    let steps_per_period = 100;
    let dt = 1.0 / (f * steps_per_period as f64);
    let mut s = scene(dt as f32, BOX_MASS, StickSlipConfig::default().stick_speed);
    let src = VibrationSource::new(
        direction,
        Amplitude::Ratio(ratio),
        f,
        Waveform::Sine,
        0.0,
        mode,
    )
    .unwrap();
    s.modifier.set_vibration(s.plate, src);
    let f_mean = F_MEAN;
    // Ramp the pull from 0.9 to 1.1 of the expected value over 100 periods (0.2 % a period).
    let (lo, hi) = (0.9 * expect * f_mean, 1.1 * expect * f_mean);
    let periods = 100;
    let total = periods * steps_per_period;
    let press = Vector::new(0.0, -(f_mean as f32), 0.0);
    for _ in 0..20 {
        let b = &mut s.world.bodies[s.body];
        b.reset_forces(true);
        b.add_force(press, true);
        s.modifier.step(&mut s.world);
    }
    let x0 = s.world.bodies[s.body].translation().x;
    for k in 0..total {
        let pull = lo + (hi - lo) * k as f64 / total as f64;
        let b = &mut s.world.bodies[s.body];
        b.reset_forces(true);
        b.add_force(Vector::new(pull as f32, 0.0, 0.0) + press, true);
        s.modifier.step(&mut s.world);
        if s.world.bodies[s.body].translation().x - x0 > 1e-4 {
            return pull / f_mean;
        }
    }
    f64::NAN
}

#[test]
fn static_friction_under_oscillation_matches_eq_4_6_8() {
    let axis = [1.0f32, 0.0, 0.0];
    let across = [0.0f32, 0.0, 1.0];
    let cases = [
        (
            "normal",
            VibrationDirection::Normal,
            0.4,
            popov::mu_s_normal(MU0, 0.4).unwrap(),
        ),
        (
            "tangential",
            VibrationDirection::Tangential { axis },
            0.2,
            popov::mu_s_tangential(MU0, 0.2).unwrap(),
        ),
        (
            "transverse",
            VibrationDirection::Transverse { axis: across },
            0.3,
            popov::mu_s_transverse(MU0, 0.3).unwrap(),
        ),
    ];
    for mode in [VibrationMode::TimeResolved, VibrationMode::Averaged] {
        for (name, dir, ratio, expect) in cases {
            let got = measured_static(dir, ratio, mode, expect);
            let err = (got - expect) / expect;
            println!(
                "static {name} {mode:?}: rapier {got:.4} Eq. {expect:.4} ({:+.2} %)",
                100.0 * err
            );
            assert!(err.abs() < 0.03, "{name} {mode:?}: {got} vs {expect}");
        }
    }
}
