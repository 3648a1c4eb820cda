//! A box on an elasto-plastic ground in a headless bevy app (gravity tilted to make an
//! incline of slope tan θ). Invariants: below break-away (tan θ = 0.9 μ_ba) the box does not
//! creep beyond the law's elastic range g_ba = μ_ba/c over 10 s, nor move further than g_ba
//! from where it was once rapier formed the contact (its first two steps, in which plain
//! rapier's own friction lets a box put down on a slope slip some 10 µm); above it (tan θ = 1.2 μ_k,
//! with μ_k = μ_ba, and tan θ = 1.2 μ_ba with μ_k < μ_ba) it slides with the kinetic
//! acceleration g (sin θ − μ_k cos θ) within 2 %. The box carries the ground's material.

mod common;
use common::*;
use stickslip_bevy::FrictionLaw;

const C: f64 = 1e5;
const MU_BA: f64 = 0.5;

#[test]
fn sticks_below_break_away_without_creep() {
    let mut app = app();
    app.insert_resource(incline(0.9 * MU_BA));
    ground(&mut app, ep(C, MU_BA, 0.4));
    let b = part(&mut app, 0.0);
    // The box carries the ground's material: the pair is that material's alone.
    app.world_mut()
        .entity_mut(b)
        .insert(FrictionLaw::new(ep(C, MU_BA, 0.4)));
    steps(&mut app, 2);
    let (formed, _) = x_v(&app, b);
    steps(&mut app, 58);
    let (x0, _) = x_v(&app, b);
    steps(&mut app, 1200);
    let (x1, v1) = x_v(&app, b);
    let g_ba = MU_BA / C;
    println!(
        "creep over 10 s: {:.3e} m (g_ba {g_ba:.1e} m), total from spawn {x1:.3e} m \
         ({formed:.3e} m while the contact formed), v {v1:.1e}",
        x1 - x0
    );
    assert!((sim_time(&app) - 10.5).abs() < 1e-6);
    assert!((x1 - x0).abs() <= g_ba, "crept {} m", x1 - x0);
    assert!(
        (x1 - formed).abs() <= g_ba,
        "moved {} m since the contact formed",
        x1 - formed
    );
}

fn kinetic_acceleration(mu_k: f64, tan: f64) {
    let mut app = app();
    app.insert_resource(incline(tan));
    ground(&mut app, ep(C, MU_BA, mu_k));
    let b = part(&mut app, 0.0);
    // The box carries the ground's material (unattached, its rapier friction 0.5 would
    // combine with the material like rapier's coefficients).
    app.world_mut()
        .entity_mut(b)
        .insert(FrictionLaw::new(ep(C, MU_BA, mu_k)));
    steps(&mut app, 60);
    let (_, v1) = x_v(&app, b);
    steps(&mut app, 120);
    let (_, v2) = x_v(&app, b);
    let a = (v2 - v1) / (120.0 / HZ);
    let theta = tan.atan();
    let expect = 9.81 * (theta.sin() - mu_k * theta.cos());
    println!("mu_k {mu_k}, tan {tan}: acceleration {a:.4} m/s², expected {expect:.4}");
    assert!(((a - expect) / expect).abs() < 0.02, "{a} vs {expect}");
}

#[test]
fn slides_above_break_away_with_the_kinetic_acceleration() {
    kinetic_acceleration(MU_BA, 1.2 * MU_BA);
    kinetic_acceleration(0.4, 1.2 * MU_BA);
}
