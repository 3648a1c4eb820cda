//! The default elasto-plastic law follows any sliding curve (seed Eq. 1) while keeping the
//! seed's sticking, break-away and slip-stick. Invariants: in steady sliding the law's
//! coefficient equals μ_ve(v) within 0.5 % for falling curves (tails below μ_ba included), flat
//! curves (below μ_ba and at μ_max) and rising ones, for slip speeds 1e-4…10 m/s, c 1e3…1e6 1/m
//! and steps 1e-4…1/60 s; a block with a Stribeck curve under the seed's Example 1 force
//! (stick at 0.95 F_ba, break away, slide, slip-stick) ends within 2 % of the exact switched
//! model (Phys), where the literal law of Eq. 4–7 cannot; and a mass–spring on a belt with
//! static 0.5 / kinetic 0.3 stick-slips with the analytic period
//! T = 2Δ/v_b + (π + 2 atan(v_b/(ωΔ)))/ω within 2 %.

use stickslip::core::law::{
    ElastoPlastic, EpVariant, FrictionLaw, FrictionState, Law, Physical, StepInput,
};
use stickslip::core::sliding_curve::{Curve, SlidingCurve, StribeckDecay};
use stickslip::core::vec2::norm;
use stickslip_theory::block::{BeltSpring, Block, ForceProfile, Integrator, Tolerances, simulate};

/// The issue's curve: μ_ve = 0.3 + 0.25 e^(−|v|/0.05), with μ_ba = 0.5 and μ_max = μ_ve(0+).
fn issue_curve() -> Curve {
    Curve::stribeck(0.55, 0.3, 0.05, StribeckDecay::Exponential, 0.0).unwrap()
}

/// (name, μ_ba, μ_max, curve) for every kind of curve.
fn curves() -> Vec<(&'static str, f64, f64, Curve)> {
    vec![
        ("falling (issue)", 0.5, 0.55, issue_curve()),
        (
            "falling, Gaussian to 0.1",
            0.4,
            0.45,
            Curve::stribeck(0.45, 0.1, 0.01, StribeckDecay::Gaussian, 0.0).unwrap(),
        ),
        ("flat below mu_ba", 0.5, 0.5, Curve::constant(0.3).unwrap()),
        ("flat at mu_max", 0.3, 0.32, Curve::constant(0.32).unwrap()),
        (
            "rising",
            0.3,
            0.35,
            Curve::stribeck(0.35, 0.6, 0.1, StribeckDecay::Exponential, 0.05).unwrap(),
        ),
    ]
}

#[test]
fn steady_sliding_equals_the_sliding_curve() {
    let speeds: Vec<f64> = (0..=10)
        .map(|i| 10f64.powf(-4.0 + 0.5 * i as f64))
        .collect();
    let mut worst = 0.0f64;
    for (name, mu_ba, mu_max, curve) in curves() {
        for c in [1e3, 1e4, 1e5, 1e6] {
            let law = ElastoPlastic::new(c, mu_ba, mu_max, curve.clone()).unwrap();
            for dt in [1e-4, 1e-3, 1.0 / 60.0] {
                for &v in &speeds {
                    let m = curve.mu(v);
                    // Enough slip to break away and settle: many decay lengths μ/c.
                    let needed = 40.0 * mu_max.max(m) / c;
                    let steps = ((needed / (v * dt)).ceil() as usize).max(20);
                    let mut s = FrictionState::default();
                    let mut mu = 0.0;
                    for _ in 0..steps {
                        mu = norm(law.step(&mut s, &StepInput::new([v * dt, 0.0], dt, 7.0)).mu);
                    }
                    let err = (mu - m).abs() / m;
                    worst = worst.max(err);
                    assert!(
                        err < 0.005,
                        "{name}, c {c}, dt {dt}, v {v}: settled at {mu}, curve {m}"
                    );
                    assert_eq!(law.sliding_coefficient(v), m);
                }
            }
        }
    }
    println!("largest relative error of the settled coefficient: {worst:.2e}");
}

#[test]
fn the_literal_law_settles_inside_the_band_as_documented() {
    // Seed Eq. 4–7 as printed: steady sliding where α(μ)·μ = μ_ve, never below μ_ba.
    let law = ElastoPlastic::new(1e4, 0.5, 0.55, issue_curve())
        .unwrap()
        .with_variant(EpVariant::Literal)
        .unwrap();
    for v in [0.1, 0.5] {
        let dt = 1e-3;
        let mut s = FrictionState::default();
        let mut mu = 0.0;
        for _ in 0..2000 {
            mu = law.step(&mut s, &StepInput::new([v * dt, 0.0], dt, 1.0)).mu[0];
        }
        let expect = law.steady_sliding_coefficient(v);
        assert!((mu - expect).abs() < 1e-6 * expect, "{mu} vs {expect}");
        assert!(mu >= 0.5 && issue_curve().mu(v) < 0.34);
    }
}

const M: f64 = 1.0;
const G: f64 = 9.81;

fn block_run(law: Law, integrator: Integrator) -> stickslip_theory::block::BlockRun {
    // Example 1's shape: 0.95 F_ba held in phase I, a push to 1.3 F_ba (above the curve's
    // μ_ve(0+) = 0.55, where the switched model releases) in phase II, the force removed at
    // 1.6 s so that the block slides back to rest well before 3 s (phase III).
    let f_ba = 0.5 * M * G;
    let profile = ForceProfile::new(
        vec![0.0, 0.5, 1.0, 1.2, 1.5, 1.6, 3.0],
        vec![
            0.0,
            0.95 * f_ba,
            0.95 * f_ba,
            1.3 * f_ba,
            1.3 * f_ba,
            0.0,
            0.0,
        ],
    )
    .unwrap();
    let block = Block::new(M, G, law).unwrap();
    simulate(
        &block,
        &profile,
        integrator,
        Tolerances::default(),
        &[1.0, 2.0, 3.0],
    )
    .unwrap()
}

#[test]
fn stribeck_block_follows_the_switched_model() {
    let c = 1e4;
    let phys = block_run(
        Law::Physical(Physical::new(0.5, issue_curve()).unwrap()),
        Integrator::Explicit,
    );
    let xp = phys.final_displacement();
    assert!(xp > 0.1, "the block should slide, Phys moved {xp}");
    for integrator in [Integrator::Explicit, Integrator::Implicit] {
        let ep = block_run(
            Law::elasto_plastic(c, 0.5, 0.55, issue_curve()).unwrap(),
            integrator,
        );
        // Phase I: sticking at 0.95 F_ba, within the elastic displacement.
        let g_ba = 0.5 / c;
        assert!(ep.max_displacement_between(0.0, 1.0) <= g_ba);
        let xe = ep.final_displacement();
        println!("{integrator:?}: EP {xe:.5} m, Phys {xp:.5} m");
        assert!(
            ((xe - xp) / xp).abs() < 0.02,
            "{integrator:?}: EP {xe} vs Phys {xp}"
        );
        // Back to rest at the end (slip-stick): over the last 0.3 s the block only moves
        // within the elastic range of the contact (|μ| ≤ μ_max, so ±μ_max/c).
        let tail: Vec<f64> =
            ep.t.iter()
                .zip(&ep.x)
                .filter(|(t, _)| **t >= 2.7)
                .map(|(_, x)| *x)
                .collect();
        let spread = tail.iter().cloned().fold(f64::MIN, f64::max)
            - tail.iter().cloned().fold(f64::MAX, f64::min);
        assert!(
            spread <= 2.0 * 0.55 / c,
            "still moving at the end: {spread} m"
        );
    }
    // The literal law slides with μ ≥ μ_ba and falls far short.
    let literal = ElastoPlastic::new(c, 0.5, 0.55, issue_curve())
        .unwrap()
        .with_variant(EpVariant::Literal)
        .unwrap();
    let xl = block_run(Law::ElastoPlastic(literal), Integrator::Explicit).final_displacement();
    assert!(xl < 0.5 * xp, "literal {xl} vs Phys {xp}");
}

/// Times where the block's velocity turns negative (once per stick-slip cycle).
fn down_crossings(t: &[f64], v: &[f64]) -> Vec<f64> {
    let mut out = Vec::new();
    for i in 1..v.len() {
        if v[i - 1] >= 0.0 && v[i] < 0.0 {
            let w = v[i - 1] / (v[i - 1] - v[i]);
            out.push(t[i - 1] + w * (t[i] - t[i - 1]));
        }
    }
    out
}

#[test]
fn belt_stick_slip_period_with_static_above_kinetic() {
    for (c, v_b) in [(1e4, 0.1), (1e5, 0.1), (1e4, 0.05), (3e4, 0.2)] {
        let belt = BeltSpring {
            mass: 1.0,
            gravity: G,
            stiffness: 100.0,
            belt_velocity: v_b,
        };
        let law = ElastoPlastic::new(c, 0.5, 0.5, Curve::constant(0.3).unwrap()).unwrap();
        let run = belt
            .simulate(&law, 8.0, Integrator::Explicit, Tolerances::default())
            .unwrap();
        let crossings = down_crossings(&run.t, &run.v);
        let periods: Vec<f64> = crossings.windows(2).skip(1).map(|w| w[1] - w[0]).collect();
        assert!(periods.len() >= 4, "too few cycles: {crossings:?}");
        let measured = periods.iter().sum::<f64>() / periods.len() as f64;
        let expect = belt.period(0.5, 0.3);
        println!("c {c}, v_b {v_b}: period {measured:.5} s, analytic {expect:.5} s");
        assert!(
            ((measured - expect) / expect).abs() < 0.02,
            "c {c}, v_b {v_b}: {measured} vs {expect}"
        );
    }
}
