//! Popov's friction under vibration, measured in real rapier worlds. A box lies on a fixed
//! plate, pressed by a normal force F̄, and is dragged at constant velocity v0 (a massive sled:
//! its horizontal velocity is imposed every step and the friction impulse of one step cannot
//! stop it, so the solver applies the contact's full friction); its contact uses the elasto-plastic law in the seed's sharp limit (μ_ba = μ_max,
//! flat sliding curve), whose tangential stiffness k_t = c·F̄ is Popov's contact spring.
//! Invariant: the measured effective coefficient μ̄ = ⟨F_x⟩/⟨F_z⟩ over a β grid on both sides
//! of β_c reproduces the core theory μ0 (1 − α Ψ_w(β)), β = c v0/(μ0 α f), within 3 % for
//! the sine, right and left sawtooth and square waves — with the normal force modulated once
//! as a real oscillating load on the box and once by a time-resolved vibration source on the
//! plate — and in averaged mode (f ≫ 1/dt). And a box pulled by a constant force under normal,
//! tangential and transverse oscillation makes no progress 2 % below the static coefficient of
//! Eq. 4, 6 and 8 and does 2 % above it, at 50, 200 and 1000 steps per period, never moving
//! against the pull. All with the default `StickSlipConfig`, in 3D and in 2D
//! (stickslip-fixtures2d; a 2D contact's tangent is a line, so it has no transverse axis).

use stickslip_core::law::Law;
use stickslip_core::sliding_curve::Curve;
use stickslip_core::waveform::Waveform;
use stickslip_fixtures::{BoxOnGround, PopovDrag, PopovDrive, v3};
use stickslip_rapier::rapier::prelude::*;
use stickslip_rapier::{
    Amplitude, FrictionMaterial, StickSlip, VibrationDirection, VibrationMode, VibrationSource,
};
use stickslip_theory::popov;

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

fn scene(dt: f32, mass: f32) -> Scene {
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
    let mut modifier = StickSlip::new(FrictionMaterial::new(law));
    modifier.attach(&mut world.colliders, box_scene.ground, None);
    modifier.attach(&mut world.colliders, box_scene.box_collider, None);
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

/// Progress (m) of a box pulled by a constant `pull` (over F̄) under `direction` vibration
/// over the last 20 of 30 periods, and the smallest displacement seen over the run (m).
fn pulled_progress(
    direction: VibrationDirection,
    ratio: f64,
    mode: VibrationMode,
    pull: f64,
    steps_per_period: usize,
) -> (f64, f64) {
    let f = 10.0;
    let dt = 1.0 / (f * steps_per_period as f64);
    let mut s = scene(dt as f32, BOX_MASS);
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
    let press = v3(0.0, -(F_MEAN as f32), 0.0);
    for _ in 0..20 {
        let b = &mut s.world.bodies[s.body];
        b.reset_forces(true);
        b.add_force(press, true);
        s.modifier.step(&mut s.world);
    }
    let x0 = s.world.bodies[s.body].translation().x as f64;
    let (mut x10, mut lowest) = (0.0, 0.0f64);
    for k in 0..30 * steps_per_period {
        let b = &mut s.world.bodies[s.body];
        b.reset_forces(true);
        b.add_force(v3((pull * F_MEAN) as f32, 0.0, 0.0) + press, true);
        s.modifier.step(&mut s.world);
        let x = s.world.bodies[s.body].translation().x as f64 - x0;
        lowest = lowest.min(x);
        if k + 1 == 10 * steps_per_period {
            x10 = x;
        }
    }
    let x = s.world.bodies[s.body].translation().x as f64 - x0;
    (x - x10, lowest)
}

#[test]
fn static_friction_under_oscillation_matches_eq_4_6_8() {
    let axis = [1.0f32, 0.0, 0.0];
    #[allow(unused_mut)] // 2D has no transverse case
    let mut cases = vec![
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
    ];
    #[cfg(not(dim2))]
    cases.push((
        "transverse",
        VibrationDirection::Transverse {
            axis: [0.0, 0.0, 1.0],
        },
        0.3,
        popov::mu_s_transverse(MU0, 0.3).unwrap(),
    ));
    // The static coefficient is the pull at which the box starts to make progress: 2 % below
    // Eq. 4/6/8 it must not (only the contact's elastic range, never against the pull), 2 %
    // above it must, at 50, 200 and 1000 steps per vibration period.
    for mode in [VibrationMode::TimeResolved, VibrationMode::Averaged] {
        for &(name, dir, ratio, expect) in &cases {
            for spp in [50, 200, 1000] {
                let (held, low_h) = pulled_progress(dir, ratio, mode, 0.98 * expect, spp);
                let (moved, low_m) = pulled_progress(dir, ratio, mode, 1.02 * expect, spp);
                println!(
                    "static {name} {mode:?} {spp} steps/period: progress over 20 periods at \
                     0.98 μ_s {held:.2e} m, at 1.02 μ_s {moved:.2e} m"
                );
                let g_ba = MU0 / C;
                assert!(
                    held.abs() < 0.01 * g_ba,
                    "{name} {mode:?} {spp}: held box moved {held}"
                );
                assert!(
                    moved > 0.1 * g_ba,
                    "{name} {mode:?} {spp}: box above μ_s moved {moved}"
                );
                assert!(
                    low_h > -1e-7 && low_m > -1e-7,
                    "{name} {mode:?} {spp}: moved against the pull ({low_h}, {low_m})"
                );
            }
        }
    }
}
