//! The vibrating conveyor, headless: parts on a trough of slope tan θ = 0.3 with
//! elasto-plastic friction μ0 = 0.5 (break-away and sliding), so tan θ lies between
//! μ0 (1 − α) = 0.2 and μ0. Invariants: without vibration the parts stand still (within the
//! law's elastic range g_ba = μ0/c); with Popov's normal vibration on the trough (α = 0.6)
//! they flow and settle at the conveying speed v* of the theory, where the mean sliding
//! friction μ0 (1 − α Ψ_w(β*)) equals tan θ, β* = c v*/(μ0 α f), within 5 %: averaged
//! (20 kHz) and time-resolved (1 kHz at 60 steps per period, speed averaged over whole
//! periods; the theory assumes a steady speed, so the part's speed ripple within a period,
//! ~μ0 α g/(2π f), must be small beside v*).

mod common;
use bevy::prelude::*;
use bevy::time::TimeUpdateStrategy;
use common::*;
use stickslip_bevy::prelude::*;
use stickslip_core::popov;

const MU0: f64 = 0.5;
const ALPHA: f64 = 0.6;
const SLOPE: f64 = 0.3;

/// Popov's conveying speed: Ψ_w(β*) = (1 − tan θ/μ0)/α, v* = β* μ0 α f / c.
fn theory_speed(c: f64, f: f64) -> f64 {
    let target = (1.0 - SLOPE / MU0) / ALPHA;
    let g = |beta: f64| popov::psi(&Waveform::Sine, beta).unwrap() - target;
    let mut conv = roots::SimpleConvergency {
        eps: 1e-12,
        max_iter: 200,
    };
    let beta = roots::find_root_brent(1e-6, 100.0, g, &mut conv).unwrap();
    beta * MU0 * ALPHA * f / c
}

struct Run {
    /// Physics rate (Hz).
    hz: f64,
    c: f64,
    /// Vibration (frequency, mode), or none.
    vibration: Option<(f64, VibrationMode)>,
    /// Steps to settle, then steps to measure over.
    settle: usize,
    measure: usize,
    /// Fixed steps per app update.
    per_update: u32,
}

/// Displacement over the measuring window and mean speed of three parts.
fn run(r: &Run) -> Vec<(f64, f64)> {
    let mut app = app();
    app.insert_resource(Time::<Fixed>::from_hz(r.hz))
        .insert_resource(TimeUpdateStrategy::FixedTimesteps(r.per_update))
        .insert_resource(incline(SLOPE));
    app.update(); // a step at the new rate before anything is spawned
    let trough = ground(&mut app, ep(r.c, MU0, MU0));
    if let Some((f, mode)) = r.vibration {
        let src = VibrationSource::new(
            VibrationDirection::Normal,
            Amplitude::Ratio(ALPHA),
            f,
            Waveform::Sine,
            0.0,
            mode,
        )
        .unwrap();
        app.world_mut().entity_mut(trough).insert(Vibration(src));
    }
    let parts: Vec<Entity> = (0..3).map(|i| part(&mut app, 0.5 * i as f32)).collect();
    steps(&mut app, r.settle / r.per_update as usize);
    let (t0, x0): (f64, Vec<f64>) = (
        sim_time(&app),
        parts.iter().map(|p| x_v(&app, *p).0).collect(),
    );
    steps(&mut app, r.measure / r.per_update as usize);
    let t = sim_time(&app) - t0;
    parts
        .iter()
        .zip(x0)
        .map(|(p, x0)| {
            let dx = x_v(&app, *p).0 - x0;
            (dx, dx / t)
        })
        .collect()
}

fn check(c: f64, f: f64, mode: VibrationMode, hz: f64, seconds: (f64, f64), per_update: u32) {
    let steps_of = |s: f64| (s * hz).round() as usize;
    let mut r = Run {
        hz,
        c,
        vibration: None,
        settle: steps_of(seconds.0),
        measure: steps_of(seconds.1),
        per_update,
    };
    for (dx, _) in run(&r) {
        assert!(dx.abs() <= MU0 / c, "moved {dx} m without vibration");
    }
    r.vibration = Some((f, mode));
    let expect = theory_speed(c, f);
    for (dx, v) in run(&r) {
        println!("{mode:?} {f} Hz: travelled {dx:.4} m at {v:.5} m/s, theory {expect:.5} m/s");
        assert!(
            ((v - expect) / expect).abs() < 0.05,
            "speed {v} vs theory {expect}"
        );
    }
}

#[test]
fn averaged_vibration_conveys_at_the_theorys_speed_and_none_holds() {
    // 20 kHz, c = 1e5: v* ≈ 5 cm/s; 0.5 s to settle, 4 s measured, 120 Hz physics.
    check(1e5, 20_000.0, VibrationMode::Averaged, 120.0, (0.5, 4.0), 1);
}

#[test]
fn time_resolved_vibration_conveys_at_the_theorys_speed_and_none_holds() {
    // 1 kHz at 60 kHz physics (60 steps per period, one period per update), c = 5e3:
    // v* ≈ 5.5 cm/s against a ripple of ~0.5 mm/s; 1 s to settle, 1 s (1000 periods)
    // measured. Measured: 4 % above v* for most parts, the same at 120 steps per period and
    // at 2 kHz with c = 1e4 (half the ripple): the time-resolved μ̄(β) of stickslip-rapier at
    // β ≈ 0.95, where a small error in μ̄ is a larger one in speed, not discretization.
    check(
        5e3,
        1000.0,
        VibrationMode::TimeResolved,
        60_000.0,
        (1.0, 1.0),
        60,
    );
}
