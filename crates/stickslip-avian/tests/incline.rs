//! On a slope, avian's own `Friction::new(μ_k).with_static_coefficient(μ_s)` becomes real
//! static friction with the plugin, and so does an elasto-plastic stickslip material.
//! Invariants, at avian's default 6 solver substeps and at 12: below break-away (tan θ
//! between μ_k and μ_s) a box put down on the slope holds, moving less than 5 µm in 3 s
//! (avian's own hold with a coefficient of μ_s creeps 0.7 mm at tan θ 0.45 and 5.5 mm at 0.55,
//! 6 substeps), where plain avian with the same `Friction` (which reads only
//! the dynamic coefficient) slides it off; above break-away it slides at the closed form
//! a = g (sin θ − μ_k cos θ) within 2 %.

mod common;

use common::avian::prelude::*;
use common::stickslip_avian::{FrictionMaterial, StickSlipFriction};
use common::*;
use stickslip_core::law::Law;
use stickslip_core::sliding_curve::Curve;

const MU_K: f32 = 0.4;
const MU_S: f32 = 0.6;
/// What a hold may creep in 3 s (m): rapier's stickslip hold creeps 2.5 µm in 10 s; the EP
/// material's elastic range μ_ba/c is 6 µm.
const HOLD: f64 = 5e-6;

/// The box's slide along x over 3 s after 0.5 s of settling, and its acceleration over the
/// last 2 s: with avian's `Friction` (μ_k, μ_s) unless `ep`, or with plain avian's at μ_s
/// when `hold` (the baseline of a hold in avian).
fn slide(stickslip: bool, substeps: u32, tan: f64, ep: bool) -> (f64, f64) {
    slide_with(stickslip, substeps, tan, ep, false)
}

fn avians_hold(substeps: u32, tan: f64) -> f64 {
    slide_with(false, substeps, tan, false, true).0
}

fn slide_with(stickslip: bool, substeps: u32, tan: f64, ep: bool, hold: bool) -> (f64, f64) {
    let mut app = app(stickslip, substeps, tan.atan());
    let friction = if hold {
        Friction::new(MU_S)
    } else {
        Friction::new(MU_K).with_static_coefficient(MU_S)
    };
    if ep {
        let law = Law::elasto_plastic(
            1e5,
            MU_S as f64,
            MU_S as f64,
            Curve::constant(MU_K as f64).unwrap(),
        )
        .unwrap();
        let m = StickSlipFriction(Some(FrictionMaterial::new(law)));
        floor(&mut app, m.clone());
        let b = block(&mut app, 0.0, m);
        return measure(&mut app, b);
    }
    floor(&mut app, friction);
    let b = block(&mut app, 0.0, friction);
    measure(&mut app, b)
}

fn measure(app: &mut bevy::prelude::App, b: bevy::prelude::Entity) -> (f64, f64) {
    run(app, 30);
    let x0 = position(app, b).x as f64;
    run(app, 60);
    let v1 = velocity(app, b).x as f64;
    run(app, 120);
    let v3 = velocity(app, b).x as f64;
    let x3 = position(app, b).x as f64;
    (x3 - x0, (v3 - v1) / 2.0)
}

fn closed_form(tan: f64) -> f64 {
    let theta = tan.atan();
    G * (theta.sin() - MU_K as f64 * theta.cos())
}

#[test]
fn avians_static_coefficient_holds_and_breaks_away() {
    for substeps in [6, 12] {
        for tan in [0.45, 0.55] {
            let (held, _) = slide(true, substeps, tan, false);
            let baseline = avians_hold(substeps, tan);
            assert!(
                held.abs() < HOLD,
                "{substeps} substeps, tan θ {tan}: crept {held} m (avian's own hold {baseline} m)"
            );
            let (plain, _) = slide(false, substeps, tan, false);
            assert!(
                plain > 0.1,
                "plain avian at tan θ {tan} should slide at μ_k: {plain} m"
            );
        }
        for tan in [0.65, 0.9] {
            let (moved, a) = slide(true, substeps, tan, false);
            let expected = closed_form(tan);
            assert!(moved > 0.1, "{substeps} substeps, tan θ {tan}: held");
            assert!(
                (a / expected - 1.0).abs() < 0.02,
                "{substeps} substeps, tan θ {tan}: a {a} vs {expected}"
            );
        }
    }
}

#[test]
fn an_elasto_plastic_material_holds_and_breaks_away() {
    for substeps in [6, 12] {
        for tan in [0.45, 0.55] {
            let (held, _) = slide(true, substeps, tan, true);
            let baseline = avians_hold(substeps, tan);
            assert!(
                held.abs() < HOLD,
                "{substeps} substeps, tan θ {tan}: crept {held} m (avian's own hold {baseline} m)"
            );
        }
        for tan in [0.65, 0.9] {
            let (moved, a) = slide(true, substeps, tan, true);
            let expected = closed_form(tan);
            assert!(moved > 0.1, "{substeps} substeps, tan θ {tan}: held");
            assert!(
                (a / expected - 1.0).abs() < 0.02,
                "{substeps} substeps, tan θ {tan}: a {a} vs {expected}"
            );
        }
    }
}
