//! Popov's sliding friction under normal vibration (seed 2020, Eq. 33) in an avian world. The
//! contact uses the elasto-plastic law in the seed's sharp limit (μ_ba = μ_max = μ0 = 0.5,
//! flat sliding curve, c = 1e4 1/m), whose tangential stiffness k_t = c F̄ is Popov's contact
//! spring; the sled is pressed by F̄ = 9.81 N with gravity off and rotations locked.
//! Invariant: a massive sled dragged at v0 over a plate with an averaged normal vibration
//! source (α = 0.5, f = 5 Hz, 40 physics ticks per period, avian's 6 substeps) feels
//! μ̄ = ⟨F_x⟩/F̄ = μ0 (1 − α Ψ_w(β)), β = c v0/(μ0 α f), within 3 % on a β grid on both sides
//! of β_c, for the sine, both sawtooth and the square wave — measured from the sled's
//! momentum and from the read-back.

mod common;

use bevy::prelude::*;
use common::stickslip_avian::{
    FrictionMaterial, StickSlipContacts, StickSlipFriction, StickSlipVibration,
};
use common::*;
use stickslip_core::contact::{Amplitude, VibrationDirection, VibrationMode, VibrationSource};
use stickslip_core::law::Law;
use stickslip_core::popov;
use stickslip_core::sliding_curve::Curve;
use stickslip_core::waveform::Waveform;

const MU0: f64 = 0.5;
const C: f64 = 1e4;
const ALPHA: f64 = 0.5;
/// Mean normal force (N), applied as a force.
const F_MEAN: f64 = 9.81;
const FREQUENCY: f64 = 5.0;
const TICKS_PER_PERIOD: usize = 40;

/// (μ̄ from the sled's momentum, μ̄ from the read-back) at dimensionless speed `beta` under
/// averaged normal vibration of waveform `w`.
fn drag(w: &Waveform, beta: f64) -> (f64, f64) {
    let hz = FREQUENCY * TICKS_PER_PERIOD as f64;
    let dt = 1.0 / hz;
    let mut app = app_at(true, hz, 6, gravity(Vec3::ZERO));
    let law = Law::elasto_plastic(C, MU0, MU0, Curve::constant(MU0).unwrap()).unwrap();
    let material = StickSlipFriction(Some(FrictionMaterial::new(law)));
    let source = VibrationSource::new(
        VibrationDirection::Normal,
        Amplitude::Ratio(ALPHA),
        FREQUENCY,
        w.clone(),
        0.0,
        VibrationMode::Averaged,
    )
    .unwrap();
    floor(&mut app, (material.clone(), StickSlipVibration(source)));
    let mass = 1000.0;
    let sled = sled(&mut app, mass, F_MEAN, material);
    let v0 = beta * MU0 * ALPHA * FREQUENCY / C;
    // The contact spring reaches the cone after ~(1 − α)/(αβ) periods.
    let warm = ((1.0 - ALPHA) / (ALPHA * beta)).ceil() as usize + 3;
    let periods = 4;
    let (mut impulse, mut fx, mut fz) = (0.0, 0.0, 0.0);
    for k in 0..(warm + periods) * TICKS_PER_PERIOD {
        drag_tick(&mut app, sled, v0);
        if k >= warm * TICKS_PER_PERIOD {
            let vx = velocity(&app, sled).x as f64;
            impulse += mass * (v0 - vx);
            for c in app.world().resource::<StickSlipContacts>().of(sled) {
                fx += c.friction_force[0].abs() as f64;
                fz += c.normal_force;
            }
        }
    }
    let time = (periods * TICKS_PER_PERIOD) as f64 * dt;
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

#[test]
fn sliding_friction_under_averaged_normal_vibration_is_eq_33() {
    let mut worst: f64 = 0.0;
    for w in [
        Waveform::Sine,
        Waveform::SawtoothRight,
        Waveform::SawtoothLeft,
        Waveform::Square,
    ] {
        for beta in beta_grid(&w) {
            let theory = MU0 * (1.0 - ALPHA * popov::psi(&w, beta).unwrap());
            let (momentum, reports) = drag(&w, beta);
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
