//! A box on an incline in a rapier2d world. Invariants: with an elasto-plastic law whose
//! break-away coefficient μ_ba = 0.5 is above its sliding coefficient μ_k = 0.4, the box put
//! down at rest stays within the law's elastic range g_ba = μ_ba/c over 10 s at tan θ = 0.95 μ_ba
//! and at tan θ = 0.45 (between μ_k and μ_ba: plain rapier2d at μ_k slides there); above μ_ba
//! it slides with a = g (sin θ − μ_k cos θ) within 2 %, as the closed form of Coulomb sliding.

mod support;

use support::{BoxOnIncline, G, ep, run};

const MU_BA: f64 = 0.5;
const MU_K: f64 = 0.4;
const C: f64 = 1e4;

/// Displacement along the incline over 10 s after 1 s of settling.
fn creep(theta: f64, with_law: bool) -> f64 {
    let mut scene = BoxOnIncline::new(theta, MU_K as f32);
    let mut m = with_law.then(|| scene.attach(ep(MU_K)));
    run(&mut scene.world, m.as_mut(), 60);
    let x0 = scene.x();
    run(&mut scene.world, m.as_mut(), 600);
    scene.x() - x0
}

#[test]
fn holds_below_break_away_where_plain_rapier2d_slides() {
    let g_ba = MU_BA / C;
    for tan in [0.95 * MU_BA, 0.45] {
        let theta = f64::atan(tan);
        let held = creep(theta, true);
        assert!(
            held.abs() < g_ba,
            "tan θ = {tan}: moved {held:e} m, elastic range {g_ba:e} m"
        );
    }
    // Plain rapier2d at the sliding coefficient has no static friction above it.
    let plain = creep(f64::atan(0.45), false);
    assert!(
        plain > 0.1,
        "plain rapier2d at μ = {MU_K} moved only {plain} m"
    );
}

#[test]
fn slides_above_break_away_at_the_kinetic_closed_form() {
    for tan in [0.6, 0.8, 1.2] {
        let theta = f64::atan(tan);
        let mut scene = BoxOnIncline::new(theta, MU_K as f32);
        let mut m = scene.attach(ep(MU_K));
        run(&mut scene.world, Some(&mut m), 30);
        let v0 = scene.vx();
        let n = 120;
        run(&mut scene.world, Some(&mut m), n);
        let a = (scene.vx() - v0) / (n as f64 / 60.0);
        let expected = G * (theta.sin() - MU_K * theta.cos());
        assert!(
            (a - expected).abs() < 0.02 * expected,
            "tan θ = {tan}: a = {a}, closed form {expected}"
        );
    }
}
