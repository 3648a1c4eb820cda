//! Popov's friction under vibration (seed 2020) in rapier2d worlds, against the closed forms
//! of `stickslip_core::popov`. The contact uses the elasto-plastic law in the seed's sharp
//! limit (μ_ba = μ_max = μ0 = 0.5, flat sliding curve, c = 1e4 1/m), whose tangential stiffness
//! k_t = c F̄ is Popov's contact spring; the sled is pressed by F̄ = 9.81 N with gravity off.
//! Invariants, with the default `StickSlipConfig`:
//! - **sliding (Eq. 33)**: a massive sled dragged at v0 over a plate with a normal vibration
//!   source (α = 0.5, f = 5 Hz) feels μ̄ = ⟨F_x⟩/F̄ = μ0 (1 − α Ψ_w(β)), β = c v0/(μ0 α f),
//!   within 3 % on a β grid on both sides of β_c, for the sine, both sawtooth and the square
//!   wave, time-resolved (400 steps per period) and averaged (40 steps per period) — measured
//!   from the sled's momentum and from the contact reports;
//! - **static friction (Eq. 4 and 6)**: a 1 kg box pulled by a constant force under normal
//!   (ratio 0.4) or tangential (ratio 0.2, along the world x axis) vibration of the plate
//!   makes no progress 2 % below μ_s = μ0 (1 − A_z/F̄) resp. μ0 − A_x/F̄ and does 2 % above
//!   it, at 50, 200 and 1000 steps per period, in both modes, never moving against the pull.
//!
//! (2D has no transverse in-plane axis: a contact's tangent is a line.)

mod support;

use stickslip_rapier2d::core::waveform::Waveform;
use stickslip_rapier2d::rapier::prelude::*;
use stickslip_rapier2d::{Amplitude, ReadBack, VibrationDirection, VibrationMode, VibrationSource};
use stickslip_theory::popov;
use support::{Sled, ep_flat};

const MU0: f64 = 0.5;
const C: f64 = 1e4;
const ALPHA: f64 = 0.5;
/// Mean normal force (N), applied as a force.
const F_MEAN: f64 = 9.81;

fn normal_source(ratio: f64, f: f64, w: Waveform, mode: VibrationMode) -> VibrationSource {
    VibrationSource::new(
        VibrationDirection::Normal,
        Amplitude::Ratio(ratio),
        f,
        w,
        0.0,
        mode,
    )
    .unwrap()
}

/// Popov's drag: (μ̄ from the sled's momentum, μ̄ from the reports) at dimensionless speed
/// `beta` under normal vibration of waveform `w` in `mode`.
fn drag(w: &Waveform, beta: f64, mode: VibrationMode) -> (f64, f64) {
    let f = 5.0;
    let spp = match mode {
        VibrationMode::TimeResolved => 400,
        VibrationMode::Averaged => 40,
    };
    let dt = 1.0 / (f * spp as f64);
    let mut sled = Sled::new(0.1, 1000.0, dt, 0.0);
    let mut m = sled
        .attach(ep_flat(C, MU0, MU0))
        .with_read_back(ReadBack::Contacts);
    m.set_vibration(sled.plate, normal_source(ALPHA, f, w.clone(), mode));
    let v0 = beta * MU0 * ALPHA * f / C;
    // The contact spring reaches the cone after ~(1 − α)/(αβ) periods.
    let warm = ((1.0 - ALPHA) / (ALPHA * beta)).ceil() as usize + 3;
    let periods = 4;
    let mass = sled.mass();
    let press = Vector::new(0.0, -(F_MEAN as f32));
    let (mut impulse, mut fx, mut fz) = (0.0, 0.0, 0.0);
    for k in 0..(warm + periods) * spp {
        sled.drive(v0);
        sled.set_force(press);
        m.step(&mut sled.world);
        if k >= warm * spp {
            impulse += mass * (v0 - sled.vx());
            let r = m.reports().unwrap()[0];
            let sign = if r.collider2 == sled.sled { -1.0 } else { 1.0 };
            fx += sign * r.friction_force[0] as f64;
            // The law saw F̄ (1 + α w)⁺ time-resolved; the solver's normal force is F̄.
            let t_mid = (k as f64 + 0.5) * dt;
            fz += r.normal_force
                * match mode {
                    VibrationMode::TimeResolved => (1.0 + ALPHA * w.value(f * t_mid)).max(0.0),
                    VibrationMode::Averaged => 1.0,
                };
        }
    }
    let time = (periods * spp) as f64 * dt;
    (impulse / (F_MEAN * time), fx / fz)
}

fn beta_grid(w: &Waveform) -> Vec<f64> {
    let bc = w.beta_c();
    if bc.is_finite() {
        vec![0.25 * bc, 0.6 * bc, 0.9 * bc, 1.5 * bc]
    } else {
        vec![0.5, 2.0, 5.0, 12.0]
    }
}

fn check_sliding(mode: VibrationMode) {
    let mut worst: f64 = 0.0;
    for w in [
        Waveform::Sine,
        Waveform::SawtoothRight,
        Waveform::SawtoothLeft,
        Waveform::Square,
    ] {
        for beta in beta_grid(&w) {
            let theory = MU0 * (1.0 - ALPHA * popov::psi(&w, beta).unwrap());
            let (momentum, reports) = drag(&w, beta, mode);
            let (e_m, e_r) = (momentum / theory - 1.0, reports / theory - 1.0);
            worst = worst.max(e_m.abs()).max(e_r.abs());
            println!(
                "{mode:?} {w:?} β {beta:6.3}: Eq. 33 {theory:.4}, momentum {momentum:.4} \
                 ({:+.2} %), reports {reports:.4} ({:+.2} %)",
                100.0 * e_m,
                100.0 * e_r
            );
            assert!(
                e_m.abs() < 0.03 && e_r.abs() < 0.03,
                "{mode:?} {w:?} β {beta}: {momentum} / {reports} vs {theory}"
            );
        }
    }
    println!("{mode:?}: worst relative error {:.2} %", 100.0 * worst);
}

#[test]
fn sliding_friction_under_time_resolved_normal_vibration_is_eq_33() {
    check_sliding(VibrationMode::TimeResolved);
}

#[test]
fn sliding_friction_under_averaged_normal_vibration_is_eq_33() {
    check_sliding(VibrationMode::Averaged);
}

/// Progress (m) of a 1 kg box pulled by `pull` F̄ under a vibration `direction` of the plate
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
    let mut sled = Sled::new(0.1, 1.0, dt, 0.0);
    let mut m = sled.attach(ep_flat(C, MU0, MU0));
    let src = VibrationSource::new(
        direction,
        Amplitude::Ratio(ratio),
        f,
        Waveform::Sine,
        0.0,
        mode,
    )
    .unwrap();
    m.set_vibration(sled.plate, src);
    let press = Vector::new(0.0, -(F_MEAN as f32));
    for _ in 0..20 {
        sled.set_force(press);
        m.step(&mut sled.world);
    }
    let x0 = sled.x();
    let (mut x10, mut lowest) = (0.0, 0.0f64);
    for k in 0..30 * steps_per_period {
        sled.set_force(press + Vector::new((pull * F_MEAN) as f32, 0.0));
        m.step(&mut sled.world);
        let x = sled.x() - x0;
        lowest = lowest.min(x);
        if k + 1 == 10 * steps_per_period {
            x10 = x;
        }
    }
    (sled.x() - x0 - x10, lowest)
}

#[test]
fn static_friction_under_normal_and_tangential_vibration_is_eq_4_and_6() {
    let cases = [
        (
            "normal",
            VibrationDirection::Normal,
            0.4,
            popov::mu_s_normal(MU0, 0.4).unwrap(),
        ),
        (
            "tangential",
            VibrationDirection::Tangential {
                axis: [1.0, 0.0, 0.0],
            },
            0.2,
            popov::mu_s_tangential(MU0, 0.2).unwrap(),
        ),
    ];
    let g_ba = MU0 / C;
    for mode in [VibrationMode::TimeResolved, VibrationMode::Averaged] {
        for (name, dir, ratio, mu_s) in cases {
            for spp in [50, 200, 1000] {
                let (held, low_h) = pulled_progress(dir, ratio, mode, 0.98 * mu_s, spp);
                let (moved, low_m) = pulled_progress(dir, ratio, mode, 1.02 * mu_s, spp);
                println!(
                    "{name} {mode:?} {spp:4} steps/period, μ_s {mu_s:.3}: progress over 20 \
                     periods at 0.98 μ_s {held:.2e} m, at 1.02 μ_s {moved:.2e} m"
                );
                assert!(
                    held.abs() < 0.01 * g_ba,
                    "{name} {mode:?} {spp}: held box moved {held} m"
                );
                assert!(
                    moved > 0.1 * g_ba,
                    "{name} {mode:?} {spp}: box above μ_s moved only {moved} m"
                );
                assert!(
                    low_h > -1e-7 && low_m > -1e-7,
                    "{name} {mode:?} {spp}: moved against the pull ({low_h}, {low_m})"
                );
            }
        }
    }
}
