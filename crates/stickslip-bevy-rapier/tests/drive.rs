//! Elliptical vibration drives parts in a bevy_rapier app. Invariant: parts on a ground whose
//! `StickSlipVibration` is a superimposed source — a normal and a tangential (along x) sine
//! component a quarter period apart, averaged mode — with no applied tangential force move
//! along x at the compliant contact theory's free drive velocity
//! (`stickslip_core::popov::free_drive_velocity`, through `VibratingPlate`'s mapping of the
//! contact to the theory) within 3 %, and the other sense of the ellipse (−¼ period) drives
//! them the other way at the same speed; in Fixed mode and in Interpolated mode with two
//! substeps.

mod common;
use bevy::prelude::*;
use bevy_rapier3d::prelude::*;
use common::*;
use stickslip_bevy_rapier::StickSlipVibration;
use stickslip_fixtures::VibratingPlate;
use stickslip_rapier_035::{VibrationMode, VibrationSource};

const MU0: f64 = 0.5;
const C: f64 = 1e4;
const ALPHA: f64 = 0.6;
const TANGENTIAL: f64 = 0.75;
const FREQUENCY: f64 = 2000.0;
const DT: f64 = 1.0 / 120.0;

/// The source and the theory's drive velocity (m/s) for a phase shift (periods).
fn source(shift: f64) -> (VibrationSource, f64) {
    let mut plate =
        VibratingPlate::elliptical(ALPHA, TANGENTIAL, shift, VibrationMode::Averaged).unwrap();
    plate.mu0 = MU0;
    plate.c = C;
    plate.frequency = FREQUENCY;
    // Ratio amplitudes: the theory's speed does not depend on the load.
    plate.normal_force = 8.0 * 9.81;
    let v = plate.theory_drive_velocity().unwrap();
    let src = VibrationSource::superimposed(&plate.components, FREQUENCY, VibrationMode::Averaged)
        .unwrap();
    (src, v)
}

/// Mean speed along x of three parts over 2 s after 0.5 s of settling (simulated time).
fn measure(mode: TimestepMode, shift: f64) -> (Vec<f64>, f64) {
    let mut app = app(mode, DT);
    let law = ep(C, MU0, MU0);
    let ground = ground(&mut app, law.clone());
    let (src, theory) = source(shift);
    app.world_mut()
        .entity_mut(ground)
        .insert(StickSlipVibration(src));
    let parts: Vec<Entity> = (0..3)
        .map(|i| part(&mut app, 0.5 * i as f32, law.clone()))
        .collect();
    // 0.5 s and 2 s of frames of DT (Interpolated may lag a frame: a few more).
    steps(&mut app, 60);
    let t0 = sim_time(&app);
    let x0: Vec<f64> = parts.iter().map(|p| x_v(&app, *p).0).collect();
    steps(&mut app, 240);
    let t = sim_time(&app) - t0;
    let v = parts
        .iter()
        .zip(x0)
        .map(|(p, x0)| (x_v(&app, *p).0 - x0) / t)
        .collect();
    (v, theory)
}

#[test]
fn elliptical_vibration_drives_parts_at_the_theorys_speed_both_ways() {
    let modes = [
        TimestepMode::Fixed {
            dt: DT as f32,
            substeps: 1,
        },
        TimestepMode::Interpolated {
            dt: DT as f32,
            time_scale: 1.0,
            substeps: 2,
        },
    ];
    for mode in modes {
        let (forward, theory) = measure(mode, 0.25);
        let (backward, theory_back) = measure(mode, -0.25);
        println!(
            "{mode:?}: +¼: {forward:?} m/s, theory {theory}; −¼: {backward:?} m/s, theory {theory_back}"
        );
        assert!(theory.abs() > 0.01, "the theory drives: {theory}");
        assert!(theory * theory_back < 0.0, "{theory} vs {theory_back}");
        for (vs, th) in [(forward, theory), (backward, theory_back)] {
            for v in vs {
                assert!(
                    ((v - th) / th).abs() < 0.03,
                    "{mode:?}: {v} m/s vs theory {th} m/s"
                );
            }
        }
    }
}
