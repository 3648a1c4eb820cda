//! Incline comparison: a 125 kg box on a slope in rapier, with plain rapier friction and with
//! each stickslip law. Prints how far the box creeps in 10 s below the break-away angle
//! (tan θ = r·μ_ba for r < 1) and, above it, the sliding acceleration against
//! a = g (sin θ − μ_k cos θ).
//!
//! Run: `cargo run --release --example incline_comparison`

use stickslip_core::law::{Coulomb, FrictionLaw, Law, Physical, Regularization, Regularized};
use stickslip_core::sliding_curve::Curve;
use stickslip_fixtures::BoxOnGround;
use stickslip_rapier::{FrictionMaterial, StickSlip};

const MU_BA: f64 = 0.5;
const MU_MAX: f64 = 0.55;
const C: f64 = 1e4;
const STEPS: usize = 600;

/// Displacement along the slope over `STEPS` steps after 1 s of settling; `None` = plain rapier
/// with coefficient μ_ba on the colliders.
fn run(law: Option<&Law>, tan_theta: f64) -> f64 {
    let mut scene = BoxOnGround {
        incline: tan_theta.atan(),
        ..BoxOnGround::default()
    }
    .build();
    let mut modifier = law.map(|l| {
        let mut m = StickSlip::new(FrictionMaterial::new(l.clone()));
        m.attach(&mut scene.world.colliders, scene.ground, None);
        m.attach(&mut scene.world.colliders, scene.box_collider, None);
        m
    });
    if modifier.is_none() {
        for (_, c) in scene.world.colliders.iter_mut() {
            c.set_friction(MU_BA as f32);
        }
    }
    let mut x0 = 0.0;
    for k in 0..(60 + STEPS) {
        if k == 60 {
            x0 = scene.x();
        }
        match modifier.as_mut() {
            Some(m) => m.step(&mut scene.world),
            None => scene.world.step(),
        }
    }
    scene.x() - x0
}

fn main() {
    let flat = Curve::constant(MU_MAX).expect("valid curve");
    let laws: Vec<(&str, Option<Law>)> = vec![
        ("rapier Coulomb (no hook)", None),
        (
            "stickslip Coulomb",
            Some(Law::Coulomb(Coulomb::new(MU_BA).expect("valid"))),
        ),
        (
            "EP (c = 1e4 1/m)",
            Some(Law::elasto_plastic(C, MU_BA, MU_MAX, flat.clone()).expect("valid")),
        ),
        (
            "Phys",
            Some(Law::Physical(
                Physical::new(MU_BA, flat.clone()).expect("valid"),
            )),
        ),
        (
            "Regul (0.01 m/s)",
            Some(Law::Regularized(
                Regularized::new(flat.clone(), 0.01, Regularization::Linear).expect("valid"),
            )),
        ),
        (
            "Regul (0.001 m/s)",
            Some(Law::Regularized(
                Regularized::new(flat.clone(), 0.001, Regularization::Linear).expect("valid"),
            )),
        ),
    ];
    println!("creep over 10 s (m); g_ba = mu_ba/c = {:.1e} m", MU_BA / C);
    println!(
        "{:<26} {:>12} {:>12} {:>12}",
        "law", "0.50 mu_ba", "0.90 mu_ba", "0.95 mu_ba"
    );
    for (name, law) in &laws {
        let row: Vec<String> = [0.5, 0.9, 0.95]
            .iter()
            .map(|r| format!("{:>12.3e}", run(law.as_ref(), r * MU_BA)))
            .collect();
        println!("{name:<26} {}", row.join(" "));
    }
    let tan_theta = 0.7;
    let theta = f64::atan(tan_theta);
    println!("\nsliding at tan θ = {tan_theta}: measured vs g (sin θ − μ_k cos θ)");
    for (name, law) in laws.iter().skip(1) {
        let law = law.as_ref().expect("a stickslip law");
        let mu_k = law.sliding_coefficient(1.0);
        let expect = 9.81 * (theta.sin() - mu_k * theta.cos());
        // Sliding from the start: over [t0, t0 + t] the box covers a (t0 t + t²/2).
        let (t0, t) = (1.0, STEPS as f64 / 60.0);
        let a = run(Some(law), tan_theta) / (t0 * t + 0.5 * t * t);
        println!(
            "{name:<26} a = {a:7.4} m/s²  expected {expect:7.4}  ({:+.2} %)",
            100.0 * (a - expect) / expect
        );
    }
}
