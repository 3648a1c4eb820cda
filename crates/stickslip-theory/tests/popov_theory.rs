//! Invariants of Popov's (2020) vibration-friction theory, checked across independent
//! implementations: the event-based numeric Ψ_w(β) (Eq. 25, 31) agrees with the closed forms
//! Eq. 34–36, with the paper's sine fits Eq. 37/38 to their measured accuracy (Eq. 37 being the
//! better one, as the paper states), with the lower-envelope form of the spring force
//! f(φ) = inf_{s≥0} [w(φ − s) + βs], and, through Eq. 33, with the time-stepped spring
//! simulator; Ψ is 1 at β = 0, 0 for β ≥ β_c, decreasing and convex for every waveform; μ̄
//! depends on (α, β) only, not on the mean indentation; the numeric solver of Eq. 9 reduces to
//! Eq. 4, 6 and 8 for a single oscillation direction and never yields μ_s > μ0.

#[path = "../../../tests/support/deterministic.rs"]
mod support;

use proptest::prelude::*;
use std::f64::consts::TAU;
use stickslip_core::waveform::{Waveform, WaveformKind};
use stickslip_theory::popov::{
    Excitation, Oscillation, SimulationOptions, SpringModel, StaticFriction, mu_eff, mu_s_normal,
    mu_s_tangential, mu_s_transverse, psi, psi_closed_form, psi_sine_eq37, psi_sine_eq38,
    static_friction_superimposed, stick_events,
};

/// A smooth custom waveform with two bumps per period (two stick events at moderate β).
fn two_bump() -> Waveform {
    Waveform::from_fn(|x| (2.0 * TAU * x).sin() + 0.4 * (TAU * x + 0.3).sin()).unwrap()
}

/// A table waveform with kinks: slow rise, fast drop, plateau.
fn table() -> Waveform {
    Waveform::from_table(&[0.0, 1.0, 2.0, 3.0, 4.0, 1.0, 1.5, 1.5]).unwrap()
}

fn all_waveforms() -> Vec<Waveform> {
    let mut w: Vec<Waveform> = WaveformKind::ALL.into_iter().map(Waveform::from).collect();
    w.push(Waveform::impulse(0.2).unwrap());
    w.push(table());
    w.push(two_bump());
    w
}

fn grid(lo: f64, hi: f64, n: usize) -> impl Iterator<Item = f64> {
    (0..=n).map(move |i| lo + (hi - lo) * i as f64 / n as f64)
}

/// Ψ from the lower envelope f(φ) = inf_{s≥0}[w(φ − s) + βs], on a grid of `n` points per
/// period via f_i = min(w_i, f_{i−1} + β h), averaged over the second of two periods.
fn psi_envelope(w: &Waveform, beta: f64, n: usize) -> f64 {
    let h = 1.0 / n as f64;
    let mut f = w.value(0.0);
    let mut sum = 0.0;
    for i in 1..=2 * n {
        let wi = w.value(i as f64 * h);
        f = wi.min(f + beta * h);
        if i > n {
            sum += wi - f;
        }
    }
    sum / n as f64
}

/// μ̄ of the spring simulator for normal oscillation at given (α, β) and mean indentation.
fn simulated_mu(w: &Waveform, alpha: f64, beta: f64, mean_indentation: f64) -> f64 {
    let (k_x, k_z, mu0, f) = (3.0, 2.0, 0.4, 50.0);
    let a_z = alpha * mean_indentation;
    let v0 = beta * mu0 * k_z * a_z * f / k_x;
    let osc = Oscillation::new(a_z, w.clone(), 0.0).unwrap();
    let model = SpringModel::new(
        k_x,
        k_z,
        mu0,
        mean_indentation,
        v0,
        f,
        Excitation::normal(osc),
    )
    .unwrap();
    assert!((model.beta().unwrap() - beta).abs() < 1e-12 * beta.max(1.0));
    let out = model.simulate(&SimulationOptions::default());
    assert!(out.periodic, "{out:?}");
    out.mu_eff / mu0
}

#[test]
fn numeric_psi_matches_closed_forms_eq_34_to_36() {
    let cases: Vec<(Waveform, Vec<f64>)> = vec![
        // Right sawtooth up to and past β_c = 2.
        (Waveform::SawtoothRight, grid(0.02, 2.4, 119).collect()),
        (Waveform::SawtoothLeft, grid(0.05, 40.0, 200).collect()),
        // Square on both sides of the kink at β = 4, and at it.
        (
            Waveform::Square,
            grid(0.05, 12.0, 239)
                .chain([3.9, 3.99, 3.999, 4.0, 4.001, 4.01, 4.1])
                .collect(),
        ),
        // The derived impulse-train form (kink at 1/δ² = 25); width ½ must give Eq. 36.
        (
            Waveform::impulse(0.2).unwrap(),
            grid(0.1, 60.0, 200).collect(),
        ),
        (
            Waveform::impulse(0.5).unwrap(),
            grid(0.05, 12.0, 100).collect(),
        ),
    ];
    for (w, betas) in cases {
        let mut worst: f64 = 0.0;
        for beta in betas {
            let exact = psi_closed_form(&w, beta).unwrap();
            let num = psi(&w, beta).unwrap();
            // Required: 0.5 % relative, or 1e-3 absolute where Ψ → 0.
            let tol = (5e-3 * exact).max(1e-3);
            assert!(
                (num - exact).abs() <= tol,
                "{w:?} β={beta}: {num} vs {exact}"
            );
            worst = worst.max((num - exact).abs());
        }
        eprintln!("closed form {w:?}: max |Ψ_num − Ψ_exact| = {worst:.2e}");
        // Piecewise-linear waveforms are integrated exactly: anything above round-off is a bug.
        assert!(worst < 1e-10, "{w:?}: {worst}");
    }
}

#[test]
fn sine_fits_eq_37_and_38_have_their_stated_accuracy() {
    let (mut e37, mut e38): (f64, f64) = (0.0, 0.0);
    for beta in grid(0.0, TAU, 400) {
        let num = psi(&Waveform::Sine, beta).unwrap();
        e37 = e37.max((num - psi_sine_eq37(beta)).abs());
        e38 = e38.max((num - psi_sine_eq38(beta)).abs());
    }
    eprintln!("sine: max |Ψ − Eq.37| = {e37:.4}, max |Ψ − Eq.38| = {e38:.4}");
    // The paper gives no numbers, only that both are empirical fits and that "the first
    // approximation is slightly more accurate". Measured: 0.0144 (Eq. 37) and 0.0194 (Eq. 38)
    // of the unit range; we require 1.5 % and 2 %.
    assert!(e37 <= e38, "Eq. 37 should be the more accurate fit");
    assert!(e37 < 0.015 && e38 < 0.02, "{e37} {e38}");
}

#[test]
fn numeric_psi_matches_the_time_stepped_spring_model() {
    let alpha = 0.8;
    for (w, betas) in [
        (Waveform::Sine, vec![0.1, 0.5, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0]),
        (Waveform::Square, vec![0.5, 2.0, 4.0, 8.0]),
        (Waveform::SawtoothLeft, vec![0.5, 2.0, 8.0]),
        (two_bump(), vec![0.5, 2.0, 5.0]),
    ] {
        let mut worst: f64 = 0.0;
        for beta in betas {
            let theory = mu_eff(1.0, alpha, psi(&w, beta).unwrap()).unwrap();
            let sim = simulated_mu(&w, alpha, beta, 1.0);
            let rel = (sim - theory).abs() / theory;
            assert!(
                rel < 5e-3,
                "{w:?} β={beta}: simulated {sim} vs Eq. 33 {theory}"
            );
            worst = worst.max(rel);
        }
        eprintln!("spring model vs Eq. 33, {w:?}: max relative μ̄ error = {worst:.2e}");
        // Required 0.5 %; smooth waveforms carry no O(step) jump error, so they must do far
        // better (measured ~5e-8 for the sine at 8192 steps per period).
        if w.breakpoints().iter().all(|b| b.jump() == 0.0) {
            assert!(worst < 1e-5, "{w:?}: {worst}");
        }
    }
}

#[test]
fn psi_agrees_with_the_lower_envelope_of_the_spring_force() {
    for w in all_waveforms() {
        let top = if w.beta_c().is_finite() {
            w.beta_c()
        } else {
            20.0
        };
        let mut worst: f64 = 0.0;
        for beta in grid(0.05 * top, 0.95 * top, 6) {
            let env = psi_envelope(&w, beta, 20_000);
            worst = worst.max((psi(&w, beta).unwrap() - env).abs());
        }
        eprintln!("envelope {w:?}: max |Ψ − Ψ_env| = {worst:.2e}");
        assert!(worst < 1e-3, "{w:?}: {worst}");
    }
}

#[test]
fn psi_has_unit_range_and_is_decreasing_and_convex() {
    for w in all_waveforms() {
        let bc = w.beta_c();
        let top = if bc.is_finite() { 1.2 * bc } else { 30.0 };
        assert_eq!(psi(&w, 0.0), Ok(1.0));
        let near0 = psi(&w, 1e-6).unwrap();
        assert!((near0 - 1.0).abs() < 1e-3, "{w:?}: Ψ(0+) = {near0}");
        if bc.is_finite() {
            assert_eq!(psi(&w, bc), Ok(0.0));
            assert_eq!(psi(&w, 1.5 * bc), Ok(0.0));
        } else {
            assert!(psi(&w, 1e4).unwrap() > 0.0, "β_c = ∞ keeps some reduction");
        }
        let h = top / 300.0;
        let values: Vec<f64> = grid(0.0, top, 300).map(|b| psi(&w, b).unwrap()).collect();
        for (i, v) in values.iter().enumerate() {
            assert!((0.0..=1.0).contains(v), "{w:?}: Ψ({}) = {v}", i as f64 * h);
        }
        for pair in values.windows(2) {
            assert!(pair[1] <= pair[0] + 1e-12, "{w:?} not decreasing: {pair:?}");
        }
        for (i, t) in values.windows(3).enumerate() {
            let second = t[0] - 2.0 * t[1] + t[2];
            assert!(
                second >= -1e-9,
                "{w:?} not convex near β = {}: {second}",
                (i + 1) as f64 * h
            );
        }
    }
}

#[test]
fn several_stick_events_per_period_are_summed() {
    let w = two_bump();
    let beta = 2.0;
    let events = stick_events(&w, beta).unwrap();
    assert!(events.len() >= 2, "{events:?}");
    let total: f64 = events.iter().map(|e| e.psi).sum();
    assert_eq!(psi(&w, beta), Ok(total));
    assert!((total - psi_envelope(&w, beta, 20_000)).abs() < 1e-3);
    for e in &events {
        // Eq. 25 at every release, Eq. 19 at every smooth onset.
        let eq25 = beta * (e.release - e.onset) - (w.value(e.release) - w.value(e.onset));
        assert!(eq25.abs() < 1e-9, "{e:?}: {eq25}");
        assert!((w.slope(e.onset) - beta).abs() < 1e-6, "{e:?}");
    }
}

#[test]
fn mu_eff_depends_on_alpha_and_beta_only() {
    // Eq. 32/33: ΔF_x scales with A_z and μ̄ with α = A_z/ū_z; rescaling ū_z at fixed (α, β)
    // (A_z = α ū_z, v0 chosen to keep β) must leave μ̄ unchanged.
    for w in [Waveform::Sine, Waveform::Square, two_bump()] {
        for (alpha, beta) in [(0.3, 1.0), (0.9, 3.0)] {
            let reference = simulated_mu(&w, alpha, beta, 1.0);
            for u in [1e-4, 0.02, 7.0, 300.0] {
                let mu = simulated_mu(&w, alpha, beta, u);
                assert!(
                    (mu - reference).abs() <= 5e-3 * reference,
                    "{w:?} α={alpha} β={beta} ū_z={u}: {mu} vs {reference}"
                );
            }
        }
    }
}

#[test]
fn static_solver_reduces_to_eq_4_6_8() {
    let mu0 = 0.6;
    type ClosedForm = fn(f64, f64) -> Result<f64, stickslip_core::ParamError>;
    let directions: [(&str, ClosedForm); 3] = [
        ("normal", mu_s_normal),
        ("tangential", mu_s_tangential),
        ("transverse", mu_s_transverse),
    ];
    // Waveforms spanning [−1, 1], as Eq. 4–8 assume; off-grid phases exercise the refinement.
    for w in [Waveform::Sine, Waveform::Square, Waveform::SawtoothLeft] {
        for (name, closed) in directions {
            for a in grid(0.0, 1.5, 30) {
                let osc = Oscillation::new(a, w.clone(), 0.1234).unwrap();
                let ex = match name {
                    "normal" => Excitation::normal(osc),
                    "tangential" => Excitation::tangential(osc),
                    _ => Excitation::transverse(osc),
                };
                let numeric = static_friction_superimposed(mu0, &ex).unwrap().mu_s();
                let exact = closed(mu0, a).unwrap();
                assert!(
                    (numeric - exact).abs() < 1e-6,
                    "{name} {w:?} A/F_z={a}: {numeric} vs {exact}"
                );
            }
        }
    }
}

fn any_waveform() -> impl Strategy<Value = Waveform> {
    prop_oneof![
        Just(Waveform::Sine),
        Just(Waveform::SawtoothRight),
        Just(Waveform::SawtoothLeft),
        Just(Waveform::Square),
        (0.02..0.98f64).prop_map(|w| Waveform::impulse(w).unwrap()),
    ]
}

fn any_oscillation() -> impl Strategy<Value = Option<Oscillation>> {
    prop::option::of(
        (0.0..2.0f64, any_waveform(), 0.0..1.0f64)
            .prop_map(|(a, w, p)| Oscillation::new(a, w, p).unwrap()),
    )
}

proptest! {
    #![proptest_config(support::deterministic(64))]

    #[test]
    fn superimposed_static_friction_never_exceeds_mu0(
        mu0 in 0.05..2.0f64,
        normal in any_oscillation(),
        tangential in any_oscillation(),
        transverse in any_oscillation(),
    ) {
        let ex = Excitation { normal, tangential, transverse };
        let s = static_friction_superimposed(mu0, &ex).unwrap();
        prop_assert!(s.mu_s() <= mu0 + 1e-9, "{s:?}");
        if let StaticFriction::Stick { lower, upper } = s {
            prop_assert!(lower < upper && lower >= -mu0 - 1e-9);
        }
    }
}
