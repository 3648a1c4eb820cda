//! The vibrating conveyor, headless: parts on an incline of slope 0.3 over an elasto-plastic
//! trough (μ_ba = 0.5). Invariants: without vibration the parts stand still (within the law's
//! elastic range); with Popov's normal vibration on the trough (α = 0.6, 20 kHz, averaged) the
//! static coefficient drops to μ_ba (1 − α) = 0.2 < 0.3, they flow, and they settle at the
//! conveying speed where the averaged sliding friction μ_k (1 − α Ψ_w(β)) equals the slope,
//! β = c v/(μ_k α f), within 5 %.

mod common;
use bevy::prelude::*;
use common::*;
use stickslip_bevy::prelude::*;
use stickslip_core::popov;
use stickslip_core::waveform::Waveform;

const C: f64 = 1e5;
const MU_BA: f64 = 0.5;
const MU_K: f64 = 0.52;
const ALPHA: f64 = 0.6;
const F: f64 = 20_000.0;
const SLOPE: f64 = 0.3;

/// The conveying speed of Popov's theory: μ_k (1 − α Ψ(β)) = slope.
fn theory_speed() -> f64 {
    let target = (1.0 - SLOPE / MU_K) / ALPHA;
    let g = |beta: f64| popov::psi(&Waveform::Sine, beta).unwrap() - target;
    let mut conv = roots::SimpleConvergency {
        eps: 1e-12,
        max_iter: 200,
    };
    let beta = roots::find_root_brent(1e-6, 100.0, g, &mut conv).unwrap();
    beta * MU_K * ALPHA * F / C
}

fn run(vibrate: bool) -> Vec<(f64, f64)> {
    let mut app = app();
    app.insert_resource(incline(SLOPE));
    let trough = ground(&mut app, ep(C, MU_BA, MU_K));
    if vibrate {
        let src = VibrationSource::new(
            VibrationDirection::Normal,
            Amplitude::Ratio(ALPHA),
            F,
            Waveform::Sine,
            0.0,
            VibrationMode::Averaged,
        )
        .unwrap();
        app.world_mut().entity_mut(trough).insert(Vibration(src));
    }
    let parts: Vec<Entity> = (0..3).map(|i| part(&mut app, 0.5 * i as f32)).collect();
    steps(&mut app, 30);
    let start: Vec<f64> = parts.iter().map(|p| x_v(&app, *p).0).collect();
    steps(&mut app, 480);
    parts
        .iter()
        .zip(start)
        .map(|(p, x0)| {
            let (x, v) = x_v(&app, *p);
            (x - x0, v)
        })
        .collect()
}

#[test]
fn parts_stand_still_without_vibration_and_flow_at_the_theorys_speed_with_it() {
    let g_ba = MU_BA / C;
    for (dx, v) in run(false) {
        assert!(
            dx.abs() <= g_ba && v.abs() < 1e-3,
            "moved {dx} m without vibration (v {v})"
        );
    }
    let expect = theory_speed();
    for (dx, v) in run(true) {
        println!("with vibration: travelled {dx:.3} m, speed {v:.4} m/s, theory {expect:.4} m/s");
        assert!(dx > 0.1, "the parts should flow, moved {dx}");
        assert!(
            ((v - expect) / expect).abs() < 0.05,
            "speed {v} vs theory {expect}"
        );
    }
}
