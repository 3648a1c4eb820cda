//! The seed's Example 1 in a real rapier world: a box on the ground under F(t) through
//! sticking just below break-away, stick-slip then sliding, and slip-stick back to rest.
//! Invariants: with the elasto-plastic contact the box does not move in phase I (within
//! g_ba = μ_ba/c), it is at rest again at the end, and its final displacement is within 2 %
//! of the core's exact switched (Phys) ODE reference.
//! In 3D and in 2D (stickslip-fixtures2d).

use stickslip_core::law::{Law, Physical};
use stickslip_core::sliding_curve::Curve;
use stickslip_fixtures::example1;
use stickslip_theory::block::{Block, ForceProfile, Integrator, Tolerances, simulate};

const MU_BA: f64 = 0.3;
const MU_MAX: f64 = 0.32;
const C: f64 = 1e4;
const G: f64 = 9.81;

#[test]
fn example1_in_rapier_follows_the_exact_switched_reference() {
    let mass = 1.0;
    let profile = ForceProfile::example1(MU_BA * mass * G, 0.95, 1.5).unwrap();
    let curve = Curve::constant(MU_MAX).unwrap();
    let reference = simulate(
        &Block::new(
            mass,
            G,
            Law::Physical(Physical::new(MU_BA, curve.clone()).unwrap()),
        )
        .unwrap(),
        &profile,
        Integrator::Explicit,
        Tolerances::default(),
        &[1.0, 3.0],
    )
    .unwrap();

    let dt = 1.0 / 240.0;
    let law = Law::elasto_plastic(C, MU_BA, MU_MAX, curve).unwrap();
    // Phase I ends at 1 s: sample its end and, for the maximum, every step up to it.
    let phase1: Vec<f64> = (1..=240).map(|k| k as f64 * dt).collect();
    let mut times = phase1.clone();
    times.push(3.0);
    let (xs, v_end) = example1(law, &profile, dt, &times);
    let max_phase1 = xs[..phase1.len()]
        .iter()
        .fold(0.0f64, |m, x| m.max(x.abs()));
    let x_end = xs[phase1.len()];
    let x_ref = reference.final_displacement();
    println!(
        "phase I max |x| {max_phase1:.2e} m (g_ba {:.1e}); final x {x_end:.5} m vs Phys {x_ref:.5} m ({:+.2} %), v_end {v_end:.1e}",
        MU_BA / C,
        100.0 * (x_end - x_ref) / x_ref
    );
    assert!(max_phase1 <= MU_BA / C, "moved {max_phase1} in phase I");
    assert!(v_end.abs() < 1e-3, "still moving: {v_end}");
    assert!(((x_end - x_ref) / x_ref).abs() < 0.02, "{x_end} vs {x_ref}");
}
